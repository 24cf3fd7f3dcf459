# Empty dependencies file for test_random_tool_inputs.
# This may be replaced when dependencies are built.
