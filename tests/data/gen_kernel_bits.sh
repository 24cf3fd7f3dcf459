#!/bin/sh
# Writes tests/data/kernel_bits.txt, the table tests/unit/test_kernel_bits.c
# checks the batch kernels against: per query the portable kernel's bits,
# the FMA kernels' as GCC compiles them and as Clang does, from a GCC and a
# Clang build's `test_kernel_bits --write` (on a CPU with AVX-512F; the
# AVX2+FMA and AVX-512F kernels must agree).  The committed table was
# written from the library as it was before the kernels' staging was
# rewritten (main at 654c856; GCC 12.2 Release, Clang RelWithDebInfo builds);
# run it again only if the kernels' results are meant to change.
#   tests/data/gen_kernel_bits.sh GCC_BUILD_DIR CLANG_BUILD_DIR
set -eu
gcc_build=${1:?usage: gen_kernel_bits.sh GCC_BUILD_DIR CLANG_BUILD_DIR}
clang_build=${2:?usage: gen_kernel_bits.sh GCC_BUILD_DIR CLANG_BUILD_DIR}
here=$(cd "$(dirname "$0")" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$gcc_build/tests/test_kernel_bits" --write > "$tmp/gcc"
"$clang_build/tests/test_kernel_bits" --write > "$tmp/clang"
awk 'NR == FNR { if (!/^#/) c[$1" "$2" "$3" "$4] = $6; next }
     /^#/ { print "# spline deriv order index portable fma_gcc fma_clang (tests/unit/test_kernel_bits.c)"; next }
     { k = $1" "$2" "$3" "$4
       if ($6 != $7 || $6 == "-") { print "AVX2 and AVX-512F differ or are missing at " k > "/dev/stderr"; exit 1 }
       print k, $5, $6, c[k] }' "$tmp/clang" "$tmp/gcc" > "$tmp/table"
awk '!/^#/ && $7 == "" { exit 1 }' "$tmp/table"
mv "$tmp/table" "$here/kernel_bits.txt"
