# Empty dependencies file for test_cover_api.
# This may be replaced when dependencies are built.
