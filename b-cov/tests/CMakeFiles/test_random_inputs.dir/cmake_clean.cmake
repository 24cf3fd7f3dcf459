file(REMOVE_RECURSE
  "CMakeFiles/test_random_inputs.dir/api/test_random_inputs.c.o"
  "CMakeFiles/test_random_inputs.dir/api/test_random_inputs.c.o.d"
  "test_random_inputs"
  "test_random_inputs.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang C)
  include(CMakeFiles/test_random_inputs.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
