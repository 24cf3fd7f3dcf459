# Empty dependencies file for test_eval_mode.
# This may be replaced when dependencies are built.
