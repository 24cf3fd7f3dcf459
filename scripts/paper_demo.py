#!/usr/bin/env python3
"""Reproduce the paper's numerical section (Figures 2-7) as one HTML page.

Usage: paper_demo.py CLI DATA_DIR OUT_DIR

Every figure is produced by the `trigspline` command (CLI) exactly as a user
would run it; the page shows each command line, the plot (inline SVG), the
beta_i and the certificate of every interval, and a note wherever our result
differs from the paper's claim (docs/method.md §9).  Standard library only.
"""
import html
import json
import math
import os
import re
import shlex
import subprocess
import sys
import tempfile

CLI, DATA, OUT = sys.argv[1], sys.argv[2], sys.argv[3]
# the command's own version ("trigspline X.Y.Z"), which is the library's
VERSION = subprocess.run([CLI, "--version"], capture_output=True, text=True,
                         check=True).stdout.split()[1]
TMP = tempfile.mkdtemp(prefix="ts_demo_")


def data(name):
    return os.path.join(DATA, name)


# The paper's own spline (docs/method.md §3): the library's defaults are the
# geometric form with Steffen's slopes (docs/method.md §5.10), so every
# function fit states the paper's options; a panel's own --alpha follows and wins.
PAPER_OPTIONS = ["--form", "paper", "--slopes", "arithmetic", "--alpha", "1"]


def run(args, svg_title):
    """Run the CLI with --json and --svg; return (status, json or None, svg text, stderr)."""
    if args[0] in ("fit", "certify") and "--points-only" not in args:
        pin = PAPER_OPTIONS[:4] if "--alphas" in args else PAPER_OPTIONS
        args = args[:2] + pin + args[2:]
    svg = os.path.join(TMP, "p%d.svg" % run.counter)
    run.counter += 1
    cmd = [CLI] + args + ["--json", "--svg", svg, "--title", svg_title]
    p = subprocess.run(cmd, capture_output=True, text=True)
    js = None
    if p.stdout.strip():
        try:
            js = json.loads(p.stdout)
        except ValueError:
            js = None
    text = ""
    if os.path.exists(svg):
        with open(svg, encoding="utf-8") as fh:
            text = fh.read()
        text = re.sub(r"^<\?xml[^>]*\?>\s*", "", text)
    return p.returncode, js, text, p.stderr.strip(), cmd


run.counter = 0


def g(v, digits=4):
    if v is None:
        return "–"
    if isinstance(v, bool):
        return "yes" if v else "NO"
    if isinstance(v, (int, float)):
        if v == 0:
            return "0"
        return "%.*g" % (digits, v)
    return html.escape(str(v))


def segment_table(js):
    head = ("<tr><th>i</th><th>[t<sub>i</sub>, t<sub>i+1</sub>]</th><th>α<sub>i</sub></th>"
            "<th>β<sub>i</sub></th><th>control points</th></tr>")
    rows = []
    for sg in js["segments"]:
        pts = " ".join("(%s)" % ", ".join(g(v) for v in p) for p in sg["P"])
        rows.append("<tr><td>%d</td><td>[%s, %s]</td><td>%s</td><td>%s</td><td>%s</td></tr>" % (
            sg["i"], g(sg["t0"]), g(sg["t1"]), g(sg["alpha"]), g(sg["beta"]), pts))
    extra = ""
    if js.get("length") is not None:
        extra = "<p>arc length %s</p>" % g(js["length"], 8)
    return extra + '<table class="iv">%s%s</table>' % (head, "".join(rows))


