file(REMOVE_RECURSE
  "CMakeFiles/test_large_offsets.dir/api/test_large_offsets.c.o"
  "CMakeFiles/test_large_offsets.dir/api/test_large_offsets.c.o.d"
  "test_large_offsets"
  "test_large_offsets.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang C)
  include(CMakeFiles/test_large_offsets.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
