# Empty dependencies file for test_refusals.
# This may be replaced when dependencies are built.
