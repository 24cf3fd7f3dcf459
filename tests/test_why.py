#!/usr/bin/env python3
"""The "why trigspline" page of `make demo` (scripts/why_demo.py): built into a
temporary directory with BUILD_DIR's trigspline and gsl_eval, then checked.

Usage: python3 tests/test_why.py BUILD_DIR
(re-runs itself under /usr/bin/python3 when the interpreter lacks numpy/scipy:
they come from Debian, `make test` installs them through `make why-deps`).

Numbers the page states are re-derived here independently and compared with
the value printed in the cell (data-key attribute; 4 significant digits, so
a relative tolerance of 5e-4 for the printing, plus the page's sampling error):
  - SciPy CubicSpline's least value on the rainfall, exactly: min over the knots
    and the real roots of its derivative in each interval (the page samples
    2000 points per interval; the sampling error is below 1/2 max|y''| (h/4000)^2,
    < 1e-5 here);
  - GSL cspline on the growth data re-derived as SciPy's natural cubic spline
    (GSL's cspline is the natural spline: the same function), its least gap
    to the line 1.5 t + 10 by 20000 samples per interval;
  - PCHIP's least gap to that line, 20000 samples per interval;
  - SciPy's periodic CubicSpline outline: least distance to the box;
  - our certificates (exact) against dense samples of our own curve from the
    CLI (the sampled least gap is >= the exact one minus rounding, and within
    the sampling bound of it);
  - the shape-constraint section: the option chain's prices from the stated
    Black–Scholes parameters, SciPy's least S'' (negative) and least gap to
    the polyline floor, our commands' exit status and certificates;
  - the overshoot example's y_max against the largest of 2000 samples per
    interval of that curve.
Also: every command shown names --form, no command is abbreviated, every
plot is an SVG that xml.etree accepts, the paper page is linked.
Prints "test_why: N passed, M failed" last.
"""
import os
import subprocess
import sys

try:
    import numpy as np
    from scipy.interpolate import CubicSpline, PchipInterpolator
except ImportError:
    if sys.executable != "/usr/bin/python3" and os.path.exists("/usr/bin/python3"):
        os.execv("/usr/bin/python3", ["/usr/bin/python3"] + sys.argv)
    print("test_why: numpy/scipy missing for %s (make why-deps installs them)" % sys.executable)
    print("test_why: 0 passed, 1 failed")
    sys.exit(1)
import html
import io
import json
import re
import shlex
import tempfile
import xml.etree.ElementTree as ET

BUILD = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else "build")
REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DATA = os.path.join(REPO, "data", "examples")
CLI = os.path.join(BUILD, "trigspline")
passed = failed = 0


def cli_xy(text):
    """Samples the command wrote: x and y by position (the header carries the
    input's column names)."""
    d = np.loadtxt(io.StringIO(text), delimiter=",", skiprows=1, ndmin=2)
    return {"x": d[:, 0], "y": d[:, 1]}


def check(cond, what):
    global passed, failed
    if cond:
        passed += 1
    else:
        failed += 1
        print("FAIL:", what)


def read_xy(name):
    with open(os.path.join(DATA, name)) as fh:
        lines = [ln.strip() for ln in fh if ln.strip() and not ln.lstrip().startswith("#")]
    rows = np.array([[float(v) for v in ln.split(",")] for ln in lines[1:]])
    return rows[:, 0], rows[:, 1]


def cell_values(page):
    """data-key -> the number printed in that element."""
    out = {}
    for m in re.finditer(r'<(td|b)[^>]*data-key="([^"]+)"[^>]*>([^<]*)<', page):
        txt = m.group(3).replace("−", "-").strip()
        try:
            out[html.unescape(m.group(2))] = float(txt)
        except ValueError:
            pass
    return out


def close(printed, exact, extra=0.0):
    return abs(printed - exact) <= 5e-4 * abs(exact) + extra + 1e-12


def dense(x, m):
    return np.concatenate([x[i] + (x[i + 1] - x[i]) * np.arange(m) / m for i in range(len(x) - 1)]
                          + [x[-1:]])


