#!/usr/bin/env python3
"""What a newcomer meets in the command's second hour: input corners and plots.

Usage: python3 tests/tools/test_cli_first_hour.py BUILD_DIR   (standard library only)

Input (docs/cli.md, docs/options.md):
  - compressed input (gzip, bzip2, xz, zstd, zip) is named as such with the
    command that decompresses it, the file named (was: "no data rows");
  - --date-format reads x with a strptime-like format: the samples equal those
    of the same data written in ISO 8601 (the expected values are the ISO
    run's, so the check is the parsing, not the spline);
  - --units-row skips the line under the header; --skip N counts lines before
    the header (pandas read_csv: skiprows=N then header=0), so --skip 1 on a
    units file makes the units the header, as documented;
  - --step S samples at the multiples of S (round clock times, decimal steps
    written as the shortest decimals: 0.3 not 0.30000000000000004), with
    --grid A:B from A; the values equal --at at the same x;
  - the matrix layout accepts an empty corner cell (pandas DataFrame.to_csv);
  - --grid outside a time x's data writes nothing to standard output.
Plots:
  - log ticks at 1-2-5 (then every digit) within three decades, never the
    10^(k/5) values 0.398, 0.631, 1.58, 2.51 of linear ticks of log10 y;
  - date ticks: ASCII hyphens (no U+2212 inside a date), the first with its
    year, at round clock times;
  - surface heatmap: sequential (viridis: its end colours #440154 / #fde725)
    on non-negative data, diverging (white at 0) only on data of both signs;
    colour-bar labels short and inside the image; axis ticks; patches hatched
    only where the surface built without the scheme leaves the bounds (z = x*y
    on a grid: never, while its nodes touch the bound 0).
  - the overshoot warning's amounts to 3 significant digits.
Prints "test_cli_first_hour: N passed, M failed" last.
"""
import bz2
import gzip
import lzma
import os
import re
import shutil
import subprocess
import sys
import tempfile
import zipfile

BUILD = sys.argv[1] if len(sys.argv) > 1 else "build"
CLI = os.path.abspath(os.path.join(BUILD, "trigspline"))
HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
TMP = tempfile.mkdtemp(prefix="ts_first_hour_")

passed = 0
failed = 0


def check(name, cond, detail=""):
    global passed, failed
    if cond:
        passed += 1
    else:
        failed += 1
        print("FAIL: %s %s" % (name, detail))


def run(*args, stdin=None):
    return subprocess.run([CLI] + list(args), capture_output=True, text=True,
                          input=stdin)


def write(name, text, mode="w"):
    path = os.path.join(TMP, name)
    with open(path, mode) as f:
        f.write(text)
    return path


ISO = ("time,q\n2024-01-05T10:00+01:00,1.5\n2024-01-05T11:00+01:00,2\n"
       "2024-01-05T12:30+01:00,1\n2024-01-05T14:00+01:00,3\n")


def test_compressed():
    text = ISO.encode()
    cases = [("gz", gzip.compress(text), "gzip", "zcat"),
             ("bz2", bz2.compress(text), "bzip2", "bzcat"),
             ("xz", lzma.compress(text), "xz", "xzcat"),
             ("zst", b"\x28\xb5\x2f\xfd" + b"\0" * 20, "zstd", "zstdcat")]
    for ext, data, kind, tool in cases:
        p = write("in.csv." + ext, data, "wb")
        r = run("fit", p)
        want = "%s: %s-compressed input: decompress it first (%s %s | trigspline ...)" % (
            p, kind, tool, p)
        check("%s named" % kind, r.returncode == 2 and want in r.stderr and r.stdout == "",
              "%d %r" % (r.returncode, r.stderr))
    r = subprocess.run([CLI, "fit", "-"], input=gzip.compress(text), capture_output=True)
    check("gzip on stdin", r.returncode == 2 and b"<stdin>: gzip-compressed input" in r.stderr
          and b"zcat FILE" in r.stderr, repr(r.stderr))
    zp = os.path.join(TMP, "in.zip")
    with zipfile.ZipFile(zp, "w") as z:
        z.writestr("in.csv", ISO)
    r = run("fit", zp)
    check("zip named", r.returncode == 2 and "a zip archive" in r.stderr, r.stderr)
    r = run("fit", zp, "--skip", "2")
    check("sniffed before --skip", r.returncode == 2 and "a zip archive" in r.stderr, r.stderr)


