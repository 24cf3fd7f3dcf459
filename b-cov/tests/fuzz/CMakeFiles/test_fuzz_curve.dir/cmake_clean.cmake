file(REMOVE_RECURSE
  "../test_fuzz_curve"
  "../test_fuzz_curve.pdb"
  "CMakeFiles/test_fuzz_curve.dir/fuzz_curve.c.o"
  "CMakeFiles/test_fuzz_curve.dir/fuzz_curve.c.o.d"
  "CMakeFiles/test_fuzz_curve.dir/replay_main.c.o"
  "CMakeFiles/test_fuzz_curve.dir/replay_main.c.o.d"
)

# Per-language clean rules from dependency scanning.
foreach(lang C)
  include(CMakeFiles/test_fuzz_curve.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
