#!/usr/bin/env python3
"""Reference for docs/method.md §11.4 (standard library only, exact rationals).

With t = tan(θ/2), (1 + t²)³ A_l(θ) is a polynomial of degree 6 (the
factored basis of §2).  This script derives those polynomials, checks that
they sum to (1 + t²)³ (the partition of unity), converts them to Bernstein
coefficients of degree 6 on [0, 1] and checks that every coefficient is
>= 0 and that the table in src/surface_cert.c ("bern", "wgt") matches.

Usage: python3 tests/ref/surface_ref.py [REPO]   -> "surface_ref: N passed, M failed"
"""
import os
import re
import sys
from fractions import Fraction as F
from math import comb

repo = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "..")


def mul(a, b):
    r = [F(0)] * (len(a) + len(b) - 1)
    for i, x in enumerate(a):
        for j, y in enumerate(b):
            r[i + j] += x * y
    return r


def power(a, n):
    r = [F(1)]
    for _ in range(n):
        r = mul(r, a)
    return r


def pad(a):
    return a + [F(0)] * (7 - len(a))


one_minus_t = [F(1), F(-1)]
# 1 - s = (1-t)²/D, s = 2t/D, 3 - s = (3 - 2t + 3t²)/D; 1 - c = 2t²/D, c = (1-t²)/D,
# 3 - c = (2 + 4t²)/D, D = 1 + t²
num = [
    pad(power(one_minus_t, 6)),
    pad(mul(mul([F(0), F(2)], power(one_minus_t, 2)), [F(3), F(-2), F(3)])),
    pad(mul(mul([F(0), F(0), F(2)], [F(1), F(0), F(-1)]), [F(2), F(0), F(4)])),
    pad([F(0)] * 6 + [F(8)]),
]
D3 = power([F(1), F(0), F(1)], 3)


def bernstein(a):
    return [sum(F(comb(m, j), comb(6, j)) * a[j] for j in range(m + 1)) for m in range(7)]


passed = failed = 0


def check(ok, msg):
    global passed, failed
    if ok:
        passed += 1
    else:
        failed += 1
        print("FAIL: " + msg)


check([sum(n[k] for n in num) for k in range(7)] == D3, "partition of unity")
bern = [bernstein(n) for n in num]
w = bernstein(D3)
check(all(b >= 0 for row in bern for b in row), "coefficients >= 0")
check(all(x > 0 for x in w), "weights > 0")
src = open(os.path.join(repo, "src", "surface_cert.c"), encoding="utf-8").read()
tab = re.search(r"bern\[7\]\[4\] = \{(.*?)\};", src, re.S).group(1)
rows = re.findall(r"\{([^{}]*)\}", tab)
check(len(rows) == 7, "7 rows in src/surface_cert.c")
for m, row in enumerate(rows):
    vals = [float(F(v.strip())) if "/" not in v else float(F(*(int(float(p)) for p in v.split("/")))) for v in row.split(",")]
    for l in range(4):
        check(abs(vals[l] - float(bern[l][m])) <= 1e-16, f"bern[{m}][{l}]")
wtab = re.search(r"wgt\[7\] = \{([^}]*)\}", src).group(1)
for m, v in enumerate(wtab.split(",")):
    check(abs(float(v) - float(w[m])) <= 1e-16, f"wgt[{m}]")
for l in range(4):
    print(f"A{l}:", " ".join(str(x) for x in bern[l]))
print("weights:", " ".join(str(x) for x in w))
print(f"surface_ref: {passed} passed, {failed} failed")
sys.exit(1 if failed else 0)
