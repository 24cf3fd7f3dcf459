# Empty dependencies file for test_fuzz_surface.
# This may be replaced when dependencies are built.
