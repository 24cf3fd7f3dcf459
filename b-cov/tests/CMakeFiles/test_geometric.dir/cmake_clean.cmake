file(REMOVE_RECURSE
  "CMakeFiles/test_geometric.dir/api/test_geometric.c.o"
  "CMakeFiles/test_geometric.dir/api/test_geometric.c.o.d"
  "test_geometric"
  "test_geometric.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang C)
  include(CMakeFiles/test_geometric.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
