file(REMOVE_RECURSE
  "../libtrigspline.pdb"
  "../libtrigspline.so"
  "../libtrigspline.so.0.2"
  "../libtrigspline.so.0.2.0"
)

# Per-language clean rules from dependency scanning.
foreach(lang C)
  include(CMakeFiles/trigspline_shared.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