def test_date_format():
    ref = run("fit", write("iso.csv", ISO), "--samples", "4")
    check("iso reference", ref.returncode == 0, ref.stderr)
    ref_rows = ref.stdout.splitlines()[1:]
    # the same instants written day/month/year with a decimal comma; no zone: UTC
    dmy = ("Datum;Abfluss\n05/01/2024 09:00;1,5\n05/01/2024 10:00;2\n05/01/2024 11:30;1\n"
           "05/01/2024 13:00;3\n")
    r = run("fit", write("dmy.csv", dmy), "--date-format", "%d/%m/%Y %H:%M",
            "--decimal-comma", "--samples", "4")
    rows = r.stdout.splitlines()
    check("date-format runs", r.returncode == 0, r.stderr)
    check("date-format header", rows[:1] == ["Datum,Abfluss"], str(rows[:1]))
    check("date-format same values", [x.split(",")[1] for x in rows[1:]] ==
          [x.split(",")[1] for x in ref_rows], "%r %r" % (rows[1:3], ref_rows[:2]))
    check("date-format written as ISO 8601 (UTC)", rows[1] == "2024-01-05T09:00,1.5", rows[1])
    # with a zone: the same output as the ISO input
    z = ("t,q\n05.01.2024 10:00 +0100,1.5\n05.01.2024 11:00 +0100,2\n"
         "05.01.2024 12:30 +0100,1\n05.01.2024 14:00 +0100,3\n")
    r = run("fit", write("z.csv", z), "--date-format", "%d.%m.%Y %H:%M %z", "--samples", "4")
    check("date-format %z", r.returncode == 0 and
          [x.split(",")[1] for x in r.stdout.splitlines()[1:]] ==
          [x.split(",")[1] for x in ref_rows], r.stderr)
    # digits only: a date all the same
    r = run("fit", write("ymd.csv", "date,q\n20240105,1\n20240106,2\n20240108,1\n"),
            "--date-format", "%Y%m%d", "--samples", "2")
    check("date-format %Y%m%d", r.returncode == 0 and
          r.stdout == "date,q\n2024-01-05,1\n2024-01-06,2\n2024-01-08,1\n", r.stdout + r.stderr)
    r = run("fit", write("us.csv", "d,q\n1/5/2024 11:00 AM,1\n1/5/2024 12:00 PM,2\n"
                         "1/5/2024 1:30 pm,1\n"), "--date-format", "%m/%d/%Y %I:%M %p",
            "--samples", "2")
    check("date-format %I %p", r.returncode == 0 and r.stdout.splitlines()[1:] ==
          ["2024-01-05T11:00,1", "2024-01-05T12:00,2", "2024-01-05T13:30,1"], r.stdout)
    r = run("fit", write("mon.csv", "d,q\n5 Jan 2024,1\n6 january 2024,2\n7 JAN 2024,4\n"),
            "--date-format", "%d %b %Y", "--samples", "2")
    check("date-format %b", r.returncode == 0 and r.stdout.splitlines()[1:] ==
          ["2024-01-05,1", "2024-01-06,2", "2024-01-07,4"], r.stdout + r.stderr)
    r = run("fit", write("bad.csv", "d,q\n05/01/2024 10:00,1\n31/02/2024 11:00,2\n"),
            "--date-format", "%d/%m/%Y %H:%M")
    check("date-format error names line and format", r.returncode == 2 and
          'bad.csv:3:1: not a date of the format "%d/%m/%Y %H:%M": "31/02/2024 11:00"'
          in r.stderr and r.stdout == "", r.stderr)
    r = run("fit", "--help")
    check("date-format in help", "--date-format FMT" in r.stdout)


