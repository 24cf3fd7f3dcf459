# Empty dependencies file for trigspline_cli_lib.
# This may be replaced when dependencies are built.
