# Empty dependencies file for test_struct_guard.
# This may be replaced when dependencies are built.
