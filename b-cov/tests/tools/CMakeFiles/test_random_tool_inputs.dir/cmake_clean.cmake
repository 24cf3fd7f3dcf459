file(REMOVE_RECURSE
  "../test_random_tool_inputs"
  "../test_random_tool_inputs.pdb"
  "CMakeFiles/test_random_tool_inputs.dir/test_random_tool_inputs.c.o"
  "CMakeFiles/test_random_tool_inputs.dir/test_random_tool_inputs.c.o.d"
)

# Per-language clean rules from dependency scanning.
foreach(lang C)
  include(CMakeFiles/test_random_tool_inputs.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
