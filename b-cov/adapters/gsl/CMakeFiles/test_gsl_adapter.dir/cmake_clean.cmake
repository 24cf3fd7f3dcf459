file(REMOVE_RECURSE
  "../../tests/test_gsl_adapter"
  "../../tests/test_gsl_adapter.pdb"
  "CMakeFiles/test_gsl_adapter.dir/test_gsl_adapter.c.o"
  "CMakeFiles/test_gsl_adapter.dir/test_gsl_adapter.c.o.d"
)

# Per-language clean rules from dependency scanning.
foreach(lang C)
  include(CMakeFiles/test_gsl_adapter.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
