#!/usr/bin/python3
"""Why trigspline: our curves beside SciPy's and GSL's on a scientist's kind of data.

Usage: /usr/bin/python3 scripts/why_demo.py BUILD_DIR DATA_DIR OUT_DIR

BUILD_DIR holds `trigspline` (the command-line tool) and `gsl_eval`
(tools/compare/gsl_eval.c, built when GSL is found); DATA_DIR the data sets of
data/examples/; the page goes to OUT_DIR/index.html (temporary file +
rename), the files the commands write to OUT_DIR/files/.

Every number on the page is computed here, when the page is made:
  - ours: the `trigspline` commands shown on the page in full (--form and
    the paper's --slopes arithmetic given explicitly), their JSON report (the exact certificate, docs/method.md §5.6,
    and the overshoot, §5.9) and their samples;
  - SciPy CubicSpline (not-a-knot), PchipInterpolator, Akima1DInterpolator,
    from Debian's python3-scipy;
  - GSL cspline (natural) and steffen through gsl_eval.
A competitor's least gap to a bound is the minimum over dense samples
(DENSE points per interval, plus the knots); its violations are the
intervals where a sample is on the wrong side.  Needs numpy, scipy and
matplotlib (Debian packages; `make demo` installs them).
"""
import html
import io
import json
import math
import os
import shlex
import subprocess
import sys

import matplotlib

