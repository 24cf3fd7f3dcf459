file(REMOVE_RECURSE
  "../test_fuzz_surface"
  "../test_fuzz_surface.pdb"
  "CMakeFiles/test_fuzz_surface.dir/fuzz_surface.c.o"
  "CMakeFiles/test_fuzz_surface.dir/fuzz_surface.c.o.d"
  "CMakeFiles/test_fuzz_surface.dir/replay_main.c.o"
  "CMakeFiles/test_fuzz_surface.dir/replay_main.c.o.d"
)

# Per-language clean rules from dependency scanning.
foreach(lang C)
  include(CMakeFiles/test_fuzz_surface.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
