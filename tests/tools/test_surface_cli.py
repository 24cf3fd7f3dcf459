#!/usr/bin/env python3
"""Script test of `trigspline surface` (docs/method.md §11).

Usage: python3 tests/tools/test_surface_cli.py BUILD_DIR   (standard library only)

The long and matrix layouts give the same surface; rows in any order give the
same output; nodes are interpolated exactly (round-trip numbers); the
positive scheme stays >= 0 where the unconstrained surface goes negative (a
spiky field, values written here); the percentage field stays in [0, 100];
--json is valid JSON with a certificate per patch; --svg is well-formed XML;
every data error names the file, the line and the node, exits with status 2
(3 for an infeasible patch, 1 for a usage error) and writes nothing.
Also runs the exact check of the Bernstein table (tests/ref/surface_ref.py).
Prints "test_surface_cli: N passed, M failed" last.
"""
import json
import os
import shutil
import random
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

BUILD = sys.argv[1] if len(sys.argv) > 1 else "build"
CLI = os.path.abspath(os.path.join(BUILD, "trigspline"))
HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
TMP = tempfile.mkdtemp(prefix="ts_surface_cli_")
passed = failed = 0


def check(name, cond, detail=""):
    global passed, failed
    if cond:
        passed += 1
    else:
        failed += 1
        print("FAIL: %s %s" % (name, detail))


def run(*args, stdin=None):
    p = subprocess.run([CLI, "surface", *args], input=stdin, capture_output=True, text=True)
    return p.returncode, p.stdout, p.stderr


def write(name, text):
    path = os.path.join(TMP, name)
    with open(path, "w") as f:
        f.write(text)
    return path


def parse_long(text):
    rows = [l.split(",") for l in text.strip().splitlines()[1:]]
    return [(float(a), float(b), float(c)) for a, b, c in rows]


# a spiky positive field on a non-uniform grid (zeros included)
X = [0.0, 0.4, 1.5, 1.7, 3.0, 4.2]
Y = [-1.0, 0.0, 0.3, 2.0, 2.5]
Z = [[0, 0, 5, 0, 1, 0], [0, 12, 0, 0, 0.5, 3], [7, 0, 0, 9, 0, 0], [0, 0.2, 0, 0, 4, 0],
     [1, 0, 0, 6, 0, 2]]
long_rows = [(x, y, Z[j][i]) for j, y in enumerate(Y) for i, x in enumerate(X)]
LONG = write("spiky.csv", "x,y,z\n" + "".join("%r,%r,%r\n" % r for r in long_rows))
shuffled = list(long_rows)
random.Random(7).shuffle(shuffled)
SHUF = write("spiky_shuffled.csv", "x,y,z\n" + "".join("%r,%r,%r\n" % r for r in shuffled))
MAT = write("spiky_matrix.csv", "y\\x," + ",".join(map(repr, X)) + "\n" +
            "".join(repr(y) + "," + ",".join(repr(v) for v in Z[j]) + "\n"
                    for j, y in enumerate(Y)))

# ---- layouts, order, interpolation ------------------------------------------
rc1, out1, _ = run(LONG, "--shape", "positive", "--samples", "6")
rc2, out2, _ = run(SHUF, "--shape", "positive", "--samples", "6")
rc3, out3, _ = run(MAT, "--matrix", "--shape", "positive", "--samples", "6")
check("long ok", rc1 == 0, str(rc1))
check("row order does not matter", out1 == out2)
check("matrix = long", out1 == out3)
pts = parse_long(out1)
check("rows", len(pts) == (5 * 6 + 1) * (4 * 6 + 1), str(len(pts)))
nodes = {(x, y): z for x, y, z in pts}
check("nodes exact", all(nodes.get((x, y)) == z for x, y, z in long_rows))
check("positive >= 0", min(z for _, _, z in pts) >= 0.0)
rc, outn, _ = run(LONG, "--samples", "6")
check("unconstrained goes negative", rc == 0 and min(z for _, _, z in parse_long(outn)) < -0.1)
rc, outm, _ = run(MAT, "--matrix", "--shape", "positive", "--samples", "2", "--matrix-out")
lines = outm.strip().splitlines()
check("matrix out", rc == 0 and len(lines) == 4 * 2 + 2 and lines[0].startswith("y\\x,0,"))
rc, outg, _ = run(LONG, "--grid", "7,5", "--form", "geometric", "--shape", "range")
gp = parse_long(outg)
check("grid", rc == 0 and len(gp) == 35 and gp[-1][:2] == (4.2, 2.5))
check("range", all(0.0 <= z <= 12.0 for _, _, z in gp))
# stdin
with open(LONG) as f:
    rc, outs, _ = run("-", "--shape", "positive", "--samples", "6", stdin=f.read())
