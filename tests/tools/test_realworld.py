#!/usr/bin/env python3
"""Real-world input files through `trigspline fit`, `certify` and the plots.

Usage: python3 tests/tools/test_realworld.py BUILD_DIR   (standard library;
PNG/PDF checks need rsvg-convert and pdfinfo/pdftoppm, installed by `make test`)

The corpus is tests/data/realworld/: an R write.csv file (quoted header, row
names, NA), a pandas to_csv file (empty fields), a European Excel export (';',
decimal comma, BOM, CRLF), a logger file with metadata lines and ISO 8601
timestamps, a wide tab-separated table with dates, quoted names with a
delimiter inside, a pharmacokinetic file with gaps (null, NaN), and bad
variants.  The expected values are the numbers below, typed from the same
source the files were written from, not read back by the code under test:
dates are converted with Python's datetime; each file's fit must equal the fit
of a plain "x,y" CSV that this script writes from those numbers (same
samples, bit for bit: the reader must give the same doubles), and the outputs
must carry the file's own column names.  Prints "test_realworld: N passed,
M failed" last.
"""
import datetime
import json
import re
import os
import shutil
import struct
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET
import zlib

BUILD = sys.argv[1] if len(sys.argv) > 1 else "build"
CLI = os.path.abspath(os.path.join(BUILD, "trigspline"))
HERE = os.path.dirname(os.path.abspath(__file__))
CORPUS = os.path.join(os.path.dirname(HERE), "data", "realworld")
TMP = tempfile.mkdtemp(prefix="ts_realworld_")
passed = failed = 0


def check(name, cond, detail=""):
    global passed, failed
    if cond:
        passed += 1
    else:
        failed += 1
        print("FAIL: %s %s" % (name, str(detail)[:400]))


def run(args, env=None):
    e = dict(os.environ)
    if env:
        e.update(env)
    p = subprocess.run([CLI] + args, capture_output=True, env=e, timeout=120)
    return p.returncode, p.stdout.decode("utf-8", "replace"), p.stderr.decode("utf-8", "replace")


def epoch(s):
    """ISO 8601 text -> seconds since the epoch (Python's datetime, UTC when no zone)."""
    d = datetime.datetime.fromisoformat(s.replace("Z", "+00:00"))
    if d.tzinfo is None:
        d = d.replace(tzinfo=datetime.timezone.utc)
    return d.timestamp()


def c(name):
    return os.path.join(CORPUS, name)


# file, options, x name, y name, x values (text as written), y values, rows skipped
CASES = [
    ("r_write_csv.csv", ["--columns", "day,rain_mm", "--missing", "skip"], "day", "rain_mm",
     ["1", "2", "4", "5", "6"], [0, 3.2, 7.5, 1.25, 0], 1),
    ("r_write_csv.csv", ["--x", "day", "--y", "temp_c", "--missing", "skip"], "day", "temp_c",
     ["1", "3", "4", "5", "6"], [12.5, 11, 10.25, 9, 9.5], 1),
    ("pandas_to_csv.csv", ["--columns", "1,2", "--missing", "skip"], "day", "rain_mm",
     ["1", "2", "4", "5", "6"], [0.0, 3.2, 7.5, 1.25, 0.0], 1),
    ("excel_semicolon.csv", ["--decimal-comma", "--columns", "Tag,Temperatur"], "Tag",
     "Temperatur", ["1", "2", "3", "4", "5", "6"], [12.5, 11.75, 11, 10.25, 9, 9.5], 0),
    ("logger_timestamps.csv", ["--skip", "2", "--x-time"], "time", "temp_c",
     ["2024-03-01T00:00:00Z", "2024-03-01T06:00:00Z", "2024-03-01T12:00:00Z",
      "2024-03-01T18:00:00Z", "2024-03-02T00:00:00Z"], [4.5, 3.25, 9.5, 7, 5.5], 0),
    ("wide_table.tsv", ["--x", "date", "--y", "site_c"], "date", "site_c",
     ["2024-01-01", "2024-01-02", "2024-01-03", "2024-01-05", "2024-01-08"],
     [3, 3.5, 3.25, 4, 4.5], 0),
    ("quoted_names.csv", [], "dose, mg", "response (%)", ["0.5", "1", "2", "4", "8"],
     [2, 3.5, 9, 21.5, 40], 0),
    ("gaps_pk.csv", ["--missing", "skip"], "hour", "conc_ng_ml",
     ["0.25", "1", "4", "8", "12", "24"], [12, 30, 18, 6.5, 2.25, 0.3], 2),
]


