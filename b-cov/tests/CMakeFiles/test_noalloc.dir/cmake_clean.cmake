file(REMOVE_RECURSE
  "CMakeFiles/test_noalloc.dir/api/test_noalloc.c.o"
  "CMakeFiles/test_noalloc.dir/api/test_noalloc.c.o.d"
  "test_noalloc"
  "test_noalloc.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang C)
  include(CMakeFiles/test_noalloc.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
