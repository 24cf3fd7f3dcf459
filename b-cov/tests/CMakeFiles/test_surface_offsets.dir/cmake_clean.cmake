file(REMOVE_RECURSE
  "CMakeFiles/test_surface_offsets.dir/api/test_surface_offsets.c.o"
  "CMakeFiles/test_surface_offsets.dir/api/test_surface_offsets.c.o.d"
  "test_surface_offsets"
  "test_surface_offsets.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang C)
  include(CMakeFiles/test_surface_offsets.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