def interval_table(js):
    if js and "segments" in js:
        return segment_table(js)
    if not js or "intervals" not in js:
        return ""
    rows = []
    lo = js.get("lower") is not None
    up = js.get("upper") is not None
    head = "<tr><th>i</th><th>[x<sub>i</sub>, x<sub>i+1</sub>]</th><th>α<sub>i</sub></th><th>β<sub>i</sub></th><th>term</th>"
    if lo:
        head += "<th>min gap above lower</th><th>at x</th>"
    if up:
        head += "<th>min gap below upper</th><th>at x</th>"
    head += "<th>certified</th></tr>"
    for iv in js["intervals"]:
        r = "<tr><td>%d</td><td>[%s, %s]</td><td>%s</td><td>%s</td><td>%s</td>" % (
            iv["i"], g(iv["x0"]), g(iv["x1"]), g(iv["alpha"]), g(iv["beta"]), g(iv.get("term")))
        if lo:
            cls = ' class="bad"' if iv.get("gap_lower") is not None and iv["gap_lower"] <= 0 else ""
            r += "<td%s>%s</td><td>%s</td>" % (cls, g(iv.get("gap_lower")), g(iv.get("at_lower")))
        if up:
            cls = ' class="bad"' if iv.get("gap_upper") is not None and iv["gap_upper"] <= 0 else ""
            r += "<td%s>%s</td><td>%s</td>" % (cls, g(iv.get("gap_upper")), g(iv.get("at_upper")))
        r += "<td>%s</td></tr>" % g(iv.get("certified"))
        rows.append(r)
    return '<table class="iv">%s%s</table>' % (head, "".join(rows))


def panel(label, caption, args, note="", expect_fail=False):
    st, js, svg, err, cmd = run(args, "(%s) %s" % (label, caption))
    if "--points-only" in args:
        js = None  # a data panel: no curve, so no certificate to show
    # the full command line; only the paths are shortened (program, data, plot file)
    shown = " ".join(shlex.quote(os.path.basename(a) if i == 0 or a.startswith(DATA) or a.startswith(TMP)
                                 else a) for i, a in enumerate(cmd))
    parts = ['<div class="panel"><h4>(%s) %s</h4>' % (html.escape(label), html.escape(caption))]
    parts.append("<pre>$ %s</pre>" % html.escape(shown))
    if svg:
        parts.append('<div class="svg">%s</div>' % svg)
    summary = []
    if js is not None:
        if js.get("lower") is not None or js.get("upper") is not None:
            summary.append("certified: <b>%s</b>" % g(js.get("certified")))
        if js.get("min_gap_lower") is not None:
            summary.append("least gap above the lower boundary: %s" % g(js["min_gap_lower"], 6))
        if js.get("min_gap_upper") is not None:
            summary.append("least gap below the upper boundary: %s" % g(js["min_gap_upper"], 6))
        smp = js.get("samples")
        if smp:
            summary.append("curve range on the samples: [%s, %s]" % (g(smp.get("min_y"), 6), g(smp.get("max_y"), 6)))
    summary.append("exit status %d" % st)
    parts.append("<p class=\"sum\">%s</p>" % "; ".join(summary))
    if err:
        parts.append("<pre class=\"err\">%s</pre>" % html.escape(err))
    if note:
        parts.append('<p class="note">%s</p>' % note)
    parts.append(interval_table(js))
    parts.append("</div>")
    if expect_fail and st == 0:
        print("warning: expected a failure for", label, file=sys.stderr)
    return "\n".join(parts), js, st


def figure(num, title, intro, panels):
    out = ['<section><h2>Figure %s — %s</h2>' % (num, html.escape(title))]
    if intro:
        out.append("<p>%s</p>" % intro)
    out.append('<div class="grid">')
    out.extend(panels)
    out.append("</div></section>")
    return "\n".join(out)


def arithmetic_slopes(x, f):
    """docs/method.md §6 arithmetic mean (re-derived here, for the printed-sign panel)."""
    n = len(x) - 1
    h = [x[i + 1] - x[i] for i in range(n)]
    D = [(f[i + 1] - f[i]) / h[i] for i in range(n)]
    d = [0.0] * (n + 1)
    for i in range(1, n):
        d[i] = (h[i] * D[i - 1] + h[i - 1] * D[i]) / (h[i - 1] + h[i])
    d[0] = D[0] + (D[0] - D[1]) * h[0] / (h[0] + h[1])
    d[n] = D[n - 1] + (D[n - 1] - D[n - 2]) * h[n - 1] / (h[n - 1] + h[n - 2])
    return h, d


def read_xy(path):
    xs, fs = [], []
    with open(path) as fh:
        for line in fh:
            line = line.strip()
            if not line or line.startswith("#"):
                continue
            a, b = line.split(",")[:2]
            try:
                xs.append(float(a))
                fs.append(float(b))
            except ValueError:
                continue
    return xs, fs


