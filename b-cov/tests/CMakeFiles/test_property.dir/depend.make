# Empty dependencies file for test_property.
# This may be replaced when dependencies are built.
