file(REMOVE_RECURSE
  "CMakeFiles/test_error_message.dir/unit/test_error_message.c.o"
  "CMakeFiles/test_error_message.dir/unit/test_error_message.c.o.d"
  "test_error_message"
  "test_error_message.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang C)
  include(CMakeFiles/test_error_message.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
