# Empty dependencies file for gsl_eval.
# This may be replaced when dependencies are built.
