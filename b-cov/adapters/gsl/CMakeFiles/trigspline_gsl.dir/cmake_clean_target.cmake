file(REMOVE_RECURSE
  "libtrigspline_gsl.a"
)
