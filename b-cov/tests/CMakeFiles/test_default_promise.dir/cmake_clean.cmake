file(REMOVE_RECURSE
  "CMakeFiles/test_default_promise.dir/api/test_default_promise.c.o"
  "CMakeFiles/test_default_promise.dir/api/test_default_promise.c.o.d"
  "test_default_promise"
  "test_default_promise.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang C)
  include(CMakeFiles/test_default_promise.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
