file(REMOVE_RECURSE
  "../../tests/test_gsl_steffen"
  "../../tests/test_gsl_steffen.pdb"
  "CMakeFiles/test_gsl_steffen.dir/test_gsl_steffen.c.o"
  "CMakeFiles/test_gsl_steffen.dir/test_gsl_steffen.c.o.d"
)

# Per-language clean rules from dependency scanning.
foreach(lang C)
  include(CMakeFiles/test_gsl_steffen.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
