# Shared by the channel scripts tools/dist/CHANNEL.sh (sourced, POSIX sh).
# A channel script is called as
#     tools/dist/CHANNEL.sh build DISTDIR    # build its artifacts into DISTDIR
#     tools/dist/CHANNEL.sh test DISTDIR     # install them in a clean place, smoke test
# exit 0 = ok, 77 = cannot run here (the reason on a "note:" line), else failed.
# Lines it prints that tools/dist/run.py reads:
#     artifact: PATH                 an artifact it built (under DISTDIR; size measured)
#     note: TEXT                     shown in the summary (why something is not built, ...)
#     smoke: y(4.2) = VALUE certified 1   the smoke test's value (compared across channels)
# Build directories go to DISTDIR/work/CHANNEL (ts_work); nothing is written
# into the source tree.
set -eu
TS_ROOT=$(cd "$(dirname "$0")/../.." && pwd)
TS_SMOKE=$TS_ROOT/tools/dist/smoke
TS_VERSION=$(sed -n 's/^project(trigspline VERSION \([0-9.]*\).*/\1/p' "$TS_ROOT/CMakeLists.txt")

# ts_setup CHANNEL DISTDIR: TS_DIST (absolute), TS_WORK (DISTDIR/work/CHANNEL)
ts_setup() {
    mkdir -p "$2"
    TS_DIST=$(cd "$2" && pwd)
    TS_WORK=$TS_DIST/work/$1
    mkdir -p "$TS_WORK"
}

# ts_artifact FILE...: report built files
ts_artifact() {
    for a in "$@"; do
        [ -f "$a" ] || { echo "missing artifact $a" >&2; return 1; }
        echo "artifact: ${a#"$TS_DIST"/} $(wc -c <"$a")"
    done
}

# ts_need COMMAND:PACKAGE ...: apt-get install the packages whose command
# (or absolute file) is missing
ts_need() {
    missing=""
    for p in "$@"; do
        c=${p%%:*}
        case $c in
            /*) [ -e "$c" ] || missing="$missing ${p#*:}" ;;
            *) command -v "$c" >/dev/null 2>&1 || missing="$missing ${p#*:}" ;;
        esac
    done
    if [ -n "$missing" ]; then
        echo "installing:$missing"
        apt-get update -q >/dev/null && DEBIAN_FRONTEND=noninteractive \
            apt-get install -y -q --no-install-recommends $missing >/dev/null
    fi
}

# ts_export_tree DEST: the files of a plain clone (tracked and untracked but
# not ignored, as they are in the working tree) copied to DEST
ts_export_tree() {
    rm -rf "$1"; mkdir -p "$1"
    if git -C "$TS_ROOT" rev-parse --is-inside-work-tree >/dev/null 2>&1; then
        (cd "$TS_ROOT" && git ls-files -z -co --exclude-standard |
            xargs -0 sh -c 'for f; do [ -e "$f" ] || [ -L "$f" ] && printf "%s\0" "$f"; done; true' sh |
            tar --null -T - -cf -) | tar -C "$1" -xf -
    else
        (cd "$TS_ROOT" && tar --exclude='./build*' --exclude='./dist' --exclude='./out' -cf - .) |
            tar -C "$1" -xf -
    fi
}
