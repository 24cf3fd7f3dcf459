# Empty dependencies file for trigspline_support.
# This may be replaced when dependencies are built.
