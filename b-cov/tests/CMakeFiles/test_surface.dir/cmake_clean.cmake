file(REMOVE_RECURSE
  "CMakeFiles/test_surface.dir/api/test_surface.c.o"
  "CMakeFiles/test_surface.dir/api/test_surface.c.o.d"
  "test_surface"
  "test_surface.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang C)
  include(CMakeFiles/test_surface.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