def test_units_row():
    plain = run("fit", write("plain.csv", "day,rain\n1,0\n2,3\n3,1\n"), "--samples", "3")
    u = write("units.csv", "day,rain\nd,mm\n1,0\n2,3\n3,1\n")
    r = run("fit", u, "--units-row", "--samples", "3")
    check("units row skipped", r.returncode == 0 and r.stdout == plain.stdout,
          r.stdout + r.stderr)
    r = run("fit", u, "--samples", "3")
    check("units row hint", r.returncode == 2 and "--units-row" in r.stderr, r.stderr)
    # --skip N: lines before the header (pandas skiprows=N): the units become the header
    r = run("fit", u, "--skip", "1", "--samples", "3")
    check("--skip counts lines before the header", r.returncode == 0 and
          r.stdout.startswith("d,mm\n"), r.stdout)
    m = write("meta.csv", "station: Bern\nday,rain\nd,mm\n1,0\n2,3\n3,1\n")
    r = run("fit", m, "--skip", "1", "--units-row", "--samples", "3")
    check("--skip with --units-row", r.returncode == 0 and r.stdout == plain.stdout,
          r.stdout + r.stderr)


def test_step():
    t = write("t.csv", ISO)
    r = run("fit", t, "--step", "15min")
    rows = r.stdout.splitlines()
    check("step runs", r.returncode == 0, r.stderr)
    xs = [x.split(",")[0] for x in rows[1:]]
    check("step: round times", len(xs) == 17 and all(re.fullmatch(
        r"2024-01-05T(1[0-4]):(00|15|30|45)\+01:00", x) for x in xs), str(xs[:3]))
    at = run("fit", t, "--at", ",".join(xs))
    check("step values = --at values", at.stdout == r.stdout, at.stdout[:200])
    r = run("fit", t, "--step", "1d")
    check("step 1d: nothing inside", r.returncode == 1 and "no multiple" in r.stderr, r.stderr)
    r = run("fit", t, "--grid", "2024-01-05T10:10+01:00:2024-01-05T11:00+01:00", "--step", "20min")
    check("grid A:B with step", r.stdout.splitlines()[1:] and
          [x.split(",")[0] for x in r.stdout.splitlines()[1:]] ==
          ["2024-01-05T10:10+01:00", "2024-01-05T10:30+01:00", "2024-01-05T10:50+01:00"],
          r.stdout + r.stderr)
    n = write("n.csv", "x,y\n0,0\n1,1\n2,0\n")
    r = run("fit", n, "--step", "0.3")
    check("decimal step: shortest decimals", [x.split(",")[0] for x in r.stdout.splitlines()[1:]]
          == ["0", "0.3", "0.6", "0.9", "1.2", "1.5", "1.8"], r.stdout)
    r = run("fit", n, "--grid", "0.1:0.5", "--step", "0.1")
    check("grid 0.1:0.5 step 0.1", [x.split(",")[0] for x in r.stdout.splitlines()[1:]] ==
          ["0.1", "0.2", "0.3", "0.4", "0.5"], r.stdout)
    r = run("fit", n, "--step", "1h")
    check("unit on numbers refused", r.returncode == 1 and "dates only" in r.stderr, r.stderr)
    r = run("fit", t, "--step", "60")
    check("time step needs a unit", r.returncode == 1 and "give the step a unit" in r.stderr,
          r.stderr)
    r = run("fit", t, "--step", "1fortnight")
    check("unknown unit", r.returncode == 1 and "unknown unit" in r.stderr, r.stderr)
    r = run("fit", n, "--grid", "0:1")
    check("grid A:B needs step", r.returncode == 1 and "needs --step" in r.stderr, r.stderr)
    r = run("fit", n, "--grid", "0:1:3", "--step", "0.5")
    check("count and step refused", r.returncode == 1 and "not both" in r.stderr, r.stderr)
    # --grid outside a time x: nothing written before the error
    r = run("fit", t, "--grid", "0:1:3")
    check("grid outside: stdout empty", r.returncode == 2 and r.stdout == "" and
          "outside the data range" in r.stderr, repr(r.stdout))
    r = run("fit", t, "--grid", "0:1:3", "--json")
    check("grid outside (json): stdout empty", r.returncode == 2 and r.stdout == "",
          repr(r.stdout))


