# Empty dependencies file for test_surface_alloc.
# This may be replaced when dependencies are built.
