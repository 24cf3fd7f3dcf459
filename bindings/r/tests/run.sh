#!/bin/sh
# The R package's tests for tests/run_all.sh: stage the package
# (bindings/r/stage.sh), install it into a temporary library, run its
# testthat suite and the smoke test (bindings/r/smoke.R).  Prints
# "r: N passed, M failed".  Needs R and testthat (make r-deps).
set -u
here=$(cd "$(dirname "$0")/.." && pwd)
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
echo "r: $p passed, $f failed"
[ "$f" -eq 0 ]
