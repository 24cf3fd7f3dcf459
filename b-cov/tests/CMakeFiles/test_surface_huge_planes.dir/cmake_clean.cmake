file(REMOVE_RECURSE
  "CMakeFiles/test_surface_huge_planes.dir/api/test_surface_huge_planes.c.o"
  "CMakeFiles/test_surface_huge_planes.dir/api/test_surface_huge_planes.c.o.d"
  "test_surface_huge_planes"
  "test_surface_huge_planes.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang C)
  include(CMakeFiles/test_surface_huge_planes.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
