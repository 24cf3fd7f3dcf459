#!/usr/bin/env python3
"""The gallery of `make demo`: figures made with trigspline.plot, each shown
with the code that made it (the code below is what runs: each entry's text
is executed, then its `fig` is saved).

    python scripts/gallery.py OUT_DIR

Needs the Python package (make demo installs it into build/gallery-venv),
pandas, xarray and matplotlib.  Writes OUT_DIR/index.html and one PNG per
entry; the page is static (no script), the images are relative links.
Run from the repository root (the data paths are relative to it).
"""
import html
import os
import sys
import tempfile
import time

import matplotlib

matplotlib.use("Agg")
matplotlib.rcParams.update({"font.size": 9, "figure.dpi": 110})

PREAMBLE = """\
import io
import numpy as np
import pandas as pd
import xarray as xr
import matplotlib.pyplot as plt
import trigspline
import trigspline.plot
"""

# (file name, title, caption, code): the code makes `fig`.
ENTRIES = [
    ("rain_dates", "A rain gauge, hourly, on a date axis",
     "Three-hourly rain rates with one missing reading; the certified curve through the "
     "readings never dips below zero. Dates use matplotlib's AutoDateLocator and "
     "ConciseDateFormatter (the year once, in the offset).",
     """\
csv = '''time,rain
2024-06-03T00:00,0.0
2024-06-03T03:00,0.0
2024-06-03T06:00,0.4
2024-06-03T09:00,3.8
2024-06-03T12:00,7.9
2024-06-03T15:00,2.1
2024-06-03T18:00,0.0
2024-06-03T21:00,0.0
2024-06-04T00:00,NA
2024-06-04T03:00,0.0
2024-06-04T06:00,1.2
2024-06-04T09:00,0.3
2024-06-04T12:00,0.0
'''
rain = pd.read_csv(io.StringIO(csv), parse_dates=["time"], index_col="time")["rain"]
ok = rain.notna()
t0 = rain.index[0]
hours = ((rain.index - t0) / pd.Timedelta(hours=1))[ok]
s = trigspline.Spline(hours, rain[ok], lower=0)
assert s.certified

fig, ax = plt.subplots(figsize=(6.4, 2.8))
trigspline.plot.spline(s, ax, epoch=t0, unit="h", ylabel="rain (mm/h)")
ax.legend(frameon=False)
fig.tight_layout()
"""),
    ("active", "Where the scheme acts",
     "Daily rainfall (data/examples) with the paper's form and arithmetic-mean slopes: "
     "the unconstrained spline (grey) goes negative; the certified one raises β only on "
     "the shaded intervals, and is the plain spline elsewhere.",
     """\
day, mm = np.loadtxt("data/examples/rainfall_daily.csv", delimiter=",", skiprows=4,
                     unpack=True)
opts = dict(form="paper", slopes="arithmetic", alpha=1.0)
free = trigspline.Spline(day, mm, shape="none", **opts)
s = trigspline.Spline(day, mm, lower=0, **opts)
assert s.certified

fig, ax = plt.subplots(figsize=(6.4, 2.8))
q = np.linspace(day[0], day[-1], 2000)
ax.plot(q, free(q), color="0.6", lw=1, label="no scheme")
trigspline.plot.spline(s, ax, label="lower=0", xlabel="day", ylabel="rain (mm)")
ax.legend(frameon=False, ncol=2)
fig.tight_layout()
"""),
    ("log_axis", "A log axis",
     "Plasma concentration after one dose, kept above the assay's detection floor "
     "(0.05 mg/L, dashed) on a log axis: ticks at round values by matplotlib's LogLocator.",
     """\
t, c = np.loadtxt("data/examples/drug_concentration.csv", delimiter=",", skiprows=4,
                  unpack=True)
s = trigspline.Spline(t, c, lower=0.05)
assert s.certified

fig, ax = plt.subplots(figsize=(6.4, 2.8))
trigspline.plot.spline(s, ax, yscale="log", xlabel="hours after the dose",
                       ylabel="concentration (mg/L)")
ax.legend(frameon=False)
fig.tight_layout()
"""),
    ("missing", "A missing value stays local",
     "One NaN in an hourly series: xarray's own linear interp and trigspline's default "
     "(skipna=False) blank only the two intervals touching it; skipna=True bridges it.",
     """\
t = np.arange(12.0)
v = np.array([0, 0.5, 2, 4.5, 3, np.nan, 1.5, 0.8, 0.2, 0, 0, 0.6])
da = xr.DataArray(v, dims="t", coords={"t": t})
q = np.linspace(0, 11, 441)
local = da.trigspline.interp(t=q, lower=0)
bridged = da.trigspline.interp(t=q, lower=0, skipna=True)
linear = da.interp(t=q)

fig, ax = plt.subplots(figsize=(6.4, 2.8))
ax.plot(q, bridged, color="0.7", lw=3, label="trigspline, skipna=True")
ax.plot(q, local, lw=1.6, label="trigspline (default)")
ax.plot(q, linear, ":", color="black", lw=1, label="xarray linear")
ax.plot(t, v, "o", ms=3.5, color="black")
ax.axvspan(4, 6, color="#fdd49e", alpha=0.5, lw=0, label="NaN in the output")
ax.set_xlabel("hour")
ax.legend(frameon=False, fontsize=8)
fig.tight_layout()
"""),
    ("percent_surface", "A percentage field, certified in [0, 100]",
     "Cloud cover (data/surface, long format) refined eightfold; every patch is proven "
     "inside [0, 100]. A sequential colour map (viridis) with a colour bar in round steps.",
     """\
x, y, z = np.loadtxt("data/surface/cloud_percent_long.csv", delimiter=",", skiprows=2,
                     unpack=True)
xs, ys = np.unique(x), np.unique(y)
grid = np.full((xs.size, ys.size), np.nan)
grid[np.searchsorted(xs, x), np.searchsorted(ys, y)] = z
srf = trigspline.Surface(xs, ys, grid, lower=0, upper=100)
assert srf.certified

fig, ax = plt.subplots(figsize=(5.6, 3.6))
trigspline.plot.surface(srf, ax, label="cloud cover (%)", xlabel="x (km)", ylabel="y (km)")
fig.tight_layout()
"""),
    ("rain_surface", "A spiky positive field on an uneven grid",
     "Precipitation (data/surface, matrix layout) with lower=0: zeros stay zeros and no "
     "patch dips below; the colour scale starts at the bound.",
     """\
m = np.genfromtxt("data/surface/spiky_rain_matrix.csv", delimiter=",", skip_header=2)
xs, ys, z = m[0, 1:], m[1:, 0], m[1:, 1:].T         # z[i, j] at (xs[i], ys[j])
srf = trigspline.Surface(xs, ys, z, lower=0)
assert srf.certified

fig, ax = plt.subplots(figsize=(5.6, 3.6))
trigspline.plot.surface(srf, ax, label="rain (mm)", xlabel="x", ylabel="y")
fig.tight_layout()
"""),
]

