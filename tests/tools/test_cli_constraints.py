#!/usr/bin/env python3
"""Constraint records on the command line (docs/cli.md, docs/method.md §13).

Usage: python3 tests/tools/test_cli_constraints.py BUILD_DIR     (standard library only)

Checks:
  - a Black-Scholes call chain (S0 = 100, sigma = 0.2, T = 1, r = 0, values
    from the closed form here) fitted with --constraint convex, decreasing,
    slope>=-1, lower=0: certified; every record's per-interval gap of
    `fit --json` against S'' / S' / S evaluated here from the interval's
    control points (X, B of the JSON) by the geometric form written from
    docs/method.md §2, §4 (A0 = (1-s)^3, A1 = 3s - 4s^2 + s^3, A2 = 3c - 4c^2 + c^3,
    A3 = (1-c)^3; S' = Y'/X', S'' = (Y''X' - Y'X'')/X'^3), 2001 samples per
    interval: the reported gap is <= every sample (tolerance 1e-7 relative:
    the JSON's shortest round-trip values and the samples' own rounding) and
    within the sampling resolution of the smallest;
  - the same records from a JSON file (strings and objects) give the same
    output byte for byte;
  - a scope @I0-I1 reports null outside it;
  - refusals: unknown SPEC (usage, exit 1), non-concave data and a secant
    beyond a slope cap (exit 2, the sentence naming the record), a search
    that gave up and a proven slope conflict (exit 3);
  - a bound given by another spline (lower=spline:FILE.csv and the JSON
    object's "spline"): the calls above their intrinsic value 100 - K, a
    spline through points of that line (exactly the line, docs/method.md
    §4), its gaps against samples of y - (100 - x); its refusals.
Prints "test_cli_constraints: N passed, M failed" last.
"""
import json
import math
import os
import subprocess
import sys
import tempfile

BUILD = sys.argv[1] if len(sys.argv) > 1 else "build"
CLI = os.path.abspath(os.path.join(BUILD, "trigspline"))
TMP = tempfile.mkdtemp(prefix="ts_constraints_test_")

passed = 0
failed = 0


def check(name, cond, detail=""):
    global passed, failed
    if cond:
        passed += 1
    else:
        failed += 1
        print("FAIL: %s %s" % (name, detail))


def run(*args):
    return subprocess.run([CLI] + list(args), capture_output=True, text=True)


def ncdf(z):
    return 0.5 * math.erfc(-z / math.sqrt(2.0))


def basis(th):
    s, c = math.sin(th), math.cos(th)
    A = ((1 - s) ** 3, 3 * s - 4 * s * s + s ** 3, 3 * c - 4 * c * c + c ** 3, (1 - c) ** 3)
    d1 = (-3 * (1 - s) ** 2 * c, c * (3 - 8 * s + 3 * s * s), -s * (3 - 8 * c + 3 * c * c),
          3 * (1 - c) ** 2 * s)
    # second derivatives by differentiating d1 once more
    d2 = (6 * (1 - s) * c * c + 3 * (1 - s) ** 2 * s,
          -s * (3 - 8 * s + 3 * s * s) + c * c * (-8 + 6 * s),
          -c * (3 - 8 * c + 3 * c * c) + s * s * (-8 + 6 * c),
          6 * (1 - c) * s * s + 3 * (1 - c) ** 2 * c)
    return A, d1, d2


def quantities(X, B, th):
    A, d1, d2 = basis(th)
    x = sum(a * v for a, v in zip(A, X))
    y = sum(a * v for a, v in zip(A, B))
    xp = sum(a * v for a, v in zip(d1, X))
    yp = sum(a * v for a, v in zip(d1, B))
    xpp = sum(a * v for a, v in zip(d2, X))
    ypp = sum(a * v for a, v in zip(d2, B))
    return x, y, yp / xp, (ypp * xp - yp * xpp) / xp ** 3


def write(name, text):
    p = os.path.join(TMP, name)
    with open(p, "w") as fh:
        fh.write(text)
    return p