check("stdin", rc == 0 and outs == out1)

# ---- percentages -------------------------------------------------------------
PCT = write("pct.csv", "x,y,z\n" + "".join("%r,%r,%r\n" % (x, y, min(100.0, 25 * Z[j][i]))
                                           for j, y in enumerate(Y) for i, x in enumerate(X)))
for form in ("paper", "c1", "geometric"):
    rc, o, _ = run(PCT, "--shape", "bounds", "--lower", "0", "--upper", "100", "--form", form,
                   "--samples", "8")
    zs = [z for _, _, z in parse_long(o)]
    check("percent " + form, rc == 0 and min(zs) >= 0.0 and max(zs) <= 100.0,
          "%s %s" % (min(zs), max(zs)))
rc, o, _ = run(PCT, "--samples", "8")
check("percent unconstrained leaves [0, 100]",
      rc == 0 and (max(z for _, _, z in parse_long(o)) > 100 or min(z for _, _, z in parse_long(o)) < 0))

# ---- JSON and SVG --------------------------------------------------------------
svg = os.path.join(TMP, "s.svg")
rc, oj, err = run(LONG, "--shape", "positive", "--json", "--svg", svg)
check("json rc", rc == 0, err)
try:
    doc = json.loads(oj)
except ValueError:
    doc = {}
check("json fields", doc.get("certified") is True and doc.get("nx_points") == 6 and
      len(doc.get("patches", [])) == 20)
check("json certificates", all(p["certified"] and p["proven_lower"] >= 0 and
                               p["proven_lower"] <= p["sampled_lower"] for p in doc.get("patches", [])))
check("json active", any(p["active"] for p in doc.get("patches", [])))
try:
    root = ET.parse(svg).getroot()
    ok = root.tag.endswith("svg") and len(root.findall(".//{http://www.w3.org/2000/svg}circle")) == 30
except (ET.ParseError, OSError):
    ok = False
check("svg", ok)
rc, oj, _ = run(LONG, "--json", "--form", "geometric", "--shape", "planes", "--lower", "0.1,0.2,-3",
                "--upper", "0,0,20")
doc = json.loads(oj) if rc == 0 else {}
check("planes json", rc == 0 and doc.get("certified") is True and
      all("proven_upper" in p for p in doc.get("patches", [])))

# ---- errors: status, message naming line and node, nothing written -----------
def err_case(name, path, args, status, needles):
    target = os.path.join(TMP, name + ".out")
    rc, _, e = run(path, *args, "-o", target)
    check(name + " status", rc == status, "%d %s" % (rc, e))
    check(name + " message", all(n in e for n in needles), e)
    check(name + " nothing written", not os.path.exists(target))


neg = list(long_rows)
neg[8] = (neg[8][0], neg[8][1], -0.5)  # node (2, 1), line 10
NEG = write("neg.csv", "x,y,z\n" + "".join("%r,%r,%r\n" % r for r in neg))
err_case("negative", NEG, ["--shape", "positive"], 2, ["neg.csv", "line 10", "node (2, 1)", "z = -0.5"])
INF = write("infeasible.csv", "x,y,z\n0,0,4\n1,0,1e-310\n2,0,1\n0,1,4\n1,1,1\n2,1,1\n")
err_case("infeasible", INF, ["--shape", "positive"], 3, ["patch (1, 0) [1, 2] x [0, 1]"])
MISS = write("miss.csv", "x,y,z\n" + "".join("%r,%r,%r\n" % r for r in long_rows[:-1]))
err_case("missing", MISS, [], 2, ["missing node (x=4.2, y=2.5)"])
DUP = write("dup.csv", "x,y,z\n" + "".join("%r,%r,%r\n" % r for r in long_rows + [long_rows[3]]))
err_case("duplicate", DUP, [], 2, ["line 32", "duplicate node (x=1.7, y=-1)", "line 5"])
NAN = write("nan.csv", "x,y,z\n0,0,1\n1,0,nan\n0,1,1\n1,1,1\n")
err_case("nan", NAN, [], 2, ["nan.csv", ":3"])
RAG = write("ragged.csv", "x,y,z\n0,0,1\n1,0\n")
err_case("ragged", RAG, [], 2, ["ragged.csv", ":3"])
err_case("side", LONG, ["--shape", "bounds", "--lower", "0.1"], 2, ["line 2", "node (0, 0)"])
err_case("plane side", LONG, ["--shape", "planes", "--form", "geometric", "--lower", "0,0,0"], 2,
         ["node (0, 0)", "on or across"])