matplotlib.use("svg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from scipy.interpolate import Akima1DInterpolator, CubicSpline, PchipInterpolator  # noqa: E402

BUILD, DATA, OUT = sys.argv[1], sys.argv[2], sys.argv[3]
REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CLI = os.path.abspath(os.path.join(BUILD, "trigspline"))
GSL = os.path.abspath(os.path.join(BUILD, "gsl_eval"))
FILES = os.path.join(OUT, "files")
DENSE = 2000   # samples per interval for the competitors' minima
PLOT_M = 60    # samples per interval in the plots
FORM = "paper"  # stated in every command: the library's default may change
matplotlib.rcParams.update({"svg.fonttype": "none", "font.size": 9, "svg.hashsalt": "trigspline"})

COLORS = {"ours": "#1a7f37", "SciPy CubicSpline": "#d62728", "SciPy PCHIP": "#9467bd",
          "SciPy Akima": "#ff7f0e", "GSL cspline": "#8c564b", "GSL steffen": "#17becf"}
COMPETITORS = ["SciPy CubicSpline", "SciPy PCHIP", "SciPy Akima", "GSL cspline", "GSL steffen"]


def shown(cmd):
    """The command as typed from the repository root (paths made relative to it)."""
    out = []
    for a in cmd:
        if os.path.isabs(a) and os.path.exists(os.path.dirname(a)):
            a = os.path.relpath(a, REPO)
        out.append(a)
    return " ".join(shlex.quote(a) for a in out)


def run(cmd, ok=(0,)):
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode not in ok:
        sys.exit("why_demo: %s failed (exit %d): %s" % (shown(cmd), p.returncode, p.stderr))
    return p


def read_table(path):
    """A data file of data/examples: # comments, a header row, numeric rows."""
    with open(path) as fh:
        lines = [ln.strip() for ln in fh if ln.strip() and not ln.lstrip().startswith("#")]
    cols = tuple(lines[0].split(","))
    rows = np.array([[float(v) for v in ln.split(",")] for ln in lines[1:]])
    return rows, cols


def read_xy(path):
    rows, cols = read_table(path)
    return rows[:, 0], rows[:, 1], cols


def figure_svg(fig):
    """The figure as inline SVG text (from its <svg> element on), then closed."""
    fig.tight_layout()
    buf = io.StringIO()
    fig.savefig(buf, format="svg")
    plt.close(fig)
    text = buf.getvalue()
    return text[text.find("<svg"):]


def read_cli_xy(text):
    """The first two columns of a CSV the command wrote (its header names
    are the input's column names, so columns are taken by position)."""
    d = np.loadtxt(io.StringIO(text), delimiter=",", skiprows=1, ndmin=2)
    return d[:, 0], d[:, 1]


def read_csv_samples(path):
    d = np.genfromtxt(path, delimiter=",", names=True)
    return [np.asarray(d[c], float) for c in d.dtype.names]


def fmt(v, digits=4):
    if v is None:
        return "–"
    if isinstance(v, bool):
        return "yes" if v else "no"
    if v == 0:
        return "0"
    return ("%.*g" % (digits, v)).replace("-", "−")


def dense_grid(x, m):
    """m points per interval (knots included), then the last knot: as `fit --samples m`."""
    pts = [x[i] + (x[i + 1] - x[i]) * (np.arange(m - 1) / (m - 1)) for i in range(len(x) - 1)]
    return np.concatenate(pts + [x[-1:]])


class Ours:
    """One `trigspline fit` configuration: its JSON report and its samples."""

    def __init__(self, key, data, args):
        self.key = key
        base = [CLI, "fit", data] + args
        self.json_path = os.path.join(FILES, key + ".json")
        self.csv_path = os.path.join(FILES, key + ".csv")
        self.cmd_json = base + ["--json", "-o", self.json_path]
        self.cmd_csv = base + ["--samples", str(PLOT_M), "-o", self.csv_path]
        self.status, self.stderr, self.js = 0, "", None
        p = subprocess.run(self.cmd_json, capture_output=True, text=True)
        self.status, self.stderr = p.returncode, p.stderr.strip()
        if p.returncode == 0:
            with open(self.json_path) as fh:
                self.js = json.load(fh)
            run(self.cmd_csv)
            self.x, self.y = read_csv_samples(self.csv_path)

    def commands_html(self):
        lines = ["$ " + shown(self.cmd_json)]
        if self.js is not None:
            lines.append("$ " + shown(self.cmd_csv))
        text = "\n".join(html.escape(s) for s in lines)
        if self.stderr:
            text += '\n<span class="err">%s</span>' % html.escape(self.stderr)
        if self.status:
            text += '\n<span class="err">(exit status %d)</span>' % self.status
        return "<pre>%s</pre>" % text


def competitors(x, f, data_path, grid):
    """name -> values on grid (SciPy evaluated here, GSL through gsl_eval)."""
    out = {"SciPy CubicSpline": CubicSpline(x, f)(grid),
           "SciPy PCHIP": PchipInterpolator(x, f)(grid),
           "SciPy Akima": Akima1DInterpolator(x, f)(grid)}
    m = (len(grid) - 1) // (len(x) - 1) + 1
    for method, name in (("cspline", "GSL cspline"), ("steffen", "GSL steffen")):
        p = run([GSL, method, data_path, str(m)])
        d = np.genfromtxt(io.StringIO(p.stdout), delimiter=",", names=True)
        if len(d["x"]) != len(grid) or np.max(np.abs(d["x"] - grid)) > 1e-9 * (1 + np.max(np.abs(grid))):
            sys.exit("why_demo: gsl_eval's grid differs from ours")
        out[name] = np.asarray(d["y"], float)
    return out


def violations(x, grid, gap):
    """(least gap, number of intervals with a sample of negative gap, worst place of each)."""
    idx = np.clip(np.searchsorted(x, grid, side="right") - 1, 0, len(x) - 2)
    bad = gap < 0
    worst = []
    for i in np.unique(idx[bad]):
        sel = np.where((idx == i) & bad)[0]
        worst.append(sel[np.argmin(gap[sel])])
    return float(np.min(gap)), len(worst), worst


SECTIONS = []
SUMMARY = []   # (data set, method, least gap, violations, note)
KEYS = {}      # data-key -> number (the test re-derives some)


def cell(key, v, digits=4):
    KEYS[key] = v
    return '<td data-key="%s">%s</td>' % (html.escape(key), fmt(v, digits))


def function_panel(key, title, intro, verdict, data_name, lower, upper, our_args, unit):
    """A data set y(x) with a lower and/or upper bound (functions of x, or None)."""
    data = os.path.join(DATA, data_name)
    x, f, cols = read_xy(data)
    ours = Ours(key + "_ours", data, ["--form", FORM, "--slopes", "arithmetic"] + our_args)
    grid = dense_grid(x, DENSE)
    comp = competitors(x, f, data, grid)
    pgrid = dense_grid(x, PLOT_M)
    # the competitors again on the (coarser) plot grid
    pcomp = competitors(x, f, data, pgrid)

    rows = []
    marks = {}
    gaps_plot = {}
    for name in COMPETITORS:
        y = comp[name]
        res = []
        for side, line in (("lower", lower), ("upper", upper)):
            if line is None:
                continue
            g = y - line(grid) if side == "lower" else line(grid) - y
            least, nviol, worst = violations(x, grid, g)
            res.append((side, least, nviol))
            marks.setdefault(name, []).extend((grid[w], y[w]) for w in worst)
            # the plotted gap: to the nearer bound
            gaps_plot[name] = (grid, np.minimum(gaps_plot[name][1], g) if name in gaps_plot else g)
        rows.append((name, res))
    # ours: the exact certificate
    our_res = []
    if ours.js is not None:
        for side in ("lower", "upper"):
            v = ours.js.get("min_gap_" + side)
            if v is not None:
                bad = sum(1 for iv in ours.js["intervals"] if not iv["certified"])
                our_res.append((side, v, bad))
        gs = [ours.y - lower(ours.x)] if lower is not None else []
        gs += [upper(ours.x) - ours.y] if upper is not None else []
        gaps_plot["ours"] = (ours.x, np.minimum.reduce(gs))

    # ---- plot: curves (top) and the gap to the bound, zoomed (bottom)
    fig, (ax, bx) = plt.subplots(2, 1, figsize=(9.5, 6.4), height_ratios=[3, 2], sharex=True)
    lo_y, hi_y = np.min(f), np.max(f)
    span = hi_y - lo_y
    for name in COMPETITORS:
        ax.plot(pgrid, pcomp[name], color=COLORS[name], lw=1.0, label=name, alpha=0.9)
    if ours.js is not None:
        ax.plot(ours.x, ours.y, color=COLORS["ours"], lw=2.2, label="trigspline (ours)")
    for side, line in (("lower", lower), ("upper", upper)):
        if line is None:
            continue
        xl = np.linspace(x[0], x[-1], 200)
        ax.plot(xl, line(xl), color="k", lw=1, ls="--")
        ylim_far = lo_y - 10 * span if side == "lower" else hi_y + 10 * span
        ax.fill_between(xl, line(xl), ylim_far, color="#f4cccc", alpha=0.5, lw=0)
    for name, pts in marks.items():
        if pts:
            px, py = zip(*pts)
            ax.plot(px, py, "x", color=COLORS[name], ms=8, mew=2)
    ax.plot(x, f, "o", color="k", ms=3.5, label="data", zorder=5)
    allv = np.concatenate([pcomp[n] for n in COMPETITORS] + ([ours.y] if ours.js is not None else []))
    pad = 0.06 * span
    ax.set_ylim(min(np.min(allv), lo_y) - pad, max(np.max(allv), hi_y) + pad)
    ax.set_ylabel("%s" % unit)
    ax.legend(fontsize=7.5, ncol=4, loc="upper left", bbox_to_anchor=(0, 1.22), frameon=False)
    ax.grid(alpha=0.25)
    worst_all = min(np.min(g) for _, g in gaps_plot.values())
    zoom = max(abs(worst_all) * 3, 0.02 * span)
    for name, (gx, g) in gaps_plot.items():
        bx.plot(gx, g, color=COLORS[name], lw=2.2 if name == "ours" else 1.0)
    bx.axhline(0, color="k", lw=1, ls="--")
    bx.axhspan(-10 * zoom, 0, color="#f4cccc", alpha=0.5, lw=0)
    bx.set_ylim(-zoom, zoom)
    bx.set_ylabel("gap to the %s bound\n(zoomed; below 0 = violation)" % (
        "nearer" if lower is not None and upper is not None else "lower" if lower is not None else "upper"))
    bx.set_xlabel(cols[0])
    bx.grid(alpha=0.25)
    svg_text = figure_svg(fig)

    # ---- table
    sides = [s for s, ln in (("lower", lower), ("upper", upper)) if ln is not None]
    head = "<tr><th>method</th>" + "".join(
        "<th>least gap to the %s bound</th><th>intervals crossing it</th>" % s for s in sides) + "</tr>"
    body = []
    if ours.js is not None:
        r = '<tr class="ours"><td>trigspline (exact certificate; certified: <b>%s</b>)</td>' % fmt(ours.js["certified"])
        for side, v, bad in our_res:
            r += cell("%s/ours/%s" % (key, side), v) + "<td>%d</td>" % bad
        body.append(r + "</tr>")
    else:
        body.append('<tr class="ours"><td>trigspline</td><td colspan="%d">refused the data (see the command '
                    'above)</td></tr>' % (2 * len(sides)))
    for name, res in rows:
        r = "<tr><td>%s</td>" % name
        for side, least, nviol in res:
            cls = ' class="bad"' if nviol else ""
            KEYS["%s/%s/%s" % (key, name, side)] = least
            r += '<td data-key="%s/%s/%s"%s>%s</td><td%s>%d</td>' % (
                key, html.escape(name), side, cls, fmt(least), cls, nviol)
            SUMMARY.append((title, name, side, least, nviol))
        body.append(r + "</tr>")
    for side, v, bad in our_res:
        SUMMARY.append((title, "trigspline", side, v, bad))
    over = ""
    if ours.js is not None and "overshoot" in ours.js:
        ov = ours.js["overshoot"]
        over = ("<p class=\"sum\">Our curve's range: [%s, %s] for data in [%s, %s]; its largest excursion beyond "
                "an interval's own data: %s above, %s below (report fields <code>overshoot</code>, docs/method.md "
                "§5.9).</p>" % (fmt(ov["y_min"]), fmt(ov["y_max"]), fmt(ov["data_min"]), fmt(ov["data_max"]),
                                fmt(ov["max_excursion_above"]), fmt(ov["max_excursion_below"])))
    SECTIONS.append(
        '<section id="%s"><h2>%s</h2><p>%s</p>%s<div class="svg">%s</div>'
        '<table class="cmp">%s%s</table>%s<p class="verdict">%s</p>'
        '<p class="small">Data: <code>%s</code> (how it was made: data/examples/README.md). Competitors '
        'sampled at %d points per interval; × marks the worst point of each interval that crosses a bound.</p>'
        "</section>" % (key, html.escape(title), intro, ours.commands_html(), svg_text, head, "".join(body), over,
                        verdict(KEYS), html.escape(os.path.relpath(data, REPO)), DENSE))
    return ours


def curve_panel():
    key = "outline"
    data = os.path.join(DATA, "field_outline.csv")
    px, py, _ = read_xy(data)
    box = (0.0, 100.0, 0.0, 60.0)
    js_path = os.path.join(FILES, key + ".json")
    csv_path = os.path.join(FILES, key + ".csv")
    base = [CLI, "curve", data, "--closed", "--param", "centripetal", "--box", "0,100,0,60"]
    cmd_json = base + ["--json", "-o", js_path]
    cmd_csv = base + ["--samples", str(PLOT_M), "-o", csv_path]
    run(cmd_json)
    run(cmd_csv)
    with open(js_path) as fh:
        js = json.load(fh)
    t_s, x_s, y_s = read_csv_samples(csv_path)
    # the competitors per coordinate on the same parameter knots (closed: first point repeated)
    t = np.asarray(js["knots"], float)
    cx, cy = np.append(px, px[0]), np.append(py, py[0])
    tg = dense_grid(t, DENSE)
    curves = {
        "SciPy CubicSpline": (CubicSpline(t, cx, bc_type="periodic")(tg), CubicSpline(t, cy, bc_type="periodic")(tg)),
        "SciPy PCHIP": (PchipInterpolator(t, cx)(tg), PchipInterpolator(t, cy)(tg)),
        "SciPy Akima": (Akima1DInterpolator(t, cx)(tg), Akima1DInterpolator(t, cy)(tg)),
    }
    fig, ax = plt.subplots(figsize=(9.5, 6.0))
    ax.add_patch(plt.Rectangle((-5, -5), 110, 70, color="#f4cccc", alpha=0.5, lw=0))
    ax.add_patch(plt.Rectangle((0, 0), 100, 60, color="white", lw=1, ls="--", ec="k"))
    rows = []
    for name, (X, Y) in curves.items():
        g = np.minimum.reduce([X - box[0], box[1] - X, Y - box[2], box[3] - Y])
        least, nviol, worst = violations(t, tg, g)
        ax.plot(X, Y, color=COLORS[name], lw=1.0, label=name)
        for w in worst:
            ax.plot(X[w], Y[w], "x", color=COLORS[name], ms=8, mew=2)
        KEYS["%s/%s/box" % (key, name)] = least
        cls = ' class="bad"' if nviol else ""
        rows.append('<tr><td>%s</td><td data-key="%s/%s/box"%s>%s</td><td%s>%d</td></tr>' % (
            name, key, html.escape(name), cls, fmt(least), cls, nviol))
        SUMMARY.append(("Closed outline inside a box", name, "box", least, nviol))
    ax.plot(x_s, y_s, color=COLORS["ours"], lw=2.2, label="trigspline (ours)")
    ax.plot(px, py, "o", color="k", ms=4, label="data", zorder=5)
    ax.set_xlim(-4, 104)
    ax.set_ylim(-4, 64)
    ax.set_aspect("equal")
    ax.legend(fontsize=7.5, loc="center", frameon=False)
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    svg_text = figure_svg(fig)
    SUMMARY.append(("Closed outline inside a box", "trigspline", "box", js["min_gap"], 0 if js["certified"] else -1))
    KEYS["outline/ours/box"] = js["min_gap"]
    body = ('<tr class="ours"><td>trigspline (exact certificate; certified: <b>%s</b>)</td>%s<td>0</td></tr>'
            % (fmt(js["certified"]), cell("outline/ours/box", js["min_gap"])) + "".join(rows))
    cmds = "\n".join(html.escape("$ " + shown(c)) for c in (cmd_json, cmd_csv))
    bad_names = [r[1] for r in SUMMARY if r[0].startswith("Closed") and r[1] != "trigspline" and r[4] > 0]
    n_bad = len(bad_names)
    SECTIONS.append(
        '<section id="%s"><h2>Closed outline inside a box (a parametric curve)</h2>'
        "<p>A field boundary surveyed at 12 points must be drawn inside the property box 0 ≤ x ≤ 100, 0 ≤ y ≤ 60 m. "
        "Each coordinate is interpolated against the same parameter (centripetal knots, from our report). "
        "Our <code>curve --box</code> raises β per segment until every segment and coordinate is certified "
        "inside the box.</p><pre>%s</pre><div class=\"svg\">%s</div>"
        '<table class="cmp"><tr><th>method</th><th>least distance to the box (negative: outside)</th>'
        "<th>segments leaving it</th></tr>%s</table>"
        '<p class="verdict">%s</p><p class="small">GSL has no periodic shape-preserving interpolant; PCHIP '
        "and Akima are not periodic, so they close the loop with a corner at the first point. Data: "
        "<code>%s</code>.</p></section>" % (
            key, cmds, svg_text, body,
            ("%s leave%s the box (worst: %s m outside); ours is certified inside it, at least %s m from every side. "
             "Which competitor fails depends on the outline: none of them can tell you." % (
                 " and ".join(bad_names), "s" if n_bad == 1 else "",
                 fmt(-min(KEYS["outline/%s/box" % b] for b in bad_names)), fmt(KEYS["outline/ours/box"])))
            if n_bad else
            "On this outline all three SciPy curves stay inside the box too; ours is the only one with a proof "
            "(and the only smooth closed one).",
            html.escape(os.path.relpath(data, REPO))))


def cloud_verdict(k):
    """What the cloud-cover command did (certified or refused), in words, from its numbers."""
    least = {n: (k["cloud/%s/lower" % n], k["cloud/%s/upper" % n]) for n in COMPETITORS}
    inside = [n for n in COMPETITORS if min(least[n]) >= 0]
    cross = ["%s (least gaps %s above 0, %s below 100)" % (n, fmt(least[n][0]), fmt(least[n][1]))
             for n in COMPETITORS if min(least[n]) < 0]
    comp = ""
    if inside:
        comp += "%s stay within 0–100 here. " % ", ".join(inside)
    if cross:
        comp += "%s cross a bound." % "; ".join(cross)
    if "cloud/ours/lower" not in k:
        return "Our between-lines scheme refused these data (the command above says why). " + comp
    return ("Our between-lines scheme accepts data on the bounds and certifies the curve: least gaps %s above 0 "
            "and %s below 100, exact (the curve reaches a bound where the data sit on it and never crosses it). "
            % (fmt(k["cloud/ours/lower"]), fmt(k["cloud/ours/upper"])) + comp)


def alpha_study():
    """Measurements behind the α guidance: overshoot, least gap, distance to the polyline, kinks."""
    sets = [("rainfall_daily.csv", ["--shape", "positive"], "rainfall ≥ 0"),
            ("drug_concentration.csv", ["--lower", "0,0.05"], "concentration > 0.05"),
            ("growth_above_trend.csv", ["--lower", "1.5,10"], "weight > 1.5 week + 10")]
    alphas = ["0.05", "0.1", "0.2", "0.5", "1", "2", "5", "20"]
    rows = []
    cmds = []
    for name, args, label in sets:
        data = os.path.join(DATA, name)
        x, f, _ = read_xy(data)
        span = float(np.max(f) - np.min(f))
        for a in alphas:
            cmd = [CLI, "fit", data, "--form", FORM, "--slopes", "arithmetic"] + args + ["--alpha", a, "--json"]
            p = run(cmd, ok=(0, 3))
            cmds.append(cmd)
            if p.returncode == 3:
                # infeasible: the large-α limit f_i c² + f_{i+1} s² is flat at the knots and a rising
                # line close to a knot overtakes it; no β >= 0 helps (docs/method.md §5.2)
                k = "alpha/%s/%s" % (name.split("_")[0], a)
                KEYS[k + "/infeasible"] = 1
                rows.append('<tr><td>%s</td><td>%s</td><td colspan="4" class="bad">refused: no β keeps the curve '
                            "above the line (exit status 3): %s</td></tr>" % (
                                label if a == alphas[0] else "", a, html.escape(p.stderr.strip().split(": ", 1)[-1])))
                continue
            js = json.loads(p.stdout)
            ov = js["overshoot"]
            exc = max(ov["max_excursion_above"], ov["max_excursion_below"]) / span
            cmd2 = [CLI, "fit", data, "--form", FORM, "--slopes", "arithmetic"] + args + ["--alpha", a, "--samples", "41"]
            q = run(cmd2)
            cmds.append(cmd2)
            sx, sy = read_cli_xy(q.stdout)
            lin = np.interp(sx, x, f)
            dev = float(np.max(np.abs(sy - lin))) / span
            k = "alpha/%s/%s" % (name.split("_")[0], a)
            KEYS[k + "/excursion"] = exc
            rows.append("<tr><td>%s</td><td>%s</td><td data-key=\"%s/excursion\">%s %%</td><td>%s</td><td>%s %%</td>"
                        "<td>%s</td></tr>" % (label if a == alphas[0] else "", a, k, fmt(100 * exc, 3),
                                              fmt(js["min_gap_lower"], 3), fmt(100 * dev, 3),
                                              "yes" if ov["warning"] else ""))
    # forms at alpha = 1 on the rainfall: the kinks (GC1) and the overshoot
    frows = []
    data = os.path.join(DATA, "rainfall_daily.csv")
    x, f, _ = read_xy(data)
    span = float(np.max(f) - np.min(f))
    for form in ("paper", "c1", "geometric"):
        cmd = [CLI, "fit", data, "--form", form, "--slopes", "arithmetic", "--shape", "positive", "--alpha", "1", "--json"]
        js = json.loads(run(cmd).stdout)
        cmds.append(cmd)
        ov = js["overshoot"]
        # slope jump at the inner knots from the JSON: left slope d_i / a_{i-1}, right d_i / a_i in the
        # paper form (docs/method.md §3); measured for every form by one-sided differences of samples
        # S' just left and right of every inner knot (1e-9 of the interval away: S'' times that is
        # far below the jumps measured), from the tool's own derivative
        at = os.path.join(FILES, "knots_pm.csv")
        with open(at, "w") as fh:
            for i in range(1, len(x) - 1):
                fh.write("%r\n%r\n" % (x[i] - 1e-9 * (x[i] - x[i - 1]), x[i] + 1e-9 * (x[i + 1] - x[i])))
        cmd_d = [CLI, "fit", data, "--form", form, "--slopes", "arithmetic", "--shape", "positive", "--alpha", "1", "--at", at,
                 "--derivative", "1"]
        q = run(cmd_d)
        cmds.append(cmd_d)
        _, sy = read_cli_xy(q.stdout)
        jumps = list(np.abs(sy[1::2] - sy[0::2]))
        KEYS["form/%s/kink" % form] = max(jumps)
        frows.append("<tr><td><code>--form %s</code></td><td data-key=\"form/%s/kink\">%s</td><td>%s %%</td>"
                     "<td>%s</td></tr>" % (form, form, fmt(max(jumps), 3),
                                           fmt(100 * max(ov["max_excursion_above"], ov["max_excursion_below"]) / span, 3),
                                           fmt(js["certified"])))
    shown_cmds = ("<details><summary>the %d commands behind these tables</summary><pre>%s</pre></details>" % (
        len(cmds), "\n".join(html.escape("$ " + shown(c)) for c in cmds)))
    return (shown_cmds + "<table class=\"cmp\"><tr><th>data (bound)</th><th>α</th><th>largest excursion beyond an interval's "
            "data (%% of the data range)</th><th>least certified gap</th><th>largest distance to the straight-line "
            "interpolant (%% of range)</th><th>stderr warning</th></tr>%s</table>" % "".join(rows),
            "<table class=\"cmp\"><tr><th>form (rainfall, positive, α = 1)</th><th>largest slope jump at a knot "
            "(mm/day per day: S′ 10<sup>−9</sup> of an interval either side, <code>--at … --derivative 1</code>)</th><th>largest excursion</th>"
            "<th>certified</th></tr>%s</table>" % "".join(frows))


def recommendation():
    """The default α, from the measurements of alpha_study (not asserted)."""
    at1 = max(v for k, v in KEYS.items() if k.startswith("alpha/") and k.endswith("/1/excursion"))
    ok = sorted(float(a) for a in {k.split("/")[2] for k in KEYS if k.startswith("alpha/")}
                if max(v for k, v in KEYS.items() if k.startswith("alpha/") and k.split("/")[2] == a
                       and k.endswith("/excursion")) <= 0.1)
    text = ("Start with α = 1, the library's default: on these three data sets its largest excursion is "
            "%s %% of the data range" % (fmt(100 * at1, 3)))
    text += (", under the warning threshold of 10 %%; the smallest α measured that stays under it on all three "
             "is %s." % fmt(ok[0]) if ok and at1 <= 0.1 else
             "; above the warning threshold of 10 %, so raise α.")
    return text


def overshoot_section():
    data = os.path.join(DATA, "rainfall_daily.csv")
    out = []
    for a in ("0.1", "1"):
        cmd = [CLI, "fit", data, "--form", FORM, "--slopes", "arithmetic", "--shape", "positive", "--alpha", a, "--json"]
        p = run(cmd)
        js = json.loads(p.stdout)
        ov = js["overshoot"]
        KEYS["overshoot/%s/y_max" % a] = ov["y_max"]
        out.append((a, cmd, p.stderr.strip(), js, ov))
    pre = "\n".join("$ %s\n%s" % (html.escape(shown(c)), ('<span class="err">%s</span>' % html.escape(e)) if e
                                  else "(no warning)") for _, c, e, _, _ in out)
    (a1, _, _, j1, o1), (a2, _, _, j2, o2) = out
    return ('<section id="overshoot"><h2>What “certified” means, and what it does not</h2>'
            "<p>The certificate is about the <b>bounds you state</b>: it proves, interval by interval, the exact "
            "least distance of the curve to each bound. It does <b>not</b> promise the curve stays near the "
            "data. With a small α the rainfall curve is certified non-negative (certified: %s) and still rises "
            'to <b data-key="overshoot/0.1/y_max">%s</b> mm where the largest observation is %s mm. Every report now '
            "gives each interval's exact range and its excursion beyond the interval's own data, and the command "
            "warns on stderr when an excursion exceeds a tenth of the data range (docs/cli.md):</p><pre>%s</pre>"
            '<p>With α = %s the same data give a largest value of <b data-key="overshoot/1/y_max">%s</b> mm '
            "(excursion %s mm). If overshoot matters, read the <code>overshoot</code> object of the JSON report "
            "(or the warning), and raise α.</p></section>" % (
                fmt(j1["certified"]), fmt(o1["y_max"]), fmt(o1["data_max"]), pre, a2, fmt(o2["y_max"]),
                fmt(o2["max_excursion_above"])))


def disaggregate_section():
    """Daily rain to hourly: ours (trigspline disaggregate), PCHIP on the
    cumulative sum, a naive cubic through the daily means; totals, negative
    hours and the rate's smoothness counted the same way for all three."""
    _, mm, _ = read_xy(os.path.join(DATA, "rainfall_daily.csv"))
    n = len(mm)
    src = os.path.join(FILES, "rain_dates.csv")
    with open(src, "w") as fh:
        fh.write("date,rain_mm\n")
        for k, v in enumerate(mm):
            fh.write("%s,%s\n" % (np.datetime64("2021-06-01") + np.timedelta64(k, "D"), repr(float(v))))
    cmd = [CLI, "disaggregate", src, "--step", "1h", "-o", os.path.join(FILES, "rain_hourly.csv")]
    run(cmd)
    ours = np.array([float(r.split(",")[2]) for r in open(os.path.join(FILES, "rain_hourly.csv")).read()
                     .splitlines()[1:]])
    cmd_rate = [CLI, "disaggregate", src, "--step", "1min", "--rate", "-o", os.path.join(FILES, "rain_rate.csv")]
    run(cmd_rate)
    # minutes since the first day; our rate per second -> mm/h
    r_ours = np.array([float(r.split(",")[1]) for r in open(os.path.join(FILES, "rain_rate.csv")).read()
                       .splitlines()[1:]]) * 3600.0
    e = np.arange(n + 1.0) * 24.0                      # hours
    P = PchipInterpolator(e, np.concatenate([[0.0], np.cumsum(mm)]))
    mid = 24.0 * (np.arange(n) + 0.5)
    naive = CubicSpline(mid, mm / 24.0)                # mm/h through the daily means
    hours = np.arange(24 * n + 1.0)
    minutes = np.arange(24 * 60 * n + 1.0) / 60.0
    methods = {
        "trigspline disaggregate": (ours, r_ours),
        "PCHIP on the cumulative sum": (np.diff(P(hours)), P(minutes, 1)),
        "cubic spline through the daily means": (
            np.array([naive.integrate(a, a + 1.0, extrapolate=True) for a in hours[:-1]]),
            naive(minutes, extrapolate=True)),
    }
    rows = []
    fig, ax = plt.subplots(figsize=(10, 3.2))
    lo, hi = 5 * 24 * 60, 21 * 24 * 60
    for name, (cells, rate) in methods.items():
        back = cells.reshape(n, 24).sum(1)
        wet = mm > 0
        err = float(np.max(np.abs(back - mm)[wet] / mm[wet]))
        dry_err = float(np.max(np.abs(back[~wet]))) if (~wet).any() else 0.0
        neg = int(np.sum(cells < 0))
        # one-sided slopes of the rate over one minute either side of each day
        # boundary (mm/h per h): a corner shows as a jump of the slope
        b = 24 * 60 * np.arange(1, n)
        sl = (rate[b] - rate[b - 1]) * 60.0
        sr = (rate[b + 1] - rate[b]) * 60.0
        jump = float(np.max(np.abs(sr - sl)))
        key = name.split()[0]
        rows.append("<tr><td>%s</td>%s%s%s%s</tr>" % (
            html.escape(name), cell("disagg/%s/total_error" % key, err, 2),
            cell("disagg/%s/dry_error" % key, dry_err, 2), cell("disagg/%s/negative" % key, neg, 4),
            cell("disagg/%s/slope_jump" % key, jump, 3)))
        ax.plot(minutes[lo:hi] / 24.0, rate[lo:hi], lw=1.0,
                color={"trigspline": COLORS["ours"], "PCHIP": COLORS["SciPy PCHIP"]}.get(key, "#d62728"),
                label=name)
    ax.axhline(0, color="#999", lw=0.6)
    ax.set_xlabel("day")
    ax.set_ylabel("rain rate (mm/h)")
    ax.legend(fontsize=8)
    svg = figure_svg(fig)
    table = ("<table class=\"cmp\"><tr><th>method</th><th>largest total error (wet days, relative)</th>"
             "<th>largest total on a dry day (mm)</th><th>negative hours</th>"
             "<th>largest jump of the rate's slope at a day boundary (mm/h²)</th></tr>%s</table>"
             % "".join(rows))
    return ('<section id="disaggregate"><h2>Daily rain to hourly: totals kept, never negative, smooth</h2>'
            "<p>Turning daily totals into an hourly rate needs three things at once: every day's hours add up to "
            "the day's total, no hour is negative, and the rate is smooth (no corner at midnight). PCHIP on the "
            "cumulative sum keeps the first two but its rate has a corner at every day boundary; a cubic spline "
            "through the daily means is smooth but keeps neither totals nor signs. "
            "<code>trigspline disaggregate</code> keeps all three (docs/method.md §12; the rate is C¹, and C² "
            "where the bounds allow):</p><pre>$ %s\n$ %s</pre><div class=\"svg\">%s</div>%s"
            '<p class="small">Slopes are one-sided differences over one minute of each method\'s rate, sampled '
            "every minute (ours from the second command, per second, shown per hour); totals are the 24 hourly "
            "cells of each day.</p></section>" % (html.escape(shown(cmd)), html.escape(shown(cmd_rate)), svg, table))


# the option-chain example: Black–Scholes call prices, closed form (docs: Hull, ch. 15)
BS = {"S": 100.0, "r": 0.02, "sigma": 0.2, "T": 0.1}
BS_STRIKES = np.arange(80.0, 121.0, 5.0)
# the floor example: a reporting limit 0.2 up to hour 3, raised linearly to 1.0 by hour 5
FLOOR = [(0.0, 0.2), (3.0, 0.2), (5.0, 1.0), (10.0, 1.0)]
FLOOR_DATA = [(0, 2.0), (1, 1.2), (2, 0.5), (3, 0.25), (4, 0.65), (5, 1.05), (6, 2.4), (7, 1.6), (8, 1.08),
              (9, 1.3), (10, 1.9)]


def bs_call(k):
    S, r, s, T = BS["S"], BS["r"], BS["sigma"], BS["T"]
    d1 = (np.log(S / k) + (r + s * s / 2) * T) / (s * np.sqrt(T))
    d2 = d1 - s * np.sqrt(T)
    N = np.vectorize(lambda z: 0.5 * (1.0 + math.erf(z / math.sqrt(2.0))))
    return S * N(d1) - k * np.exp(-r * T) * N(d2)


def bs_density(k):
    """d²C/dK² = e^{-rT} q(K), q the risk-neutral (lognormal) density of the price at T."""
    S, r, s, T = BS["S"], BS["r"], BS["sigma"], BS["T"]
    d2 = (np.log(S / k) + (r - s * s / 2) * T) / (s * np.sqrt(T))
    return np.exp(-r * T) * np.exp(-d2 * d2 / 2) / (np.sqrt(2 * np.pi) * k * s * np.sqrt(T))


def cubic_d2_min(pp):
    """Exact least S'' of a piecewise cubic (S'' linear per piece: its ends) and where."""
    h = np.diff(pp.x)
    left, right = 2 * pp.c[1], 6 * pp.c[0] * h + 2 * pp.c[1]
    ends = np.concatenate([left, right])
    at = np.concatenate([pp.x[:-1], pp.x[1:]])
    i = int(np.argmin(ends))
    return float(ends[i]), float(at[i])


def write_xy(path, header, xs, ys):
    with open(path, "w") as fh:
        fh.write(header + "\n" + "".join("%r,%r\n" % (float(a), float(b)) for a, b in zip(xs, ys)))


def constraint_section():
    """Shape constraints (docs/method.md §13): a convex, decreasing option chain
    and data above a polyline floor; ours certified, SciPy's measured."""
    # ---- (1) call prices in strike: convex and decreasing
    K, C = BS_STRIKES, bs_call(BS_STRIKES)
    src = os.path.join(FILES, "option_calls.csv")
    write_xy(src, "strike,call", K, C)
    args = ["--form", "geometric", "--constraint", "convex", "--constraint", "decreasing"]
    cmd = [CLI, "fit", src] + args + ["--json", "-o", os.path.join(FILES, "option_calls.json")]
    cmd_d2 = [CLI, "fit", src] + args + ["--derivative", "2", "--samples", str(PLOT_M),
                                         "-o", os.path.join(FILES, "option_calls_d2.csv")]
    run(cmd)
    run(cmd_d2)
    with open(os.path.join(FILES, "option_calls.json")) as fh:
        js = json.load(fh)
    conv, decr = js["constraints"]
    i = int(np.argmin([iv["gap"] for iv in conv]))
    ours_min, ours_at = conv[i]["gap"], conv[i]["at"]
    ours_cert = js["certified"] and all(iv["certified"] for iv in conv + decr)
    xo, d2o = read_csv_samples(os.path.join(FILES, "option_calls_d2.csv"))
    fits = {"SciPy CubicSpline": CubicSpline(K, C), "SciPy PCHIP": PchipInterpolator(K, C)}
    rows = ['<tr><td>trigspline (exact certificate; certified: <b>%s</b>)</td>%s%s</tr>' % (
        fmt(ours_cert), cell("convex/ours/d2_min", ours_min), cell("convex/ours/d2_at", ours_at))]
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(9.5, 3.6))
    kg = dense_grid(K, PLOT_M)
    for name, pp in fits.items():
        m, at = cubic_d2_min(pp)
        rows.append("<tr><td>%s</td>%s%s</tr>" % (html.escape(name), cell("convex/%s/d2_min" % name, m).replace(
            "<td", '<td class="bad"' if m < 0 else "<td", 1), cell("convex/%s/d2_at" % name, at)))
        bx.plot(kg, pp(kg, 2), color=COLORS[name], lw=1.0, label=name)
        ax.plot(kg, pp(kg), color=COLORS[name], lw=1.0, label=name)
    ax.plot(K, C, "o", color="k", ms=3.5, label="data", zorder=5)
    ax.set_xlabel("strike")
    ax.set_ylabel("call price")
    ax.legend(fontsize=7.5, frameon=False)
    ax.grid(alpha=0.25)
    bx.plot(xo, d2o, color=COLORS["ours"], lw=2.2, label="trigspline (ours)")
    kk = np.linspace(K[0], K[-1], 400)
    bx.plot(kk, bs_density(kk), color="k", lw=1, ls=":", label="closed form e^(−rT) q(K)")
    bx.axhline(0, color="k", lw=1, ls="--")
    lo = min(np.min(d2o), min(np.min(pp(kg, 2)) for pp in fits.values()))
    bx.axhspan(min(lo, 0) * 10 - 1, 0, color="#f4cccc", alpha=0.5, lw=0)
    bx.set_ylim(min(lo, 0) * 1.3 - 0.002, None)
    bx.set_xlabel("strike")
    bx.set_ylabel("S″ (implied density; below 0 = arbitrage)")
    bx.legend(fontsize=7.5, frameon=False)
    bx.grid(alpha=0.25)
    svg1 = figure_svg(fig)
    neg = [n for n in fits if KEYS["convex/%s/d2_min" % n] < 0]
    verdict1 = ("%s: a negative implied density, a price curve that admits a butterfly arbitrage. " % "; ".join(
        "%s's S″ goes down to %s (at strike %s)" % (n, fmt(KEYS["convex/%s/d2_min" % n]),
                                                    fmt(KEYS["convex/%s/d2_at" % n])) for n in neg)
                if neg else "On these prices SciPy's curves stay convex too. ")
    verdict1 += ("Ours: least S″ %s (exact, at strike %s), convex and decreasing certified on every interval."
                 % (fmt(ours_min), fmt(ours_at)) if ours_cert else "Ours is not certified here (see the command).")

    # ---- (2) data above a piecewise-linear floor
    fx, fy = np.array(FLOOR).T
    x, f = np.array(FLOOR_DATA, float).T
    src2 = os.path.join(FILES, "above_floor.csv")
    write_xy(src2, "hour,level", x, f)
    spec = "lower=poly:" + ";".join("%g,%g" % p for p in FLOOR)
    args2 = ["--form", "geometric", "--constraint", spec]
    cmd2 = [CLI, "fit", src2] + args2 + ["--json", "-o", os.path.join(FILES, "above_floor.json")]
    cmd2_csv = [CLI, "fit", src2] + args2 + ["--samples", str(PLOT_M),
                                             "-o", os.path.join(FILES, "above_floor_samples.csv")]
    run(cmd2)
    run(cmd2_csv)
    with open(os.path.join(FILES, "above_floor.json")) as fh:
        js2 = json.load(fh)
    (rec,) = js2["constraints"]
    our_gap = min(iv["gap"] for iv in rec if iv["gap"] is not None)
    our_cert2 = js2["certified"] and all(iv["certified"] for iv in rec if iv["gap"] is not None)
    xs, ys = read_csv_samples(os.path.join(FILES, "above_floor_samples.csv"))
    grid = dense_grid(x, DENSE)
    rows2 = ['<tr><td>trigspline (exact certificate; certified: <b>%s</b>)</td>%s<td>0</td></tr>' % (
        fmt(our_cert2), cell("polyfloor/ours/lower", our_gap))]
    fig, (ax2, bx2) = plt.subplots(2, 1, figsize=(9.5, 5.6), height_ratios=[3, 2], sharex=True)
    pg = dense_grid(x, PLOT_M)
    worst = 0.0
    for name, M in (("SciPy CubicSpline", CubicSpline), ("SciPy PCHIP", PchipInterpolator)):
        g = M(x, f)(grid) - np.interp(grid, fx, fy)
        least, nviol, bad = violations(x, grid, g)
        worst = min(worst, least)
        rows2.append("<tr><td>%s</td>%s<td%s>%d</td></tr>" % (
            html.escape(name), cell("polyfloor/%s/lower" % name, least).replace(
                "<td", '<td class="bad"' if least < 0 else "<td", 1), ' class="bad"' if nviol else "", nviol))
        ax2.plot(pg, M(x, f)(pg), color=COLORS[name], lw=1.0, label=name)
        for w in bad:
            ax2.plot(grid[w], M(x, f)(grid[w]), "x", color=COLORS[name], ms=8, mew=2)
        bx2.plot(pg, M(x, f)(pg) - np.interp(pg, fx, fy), color=COLORS[name], lw=1.0)
    ax2.plot(xs, ys, color=COLORS["ours"], lw=2.2, label="trigspline (ours)")
    bx2.plot(xs, ys - np.interp(xs, fx, fy), color=COLORS["ours"], lw=2.2)
    ax2.plot(fx, fy, color="k", lw=1, ls="--")
    ax2.fill_between(fx, fy, -10, color="#f4cccc", alpha=0.5, lw=0)
    ax2.plot(x, f, "o", color="k", ms=3.5, label="data", zorder=5)
    ax2.set_ylim(0, np.max(f) * 1.15)
    ax2.set_ylabel("level")
    ax2.legend(fontsize=7.5, ncol=4, loc="upper left", frameon=False)
    ax2.grid(alpha=0.25)
    zoom = max(abs(worst) * 3, 0.05)
    bx2.axhline(0, color="k", lw=1, ls="--")
    bx2.axhspan(-10 * zoom, 0, color="#f4cccc", alpha=0.5, lw=0)
    bx2.set_ylim(-zoom, zoom)
    bx2.set_ylabel("gap to the floor\n(zoomed; below 0 = violation)")
    bx2.set_xlabel("hour")
    svg2 = figure_svg(fig)
    below = [n for n in ("SciPy CubicSpline", "SciPy PCHIP") if KEYS["polyfloor/%s/lower" % n] < 0]
    verdict2 = ("%s dip%s below the floor between knots (by %s), although every data point is above it. "
                % (" and ".join(below), "s" if len(below) == 1 else "",
                   " and ".join(fmt(-KEYS["polyfloor/%s/lower" % n]) for n in below))
                if below else "Here SciPy's curves stay above the floor too. ")
    verdict2 += ("Ours is certified above it on every interval, least gap %s." % fmt(our_gap) if our_cert2
                 else "Ours is not certified here (see the command).")
    cmds = lambda *cs: "\n".join(html.escape("$ " + shown(c)) for c in cs)  # noqa: E731
    return ('<section id="constraints"><h2>Shape constraints: a convex option chain, a floor that changes</h2>'
            "<p><b>Convex and decreasing.</b> Call prices fall and are convex in the strike; S″ (the second "
            "derivative in the strike) is the discounted risk-neutral density, so a negative S″ anywhere is an "
            "arbitrage. The data: Black–Scholes prices at strikes %s–%s (step 5), spot %s, rate %s, volatility "
            "%s, %s years to expiry, from the closed form. <code>--constraint convex --constraint decreasing"
            "</code> (docs/method.md §13) certifies S″ ≥ 0 and S′ ≤ 0 on every interval, exactly:</p>"
            "<pre>%s</pre><div class=\"svg\">%s</div>"
            '<table class="cmp"><tr><th>method</th><th>least S″ (implied density)</th><th>at strike</th></tr>'
            "%s</table><p class=\"verdict\">%s</p>"
            "<p><b>Above a piecewise-linear floor.</b> A level reported against a limit that changes: 0.2 up to "
            "hour 3, raised linearly to 1.0 by hour 5 (a less sensitive method phased in), every observation "
            "above it. <code>--constraint 'lower=poly:X,Y;...'</code> takes the floor as a polyline:</p>"
            "<pre>%s</pre><div class=\"svg\">%s</div>"
            '<table class="cmp"><tr><th>method</th><th>least gap to the floor</th><th>intervals below it</th></tr>'
            "%s</table><p class=\"verdict\">%s</p>"
            '<p class="small">SciPy\'s least S″ is exact (S″ of a cubic is linear on each interval: the least '
            "of its ends); their least gaps to the floor are minima over %d samples per interval. Ours are the "
            "JSON report's <code>constraints</code> records (the exact minimum per interval).</p></section>" % (
                fmt(K[0]), fmt(K[-1]), fmt(BS["S"]), fmt(BS["r"]), fmt(BS["sigma"]), fmt(BS["T"]),
                cmds(cmd, cmd_d2), svg1, "".join(rows), verdict1,
                cmds(cmd2, cmd2_csv), svg2, "".join(rows2), verdict2, DENSE))


