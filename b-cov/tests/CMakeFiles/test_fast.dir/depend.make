# Empty dependencies file for test_fast.
# This may be replaced when dependencies are built.
