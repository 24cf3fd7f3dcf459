# Empty dependencies file for test_basis.
# This may be replaced when dependencies are built.
