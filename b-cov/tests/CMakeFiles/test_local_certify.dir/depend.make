# Empty dependencies file for test_local_certify.
# This may be replaced when dependencies are built.
