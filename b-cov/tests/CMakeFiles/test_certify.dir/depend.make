# Empty dependencies file for test_certify.
# This may be replaced when dependencies are built.
