file(REMOVE_RECURSE
  "libtrigspline_support.a"
)
