file(REMOVE_RECURSE
  "CMakeFiles/test_cover_core.dir/unit/test_cover_core.c.o"
  "CMakeFiles/test_cover_core.dir/unit/test_cover_core.c.o.d"
  "test_cover_core"
  "test_cover_core.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang C)
  include(CMakeFiles/test_cover_core.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