sections = []

# ---- Figures 2 and 3: closed curves ------------------------------------
curve_note = ""
notes_path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "docs", "curves.md")
if os.path.exists(notes_path):
    with open(notes_path, encoding="utf-8") as fh:
        txt = fh.read()
    m = re.search(r"<!-- demo-note -->(.*?)<!-- /demo-note -->", txt, re.S)
    curve_note = re.sub(r"`([^`]*)`", r"<code>\1</code>", html.escape((m.group(1) if m else "").strip()))

for num, name in (("2", "fig2_closed.csv"), ("3", "fig3_closed.csv")):
    ps = []
    for b in ("0.001", "0.01", "0.05", "1", "10", "100"):
        extra = b not in ("0.001", "0.01", "0.05")
        cap = "α = 0.37, β = %s%s" % (b, " (beyond the paper: larger β)" if extra else "")
        ps.append(panel(chr(ord("a") + len(ps)), cap,
                        ["curve", data(name), "--closed", "--param", "uniform", "--alpha", "0.37", "--beta", b,
                         "--show-control"])[0])
    sections.append(figure(num, "closed curve through %s" % name,
                           "The paper's closed example with α<sub>i</sub> = 0.37 and "
                           "β<sub>i</sub> ∈ {0.001, 0.01, 0.05}, plus two larger β to test its claim that "
                           "the curve tends to a straight line as β grows (uniform parameter knots).</p>"
                           '<p class="note"><b>What really happens.</b> ' + curve_note, ps))

# ---- Figure 4: Table 1, positive ----------------------------------------
t1 = data("table1_positive.csv")
ps = []
ps.append(panel("a", "data (Table 1)", ["fit", t1, "--points-only"])[0])
html_b, js_b, _ = panel("b", "no scheme, α = 1.4, β = 1.9 (the paper's 'negative behaviour')",
                        ["certify", t1, "--alpha", "1.4", "--beta", "1.9", "--shape", "positive"])
low = js_b.get("min_gap_lower") if js_b else None
ps.append(html_b.replace("</h4>", "</h4>", 1) + "")
note_b = ("<b>Differs from the paper.</b> The paper shows this curve going negative. With the "
          "arithmetic-mean slopes it does not: its exact minimum (the certificate) is %s, attained at the knot x = 5 (docs/method.md §9.6). The defect needs a much "
          "smaller a = α+β for every interval: panels (b′) and (b″)." % g(low, 4))
ps[-1] = ps[-1].replace('<table class="iv">', '<p class="note">%s</p><table class="iv">' % note_b, 1)
ps.append(panel("b′", "no scheme, α = 0.04, β = 0 (a = 0.04 on every interval)",
                ["certify", t1, "--alpha", "0.04", "--beta", "0", "--shape", "positive"],
                "Parameters that do show the defect: the curve first dips below zero near a = 0.04 (docs/method.md §9.6).")[0])
ps.append(panel("b″", "no scheme, α = 0.01, β = 0",
                ["certify", t1, "--alpha", "0.01", "--beta", "0", "--shape", "positive"],
                "At a = 0.01 the dip is deep (about −6.2).")[0])
ps.append(panel("c", "positive scheme, α = 0.15", ["fit", t1, "--shape", "positive", "--alpha", "0.15"])[0])
ps.append(panel("d", "positive scheme, α = 0.0001", ["fit", t1, "--shape", "positive", "--alpha", "0.0001"])[0])
sections.append(figure("4", "positive data (Table 1)",
                       "Theorem 2: β<sub>i</sub> chosen so that all four control values are positive. "
                       "This is rigorous; each interval's exact minimum is also computed.", ps))

# ---- Figure 5: Table 2, above a line -------------------------------------
t2 = data("table2_above_line.csv")
LINE2 = "0.03,0.3"
ps = []
html_a, _, st_a = panel("a", "data with the paper's line y = 0.31x + 1: refused",
                        ["fit", t2, "--shape", "above", "--line", "0.31,1"],
                        "<b>Differs from the paper.</b> Table 2 does not lie above y = 0.31x + 1: the points at "
                        "x = 1, 14 and 15 are below it (docs/method.md §9.5), so the scheme refuses the data and names the "
                        "first offending point. The panels below use the line <b>y = 0.03x + 0.3</b>, which "
                        "every data point lies above.", expect_fail=True)
