# Empty dependencies file for test_fuzz_spline.
# This may be replaced when dependencies are built.
