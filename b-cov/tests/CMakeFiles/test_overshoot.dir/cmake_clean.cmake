file(REMOVE_RECURSE
  "CMakeFiles/test_overshoot.dir/api/test_overshoot.c.o"
  "CMakeFiles/test_overshoot.dir/api/test_overshoot.c.o.d"
  "test_overshoot"
  "test_overshoot.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang C)
  include(CMakeFiles/test_overshoot.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