ps.append(html_a)
ps.append(panel("a′", "data and the line y = 0.03x + 0.3", ["fit", t2, "--points-only", "--lower", LINE2])[0])
ps.append(panel("b", "no scheme, α = 0.15, β = 0.40", ["certify", t2, "--alpha", "0.15", "--beta", "0.40",
                                                       "--line", LINE2, "--shape", "above"])[0])
ps.append(panel("b′", "no scheme, α = 0.01, β = 0", ["certify", t2, "--alpha", "0.01", "--beta", "0",
                                                     "--line", LINE2, "--shape", "above"],
                "Small a on every interval: the unconstrained curve crosses the line.")[0])
ps.append(panel("c", "above-line scheme, α = 0.01", ["fit", t2, "--shape", "above", "--line", LINE2,
                                                     "--alpha", "0.01"])[0])
ps.append(panel("d", "above-line scheme, α = 0.12", ["fit", t2, "--shape", "above", "--line", LINE2,
                                                     "--alpha", "0.12"])[0])
sections.append(figure("5", "data above a line (Table 2)",
                       "Theorem 3. In the paper form the line varies across an interval while the theorem "
                       "treats it as one value, so every interval is certified by its exact minimum and "
                       "β<sub>i</sub> raised where needed (term 'certify').", ps))

# ---- Figure 6: Table 3, below y = x + 2.5 --------------------------------
t3 = data("table3_below_line.csv")
ps = []
ps.append(panel("a", "data and the line y = x + 2.5", ["fit", t3, "--points-only", "--upper", "1,2.5"])[0])
ps.append(panel("b", "no scheme, α = 0.2, β = 0.21", ["certify", t3, "--alpha", "0.2", "--beta", "0.21",
                                                      "--line", "1,2.5", "--shape", "below"],
                "The paper's arbitrary parameters do show the defect here: on [3, 5] the certificate finds the "
                "curve slightly above the line (least gap below it negative; the forbidden region is shaded).")[0])
ps.append(panel("c", "below-line scheme (corrected signs), α = 0.001",
                ["fit", t3, "--shape", "below", "--line", "1,2.5", "--alpha", "0.001"])[0])
ps.append(panel("d", "below-line scheme (corrected signs), α = 0.1",
                ["fit", t3, "--shape", "below", "--line", "1,2.5", "--alpha", "0.1"])[0])
# the paper's printed Theorem 4: Theorem 3's signs applied to the upper gaps
x3, f3 = read_xy(t3)
h3, d3 = arithmetic_slopes(x3, f3)
alpha, t = 0.001, 0.01
G = [xx + 2.5 - ff for xx, ff in zip(x3, f3)]
betas = []
for i in range(len(h3)):
    K = 2 * h3[i] / (3 * math.pi)
    betas.append(t + max(0.0, -alpha - K * d3[i] / G[i], -alpha + K * d3[i + 1] / G[i + 1]))
ps.append(panel("c′", "the paper's printed Theorem 4 (wrong signs), α = 0.001, margin 0.01",
                ["certify", t3, "--alpha", "0.001", "--betas", ",".join(repr(b) for b in betas),
                 "--line", "1,2.5", "--shape", "below"],
                "<b>Differs from the paper.</b> Theorem 4 as printed uses the signs of Theorem 3; with "
                "those β<sub>i</sub> (computed by this page from the printed rule) the curve rises far above "
                "the line (docs/method.md §5.3). With the corrected rule, panel (c), it stays below.",
                expect_fail=True)[0])
sections.append(figure("6", "data below a line (Table 3)",
                       "Theorem 4, with the signs corrected (docs/method.md §5.3).", ps))

# ---- Figure 7: Table 4, between two lines --------------------------------
t4 = data("table4_between_lines.csv")
LL, UL = "1,0.1", "8,6"
ps = []
ps.append(panel("a", "data between y = x + 0.1 and y = 8x + 6",
                ["fit", t4, "--points-only", "--lower", LL, "--upper", UL])[0])
