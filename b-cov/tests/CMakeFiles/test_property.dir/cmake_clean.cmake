file(REMOVE_RECURSE
  "CMakeFiles/test_property.dir/api/test_property.c.o"
  "CMakeFiles/test_property.dir/api/test_property.c.o.d"
  "test_property"
  "test_property.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang C)
  include(CMakeFiles/test_property.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
