# Empty dependencies file for test_slopes.
# This may be replaced when dependencies are built.
