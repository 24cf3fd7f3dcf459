
# Consider dependencies only in project.
set(CMAKE_DEPENDS_IN_PROJECT_ONLY OFF)

# The set of languages for which implicit dependencies are needed:
set(CMAKE_DEPENDS_LANGUAGES
  )

# The set of dependency files which are needed:
set(CMAKE_DEPENDS_DEPENDENCY_FILES
  "/work/wt/trust/tests/fuzz/fuzz_spline.c" "tests/fuzz/CMakeFiles/test_fuzz_spline.dir/fuzz_spline.c.o" "gcc" "tests/fuzz/CMakeFiles/test_fuzz_spline.dir/fuzz_spline.c.o.d"
  "/work/wt/trust/tests/fuzz/replay_main.c" "tests/fuzz/CMakeFiles/test_fuzz_spline.dir/replay_main.c.o" "gcc" "tests/fuzz/CMakeFiles/test_fuzz_spline.dir/replay_main.c.o.d"
  )

# Targets to which this target links.
set(CMAKE_TARGET_LINKED_INFO_FILES
  "/work/wt/trust/b-cov/src/CMakeFiles/trigspline.dir/DependInfo.cmake"
  )

# Fortran module output directory.
set(CMAKE_Fortran_TARGET_MODULE_DIR "")
