# Empty dependencies file for test_error_message.
# This may be replaced when dependencies are built.
