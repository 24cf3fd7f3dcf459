# Empty dependencies file for test_vocab.
# This may be replaced when dependencies are built.
