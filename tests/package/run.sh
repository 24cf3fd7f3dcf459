#!/usr/bin/env bash
# Packaging test: what a C user of an installed (or vendored) trigspline sees.
#
#  (a) cmake --install BUILD --prefix TMP: the files of the package exist;
#  (b) the external program tests/package/app.c is built and run
#        1. with find_package(trigspline) (CMAKE_PREFIX_PATH = TMP), linking
#           trigspline::trigspline (shared) and trigspline::trigspline_static;
#           a request for major version 1 must fail (SameMajorVersion), and
#           before 1.0 one for the previous minor (SameMinorVersion); the
#           soname is libtrigspline.so.0.MINOR before 1.0, .so.MAJOR after;
#        2. with `pkg-config --cflags --libs trigspline` (shared; run with
#           LD_LIBRARY_PATH);
#        3. with `pkg-config --static --cflags --libs trigspline` and -static
#           (readelf: libtrigspline.so is not needed);
#        4. from an outside CMake project that add_subdirectory()s the source
#           tree (only the library may be defined there);
#        5. the GSL adapter (when the build found GSL): tests/package/gsl_app.c
#           with find_package(trigspline COMPONENTS gsl) (trigspline::gsl) and
#           with `pkg-config --cflags --libs trigspline_gsl`;
#      every run checked against the closed form below;
#  (c) nm -D --defined-only of the installed libtrigspline.so lists exactly
#      the functions declared in the installed trigspline.h.
#
# Expected values.  Data (0,0), (1,1), user slopes d0 = d1 = 1, alpha = 1,
# beta = 0, paper form (docs/method.md §2-§3): h = 1, a = 1, k = 2/(3π),
# control values B = [0, k, 1 - k, 1]; at θ = (π/2) x, s = sin θ, c = cos θ,
#   S  = A1 k + A2 (1 - k) + A3,  A1 = s(1-s)(3-s), A2 = c(1-c)(3-c), A3 = (1-c)³
#   S' = (π/2) [3(1-s)² c k + 2 s c (1 - 2k) + 3(1-c)² s k]          (2.1)
# computed here by awk from that closed form, not by the library.
# (At x = 1/2, S = s² = 1/2 for any k; the printed sign of B2 in the paper
# would give 1/2 + 2k A2 = 0.61 there.)
# Tolerance 1e-14 (absolute; values and slopes are O(1)): both sides evaluate
# the same closed form in double precision, each with a few rounding errors
# (sin/cos to 1 ulp, about ten operations: <= ~2e-15 each); 1e-14 covers
# their sum with a margin, while any error in the method (sign of B2, k, the
# basis) changes the values by more than 1e-3.
#
# Prints "package: N passed, M failed"; exit status 0 only if M = 0.
# Everything happens in a temporary directory, removed on exit.
set -u

build="" source="" cc=cc cmake=cmake generator="Unix Makefiles" libdir=lib includedir=include
version=""
while [ $# -gt 0 ]; do
    case $1 in
        --build) build=$2; shift 2;;
        --source) source=$2; shift 2;;
        --cc) cc=$2; shift 2;;
        --cmake) cmake=$2; shift 2;;
        --generator) generator=$2; shift 2;;
        --libdir) libdir=$2; shift 2;;
        --includedir) includedir=$2; shift 2;;
        --version) version=$2; shift 2;;
        *) echo "run.sh: unknown argument $1" >&2; exit 2;;
    esac
done
here=$(cd "$(dirname "$0")" && pwd)
[ -n "$source" ] || source=$(cd "$here/../.." && pwd)
if [ -z "$build" ] || [ ! -f "$build/CMakeCache.txt" ]; then
    echo "run.sh: --build must name a configured build directory" >&2
    echo "package: 0 passed, 1 failed"
    exit 1
fi

pass=0; fail=0
ok()  { pass=$((pass + 1)); echo "ok   $*"; }
bad() { fail=$((fail + 1)); echo "FAIL $*"; }
check() { # description, command...
    local what=$1; shift
    if "$@"; then ok "$what"; else bad "$what"; fi
}

