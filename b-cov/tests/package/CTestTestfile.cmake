# CMake generated Testfile for 
# Source directory: /work/wt/trust/tests/package
# Build directory: /work/wt/trust/b-cov/tests/package
# 
# This file includes the relevant testing commands required for 
# testing this directory and lists subdirectories to be tested as well.
add_test([=[package]=] "/work/wt/trust/b-cov/tests/test_package")
set_tests_properties([=[package]=] PROPERTIES  _BACKTRACE_TRIPLES "/work/wt/trust/tests/package/CMakeLists.txt;12;add_test;/work/wt/trust/tests/package/CMakeLists.txt;0;")
