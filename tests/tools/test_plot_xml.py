#!/usr/bin/env python3
"""Checks the SVG output of the plot module (tools/support/tsu_plot.c) with the Python
standard library only.

    python3 tests/tools/test_plot_xml.py BUILD_DIR

1. Runs BUILD_DIR/tests/test_plot into a fresh temporary directory and checks
   each SVG it writes: well-formed XML, <svg> root in the SVG namespace, only
   finite numbers with at most two decimals, pure ASCII, the expected numbers
   of polylines / markers / shaded polygons, title text, tick labels in order
   and inside the frame, everything drawn inside the plot area, the legend
   not covering data, the pixel mapping (recovered from the tick marks and
   their labels) putting the known data where they belong, the polyline
   simplification error within 0.1 px, equal aspect, and inlining into HTML.
2. Parses every *.svg found under BUILD_DIR (the C test's own output and any
   other produced SVG) and applies the generic checks.

Last line: "test_plot_xml: N passed, M failed".
"""
import bisect
import math
import os
import re
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET
from html.parser import HTMLParser

NS = "{http://www.w3.org/2000/svg}"
NUMERIC = {"x", "y", "x1", "y1", "x2", "y2", "cx", "cy", "r", "width", "height",
           "stroke-width", "fill-opacity", "font-size", "dy", "rx"}
PIXEL = {"x", "y", "x1", "y1", "x2", "y2", "cx", "cy", "r", "width", "height", "dy"}
TWO_DEC = re.compile(r"^-?\d+(\.\d{1,2})?$")

passed = 0
failed = 0


def check(cond, msg):
    global passed, failed
    if cond:
        passed += 1
    else:
        failed += 1
        print("FAIL: " + msg, file=sys.stderr)
    return cond


def tag(el):
    return el.tag[len(NS):] if el.tag.startswith(NS) else el.tag


def points(s):
    out = []
    for pair in s.split():
        a, b = pair.split(",")
        out.append((float(a), float(b)))
    return out


def text_of(el):
    return "".join(el.itertext())


def label_value(s):
    return float(s.replace("\u2212", "-"))


# ---------------------------------------------------------------- generic

def generic(path, strict):
    """Checks for any SVG; strict adds those that hold for test_plot files."""
    name = os.path.basename(path)
    with open(path, "rb") as f:
        raw = f.read()
    try:
        root = ET.fromstring(raw)
    except ET.ParseError as e:
        check(False, "%s: not well-formed XML: %s" % (name, e))
        return None
    check(root.tag == NS + "svg", "%s: root is %s, not svg in the SVG namespace" % (name, root.tag))
    check(b'xmlns="http://www.w3.org/2000/svg"' in raw, "%s: no xmlns" % name)
    ok_num = True
    ok_dec = True
    for el in root.iter():
        for k, v in el.attrib.items():
            if "nan" in v.lower() or re.search(r"\binf", v.lower()):
                ok_num = False
            if k in NUMERIC:
                try:
                    ok_num &= math.isfinite(float(v))
                except ValueError:
                    ok_num = False
                if strict and k in PIXEL and not TWO_DEC.match(v):
                    ok_dec = False
            if k == "points":
                try:
                    pts = points(v)
                    ok_num &= all(math.isfinite(a) and math.isfinite(b) for a, b in pts)
                    if strict:
                        ok_dec &= all(TWO_DEC.match(t) for pair in v.split() for t in pair.split(","))
                except ValueError:
                    ok_num = False
    check(ok_num, "%s: a numeric attribute is not a finite number" % name)
    vb = root.get("viewBox", "").split()
    check(len(vb) == 4 and all(math.isfinite(float(t)) for t in vb), "%s: viewBox" % name)
    if strict:
        check(ok_dec, "%s: a pixel coordinate has more than 2 decimals" % name)
        check(all(b < 0x80 for b in raw), "%s: not pure ASCII" % name)
        check(b" id=" not in raw, "%s: ids would clash when inlined twice" % name)
    return root


# ------------------------------------------------------------- structure

