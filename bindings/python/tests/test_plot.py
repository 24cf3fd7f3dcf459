"""trigspline.plot: figures rendered to PNG with the Agg backend, checked for
their structure (not their pixels): the sequential colour map, round and
short labels, matplotlib's date and log tickers, the data, bounds and
active intervals drawn where the spline's own report puts them.

"Round" is checked independently of matplotlib's formatter: a label's
number has at most two significant digits (k·10^n with k < 100)."""
import math
import subprocess
import sys

import numpy as np
import pytest

mpl = pytest.importorskip("matplotlib", reason="python3-matplotlib is installed by make test")
mpl.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import trigspline  # noqa: E402
from trigspline import Spline, Surface  # noqa: E402
from trigspline import plot as tsplot  # noqa: E402

MINUS = "\u2212"


def labels(axis, minor=False):
    """The non-empty labels of an axis' ticks inside its view."""
    lo, hi = sorted(axis.get_view_interval())
    return [t.get_text() for loc, t in zip(axis.get_ticklocs(minor=minor),
                                           axis.get_ticklabels(minor=minor))
            if t.get_text() and lo <= loc <= hi]


def number(text):
    """A label as a number: plain text or mathtext k×10^{n}."""
    t = text.replace(MINUS, "-").replace("$", "").replace(r"\mathdefault", "")
    t = t.replace("{", "").replace("}", "")
    if "10^" in t:
        k, _, e = t.rpartition("10^")
        k = k.replace(r"\times", "") or "1"
        return float(k) * 10.0 ** int(e)
    return float(t)


def is_round(v):
    if v == 0:
        return True
    e = math.floor(math.log10(abs(v)))
    k = abs(v) / 10.0 ** (e - 1)        # two significant digits before the point
    return abs(k - round(k)) < 1e-9 * k


@pytest.fixture(autouse=True)
def close_figures():
    yield
    plt.close("all")


def rain_spline():
    x = np.arange(12.0)
    f = np.array([0, 0, 3, 8, 1, 0, 0, 0.2, 5, 0.5, 0, 0])
    return Spline(x, f, lower=0, form="paper", slopes="arithmetic", alpha=1.0)


def test_spline_with_data_bounds_and_active_intervals(tmp_path):
    s = rain_spline()
    fig, ax = plt.subplots()
    line = tsplot.spline(s, ax)
    assert line.axes is ax
    fig.savefig(tmp_path / "spline.png")
    assert (tmp_path / "spline.png").stat().st_size > 5000
    # the curve: the spline at its samples, through the data
    xs, ys = line.get_xdata(), line.get_ydata()
    np.testing.assert_array_equal(ys, s(xs))
    assert set(s.x).issubset(set(xs)) and ys.min() >= 0
    data = [l for l in ax.lines if l.get_label() == "data"][0]
    np.testing.assert_array_equal(data.get_xdata(), s.x)
    np.testing.assert_array_equal(data.get_ydata(), s.values)
    lower = [l for l in ax.lines if l.get_label() == "lower bound"][0]
    assert lower.get_linestyle() == "--" and list(lower.get_ydata()) == [0, 0]
    # active: the intervals whose beta a bound term chose (the report), and
    # this data set has some (a zero next to a rise) but not everywhere
    want = [(r["x0"], r["x1"]) for r in s.report() if r["term"] in tsplot.ACTIVE_TERMS]
    spans = [p for p in ax.patches]
    got = sorted((p.get_xy()[:, 0].min(), p.get_xy()[:, 0].max()) for p in spans)
    assert got == sorted(want) and 0 < len(got) < s.intervals
    # shape='none': nothing is active, no bound
    fig2, ax2 = plt.subplots()
    tsplot.spline(Spline(s.x, s.values, shape="none"), ax2)
    assert not ax2.patches and all("bound" not in l.get_label() for l in ax2.lines)
    # axis ticks round
    fig.canvas.draw()
    for t in labels(ax.xaxis) + labels(ax.yaxis):
        assert is_round(number(t)), t


def test_date_axis_uses_matplotlibs_date_tickers(tmp_path):
    import matplotlib.dates as mdates
    s = rain_spline()
    fig, ax = plt.subplots()
    line = tsplot.spline(s, ax, epoch="2021-03-01T00:00", unit="h")
    fig.savefig(tmp_path / "dates.png")
    assert isinstance(ax.xaxis.get_major_locator(), mdates.AutoDateLocator)
    assert isinstance(ax.xaxis.get_major_formatter(), mdates.ConciseDateFormatter)
    fig.canvas.draw()
    ticks = labels(ax.xaxis)
    assert len(ticks) >= 4 and not any(MINUS in t or t.startswith("-") for t in ticks), ticks
    # the year is written once, in the offset
    assert "2021" in ax.xaxis.get_major_formatter().get_offset()
    # ticks at whole hours; the data at the hours since the epoch
    hours = (ax.get_xticks() - mdates.date2num(np.datetime64("2021-03-01T00:00"))) * 24
    np.testing.assert_allclose(hours, np.round(hours), atol=1e-6)
    x0 = np.asarray(line.get_xdata())[0]
    assert x0 == np.datetime64("2021-03-01T00:00", "ns")


