#!/bin/sh
# The R package as a distributable artifact (bindings/r).
#   r.sh build DISTDIR   stage the package (bindings/r/stage.sh) and
#                        R CMD build it: DISTDIR/trigspline_VERSION.tar.gz,
#                        VERSION from project() in CMakeLists.txt
#   r.sh test DISTDIR    install that tarball into a temporary library
#                        (R CMD INSTALL -l) and run the smoke test from
#                        another directory; with R_CHECK=1 also
#                        R CMD check --as-cran on it (tests included)
# Needs R (Debian r-base-dev) and, for R_CHECK=1, testthat (r-cran-testthat):
# `make r-deps` installs both.
set -eu
[ $# -eq 2 ] || { echo "usage: $0 build|test DISTDIR" >&2; exit 2; }
cmd=$1
root=$(cd "$(dirname "$0")/../.." && pwd)
mkdir -p "$2"
dist=$(cd "$2" && pwd)
version=$(sed -n 's/^project(trigspline VERSION \([0-9.]*\).*/\1/p' "$root/CMakeLists.txt")
tarball=$dist/trigspline_$version.tar.gz
command -v R >/dev/null || { echo "$0: R not found (make r-deps)" >&2; exit 1; }

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT INT TERM

case $cmd in
build)
    "$root/bindings/r/stage.sh" "$tmp/stage" >/dev/null
    # --no-build-vignettes: there are none; the tarball holds no objects
    (cd "$tmp" && R CMD build --no-build-vignettes stage/trigspline >build.log 2>&1) ||
        { cat "$tmp/build.log" >&2; exit 1; }
    mv "$tmp/trigspline_$version.tar.gz" "$tarball"
    echo "artifact: ${tarball#"$dist"/} $(wc -c < "$tarball")"
    ;;
test)
    [ -f "$tarball" ] || { echo "$0: $tarball missing (r.sh build first)" >&2; exit 1; }
    mkdir "$tmp/lib"
    R CMD INSTALL -l "$tmp/lib" "$tarball" >"$tmp/install.log" 2>&1 ||
        { cat "$tmp/install.log" >&2; exit 1; }
    # the smoke test, from a directory without the sources
    cd "$tmp"
    R_LIBS="$tmp/lib" Rscript --vanilla "$root/bindings/r/smoke.R"
    if [ "${R_CHECK:-0}" = 1 ]; then
        # The PDF manual needs LaTeX, which r-base-dev does not bring:
        # checked where pdflatex is installed (without the inconsolata font,
        # 1.4 GB of texlive-fonts-extra, when that is missing), else skipped.
        manual=--no-manual
        if command -v pdflatex >/dev/null 2>&1; then
            manual=
            kpsewhich zi4.sty >/dev/null 2>&1 || kpsewhich inconsolata.sty >/dev/null 2>&1 ||
                export R_RD4PDF=times,hyper
        fi
        MAKEFLAGS=-j2 R CMD check --as-cran $manual --output="$tmp" "$tarball" \
            >"$tmp/check.log" 2>&1 || true
        # the tail, and every NOTE / WARNING / ERROR with its explanation
        tail -n 25 "$tmp/check.log"
        echo "---- R CMD check: notes, warnings, errors"
        awk '/^\* / {show = 0; item = $0}
             /(\.\.\.|^) *(NOTE|WARNING|ERROR)$/ {show = 1; if (item != $0) print item}
             show' "$tmp/check.log"
        if grep -q "^Status: .*\(ERROR\|WARNING\)" "$tmp/check.log"; then
            echo "$0: R CMD check failed" >&2
            exit 1
        fi
        # NOTEs allowed: only the two that need the network (CRAN's package
        # index for the incoming checks; a time server for the timestamps)
        other=$(awk '/^\* / {item = $0} /(\.\.\.|^) *NOTE$/ {print item}' "$tmp/check.log" |
                grep -v -e 'checking CRAN incoming feasibility' \
                        -e 'checking for future file timestamps' || true)
        if [ -n "$other" ]; then
            echo "$0: R CMD check NOTEs: $other" >&2
            exit 1
        fi
    fi
    ;;
*)
    echo "usage: $0 build|test DISTDIR" >&2; exit 2 ;;
esac
