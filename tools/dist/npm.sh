#!/bin/sh
# npm channel: the WebAssembly module as the npm package `trigspline`
# (bindings/web/package.json: exports, types, files, engines), packed with
# `npm pack` as DISTDIR/trigspline-VERSION.tgz.
#   build: `make web` into DISTDIR/work/npm (its own WEB_BUILD and WEB_OUT),
#          the package staged there (package.json without devDependencies,
#          the version of CMakeLists.txt's project(); trigspline.mjs, the two
#          modules trigspline.wasm (scalar) and trigspline-simd.wasm (SIMD128),
#          .d.mts, README, LICENSE) and packed.
#   test:  the tarball installed (npm install --offline) into a fresh
#          directory; the smoke test imported in Node (smoke/smoke_npm.mjs);
#          the types checked with tsc --strict against the installed package
#          (bindings/web/test/types/use.mts); the package imported in a page
#          in Chromium (smoke/npm_page.mjs, nothing off the loopback).  tsc
#          and playwright-core come from bindings/web/node_modules (its
#          devDependencies; npm ci there when missing).
# Prints artifact:/note:/smoke: lines (tools/dist conventions); exit 0 ok,
# 77 cannot run here, else failed.
set -eu
TS_ROOT=$(cd "$(dirname "$0")/../.." && pwd)
TS_VERSION=$(sed -n 's/^project(trigspline VERSION \([0-9.]*\).*/\1/p' "$TS_ROOT/CMakeLists.txt")
[ $# -eq 2 ] || { echo "usage: $0 build|test DISTDIR" >&2; exit 2; }
mkdir -p "$2"
DIST=$(cd "$2" && pwd)
WORK=$DIST/work/npm
mkdir -p "$WORK"
tarball=$DIST/trigspline-$TS_VERSION.tgz
for c in node npm; do
    command -v $c >/dev/null 2>&1 || { echo "note: $c not installed (Debian nodejs, npm)"; exit 77; }
done
web_modules() {
    for p in typescript playwright-core; do
        [ -e "$TS_ROOT/bindings/web/node_modules/$p/package.json" ] ||
            { (cd "$TS_ROOT/bindings/web" && npm ci --no-audit --no-fund --loglevel=error) && break; }
    done
}

case $1 in
build)
    command -v emcc >/dev/null 2>&1 || { echo "note: emcc not installed (Debian emscripten)"; exit 77; }
    make -C "$TS_ROOT" --no-print-directory web WEB_BUILD="$WORK/build-web" WEB_OUT="$WORK/web" \
        >"$WORK/build.log" 2>&1 || { tail -n 40 "$WORK/build.log"; exit 1; }
    stage=$WORK/package
    rm -rf "$stage" "$tarball"; mkdir -p "$stage"
    node -e '
        const fs = require("fs");
        const p = JSON.parse(fs.readFileSync(process.argv[1], "utf8"));
        delete p.devDependencies;
        p.version = process.argv[2];
        fs.writeFileSync(process.argv[3], JSON.stringify(p, null, 2) + "\n");
    ' "$TS_ROOT/bindings/web/package.json" "$TS_VERSION" "$stage/package.json"
    cp "$WORK/web/trigspline.mjs" "$WORK/web/trigspline.wasm" "$WORK/web/trigspline-simd.wasm" \
        "$WORK/web/trigspline.d.mts" "$stage/"
    cp "$TS_ROOT/bindings/web/README.npm.md" "$stage/README.md"
    cp "$TS_ROOT/LICENSE" "$stage/LICENSE"
    (cd "$stage" && npm pack --pack-destination "$DIST" --loglevel=error >/dev/null)
    [ -f "$tarball" ] || { echo "npm pack wrote no $tarball"; exit 1; }
    echo "artifact: ${tarball#"$DIST"/} $(wc -c <"$tarball")"
    ;;
test)
    [ -f "$tarball" ] || { echo "no $tarball (build first)"; exit 1; }
    web_modules
    app=$WORK/app
    rm -rf "$app"; mkdir -p "$app"
    printf '{ "name": "trigspline-smoke", "private": true, "type": "module" }\n' >"$app/package.json"
    (cd "$app" && npm install --offline --no-audit --no-fund --loglevel=error "$tarball" >/dev/null)
    ok=0
    # the package's own files, no more
    listed=$(cd "$app/node_modules/trigspline" && find . -type f | sort | tr '\n' ' ')
    echo "installed files: $listed"
    [ "$listed" = "./LICENSE ./README.md ./package.json ./trigspline-simd.wasm ./trigspline.d.mts ./trigspline.mjs ./trigspline.wasm " ] || ok=1
    cp "$TS_ROOT/tools/dist/smoke/smoke_npm.mjs" "$app/"
    (cd "$app" && node smoke_npm.mjs) || ok=1
    cp "$TS_ROOT/bindings/web/test/types/use.mts" "$app/"
    printf '%s\n' '{ "compilerOptions": { "strict": true, "noEmit": true, "target": "es2022", "module": "nodenext",' \
        '  "moduleResolution": "nodenext", "lib": ["es2022", "dom", "esnext.disposable"], "types": [] },' \
        '  "files": ["use.mts"] }' >"$app/tsconfig.json"
    if (cd "$app" && node "$TS_ROOT/bindings/web/node_modules/typescript/bin/tsc" -p .); then
        echo "smoke: tsc --strict on the installed types: ok"
    else
        echo "smoke: tsc --strict on the installed types: FAILED"; ok=1
    fi
    if [ -x /usr/bin/chromium ]; then
        node "$TS_ROOT/tools/dist/smoke/npm_page.mjs" "$app" "$TS_ROOT/bindings/web/package.json" || ok=1
    else
        echo "note: no /usr/bin/chromium: the page import is not tested (Debian chromium)"
    fi
    exit $ok
    ;;
*) echo "usage: $0 build|test DISTDIR" >&2; exit 2 ;;
esac