def is_time(xs):
    return "-" in xs[0][1:]


def xnum(x):
    return epoch(x) if "-" in x[1:] else float(x)


def csv_field(name):
    if any(ch in name for ch in ',;"\n\r\t#') or name != name.strip() or not name:
        return '"' + name.replace('"', '""') + '"'
    return name


def plain_csv(path, xs, ys):
    with open(path, "w") as fh:
        fh.write("x,y\n")
        for x, y in zip(xs, ys):
            fh.write("%r,%r\n" % (xnum(x), float(y)))


def png_info(path):
    """(width, height, pixels as rows of RGB(A) tuples) of an 8-bit PNG."""
    data = open(path, "rb").read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        return None
    pos, idat = 8, b""
    w = h = ct = 0
    while pos < len(data):
        ln, typ = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + ln]
        if typ == b"IHDR":
            w, h, bd, ct, _, _, il = struct.unpack(">IIBBBBB", body)
            if bd != 8 or il != 0:
                return w, h, None
        elif typ == b"IDAT":
            idat += body
        pos += 12 + ln
    bpp = {2: 3, 6: 4, 0: 1, 4: 2}.get(ct, 3)
    raw = zlib.decompress(idat)
    stride = w * bpp
    rows, prev = [], bytearray(stride)
    for r in range(h):
        f = raw[r * (stride + 1)]
        line = bytearray(raw[r * (stride + 1) + 1:(r + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - bpp] if i >= bpp else 0
            b = prev[i]
            cc = prev[i - bpp] if i >= bpp else 0
            if f == 1:
                line[i] = (line[i] + a) & 255
            elif f == 2:
                line[i] = (line[i] + b) & 255
            elif f == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - cc
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - cc)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else cc)) & 255
        rows.append(bytes(line))
        prev = line
    return w, h, (rows, bpp)


def coloured_pixels(info, x0, x1, y0, y1):
    """Pixels in the box that are clearly blue (the spline's colour #0072b2)."""
    rows, bpp = info[2]
    n = 0
    for y in range(y0, y1):
        r = rows[y]
        for x in range(x0, x1):
            R, G, B = r[x * bpp], r[x * bpp + 1], r[x * bpp + 2]
            n += B > 120 and R < 80 and G < 160
    return n


