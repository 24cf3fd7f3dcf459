
# Consider dependencies only in project.
set(CMAKE_DEPENDS_IN_PROJECT_ONLY OFF)

# The set of languages for which implicit dependencies are needed:
set(CMAKE_DEPENDS_LANGUAGES
  )

# The set of dependency files which are needed:
set(CMAKE_DEPENDS_DEPENDENCY_FILES
  "/work/wt/trust/tests/fuzz/fuzz_number.c" "tests/fuzz/CMakeFiles/test_fuzz_number.dir/fuzz_number.c.o" "gcc" "tests/fuzz/CMakeFiles/test_fuzz_number.dir/fuzz_number.c.o.d"
  "/work/wt/trust/tests/fuzz/replay_main.c" "tests/fuzz/CMakeFiles/test_fuzz_number.dir/replay_main.c.o" "gcc" "tests/fuzz/CMakeFiles/test_fuzz_number.dir/replay_main.c.o.d"
  )

# Targets to which this target links.
set(CMAKE_TARGET_LINKED_INFO_FILES
  "/work/wt/trust/b-cov/tools/CMakeFiles/trigspline_support.dir/DependInfo.cmake"
  "/work/wt/trust/b-cov/src/CMakeFiles/trigspline.dir/DependInfo.cmake"
  )

# Fortran module output directory.
set(CMAKE_Fortran_TARGET_MODULE_DIR "")
