file(REMOVE_RECURSE
  "CMakeFiles/trigspline_support.dir/support/tsu_io.c.o"
  "CMakeFiles/trigspline_support.dir/support/tsu_io.c.o.d"
  "CMakeFiles/trigspline_support.dir/support/tsu_number.c.o"
  "CMakeFiles/trigspline_support.dir/support/tsu_number.c.o.d"
  "CMakeFiles/trigspline_support.dir/support/tsu_output.c.o"
  "CMakeFiles/trigspline_support.dir/support/tsu_output.c.o.d"
  "CMakeFiles/trigspline_support.dir/support/tsu_plot.c.o"
  "CMakeFiles/trigspline_support.dir/support/tsu_plot.c.o.d"
  "CMakeFiles/trigspline_support.dir/support/tsu_table.c.o"
  "CMakeFiles/trigspline_support.dir/support/tsu_table.c.o.d"
  "CMakeFiles/trigspline_support.dir/support/tsu_time.c.o"
  "CMakeFiles/trigspline_support.dir/support/tsu_time.c.o.d"
  "libtrigspline_support.a"
  "libtrigspline_support.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang C)
  include(CMakeFiles/trigspline_support.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
