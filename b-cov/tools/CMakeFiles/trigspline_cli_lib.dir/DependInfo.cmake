
# Consider dependencies only in project.
set(CMAKE_DEPENDS_IN_PROJECT_ONLY OFF)

# The set of languages for which implicit dependencies are needed:
set(CMAKE_DEPENDS_LANGUAGES
  )

# The set of dependency files which are needed:
set(CMAKE_DEPENDS_DEPENDENCY_FILES
  "/work/wt/trust/tools/cli/args.c" "tools/CMakeFiles/trigspline_cli_lib.dir/cli/args.c.o" "gcc" "tools/CMakeFiles/trigspline_cli_lib.dir/cli/args.c.o.d"
  "/work/wt/trust/tools/cli/axis.c" "tools/CMakeFiles/trigspline_cli_lib.dir/cli/axis.c.o" "gcc" "tools/CMakeFiles/trigspline_cli_lib.dir/cli/axis.c.o.d"
  "/work/wt/trust/tools/cli/certify.c" "tools/CMakeFiles/trigspline_cli_lib.dir/cli/certify.c.o" "gcc" "tools/CMakeFiles/trigspline_cli_lib.dir/cli/certify.c.o.d"
  "/work/wt/trust/tools/cli/curve.c" "tools/CMakeFiles/trigspline_cli_lib.dir/cli/curve.c.o" "gcc" "tools/CMakeFiles/trigspline_cli_lib.dir/cli/curve.c.o.d"
  "/work/wt/trust/tools/cli/curve_json.c" "tools/CMakeFiles/trigspline_cli_lib.dir/cli/curve_json.c.o" "gcc" "tools/CMakeFiles/trigspline_cli_lib.dir/cli/curve_json.c.o.d"
  "/work/wt/trust/tools/cli/curve_plot.c" "tools/CMakeFiles/trigspline_cli_lib.dir/cli/curve_plot.c.o" "gcc" "tools/CMakeFiles/trigspline_cli_lib.dir/cli/curve_plot.c.o.d"
  "/work/wt/trust/tools/cli/data.c" "tools/CMakeFiles/trigspline_cli_lib.dir/cli/data.c.o" "gcc" "tools/CMakeFiles/trigspline_cli_lib.dir/cli/data.c.o.d"
  "/work/wt/trust/tools/cli/fit.c" "tools/CMakeFiles/trigspline_cli_lib.dir/cli/fit.c.o" "gcc" "tools/CMakeFiles/trigspline_cli_lib.dir/cli/fit.c.o.d"
  "/work/wt/trust/tools/cli/fit_options.c" "tools/CMakeFiles/trigspline_cli_lib.dir/cli/fit_options.c.o" "gcc" "tools/CMakeFiles/trigspline_cli_lib.dir/cli/fit_options.c.o.d"
  "/work/wt/trust/tools/cli/help.c" "tools/CMakeFiles/trigspline_cli_lib.dir/cli/help.c.o" "gcc" "tools/CMakeFiles/trigspline_cli_lib.dir/cli/help.c.o.d"
  "/work/wt/trust/tools/cli/json.c" "tools/CMakeFiles/trigspline_cli_lib.dir/cli/json.c.o" "gcc" "tools/CMakeFiles/trigspline_cli_lib.dir/cli/json.c.o.d"
  "/work/wt/trust/tools/cli/messages.c" "tools/CMakeFiles/trigspline_cli_lib.dir/cli/messages.c.o" "gcc" "tools/CMakeFiles/trigspline_cli_lib.dir/cli/messages.c.o.d"
  "/work/wt/trust/tools/cli/names.c" "tools/CMakeFiles/trigspline_cli_lib.dir/cli/names.c.o" "gcc" "tools/CMakeFiles/trigspline_cli_lib.dir/cli/names.c.o.d"
  "/work/wt/trust/tools/cli/options.c" "tools/CMakeFiles/trigspline_cli_lib.dir/cli/options.c.o" "gcc" "tools/CMakeFiles/trigspline_cli_lib.dir/cli/options.c.o.d"
  "/work/wt/trust/tools/cli/output.c" "tools/CMakeFiles/trigspline_cli_lib.dir/cli/output.c.o" "gcc" "tools/CMakeFiles/trigspline_cli_lib.dir/cli/output.c.o.d"
  "/work/wt/trust/tools/cli/overshoot.c" "tools/CMakeFiles/trigspline_cli_lib.dir/cli/overshoot.c.o" "gcc" "tools/CMakeFiles/trigspline_cli_lib.dir/cli/overshoot.c.o.d"
  "/work/wt/trust/tools/cli/sample.c" "tools/CMakeFiles/trigspline_cli_lib.dir/cli/sample.c.o" "gcc" "tools/CMakeFiles/trigspline_cli_lib.dir/cli/sample.c.o.d"
  "/work/wt/trust/tools/cli/spline_json.c" "tools/CMakeFiles/trigspline_cli_lib.dir/cli/spline_json.c.o" "gcc" "tools/CMakeFiles/trigspline_cli_lib.dir/cli/spline_json.c.o.d"
  "/work/wt/trust/tools/cli/spline_plot.c" "tools/CMakeFiles/trigspline_cli_lib.dir/cli/spline_plot.c.o" "gcc" "tools/CMakeFiles/trigspline_cli_lib.dir/cli/spline_plot.c.o.d"
  "/work/wt/trust/tools/cli/stream.c" "tools/CMakeFiles/trigspline_cli_lib.dir/cli/stream.c.o" "gcc" "tools/CMakeFiles/trigspline_cli_lib.dir/cli/stream.c.o.d"
  "/work/wt/trust/tools/cli/surface.c" "tools/CMakeFiles/trigspline_cli_lib.dir/cli/surface.c.o" "gcc" "tools/CMakeFiles/trigspline_cli_lib.dir/cli/surface.c.o.d"
  "/work/wt/trust/tools/cli/table.c" "tools/CMakeFiles/trigspline_cli_lib.dir/cli/table.c.o" "gcc" "tools/CMakeFiles/trigspline_cli_lib.dir/cli/table.c.o.d"
  )

# Targets to which this target links.
set(CMAKE_TARGET_LINKED_INFO_FILES
  "/work/wt/trust/b-cov/tools/CMakeFiles/trigspline_support.dir/DependInfo.cmake"
  "/work/wt/trust/b-cov/src/CMakeFiles/trigspline.dir/DependInfo.cmake"
  )

# Fortran module output directory.
set(CMAKE_Fortran_TARGET_MODULE_DIR "")
