# Empty dependencies file for trigspline_obj.
# This may be replaced when dependencies are built.
