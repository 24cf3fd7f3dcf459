#!/usr/bin/env bash
# The web tests: node --test on the Node and browser tests, then the closing
# line "N passed, M failed" (tests/run_all.sh convention).
#   run.sh OUT_WEB WEB_BUILD NATIVE_BUILD ARTIFACTS [CHARTS]
# OUT_WEB: out/web (make web); WEB_BUILD: build-web (the musl reference and
# CLI); NATIVE_BUILD: build (the shipped CLI); ARTIFACTS: screenshot, timings;
# CHARTS: out/charts (the gallery, make charts-demo; its test is skipped
# without it).
set -u
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../../.." && pwd)
abs() { (cd "$1" && pwd); }
mkdir -p "$4"
export TS_WEB_OUT=$(abs "$1")
export TS_WEB_REF=$(abs "$2")/reference.bin
export TS_WEB_REFBIN=$(abs "$2")/reference-musl
export TS_WEB_CLI=$(abs "$2")/trigspline-musl
export TS_WEB_CLI_SHIPPED=$(abs "$3")/trigspline
export TS_WEB_ARTIFACTS=$(abs "$4")
export TS_HEADER=$root/include/trigspline.h
charts_test=()
if [ -n "${5:-}" ]; then export TS_CHARTS_PAGE=$(abs "$5")/index.html; charts_test=("$here/charts.test.mjs"); fi
"$TS_WEB_REFBIN" "$TS_WEB_REF" || { echo "reference values not written"; echo "0 passed, 1 failed"; exit 1; }
out=$(node --test --test-reporter=tap "$here/node.test.mjs" "$here/stack.test.mjs" "$here/types.test.mjs" "$here/browser.test.mjs" "$here/explorer_data.test.mjs" "$here/readme_size.test.mjs" "$here/histo.test.mjs" "$here/simd.test.mjs" "${charts_test[@]}" 2>&1); rc=$?
printf '%s\n' "$out" | grep -E '^(not )?ok |^# [^\\]|^# \\#|# [a-z ]+:' | grep -v '^# Subtest'
pass=$(printf '%s\n' "$out" | sed -n 's/^# pass \([0-9]*\)$/\1/p' | tail -n 1)
fail=$(printf '%s\n' "$out" | sed -n 's/^# fail \([0-9]*\)$/\1/p' | tail -n 1)
if [ -z "$pass" ] || [ -z "$fail" ]; then printf '%s\n' "$out" | tail -n 40; pass=${pass:-0}; fail=$((${fail:-0} + 1)); fi
if [ "$rc" -ne 0 ] && [ "$fail" -eq 0 ]; then printf '%s\n' "$out" | tail -n 40; fail=1; fi
if [ "$fail" -ne 0 ]; then printf '%s\n' "$out" | grep -v '^ *at ' | grep -A30 '^not ok' | head -n 120; fi
echo "web: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
