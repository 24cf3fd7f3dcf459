#!/usr/bin/env python3
"""The overshoot report of the command-line tool (docs/cli.md, docs/method.md §5.9).

Usage: python3 tests/tools/test_cli_overshoot.py BUILD_DIR     (standard library only)

Checks, on the paper's Table 2 data (a sharp peak of 25: small alpha overshoots)
and a flat-topped series, in the paper, C1 and geometric forms:
  - every interval's y_min / y_max / excursion_* of `fit --json` against
    dense sampling of S(theta) = sum A_l(theta) B_l written here from the closed
    form of the basis (docs/method.md §2: A0 = (1-s)^3, A1 = 3s - 4s^2 + s^3,
    A2 = 3c - 4c^2 + c^3, A3 = (1-c)^3), 4001 samples per interval; tolerance:
    the sampling bound 1/2 max|S''| (dtheta/2)^2 with max|S''| <= 8|B1-B0| +
    8|B2-B0| + 6|B3-B0| (max|A_l''| = 6, 8, 8, 6), plus 1e-12 of the values
    (rounding of a few operations on numbers printed round-trip);
  - the "overshoot" summary against the same sampling, and against the
    largest value of the tool's own dense CSV output (which it must not exceed);
  - the warning line on stderr exactly when the largest excursion exceeds
    warn_fraction (0.1) of the data range, in the whole-data path (--json,
    --no-stream), the streaming path (plain CSV) and certify; never on stdout.
Prints "test_cli_overshoot: N passed, M failed" last.
"""
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile

BUILD = sys.argv[1] if len(sys.argv) > 1 else "build"
CLI = os.path.abspath(os.path.join(BUILD, "trigspline"))
HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
T2 = os.path.join(REPO, "data", "paper", "table2_above_line.csv")
TMP = tempfile.mkdtemp(prefix="ts_overshoot_test_")
FRACTION = 0.1  # docs/cli.md

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


def seg(B, th):
    s, c = math.sin(th), math.cos(th)
    A = ((1 - s) ** 3, 3 * s - 4 * s * s + s ** 3, 3 * c - 4 * c * c + c ** 3, (1 - c) ** 3)
    return sum(a * b for a, b in zip(A, B))


def sampled(B, n=4000):
    ys = [B[0]] + [seg(B, 0.5 * math.pi * j / n) for j in range(1, n)] + [B[3]]
    d = 0.5 * math.pi / n
    g2 = 8 * abs(B[1] - B[0]) + 8 * abs(B[2] - B[0]) + 6 * abs(B[3] - B[0])
    tol = 0.5 * g2 * (d / 2) ** 2 + 1e-12 * max(abs(b) for b in B)
    return min(ys), max(ys), tol


def write(name, rows):
    p = os.path.join(TMP, name)
    with open(p, "w") as fh:
        for x, y in rows:
            fh.write("%r,%r\n" % (x, y))
    return p


def check_json(label, out):
    rep = json.loads(out)
    lo_all, hi_all, ea, eb, tol_all = math.inf, -math.inf, 0.0, 0.0, 0.0
    data = [k["f"] for k in rep["knots"]]
    for iv in rep["intervals"]:
        lo, hi, tol = sampled(iv["B"])
        tol_all = max(tol_all, tol)
        f0, f1 = iv["B"][0], iv["B"][3]
        check(label + " y_min", iv["y_min"] <= lo + tol and iv["y_min"] >= lo - tol,
              "interval %d: %r vs sampled %r" % (iv["i"], iv["y_min"], lo))
        check(label + " y_max", iv["y_max"] >= hi - tol and iv["y_max"] <= hi + tol,
              "interval %d: %r vs sampled %r" % (iv["i"], iv["y_max"], hi))
        check(label + " excursion_above",
              abs(iv["excursion_above"] - max(0.0, hi - max(f0, f1))) <= 2 * tol,
              "interval %d: %r" % (iv["i"], iv["excursion_above"]))
        check(label + " excursion_below",
              abs(iv["excursion_below"] - max(0.0, min(f0, f1) - lo)) <= 2 * tol,
              "interval %d: %r" % (iv["i"], iv["excursion_below"]))
        check(label + " places", iv["x0"] <= iv["at_y_min"] <= iv["x1"]
              and iv["x0"] <= iv["at_y_max"] <= iv["x1"])
        lo_all, hi_all = min(lo_all, lo), max(hi_all, hi)
        ea = max(ea, hi - max(f0, f1))
        eb = max(eb, min(f0, f1) - lo)
    ov = rep["overshoot"]
    check(label + " data range", ov["data_min"] == min(data) and ov["data_max"] == max(data))
    check(label + " overall y_max", abs(ov["y_max"] - hi_all) <= tol_all, repr(ov))
    check(label + " overall y_min", abs(ov["y_min"] - lo_all) <= tol_all, repr(ov))
    check(label + " max_excursion_above", abs(ov["max_excursion_above"] - ea) <= 2 * tol_all)
    check(label + " max_excursion_below", abs(ov["max_excursion_below"] - eb) <= 2 * tol_all)
    check(label + " warn_fraction", ov["warn_fraction"] == FRACTION)
    ratio = max(ov["max_excursion_above"], ov["max_excursion_below"]) / (max(data) - min(data))
    check(label + " warning flag", ov["warning"] == (ratio > FRACTION))
    # the tool's own dense samples never exceed the exact range
    return rep, ratio