CSS = """
body{font-family:system-ui,sans-serif;max-width:1400px;margin:1em auto;padding:0 1em;color:#222}
h1{font-size:1.5em} .grid{display:grid;grid-template-columns:repeat(auto-fill,minmax(620px,1fr));gap:1.2em}
figure{border:1px solid #ddd;border-radius:6px;padding:.6em;margin:0;background:#fafafa}
figure img{max-width:100%;height:auto;display:block;margin:0 auto}
figcaption{font-size:.9em;margin:.4em 0}
pre{background:#f0f0f0;padding:.4em .6em;overflow-x:auto;font-size:.78em}
"""


def render(out_dir, name, code):
    import matplotlib.pyplot as plt
    ns = {"__name__": "__gallery__"}
    exec(compile(PREAMBLE, "<preamble>", "exec"), ns)
    exec(compile(code, "<gallery: %s>" % name, "exec"), ns)
    fig = ns["fig"]
    fig.savefig(os.path.join(out_dir, name + ".png"))
    plt.close("all")


def page(version, timings):
    parts = ["<!DOCTYPE html>", '<html lang="en"><head><meta charset="utf-8">',
             "<title>trigspline gallery</title><style>%s</style></head><body>" % CSS,
             "<h1>trigspline gallery</h1>",
             "<p>Figures made with <code>trigspline.plot</code> (trigspline %s), each with the "
             "code that made it; every entry starts with:</p>" % html.escape(version),
             "<pre><code>%s</code></pre>" % html.escape(PREAMBLE),
             "<p>A walk-through: <code>docs/tutorial.md</code>. Options and defaults: "
             "<code>docs/options.md</code>.</p>", '<div class="grid">']
    for name, title, caption, code in ENTRIES:
        parts.append('<figure id="%s"><h2>%s</h2>' % (name, html.escape(title)))
        parts.append('<img src="%s.png" alt="%s">' % (name, html.escape(title, quote=True)))
        parts.append("<figcaption>%s</figcaption>" % html.escape(caption))
        parts.append("<pre><code>%s</code></pre></figure>" % html.escape(code))
    parts.append("</div><p><small>Made by scripts/gallery.py in %.1f s.</small></p>"
                 % sum(timings))
    parts.append("</body></html>")
    return "\n".join(parts) + "\n"


def main(argv):
    if len(argv) != 2:
        sys.exit("usage: gallery.py OUT_DIR")
    out_dir = argv[1]
    os.makedirs(out_dir, exist_ok=True)
    import trigspline
    timings = []
    for name, _, _, code in ENTRIES:
        t = time.perf_counter()
        render(out_dir, name, code)
        timings.append(time.perf_counter() - t)
    text = page(trigspline.__version__, timings)
    fd, tmp = tempfile.mkstemp(dir=out_dir, suffix=".html")
    with os.fdopen(fd, "w", encoding="utf-8") as fh:
        fh.write(text)
    os.chmod(tmp, 0o644)
    os.replace(tmp, os.path.join(out_dir, "index.html"))
    print("gallery: %s/index.html, %d figures in %.1f s" % (out_dir, len(ENTRIES), sum(timings)))


if __name__ == "__main__":
    main(sys.argv)
