# Empty dependencies file for test_gsl_steffen.
# This may be replaced when dependencies are built.
