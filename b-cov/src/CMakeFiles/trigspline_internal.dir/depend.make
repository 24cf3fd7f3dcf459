# Empty dependencies file for trigspline_internal.
# This may be replaced when dependencies are built.