def surface_note():
    """One sentence on gridded fields, from what `trigspline surface` does with the example field."""
    data = os.path.join(REPO, "data", "surface", "cloud_percent_long.csv")
    cmd = [CLI, "surface", data, "--shape", "bounds", "--lower", "0", "--upper", "100", "--json"]
    p = subprocess.run(cmd, capture_output=True, text=True)
    head = "Gridded fields (surfaces) are not compared on this page; "
    if p.returncode != 0:
        return head + "<code>%s</code> exits with status %d: %s" % (
            html.escape(shown(cmd)), p.returncode, html.escape(p.stderr.strip()))
    js = json.loads(p.stdout)
    return head + ("<code>%s</code> fits a %d × %d percentage field kept within 0–100 and certifies it patch by "
                   "patch (certified: <b>%s</b>; docs/method.md §11)." % (
                       html.escape(shown(cmd)), js["nx_points"], js["ny_points"], fmt(js["certified"])))


def main():
    for exe in (CLI, GSL):
        if not os.access(exe, os.X_OK):
            sys.exit("why_demo: %s not built (GSL's development files are needed for gsl_eval)" % exe)
    os.makedirs(FILES, exist_ok=True)

    function_panel(
        "rainfall", "Daily rainfall with many zeros (must stay ≥ 0)",
        "Forty days of rain-gauge totals, more than half of them zero. An interpolant that dips below zero "
        "between a storm and a dry day invents negative rain.",
        lambda k: ("Here PCHIP and GSL steffen are as good as we are: both stay ≥ 0 (least gaps %s and %s: they "
                   "touch 0 exactly on dry spells), as any interpolant that never leaves the range of "
                   "neighbouring data does. SciPy's CubicSpline dips to %s mm and Akima to %s mm. What we add on "
                   "plain non-negative data is the per-interval proof (the certificate) and the overshoot report."
                   % (fmt(k["rainfall/SciPy PCHIP/lower"]), fmt(k["rainfall/GSL steffen/lower"]),
                      fmt(k["rainfall/SciPy CubicSpline/lower"]), fmt(k["rainfall/SciPy Akima/lower"]))),
        "rainfall_daily.csv", lambda t: 0 * t, None, ["--shape", "positive", "--alpha", "1"], "rain (mm/day)")

    function_panel(
        "drug", "Drug concentration decaying towards the assay's floor (must stay above 0.05 mg/L)",
        "Plasma concentration after one dose, sampled on a sparse clinical schedule; the late values sit just "
        "above the detection floor 0.05 mg/L, and a curve below the floor is meaningless.",
        lambda k: ("A constant floor is still the easy case for PCHIP (least gap %s) and steffen (%s): they stay "
                   "within each interval's data. CubicSpline reaches %s below the floor, Akima %s. Ours: least gap "
                   "%s, certified." % (fmt(k["drug/SciPy PCHIP/lower"]), fmt(k["drug/GSL steffen/lower"]),
                                       fmt(-k["drug/SciPy CubicSpline/lower"]), fmt(-k["drug/SciPy Akima/lower"]),
                                       fmt(k["drug/ours/lower"]))),
        "drug_concentration.csv", lambda t: 0.05 + 0 * t, None, ["--lower", "0,0.05", "--alpha", "1"], "mg/L")

    function_panel(
        "cloud", "A percentage that reaches 0 and 100",
        "Cloud cover is exactly 0 % on a clear sky and 100 % overcast, and the record has both: the curve must "
        "stay within 0–100 between the observations too, touching the bounds only where the data do.",
        cloud_verdict, "cloud_cover.csv", lambda t: 0 * t, lambda t: 100 + 0 * t,
        ["--lower", "0,0", "--upper", "0,100", "--alpha", "1"], "cloud cover (%)")

    function_panel(
        "growth", "Growth that must stay above a rising reference line",
        "Weekly weights of an animal that grows in spurts and must stay above the welfare line weight = 1.5 week "
        "+ 10, which rises with age. Between a stall and a spurt the data come within 0.15 kg of the line.",
        lambda k: ("A sloped bound is where the alternatives fail: every one of them crosses the line (PCHIP by "
                   "%s kg, steffen by %s, CubicSpline by %s, Akima by %s). Staying inside the range of the data is "
                   "no help when the bound itself rises. Ours keeps a certified least gap of %s kg." % (
                       fmt(-k["growth/SciPy PCHIP/lower"]), fmt(-k["growth/GSL steffen/lower"]),
                       fmt(-k["growth/SciPy CubicSpline/lower"]), fmt(-k["growth/SciPy Akima/lower"]),
                       fmt(k["growth/ours/lower"]))),
        "growth_above_trend.csv", lambda t: 1.5 * t + 10, None, ["--lower", "1.5,10", "--alpha", "1"], "kg")

    curve_panel()
    over = overshoot_section() + disaggregate_section() + constraint_section()
    alpha_table, form_table = alpha_study()

    # summary: one row per data set and method (the worst side)
    order = []
    best = {}
    for ds, meth, side, least, nv in SUMMARY:
        k = (ds, meth)
        if k not in best:
            order.append(k)
            best[k] = (least, nv)
        else:
            best[k] = (min(best[k][0], least), best[k][1] + max(nv, 0))
    datasets = []
    for ds, _ in order:
        if ds not in datasets:
            datasets.append(ds)
    methods = ["trigspline"] + COMPETITORS
    srows = []
    for ds in datasets:
        r = "<tr><td>%s</td>" % html.escape(ds)
        for m in methods:
            if (ds, m) not in best:
                r += "<td>%s</td>" % ("refused (see its section)" if m == "trigspline" else "–")
                continue
            least, nv = best[(ds, m)]
            cls = ' class="bad"' if least < 0 else ' class="good"' if m == "trigspline" else ""
            r += "<td%s>%s%s</td>" % (cls, fmt(least, 3), " (%d)" % nv if nv > 0 else "")
        srows.append(r + "</tr>")
    summary = ("<table class=\"cmp\"><tr><th>data set</th>%s</tr>%s</table>" % (
        "".join("<th>%s</th>" % m for m in methods), "".join(srows)))

    page = PAGE % {
        "css": CSS, "summary": summary, "sections": "\n".join(SECTIONS), "overshoot": over,
        "alpha_table": alpha_table, "form_table": form_table, "form": FORM, "dense": DENSE,
        "recommend": recommendation(), "surface": surface_note()}
    dst = os.path.join(OUT, "index.html")
    tmp = dst + ".tmp"
    with open(tmp, "w", encoding="utf-8") as fh:
        fh.write(page)
    os.replace(tmp, dst)
    with open(os.path.join(OUT, "numbers.json"), "w") as fh:
        json.dump(KEYS, fh, indent=0, sort_keys=True)
    print(os.path.abspath(dst))


