file(REMOVE_RECURSE
  "CMakeFiles/test_region_samples.dir/api/test_region_samples.c.o"
  "CMakeFiles/test_region_samples.dir/api/test_region_samples.c.o.d"
  "test_region_samples"
  "test_region_samples.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang C)
  include(CMakeFiles/test_region_samples.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
