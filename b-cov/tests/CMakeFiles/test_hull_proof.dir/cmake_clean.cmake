file(REMOVE_RECURSE
  "CMakeFiles/test_hull_proof.dir/api/test_hull_proof.c.o"
  "CMakeFiles/test_hull_proof.dir/api/test_hull_proof.c.o.d"
  "test_hull_proof"
  "test_hull_proof.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang C)
  include(CMakeFiles/test_hull_proof.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