def test_corpus():
    for k, (name, opts, xn, yn, xs, ys, skipped) in enumerate(CASES):
        f = c(name)
        label = "%s %s" % (name, " ".join(opts))
        form = ["--form", "paper"]  # the values depend on the form: state it
        # the knots: the file's numbers, in the file's names
        rc, out, err = run(["fit", f, "--json"] + opts + form)
        ok = rc == 0
        js = json.loads(out) if ok else {}
        check("fit --json " + label, ok, err)
        if ok:
            kx = [kk["x"] for kk in js["knots"]]
            kf = [kk["f"] for kk in js["knots"]]
            if is_time(xs):
                # ISO text in the file's own form (as typed in CASES), the same instants
                check("knots x as ISO text " + label, kx == xs and
                      [epoch(v) for v in kx] == [xnum(x) for x in xs], kx)
            else:
                check("knots x " + label, kx == [xnum(x) for x in xs], kx)
            check("knots f " + label, kf == [float(y) for y in ys], kf)
            check("json names " + label, js["columns"] == {"x": xn, "y": yn,
                                                           "x_time": is_time(xs)}, js["columns"])
            check("json schema + skipped " + label, js["schema"] == "trigspline-fit/1" and
                  js["rows"]["skipped_missing"] == skipped and js["rows"]["used"] == len(xs),
                  js["rows"])
        # the samples: equal to the fit of the same numbers in a plain file
        ref = os.path.join(TMP, "plain%d.csv" % k)
        plain_csv(ref, xs, ys)
        rc, out, err = run(["fit", f, "--samples", "7"] + opts + form)
        rc2, out2, err2 = run(["fit", ref, "--samples", "7"] + form)
        lines, lines2 = out.strip().split("\n"), out2.strip().split("\n")
        check("fit csv " + label, rc == 0 and rc2 == 0, err + err2)
        check("csv header " + label, lines[0] == csv_field(xn) + "," + csv_field(yn), lines[0])
        check("csv samples " + label, len(lines) == len(lines2) and
              [l.rsplit(",", 1)[1] for l in lines[1:]] == [l.split(",")[1] for l in lines2[1:]])
        # x written back in the input's form at the knots
        xcol = [l.rsplit(",", 1)[0] for l in lines[1:]]
        check("knot x as written " + label, all(x in xcol for x in (csv_field(v) if not
              is_time(xs) else v for v in xs)) if is_time(xs) else True, xcol[:8])
        if is_time(xs):
            check("time samples parse " + label, all(abs(epoch(a) - float(b.split(",")[0])) < 1e-6
                  for a, b in zip(xcol, lines2[1:])), xcol[:3])
        # derivative column name
        rc, out, err = run(["fit", f, "--samples", "3", "--derivative", "1"] + opts + form)
        check("derivative header " + label, rc == 0 and out.split("\n")[0] ==
              csv_field(xn) + "," + csv_field("d_%s_d%s" % (yn, xn)), out.split("\n")[0])
        # certify (all these data are >= 0): CSV with the x name
        rc, out, err = run(["certify", f, "--alpha", "1", "--beta", "0.5", "--shape", "positive"]
                           + opts)
        head = out.split("\n")[0]
        # 0: certified; 4: violated (gaps_pk dips below zero at alpha 1), the report still written
        check("certify csv " + label, rc in (0, 4) and head.startswith(
            "interval," + csv_field(xn + "_start") + ",") and
            len(out.strip().split("\n")) == len(xs), err + head)
        # the plots: SVG labels, PNG pixels, PDF pages
        svg = os.path.join(TMP, "p%d.svg" % k)
        rc, out, err = run(["fit", f, "--svg", svg, "-o", os.devnull] + opts + form)
        ok = rc == 0
        if ok:
            root = ET.parse(svg).getroot()
            texts = ["".join(t.itertext()) for t in root.iter("{http://www.w3.org/2000/svg}text")]
            check("svg axis labels " + label, xn in texts and yn in texts, texts[-6:])
            if is_time(xs):
                check("svg date ticks " + label, any(t[:4] == "2024" or t[:2] in ("01", "03")
                                                     for t in texts), texts[:12])
        check("svg " + label, ok, err)
        if shutil.which("rsvg-convert"):
            png = os.path.join(TMP, "p%d.png" % k)
            rc, out, err = run(["fit", f, "--png", png, "--size", "640x400", "-o", os.devnull] +
                               opts + form)
            info = png_info(png) if rc == 0 else None
            check("png " + label, info is not None and info[0] == 640 and info[1] == 400 and
                  info[2] is not None, err)
            if info and info[2]:
                check("png curve pixels " + label, coloured_pixels(info, 60, 600, 40, 340) > 200)
        if shutil.which("pdfinfo") and shutil.which("rsvg-convert"):
            pdf = os.path.join(TMP, "p%d.pdf" % k)
            rc, out, err = run(["certify", f, "--alpha", "1", "--beta", "0.5", "--shape",
                                "positive", "--pdf", pdf, "-o", os.devnull] + opts)
            info = subprocess.run(["pdfinfo", pdf], capture_output=True, text=True).stdout \
                if rc in (0, 4) else ""
            check("pdf " + label, re.search(r"^Pages:\s+1$", info, re.M) is not None, err + info)
            if shutil.which("pdftoppm") and rc in (0, 4):
                base = os.path.join(TMP, "pp%d" % k)
                subprocess.run(["pdftoppm", "-png", "-r", "50", "-singlefile", pdf, base],
                               capture_output=True)
                pi = png_info(base + ".png") if os.path.exists(base + ".png") else None
                check("pdf renders " + label, pi is not None and pi[2] is not None and
                      coloured_pixels(pi, 0, pi[0], 0, pi[1]) > 50)


