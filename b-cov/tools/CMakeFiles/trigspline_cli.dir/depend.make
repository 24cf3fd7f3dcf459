# Empty dependencies file for trigspline_cli.
# This may be replaced when dependencies are built.