CSS = """
body{font-family:system-ui,sans-serif;max-width:1100px;margin:1em auto;padding:0 1em;color:#222;line-height:1.45}
h1{font-size:1.6em} h2{border-bottom:2px solid #ccc;padding-bottom:.2em;margin-top:2em}
pre{background:#f0f0f0;padding:.4em .6em;white-space:pre-wrap;word-break:break-all;font-size:.8em}
.err{color:#900}
table.cmp{border-collapse:collapse;font-size:.85em;margin:.6em 0}
table.cmp td,table.cmp th{border:1px solid #ccc;padding:2px 6px;text-align:right}
table.cmp td:first-child{text-align:left}
td.bad{background:#fcc;font-weight:bold} td.good{background:#dfd} tr.ours td{background:#eef8ee}
.verdict{background:#eef3ff;border-left:4px solid #3060c0;padding:.4em .6em}
.small{color:#666;font-size:.85em}
.svg svg{max-width:100%;height:auto}
"""

PAGE = """<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>Why trigspline</title>
<style>%(css)s</style></head><body>
<h1>Why trigspline? Your kind of data, the alternatives, and what we guarantee</h1>
<p>You have measurements that must respect a bound: rain is never negative, a concentration never drops
below the assay's floor, a percentage stays within 0–100, a weight stays above a reference line, an
outline stays inside its property. An interpolating curve through your points can break such a bound between
the points even though every point respects it. This page puts trigspline beside the interpolants you probably
use already — SciPy's <code>CubicSpline</code>, <code>PchipInterpolator</code> and
<code>Akima1DInterpolator</code>, GSL's <code>cspline</code> and <code>steffen</code> — on five data sets of
that kind, and says plainly where the alternatives are just as good.</p>
<p><b>In short.</b> On plain non-negative data (and any constant floor or ceiling) PCHIP and GSL steffen stay
inside too, because they never leave the range of neighbouring data: use them if that is all you need.
What only trigspline gives: bounds that are <b>sloped lines</b> (above a trend, below a capacity that grows),
<b>a band between two sloped lines</b> (the paper page, Figure 7), <b>smooth closed curves kept inside a
box</b>, and for every curve an <b>exact certificate</b>
— the least distance to each bound on every interval, from the critical points of the curve, not from samples.</p>
<p class="small">Every number and plot below was computed when this page was made (<code>make demo</code>,
scripts/why_demo.py). Our curves come from the <code>trigspline</code> commands shown in full, always with
<code>--form %(form)s</code> stated; the competitors' least gaps are minima over %(dense)d samples per interval.
The paper's reproduction is on <a href="../paper/index.html">the other page</a>. %(surface)s</p>
<h2>Summary: least gap to the bound (negative = the curve breaks it; in brackets: intervals that do)</h2>
%(summary)s
%(sections)s
%(overshoot)s
<section id="alpha"><h2>Choosing α and the form</h2>
<p><b>What α does.</b> On each interval the curve's tension is a = α + β: α is yours, β is added by the
shape scheme, just enough to keep the bound (docs/method.md §5). <b>Small α</b>: the curve follows the slopes at
the data freely and can bulge far beyond the data between points (the bound is still kept, β grows where it
must) — the overshoot of the section above. <b>Large α</b>: in the paper and C¹ forms each interval tends to
f<sub>i</sub> cos²θ + f<sub>i+1</sub> sin²θ, a smooth step between its two values that is flat at both knots:
no overshoot at all, but a staircase look, and near a rising bound a flat step can cut under it — so a large α
can make a sloped bound infeasible (the refusal below). In the geometric form large α tends to the straight
polyline instead (docs/method.md §4). The measurements, paper form:</p>
%(alpha_table)s
<p><b>Forms.</b> <code>--form paper</code> (the paper's construction) has a jump of slope at a knot wherever
neighbouring intervals have different a (the shape schemes make them differ); <code>--form c1</code> removes the
jumps and keeps every guarantee; <code>--form geometric</code> has the slope d<sub>i</sub> at each knot from both sides too, with the curve
written as a parametric (x(θ), y(θ)) segment (docs/method.md §4). On the rainfall:</p>
%(form_table)s
<p><b>Recommendation.</b> %(recommend)s If the warning or the report's <code>overshoot</code> says the
curve bulges, raise α (2–5); if it looks like a staircase (flat at every data point), lower it towards 0.5.
Use <code>--form c1</code> when you need a continuous slope (rates, derivatives) — it keeps every guarantee —
<code>--form geometric</code> for outlines and for a curve that tends to the polyline, and the paper form to
reproduce the paper.</p></section>
<p style="margin-top:3em;color:#777">Generated by scripts/why_demo.py.</p>
</body></html>
"""

if __name__ == "__main__":
    main()
