file(REMOVE_RECURSE
  "CMakeFiles/test_range_edges.dir/api/test_range_edges.c.o"
  "CMakeFiles/test_range_edges.dir/api/test_range_edges.c.o.d"
  "test_range_edges"
  "test_range_edges.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang C)
  include(CMakeFiles/test_range_edges.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