class Plot:
    """The parts of a test_plot SVG the checks need."""

    def __init__(self, root):
        self.root = root
        g = {}
        for el in root.iter(NS + "g"):
            g.setdefault(el.get("class", ""), []).append(el)
        self.groups = g
        axes = g["axes"][0]
        fr = [e for e in axes if tag(e) == "rect"][0]
        self.fx, self.fy = float(fr.get("x")), float(fr.get("y"))
        self.fw, self.fh = float(fr.get("width")), float(fr.get("height"))
        marks = [e for e in axes if tag(e) == "line"]
        self.xmarks = [float(e.get("x1")) for e in marks if e.get("x1") == e.get("x2")]
        self.ymarks = [float(e.get("y1")) for e in marks if e.get("y1") == e.get("y2")]
        self.xtext = [e for e in g["xticks"][0] if tag(e) == "text"]
        self.ytext = [e for e in g["yticks"][0] if tag(e) == "text"]
        self.xexp = self._exp("xexp")
        self.yexp = self._exp("yexp")
        self.series = [e for k, v in g.items() if k.startswith("series") for e in v]
        self.legend = g.get("legend", [None])[0]

    def _exp(self, cls):
        for el in self.root.iter(NS + "text"):
            if el.get("class") == cls:
                return int(text_of(list(el)[0]).replace("\u2212", "-"))
        return 0

    def count(self, what, cls=None):
        n = 0
        for s in self.series:
            if cls and s.get("class") != cls:
                continue
            n += sum(1 for e in s.iter(NS + what))
        return n

    def all_in_series(self, what):
        return [e for s in self.series for e in s.iter(NS + what)]

    def mapping(self, axis):
        """(a, b) with pixel = a + b * value, from the tick marks and labels."""
        marks = self.xmarks if axis == 0 else self.ymarks
        texts = self.xtext if axis == 0 else self.ytext
        e = self.xexp if axis == 0 else self.yexp
        vals = [label_value(text_of(t)) * 10.0 ** e for t in texts]
        b = (marks[-1] - marks[0]) / (vals[-1] - vals[0])
        a = marks[0] - b * vals[0]
        return a, b, vals, marks

    def inside(self, x, y, tol):
        return (self.fx - tol <= x <= self.fx + self.fw + tol and
                self.fy - tol <= y <= self.fy + self.fh + tol)


def seg_hits_rect(p, q, r):
    """Does segment p-q meet the rectangle r = (x0, y0, x1, y1)? (Liang-Barsky)"""
    (x0, y0), (x1, y1) = p, q
    dx, dy = x1 - x0, y1 - y0
    t0, t1 = 0.0, 1.0
    for pp, qq in ((-dx, x0 - r[0]), (dx, r[2] - x0), (-dy, y0 - r[1]), (dy, r[3] - y0)):
        if pp == 0:
            if qq < 0:
                return False
        else:
            t = qq / pp
            if pp < 0:
                t0 = max(t0, t)
            else:
                t1 = min(t1, t)
            if t0 > t1:
                return False
    return True


