file(REMOVE_RECURSE
  "CMakeFiles/test_surface_alloc.dir/unit/test_surface_alloc.c.o"
  "CMakeFiles/test_surface_alloc.dir/unit/test_surface_alloc.c.o.d"
  "test_surface_alloc"
  "test_surface_alloc.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang C)
  include(CMakeFiles/test_surface_alloc.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
