file(REMOVE_RECURSE
  "../../gsl_eval"
  "../../gsl_eval.pdb"
  "CMakeFiles/gsl_eval.dir/__/__/tools/compare/gsl_eval.c.o"
  "CMakeFiles/gsl_eval.dir/__/__/tools/compare/gsl_eval.c.o.d"
)

# Per-language clean rules from dependency scanning.
foreach(lang C)
  include(CMakeFiles/gsl_eval.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
