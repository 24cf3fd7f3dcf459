#!/bin/bash
# libtrigspline: the CMake build and install into $PREFIX (conda-build sets
# CC, CFLAGS, CMAKE_ARGS for the target platform).
set -euxo pipefail
cmake -S . -B build-conda ${CMAKE_ARGS} -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_INSTALL_PREFIX="${PREFIX}" -DCMAKE_INSTALL_LIBDIR=lib \
  -DTS_WERROR=OFF -DTS_BUILD_TESTS=OFF -DTS_BUILD_EXAMPLES=OFF -DTS_BUILD_BENCH=OFF
cmake --build build-conda -j "${CPU_COUNT}"
cmake --install build-conda
