# Empty dependencies file for test_surface_offsets.
# This may be replaced when dependencies are built.