def dense_max(path, args):
    r = run("fit", path, "--samples", "400", *args)
    ys = [float(line.split(",")[1]) for line in r.stdout.splitlines()[1:]]
    return min(ys), max(ys), r


def test_table2():
    for form, alphas in (("paper", ("0.1", "1", "4")), ("c1", ("0.1", "1")),
                         ("geometric", ("0.5", "2"))):
        for alpha in alphas:
            for shape in ("none", "positive"):
                label = "table2 %s alpha %s %s" % (form, alpha, shape)
                args = ["--shape", shape, "--alpha", alpha, "--form", form]
                r = run("fit", T2, "--json", *args)
                check(label + " exit", r.returncode == 0, r.stderr)
                if r.returncode:
                    continue
                rep, ratio = check_json(label, r.stdout)
                warned = "warning: the curve" in r.stderr
                check(label + " warning line (json)", warned == (ratio > FRACTION),
                      "ratio %.3g stderr %r" % (ratio, r.stderr))
                check(label + " nothing on stdout", "warning: the curve" not in r.stdout)
                lo, hi, rs = dense_max(T2, args)  # streaming path
                ov = rep["overshoot"]
                check(label + " dense <= exact", hi <= ov["y_max"] * (1 + 1e-12) + 1e-12
                      and lo >= ov["y_min"] - 1e-12 * abs(ov["y_min"]) - 1e-12,
                      "%r %r vs %r %r" % (lo, hi, ov["y_min"], ov["y_max"]))
                check(label + " warning line (stream)",
                      ("warning: the curve" in rs.stderr) == (ratio > FRACTION), rs.stderr)
                rn = run("fit", T2, "--no-stream", *args)
                check(label + " warning line (no-stream)",
                      ("warning: the curve" in rn.stderr) == (ratio > FRACTION), rn.stderr)


def test_known_values():
    # alpha 0.1 on Table 2: a large overshoot, warned, named interval 2 [3, 9]
    r = run("fit", T2, "--alpha", "0.1", "--form", "paper", "--slopes", "arithmetic", "--json")
    ov = json.loads(r.stdout)["overshoot"]
    check("t2 alpha 0.1 warns", ov["warning"] and "warning: the curve rises" in r.stderr,
          r.stderr)
    check("t2 alpha 0.1 names the interval", "interval %d [" % ov["interval_above"] in r.stderr)
    check("t2 warning is one line", r.stderr.count("\n") == 1, r.stderr)
    # a straight line: no excursion at all (exactly 0), no warning
    p = write("line.csv", [(float(i), 2.0 * i + 1) for i in range(8)])
    r = run("fit", p, "--json", "--form", "paper")
    ov = json.loads(r.stdout)["overshoot"]
    check("line: no excursion", ov["max_excursion_above"] == 0 and ov["max_excursion_below"] == 0,
          repr(ov))
    check("line: no warning", r.stderr == "", r.stderr)
    # a flat top next to a step: the dip below is reported ("dips ... below")
    p = write("step.csv", [(0.0, 10.0), (1.0, 10.0), (2.0, 10.0), (3.0, 0.0), (4.0, 0.0),
                           (5.0, 0.0)])
    r = run("fit", p, "--json", "--form", "paper", "--alpha", "0.1")
    rep, ratio = check_json("step", r.stdout)
    check("step: warned iff above fraction", ("warning" in r.stderr) == (ratio > FRACTION),
          "%r %r" % (ratio, r.stderr))


def test_certify():
    r = run("certify", T2, "--alpha", "0.1", "--beta", "0", "--shape", "positive",
            "--form", "paper", "--json")
    check("certify exit", r.returncode in (0, 4), r.stderr)
    rep, ratio = check_json("certify", r.stdout)
    check("certify warning", ("warning: the curve" in r.stderr) == (ratio > FRACTION), r.stderr)


def main():
    if not os.access(CLI, os.X_OK):
        print("test_cli_overshoot: %s not built" % CLI)
        print("test_cli_overshoot: 0 passed, 1 failed")
        return 1
    try:
        for t in (test_table2, test_known_values, test_certify):
            try:
                t()
            except Exception as e:
                check("%s raised" % t.__name__, False, repr(e))
    finally:
        shutil.rmtree(TMP, ignore_errors=True)
    print("test_cli_overshoot: %d passed, %d failed" % (passed, failed))
    return 0 if failed == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
