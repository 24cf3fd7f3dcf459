# CMake generated Testfile for 
# Source directory: /work/wt/trust/adapters/gsl
# Build directory: /work/wt/trust/b-cov/adapters/gsl
# 
# This file includes the relevant testing commands required for 
# testing this directory and lists subdirectories to be tested as well.
