# Empty dependencies file for test_cover_eval.
# This may be replaced when dependencies are built.
