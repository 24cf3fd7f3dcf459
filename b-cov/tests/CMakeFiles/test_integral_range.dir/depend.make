# Empty dependencies file for test_integral_range.
# This may be replaced when dependencies are built.
