#!/bin/sh
# Python channel: the sdist and a wheel of bindings/python.
#   build: the sdist (setuptools' PEP 517 backend, in-process: no isolated
#          environment), then the wheel *from that sdist* with
#          `pip wheel --no-build-isolation` in a venv made with
#          --system-site-packages: no index is reachable here, so the build
#          requirements pyproject.toml declares (setuptools, wheel, numpy)
#          are Debian's.  (Build isolation from an index is exercised by
#          bindings/python/tests/test_install.py with a local wheelhouse.)
#          manylinux/musllinux wheels: cibuildwheel (pyproject.toml), which
#          needs Docker and PyPI: not run here.
#   test:  the wheel installed into a fresh venv (--system-site-packages for
#          Debian's numpy; --no-index), its metadata checked, the smoke test
#          run from another directory; the sdist's contents checked.
. "$(dirname "$0")/lib/common.sh"
ts_setup python "$2"
PY=/usr/bin/python3
ts_need "$PY:python3" /usr/lib/python3/dist-packages/numpy/__init__.py:python3-numpy \
    /usr/lib/python3/dist-packages/setuptools/__init__.py:python3-setuptools \
    /usr/lib/python3/dist-packages/wheel/__init__.py:python3-wheel \
    /usr/lib/python3/dist-packages/pip/__init__.py:python3-pip \
    /usr/include/python3.11/Python.h:python3-dev /usr/lib/python3.11/ensurepip/__init__.py:python3-venv
PKG=$TS_ROOT/bindings/python
SDIST=$TS_DIST/trigspline-$TS_VERSION.tar.gz
export PIP_NO_INDEX=1 PIP_DISABLE_PIP_VERSION_CHECK=1
unset PIP_FIND_LINKS PYTHONPATH

case $1 in
build)
    rm -f "$SDIST" "$TS_DIST"/trigspline-"$TS_VERSION"-*.whl
    # the sdist, built in a copy of the package directory so that the
    # source tree gets no egg-info (setup.py finds the library at ../..: the
    # copy sits at the same depth of an exported tree)
    ts_export_tree "$TS_WORK/tree"
    (cd "$TS_WORK/tree/bindings/python" &&
        "$PY" -c 'import sys, setuptools.build_meta as b; print(b.build_sdist(sys.argv[1]))' \
            "$TS_DIST") >"$TS_WORK/sdist.log" 2>&1 || { cat "$TS_WORK/sdist.log"; exit 1; }
    rm -rf "$TS_WORK/venv"
    "$PY" -m venv --system-site-packages "$TS_WORK/venv"
    "$TS_WORK/venv/bin/pip" wheel -q --no-build-isolation --no-deps -w "$TS_DIST" "$SDIST" \
        >"$TS_WORK/wheel.log" 2>&1 || { cat "$TS_WORK/wheel.log"; exit 1; }
    ts_artifact "$SDIST" "$TS_DIST"/trigspline-"$TS_VERSION"-*.whl
    echo "note: manylinux/musllinux wheels: cibuildwheel (bindings/python/pyproject.toml), not run here (needs Docker and PyPI)"
    ;;
test)
    whl=$(ls "$TS_DIST"/trigspline-"$TS_VERSION"-*.whl)
    ok=0
    # the sdist: the package, its C sources and the library's copy, LICENSE
    list=$(tar tzf "$SDIST")
    for f in pyproject.toml setup.py LICENSE src/_core.c trigspline/__init__.py trigspline/py.typed \
             csrc/src/spline.c csrc/src/internal.h csrc/include/trigspline.h csrc/CMakeLists.txt; do
        printf '%s\n' "$list" | grep -qx "trigspline-$TS_VERSION/$f" ||
            { echo "sdist lacks $f"; ok=1; }
    done
    # the wheel's metadata: Requires-Python, numpy, the licence
    meta=$("$PY" - "$whl" <<'PYEOF'
import sys, zipfile
z = zipfile.ZipFile(sys.argv[1])
names = z.namelist()
md = next(n for n in names if n.endswith(".dist-info/METADATA"))
print(z.read(md).decode())
print("FILES:", " ".join(n for n in names if n.endswith((".so", "LICENSE", "py.typed"))))
PYEOF
) || ok=1
    for want in "Requires-Python: >=3.9" "Requires-Dist: numpy" "License: BSD-3-Clause" \
                "Classifier: License :: OSI Approved :: BSD License" ".dist-info/LICENSE" \
                "trigspline/_core." "trigspline/_gufunc." "trigspline/py.typed"; do
        printf '%s\n' "$meta" | grep -qF "$want" || { echo "wheel metadata lacks: $want"; ok=1; }
    done
    echo "wheel: $(printf '%s\n' "$meta" | grep -E '^(Requires-Python|Requires-Dist: numpy|License)' | tr '\n' ';')"
    rm -rf "$TS_WORK/test-venv" "$TS_WORK/elsewhere"
    "$PY" -m venv --system-site-packages "$TS_WORK/test-venv"
    "$TS_WORK/test-venv/bin/pip" install -q --no-index "$whl" || exit 1
    mkdir -p "$TS_WORK/elsewhere"
    (cd "$TS_WORK/elsewhere" && env -i PATH=/usr/bin:/bin "$TS_WORK/test-venv/bin/python" \
        "$TS_SMOKE/smoke.py" --expect-prefix "$TS_WORK/test-venv") || ok=1
    exit $ok
    ;;
*) echo "usage: $0 build|test DISTDIR" >&2; exit 2 ;;
esac