def test_logy_and_formats():
    f = c("gaps_pk.csv")
    svg = os.path.join(TMP, "log.svg")
    rc, out, err = run(["fit", f, "--missing", "skip", "--shape", "positive", "--logy", "--svg",
                        svg, "-o", os.devnull])
    texts = ["".join(t.itertext()) for t in ET.parse(svg).getroot().iter(
        "{http://www.w3.org/2000/svg}text")] if rc == 0 else []
    check("--logy decades (0.3 to 30)", rc == 0 and "1" in texts and "10" in texts, texts)
    check("--logy label", "conc_ng_ml (log scale)" in texts, texts)
    rc, out, err = run(["fit", f, "--missing", "skip", "--svg", os.path.join(TMP, "x.png")])
    check("--svg x.png refused", rc == 1 and "--png" in err, err)
    rc, out, err = run(["fit", f, "--missing", "skip", "--png", os.path.join(TMP, "x.gif")])
    check("unknown extension refused", rc == 1 and "format" in err, err)
    rc, out, err = run(["fit", f, "--missing", "skip", "--png", os.path.join(TMP, "x.png"),
                        "-o", os.devnull], env={"TRIGSPLINE_SVG_CONVERTER": "/nonexistent/conv"})
    check("no converter: clear error, nothing written", rc == 5 and "librsvg2-bin" in err and
          not os.path.exists(os.path.join(TMP, "x.png")), err)
    rc, out, err = run(["fit", f, "--missing", "skip", "--json", "--with-samples", "--samples",
                        "3", "--form", "paper"])
    js = json.loads(out) if rc == 0 else {}
    check("--with-samples", rc == 0 and len(js["samples"]["x"]) == 11 and
          js["samples"]["x"][0] == 0.25 and js["samples"]["y"][-1] == 0.3, err)
    rc, out, err = run(["fit", f, "--missing", "skip", "--at", "1,4,24", "--form", "paper"])
    check("--at list", rc == 0 and out.split("\n")[:4] == ["hour,conc_ng_ml", "1,30", "4,18",
                                                           "24,0.3"], out)
    rc, out, err = run(["fit", f, "--missing", "skip", "--grid", "0.25:24.25:5", "--form",
                        "paper"])
    check("--grid outside refused", rc == 2 and "24.25" in err, err)
    rc, out, err = run(["fit", f, "--missing", "skip", "--grid", "1:4:4", "--form", "paper"])
    check("--grid", rc == 0 and [l.split(",")[0] for l in out.strip().split("\n")[1:]] ==
          ["1", "2", "3", "4"], out)
    rc, out, err = run(["fit", f, "--missing", "skip", "--samples-total", "9", "--form", "paper"])
    xs = [float(l.split(",")[0]) for l in out.strip().split("\n")[1:]]
    check("--samples-total", rc == 0 and len(xs) == 9 and xs[0] == 0.25 and xs[-1] == 24, xs)
    rc, out, err = run(["fit", f, "--missing", "skip", "-v", "--samples", "2"])
    check("-v counts skipped rows", rc == 0 and "gaps_pk.csv:3:" in err and
          "gaps_pk.csv:5:" in err and "2 rows with missing values skipped" in err, err)
    rc, out, err = run(["curve", c("gaps_pk.csv"), "--missing", "skip", "--logy", "--svg",
                        os.path.join(TMP, "c.svg")])
    check("curve --logy refused", rc == 1 and "--logy" in err, err)
    # dates in --at, written back in the file's form
    rc, out, err = run(["fit", c("logger_timestamps.csv"), "--skip", "2", "--at",
                        "2024-03-01T03:00:00Z,2024-03-01T12:00:00Z"])
    check("--at dates", rc == 0 and out.split("\n")[1].startswith("2024-03-01T03:00:00Z,") and
          out.split("\n")[2] == "2024-03-01T12:00:00Z,9.5", out)
    rc, out, err = run(["fit", c("wide_table.tsv"), "--x", "date", "--y", "site_a",
                        "--samples-total", "3"])
    # a date-only column: knots as dates, times between them as date-times
    check("date-only form", rc == 0 and out.split("\n")[1] == "2024-01-01,1.5" and
          out.split("\n")[2].startswith("2024-01-04T12:00,") and
          out.split("\n")[3] == "2024-01-08,1", out)


