# Empty dependencies file for test_default_promise.
# This may be replaced when dependencies are built.
