# Empty dependencies file for test_fenv.
# This may be replaced when dependencies are built.