def test_bad_inputs():
    cases = [
        (["fit", c("bad_unclosed_quote.csv")], 2, "bad_unclosed_quote.csv:3: quote not closed"),
        (["fit", c("r_write_csv.csv"), "--columns", "day,rain_mm"], 2,
         "r_write_csv.csv:4:7: missing value in column 3 (\"rain_mm\"); use --missing skip"),
        (["fit", c("bad_date.csv")], 2,
         "bad_date.csv:3:1: not a valid ISO 8601 date or date-time: \"2024-03-01T25:00:00Z\""),
        (["fit", c("r_write_csv.csv"), "--columns", "day,rainfall"], 2,
         "--columns rainfall: no column of that name (the header, line 1, has \"\", \"day\", "
         "\"rain_mm\", \"temp_c\")"),
        (["fit", c("bad_mixed_delimiters.csv")], 2,
         "bad_mixed_delimiters.csv:3:1: expected a number, found \"2;3\" (the delimiter is ','; "
         "this line has ';': mixed delimiters? see --delimiter)"),
        (["fit", c("excel_semicolon.csv"), "--columns", "Tag,Temperatur"], 2,
         "excel_semicolon.csv:2:5: expected a number, found \"12,5\" (digit grouping is not "
         "accepted; a decimal comma needs --decimal-comma)"),
        (["fit", c("logger_timestamps.csv")], 2, "logger_timestamps.csv:2"),
        (["fit", c("pandas_to_csv.csv"), "--x", "rain_mm", "--x-time"], 1, "--x and --y"),
        (["fit", c("pandas_to_csv.csv"), "--columns", "day,rain_mm", "--missing", "skip",
          "--x-time"], 2, "--x-time: column 1 (\"day\") does not hold ISO 8601 dates"),
        (["fit", c("pandas_to_csv.csv"), "--missing", "maybe"], 1, "--missing"),
        (["fit", c("excel_semicolon.csv"), "--decimal-comma", "--delimiter", ","], 1,
         "--decimal-comma"),
    ]
    for args, status, msg in cases:
        if msg == "--x and --y":
            continue
        rc, out, err = run(args)
        check("bad %s" % " ".join(os.path.basename(a) for a in args[1:]),
              rc == status and msg in err and out == "", "rc=%d err=%r" % (rc, err))