err_case("lines", LONG, ["--shape", "bounds", "--lower", "5", "--upper", "5"], 2, ["spiky.csv"])
err_case("sloped paper", LONG, ["--shape", "planes", "--lower", "1,0,-100"], 1, ["spiky.csv"])
MUNS = write("unsorted.csv", "y\\x,0,2,1\n0,1,2,3\n1,4,5,6\n")
err_case("matrix unsorted x", MUNS, ["--matrix"], 2, ["line 1", "column 4", "x = 1"])
MUNY = write("unsorted_y.csv", "y\\x,0,1\n0,1,2\n2,4,5\n1,4,5\n")
err_case("matrix unsorted y", MUNY, ["--matrix"], 2, ["line 4", "y = 1"])
MBAD = write("mbad.csv", "y\\x,0,b\n0,1,2\n1,4,5\n")
err_case("matrix header", MBAD, ["--matrix"], 2, ["column 3", "\"b\""])
err_case("three columns", MAT, [], 2, ["3 columns"])
err_case("tiny matrix", write("tiny.csv", "y\\x,0\n0,1\n"), ["--matrix"], 2, ["at least 2"])
err_case("no file", os.path.join(TMP, "absent.csv"), [], 5, ["absent.csv"])
# finite z alternating +-1.5e308: the slopes overflow (was reported as "NaN or
# infinite value in the input", which the data are not)
BIG = write("huge.csv", "x,y,z\n" + "".join("%d,%d,%s\n" % (i, j, "1.5e308" if (i + j) % 2 else
                                                            "-1.5e308")
                                           for j in range(60) for i in range(60)))
err_case("huge finite", BIG, ["--shape", "range"], 2, ["huge.csv", "line 2", "node (0, 0)",
                                                       "overflow a double"])
rc, _, e = run(BIG, "--shape", "range", "-o", os.path.join(TMP, "huge.out"))
check("huge finite: not called NaN or infinite", "NaN" not in e and "infinite" not in e, e)
# the input named as -o (its own name, ./name, a symbolic or hard link): refused, kept
for name, target in (("same", LONG), ("dot", "./" + os.path.relpath(LONG)),
                     ("symlink", os.path.join(TMP, "long_link.csv")),
                     ("hard link", os.path.join(TMP, "long_hard.csv"))):
    if name == "symlink" and not os.path.lexists(target):
        os.symlink(LONG, target)
    if name == "hard link" and not os.path.exists(target):
        os.link(LONG, target)
    before = open(LONG).read()
    rc, out, e = run(LONG, "-o", target)
    check("-o the input (%s) refused" % name, rc == 1 and "names the input file" in e and
          out == "", "%d %s" % (rc, e))
    check("-o the input (%s) kept the data" % name, open(LONG).read() == before)
for args, needle in ((["--shape", "wobbly"], "--shape"), (["--alpha", "-1"], "--alpha"),
                     (["--grid", "3"], "--grid"), (["--samples", "0"], "--samples"),
                     (["--bogus", "1"], "unknown option"), (["--form"], "needs a value"),
                     (["--lower", "1,2"], "--lower"), (["--slopes", "user"], "--slopes"),
                     ([LONG], "more than one")):
    rc, _, e = run(LONG, *args)
    check("usage " + needle, rc == 1 and needle in e, e)
rc, _, e = run()
check("usage missing", rc == 1 and "missing DATA" in e)
rc, o, _ = run("--help")
check("help", rc == 0 and "--matrix" in o)
rc, _, e = run(LONG, "--form", "geometric", "--alpha", "0.1")
check("geometric bound", rc == 1 and "geometric" in e, e)

# ---- gridded fields (docs/method.md §11.7): --lower-grid / --upper-grid --------
# the spiky field between a floor 1 below and a ceiling 2 above its own
# range, both on grids of their own (matrix and long layouts); the sides of
# the samples are checked against the exact bilinear fields (fractions)
from fractions import Fraction as Fr  # noqa: E402