def structural(name, root, legend_check=True):
    """Checks valid for every test_plot file (the legend check not for
    random plots, where the legend may have nowhere free to go)."""
    P = Plot(root)
    # ticks: ordered, inside the frame, labels and marks paired
    check(len(P.xmarks) == len(P.xtext) >= 3, "%s: x ticks" % name)
    check(len(P.ymarks) == len(P.ytext) >= 3, "%s: y ticks" % name)
    xs = [float(t.get("x")) for t in P.xtext]
    check(all(a < b for a, b in zip(xs, xs[1:])), "%s: x tick labels not increasing" % name)
    check(all(P.fx - 0.01 <= x <= P.fx + P.fw + 0.01 for x in xs), "%s: x tick outside" % name)
    check(all(a > b for a, b in zip(P.ymarks, P.ymarks[1:])), "%s: y ticks not decreasing" % name)
    check(all(P.fy - 0.01 <= y <= P.fy + P.fh + 0.01 for y in P.ymarks), "%s: y tick outside" % name)
    for axis in (0, 1):
        a, b, vals, marks = P.mapping(axis)
        check(all(abs(a + b * v - m) < 0.02 for v, m in zip(vals, marks)),
              "%s: axis %d ticks not equally spaced by value" % (name, axis))
        steps = [v2 - v1 for v1, v2 in zip(vals, vals[1:])]
        st = steps[0]
        mant = st / 10 ** math.floor(math.log10(st) + 1e-9)
        check(any(abs(mant - m) < 1e-6 for m in (1, 2, 5)), "%s: step %r not 1-2-5" % (name, st))
        texts = [text_of(t) for t in (P.xtext if axis == 0 else P.ytext)]
        check(len(set(texts)) == len(texts), "%s: duplicate tick labels" % name)
        check(all(len(t) <= 10 for t in texts), "%s: long tick label %r" % (name, texts))
    # everything drawn inside the plot area
    for pl in P.all_in_series("polyline"):
        pts = points(pl.get("points"))
        check(len(pts) >= 2, "%s: polyline with < 2 points" % name)
        check(all(P.inside(x, y, 0.011) for x, y in pts), "%s: polyline leaves the frame" % name)
    for ln in P.all_in_series("line"):
        ok = all(P.inside(float(ln.get(a)), float(ln.get(b)), 0.011)
                 for a, b in (("x1", "y1"), ("x2", "y2")))
        check(ok, "%s: line leaves the frame" % name)
    for pg in P.all_in_series("polygon"):
        pts = points(pg.get("points"))
        check(len(pts) >= 3 and all(P.inside(x, y, 0.011) for x, y in pts),
              "%s: shaded polygon leaves the frame" % name)
    for c in P.all_in_series("circle"):
        check(P.inside(float(c.get("cx")), float(c.get("cy")), 0.51), "%s: marker outside" % name)
    if P.legend is not None:
        r = [e for e in P.legend if tag(e) == "rect"][0]
        check(float(r.get("x")) >= 0 and float(r.get("y")) >= 0, "%s: legend off the canvas" % name)
    # the legend, when inside the frame, covers no data
    if P.legend is not None and legend_check:
        r = [e for e in P.legend if tag(e) == "rect"][0]
        lx, ly = float(r.get("x")), float(r.get("y"))
        lw, lh = float(r.get("width")), float(r.get("height"))
        if lx < P.fx + P.fw:
            box = (lx + 0.5, ly + 0.5, lx + lw - 0.5, ly + lh - 0.5)
            hit = False
            for s in P.series:
                if s.get("class") == "series region":
                    s = [e for e in s if tag(e) == "g"][0]  # its line; shading may pass under
                for pl in s.iter(NS + "polyline"):
                    pts = points(pl.get("points"))
                    hit |= any(seg_hits_rect(p, q, box) for p, q in zip(pts, pts[1:]))
                for ln in s.iter(NS + "line"):
                    hit |= seg_hits_rect((float(ln.get("x1")), float(ln.get("y1"))),
                                         (float(ln.get("x2")), float(ln.get("y2"))), box)
                for c in s.iter(NS + "circle"):
                    hit |= seg_hits_rect((float(c.get("cx")), float(c.get("cy"))),
                                         (float(c.get("cx")), float(c.get("cy"))), box)
            check(not hit, "%s: the legend covers data" % name)
        else:
            check(lx >= P.fx + P.fw + 1, "%s: outside legend overlaps the frame" % name)
        n_entries = sum(1 for e in P.legend if tag(e) == "text")
        check(n_entries >= 1, "%s: empty legend" % name)
    return P


# --------------------------------------------------- per-file expectations

TABLE1 = [(0, 2), (2, 1.58), (3, 1.55), (5, 1.54), (15, 1.8), (25, 1.54), (27, 1.55),
          (28, 1.58), (30, 2)]

# title, polylines, series circles, shaded polygons, series lines, legend entries
EXPECT = {
    "plot_full.svg": ("Table 1: positive data", 2, 18, 2, 3, 6),
    "plot_degenerate.svg": ("constant data", 1, 4, 0, 0, 2),
    "plot_single.svg": (None, 0, 1, 0, 0, 0),
    "plot_empty.svg": ("empty", 0, 0, 0, 0, 0),
    "plot_nan.svg": ("gaps in the data", 3, 8, 0, 0, 2),
    "plot_huge.svg": ("huge x, tiny y", 1, 0, 0, 0, 1),
    "plot_extreme.svg": (None, 1, 5, 1, 1, 0),
    "plot_special.svg": ("A & B <tag> \"q\" 'a' \u03b2 \u2014 \ufffd ", 1, 3, 0, 0, 2),
    "plot_bigcurve.svg": ("sin x, 20000 samples", 1, 0, 0, 0, 1),
    "plot_closed.svg": ("closed curve", 2, 9, 0, 0, 3),
    "plot_inline.svg": ("fixed ranges", 1, None, 1, 2, 3),
    "plot_legend_outside.svg": ("legend outside", 0, 10, 0, 0, 2),
    "plot_legend_ul.svg": ("legend upper left", 1, 50, 0, 0, 2),
}