def check_claims(page):
    """Every section that shows `trigspline fit` commands says what they do:
    it speaks of a refusal exactly when one of them exits non-zero (with that
    exit status shown), and when all succeed its data set has a number, not a
    refusal, in the summary table.  The commands are re-run here (from the
    repository, as shown; the page's output directory still exists)."""
    summary = page[:page.index("<section")]
    for m in re.finditer(r'<section id="([^"]+)"><h2>(.*?)</h2>(.*?)</section>', page, re.S):
        key, title, body = m.group(1), html.unescape(m.group(2)), m.group(3)
        pre = re.search(r"<pre>(.*?)</pre>", body, re.S)
        if not pre:
            continue
        cmds = [html.unescape(c) for c in re.findall(r"^\$ (build/trigspline fit [^\n<]*)", pre.group(1), re.M)]
        if not cmds:
            continue
        status = [subprocess.run([CLI] + shlex.split(c)[1:], cwd=REPO, capture_output=True).returncode
                  for c in cmds]
        text = re.sub(r"<[^>]+>", " ", re.sub(r'<div class="svg">.*?</div>', "", body, flags=re.S))
        refused = any(status)
        check(refused == bool(re.search(r"refus", text, re.I)),
              "%s: the section speaks of a refusal exactly when a command exits non-zero (exits %s)" % (key, status))
        for st in status:
            check(st == 0 or "(exit status %d)" % st in body, "%s: exit status %d shown" % (key, st))
        if 'class="ours"' not in body:  # not a comparison with the alternatives
            continue
        row = re.search(r"<tr><td>%s</td>(.*?)</tr>" % re.escape(html.escape(title)), summary)
        check(row is not None, "%s: a summary row" % key)
        if row and not refused:
            first = re.search(r"<td[^>]*>([^<]*)</td>", row.group(1)).group(1)
            check(re.fullmatch(r"[−\d.e+]+( \(\d+\))?", first) is not None,
                  "%s: the summary states our least gap, not %r" % (key, first))


def section_commands(page, sid):
    """The `trigspline fit` commands of section sid, as argument lists (from the repository)."""
    body = re.search(r'<section id="%s">(.*?)</section>' % sid, page, re.S).group(1)
    cmds = [shlex.split(html.unescape(c))
            for c in re.findall(r"(?:^|<pre>)\$ (build/trigspline fit [^\n<]*)", body, re.M)]
    return body, cmds


def without_output(args):
    """args without -o FILE, as a list for CLI (stdout instead)."""
    out = []
    skip = False
    for a in args[1:]:
        if skip:
            skip = False
        elif a == "-o":
            skip = True
        else:
            out.append(a)
    return [CLI] + out


