# Empty dependencies file for test_flat.
# This may be replaced when dependencies are built.