def exact_field(fx, fy, fz, x, y):
    i = max(k for k in range(len(fx) - 1) if fx[k] <= x)
    j = max(k for k in range(len(fy) - 1) if fy[k] <= y)
    X0, X1, Y0, Y1 = (Fr(v) for v in (fx[i], fx[i + 1], fy[j], fy[j + 1]))
    X, Y = Fr(x), Fr(y)
    return (Fr(fz[j][i]) * (X1 - X) * (Y1 - Y) + Fr(fz[j][i + 1]) * (X - X0) * (Y1 - Y) +
            Fr(fz[j + 1][i]) * (X1 - X) * (Y - Y0) + Fr(fz[j + 1][i + 1]) * (X - X0) * (Y - Y0)) \
        / ((X1 - X0) * (Y1 - Y0))


FX, FY = [-1.0, 2.0, 5.0], [-2.0, 1.0, 3.0]
FLO = [[-1.5, -1.0, -1.25], [-1.0, -2.0, -1.0], [-1.0, -1.5, -1.0]]   # rows of constant y
FUP = [[14.0, 15.0, 14.5], [15.0, 14.0, 15.0], [14.0, 14.5, 15.0]]
LOG = write("floor.csv", "y\\x," + ",".join(map(repr, FX)) + "\n" +
            "".join(repr(y) + "," + ",".join(map(repr, FLO[j])) + "\n" for j, y in enumerate(FY)))
UPG = write("ceiling_long.csv", "x,y,z\n" + "".join("%r,%r,%r\n" % (x, y, FUP[j][i])
                                                    for j, y in enumerate(FY)
                                                    for i, x in enumerate(FX)))
UPM = write("ceiling.csv", "y\\x," + ",".join(map(repr, FX)) + "\n" +
            "".join(repr(y) + "," + ",".join(map(repr, FUP[j])) + "\n" for j, y in enumerate(FY)))
for form in ("paper", "c1", "geometric"):
    rc, o, e = run(MAT, "--matrix", "--lower-grid", LOG, "--upper-grid", UPM, "--form", form,
                   "--samples", "6")
    check("grids %s rc" % form, rc in (0, 3), e)
    if rc == 0:
        pts = parse_long(o)
        bad = [p for p in pts if not (exact_field(FX, FY, FLO, p[0], p[1]) < Fr(p[2]) <
                                      exact_field(FX, FY, FUP, p[0], p[1]))]
        check("grids %s strictly between the fields" % form, not bad, str(bad[:3]))
    else:
        check("grids %s unproven names a patch" % form, "patch (" in e, e)
rc, o1, _ = run(LONG, "--lower-grid", write("floor_long.csv", "x,y,z\n" + "".join(
    "%r,%r,%r\n" % (x, y, FLO[j][i]) for j, y in enumerate(FY) for i, x in enumerate(FX))),
    "--form", "geometric", "--json")
doc = json.loads(o1) if rc == 0 else {}
check("grids json", rc == 0 and doc.get("shape") == "grids" and doc.get("certified") is True and
      all(p["certified"] and 0 < p["proven_lower"] <= p["sampled_lower"]
          for p in doc.get("patches", [])), o1[:300])
SHORT = write("short_field.csv", "x,y,z\n0,-1,0\n4.2,-1,0\n0,2,0\n4.2,2,0\n")
err_case("grid not covering", LONG, ["--lower-grid", SHORT], 2,
         ["short_field.csv", "lower field's grid [0, 4.2] x [-1, 2] does not cover",
          "[0, 4.2] x [-1, 2.5]"])
ONF = write("on_field.csv", "x,y,z\n-1,-2,0\n5,-2,0\n-1,3,0\n5,3,0\n")
err_case("node on a field", LONG, ["--lower-grid", ONF], 2,
         ["line 2", "node (0, 0)", "not above the lower field, whose value there is 0"])
err_case("fields meet", LONG, ["--lower-grid", ONF, "--upper-grid", ONF], 2,
         ["the upper field (value 0) is not above the lower field (value 0)"])
TENT = write("tent.csv", "x,y,z\n0,0,-1\n1,0,-1\n2,0,-1\n0,1,-1\n1,1,0.5\n2,1,-1\n"
             "0,2,-1\n1,2,-1\n2,2,-1\n")
