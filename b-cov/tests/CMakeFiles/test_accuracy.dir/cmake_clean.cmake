file(REMOVE_RECURSE
  "CMakeFiles/test_accuracy.dir/api/test_accuracy.c.o"
  "CMakeFiles/test_accuracy.dir/api/test_accuracy.c.o.d"
  "test_accuracy"
  "test_accuracy.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang C)
  include(CMakeFiles/test_accuracy.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