K = [60, 70, 80, 90, 100, 105, 110, 120, 140]
C = []
for k in K:
    d1 = (math.log(100.0 / k) + 0.02) / 0.2
    C.append(100.0 * ncdf(d1) - k * ncdf(d1 - 0.2))
chain = write("calls.csv", "strike,call\n" + "".join("%r,%r\n" % (k, c) for k, c in zip(K, C)))
SPECS = ["convex", "decreasing", "slope>=-1", "lower=0"]
args = []
for s in SPECS:
    args += ["--constraint", s]
r = run("fit", chain, "--json", *args)
check("chain fit", r.returncode == 0, r.stderr)
rep = json.loads(r.stdout)
check("chain certified", rep["certified"] is True)
check("four records", len(rep["constraints"]) == 4)


def quantity(kind, x, y, sp, spp):
    return {"convex": spp, "decreasing": -sp, "slope>=-1": sp + 1.0, "lower=0": y}[kind]


for k, spec in enumerate(SPECS):
    for i, iv in enumerate(rep["intervals"]):
        cr = rep["constraints"][k][i]
        check("in scope %s %d" % (spec, i), cr is not None)
        if cr is None:
            continue
        check("certified %s %d" % (spec, i), cr["certified"] is True)
        vals = []
        for j in range(2001):
            th = (math.pi / 2) * j / 2000
            x, y, sp, spp = quantities(iv["X"], iv["B"], th)
            vals.append(quantity(spec, x, y, sp, spp))
        lo = min(vals)
        scale = 1.0 + abs(lo)
        check("gap below samples %s %d" % (spec, i), cr["gap"] <= lo + 1e-7 * scale,
              "gap %r min sample %r" % (cr["gap"], lo))
        check("gap near samples %s %d" % (spec, i), lo - cr["gap"] <= 1e-4 * scale,
              "gap %r min sample %r" % (cr["gap"], lo))
        # the exact minimum, rounded: >= 0 up to 1e-12 of the quantity's scale
        check("gap non-negative %s %d" % (spec, i), cr["gap"] >= -1e-12 * scale, cr["gap"])

# the same from a JSON file: strings and objects
cfile = write("cons.json", json.dumps(["convex", {"kind": "decreasing"},
                                       {"kind": "slope-min", "value": -1},
                                       {"kind": "lower", "value": 0}]))
r2 = run("fit", chain, "--json", "--constraints", cfile)
check("file same output", r2.returncode == 0 and r2.stdout == r.stdout, r2.stderr)

# a polyline given as points, and scope
r3 = run("fit", chain, "--json", "--constraint", "lower=poly:50,30;100,3;140,0.2",
         "--constraint", "abs-slope<=1.5@2-4")
check("poly + scope fit", r3.returncode == 0, r3.stderr)
if r3.returncode == 0:
    rep3 = json.loads(r3.stdout)
    scope = rep3["constraints"][1]
    check("scope nulls", [c is None for c in scope] == [True, True, False, False, False, True, True, True])
    check("poly certified", all(c is not None and c["certified"] for c in rep3["constraints"][0]))
rj = write("poly.json", json.dumps([{"kind": "lower", "points": [[50, 30], [100, 3], [140, 0.2]]},
                                    {"kind": "slope-abs", "value": 1.5, "first": 2, "count": 3}]))
r4 = run("fit", chain, "--json", "--constraints", rj)
check("poly file same", r4.returncode == 0 and r4.stdout == r3.stdout, r4.stderr)

# refusals
r = run("fit", chain, "--constraint", "wiggly")
check("unknown spec", r.returncode == 1 and "unknown constraint \"wiggly\"" in r.stderr, r.stderr)
r = run("fit", chain, "--constraint", "concave")
check("not concave", r.returncode == 2 and "not concave here" in r.stderr and
      "(constraint 0, concave)" in r.stderr, r.stderr)
r = run("fit", chain, "--constraint", "convex", "--constraint", "slope<=-0.99")
check("secant beyond cap", r.returncode == 2 and "beyond the slope-max bound -0.99" in r.stderr,
      r.stderr)
r = run("fit", chain, "--constraint", "convex", "--shape", "positive")
check("no shape with constraints", r.returncode == 1 and "--constraint replaces --shape" in r.stderr,
      r.stderr)

