#!/bin/sh
# The R package's tests for tests/run_all.sh: stage the package
# (bindings/r/stage.sh), install it into a temporary library, run its
# testthat suite and the smoke test (bindings/r/smoke.R); given a CMake
# build directory (run.sh BUILD), also the bit-identity check against its
# libtrigspline.a (bits.c, bits.R).  Prints "r: N passed, M failed".  Needs
# R and testthat (make r-deps).
set -u
here=$(cd "$(dirname "$0")/.." && pwd)
build=""
[ $# -ge 1 ] && build=$(cd "$1" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT INT TERM
if ! command -v Rscript >/dev/null 2>&1; then
    echo "Rscript not found (make r-deps)"; echo "r: 0 passed, 1 failed"; exit 1
fi
"$here/stage.sh" "$tmp/stage" >/dev/null || { echo "r: 0 passed, 1 failed"; exit 1; }
mkdir "$tmp/lib"
if ! MAKEFLAGS=-j2 R CMD INSTALL --no-docs --no-multiarch -l "$tmp/lib" "$tmp/stage/trigspline" \
        >"$tmp/install.log" 2>&1; then
    tail -n 30 "$tmp/install.log"; echo "r: 0 passed, 1 failed"; exit 1
fi
cd "$tmp"
R_LIBS="$tmp/lib" Rscript --vanilla - "$tmp/stage/trigspline/tests/testthat" >"$tmp/testthat.log" 2>&1 <<'REOF'
suppressMessages(library(testthat))
library(trigspline)
res <- as.data.frame(test_dir(commandArgs(TRUE)[1], reporter = "summary",
                              stop_on_failure = FALSE))
failed <- sum(res$failed) + sum(res$error)
cat(sprintf("testthat: %d passed, %d failed\n", sum(res$passed), failed))
quit(status = failed > 0)
REOF
rc=$?
cat "$tmp/testthat.log"
p=$(sed -n 's/^testthat: \([0-9]*\) passed, \([0-9]*\) failed$/\1/p' "$tmp/testthat.log")
f=$(sed -n 's/^testthat: \([0-9]*\) passed, \([0-9]*\) failed$/\2/p' "$tmp/testthat.log")
[ -n "$p" ] || { p=0; f=1; }
[ "$rc" -eq 0 ] || [ "$f" -gt 0 ] || f=1
if R_LIBS="$tmp/lib" Rscript --vanilla "$here/smoke.R"; then p=$((p + 1)); else f=$((f + 1)); fi
# (a sanitizer build's library needs its runtime: not linked here)
if [ -n "$build" ] && grep -q '^TS_SANITIZE:BOOL=ON' "$build/CMakeCache.txt" 2>/dev/null; then
    echo "bit-identity check skipped: $build is a sanitizer build"
elif [ -n "$build" ] && [ -f "$build/libtrigspline.a" ]; then
    if cc -std=c11 -O2 -I"$here/../../include" -I"$build/include" "$here/tests/bits.c" \
           "$build/libtrigspline.a" -lm -lpthread -o "$tmp/bits" &&
       R_LIBS="$tmp/lib" Rscript --vanilla "$here/tests/bits.R" "$tmp/bits" >"$tmp/bits.log" 2>&1; then
        :
    fi
    cat "$tmp/bits.log" 2>/dev/null
    bp=$(sed -n 's/^bits: \([0-9]*\) passed, \([0-9]*\) failed$/\1/p' "$tmp/bits.log" 2>/dev/null)
    bf=$(sed -n 's/^bits: \([0-9]*\) passed, \([0-9]*\) failed$/\2/p' "$tmp/bits.log" 2>/dev/null)
    [ -n "$bp" ] || { bp=0; bf=1; }
    p=$((p + bp)); f=$((f + bf))
fi
echo "r: $p passed, $f failed"
[ "$f" -eq 0 ]
