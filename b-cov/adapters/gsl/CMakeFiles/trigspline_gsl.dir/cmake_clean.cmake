file(REMOVE_RECURSE
  "CMakeFiles/trigspline_gsl.dir/trigspline_gsl.c.o"
  "CMakeFiles/trigspline_gsl.dir/trigspline_gsl.c.o.d"
  "libtrigspline_gsl.a"
  "libtrigspline_gsl.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang C)
  include(CMakeFiles/trigspline_gsl.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
