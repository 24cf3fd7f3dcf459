file(REMOVE_RECURSE
  "CMakeFiles/test_certify.dir/unit/test_certify.c.o"
  "CMakeFiles/test_certify.dir/unit/test_certify.c.o.d"
  "test_certify"
  "test_certify.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang C)
  include(CMakeFiles/test_certify.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
