file(REMOVE_RECURSE
  "../test_io"
  "../test_io.pdb"
  "CMakeFiles/test_io.dir/test_io.c.o"
  "CMakeFiles/test_io.dir/test_io.c.o.d"
)

# Per-language clean rules from dependency scanning.
foreach(lang C)
  include(CMakeFiles/test_io.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
