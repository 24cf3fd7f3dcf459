file(REMOVE_RECURSE
  "CMakeFiles/test_batch.dir/api/test_batch.c.o"
  "CMakeFiles/test_batch.dir/api/test_batch.c.o.d"
  "test_batch"
  "test_batch.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang C)
  include(CMakeFiles/test_batch.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
