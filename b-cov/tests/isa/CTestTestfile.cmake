# CMake generated Testfile for 
# Source directory: /work/wt/trust/tests/isa
# Build directory: /work/wt/trust/b-cov/tests/isa
# 
# This file includes the relevant testing commands required for 
# testing this directory and lists subdirectories to be tested as well.
