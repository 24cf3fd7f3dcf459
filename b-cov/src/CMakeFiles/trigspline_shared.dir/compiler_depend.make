# Empty compiler generated dependencies file for trigspline_shared.
# This may be replaced when dependencies are built.
