file(REMOVE_RECURSE
  "../test_plot"
  "../test_plot.pdb"
  "CMakeFiles/test_plot.dir/test_plot.c.o"
  "CMakeFiles/test_plot.dir/test_plot.c.o.d"
)

# Per-language clean rules from dependency scanning.
foreach(lang C)
  include(CMakeFiles/test_plot.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
