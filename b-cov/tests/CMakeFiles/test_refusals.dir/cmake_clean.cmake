file(REMOVE_RECURSE
  "CMakeFiles/test_refusals.dir/api/test_refusals.c.o"
  "CMakeFiles/test_refusals.dir/api/test_refusals.c.o.d"
  "test_refusals"
  "test_refusals.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang C)
  include(CMakeFiles/test_refusals.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
