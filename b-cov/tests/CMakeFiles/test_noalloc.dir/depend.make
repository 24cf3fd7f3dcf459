# Empty dependencies file for test_noalloc.
# This may be replaced when dependencies are built.
