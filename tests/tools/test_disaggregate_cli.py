#!/usr/bin/env python3
"""Script test of `trigspline disaggregate` (docs/method.md §12, docs/cli.md).

Usage: python3 tests/tools/test_disaggregate_cli.py BUILD_DIR   (standard library only)

Daily rain (data/examples/rainfall_daily.csv as dates, and the real series
data/rain/hadukp_sw_england_daily_2016.csv) to hourly totals:
every day's 24 hours add up to its total (1e-13 relative: sums of 24
shortest-round-trip numbers), none negative, dates written as read; bins as
start,end,total rows; the rate; every error exits with its status and names
the file and line.  Prints "test_disaggregate_cli: N passed, M failed" last.
"""
import os
import subprocess
import sys
import tempfile

BUILD = sys.argv[1] if len(sys.argv) > 1 else "build"
CLI = os.path.abspath(os.path.join(BUILD, "trigspline"))
HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
TMP = tempfile.mkdtemp(prefix="ts_disagg_cli_")
passed = failed = 0


def check(name, cond, detail=""):
    global passed, failed
    if cond:
        passed += 1
    else:
        failed += 1
        print("FAIL: %s %s" % (name, detail))


def run(args, data=None):
    p = subprocess.run([CLI, "disaggregate"] + args, input=data, capture_output=True, text=True)
    return p.returncode, p.stdout, p.stderr


def write(name, text):
    path = os.path.join(TMP, name)
    with open(path, "w") as f:
        f.write(text)
    return path


# daily rain as dates
rows = []
with open(os.path.join(REPO, "data", "examples", "rainfall_daily.csv")) as f:
    for line in f:
        if line[:1].isdigit():
            day, mm = line.strip().split(",")
            rows.append((int(day), float(mm)))
text = "date,rain_mm\n" + "".join("2021-06-%02d,%s\n" % (d if d <= 30 else d, mm)
                                  for d, mm in rows if d <= 30)
totals = [mm for d, mm in rows if d <= 30]
path = write("rain.csv", text)
rc, out, err = run([path, "--step", "1h"])
check("daily: exit 0", rc == 0, err)
lines = out.splitlines()
check("daily: header", lines[0] == "start,end,total", lines[0])
cells = [ln.split(",") for ln in lines[1:]]
check("daily: 24 cells a day", len(cells) == 24 * len(totals), len(cells))
check("daily: first cell", cells[0][0] == "2021-06-01" and cells[0][1] == "2021-06-01T01:00",
      cells[0])
vals = [float(c[2]) for c in cells]
check("daily: none negative", min(vals) >= 0.0, min(vals))
worst = 0.0
for j, t in enumerate(totals):
    s = sum(vals[24 * j:24 * j + 24])
    if t > 0:
        worst = max(worst, abs(s - t) / t)
    else:
        check("daily: dry day dry", s == 0.0, (j, s))
check("daily: totals kept", worst <= 1e-13, worst)

# a real daily series (data/rain: HadUKP South West England, 177 days, 12 of
# them 0.00): the same three checks
real = os.path.join(REPO, "data", "rain", "hadukp_sw_england_daily_2016.csv")
with open(real) as f:
    rtot = [float(ln.split(",")[1]) for ln in f if ln[:1].isdigit()]
rc, out, err = run([real, "--step", "1h"])
rv = [float(ln.split(",")[2]) for ln in out.splitlines()[1:]]
check("real: exit 0, 24 cells a day", rc == 0 and len(rv) == 24 * len(rtot), err)
check("real: none negative", rv and min(rv) >= 0.0, min(rv) if rv else None)
rworst = 0.0
for j, t in enumerate(rtot):
    s = sum(rv[24 * j:24 * j + 24])
    if t > 0:
        rworst = max(rworst, abs(s - t) / t)
    else:
        check("real: dry day dry", s == 0.0, (j, s))
check("real: totals kept", rworst <= 1e-13, rworst)

# bins as rows, numbers
rc, out, err = run(["--step", "0.25"], "0,1,2\n1,3,4\n3,4,0\n")
cells = [ln.split(",") for ln in out.splitlines()[1:]]
check("rows: exit 0", rc == 0, err)
check("rows: 16 cells", len(cells) == 16, len(cells))
check("rows: bin 1 kept", abs(sum(float(c[2]) for c in cells[4:12]) - 4.0) <= 1e-14, cells)
check("rows: last bin dry", all(float(c[2]) == 0.0 for c in cells[12:]), cells[12:])

# a step that is a whole fraction only to rounding: 24 cells a bin, not 25
rc, out, err = run(["--step", repr(1 / 24)], "0,1\n1,2\n")
check("step 1/24: 48 cells", rc == 0 and len(out.splitlines()) == 49, len(out.splitlines()))

# the rate
rc, out, err = run(["--step", "0.1", "--rate"], "0,0\n1,5\n2,0\n")
r = [float(ln.split(",")[1]) for ln in out.splitlines()[1:]]
check("rate: exit 0 and header", rc == 0 and out.startswith("x,rate\n"), err)
check("rate: 31 points, none negative", len(r) == 31 and min(r) >= 0.0, r)
check("rate: zero at the dry edges", r[10] == 0.0 and r[20] == 0.0, (r[10], r[20]))
out_path = os.path.join(TMP, "o.csv")
rc, out, err = run(["--step", "0.5", "-o", out_path], "0,1\n1,2\n")
check("-o writes the file", rc == 0 and out == "" and open(out_path).read().startswith("start"),
      err)

# errors
rc, out, err = run(["--step", "0.5"], "0,1\n1,-2\n")
check("negative: exit 2, names the line", rc == 2 and "<stdin>:2:" in err and out == "", err)
check("negative: names the bin and its total",
      "<stdin>:2: bin 1 [1, 2]: total -2 is negative; totals must be >= 0" in err, err)
rc, out, err = run(["--step", "0.5", "--hi", "1"], "0,0\n1,1\n2,1\n")
# means 0 and 1 under hi = 1: the edge value must be <= 0 and >= 1 (method.md 12.4)
check("neighbours --hi refuses: exit 3, names both bins",
      rc == 3 and "bin 0 [0, 1] and bin 1 [1, 2]: the means 0 and 1 are too far apart" in err, err)
rc, out, err = run([], "0,1\n1,2\n")
check("no --step: exit 1", rc == 1 and "--step" in err, err)
rc, out, err = run([path, "--step", "1q"])
check("bad step: exit 1", rc == 1, err)
rc, out, err = run(["--step", "0.5"], "0,1,2\n2,3,4\n")
check("gap between bins: exit 2", rc == 2 and "contiguous" in err, err)
rc, out, err = run(["--step", "0.5", "--hi", "1"], "0,1\n1,3\n")
check("mean above --hi: exit 3", rc == 3 and "<stdin>:2:" in err, err)
check("mean above --hi: names the mean and the bounds",
      "bin 1 [1, 2]: total 3 gives the mean 3, outside the rate bounds [0, 1]" in err, err)
rc, out, err = run(["--step", "0.5", "--alpha", "0"], "0,1\n1,3\n")
check("alpha 0: exit 1", rc == 1, err)
rc, out, err = run(["--bogus"])
check("unknown option: exit 1", rc == 1, err)
rc, out, err = run(["--help"])
check("--help", rc == 0 and out.startswith("Usage: trigspline disaggregate"), err)

print("test_disaggregate_cli: %d passed, %d failed" % (passed, failed))
sys.exit(1 if failed else 0)
