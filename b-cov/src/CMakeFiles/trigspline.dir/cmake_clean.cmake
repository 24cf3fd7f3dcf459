file(REMOVE_RECURSE
  "../libtrigspline.a"
  "../libtrigspline.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang C)
  include(CMakeFiles/trigspline.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
