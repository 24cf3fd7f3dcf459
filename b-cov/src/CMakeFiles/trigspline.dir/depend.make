# Empty dependencies file for trigspline.
# This may be replaced when dependencies are built.
