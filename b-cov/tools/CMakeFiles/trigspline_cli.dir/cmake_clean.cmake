file(REMOVE_RECURSE
  "../trigspline"
  "../trigspline.pdb"
  "CMakeFiles/trigspline_cli.dir/cli/main.c.o"
  "CMakeFiles/trigspline_cli.dir/cli/main.c.o.d"
)

# Per-language clean rules from dependency scanning.
foreach(lang C)
  include(CMakeFiles/trigspline_cli.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
