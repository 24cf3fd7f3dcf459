# Empty dependencies file for test_surface.
# This may be replaced when dependencies are built.
