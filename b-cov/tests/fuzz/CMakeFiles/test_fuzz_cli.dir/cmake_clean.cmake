file(REMOVE_RECURSE
  "../test_fuzz_cli"
  "../test_fuzz_cli.pdb"
  "CMakeFiles/test_fuzz_cli.dir/fuzz_cli.c.o"
  "CMakeFiles/test_fuzz_cli.dir/fuzz_cli.c.o.d"
  "CMakeFiles/test_fuzz_cli.dir/replay_main.c.o"
  "CMakeFiles/test_fuzz_cli.dir/replay_main.c.o.d"
)

# Per-language clean rules from dependency scanning.
foreach(lang C)
  include(CMakeFiles/test_fuzz_cli.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