ps.append(panel("b", "no scheme, α = 0.2, β = 0.5", ["certify", t4, "--alpha", "0.2", "--beta", "0.5",
                                                     "--lower", LL, "--upper", UL, "--shape", "between"])[0])
ps.append(panel("b′", "no scheme, α = 0.02, β = 0", ["certify", t4, "--alpha", "0.02", "--beta", "0",
                                                     "--lower", LL, "--upper", UL, "--shape", "between"],
                "Small a on every interval: the unconstrained curve leaves the band.")[0])
ps.append(panel("c", "between-lines scheme, α = 0.4", ["fit", t4, "--shape", "between", "--lower", LL,
                                                       "--upper", UL, "--alpha", "0.4"])[0])
ps.append(panel("d", "between-lines scheme, α = 0.1", ["fit", t4, "--shape", "between", "--lower", LL,
                                                       "--upper", UL, "--alpha", "0.1"])[0])
sections.append(figure("7", "data between two lines (Table 4)",
                       "Theorem 5 (its terms a3, a4 carry Theorem 4's sign error; corrected here).", ps))

# ---- surfaces (docs/method.md §11) -------------------------------------------
def surface_run(args):
    """trigspline surface ARGS --json --svg: (status, json, svg text, stderr, cmd)."""
    svg = os.path.join(TMP, "s%d.svg" % run.counter)
    run.counter += 1
    cmd = [CLI, "surface"] + args + ["--json", "--svg", svg]
    p = subprocess.run(cmd, capture_output=True, text=True)
    js = json.loads(p.stdout) if p.returncode == 0 and p.stdout.strip() else None
    text = open(svg, encoding="utf-8").read() if os.path.exists(svg) else ""
    return p.returncode, js, text, p.stderr.strip(), cmd


def read_grid(path, matrix):
    rows = [l.split(",") for l in open(path, encoding="utf-8")
            if l.strip() and not l.startswith("#")]
    if matrix:
        xs = [float(v) for v in rows[0][1:]]
        ys = [float(r[0]) for r in rows[1:]]
        zs = [[float(v) for v in r[1:]] for r in rows[1:]]
        return xs, ys, zs
    pts = [(float(a), float(b), float(c)) for a, b, c in rows[1:]]
    xs = sorted({p[0] for p in pts})
    ys = sorted({p[1] for p in pts})
    zs = [[0.0] * len(xs) for _ in ys]
    for a, b, c in pts:
        zs[ys.index(b)][xs.index(a)] = c
    return xs, ys, zs


def bicubic_range(xs, ys, zs, m=8):
    """min and max of the usual bicubic (tensor cubic Hermite, three-point
    slopes along grid lines and their cross derivative), sampled m per cell."""
    def slopes(t, f):
        n = len(t) - 1
        h = [t[i + 1] - t[i] for i in range(n)]
        d = [(f[i + 1] - f[i]) / h[i] for i in range(n)]
        out = [0.0] * (n + 1)
        for i in range(1, n):
            out[i] = (h[i] * d[i - 1] + h[i - 1] * d[i]) / (h[i - 1] + h[i])
        out[0] = d[0] + (d[0] - d[1]) * h[0] / (h[0] + h[1]) if n > 1 else d[0]
        out[n] = d[n - 1] + (d[n - 1] - d[n - 2]) * h[n - 1] / (h[n - 1] + h[n - 2]) if n > 1 else d[0]
        return out
    nx, ny = len(xs), len(ys)
    p = [slopes(xs, zs[j]) for j in range(ny)]
    qc = [slopes(ys, [zs[j][i] for j in range(ny)]) for i in range(nx)]
    q = [[qc[i][j] for i in range(nx)] for j in range(ny)]
    rc = [slopes(ys, [p[j][i] for j in range(ny)]) for i in range(nx)]
    r = [[rc[i][j] for i in range(nx)] for j in range(ny)]

    def herm(t):
        return (2 * t ** 3 - 3 * t ** 2 + 1, t ** 3 - 2 * t ** 2 + t, -2 * t ** 3 + 3 * t ** 2, t ** 3 - t ** 2)
    lo, hi = math.inf, -math.inf
    for j in range(ny - 1):
        hy = ys[j + 1] - ys[j]
        for i in range(nx - 1):
            hx = xs[i + 1] - xs[i]
            for a in range(m + 1):
                ha = herm(a / m)
                for b in range(m + 1):
                    hb = herm(b / m)
                    v = 0.0
                    for ci in (0, 1):
                        for cj in (0, 1):
                            I, J = i + ci, j + cj
                            wx0, wx1 = ha[2 * ci], ha[2 * ci + 1] * hx
                            wy0, wy1 = hb[2 * cj], hb[2 * cj + 1] * hy
                            v += (wx0 * wy0 * zs[J][I] + wx1 * wy0 * p[J][I] +
                                  wx0 * wy1 * q[J][I] + wx1 * wy1 * r[J][I])
                    lo, hi = min(lo, v), max(hi, v)
    return lo, hi


