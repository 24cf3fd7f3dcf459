# Empty dependencies file for test_fuzz_number.
# This may be replaced when dependencies are built.