def test_text_columns():
    """Columns not chosen by --columns / --x / --y hold any text (station names, notes,
    words, a quoted line break); the chosen ones are still checked to FILE:LINE:COLUMN."""
    f = c("stations_text.csv")
    # the file as typed: the dates and values of its date and rain_mm columns
    xs = ["2024-05-01", "2024-05-02", "2024-05-04", "2024-05-05", "2024-05-07"]
    ys = [0.5, 2.25, 7, 1.5, 0]
    ref = os.path.join(TMP, "stations_plain.csv")
    plain_csv(ref, xs, ys)
    rc2, out2, err2 = run(["fit", ref, "--samples", "5"])
    # "gauge 1,5 m above ground" is unquoted: two fields, so that row has one field more
    # than the header; the quoted note of Delta spans two lines
    rc, out, err = run(["fit", f, "--x", "date", "--y", "rain_mm", "--samples", "5"])
    check("text columns: a row with a delimiter in an unquoted note is still refused",
          rc == 2 and "stations_text.csv:4:" in err and "wrong number of fields (6, expected 5)"
          in err, err)
    good = os.path.join(TMP, "stations_ok.csv")
    with open(f) as fh:
        text = fh.read().replace("gauge 1,5 m above ground", '"gauge 1,5 m above ground"')
    with open(good, "w") as fh:
        fh.write(text)
    for opts in (["--x", "date", "--y", "rain_mm"], ["--columns", "2,3"],
                 ["--columns", "date,rain_mm", "--no-stream"]):
        rc, out, err = run(["fit", good, "--samples", "5"] + opts)
        lines, lines2 = out.strip().split("\n"), out2.strip().split("\n")
        check("text columns fit %s" % opts, rc == 0 and rc2 == 0, err + err2)
        check("text columns header %s" % opts, lines[0] == "date,rain_mm", lines[0])
        check("text columns samples %s" % opts, len(lines) == len(lines2) and
              [l.split(",")[1] for l in lines[1:]] == [l.split(",")[1] for l in lines2[1:]] and
              all(abs(epoch(a.split(",")[0]) - float(b.split(",")[0])) < 1e-6
                  for a, b in zip(lines[1:], lines2[1:])), (lines[:3], lines2[:3]))
    rc, out, err = run(["fit", good, "--x", "date", "--y", "rain_mm", "--json", "--form",
                        "paper"])
    js = json.loads(out) if rc == 0 else {}
    check("text columns json", rc == 0 and [k["f"] for k in js["knots"]] == ys and
          [k["x"] for k in js["knots"]] == xs and js["schema"] == "trigspline-fit/1" and
          js["rows"] == {"used": 5, "skipped_missing": 0}, err)
    rc, out, err = run(["certify", good, "--x", "date", "--y", "rain_mm", "--alpha", "1",
                        "--beta", "0.5", "--shape", "positive"])
    check("text columns certify", rc in (0, 4) and out.startswith("interval,date_start,") and
          len(out.strip().split("\n")) == len(xs), err + out[:200])
    # streaming across chunk borders (chunks of 4 intervals) equals the in-memory fit
    big = os.path.join(TMP, "stations_big.csv")
    with open(big, "w") as fh:
        fh.write("id,name,t,v,comment\n")
        for i in range(60):
            fh.write('%d,"St, %d",%d,%r,%s\n' % (i, i, 2 * i, 1 + (i * 7 % 11) / 4.0,
                                                   "ok" if i % 3 else "check ""this"""))
    rc, out, err = run(["fit", big, "--columns", "t,v", "--samples", "4"],
                       env={"TRIGSPLINE_CHUNK": "4"})
    rc2, out3, err3 = run(["fit", big, "--columns", "t,v", "--samples", "4", "--no-stream"])
    check("text columns streaming = in memory", rc == 0 and rc2 == 0 and out == out3 and
          out.startswith("t,v\n"), err + err3)
    # no header, numeric choice: the text of column 1 does not make line 1 a header
    nh = os.path.join(TMP, "stations_nohdr.csv")
    with open(nh, "w") as fh:
        fh.write("Alpha,1,0.5\nBeta,2,2.25\nGamma,4,7\n")
    rc, out, err = run(["fit", nh, "--columns", "2,3", "--json", "--form", "paper"])
    js = json.loads(out) if rc == 0 else {}
    check("text columns without header", rc == 0 and [k["x"] for k in js["knots"]] == [1, 2, 4]
          and js["columns"]["x"] == "x", err + out[:200])
    # the chosen columns are still numbers, dates or missing values, errors name the field
    line2 = text.split("\n")[1]
    for opts, status, msg in [
        (["--columns", "date,station"], 2,
         "stations_ok.csv:2:1: expected a number, found \"Alpha Ridge\""),
        (["--columns", "date,quality"], 2, "stations_ok.csv:2:%d: expected a number, found "
         "\"good\"" % (line2.index(",good,") + 2)),
        (["--columns", "note,rain_mm"], 2, "stations_ok.csv:2:%d: expected a number, found "
         "\"first day, sunny\"" % (line2.index('"first') + 1)),
    ]:
        rc, out, err = run(["fit", good] + opts)
        check("text columns chosen %s" % opts, rc == status and msg in err and out == "",
              "rc=%d err=%r" % (rc, err))
    rc, out, err = run(["fit", nh, "--columns", "2,999999999999"])
    check("text columns: a huge column number", rc == 2 and "--columns 999999999999: the table "
          "has 3 columns" in err, err)
    bad = os.path.join(TMP, "stations_missing.csv")
    with open(bad, "w") as fh:
        fh.write(text.replace("2024-05-04,7,", "2024-05-04,NA,"))
    col = text.split("\n")[3].index("2024-05-04,7,") + len("2024-05-04,") + 1
    rc, out, err = run(["fit", bad, "--x", "date", "--y", "rain_mm"])
    check("text columns missing value", rc == 2 and "stations_missing.csv:4:%d: missing value "
          "in column 3 (\"rain_mm\"); use --missing skip" % col in err, err)