flat = write("flat.csv", "0,1\n1,1\n")
r = run("fit", flat, "--constraint", "lower=poly:0,0;0.5,1.2;1,0")
check("unproven exit 3", r.returncode == 3 and "the search gave up" in r.stderr, r.stderr)
tent = write("tent.csv", "0,0\n1,1\n2,0\n")
r = run("fit", tent, "--constraint", "abs-slope<=1")
check("conflict exit 3", r.returncode == 3 and "straight lines of different slopes" in r.stderr,
      r.stderr)

# a bound given by another spline (docs/method.md §13.7): the calls above
# their intrinsic value 100 - K, as a spline through points of that line on
# [40, 99] (default form, geometric: collinear points give slopes -1 and the
# line itself, §4); the gaps against y - (100 - x) sampled here on [40, 99]
intr = write("intrinsic.csv", "k,v\n" + "".join("%r,%r\n" % (k, 100.0 - k)
                                                for k in (40.0, 55.0, 70.0, 85.0, 99.0)))
r5 = run("fit", chain, "--json", "--constraint", "convex", "--constraint", "lower=spline:" + intr)
check("spline bound fit", r5.returncode == 0, r5.stderr)
if r5.returncode == 0:
    rep5 = json.loads(r5.stdout)
    check("spline bound certified", rep5["certified"] is True)
    for i, iv in enumerate(rep5["intervals"]):
        cr = rep5["constraints"][1][i]
        check("spline scope %d" % i, (cr is None) == (iv["x0"] >= 99.0), cr)
        if cr is None:
            continue
        check("spline certified %d" % i, cr["certified"] is True)
        vals = []
        for j in range(2001):
            x, y, sp, spp = quantities(iv["X"], iv["B"], (math.pi / 2) * j / 2000)
            if 40.0 <= x <= 99.0:
                vals.append(y - (100.0 - x))
        lo = min(vals)
        scale = 1.0 + abs(lo)
        check("spline gap below samples %d" % i, cr["gap"] <= lo + 1e-7 * scale,
              "gap %r min sample %r" % (cr["gap"], lo))
        check("spline gap near samples %d" % i, lo - cr["gap"] <= 1e-4 * scale and cr["gap"] > 0,
              "gap %r min sample %r" % (cr["gap"], lo))
    sj = write("spline.json", json.dumps(["convex", {"kind": "lower", "spline": intr}]))
    r6 = run("fit", chain, "--json", "--constraints", sj)
    check("spline file same", r6.returncode == 0 and r6.stdout == r5.stdout, r6.stderr)
# refusals: a datum across the bound curve (exit 2, the point named), the
# curve's own file bad (its line named) or missing (exit 5), no file, a
# spline with points or on a kind that is not a bound (usage, exit 1)
r = run("fit", chain, "--constraint", "upper=spline:" + intr)
check("spline across", r.returncode == 2 and "is not below the upper bound (constraint 0, upper)"
      in r.stderr, r.stderr)
dup = write("dup.csv", "x,y\n1,2\n1,3\n")
r = run("fit", chain, "--constraint", "lower=spline:" + dup)
check("spline bad file", r.returncode == 2 and "dup.csv:3:" in r.stderr, r.stderr)
r = run("fit", chain, "--constraint", "lower=spline:" + os.path.join(TMP, "none.csv"))
check("spline missing file", r.returncode == 5 and "cannot open" in r.stderr, r.stderr)
r = run("fit", chain, "--constraint", "lower=spline:")
check("spline no file", r.returncode == 1 and "needs a file" in r.stderr, r.stderr)
for bad in ({"kind": "convex", "spline": intr},
            {"kind": "lower", "spline": intr, "points": [[0, 0], [1, 1]]}):
    r = run("fit", chain, "--constraints", write("bad.json", json.dumps([bad])))
    check("spline bad object", r.returncode == 1 and "\"spline\"" in r.stderr, r.stderr)

print("test_cli_constraints: %d passed, %d failed" % (passed, failed))
sys.exit(1 if failed else 0)
