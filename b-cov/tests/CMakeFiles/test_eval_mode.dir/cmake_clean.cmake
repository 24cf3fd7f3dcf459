file(REMOVE_RECURSE
  "CMakeFiles/test_eval_mode.dir/api/test_eval_mode.c.o"
  "CMakeFiles/test_eval_mode.dir/api/test_eval_mode.c.o.d"
  "test_eval_mode"
  "test_eval_mode.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang C)
  include(CMakeFiles/test_eval_mode.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
