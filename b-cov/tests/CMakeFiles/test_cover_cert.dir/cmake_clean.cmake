file(REMOVE_RECURSE
  "CMakeFiles/test_cover_cert.dir/unit/test_cover_cert.c.o"
  "CMakeFiles/test_cover_cert.dir/unit/test_cover_cert.c.o.d"
  "test_cover_cert"
  "test_cover_cert.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang C)
  include(CMakeFiles/test_cover_cert.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
