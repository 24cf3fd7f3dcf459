#!/bin/sh
# Memory of the streaming fit on long real-world input (docs/design.md,
# "Real-world input"): BENCH_STREAM_ROWS rows (default 1e8) with every field
# quoted and ISO 8601 timestamps as x, piped into `trigspline fit --samples 2`
# (output to /dev/null).  Prints the peak resident set (GNU time) against the
# bar of 16 MiB, and the rows per second.  Usage: bench/bench_stream.sh BUILD_DIR
set -eu
build=${1:-build}
rows=${BENCH_STREAM_ROWS:-100000000}
here=$(cd "$(dirname "$0")" && pwd)
gen="$build/stream_gen"
cc -O2 -o "$gen" "$here/stream_gen.c"
out=$(mktemp)
trap 'rm -f "$out"' EXIT
start=$(date +%s.%N)
"$gen" "$rows" | /usr/bin/time -f "%M" -o "$out" "$build/trigspline" fit - --samples 2 \
    --shape positive -o /dev/null
end=$(date +%s.%N)
kb=$(tail -n 1 "$out")
awk -v kb="$kb" -v rows="$rows" -v t0="$start" -v t1="$end" 'BEGIN {
    mib = kb / 1024; secs = t1 - t0;
    printf "stream: %d rows, quoted fields, ISO 8601 x: peak RSS %.1f MiB (bar 16 MiB: %s), %.1f s, %.2f M rows/s\n",
        rows, mib, (mib <= 16 ? "within" : "OVER"), secs, rows / secs / 1e6;
    exit (mib <= 16 ? 0 : 1) }'
