#!/bin/sh
# The distribution smoke test of the trigspline command (as smoke.c): the
# paper's Table 1, positive, alpha 0.15, evaluated at x = 4.2 and certified
# (--json), and one refusal (a negative value: exit 2 naming point 3).
#   smoke_cli.sh TRIGSPLINE_COMMAND
# Prints the "smoke:" lines; exit 0 when both behave as documented.
set -u
cmd=$1
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
printf 'x,f\n0,2\n2,1.58\n3,1.55\n5,1.54\n15,1.8\n25,1.54\n27,1.55\n28,1.58\n30,2\n' >"$tmp/t1.csv"
printf 'x\n4.2\n' >"$tmp/at.csv"
cd "$tmp" || exit 1
ok=0
echo "smoke: version $("$cmd" --version 2>&1 | head -n 1)"
y=$("$cmd" fit t1.csv --shape positive --alpha 0.15 --at at.csv | sed -n 2p | cut -d, -f2) || ok=1
cert=$("$cmd" fit t1.csv --shape positive --alpha 0.15 --json | grep -c '"certified": *true') || ok=1
[ "$cert" -ge 1 ] && c=1 || c=0
echo "smoke: y(4.2) = $y certified $c"
[ "$c" = 1 ] && [ -n "$y" ] || ok=1
sed 's/^5,1.54$/5,-1/' t1.csv >neg.csv
msg=$("$cmd" fit neg.csv --shape positive --alpha 0.15 2>&1 >/dev/null); rc=$?
echo "smoke: error exit $rc: $msg"
[ "$rc" = 2 ] || ok=1
exit $ok
