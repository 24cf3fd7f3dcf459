#!/bin/sh
# Debian channel: debian/ builds libtrigspline0.2 (the soname is
# libtrigspline.so.0.2 before 1.0, docs/versions.md, so Debian's naming rule
# gives that name), libtrigspline-dev, trigspline (the command and its man
# page) and python3-trigspline.
#   build: `dpkg-buildpackage -us -uc -b` in an exported copy of the tree,
#          lintian on the result (fails on any error or warning; overrides,
#          if any, in debian/*.lintian-overrides with their reasons), the
#          symbols file checked against abi/trigspline.abi.
#   test:  a throwaway root: an overlay of this system (lower, read-only: the
#          packages' dependencies are installed here) in a private mount
#          namespace, entered with chroot; `dpkg -i` of the four packages,
#          the smoke test of the C library (pkg-config), the command (its man
#          page installed) and the Python module, then `dpkg --purge`.  The
#          overlay is discarded: nothing is installed on this system.
#   symbols: rewrites debian/libtrigspline0.2.symbols from abi/trigspline.abi
#          (after a change of the ABI; check_abi.py --update first).
. "$(dirname "$0")/lib/common.sh"
ts_setup debian "$2"
ARCH=$(dpkg --print-architecture 2>/dev/null || echo amd64)
DEBV=$(sed -n '1s/^trigspline (\([^)]*\)).*/\1/p' "$TS_ROOT/debian/changelog")
LIBPKG=libtrigspline0.2
SYMBOLS=$TS_ROOT/debian/$LIBPKG.symbols
OUT=$TS_DIST/debian
PACKAGES="$LIBPKG libtrigspline-dev trigspline python3-trigspline"

abi_symbols() {
    sed -n 's/^symbol \(.*\)$/\1/p' "$TS_ROOT/abi/trigspline.abi" | sort
}

case $1 in
symbols)
    # the library's exported functions (abi/trigspline.abi), each since the
    # upstream version that has it (all 0.2.0: the first packaged release)
    { echo "libtrigspline.so.0.2 $LIBPKG #MINVER#"
      echo "* Build-Depends-Package: libtrigspline-dev"
      abi_symbols | sed 's/^\(.*\)$/ \1@Base 0.2.0/'; } >"$SYMBOLS"
    echo "wrote $SYMBOLS"
    ;;
