file(REMOVE_RECURSE
  "../libtrigspline.a"
)
