# Empty dependencies file for test_cover_cert.
# This may be replaced when dependencies are built.
