# Empty dependencies file for test_fuzz_curve.
# This may be replaced when dependencies are built.
