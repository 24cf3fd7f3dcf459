file(REMOVE_RECURSE
  "libtrigspline_cli_lib.a"
)