build)
    ts_need dpkg-buildpackage:dpkg-dev dh:debhelper dh_python3:dh-python lintian:lintian \
        cmake:cmake /usr/share/doc/python3-all-dev:python3-all-dev \
        /usr/lib/python3/dist-packages/numpy/__init__.py:python3-numpy \
        /usr/lib/python3/dist-packages/setuptools/__init__.py:python3-setuptools \
        /usr/lib/python3/dist-packages/wheel/__init__.py:python3-wheel
    ok=0
    # the symbols file lists exactly the exported functions of the ABI file
    if [ "$(sed -n 's/^ \([^@]*\)@Base .*/\1/p' "$SYMBOLS" | sort)" != "$(abi_symbols)" ]; then
        echo "debian/$LIBPKG.symbols differs from abi/trigspline.abi: run tools/dist/debian.sh symbols DISTDIR"
        ok=1
    fi
    src=$TS_WORK/src/trigspline-$TS_VERSION
    ts_export_tree "$src"
    rm -f "$TS_WORK"/src/*.deb "$TS_WORK"/src/*.changes "$TS_WORK"/src/*.buildinfo
    # Debian's own tools and interpreters only (not a python3 earlier on PATH)
    (cd "$src" && PATH=/usr/sbin:/usr/bin:/sbin:/bin DEB_BUILD_OPTIONS="parallel=2" dpkg-buildpackage -us -uc -b) \
        >"$TS_WORK/dpkg-buildpackage.log" 2>&1 || { tail -n 60 "$TS_WORK/dpkg-buildpackage.log"; exit 1; }
    grep -E "^dpkg-gensymbols: warning" "$TS_WORK/dpkg-buildpackage.log" && ok=1
    grep -E "^smoke:" "$TS_WORK/dpkg-buildpackage.log" | sed 's/^smoke: /build-time smoke: /'
    rm -rf "$OUT"; mkdir -p "$OUT"
    mv "$TS_WORK"/src/*.deb "$TS_WORK"/src/*.changes "$TS_WORK"/src/*.buildinfo "$OUT"/
    changes=$(ls "$OUT"/*.changes)
    lintian --info --display-level ">=warning" "$changes" 2>&1 |
        grep -v "running with root privileges is not recommended" >"$TS_WORK/lintian.txt" || true
    lintian --fail-on error,warning "$changes" >/dev/null 2>&1 || ok=1
    echo "lintian ($(lintian --version)) on $(basename "$changes"):"
    if [ -s "$TS_WORK/lintian.txt" ]; then sed 's/^/  /' "$TS_WORK/lintian.txt" | tail -n 40
    else echo "  no errors, no warnings"; fi
    echo "lintian info tags and overrides:"
    lintian --display-level ">=info" --show-overrides "$changes" 2>&1 | grep -E "^[IO]:" | sed 's/^/  /' | tail -n 20 || true
    for p in $PACKAGES; do ts_artifact "$OUT/${p}_${DEBV}_$ARCH.deb"; done
    echo "note: also built (debug symbols, not installed by the test): $(cd "$OUT" && ls ./*-dbgsym_*.deb | sed 's|^\./||' | tr '\n' ' ')"
    exit $ok
    ;;
test)
    ok=0
    for p in $PACKAGES; do [ -f "$OUT/${p}_${DEBV}_$ARCH.deb" ] || { echo "missing $p"; exit 1; }; done
    w=$TS_WORK/overlay
    rm -rf "$w"; mkdir -p "$w/upper" "$w/work" "$w/root"
    unshare -m sh -s "$w" "$OUT" "$TS_SMOKE" "$PACKAGES" <<'EOS' || ok=1
set -eu
w=$1; out=$2; smoke=$3; packages=$4
mount --make-rprivate /
mount -t overlay overlay -o "lowerdir=/,upperdir=$w/upper,workdir=$w/work" "$w/root"
mount -t proc proc "$w/root/proc"
mount --rbind /dev "$w/root/dev"
r=$w/root
rm -rf "$r/tmp/dist-test"; mkdir -p "$r/tmp/dist-test/debs" "$r/tmp/dist-test/run"
for p in $packages; do cp "$out/${p}"_*.deb "$r/tmp/dist-test/debs/"; done
cp "$smoke"/smoke.c "$smoke"/smoke.py "$smoke"/smoke_cli.sh "$r/tmp/dist-test/"
for p in $packages; do
    if chroot "$r" dpkg -s "$p" >/dev/null 2>&1; then echo "$p already installed"; exit 1; fi
done
chroot "$r" env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin sh -eu -c '
cd /tmp/dist-test
dpkg -i debs/*.deb >/dev/null
dpkg-query -W -f "installed: \${Package} \${Version} \${Status}\n" '"$packages"'
test -f /usr/share/man/man1/trigspline.1.gz && echo "man page: /usr/share/man/man1/trigspline.1.gz"
cc -std=c11 smoke.c $(pkg-config --cflags --libs trigspline) -o run/smoke
ldd run/smoke | grep -q "libtrigspline.so.0.2 => /usr/lib/" && echo "smoke program linked with $(ldd run/smoke | grep -o "libtrigspline[^ ]* => [^ ]*")"
run/smoke
sh smoke_cli.sh /usr/bin/trigspline
cd run && python3 ../smoke.py --expect-prefix /usr/lib/python3/dist-packages
dpkg --purge '"$packages"' >/dev/null
for p in '"$packages"'; do ! dpkg -s "$p" >/dev/null 2>&1 || { echo "$p not removed"; exit 1; }; done
test ! -e /usr/bin/trigspline && test ! -e /usr/lib/python3/dist-packages/trigspline && echo "purged: no file left"
'
EOS
    rm -rf "$w"
    exit $ok
    ;;
*) echo "usage: $0 build|test|symbols DISTDIR" >&2; exit 2 ;;
esac
