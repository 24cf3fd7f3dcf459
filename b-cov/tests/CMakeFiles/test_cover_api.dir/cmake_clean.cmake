file(REMOVE_RECURSE
  "CMakeFiles/test_cover_api.dir/unit/test_cover_api.c.o"
  "CMakeFiles/test_cover_api.dir/unit/test_cover_api.c.o.d"
  "test_cover_api"
  "test_cover_api.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang C)
  include(CMakeFiles/test_cover_api.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
