file(REMOVE_RECURSE
  "CMakeFiles/test_vocab.dir/unit/test_vocab.c.o"
  "CMakeFiles/test_vocab.dir/unit/test_vocab.c.o.d"
  "test_vocab"
  "test_vocab.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang C)
  include(CMakeFiles/test_vocab.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