def test_matrix_corner():
    ref = run("surface", write("m1.csv", "y\\x,0,1,2\n10,1,2,3\n20,2,3,5\n30,3,4,6\n"),
              "--matrix", "--samples", "2")
    check("matrix reference", ref.returncode == 0, ref.stderr)
    # pandas DataFrame.to_csv(): an empty corner cell
    r = run("surface", write("m2.csv", ",0,1,2\n10,1,2,3\n20,2,3,5\n30,3,4,6\n"), "--matrix",
            "--samples", "2")
    check("empty corner read", r.returncode == 0 and r.stdout == ref.stdout, r.stderr)
    r = run("surface", "-", "--matrix", "--samples", "2",
            stdin='"",0,1,2\n10,1,2,3\n20,2,3,5\n30,3,4,6\n')
    check("quoted empty corner on stdin", r.returncode == 0 and r.stdout == ref.stdout, r.stderr)
    r = run("surface", write("m3.csv", "x,y,z\n,0,1\n"))
    check("long layout: an empty field still an error", r.returncode == 2 and
          "empty field" in r.stderr, r.stderr)


def svg_texts(path, cls):
    s = open(path).read()
    m = re.search(r'<g class="%s"[^>]*>(.*?)</g>' % cls, s, re.S)
    return re.findall(r"<text[^>]*>([^<]*)</text>", m.group(1)) if m else []


def test_log_ticks():
    for name, data in (("drug", os.path.join(REPO, "data", "examples", "drug_concentration.csv")),
                       ("t1", os.path.join(REPO, "data", "paper", "table1_positive.csv"))):
        svg = os.path.join(TMP, name + "_log.svg")
        r = run("fit", data, "--logy", "--points-only", "--svg", svg, "-o", os.devnull)
        labels = [x.replace("&#8722;", "-") for x in svg_texts(svg, "yticks")]
        check("%s log ticks exist" % name, r.returncode == 0 and len(labels) >= 3, str(labels))
        vals = [float(x) for x in labels]
        # round: each label has one or two significant digits
        check("%s log ticks round" % name, all(re.fullmatch(r"0\.0*[1-9]|[1-9]0*|[1-9]\.[0-9]|"
                                                            r"[1-9]e-?[0-9]+", x)
                                               for x in labels), str(labels))
        check("%s no 10^(k/5) ticks" % name, not any(x in ("0.398", "0.631", "1.58", "2.51")
                                                     for x in labels), str(labels))
        check("%s increasing" % name, vals == sorted(vals) and len(set(vals)) == len(vals))
    svg = os.path.join(TMP, "drug_log.svg")
    labels = svg_texts(svg, "yticks")
    check("drug: 1-2-5 ticks", labels[:4] == ["0.05", "0.1", "0.2", "0.5"], str(labels))


