#!/bin/sh
# Writes tests/data/kernel_bits.txt, the table tests/unit/test_kernel_bits.c
# checks the batch kernels against, from a build's test_kernel_bits --write
# (the portable kernel).  The committed table was written from the library
# as it was before the kernels' staging was rewritten (main at 654c856),
# built with `cmake -DCMAKE_BUILD_TYPE=Release`; run it again only if the
# kernels' results are meant to change.
#   tests/data/gen_kernel_bits.sh BUILD_DIR
set -eu
build=${1:?usage: gen_kernel_bits.sh BUILD_DIR}
here=$(cd "$(dirname "$0")" && pwd)
"$build/tests/test_kernel_bits" --write > "$here/kernel_bits.txt.tmp"
mv "$here/kernel_bits.txt.tmp" "$here/kernel_bits.txt"
