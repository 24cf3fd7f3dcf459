file(REMOVE_RECURSE
  "CMakeFiles/test_basis.dir/unit/test_basis.c.o"
  "CMakeFiles/test_basis.dir/unit/test_basis.c.o.d"
  "test_basis"
  "test_basis.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang C)
  include(CMakeFiles/test_basis.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