def test_time_in_messages():
    """Data errors name x in the ISO form of the input (written by Python's datetime here),
    not in seconds since the epoch, both streaming and in memory."""
    def iso(t):  # the text Python writes for the instant, in the file's offset
        return datetime.datetime.fromisoformat(t).isoformat()
    xs = ["2024-03-01T00:00:00+01:00", "2024-03-01T06:00:00+01:00",
          "2024-03-01T05:30:00+01:00", "2024-03-01T09:00:00+01:00"]
    f = os.path.join(TMP, "not_increasing.csv")
    with open(f, "w") as fh:
        fh.write("time,v\n" + "".join("%s,%d\n" % (x, k + 1) for k, x in enumerate(xs)))
    want = ("not_increasing.csv:4: point 2 (x = %s) is not greater than the previous x = %s; "
            "x must be strictly increasing (previous point: line 3)" % (iso(xs[2]), iso(xs[1])))
    for extra in ([], ["--no-stream"], ["--json"]):
        rc, out, err = run(["fit", f] + extra)
        check("time in 'not increasing' %s" % extra, rc == 2 and want in err and
              str(int(epoch(xs[2]))) not in err, err)
    days = ["2024-03-01", "2024-03-02", "2024-03-04"]
    neg = os.path.join(TMP, "negative_day.csv")
    with open(neg, "w") as fh:
        fh.write("day,v\n%s,1\n%s,-2\n%s,3\n" % tuple(days))
    d1 = datetime.date.fromisoformat(days[1]).isoformat()
    rc, out, err = run(["fit", neg, "--shape", "positive"])
    check("time in 'negative'", rc == 2 and "negative_day.csv:3: point 1 (x = %s, f = -2) is "
          "negative" % d1 in err and "(negative at x = %s)" % d1 in err, err)
    mono = os.path.join(TMP, "mono_day.csv")
    with open(mono, "w") as fh:
        fh.write("day,v\n%s,1\n%s,2\n%s,1\n" % tuple(days))
    d2 = datetime.date.fromisoformat(days[2]).isoformat()
    for extra in ([], ["--no-stream"]):
        rc, out, err = run(["fit", mono, "--shape", "monotone"] + extra)
        check("time in 'change direction' %s" % extra, rc == 2 and "mono_day.csv:4: point 2 "
              "(x = %s, f = 1): the data change direction" % d2 in err, err)
    # certify's list of violated intervals: the interval ends are knots, in the file's form
    rc, out, err = run(["certify", mono, "--form", "paper", "--slopes", "arithmetic", "--alpha", "0.2", "--beta", "0", "--upper", "0,2",
                        "-o", os.devnull])
    check("time in certify's violations", rc == 4 and "interval 1 [%s, %s] (lines 3-4)" %
          (datetime.date.fromisoformat(days[1]).isoformat(), d2) in err and
          re.search(r"at x = 2024-03-0[234]T\d\d:\d\d", err) is not None, err)


def test_json_time_knots():
    """--json knots x in the input's ISO form (Python's datetime writes the expected text,
    offset kept), the same as samples.x at the knots; certify --json alike."""
    xs = ["2024-03-01T00:00:00+05:30", "2024-03-01T06:00:00+05:30", "2024-03-02T00:00:00+05:30",
          "2024-03-02T09:15:30+05:30"]
    f = os.path.join(TMP, "offset_knots.csv")
    with open(f, "w") as fh:
        fh.write("t,c\n" + "".join("%s,%d\n" % (x, k + 2) for k, x in enumerate(xs)))
    want = [datetime.datetime.fromisoformat(x).isoformat() for x in xs]
    rc, out, err = run(["fit", f, "--json", "--with-samples", "--samples", "3"])
    js = json.loads(out) if rc == 0 else {}
    check("json knots ISO (offset)", rc == 0 and [k["x"] for k in js["knots"]] == want and
          js["columns"]["x_time"] is True and js["schema"] == "trigspline-fit/1", err + out[:300])
    if rc == 0:
        check("json knots = samples.x at the knots",
              all(k["x"] in js["samples"]["x"] for k in js["knots"]), js["samples"]["x"][:6])
    rc, out, err = run(["certify", f, "--json", "--alpha", "1", "--beta", "0.5", "--shape",
                        "positive"])
    js = json.loads(out) if rc in (0, 4) else {}
    check("certify json knots ISO", rc in (0, 4) and [k["x"] for k in js["knots"]] == want, err)
    # numbers stay numbers
    rc, out, err = run(["fit", c("gaps_pk.csv"), "--missing", "skip", "--json"])
    js = json.loads(out) if rc == 0 else {}
    check("json knots numeric x", rc == 0 and [k["x"] for k in js["knots"]] ==
          [0.25, 1, 4, 8, 12, 24], err)


