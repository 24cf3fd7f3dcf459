file(REMOVE_RECURSE
  "../test_fuzz_spline"
  "../test_fuzz_spline.pdb"
  "CMakeFiles/test_fuzz_spline.dir/fuzz_spline.c.o"
  "CMakeFiles/test_fuzz_spline.dir/fuzz_spline.c.o.d"
  "CMakeFiles/test_fuzz_spline.dir/replay_main.c.o"
  "CMakeFiles/test_fuzz_spline.dir/replay_main.c.o.d"
)

# Per-language clean rules from dependency scanning.
foreach(lang C)
  include(CMakeFiles/test_fuzz_spline.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