def expectations(name, root, P):
    title, npl, ncirc, npoly, nlines, nleg = EXPECT[name]
    first = list(root)[0]
    if title is None:
        check(tag(first) != "title", "%s: unexpected <title>" % name)
    else:
        check(tag(first) == "title" and first.text == title,
              "%s: <title> is %r" % (name, first.text if tag(first) == "title" else tag(first)))
        tt = [t for t in root.iter(NS + "text") if t.get("class") == "title"]
        check(len(tt) == 1 and text_of(tt[0]) == title, "%s: title text" % name)
    check(P.count("polyline") == npl, "%s: %d polylines, expected %d" % (name, P.count("polyline"), npl))
    if ncirc is not None:
        check(P.count("circle") == ncirc, "%s: %d markers, expected %d" % (name, P.count("circle"), ncirc))
    check(P.count("polygon") == npoly, "%s: %d polygons, expected %d" % (name, P.count("polygon"), npoly))
    check(P.count("line") == nlines, "%s: %d lines, expected %d" % (name, P.count("line"), nlines))
    got = 0 if P.legend is None else sum(1 for e in P.legend if tag(e) == "text")
    check(got == nleg, "%s: %d legend entries, expected %d" % (name, got, nleg))


def check_full(P):
    """Data markers sit where the tick-derived mapping puts Table 1."""
    ax, bx, _, _ = P.mapping(0)
    ay, by, _, _ = P.mapping(1)
    pts = [g for g in P.series if g.get("class") == "series points"][0]
    circles = [(float(c.get("cx")), float(c.get("cy"))) for c in pts.iter(NS + "circle")]
    want = [(ax + bx * x, ay + by * y) for x, y in TABLE1]
    check(len(circles) == len(want) and
          all(abs(c[0] - w[0]) < 0.03 and abs(c[1] - w[1]) < 0.03 for c, w in zip(circles, want)),
          "plot_full: markers not at the data")
    # the floor y = 0 is drawn at the pixel of 0
    region = [g for g in P.series if g.get("class") == "series region"][0]
    ln = list(region.iter(NS + "line"))[0]
    check(abs(float(ln.get("y1")) - ay) < 0.03, "plot_full: floor not at y = 0")


def check_bigcurve(P):
    """Every one of the 20000 samples of sin lies within 0.1 px of the
    simplified polyline (plus rounding: vertices 0.005 px, mapping 0.02 px)."""
    ax, bx, _, _ = P.mapping(0)
    ay, by, _, _ = P.mapping(1)
    pl = points(P.all_in_series("polyline")[0].get("points"))
    check(len(pl) < 1000, "bigcurve: %d vertices" % len(pl))
    vx = [p[0] for p in pl]
    check(all(a < b for a, b in zip(vx, vx[1:])), "bigcurve: vertices not increasing in x")
    n = 20000
    worst = 0.0
    for i in range(n):
        x = 2 * math.pi * i / (n - 1)
        px, py = ax + bx * x, ay + by * math.sin(x)
        j = bisect.bisect_left(vx, px)
        best = math.inf
        for k in range(max(0, j - 2), min(len(pl) - 1, j + 2)):
            (x0, y0), (x1, y1) = pl[k], pl[k + 1]
            dx, dy = x1 - x0, y1 - y0
            t = max(0.0, min(1.0, ((px - x0) * dx + (py - y0) * dy) / (dx * dx + dy * dy)))
            best = min(best, math.hypot(px - x0 - t * dx, py - y0 - t * dy))
        worst = max(worst, best)
    check(worst <= 0.1 + 0.03, "bigcurve: sample %.4f px from the polyline" % worst)
    check(worst > 0.02, "bigcurve: no simplification happened (worst %.4f)" % worst)


def check_closed(P):
    """Equal aspect: as many pixels per unit on both axes (mapping from ticks)."""
    _, bx, _, _ = P.mapping(0)
    _, by, _, _ = P.mapping(1)
    check(abs(bx + by) <= 2e-3 * bx, "closed: %g px/unit in x, %g in y" % (bx, -by))


