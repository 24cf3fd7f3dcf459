#!/bin/sh
# Instructions per point of the batch kernels under callgrind (bench/icount.c):
#   bench/icount.sh BUILD_DIR   (a -DTS_BUILD_BENCH=ON build with target icount)
set -eu
b=${1:?usage: icount.sh BUILD_DIR}
run() {
    out=$(valgrind --tool=callgrind --callgrind-out-file=/dev/null --toggle-collect=measured \
        "$b/bench/icount" "$@" 2>&1)
    ir=$(printf '%s\n' "$out" | sed -n 's/.*Collected : \([0-9]*\).*/\1/p')
    echo "$* : $(echo "$ir" | awk -v m="${ICOUNT_M:-100000}" '{printf "%.1f", $1 / m}') instructions/point"
}
run gsl 0 sorted
run gsl 0 random
for form in paper c1 geometric; do
    for isa in 1 0; do
        run $form $isa sorted
        run $form $isa random
    done
done
for form in paper c1 geometric; do
    run $form -1 sorted
done
run paper 1 sorted 1
run geometric 1 sorted 1
