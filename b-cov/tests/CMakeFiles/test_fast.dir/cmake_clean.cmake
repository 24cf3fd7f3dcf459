file(REMOVE_RECURSE
  "CMakeFiles/test_fast.dir/unit/test_fast.c.o"
  "CMakeFiles/test_fast.dir/unit/test_fast.c.o.d"
  "test_fast"
  "test_fast.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang C)
  include(CMakeFiles/test_fast.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
