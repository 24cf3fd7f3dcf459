#----------------------------------------------------------------
# Generated CMake target import file for configuration "Debug".
#----------------------------------------------------------------

# Commands may need to know the format version.
set(CMAKE_IMPORT_FILE_VERSION 1)

# Import target "trigspline::trigspline_static" for configuration "Debug"
set_property(TARGET trigspline::trigspline_static APPEND PROPERTY IMPORTED_CONFIGURATIONS DEBUG)
set_target_properties(trigspline::trigspline_static PROPERTIES
  IMPORTED_LINK_INTERFACE_LANGUAGES_DEBUG "C"
  IMPORTED_LOCATION_DEBUG "${_IMPORT_PREFIX}/lib/libtrigspline.a"
  )

list(APPEND _cmake_import_check_targets trigspline::trigspline_static )
list(APPEND _cmake_import_check_files_for_trigspline::trigspline_static "${_IMPORT_PREFIX}/lib/libtrigspline.a" )

# Import target "trigspline::trigspline" for configuration "Debug"
set_property(TARGET trigspline::trigspline APPEND PROPERTY IMPORTED_CONFIGURATIONS DEBUG)
set_target_properties(trigspline::trigspline PROPERTIES
  IMPORTED_LOCATION_DEBUG "${_IMPORT_PREFIX}/lib/libtrigspline.so.0.2.0"
  IMPORTED_SONAME_DEBUG "libtrigspline.so.0.2"
  )

list(APPEND _cmake_import_check_targets trigspline::trigspline )
list(APPEND _cmake_import_check_files_for_trigspline::trigspline "${_IMPORT_PREFIX}/lib/libtrigspline.so.0.2.0" )

# Commands beyond this point should not need to know the version.
set(CMAKE_IMPORT_FILE_VERSION)
