#!/bin/sh
# Record what the trigspline command writes (standard output, standard error,
# exit status, plots) for the data sets of data/paper, data/examples and
# data/surface under many options, plus every --help text, one file per case,
# into OUTDIR.  Run it before and after a refactoring and compare the two
# directories (diff -r): the command's outputs must not change.
#   usage: tests/tools/golden_cli.sh BUILD_DIR OUTDIR      (from anywhere)
set -u
[ $# -eq 2 ] || { echo "usage: $0 BUILD_DIR OUTDIR" >&2; exit 2; }
CLI=$(cd "$1" && pwd)/trigspline
mkdir -p "$2"
OUT=$(cd "$2" && pwd)
cd "$(dirname "$0")/../.." || exit 2
n=0
# case NAME ARGS...: files NAME.out, NAME.err, NAME.rc; "@PLOT@" in ARGS is
# replaced by the path of NAME.svg in OUTDIR (written there as it is).
case_() {
    name=$1
    shift
    plot="$OUT/$name.svg"
    set -- $(printf '%s\n' "$@" | sed "s|@PLOT@|$plot|")
    "$CLI" "$@" >"$OUT/$name.out" 2>"$OUT/$name.err" </dev/null
    echo $? >"$OUT/$name.rc"
    sed -i "s|$OUT/||g" "$OUT/$name.err"
    n=$((n + 1))
}

case_ help-main --help
for c in fit certify curve surface; do case_ "help-$c" $c --help; done
case_ usage-none
case_ usage-cmd bogus

for f in data/paper/*.csv data/examples/*.csv; do
    b=$(basename "$f" .csv)
    for j in "" --json; do
        t=$b${j:+-json}
        case_ "fit-$t" fit "$f" $j
        case_ "fit-$t-s7" fit "$f" $j --samples 7
        case_ "fit-$t-c1" fit "$f" $j --form c1
        case_ "fit-$t-geo" fit "$f" $j --form geometric
        case_ "fit-$t-pos" fit "$f" $j --shape positive
        case_ "fit-$t-mono" fit "$f" $j --shape monotone
        case_ "fit-$t-above" fit "$f" $j --shape above --line 0.03,0.3
        case_ "fit-$t-below" fit "$f" $j --shape below --line 1,2.5
        case_ "fit-$t-between" fit "$f" $j --lower 0.1,-1 --upper 8,6
        case_ "fit-$t-between2" fit "$f" $j --shape between --lower 0,0 --upper 0,100
        case_ "fit-$t-slopes" fit "$f" $j --slopes fritsch-carlson --alpha 0.5 --margin 0.2
        case_ "fit-$t-beta" fit "$f" $j --beta 2 --alpha 1.5
        case_ "fit-$t-total" fit "$f" $j --samples-total 17 --derivative 1
        case_ "fit-$t-grid" fit "$f" $j --grid 0:3:7 --extrapolate clamp
        case_ "fit-$t-at" fit "$f" $j --at 0.5,1,2.25 --extrapolate linear
        case_ "certify-$t" certify "$f" $j --alpha 1 --beta 1 --shape positive
        case_ "certify-$t-lines" certify "$f" $j --alpha 1 --beta 0.5 --lower 0,0 --upper 1,30
        case_ "curve-$t" curve "$f" $j
        case_ "curve-$t-closed" curve "$f" $j --closed --samples 5
        case_ "curve-$t-chord" curve "$f" $j --param chord --slopes harmonic
        case_ "curve-$t-box" curve "$f" $j --closed --box 0,100,0,60
        case_ "curve-$t-box2" curve "$f" $j --box -inf,inf,-0.5,inf --margin 0.3
    done
    case_ "fit-$b-svg" fit "$f" --shape positive --svg @PLOT@ --title T --show-control
    case_ "fit-$b-svg2" fit "$f" --svg @PLOT@ --points-only --logy --size 400x300
    case_ "certify-$b-svg" certify "$f" --alpha 1 --beta 1 --shape positive --svg @PLOT@
    case_ "curve-$b-svg" curve "$f" --closed --svg @PLOT@ --show-control
done
for f in data/surface/*.csv; do
    b=$(basename "$f" .csv)
    m=
    case $b in *matrix*) m=--matrix ;; esac
    for j in "" --json; do
        t=$b${j:+-json}
        case_ "surface-$t" surface "$f" $m $j
        case_ "surface-$t-pos" surface "$f" $m $j --shape positive
        case_ "surface-$t-range" surface "$f" $m $j --shape range --samples 2
        case_ "surface-$t-bounds" surface "$f" $m $j --shape bounds --lower 0 --upper 100
        case_ "surface-$t-planes" surface "$f" $m $j --shape planes --lower 0,0,-1
        case_ "surface-$t-form" surface "$f" $m $j --form c1 --slopes harmonic --zero-twist
        case_ "surface-$t-grid" surface "$f" $m $j --grid 5,6 --matrix-out
        case_ "surface-$t-ab" surface "$f" $m $j --alpha 2 --beta 0.5 --margin 0.1
    done
    case_ "surface-$b-svg" surface "$f" $m --shape positive --svg @PLOT@
done
# usage errors: the messages name the option and the bad value
F=data/paper/table1_positive.csv
S=data/surface/cloud_percent_long.csv
i=0
while read -r cmd args; do
    i=$((i + 1))
    case $cmd in surface) d=$S ;; *) d=$F ;; esac
    case_ "usage-$i" $cmd $d $args
done <<'CASES'
fit --shape wobbly
fit --alpha -1
fit --alpha x
fit --beta -1
fit --samples 1
fit --samples
fit --bogus
fit --json=1
fit --closed
fit --slopes user
fit --form x
fit --line 1
fit --line 1,2,3
fit --alphas 1,-2
fit --betas 1,x
fit --derivative 3
fit --extrapolate no
fit --columns 1
fit --columns 1,1
fit --format gif --svg a.svg
fit --format png --svg @PLOT@
fit --svg a.txt
fit --png a.svg
fit --svg a.svg --pdf b.pdf
fit --xlabel X
fit --with-samples
fit --samples 4 --grid 0:1:3
fit --grid 1:0:3
fit --delimiter x
fit --decimal-comma --delimiter ,
fit --missing maybe
fit --skip -1
fit --size 10x10
fit --samples-total 1
fit --c1 --form paper
fit -o
fit --output=
fit --svg -
fit extra.csv
fit -- --weird
certify --param chord
curve --box 1,0,0,1
curve --box 0,1,0
curve --box inf,1,0,1
curve --param x
curve --margin 0
curve --at 1
surface --shape wobbly
surface --alpha -1
surface --grid 3
surface --samples 0
surface --bogus 1
surface --form
surface --lower 1,2
surface --slopes user
surface --slopes periodic
surface --svg a.png
surface -o
surface extra.csv
surface --margin 0
surface --beta x
CASES
case_ usage-surface-nodata surface
echo "golden_cli: $n cases in $OUT"