def test_log_axes_round_ticks(tmp_path):
    x = np.geomspace(0.3, 3.0, 9)
    f = np.array([1, 2, 1.5, 3, 2.5, 2.8, 4, 3.5, 5.0])
    s = Spline(x, f, lower=0)
    fig, ax = plt.subplots()
    tsplot.spline(s, ax, xscale="log", yscale="log")
    fig.savefig(tmp_path / "log.png")
    assert ax.get_xscale() == "log" and ax.get_yscale() == "log"
    fig.canvas.draw()
    for axis in (ax.xaxis, ax.yaxis):
        shown = labels(axis) + labels(axis, minor=True)
        assert len(shown) >= 2, shown         # a one-decade range still shows numbers
        for t in shown:
            v = number(t)
            assert is_round(v) and len(t) <= 4, t
    # y = 0 (the positive scheme's bound) cannot be drawn on a log axis
    assert all("bound" not in l.get_label() for l in ax.lines)
    # many decades: powers of ten only
    fig2, ax2 = plt.subplots()
    tsplot.spline(Spline(np.geomspace(0.01, 1e4, 9), f, lower=0), ax2, xscale="log")
    fig2.canvas.draw()
    shown = labels(ax2.xaxis) + labels(ax2.xaxis, minor=True)
    assert shown and all(math.log10(number(t)).is_integer() for t in shown), shown


def percent_surface():
    rng = np.random.default_rng(3)
    z = np.clip(rng.normal(50, 40, (9, 7)), 0, 100)
    return Surface(np.arange(9.0) * 2.5, np.arange(7.0) * 1.7, z, lower=0, upper=100)


def test_surface_heatmap_sequential_map_and_short_colorbar_labels(tmp_path):
    srf = percent_surface()
    fig, ax = plt.subplots()
    mesh = tsplot.surface(srf, ax, label="cloud cover (%)", xlabel="lon", ylabel="lat")
    fig.savefig(tmp_path / "heat.png")
    assert mesh.get_cmap().name == "viridis"
    assert mesh.norm.vmin == 0 and mesh.norm.vmax == 100   # the surface's bounds
    cb = mesh.colorbar
    assert cb is not None and cb.ax.get_ylabel() == "cloud cover (%)"
    fig.canvas.draw()
    cbl = labels(cb.ax.yaxis)
    assert cbl == ["0", "20", "40", "60", "80", "100"]
    for axis in (ax.xaxis, ax.yaxis):
        t = labels(axis)
        assert len(t) >= 3 and all(is_round(number(v)) for v in t), t
    assert ax.get_xlabel() == "lon" and ax.get_ylabel() == "lat"
    # the data nodes
    nodes = [l for l in ax.lines if l.get_label() == "data"][0]
    assert len(nodes.get_xdata()) == 9 * 7
    # the image itself: the samples of the surface
    xs = np.unique(mesh.get_coordinates()[..., 0])
    ys = np.unique(mesh.get_coordinates()[..., 1])
    np.testing.assert_array_equal(mesh.get_array().reshape(len(ys), len(xs)).T, srf(xs, ys))


def test_colorbar_of_an_awkward_range_stays_short():
    # no bounds: the colour scale is the sampled range, whose ends are long
    # numbers; the labels are the round values inside it
    rng = np.random.default_rng(5)
    z = rng.normal(0.0, 1.0, (6, 5)) * 3.7 + 11.13
    srf = Surface(np.linspace(0, 1, 6), np.linspace(0, 2, 5), z)
    fig, ax = plt.subplots()
    mesh = tsplot.surface(srf, ax, samples=4)
    fig.canvas.draw()
    lo, hi = mesh.norm.vmin, mesh.norm.vmax
    assert len(repr(lo)) > 8                   # the end itself is not round
    cbl = labels(mesh.colorbar.ax.yaxis)
    assert len(cbl) >= 3
    for t in cbl:
        v = number(t)
        assert len(t) <= 4 and is_round(v) and lo <= v <= hi, (t, lo, hi)


def test_wrong_objects_and_no_matplotlib(monkeypatch):
    with pytest.raises(TypeError, match="Spline"):
        tsplot.spline(percent_surface())
    with pytest.raises(TypeError, match="Surface"):
        tsplot.surface(rain_spline())
    monkeypatch.setitem(sys.modules, "matplotlib.pyplot", None)
    with pytest.raises(ImportError, match="python3-matplotlib"):
        tsplot.spline(rain_spline())


def test_importing_the_module_does_not_import_matplotlib():
    code = "import sys, trigspline.plot; print('matplotlib' in sys.modules)"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True).stdout
    assert out.strip() == "False"
    assert trigspline.plot is tsplot