def check_constraints(page, vals):
    """The shape-constraint section (docs/method.md §13), run while its data
    files exist: the option chain re-derived from the parameters the page
    states (SciPy's normal cdf, not the script's erf), our commands re-run."""
    from scipy.stats import norm
    body, cmds = section_commands(page, "constraints")
    check(len(cmds) == 4, "constraints: four commands shown (%d)" % len(cmds))
    if len(cmds) != 4:
        return
    # ---- the option chain: prices from the stated parameters
    par = re.search(r"strikes (\d+)–(\d+) \(step (\d+)\), spot ([\d.]+), rate ([\d.]+), volatility ([\d.]+), "
                    r"([\d.]+) years", body)
    check(par is not None, "constraints: the Black–Scholes parameters are stated")
    if par is None:
        return
    k0, k1, dk, S, r, sig, T = (float(v) for v in par.groups())
    K = np.arange(k0, k1 + dk / 2, dk)
    d1 = (np.log(S / K) + (r + sig * sig / 2) * T) / (sig * np.sqrt(T))
    C = S * norm.cdf(d1) - K * np.exp(-r * T) * norm.cdf(d1 - sig * np.sqrt(T))
    data = cmds[0][2]
    x, f = cli_xy(open(os.path.join(REPO, data)).read()).values()
    # the data the command read are the closed form (printed shortest round-trip by the script;
    # two cdf implementations differ by a few ulps of the price: 1e-12 relative)
    check(len(x) == len(K) and np.allclose(x, K, rtol=0, atol=0) and np.allclose(f, C, rtol=1e-12, atol=1e-12),
          "constraints: the option data are the Black–Scholes prices stated")
    q = subprocess.run(without_output(cmds[0]), cwd=REPO, capture_output=True, text=True)
    check(q.returncode == 0, "convex: our command exits 0 (%d: %s)" % (q.returncode, q.stderr))
    if q.returncode == 0:
        js = json.loads(q.stdout)
        recs = js["constraints"]
        check(js["certified"] and all(iv["certified"] for rec in recs for iv in rec),
              "convex: our command reports every interval certified")
        exact = min(iv["gap"] for iv in recs[0])
        check(exact >= 0, "convex: our least S'' >= 0 (%r)" % exact)
        check(close(vals["convex/ours/d2_min"], exact), "convex: page states our certificate")
        # our S'' sampled: never below the exact least value (up to rounding) and near it
        d = cli_xy(subprocess.run(without_output(cmds[1])[:-2] + ["--samples", "2001"], cwd=REPO,
                                  capture_output=True, text=True).stdout)
        s2 = float(np.min(d["y"]))
        check(s2 >= exact * (1 - 5e-4) - 1e-12, "convex: sampled S'' %r below the certificate %r" % (s2, exact))
    for name, M in (("SciPy CubicSpline", CubicSpline), ("SciPy PCHIP", PchipInterpolator)):
        # S'' is linear on each piece: ends of every piece, 1e-9 of the interval inside
        # (the error is |S'''| 1e-9 h, < 1e-9 here)
        sp = M(K, C)
        h = np.diff(K)
        ends = np.concatenate([sp(K[:-1] + 1e-9 * h, 2), sp(K[1:] - 1e-9 * h, 2)])
        m = float(np.min(ends))
        check(m < 0, "convex: %s's S'' goes negative (%r)" % (name, m))
        check(close(vals.get("convex/%s/d2_min" % name, 1e300), m, 1e-8),
              "convex: %s least S'': page %r, re-derived %r" % (name, vals.get("convex/%s/d2_min" % name), m))
    # ---- above a polyline floor
    spec = [a for a in cmds[2] if a.startswith("lower=poly:")]
    check(len(spec) == 1, "floor: the polyline is on the command")
    if len(spec) != 1:
        return
    fx, fy = np.array([[float(v) for v in p.split(",")] for p in spec[0][len("lower=poly:"):].split(";")]).T
    x, f = cli_xy(open(os.path.join(REPO, cmds[2][2])).read()).values()
    check(np.all(f > np.interp(x, fx, fy)), "floor: every data point above the floor")
    q = subprocess.run(without_output(cmds[2]), cwd=REPO, capture_output=True, text=True)
    check(q.returncode == 0, "floor: our command exits 0 (%d: %s)" % (q.returncode, q.stderr))
    if q.returncode == 0:
        js = json.loads(q.stdout)
        (rec,) = js["constraints"]
        check(js["certified"] and all(iv["certified"] for iv in rec if iv["gap"] is not None),
              "floor: our command reports certified")
        exact = min(iv["gap"] for iv in rec if iv["gap"] is not None)
        check(exact > 0 and close(vals["polyfloor/ours/lower"], exact), "floor: page states our certificate")
        d = cli_xy(subprocess.run(without_output(cmds[3])[:-2] + ["--samples", "2001"], cwd=REPO,
                                  capture_output=True, text=True).stdout)
        s = float(np.min(d["y"] - np.interp(d["x"], fx, fy)))
        check(s >= exact * (1 - 5e-4) - 1e-12, "floor: sampled gap %r below the certificate %r" % (s, exact))
    xs = dense(x, 20000)
    for name, M in (("SciPy CubicSpline", CubicSpline), ("SciPy PCHIP", PchipInterpolator)):
        g = float(np.min(M(x, f)(xs) - np.interp(xs, fx, fy)))
        check(g < 0, "floor: %s dips below the floor (%r)" % (name, g))
        # the page samples 2000 per interval: within 1/2 max|S''| (h/4000)^2 < 1e-5 of this
        check(close(vals.get("polyfloor/%s/lower" % name, 1e300), g, 1e-5),
              "floor: %s least gap: page %r, re-derived %r" % (name, vals.get("polyfloor/%s/lower" % name), g))


