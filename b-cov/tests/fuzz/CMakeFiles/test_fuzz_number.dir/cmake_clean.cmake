file(REMOVE_RECURSE
  "../test_fuzz_number"
  "../test_fuzz_number.pdb"
  "CMakeFiles/test_fuzz_number.dir/fuzz_number.c.o"
  "CMakeFiles/test_fuzz_number.dir/fuzz_number.c.o.d"
  "CMakeFiles/test_fuzz_number.dir/replay_main.c.o"
  "CMakeFiles/test_fuzz_number.dir/replay_main.c.o.d"
)

# Per-language clean rules from dependency scanning.
foreach(lang C)
  include(CMakeFiles/test_fuzz_number.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
