# Empty dependencies file for test_fuzz_table.
# This may be replaced when dependencies are built.