def main():
    if not os.access(os.path.join(BUILD, "gsl_eval"), os.X_OK):
        print("test_why: %s/gsl_eval not built (GSL missing: make why-deps)" % BUILD)
        print("test_why: 0 passed, 1 failed")
        return 1
    with tempfile.TemporaryDirectory() as out:
        p = subprocess.run(["/usr/bin/python3", os.path.join(REPO, "scripts", "why_demo.py"), BUILD, DATA, out],
                           capture_output=True, text=True)
        check(p.returncode == 0, "why_demo.py exit %d: %s" % (p.returncode, p.stderr[-800:]))
        if p.returncode:
            return 1
        with open(os.path.join(out, "index.html"), encoding="utf-8") as fh:
            page = fh.read()
        with open(os.path.join(out, "numbers.json")) as fh:
            numbers = json.load(fh)
        check_claims(page)
        check_constraints(page, cell_values(page))
    vals = cell_values(page)

    # ---- structure
    svgs = re.findall(r"<svg.*?</svg>", page, re.S)
    check(len(svgs) >= 5, "at least 5 plots (got %d)" % len(svgs))
    for i, s in enumerate(svgs):
        try:
            ET.fromstring(s)
            ok = True
        except ET.ParseError as e:
            ok = False
            print("svg %d: %s" % (i, e))
        check(ok, "plot %d is well-formed SVG" % i)
    cmds = [html.unescape(c) for c in re.findall(r"(?:^|<pre>)\$ ([^\n<]*)", page, re.M)]
    check(len(cmds) >= 12, "commands shown (%d)" % len(cmds))
    for c in cmds:
        check("--form " in c or " curve " in c or " disaggregate " in c, "command states --form: %s" % c)
        check("…" not in c and "..." not in c, "command in full: %s" % c)
        check(c.startswith("build/trigspline "), "command as typed from the repository: %s" % c)
    check('href="../paper/index.html"' in page, "links the paper page")
    check("will be added" not in page and "will\nbe added" not in page, "no promise of what exists already")
    m = re.search(r"<code>(build/trigspline surface [^<]*)</code>", page)
    check(m is not None, "names the surface command")
    if m:
        q = subprocess.run([CLI] + html.unescape(m.group(1)).split()[1:], cwd=REPO, capture_output=True, text=True)
        claim = re.search(r"certified: <b>(\w+)</b>", page[m.end():m.end() + 400])
        check(q.returncode == 0 and claim is not None and claim.group(1) == ("yes" if json.loads(q.stdout)[
            "certified"] else "no"), "the surface sentence states what the command does (exit %d)" % q.returncode)
    for k in ("rainfall/SciPy CubicSpline/lower", "growth/GSL cspline/lower", "growth/SciPy PCHIP/lower",
              "outline/SciPy CubicSpline/box", "rainfall/ours/lower", "growth/ours/lower", "overshoot/0.1/y_max"):
        check(k in vals, "page states %s" % k)
        check(k in numbers and k not in vals or close(vals.get(k, 0.0), numbers.get(k, 1e300)),
              "numbers.json agrees with the page for %s" % k)
    if failed:
        return 1

    # ---- rainfall: SciPy CubicSpline's exact minimum
    x, f = read_xy("rainfall_daily.csv")
    cs = CubicSpline(x, f)
    cand = list(x)
    for r in cs.derivative().roots(extrapolate=False):
        cand.append(r)
    exact = float(np.min(cs(np.array(cand))))
    check(exact < 0, "CubicSpline dips below 0 on the rainfall (%g)" % exact)
    check(close(vals["rainfall/SciPy CubicSpline/lower"], exact, 1e-5),
          "rainfall CubicSpline minimum: page %r, exact %r" % (vals["rainfall/SciPy CubicSpline/lower"], exact))

    # ---- growth: GSL cspline = natural cubic spline; PCHIP; the sloped line
    x, f = read_xy("growth_above_trend.csv")
    xs = dense(x, 20000)
    line = 1.5 * xs + 10
    nat = float(np.min(CubicSpline(x, f, bc_type="natural")(xs) - line))
    check(close(vals["growth/GSL cspline/lower"], nat, 1e-6),
          "growth GSL cspline least gap: page %r, natural spline %r" % (vals["growth/GSL cspline/lower"], nat))
    pch = float(np.min(PchipInterpolator(x, f)(xs) - line))
    check(pch < 0, "PCHIP crosses the rising line (%g)" % pch)
    check(close(vals["growth/SciPy PCHIP/lower"], pch, 1e-6),
          "growth PCHIP least gap: page %r, re-derived %r" % (vals["growth/SciPy PCHIP/lower"], pch))

    # ---- outline: periodic CubicSpline per coordinate on our knots
    px, py = read_xy("field_outline.csv")
    js = json.loads(subprocess.run([CLI, "curve", os.path.join(DATA, "field_outline.csv"), "--closed", "--param",
                                    "centripetal", "--box", "0,100,0,60", "--json"],
                                   capture_output=True, text=True).stdout)
    t = np.asarray(js["knots"], float)
    ts = dense(t, 20000)
    X = CubicSpline(t, np.append(px, px[0]), bc_type="periodic")(ts)
    Y = CubicSpline(t, np.append(py, py[0]), bc_type="periodic")(ts)
    g = float(np.min(np.minimum.reduce([X, 100 - X, Y, 60 - Y])))
    check(close(vals["outline/SciPy CubicSpline/box"], g, 1e-5),
          "outline CubicSpline box distance: page %r, re-derived %r" % (vals["outline/SciPy CubicSpline/box"], g))
    check(close(vals["outline/ours/box"], js["min_gap"]), "outline: our certificate stated")

    # ---- ours: the exact certificate against dense samples of our curve
    for key, name, args, lo in (("rainfall", "rainfall_daily.csv", ["--shape", "positive"], lambda s: 0 * s),
                                ("growth", "growth_above_trend.csv", ["--lower", "1.5,10"], lambda s: 1.5 * s + 10)):
        q = subprocess.run([CLI, "fit", os.path.join(DATA, name), "--form", "paper", "--slopes", "arithmetic"] + args +
                           ["--alpha", "1", "--samples", "2001"], capture_output=True, text=True)
        d = cli_xy(q.stdout)
        smin = float(np.min(d["y"] - lo(d["x"])))
        page_v = vals["%s/ours/lower" % key]
        span = float(np.max(d["y"]) - np.min(d["y"]))
        # sampled >= exact (up to rounding); exact within the sampling bound below
        check(smin >= page_v * (1 - 5e-4) - 1e-12 * span, "%s: samples below our certificate (%r < %r)"
              % (key, smin, page_v))
        check(smin - page_v <= 5e-4 * abs(page_v) + 1e-3 * span,
              "%s: certificate %r far below the sampled least gap %r" % (key, page_v, smin))

    # ---- the overshoot example
    q = subprocess.run([CLI, "fit", os.path.join(DATA, "rainfall_daily.csv"), "--form", "paper", "--shape",
                        "positive", "--alpha", "0.1", "--samples", "2001"], capture_output=True, text=True)
    d = cli_xy(q.stdout)
    ymax = float(np.max(d["y"]))
    check(close(vals["overshoot/0.1/y_max"], ymax, 1e-3),
          "overshoot example: page y_max %r, sampled %r" % (vals["overshoot/0.1/y_max"], ymax))
    check(ymax > 1.2 * float(np.max(read_xy("rainfall_daily.csv")[1])), "the example does overshoot")
    check("warning: the curve rises" in page, "the page shows the CLI's overshoot warning")

    # ---- daily rain to hourly (docs/method.md §12): ours keeps totals and
    # signs; PCHIP's corners and the naive cubic's negatives re-derived
    mm = read_xy("rainfall_daily.csv")[1]
    n = len(mm)
    check(vals.get("disagg/trigspline/negative") == 0, "ours: no negative hour")
    check(vals.get("disagg/trigspline/total_error", 1.0) <= 1e-13, "ours: totals kept")
    check(vals.get("disagg/trigspline/dry_error", 1.0) == 0, "ours: dry days dry")
    check(vals.get("disagg/PCHIP/negative") == 0, "PCHIP on the cumulative: no negative hour")
    mid = 24.0 * (np.arange(n) + 0.5)
    naive = CubicSpline(mid, mm / 24.0)
    cells = np.array([naive.integrate(a, a + 1.0, extrapolate=True) for a in range(24 * n)])
    check(vals.get("disagg/cubic/negative") == int(np.sum(cells < 0)),
          "naive cubic: negative hours %r, re-derived %d" % (vals.get("disagg/cubic/negative"),
                                                               int(np.sum(cells < 0))))
    e = np.arange(n + 1.0) * 24.0
    P = PchipInterpolator(e, np.concatenate([[0.0], np.cumsum(mm)]))
    d2 = P.derivative(2)
    J = float(np.max(np.abs(d2(e[1:-1] + 1e-9) - d2(e[1:-1] - 1e-9))))   # r' jumps, exact to 1e-9
    # the page's one-sided differences over 1 min differ from the exact
    # jump by at most (1/60 h) max|r''| (r'' = C''' = 6 c0, constant per day)
    bound = (1.0 / 60.0) * float(np.max(np.abs(6.0 * P.c[0]))) + 1e-9
    # (printed to 3 significant digits: 5e-3 relative)
    check(abs(vals.get("disagg/PCHIP/slope_jump", -1.0) - J) <= bound + 5e-3 * J,
          "PCHIP slope jump: page %r, exact %r (bound %r)" % (vals.get("disagg/PCHIP/slope_jump"), J, bound))
    check(vals.get("disagg/trigspline/slope_jump", 1.0) <= 1e-3 * J, "ours: no corner at the day boundaries")
    return 0 if failed == 0 else 1



if __name__ == "__main__":
    rc = main()
    print("test_why: %d passed, %d failed" % (passed, failed))
    sys.exit(1 if failed else rc)