def check_huge(P):
    check(P.xexp == 12 and P.yexp == -9, "huge: exponents %d, %d" % (P.xexp, P.yexp))


def check_legend_positions(name, P):
    r = [e for e in P.legend if tag(e) == "rect"][0]
    lx, ly = float(r.get("x")), float(r.get("y"))
    if name == "plot_legend_outside.svg":
        check(lx > P.fx + P.fw, "legend_outside: legend at x %g inside the frame" % lx)
    else:
        check(abs(lx - P.fx - 8) < 0.01 and abs(ly - P.fy - 8) < 0.01,
              "legend_ul: legend at %g,%g" % (lx, ly))


class TagBalance(HTMLParser):
    def __init__(self):
        super().__init__()
        self.stack = []
        self.ok = True
        self.svg = 0

    def handle_starttag(self, t, attrs):
        if t == "svg":
            self.svg += 1
        if t != "meta":
            self.stack.append(t)

    def handle_endtag(self, t):
        if not self.stack or self.stack.pop() != t:
            self.ok = False


def check_inline(path):
    with open(path, encoding="ascii") as f:
        svg = f.read()
    check(svg.startswith("<svg "), "inline: does not start with <svg")
    check("<?xml" not in svg, "inline: has an XML declaration")
    page = ("<!DOCTYPE html><html><head><meta charset=\"utf-8\"><title>t</title></head>"
            "<body><p>one</p>" + svg + "<p>two</p>" + svg + "</body></html>")
    hp = TagBalance()
    hp.feed(page)
    hp.close()
    check(hp.ok and not hp.stack and hp.svg == 2, "inline: HTML tags do not balance")
    xhtml = "<html xmlns=\"http://www.w3.org/1999/xhtml\"><body>" + svg + svg + "</body></html>"
    try:
        doc = ET.fromstring(xhtml)
        check(len(list(doc.iter(NS + "svg"))) == 2, "inline: svg not found in XHTML")
    except ET.ParseError as e:
        check(False, "inline: XHTML page not well-formed: %s" % e)


def main():
    if len(sys.argv) < 2:
        print("usage: test_plot_xml.py BUILD_DIR", file=sys.stderr)
        check(False, "no build directory")
        print("test_plot_xml: %d passed, %d failed" % (passed, failed))
        return 1
    build = sys.argv[1]
    prog = os.path.join(build, "tests", "test_plot")
    if check(os.access(prog, os.X_OK), "%s not built" % prog):
        with tempfile.TemporaryDirectory() as d:
            r = subprocess.run([prog, d], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                               universal_newlines=True, timeout=300)
            check(r.returncode == 0, "test_plot failed: " + r.stdout[-300:] + r.stderr[-2000:])
            produced = sorted(f for f in os.listdir(d) if f.endswith(".svg"))
            fuzz = [f for f in produced if f.startswith("fuzz_")]
            check(sorted(EXPECT) == [f for f in produced if f not in fuzz],
                  "files: %s vs %s" % (produced, sorted(EXPECT)))
            check(len(fuzz) == 10, "%d random plots" % len(fuzz))
            for name in produced:
                path = os.path.join(d, name)
                root = generic(path, strict=True)
                if root is None:
                    continue
                P = structural(name, root, legend_check=name not in fuzz)
                if name in EXPECT:
                    expectations(name, root, P)
                if name == "plot_full.svg":
                    check_full(P)
                elif name == "plot_bigcurve.svg":
                    check_bigcurve(P)
                elif name == "plot_closed.svg":
                    check_closed(P)
                elif name == "plot_huge.svg":
                    check_huge(P)
                elif name.startswith("plot_legend_"):
                    check_legend_positions(name, P)
                elif name == "plot_inline.svg":
                    check_inline(path)
    # every other SVG produced in the build directory
    n = 0
    for dirpath, _, files in os.walk(build):
        for f in files:
            if f.endswith(".svg"):
                generic(os.path.join(dirpath, f), strict=False)
                n += 1
    print("test_plot_xml: parsed %d further SVG files under %s" % (n, build))
    print("test_plot_xml: %d passed, %d failed" % (passed, failed))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
