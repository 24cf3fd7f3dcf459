# Empty dependencies file for trigspline_gsl.
# This may be replaced when dependencies are built.
