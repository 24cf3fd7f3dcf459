#!/bin/sh
# musl channel (Alpine and other musl systems): the library (shared and
# static), header, CMake package, pkg-config file, man page and a static
# `trigspline` command, built with Debian's musl-gcc (musl-tools), as
# DISTDIR/trigspline-VERSION-x86_64-linux-musl.tar.gz, laid out for
# `tar -C /usr/local --strip-components=1 -xzf ...` (prefix /usr/local).
#   test: extracted into a scratch directory; no IRELATIVE relocation (musl's
#   loader has no ifunc); the smoke program linked with musl-gcc against the
#   shared and the static library, and the static command, run there.
# (All C test programs on musl: make test-musl; three of them: make test.)
. "$(dirname "$0")/lib/common.sh"
ts_setup musl "$2"
ts_need musl-gcc:musl-tools cmake:cmake readelf:binutils
arch=$(uname -m)
name=trigspline-$TS_VERSION-$arch-linux-musl
tarball=$TS_DIST/$name.tar.gz

case $1 in
build)
    rm -rf "$TS_WORK/build" "$TS_WORK/stage" "$tarball"
    CC=musl-gcc cmake -S "$TS_ROOT" -B "$TS_WORK/build" -DCMAKE_BUILD_TYPE=Release \
        -DCMAKE_C_FLAGS_RELEASE=-O2 -DTS_WERROR=ON -DTS_BUILD_TESTS=OFF -DTS_BUILD_EXAMPLES=OFF \
        -DCMAKE_EXE_LINKER_FLAGS=-static -DCMAKE_INSTALL_PREFIX=/usr/local \
        -DCMAKE_INSTALL_LIBDIR=lib >"$TS_WORK/configure.log" 2>&1 ||
        { cat "$TS_WORK/configure.log"; exit 1; }
    cmake --build "$TS_WORK/build" -j 2 >"$TS_WORK/build.log" 2>&1 || { tail -n 40 "$TS_WORK/build.log"; exit 1; }
    DESTDIR="$TS_WORK/stage" cmake --install "$TS_WORK/build" --strip >/dev/null
    mv "$TS_WORK/stage/usr/local" "$TS_WORK/stage/$name"
    tar -C "$TS_WORK/stage" --owner=0 --group=0 --sort=name -czf "$tarball" "$name"
    ts_artifact "$tarball"
    ;;
test)
    root=$TS_WORK/root
    rm -rf "$root"; mkdir -p "$root"
    tar -C "$root" --strip-components=1 -xzf "$tarball"
    ok=0
    for f in include/trigspline.h include/trigspline_version.h lib/libtrigspline.a \
             lib/libtrigspline.so lib/pkgconfig/trigspline.pc lib/cmake/trigspline/trigsplineConfig.cmake \
             bin/trigspline share/man/man1/trigspline.1; do
        [ -e "$root/$f" ] || { echo "missing $f"; ok=1; }
    done
    n=$(readelf -r "$root/lib/libtrigspline.so" | grep -c IRELATIV || true)
    echo "IRELATIVE relocations in libtrigspline.so: $n"
    [ "$n" = 0 ] || ok=1
    if readelf -l "$root/bin/trigspline" | grep -q INTERP; then echo "bin/trigspline is not static"; ok=1; fi
    musl-gcc -std=c11 -O2 -I"$root/include" "$TS_SMOKE/smoke.c" -L"$root/lib" -Wl,-rpath,"$root/lib" \
        -ltrigspline -lm -o "$TS_WORK/smoke-shared" && "$TS_WORK/smoke-shared" || ok=1
    musl-gcc -static -std=c11 -O2 -I"$root/include" "$TS_SMOKE/smoke.c" "$root/lib/libtrigspline.a" \
        -lm -o "$TS_WORK/smoke-static" && "$TS_WORK/smoke-static" || ok=1
    env -i PATH=/usr/bin:/bin sh "$TS_SMOKE/smoke_cli.sh" "$root/bin/trigspline" || ok=1
    exit $ok
    ;;
*) echo "usage: $0 build|test DISTDIR" >&2; exit 2 ;;
esac
