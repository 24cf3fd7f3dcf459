# Empty dependencies file for test_large_offsets.
# This may be replaced when dependencies are built.
