#!/usr/bin/env bash
# The Python package's tests as a user gets the package: install it with pip
# (no build isolation, warnings are errors) into a fresh venv made by Debian's
# python3 with --system-site-packages (numpy, scipy, pytest from Debian), then
# run pytest from outside the source tree (no index is reachable: Debian's
# setuptools, wheel and numpy build it).  test_install.py also installs it a
# second time with plain `pip install` (build isolation) into a venv without
# system site-packages, from a local wheelhouse standing in for PyPI.
#   bindings/python/tests/run.sh BUILD_DIR
# BUILD_DIR: the CMake build whose libtrigspline.so test_clib.py compares
# against; the venv goes to BUILD_DIR/python-venv.  Last line:
# "pytest: N passed, M failed"; exit status 0 only if pytest passed.
set -u
here=$(cd "$(dirname "$0")" && pwd)
pkg=$(dirname "$here")
build=$(cd "${1:-build}" && pwd)
py=/usr/bin/python3
venv="$build/python-venv"
rm -rf "$venv"
"$py" -m venv --system-site-packages "$venv" || { echo "pytest: 0 passed, 1 failed"; exit 1; }
if ! env -u PIP_FIND_LINKS PIP_NO_INDEX=1 CFLAGS="-Werror" \
    "$venv/bin/pip" install -q --no-build-isolation "$pkg" >"$build/python-install.log" 2>&1; then
    cat "$build/python-install.log"
    echo "pytest: 0 passed, 1 failed"
    exit 1
fi
out=$(cd "$build" && TS_BUILD_DIR="$build" "$venv/bin/python" -m pytest -p no:cacheprovider \
      -q -rfEs "$here" 2>&1)
rc=$?
printf '%s\n' "$out"
summary=$(printf '%s\n' "$out" | tail -n 1)
p=$(printf '%s' "$summary" | grep -oE '[0-9]+ passed' | grep -oE '[0-9]+' || echo 0)
f=0
for k in $(printf '%s' "$summary" | grep -oE '[0-9]+ (failed|errors?)' | grep -oE '[0-9]+'); do
    f=$((f + k))
done
if [ "$rc" -ne 0 ] && [ "$f" -eq 0 ]; then f=1; fi
echo "pytest: $p passed, $f failed"
exit $rc