def surface_panel(label, caption, args, note=""):
    st, js, svg, err, cmd = surface_run(args)
    shown = " ".join(shlex.quote(os.path.basename(a) if i == 0 or i == len(cmd) - 1 or
                                 a.startswith(DATA) or a.startswith(SURF) else a)
                     for i, a in enumerate(cmd))
    parts = ['<div class="panel"><h4>(%s) %s</h4>' % (html.escape(label), html.escape(caption)),
             "<pre>$ %s</pre>" % html.escape(shown)]
    if svg:
        parts.append('<div class="svg">%s</div>' % svg)
    summary = ["exit status %d" % st]
    if js:
        summary.insert(0, "range on %d samples: [%s, %s]" % (js["samples"], g(js["sample_min"], 6),
                                                              g(js["sample_max"], 6)))
        if js["shape"] != "none":
            pl = [p["proven_lower"] for p in js["patches"] if "proven_lower" in p]
            pu = [p["proven_upper"] for p in js["patches"] if "proven_upper" in p]
            summary.insert(0, "certified: <b>%s</b> (%d patches%s%s)" % (
                g(js["certified"]), len(js["patches"]),
                "; least proven gap above the floor %s" % g(min(pl), 6) if pl else "",
                "; below the ceiling %s" % g(min(pu), 6) if pu else ""))
    parts.append('<p class="sum">%s</p>' % "; ".join(summary))
    if err:
        parts.append('<pre class="err">%s</pre>' % html.escape(err))
    if note:
        parts.append('<p class="note">%s</p>' % note)
    parts.append("</div>")
    return "\n".join(parts)


SURF = os.path.join(os.path.dirname(os.path.abspath(DATA)), "surface")
RAIN = os.path.join(SURF, "spiky_rain_matrix.csv")
CLOUD = os.path.join(SURF, "cloud_percent_long.csv")
if os.path.exists(RAIN) and os.path.exists(CLOUD):
    rx, ry, rz = read_grid(RAIN, True)
    cx, cy, cz = read_grid(CLOUD, False)
    rlo, rhi = bicubic_range(rx, ry, rz)
    clo, chi = bicubic_range(cx, cy, cz)
    ps = [
        surface_panel("a", "spiky positive field, no scheme", [RAIN, "--matrix", "--samples", "8"],
                      "Without a scheme the surface dips below zero. The usual bicubic (tensor cubic "
                      "Hermite, three-point slopes and twists, as SciPy-style interpolators do) "
                      "sampled 8 per cell ranges over [%s, %s] on the same data." % (g(rlo, 5), g(rhi, 5))),
        surface_panel("b", "spiky positive field, certified positive",
                      [RAIN, "--matrix", "--samples", "8", "--shape", "positive", "--form", "geometric"],
                      "Every patch is proven ≥ 0 (all 16 control values ≥ 0, docs/method.md §11.3); "
                      "zeros stay zeros. Orange outlines: patches where the floor is active."),
        surface_panel("c", "percentage field, no scheme", [CLOUD, "--samples", "8"],
                      "The unconstrained surface leaves [0, 100]; the usual bicubic ranges over "
                      "[%s, %s]." % (g(clo, 5), g(chi, 5))),
        surface_panel("d", "percentage field, certified in [0, 100]",
                      [CLOUD, "--samples", "8", "--shape", "bounds", "--lower", "0", "--upper", "100"],
                      "Floor and ceiling kept exactly; every patch certified."),
    ]
    sections.append('<section><h2>Surfaces — certified interpolation of gridded data</h2>'
                    '<p>Beyond the paper: the tensor product of the method (docs/method.md §11). '
                    'Heatmaps with contour lines; black dots are the data nodes.</p>'
                    '<div class="grid">%s</div></section>' % "\n".join(ps))