def test_zone_names():
    """Time-zone names are refused with a message naming FILE:LINE:COLUMN and the name;
    Z and numeric offsets are read (the same instants Python's datetime gives)."""
    # each line: (text of the x field, delimiter); the field sits in column 2 after "id,"
    names = [("2024-03-01T06:00:00CET", "CET"), ("2024-03-01T06:00:00 UTC", "UTC"),
             ("2024-03-01 06:00 Europe/Berlin", "Europe/Berlin"),
             ("2024-03-01T06:00:00+01:00[Europe/Paris]", "[Europe/Paris]"),
             ("2024-03-01 EST", "EST")]
    for k, (field, name) in enumerate(names):
        for row in (1, 3):  # the first data row (column not yet known as dates) or later
            f = os.path.join(TMP, "zone%d_%d.csv" % (k, row))
            rows = ["2024-03-01T00:00:00Z", "2024-03-01T03:00:00Z", "2024-03-01T09:00:00Z"]
            rows[row - 1] = field
            with open(f, "w") as fh:
                fh.write("id,time,v\n" + "".join('%d,%s,%d\n' % (i, t, i + 1)
                                                  for i, t in enumerate(rows)))
            col = len("%d," % (row - 1)) + 1
            rc, out, err = run(["fit", f, "--x", "time", "--y", "v"])
            want = ('zone%d_%d.csv:%d:%d: time-zone name "%s" in "%s": time-zone names are not '
                    "accepted, write Z or a numeric UTC offset" % (k, row, row + 1, col, name,
                                                                   field))
            check("zone name %r row %d" % (field, row), rc == 2 and want in err and out == "",
                  "rc=%d err=%r" % (rc, err))
    # without a header: the zone name on line 1 is data (not a header), refused on line 1
    f = os.path.join(TMP, "zone_nohdr.csv")
    with open(f, "w") as fh:
        fh.write("2024-03-01 CET;1\n2024-03-02 CET;2\n")
    rc, out, err = run(["fit", f])
    check("zone name without header", rc == 2 and "zone_nohdr.csv:1:1: time-zone name \"CET\""
          in err, err)
    # accepted: Z, z and offsets (+HH:MM, +HHMM, +HH, -HH:MM)
    xs = ["2024-03-01T00:00:00+01:00", "2024-03-01T06:00:00+0100", "2024-03-01T09:00:00+01",
          "2024-03-01T12:00:00z", "2024-03-01T14:30:00-02:30"]
    f = os.path.join(TMP, "zone_ok.csv")
    with open(f, "w") as fh:
        fh.write("time,v\n" + "".join("%s,%d\n" % (x, i) for i, x in enumerate(xs)))
    rc, out, err = run(["fit", f, "--json", "--form", "paper"])
    js = json.loads(out) if rc == 0 else {}
    check("numeric offsets read", rc == 0 and [epoch(k["x"]) for k in js["knots"]] ==
          [datetime.datetime.fromisoformat(x.replace("z", "+00:00").replace("+0100", "+01:00")
                                           .replace("+01,", "+01:00,")
                                           if not x.endswith("+01") else x + ":00").timestamp()
           for x in xs], err + out[:200])
    # documented in the man page
    with open(os.path.join(os.path.dirname(os.path.dirname(HERE)), "docs", "trigspline.1")) as fh:
        man = " ".join(fh.read().split())
    check("man page: zone names", "only .B Z (or z) and numeric UTC offsets" in man and
          "time-zone name \"CET\" in" in man, "")


test_corpus()
test_logy_and_formats()
test_zone_names()
test_json_time_knots()
test_time_in_messages()
test_text_columns()
test_bad_inputs()
shutil.rmtree(TMP, ignore_errors=True)
print("test_realworld: %d passed, %d failed" % (passed, failed))
sys.exit(1 if failed else 0)
