# Empty dependencies file for test_surface_huge_planes.
# This may be replaced when dependencies are built.
