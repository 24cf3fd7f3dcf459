file(REMOVE_RECURSE
  "CMakeFiles/test_curve.dir/api/test_curve.c.o"
  "CMakeFiles/test_curve.dir/api/test_curve.c.o.d"
  "test_curve"
  "test_curve.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang C)
  include(CMakeFiles/test_curve.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
