# Empty dependencies file for test_overshoot.
# This may be replaced when dependencies are built.
