file(REMOVE_RECURSE
  "CMakeFiles/test_slopes.dir/unit/test_slopes.c.o"
  "CMakeFiles/test_slopes.dir/unit/test_slopes.c.o.d"
  "test_slopes"
  "test_slopes.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang C)
  include(CMakeFiles/test_slopes.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
