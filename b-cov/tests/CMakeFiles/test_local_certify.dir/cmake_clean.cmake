file(REMOVE_RECURSE
  "CMakeFiles/test_local_certify.dir/api/test_local_certify.c.o"
  "CMakeFiles/test_local_certify.dir/api/test_local_certify.c.o.d"
  "test_local_certify"
  "test_local_certify.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang C)
  include(CMakeFiles/test_local_certify.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