FLAT = write("flat.csv", "x,y,z\n0,0,0\n2,0,0\n0,2,0\n2,2,0\n")
err_case("field bulging past the data", FLAT, ["--lower-grid", TENT], 3, ["patch (0, 0)"])
rc, _, e = run(LONG, "--shape", "bounds", "--lower", "0", "--lower-grid", LOG)
check("grids with another shape: usage", rc == 1 and "--shape grids" in e, e)
rc, _, e = run(LONG, "--shape", "grids")
check("grids without a field: usage", rc == 1 and "--lower-grid" in e, e)
rc, _, e = run(LONG, "--lower-grid", os.path.join(TMP, "absent_field.csv"))
check("absent field: I/O", rc == 5 and "absent_field.csv" in e, e)

# ---- PNG and PDF plots (converted from the SVG, as for fit), and the format
# given by the option: a plot extension that says another format is refused
if shutil.which("rsvg-convert"):
    png, pdf = os.path.join(TMP, "s.png"), os.path.join(TMP, "s.pdf")
    rc, _, e = run(LONG, "--shape", "positive", "--png", png, "-o", os.devnull)
    with open(png, "rb") as fh:
        head = fh.read(8) if rc == 0 else b""
    check("png", rc == 0 and head == b"\x89PNG\r\n\x1a\n", e)
    rc, _, e = run(LONG, "--shape", "positive", "--pdf", pdf, "-o", os.devnull)
    with open(pdf, "rb") as fh:
        head = fh.read(5) if rc == 0 else b""
    check("pdf", rc == 0 and head == b"%PDF-", e)
rc, _, e = run(LONG, "--svg", os.path.join(TMP, "x.png"))
check("svg into .png refused", rc == 1 and "extension" in e
      and not os.path.exists(os.path.join(TMP, "x.png")), e)

# ---- the documentation: every option of --help in trigspline(1)'s SURFACE
# section (as a .TP item), its exit statuses, and the README's surface example runs
import re  # noqa: E402

rc, o, _ = run("--help")
opts = sorted(set(re.findall(r"(?<![\w-])(--[a-z][a-z-]*|-o|-h)\b", o)))
with open(os.path.join(REPO, "docs", "trigspline.1")) as fh:
    man = fh.read()
sec = man[man.index(".SH SURFACE"):man.index(".SH", man.index(".SH SURFACE") + 4)]
items = [sec.split("\n")[k + 1].replace("\\-", "-") for k, ln in
         enumerate(sec.split("\n")) if ln == ".TP"]
check("help lists options", len(opts) >= 18, opts)
for op in opts:
    check("man page documents surface " + op, any(re.search(r"(?<![\w-])%s\b" % re.escape(op),
                                                            it) for it in items), op)
check("man page surface synopsis", ".B trigspline surface" in man[:man.index(".SH DESCRIPTION")])
for code, word in (("0", "success"), ("1", "usage"), ("2", "bad data"), ("3", "a patch"),
                   ("5", "a file cannot be read")):
    check("man page surface exit %s" % code, re.search(r"\b%s %s" % (code, word),
                                                       " ".join(sec.split())) is not None)
for fmt in ("matrix layout", "long format", "--svg", "--png", "--pdf"):
    check("man page surface " + fmt, fmt in sec.replace("\\-", "-").replace(".B ", ""), fmt)
with open(os.path.join(REPO, "README.md")) as fh:
    readme = fh.read()
block = readme[readme.index("## Using the command"):]
block = block[block.index("```sh"):block.index("```", block.index("```sh") + 5)]
cmd = re.search(r"build/trigspline surface (.*?)(?<!\\)\n", block, re.S)
check("README has a surface example", cmd is not None, block[-400:])
if cmd:
    args = cmd.group(1).replace("\\\n", " ").split()
    args = [os.path.join(REPO, a) if a.startswith("data/") else
            os.path.join(TMP, a) if a.endswith((".svg", ".csv")) else a for a in args]
    rc, out, e = run(*args)
    check("README surface example runs", rc == 0 and out == "" and
          os.path.getsize(args[args.index("-o") + 1]) > 0, e)

# ---- the exact reference of the Bernstein table -------------------------------
p = subprocess.run([sys.executable, os.path.join(REPO, "tests", "ref", "surface_ref.py"), REPO],
                   capture_output=True, text=True)
check("surface_ref.py", p.returncode == 0 and "0 failed" in p.stdout, p.stdout)

shutil.rmtree(TMP, ignore_errors=True)
print("test_surface_cli: %d passed, %d failed" % (passed, failed))
sys.exit(1 if failed else 0)
