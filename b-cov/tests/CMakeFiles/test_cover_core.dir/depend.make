# Empty dependencies file for test_cover_core.
# This may be replaced when dependencies are built.
