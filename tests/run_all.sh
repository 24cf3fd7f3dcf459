#!/usr/bin/env bash
# Runs every test program of each build directory given (BUILD/tests/test_*:
# the programs of tests/api/, tests/unit/, tests/tools/ all land there), the
# valgrind leak checks, the script tests (scripts/check_layers.py,
# scripts/check_abi.py, tests/test_*.py and tests/tools/test_*.py) and the Python package's pytest run
# (bindings/python/tests/run.sh), the R package's tests (bindings/r/tests/run.sh)
# and the version check (tests/check_version.py)
# against the first; prints each program's line and,
# last, the sum as "total: N passed, M failed".  Exit status 0 only if nothing
# failed.
set -u
here=$(cd "$(dirname "$0")" && pwd)
pass=0; fail=0; status=0
run_one() { # label, command...
    local label=$1; shift
    local out rc line p f
    out=$("$@" 2>&1); rc=$?
    line=$(printf '%s\n' "$out" | grep -E '[0-9]+ passed, [0-9]+ failed' | tail -n 1)
    if [ -n "$line" ]; then
        p=$(printf '%s' "$line" | sed -E 's/.* ([0-9]+) passed, ([0-9]+) failed.*/\1/')
        f=$(printf '%s' "$line" | sed -E 's/.* ([0-9]+) passed, ([0-9]+) failed.*/\2/')
    else
        p=0; f=1
    fi
    if [ "$rc" -ne 0 ] && [ "$f" -eq 0 ]; then f=1; fi
    pass=$((pass + p)); fail=$((fail + f))
    if [ "$f" -ne 0 ] || [ "$rc" -ne 0 ]; then
        status=1
        printf '%s\n' "$out" | tail -n 40
        echo "[$label] FAILED (exit $rc)"
    else
        echo "[$label] $p passed, 0 failed"
    fi
}
first=""
for dir in "$@"; do
    [ -z "$first" ] && first=$dir
    for t in "$dir"/tests/test_*; do
        [ -x "$t" ] || continue
        run_one "$(basename "$dir")/$(basename "$t")" "$t"
    done
done
# Leak check of the core programs under valgrind (memcheck), when installed.
if [ -n "$first" ] && command -v valgrind >/dev/null 2>&1; then
    for name in test_core test_errors test_basis test_slopes test_shape test_geometric test_noalloc; do
        [ -x "$first/tests/$name" ] || continue
        run_one "valgrind/$name" valgrind -q --leak-check=full --errors-for-leak-kinds=all \
            --error-exitcode=9 "$first/tests/$name"
    done
fi
if [ -n "$first" ]; then
    run_one "script/check_layers.py" python3 "$here/../scripts/check_layers.py" "$here/.."
    # exported symbols, struct layouts and enum values against abi/trigspline.abi
    run_one "script/check_abi.py" python3 "$here/../scripts/check_abi.py" "$first"
    for py in "$here"/test_*.py "$here"/tools/test_*.py; do
        [ -f "$py" ] || continue
        run_one "script/$(basename "$py")" python3 "$py" "$first"
    done
    # The Python package: installed into a fresh venv, pytest (its own closing line)
    if [ -x "$here/../bindings/python/tests/run.sh" ]; then
        run_one "pytest/bindings/python" "$here/../bindings/python/tests/run.sh" "$first"
    fi
    # The R package: staged, installed into a temporary library, testthat and
    # the smoke test, and its values bit for bit against the library of the
    # first build (bindings/r/tests/run.sh; R and testthat: make r-deps)
    run_one "r/bindings/r" "$here/../bindings/r/tests/run.sh" "$first"
    # Every stated version against CMakeLists.txt (after pytest: its venv has the package)
    run_one "script/check_version.py" python3 "$here/check_version.py" "$first"
fi
echo "total: $pass passed, $fail failed"
exit $status
