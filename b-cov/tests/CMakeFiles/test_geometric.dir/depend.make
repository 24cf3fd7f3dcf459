# Empty dependencies file for test_geometric.
# This may be replaced when dependencies are built.
