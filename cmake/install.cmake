# Install rules: the libraries, the header, the man page, the licence, the CMake package
# (trigsplineConfig.cmake, ...ConfigVersion.cmake, trigsplineTargets.cmake)
# and trigspline.pc.  Included from the top-level CMakeLists.txt when TS_INSTALL.
include(CMakePackageConfigHelpers)

set(TS_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/trigspline)

install(TARGETS trigspline trigspline_shared EXPORT trigsplineTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} NAMELINK_COMPONENT Development
  RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(FILES ${PROJECT_SOURCE_DIR}/include/trigspline.h
              ${TS_GENERATED_INCLUDE_DIR}/trigspline_version.h
  DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(FILES ${PROJECT_SOURCE_DIR}/docs/trigspline.1
  DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
# The licence travels with the binaries (share/doc/trigspline/LICENSE).
install(FILES ${PROJECT_SOURCE_DIR}/LICENSE
  DESTINATION ${CMAKE_INSTALL_DOCDIR})

install(EXPORT trigsplineTargets NAMESPACE trigspline::
  FILE trigsplineTargets.cmake DESTINATION ${TS_CMAKE_DIR})

# What the static library needs besides itself, read from the target so that
# the package files follow src/CMakeLists.txt (e.g. when threads go away).
get_target_property(TS_STATIC_DEPS trigspline INTERFACE_LINK_LIBRARIES)
set(TS_NEEDS_THREADS OFF)
set(TS_PC_LIBS_PRIVATE "")
if("m" IN_LIST TS_STATIC_DEPS)
  string(APPEND TS_PC_LIBS_PRIVATE " -lm")
endif()
if("Threads::Threads" IN_LIST TS_STATIC_DEPS)
  set(TS_NEEDS_THREADS ON)
  string(APPEND TS_PC_LIBS_PRIVATE " -lpthread")
endif()
string(STRIP "${TS_PC_LIBS_PRIVATE}" TS_PC_LIBS_PRIVATE)

configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/trigsplineConfig.cmake.in
  ${PROJECT_BINARY_DIR}/cmake/trigsplineConfig.cmake
  INSTALL_DESTINATION ${TS_CMAKE_DIR})
# Compatible versions (docs/versions.md): the same major from 1.0 on; before
# 1.0 the same minor (0.x minor releases may break API and ABI).
if(PROJECT_VERSION_MAJOR EQUAL 0)
  set(TS_COMPATIBILITY SameMinorVersion)
else()
  set(TS_COMPATIBILITY SameMajorVersion)
endif()
write_basic_package_version_file(${PROJECT_BINARY_DIR}/cmake/trigsplineConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY ${TS_COMPATIBILITY})
install(FILES ${PROJECT_BINARY_DIR}/cmake/trigsplineConfig.cmake
              ${PROJECT_BINARY_DIR}/cmake/trigsplineConfigVersion.cmake
  DESTINATION ${TS_CMAKE_DIR})

# trigspline.pc carries absolute paths of the prefix it is installed under,
# which is known only at install time (cmake --install --prefix P): the
# template is filled in two steps, the prefix last, by the install script.
foreach(d LIBDIR INCLUDEDIR)
  if(IS_ABSOLUTE "${CMAKE_INSTALL_${d}}")
    set(TS_PC_${d} "${CMAKE_INSTALL_${d}}")
  else()
    set(TS_PC_${d} "\${prefix}/${CMAKE_INSTALL_${d}}")
  endif()
endforeach()
set(TS_PC_PREFIX "@TS_PC_PREFIX@")  # kept for the second step
configure_file(${PROJECT_SOURCE_DIR}/cmake/trigspline.pc.in
  ${PROJECT_BINARY_DIR}/cmake/trigspline.pc.in @ONLY)
install(CODE "
  set(TS_PC_PREFIX \"\${CMAKE_INSTALL_PREFIX}\")
  configure_file(\"${PROJECT_BINARY_DIR}/cmake/trigspline.pc.in\"
                 \"${PROJECT_BINARY_DIR}/cmake/trigspline.pc\" @ONLY)")
install(FILES ${PROJECT_BINARY_DIR}/cmake/trigspline.pc
  DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
