#!/bin/sh
# Stage the R package: stage.sh OUTDIR writes OUTDIR/trigspline, the package
# of bindings/r/trigspline completed with the library's C sources (the ones
# src/CMakeLists.txt lists in TS_LIBRARY_SOURCES, plus src/internal.h and
# include/trigspline.h), the generated trigspline_version.h, the version of
# CMakeLists.txt's project() in DESCRIPTION and kernels.c's compile options
# in src/Makevars.  R packages must be self-contained, so the staged tree is
# what `R CMD build` / `R CMD INSTALL` take.
set -eu
[ $# -eq 1 ] || { echo "usage: $0 OUTDIR" >&2; exit 2; }
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
out=$1/trigspline

version=$(sed -n 's/^project(trigspline VERSION \([0-9.]*\).*/\1/p' "$root/CMakeLists.txt")
[ -n "$version" ] || { echo "$0: no version in CMakeLists.txt project()" >&2; exit 1; }
major=${version%%.*}; rest=${version#*.}; minor=${rest%%.*}; patch=${rest#*.}

# TS_LIBRARY_SOURCES of src/CMakeLists.txt, comments dropped, except
# deprecated.c: the package exports no C symbols, so the forwarding
# wrappers of the 0.1 names (and the pragma that compiles them, which
# R CMD check --as-cran reports) are not needed
sources=$(sed -n '/^set(TS_LIBRARY_SOURCES/,/^)/p' "$root/src/CMakeLists.txt" |
          sed 's/#.*//' | grep -o '[A-Za-z0-9_]*\.c' | grep -vx 'deprecated\.c')
[ -n "$sources" ] || { echo "$0: no TS_LIBRARY_SOURCES in src/CMakeLists.txt" >&2; exit 1; }
# kernels.c's COMPILE_OPTIONS (the call spans lines: join them first)
kflags=$(tr '\n' ' ' < "$root/src/CMakeLists.txt" |
         sed -n 's/.*kernels\.c[ ]*PROPERTIES COMPILE_OPTIONS "\([^"]*\)".*/\1/p' | tr ';' ' ')
[ -n "$kflags" ] || { echo "$0: kernels.c's options not found in src/CMakeLists.txt" >&2; exit 1; }

rm -rf "$out"
mkdir -p "$out"
cp -R "$here/trigspline/." "$out/"
rm -f "$out/src/Makevars.in" "$out/DESCRIPTION"
sed "s/@VERSION@/$version/" "$here/trigspline/DESCRIPTION" > "$out/DESCRIPTION"
sed "s|@TS_KERNEL_FLAGS@|$kflags|" "$here/trigspline/src/Makevars.in" > "$out/src/Makevars"
for f in $sources; do
    case "$f" in r_*) echo "$0: library source $f clashes with the package's r_*.c" >&2; exit 1;; esac
    cp "$root/src/$f" "$out/src/$f"
done
cp "$root/src/internal.h" "$root/include/trigspline.h" "$out/src/"
sed -e "s/@PROJECT_VERSION_MAJOR@/$major/g" -e "s/@PROJECT_VERSION_MINOR@/$minor/g" \
    -e "s/@PROJECT_VERSION_PATCH@/$patch/g" "$root/cmake/trigspline_version.h.in" \
    > "$out/src/trigspline_version.h"
if grep -q '@' "$out/src/trigspline_version.h"; then
    echo "$0: cmake/trigspline_version.h.in has a variable this script does not fill" >&2; exit 1
fi
echo "$out"
