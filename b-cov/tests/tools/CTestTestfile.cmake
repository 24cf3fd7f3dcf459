# CMake generated Testfile for 
# Source directory: /work/wt/trust/tests/tools
# Build directory: /work/wt/trust/b-cov/tests/tools
# 
# This file includes the relevant testing commands required for 
# testing this directory and lists subdirectories to be tested as well.
add_test([=[test_io]=] "/work/wt/trust/b-cov/tests/test_io")
set_tests_properties([=[test_io]=] PROPERTIES  _BACKTRACE_TRIPLES "/work/wt/trust/tests/tools/CMakeLists.txt;12;add_test;/work/wt/trust/tests/tools/CMakeLists.txt;0;")
add_test([=[test_plot]=] "/work/wt/trust/b-cov/tests/test_plot")
set_tests_properties([=[test_plot]=] PROPERTIES  _BACKTRACE_TRIPLES "/work/wt/trust/tests/tools/CMakeLists.txt;12;add_test;/work/wt/trust/tests/tools/CMakeLists.txt;0;")
add_test([=[test_random_tool_inputs]=] "/work/wt/trust/b-cov/tests/test_random_tool_inputs")
set_tests_properties([=[test_random_tool_inputs]=] PROPERTIES  _BACKTRACE_TRIPLES "/work/wt/trust/tests/tools/CMakeLists.txt;12;add_test;/work/wt/trust/tests/tools/CMakeLists.txt;0;")
add_test([=[test_plot_xml]=] "python3" "/work/wt/trust/tests/tools/test_plot_xml.py" "/work/wt/trust/b-cov")
set_tests_properties([=[test_plot_xml]=] PROPERTIES  _BACKTRACE_TRIPLES "/work/wt/trust/tests/tools/CMakeLists.txt;17;add_test;/work/wt/trust/tests/tools/CMakeLists.txt;0;")
add_test([=[test_cli]=] "python3" "/work/wt/trust/tests/tools/test_cli.py" "/work/wt/trust/b-cov")
set_tests_properties([=[test_cli]=] PROPERTIES  _BACKTRACE_TRIPLES "/work/wt/trust/tests/tools/CMakeLists.txt;17;add_test;/work/wt/trust/tests/tools/CMakeLists.txt;0;")
