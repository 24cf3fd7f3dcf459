"""Dump the Python package's results on the paper's and the example data, as
hex floats, for a before/after comparison of a refactoring that must not
change a bit.

    python tools/golden/python_outputs.py DATA_DIR OUT_FILE

DATA_DIR is the repository's data/ folder.  Every call that raises is
written as its exception class, so refusals are compared too.  Warnings
(deprecations of renamed keywords) are ignored: only numbers count.
"""
import csv
import os
import sys
import warnings

import numpy as np

import trigspline

warnings.simplefilter("ignore")
DATA, OUT = sys.argv[1], sys.argv[2]
lines = []


def emit(tag, values):
    a = np.asarray(values, dtype=float).ravel()
    lines.append("%s %s" % (tag, " ".join(float(v).hex() for v in a)))


def attempt(tag, fn):
    try:
        emit(tag, fn())
    except Exception as e:  # noqa: BLE001 - the class is the result
        lines.append("%s raises %s" % (tag, type(e).__name__))


def read_xy(path):
    with open(path) as fp:
        rows = [r for r in csv.reader(fp) if r and not r[0].startswith("#")]
    out = []
    for r in rows:
        try:
            out.append((float(r[0]), float(r[1])))
        except ValueError:
            continue
    a = np.array(out)
    return a[:, 0], a[:, 1]


series = {}
for sub in ("paper", "examples"):
    d = os.path.join(DATA, sub)
    for name in sorted(os.listdir(d)):
        if name.endswith(".csv") and "closed" not in name and "outline" not in name:
            try:
                series["%s/%s" % (sub, name)] = read_xy(os.path.join(d, name))
            except Exception:  # noqa: BLE001 - non-numeric files are skipped
                pass

for key, (x, f) in series.items():
    xq = np.linspace(x[0], x[-1], 97)
    lo, hi = float(np.min(f)), float(np.max(f))
    configs = [("none", {}), ("positive", {"shape": "positive"}),
               ("positive-a015", {"shape": "positive", "alpha": 0.15}),
               ("monotone", {"shape": "monotone"}),
               ("between", {"shape": "between", "lower": (0.0, lo - 1.0),
                            "upper": (0.0, hi + 1.0)})]
    for form in ("paper", "c1", "geometric"):
        for cname, kw in configs:
            tag = "%s %s %s" % (key, form, cname)
            attempt(tag + " spline", lambda: trigspline.Spline(x, f, form=form, **kw)(xq))
            attempt(tag + " deriv1", lambda: trigspline.Spline(x, f, form=form, **kw)(xq, 1))
            attempt(tag + " deriv2", lambda: trigspline.Spline(x, f, form=form, **kw)(xq, 2))
            attempt(tag + " integral", lambda: [trigspline.Spline(x, f, form=form, **kw)
                                                .integrate(x[0], x[-1])])
            attempt(tag + " roots", lambda: trigspline.Spline(x, f, form=form, **kw)
                    .solve(float(np.median(f))))
            attempt(tag + " interp", lambda: trigspline.interp(x, f, xq, form=form, **kw))
    for slopes in ("arithmetic", "geometric", "harmonic", "akima", "makima"):
        attempt("%s slopes %s" % (key, slopes),
                lambda: trigspline.Spline(x, f, slopes=slopes)(xq))

try:
    import xarray as xr
    x, f = series["paper/table1_positive.csv"]
    da = xr.DataArray(np.vstack([f, f * 2]), dims=("s", "t"), coords={"t": x})
    import trigspline.xarray  # noqa: F401 - registers the accessor
    q = np.linspace(x[0], x[-1], 31)
    attempt("xarray interp", lambda: da.trigspline.interp(t=q, shape="positive").values)
    attempt("xarray interp chunked",
            lambda: da.chunk({"t": 3}).trigspline.interp(t=q, shape="positive").values)
except ImportError:
    lines.append("xarray missing")

try:
    zpath = os.path.join(DATA, "surface")
    xs = np.linspace(0.0, 1.0, 6)
    ys = np.linspace(0.0, 2.0, 5)
    z = np.abs(np.sin(np.add.outer(xs * 3, ys)))
    for shape in ("none", "positive", "range"):
        attempt("surface %s" % shape, lambda: trigspline.Surface(xs, ys, z, shape=shape)(
            np.linspace(0, 1, 9)[:, None], np.linspace(0, 2, 7)[None, :]))
except Exception as e:  # noqa: BLE001
    lines.append("surface setup raises %s" % type(e).__name__)

with open(OUT, "w") as fp:
    fp.write("\n".join(lines) + "\n")
print("%d lines" % len(lines))
