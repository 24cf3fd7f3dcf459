file(REMOVE_RECURSE
  "CMakeFiles/test_flat.dir/api/test_flat.c.o"
  "CMakeFiles/test_flat.dir/api/test_flat.c.o.d"
  "test_flat"
  "test_flat.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang C)
  include(CMakeFiles/test_flat.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
