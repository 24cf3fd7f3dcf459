file(REMOVE_RECURSE
  "CMakeFiles/test_integral_range.dir/api/test_integral_range.c.o"
  "CMakeFiles/test_integral_range.dir/api/test_integral_range.c.o.d"
  "test_integral_range"
  "test_integral_range.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang C)
  include(CMakeFiles/test_integral_range.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
