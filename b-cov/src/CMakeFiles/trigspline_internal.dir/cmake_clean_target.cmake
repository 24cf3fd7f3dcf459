file(REMOVE_RECURSE
  "../libtrigspline_internal.a"
)
