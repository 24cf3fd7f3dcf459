file(REMOVE_RECURSE
  "CMakeFiles/test_cover_eval.dir/unit/test_cover_eval.c.o"
  "CMakeFiles/test_cover_eval.dir/unit/test_cover_eval.c.o.d"
  "test_cover_eval"
  "test_cover_eval.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang C)
  include(CMakeFiles/test_cover_eval.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
