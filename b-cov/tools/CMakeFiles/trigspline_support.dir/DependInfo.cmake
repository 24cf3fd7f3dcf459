
# Consider dependencies only in project.
set(CMAKE_DEPENDS_IN_PROJECT_ONLY OFF)

# The set of languages for which implicit dependencies are needed:
set(CMAKE_DEPENDS_LANGUAGES
  )

# The set of dependency files which are needed:
set(CMAKE_DEPENDS_DEPENDENCY_FILES
  "/work/wt/trust/tools/support/tsu_io.c" "tools/CMakeFiles/trigspline_support.dir/support/tsu_io.c.o" "gcc" "tools/CMakeFiles/trigspline_support.dir/support/tsu_io.c.o.d"
  "/work/wt/trust/tools/support/tsu_number.c" "tools/CMakeFiles/trigspline_support.dir/support/tsu_number.c.o" "gcc" "tools/CMakeFiles/trigspline_support.dir/support/tsu_number.c.o.d"
  "/work/wt/trust/tools/support/tsu_output.c" "tools/CMakeFiles/trigspline_support.dir/support/tsu_output.c.o" "gcc" "tools/CMakeFiles/trigspline_support.dir/support/tsu_output.c.o.d"
  "/work/wt/trust/tools/support/tsu_plot.c" "tools/CMakeFiles/trigspline_support.dir/support/tsu_plot.c.o" "gcc" "tools/CMakeFiles/trigspline_support.dir/support/tsu_plot.c.o.d"
  "/work/wt/trust/tools/support/tsu_table.c" "tools/CMakeFiles/trigspline_support.dir/support/tsu_table.c.o" "gcc" "tools/CMakeFiles/trigspline_support.dir/support/tsu_table.c.o.d"
  "/work/wt/trust/tools/support/tsu_time.c" "tools/CMakeFiles/trigspline_support.dir/support/tsu_time.c.o" "gcc" "tools/CMakeFiles/trigspline_support.dir/support/tsu_time.c.o.d"
  )

# Targets to which this target links.
set(CMAKE_TARGET_LINKED_INFO_FILES
  )

# Fortran module output directory.
set(CMAKE_Fortran_TARGET_MODULE_DIR "")
