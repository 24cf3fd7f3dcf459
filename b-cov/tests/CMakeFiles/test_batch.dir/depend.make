# Empty dependencies file for test_batch.
# This may be replaced when dependencies are built.
