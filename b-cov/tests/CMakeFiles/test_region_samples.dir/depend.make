# Empty dependencies file for test_region_samples.
# This may be replaced when dependencies are built.
