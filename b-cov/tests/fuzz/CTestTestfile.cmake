# CMake generated Testfile for 
# Source directory: /work/wt/trust/tests/fuzz
# Build directory: /work/wt/trust/b-cov/tests/fuzz
# 
# This file includes the relevant testing commands required for 
# testing this directory and lists subdirectories to be tested as well.
add_test([=[test_fuzz_cli]=] "/work/wt/trust/b-cov/tests/test_fuzz_cli")
set_tests_properties([=[test_fuzz_cli]=] PROPERTIES  LABELS "fuzz" _BACKTRACE_TRIPLES "/work/wt/trust/tests/fuzz/CMakeLists.txt;34;add_test;/work/wt/trust/tests/fuzz/CMakeLists.txt;0;")
add_test([=[test_fuzz_curve]=] "/work/wt/trust/b-cov/tests/test_fuzz_curve")
set_tests_properties([=[test_fuzz_curve]=] PROPERTIES  LABELS "fuzz" _BACKTRACE_TRIPLES "/work/wt/trust/tests/fuzz/CMakeLists.txt;34;add_test;/work/wt/trust/tests/fuzz/CMakeLists.txt;0;")
add_test([=[test_fuzz_number]=] "/work/wt/trust/b-cov/tests/test_fuzz_number")
set_tests_properties([=[test_fuzz_number]=] PROPERTIES  LABELS "fuzz" _BACKTRACE_TRIPLES "/work/wt/trust/tests/fuzz/CMakeLists.txt;34;add_test;/work/wt/trust/tests/fuzz/CMakeLists.txt;0;")
add_test([=[test_fuzz_spline]=] "/work/wt/trust/b-cov/tests/test_fuzz_spline")
set_tests_properties([=[test_fuzz_spline]=] PROPERTIES  LABELS "fuzz" _BACKTRACE_TRIPLES "/work/wt/trust/tests/fuzz/CMakeLists.txt;34;add_test;/work/wt/trust/tests/fuzz/CMakeLists.txt;0;")
add_test([=[test_fuzz_surface]=] "/work/wt/trust/b-cov/tests/test_fuzz_surface")
set_tests_properties([=[test_fuzz_surface]=] PROPERTIES  LABELS "fuzz" _BACKTRACE_TRIPLES "/work/wt/trust/tests/fuzz/CMakeLists.txt;34;add_test;/work/wt/trust/tests/fuzz/CMakeLists.txt;0;")
add_test([=[test_fuzz_table]=] "/work/wt/trust/b-cov/tests/test_fuzz_table")
set_tests_properties([=[test_fuzz_table]=] PROPERTIES  LABELS "fuzz" _BACKTRACE_TRIPLES "/work/wt/trust/tests/fuzz/CMakeLists.txt;34;add_test;/work/wt/trust/tests/fuzz/CMakeLists.txt;0;")
