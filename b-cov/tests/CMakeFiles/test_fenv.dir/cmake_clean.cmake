file(REMOVE_RECURSE
  "CMakeFiles/test_fenv.dir/api/test_fenv.c.o"
  "CMakeFiles/test_fenv.dir/api/test_fenv.c.o.d"
  "test_fenv"
  "test_fenv.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang C)
  include(CMakeFiles/test_fenv.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
