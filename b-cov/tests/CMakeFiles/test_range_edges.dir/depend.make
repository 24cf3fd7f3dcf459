# Empty dependencies file for test_range_edges.
# This may be replaced when dependencies are built.