tmp=$(mktemp -d "${TMPDIR:-/tmp}/trigspline-package.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
prefix=$tmp/prefix
log=$tmp/log

finish() {
    echo "package: $pass passed, $fail failed"
    [ "$fail" -eq 0 ]
    exit $?
}

# pkg-config: installed on demand (Debian), as every target does.
if ! command -v pkg-config >/dev/null 2>&1; then
    if [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1; then
        { apt-get update && apt-get install -y pkg-config; } >"$log" 2>&1 || cat "$log"
    fi
fi

# Compare the program's output with the closed form (see the top).
values_ok() { # output file of app
    awk -v want="$version" '
        function bad(msg) { print "  " msg; err = 1 }
        $1 == "version" {
            seen_v = 1
            if ($2 != want || $3 != want) bad("version " $2 " / header " $3 ", expected " want)
        }
        $1 == "at" {
            n++
            x = $2 + 0; y = $3 + 0; dy = $4 + 0
            pi = atan2(0, -1); k = 2 / (3 * pi)
            t = pi / 2 * x; s = sin(t); c = cos(t)
            A1 = s * (1 - s) * (3 - s); A2 = c * (1 - c) * (3 - c); A3 = (1 - c) ^ 3
            ey = A1 * k + A2 * (1 - k) + A3
            edy = pi / 2 * (3 * (1 - s) ^ 2 * c * k + 2 * s * c * (1 - 2 * k) + 3 * (1 - c) ^ 2 * s * k)
            if (!(y - ey <= 1e-14 && ey - y <= 1e-14))
                bad(sprintf("S(%.17g) = %.17g, closed form %.17g", x, y, ey))
            if (!(dy - edy <= 1e-14 && edy - dy <= 1e-14))
                bad(sprintf("S\x27(%.17g) = %.17g, closed form %.17g", x, dy, edy))
        }
        END {
            if (!seen_v) bad("no version line")
            if (n != 3) bad("expected 3 values, got " n)
            exit err
        }' "$1"
}

run_app() { # description, program, [env assignments...]
    local what=$1 prog=$2; shift 2
    if [ ! -x "$prog" ]; then bad "$what: $prog not built"; return; fi
    if env "$@" "$prog" >"$tmp/out" 2>&1 && values_ok "$tmp/out"; then
        ok "$what: values match the closed form"
    else
        cat "$tmp/out"; bad "$what: values"
    fi
}

needs_so() { # program: 0 if it has DT_NEEDED libtrigspline.so*
    readelf -d "$1" 2>/dev/null | grep -q 'NEEDED.*\[libtrigspline\.so'
}
not_needs_so() { ! needs_so "$1"; }

# ---- (a) install --------------------------------------------------------
if "$cmake" --install "$build" --prefix "$prefix" >"$log" 2>&1; then
    ok "cmake --install --prefix"
else
    cat "$log"; bad "cmake --install --prefix"; finish
fi
for f in "$includedir/trigspline.h" "$includedir/trigspline_version.h" "$libdir/libtrigspline.a" "$libdir/libtrigspline.so" \
         "$libdir/cmake/trigspline/trigsplineConfig.cmake" \
         "$libdir/cmake/trigspline/trigsplineConfigVersion.cmake" \
         "$libdir/cmake/trigspline/trigsplineTargets.cmake" \
         "$libdir/pkgconfig/trigspline.pc" "share/doc/trigspline/LICENSE"; do
    check "installed $f" test -e "$prefix/$f"
done
check "no internal header installed" test ! -e "$prefix/$includedir/internal.h"
if grep -q "^prefix=$prefix\$" "$prefix/$libdir/pkgconfig/trigspline.pc"; then
    ok "trigspline.pc names the prefix given to cmake --install"
else
    cat "$prefix/$libdir/pkgconfig/trigspline.pc"; bad "trigspline.pc prefix"
fi

# ---- (b1) find_package ----------------------------------------------------
gen=(-G "$generator" -DCMAKE_C_COMPILER="$cc" -DCMAKE_BUILD_TYPE=Release)
want_minor=${version%.*}   # X.Y of X.Y.Z
if "$cmake" -S "$here/consumer" -B "$tmp/fp" "${gen[@]}" -DTS_MODE=package \
        -DTS_WANT_VERSION="$want_minor" -DCMAKE_PREFIX_PATH="$prefix" >"$log" 2>&1 &&
   "$cmake" --build "$tmp/fp" >>"$log" 2>&1; then
    ok "find_package(trigspline $want_minor): configure and build"
    run_app "find_package, trigspline::trigspline" "$tmp/fp/app_shared"
    run_app "find_package, trigspline::trigspline_static" "$tmp/fp/app_static"
    check "find_package: app_shared needs libtrigspline.so" needs_so "$tmp/fp/app_shared"
    check "find_package: app_static does not need libtrigspline.so" not_needs_so "$tmp/fp/app_static"
else
    cat "$log"; bad "find_package(trigspline $want_minor): configure and build"
fi
if "$cmake" -S "$here/consumer" -B "$tmp/fp1" "${gen[@]}" -DTS_MODE=package \
        -DTS_WANT_VERSION=1 -DCMAKE_PREFIX_PATH="$prefix" >"$log" 2>&1; then
    bad "find_package(trigspline 1) accepted version $version (SameMajorVersion)"
else
    ok "find_package(trigspline 1) refuses version $version (SameMajorVersion)"
fi
# before 1.0 a minor release may break the API (docs/versions.md): 0.Y asks
# for exactly that minor (SameMinorVersion), so 0.(Y-1) is refused too
major=${version%%.*}; minor=${want_minor#*.}
if [ "$major" = 0 ] && [ "$minor" -gt 0 ]; then
    older="0.$((minor - 1))"
    if "$cmake" -S "$here/consumer" -B "$tmp/fp0" "${gen[@]}" -DTS_MODE=package \
            -DTS_WANT_VERSION="$older" -DCMAKE_PREFIX_PATH="$prefix" >"$log" 2>&1; then
        bad "find_package(trigspline $older) accepted version $version (SameMinorVersion before 1.0)"
    else
        ok "find_package(trigspline $older) refuses version $version (SameMinorVersion before 1.0)"
    fi
fi
if [ "$major" = 0 ]; then want_so="libtrigspline.so.$want_minor"; else want_so="libtrigspline.so.$major"; fi
check "soname $want_so" sh -c "readelf -d '$prefix/$libdir/libtrigspline.so' | grep -q 'SONAME.*\[$want_so\]'"

# ---- (b2, b3) pkg-config --------------------------------------------------
if command -v pkg-config >/dev/null 2>&1; then
    export PKG_CONFIG_PATH="$prefix/$libdir/pkgconfig"
    check "pkg-config --modversion = $version" test "$(pkg-config --modversion trigspline)" = "$version"
    case " $(pkg-config --static --libs trigspline) " in
        *" -lm "*) ok "pkg-config --static --libs has -lm";;
        *) bad "pkg-config --static --libs lacks -lm";;
    esac
    # shared
    # shellcheck disable=SC2046
    if "$cc" -std=c11 -Wall -Wextra -Wpedantic -Werror "$here/app.c" -o "$tmp/app_pc" \
            $(pkg-config --cflags --libs trigspline) >"$log" 2>&1; then
        ok "pkg-config --cflags --libs: build"
        check "pkg-config shared: needs libtrigspline.so" needs_so "$tmp/app_pc"
        run_app "pkg-config shared (LD_LIBRARY_PATH)" "$tmp/app_pc" \
            LD_LIBRARY_PATH="$prefix/$libdir"
        if LD_LIBRARY_PATH="$prefix/$libdir" ldd "$tmp/app_pc" 2>/dev/null |
                grep -q "libtrigspline\.so.* => $prefix/$libdir/"; then
            ok "pkg-config shared: ldd resolves the installed libtrigspline.so"
        else
            bad "pkg-config shared: ldd does not resolve the installed libtrigspline.so"
        fi
    else
        cat "$log"; bad "pkg-config --cflags --libs: build"
    fi
    # static (-static: the archive is the only libtrigspline the linker may take)
    # shellcheck disable=SC2046
    if "$cc" -std=c11 -Wall -Wextra -Wpedantic -Werror -static "$here/app.c" -o "$tmp/app_pcs" \
            $(pkg-config --static --cflags --libs trigspline) >"$log" 2>&1; then
        ok "pkg-config --static --cflags --libs: build"
        check "pkg-config static: libtrigspline.so not needed (readelf -d)" not_needs_so "$tmp/app_pcs"
        run_app "pkg-config static (no LD_LIBRARY_PATH)" "$tmp/app_pcs"
    else
        cat "$log"; bad "pkg-config --static --cflags --libs: build"
    fi
    unset PKG_CONFIG_PATH
else
    bad "pkg-config is not installed and could not be installed"
fi

# ---- (b4) add_subdirectory of the source tree -----------------------------
if "$cmake" -S "$here/consumer" -B "$tmp/sub" "${gen[@]}" -DTS_MODE=subdir \
        -DTS_SOURCE="$source" >"$log" 2>&1 &&
   "$cmake" --build "$tmp/sub" -j 2 >>"$log" 2>&1; then
    ok "add_subdirectory(source tree): configure and build (library only)"
    run_app "add_subdirectory, trigspline::trigspline" "$tmp/sub/app_shared"
    run_app "add_subdirectory, trigspline::trigspline_static" "$tmp/sub/app_static"
    check "add_subdirectory: app_static does not need libtrigspline.so" not_needs_so "$tmp/sub/app_static"
else
    tail -n 30 "$log"; bad "add_subdirectory(source tree): configure and build"
fi

# ---- (b5) the GSL adapter: find_package(... COMPONENTS gsl), pkg-config -----
# Built and installed when the build found GSL (its CMake cache says so).
gsl_ok() { # output file of gsl_app: the line y = 2x + 1 reproduced (1e-13
    # relative: a few roundings of the geometric form's evaluation, while any
    # wrong link, type or scheme is off by far more), the positive type's
    # name, negative data refused
    awk '
        function bad(msg) { print "  " msg; err = 1 }
        $1 == "name" { name = $2 }
        $1 == "at" { n++; x = $2 + 0; y = $3 + 0; e = 2 * x + 1
                     if (!(y - e <= 1e-13 * e && e - y <= 1e-13 * e))
                         bad(sprintf("S(%.17g) = %.17g, expected %.17g", x, y, e)) }
        $1 == "edom" { edom = $2 }
        END { if (name != "trigspline-positive") bad("name " name)
              if (n != 3) bad("expected 3 values, got " n)
              if (edom != 1) bad("negative data not refused with GSL_EDOM")
              exit err }' "$1"
}
if grep -q '^TS_GSL_LIBRARY:FILEPATH=/' "$build/CMakeCache.txt"; then
    for f in "$libdir/libtrigspline_gsl.a" "$includedir/trigspline_gsl.h" \
             "$libdir/cmake/trigspline/trigsplineGslTargets.cmake" "$libdir/pkgconfig/trigspline_gsl.pc"; do
        check "installed $f" test -e "$prefix/$f"
    done
    if "$cmake" -S "$here/consumer" -B "$tmp/gsl" "${gen[@]}" -DTS_MODE=gsl \
            -DTS_WANT_VERSION="$want_minor" -DCMAKE_PREFIX_PATH="$prefix" >"$log" 2>&1 &&
       "$cmake" --build "$tmp/gsl" >>"$log" 2>&1; then
        ok "find_package(trigspline COMPONENTS gsl): configure and build against trigspline::gsl"
        if "$tmp/gsl/gsl_app" >"$tmp/gout" 2>&1 && gsl_ok "$tmp/gout"; then
            ok "find_package gsl_app: values on the line, positive type, GSL_EDOM"
        else
            cat "$tmp/gout"; bad "find_package gsl_app: values"
        fi
    else
        cat "$log"; bad "find_package(trigspline COMPONENTS gsl): configure and build"
    fi
    if command -v pkg-config >/dev/null 2>&1; then
        export PKG_CONFIG_PATH="$prefix/$libdir/pkgconfig"
        check "pkg-config --modversion trigspline_gsl = $version" \
            test "$(pkg-config --modversion trigspline_gsl)" = "$version"
        # shellcheck disable=SC2046
        if "$cc" -std=c11 -Wall -Wextra -Wpedantic -Werror "$here/gsl_app.c" -o "$tmp/gsl_pc" \
                $(pkg-config --cflags --libs trigspline_gsl) >"$log" 2>&1; then
            ok "pkg-config --cflags --libs trigspline_gsl: build"
            if LD_LIBRARY_PATH="$prefix/$libdir" "$tmp/gsl_pc" >"$tmp/gout" 2>&1 &&
               gsl_ok "$tmp/gout"; then
                ok "pkg-config gsl_app: values on the line, positive type, GSL_EDOM"
            else
                cat "$tmp/gout"; bad "pkg-config gsl_app: values"
            fi
        else
            cat "$log"; bad "pkg-config --cflags --libs trigspline_gsl: build"
        fi
        unset PKG_CONFIG_PATH
    fi
else
    echo "skip the GSL adapter: the build did not find GSL"
fi

# ---- (c) exported symbols = declared functions ----------------------------
so=$prefix/$libdir/libtrigspline.so
hdr=$prefix/$includedir/trigspline.h
# Declared: every identifier ts_* followed by "(" in the preprocessed header
# (comments gone; typedef'd names and parameters are never followed by "(").
if "$cc" -E -P -x c "$hdr" >"$tmp/hdr.i" 2>"$log"; then
    tr '\n' ' ' <"$tmp/hdr.i" | grep -oE '\bts_[A-Za-z0-9_]*[[:space:]]*\(' |
        sed -E 's/[[:space:]]*\($//' | sort -u >"$tmp/declared"
    nm -D --defined-only "$so" | awk 'NF >= 3 { print $3 }' | sed 's/@.*//' | sort -u >"$tmp/exported"
    check "header declares functions ($(wc -l <"$tmp/declared"))" test -s "$tmp/declared"
    if cmp -s "$tmp/declared" "$tmp/exported"; then
        ok "nm -D --defined-only = the $(wc -l <"$tmp/declared") functions of trigspline.h"
    else
        echo "  exported but not declared:"; comm -13 "$tmp/declared" "$tmp/exported" | sed 's/^/    /'
        echo "  declared but not exported:"; comm -23 "$tmp/declared" "$tmp/exported" | sed 's/^/    /'
        bad "nm -D --defined-only differs from the functions of trigspline.h"
    fi
    if grep -q '^ts__' "$tmp/exported"; then bad "ts__ internals exported"
    else ok "no ts__ internals exported"; fi
else
    cat "$log"; bad "preprocess the installed header"
fi

finish