def test_date_ticks():
    rows = ["time,rain"]
    for h in range(0, 60, 3):
        d, hh = 5 + (h + 10) // 24, (h + 10) % 24
        rows.append("2023-12-%02dT%02d:00+01:00,%d" % (d, hh, (h * 7) % 5))
    t = write("hourly.csv", "\n".join(rows) + "\n")
    svg = os.path.join(TMP, "hourly.svg")
    r = run("fit", t, "--shape", "positive", "--svg", svg, "-o", os.devnull)
    labels = svg_texts(svg, "xticks")
    check("date ticks exist", r.returncode == 0 and len(labels) >= 3, str(labels))
    check("no U+2212 in dates", not any("&#8722;" in x or "\u2212" in x for x in labels),
          str(labels))
    check("first tick with the year", labels and labels[0].startswith("2023-12-"), str(labels))
    check("round clock times", all(re.search(r"(^| )([01][0-9]|2[0-3]):00$", x)
                                   for x in labels), str(labels))
    rows = ["date,v"] + ["2023-%02d-%02d,%d" % (10 + i // 4, 3 + 7 * (i % 4), i % 3)
                         for i in range(12)]
    svg = os.path.join(TMP, "weeks.svg")
    r = run("fit", write("weeks.csv", "\n".join(rows) + "\n"), "--svg", svg, "-o", os.devnull)
    labels = svg_texts(svg, "xticks")
    check("day ticks on calendar days", r.returncode == 0 and len(labels) >= 3 and
          labels[0].startswith("2023-") and all(re.fullmatch(
              r"(2023-)?(1[0-2])-(01|06|08|11|15|16|21|22|26)|2023-1[0-2]", x) for x in labels),
          str(labels))


def rect_fills(svg):
    s = open(svg).read()
    first = s.index("<g shape-rendering")
    body = s[first:s.index("</g>", first)]
    return re.findall(r'fill="(#[0-9a-f]{6})"', body)


def svg_size(svg):
    s = open(svg).read()
    m = re.search(r'<svg[^>]*width="([0-9.]+)"', s)
    return float(m.group(1)), s


def test_heatmap():
    svg = os.path.join(TMP, "rain.svg")
    data = os.path.join(REPO, "data", "surface", "spiky_rain_matrix.csv")
    r = run("surface", data, "--matrix", "--shape", "positive", "--svg", svg, "-o", os.devnull)
    check("heatmap written", r.returncode == 0, r.stderr)
    fills = rect_fills(svg)
    check("viridis on non-negative data", "#440154" in fills and all(
          f != "#ffffff" for f in fills), str(fills[:5]))
    width, s = svg_size(svg)
    # colour-bar labels: short, and they fit (7 px per character at 12 px) inside
    bar = re.findall(r'<path d="M([0-9.]+) [0-9.]+h4"[^>]*/>\n<text x="([0-9.]+)"[^>]*>([^<]*)<',
                     s)
    check("colour bar labelled", len(bar) >= 3, str(bar))
    check("colour bar labels short and inside", all(
        len(lab) <= 8 and float(x) + 7 * len(lab) <= width for _, x, lab in bar), str(bar))
    ticks = re.findall(r'text-anchor="middle">([0-9.]+)</text>', s)
    check("x axis ticks", len(ticks) >= 4, str(ticks))
    hatched = s.count("the shape scheme acts here")
    check("hatching not on every patch", 0 < hatched < 88 * 2 // 3, str(hatched))
    # nodes touching 0 but nothing for the scheme to do: nothing hatched
    rows = ["x,y,z"] + ["%d,%d,%d" % (i, j, i * j) for i in range(5) for j in range(5)]
    svg2 = os.path.join(TMP, "xy.svg")
    r = run("surface", write("xy.csv", "\n".join(rows) + "\n"), "--shape", "positive", "--svg",
            svg2, "-o", os.devnull)
    check("z = xy: no hatching", r.returncode == 0 and
          open(svg2).read().count("the shape scheme acts here") == 0, r.stderr)
    # data of both signs: diverging, white at 0
    rows = ["x,y,z"] + ["%d,%d,%d" % (i, j, (i - 2) * (j + 1)) for i in range(5) for j in range(4)]
    svg3 = os.path.join(TMP, "div.svg")
    r = run("surface", write("div.csv", "\n".join(rows) + "\n"), "--svg", svg3, "-o",
            os.devnull)
    fills = rect_fills(svg3)
    check("diverging on both signs", r.returncode == 0 and "#440154" not in fills and any(
        all(int(f[k:k + 2], 16) >= 0xf0 for k in (1, 3, 5)) for f in fills), str(fills[:3]))
    check("minus signs on the colour bar", "&#8722;" in open(svg3).read())


def test_warning_digits():
    data = os.path.join(REPO, "data", "paper", "table2_above_line.csv")
    r = run("fit", data, "--alpha", "0.1", "--form", "paper", "--json")
    warn = [x for x in r.stderr.splitlines() if "warning: the curve" in x]
    check("warning printed", len(warn) == 1, r.stderr)
    if warn:
        m = re.search(r"(rises|dips) (\S+) (above|below).*\(to (\S+) at x = (\S+);.*range (\S+)\)",
                      warn[0])
        check("warning parsed", m is not None, warn[0])
        if m:
            for g in (m.group(2), m.group(4), m.group(6)):
                digits = re.sub(r"[^0-9]", "", g.split("e")[0]).lstrip("0")
                check("3 significant digits: %s" % g, len(digits) <= 3, warn[0])
            check("x to a few digits", len(re.sub(r"[^0-9]", "", m.group(5))) <= 5, warn[0])


def main():
    if not os.access(CLI, os.X_OK):
        print("test_cli_first_hour: %s not built" % CLI)
        print("test_cli_first_hour: 0 passed, 1 failed")
        return 1
    try:
        for t in (test_compressed, test_date_format, test_units_row, test_step,
                  test_matrix_corner, test_log_ticks, test_date_ticks, test_heatmap,
                  test_warning_digits):
            try:
                t()
            except Exception as e:
                check("%s raised" % t.__name__, False, repr(e))
    finally:
        shutil.rmtree(TMP, ignore_errors=True)
    print("test_cli_first_hour: %d passed, %d failed" % (passed, failed))
    return 0 if failed == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
