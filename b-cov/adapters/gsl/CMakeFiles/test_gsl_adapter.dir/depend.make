# Empty dependencies file for test_gsl_adapter.
# This may be replaced when dependencies are built.
