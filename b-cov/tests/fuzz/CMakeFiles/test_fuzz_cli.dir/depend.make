# Empty dependencies file for test_fuzz_cli.
# This may be replaced when dependencies are built.
