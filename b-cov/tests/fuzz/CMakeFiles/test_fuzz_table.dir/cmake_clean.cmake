file(REMOVE_RECURSE
  "../test_fuzz_table"
  "../test_fuzz_table.pdb"
  "CMakeFiles/test_fuzz_table.dir/fuzz_table.c.o"
  "CMakeFiles/test_fuzz_table.dir/fuzz_table.c.o.d"
  "CMakeFiles/test_fuzz_table.dir/replay_main.c.o"
  "CMakeFiles/test_fuzz_table.dir/replay_main.c.o.d"
)

# Per-language clean rules from dependency scanning.
foreach(lang C)
  include(CMakeFiles/test_fuzz_table.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
