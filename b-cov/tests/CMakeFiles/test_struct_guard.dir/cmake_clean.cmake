file(REMOVE_RECURSE
  "CMakeFiles/test_struct_guard.dir/api/test_struct_guard.c.o"
  "CMakeFiles/test_struct_guard.dir/api/test_struct_guard.c.o.d"
  "test_struct_guard"
  "test_struct_guard.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang C)
  include(CMakeFiles/test_struct_guard.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