DIFFS = """
<ol>
<li><b>B<sub>2</sub> sign.</b> The paper prints B<sub>2</sub> = f<sub>i+1</sub> + k<sub>i</sub>d<sub>i+1</sub>; that
gives the end slope −d<sub>i+1</sub>/a<sub>i</sub>. Its Theorems 2–5 use the minus sign, which is what we implement
(and test: both end slopes of every interval).</li>
<li><b>Kinks.</b> The spline is GC¹: at a knot the left slope is d<sub>i</sub>/a<sub>i−1</sub>, the right one
d<sub>i</sub>/a<sub>i</sub>. The shape schemes make a<sub>i</sub> differ, so the graph has kinks; the
<code>--c1</code> option removes them and keeps every guarantee.</li>
<li><b>Line constraints are certified.</b> Theorems 3–5 treat the line as constant on an interval; the library
computes the exact minimum gap on every interval and raises β<sub>i</sub> where needed.</li>
<li><b>Theorem 4's signs</b> (and Theorem 5's a3, a4) are wrong as printed: Figure 6 (c′).</li>
<li><b>Table 2's line.</b> The data do not lie above y = 0.31x + 1: Figure 5 (a).</li>
<li><b>Figure 4b.</b> No negative behaviour at α = 1.4, β = 1.9 with arithmetic-mean slopes: Figure 4 (b).</li>
<li><b>Theorem 1 (O(h³))</b> does not hold: the scheme does not reproduce straight lines; see docs/accuracy.md.</li>
</ol>
"""

CSS = """
body{font-family:system-ui,sans-serif;max-width:1500px;margin:1em auto;padding:0 1em;color:#222}
h1{font-size:1.6em} h2{border-bottom:2px solid #ccc;padding-bottom:.2em;margin-top:2em}
.grid{display:grid;grid-template-columns:repeat(auto-fill,minmax(700px,1fr));gap:1.2em}
.panel{border:1px solid #ddd;border-radius:6px;padding:.6em;background:#fafafa;overflow-x:auto}
.panel h4{margin:.2em 0 .4em}
pre{background:#f0f0f0;padding:.3em .5em;white-space:pre-wrap;word-break:break-all;font-size:.8em}
pre.err{background:#fff0f0;color:#900}
.note{background:#fff8e0;border-left:4px solid #e0a000;padding:.4em .6em}
table.iv{border-collapse:collapse;font-size:.8em;margin-top:.4em}
table.iv td,table.iv th{border:1px solid #ccc;padding:1px 5px;text-align:right}
td.bad{background:#fcc;font-weight:bold}
.svg svg{max-width:100%;height:auto}
"""

page = """<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>trigspline — the paper's numerical section</title>
<style>%s</style></head><body>
<h1>Shape-preserving positive trigonometric spline curves — the numerical section, reproduced</h1>
<p>Every panel below was made by the <code>trigspline</code> command shown above it, on the paper's data
(<code>data/paper/</code>). Tables list, per interval, the shape parameters and the <b>certificate</b>: the
exact minimum distance of the curve to each boundary on that interval (from the critical points of the
trigonometric polynomial, not from samples) and where it is attained. Slopes: arithmetic mean (docs/method.md §6);
margin t = 0.01 unless stated.</p>
<p>Why use this rather than PCHIP, Akima or GSL's splines, how to choose α, and what the certificate
does and does not promise: <a href="../why/index.html">the companion page</a>.</p>
<h2>Where our results differ from the paper</h2>%s
%s
<p style="margin-top:3em;color:#777">Generated by scripts/paper_demo.py with trigspline %s.</p>
</body></html>
""" % (CSS, DIFFS, "\n".join(sections), VERSION)

os.makedirs(OUT, exist_ok=True)
dst = os.path.join(OUT, "index.html")
tmp = dst + ".tmp"
with open(tmp, "w", encoding="utf-8") as fh:
    fh.write(page)
os.replace(tmp, dst)
print(os.path.abspath(dst))
