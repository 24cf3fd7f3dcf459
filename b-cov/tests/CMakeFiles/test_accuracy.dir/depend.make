# Empty dependencies file for test_accuracy.
# This may be replaced when dependencies are built.
