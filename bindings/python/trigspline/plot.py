"""Figures with matplotlib (optional: imported when a function is called).

* ``spline(s)``: the curve, its data, the scheme's bounds and the intervals
  where the scheme is active (β raised to keep the shape).
* ``surface(srf)``: a heatmap with a sequential colour map (viridis), a
  colour bar with round labels, the data nodes and axis ticks.

Axes use matplotlib's own tickers: ``xscale='log'`` / ``yscale='log'``
(``LogLocator``), and dates when ``epoch`` is given (x then counts ``unit``
since ``epoch``, as ``trigspline.pandas`` and the xarray accessor fit time
coordinates): ``AutoDateLocator`` with ``ConciseDateFormatter``, which
writes the year once in the offset.

    >>> import trigspline, trigspline.plot
    >>> s = trigspline.Spline([0, 1, 2, 3], [0, 2, 0, 1], lower=0)
    >>> line = trigspline.plot.spline(s)          # doctest: +SKIP
    >>> line.axes.figure.savefig("spline.png")    # doctest: +SKIP
"""
import numpy as np

from .spline import Spline
from .surface import Surface

__all__ = ["spline", "surface", "ACTIVE_TERMS", "COLORMAP"]

#: The β terms of the shape schemes (docs/method.md §5, ``Spline.report()``
#: ``term``): an interval whose β one of them chose is drawn as active.
#: 'margin' (β = t, the scheme had nothing to do), 'user' and 'geometric'
#: (the form's own bound, docs/method.md §4) are not.
ACTIVE_TERMS = ("lower-left", "lower-right", "upper-left", "upper-right", "monotone",
                "certify")

#: The default colour map of ``surface``: sequential and perceptually uniform.
COLORMAP = "viridis"


def _pyplot():
    try:
        import matplotlib.pyplot as plt
    except ImportError as e:  # pragma: no cover - matplotlib is optional
        raise ImportError("trigspline.plot needs matplotlib (Debian: apt-get install "
                          "python3-matplotlib; pip: pip install matplotlib): %s" % e) from None
    return plt


def _axes(ax):
    return _pyplot().gca() if ax is None else ax


def _dates(x, epoch, unit):
    """x (counts of unit since epoch) as datetime64[ns]; x itself without an epoch."""
    x = np.asarray(x, dtype=np.float64)
    if epoch is None:
        return x
    e = np.datetime64(epoch, "ns")
    ns = np.timedelta64(1, unit) / np.timedelta64(1, "ns")
    return e + np.round(x * ns).astype("timedelta64[ns]")


def _date_axis(axis):
    import matplotlib.dates as mdates
    loc = mdates.AutoDateLocator()
    axis.set_major_locator(loc)
    axis.set_major_formatter(mdates.ConciseDateFormatter(loc))


def _scale(ax, xscale, yscale, epoch):
    import matplotlib.ticker as mticker
    for axis, scale, setter in ((ax.xaxis, xscale, ax.set_xscale),
                                (ax.yaxis, yscale, ax.set_yscale)):
        if scale is None:
            continue
        setter(scale)
        if scale == "log":
            # matplotlib's LogLocator puts the ticks at k·10^n; labelled as
            # plain numbers (0.3, 1, 20), and over two decades or less also
            # at 2·10^n and 5·10^n, so that a short range shows numbers
            axis.set_major_formatter(_LogLabels())
            axis.set_minor_formatter(_LogLabels())
    if epoch is not None:
        _date_axis(ax.xaxis)


def _log_labels_class():
    import matplotlib.ticker as mticker

    class LogLabels(mticker.Formatter):
        """Round labels on a log axis: 1, 2, 5 times a power of ten (only the
        powers over more than two decades); plain numbers from 0.001 to
        10^5, k×10^n beyond."""

        def __call__(self, v, pos=None):
            if not (v > 0 and np.isfinite(v)):
                return ""
            e = int(np.floor(np.log10(v) + 1e-9))
            k = int(round(v / 10.0 ** e))
            if k == 10:
                e, k = e + 1, 1
            lo, hi = self.axis.get_view_interval() if self.axis is not None else (v, v)
            decades = np.log10(max(hi, lo) / min(hi, lo)) if min(hi, lo) > 0 else np.inf
            if k not in ((1, 2, 5) if decades <= 2 else (1,)):
                return ""
            if -3 <= e < 5:
                return "%g" % (k * 10.0 ** e)
            return r"$%s10^{%d}$" % ("" if k == 1 else r"%d\times" % k, e)

    return LogLabels


def _LogLabels():
    return _log_labels_class()()


def _samples(x, per_interval, xscale):
    """per_interval points in every interval (log-spaced on a log axis), knots included."""
    x = np.asarray(x, dtype=np.float64)
    t = np.linspace(0.0, 1.0, per_interval + 1)[:-1]
    if xscale == "log" and x[0] > 0:
        lx = np.log(x)
        q = np.exp(lx[:-1, None] + np.diff(lx)[:, None] * t)
    else:
        q = x[:-1, None] + np.diff(x)[:, None] * t
    return np.append(q.ravel(), x[-1])


def spline(s, ax=None, *, data=True, bounds=True, active=True, per_interval=32, epoch=None,
           unit="s", xscale=None, yscale=None, label=None, color=None, xlabel=None,
           ylabel=None):
    """Draw a :class:`~trigspline.Spline` (first series) on ``ax``.

    Parameters
    ----------
    s : Spline
    ax : matplotlib Axes, default the current axes (``plt.gca()``)
    data : bool, default True
        The data points as markers.
    bounds : bool, default True
        The scheme's lower/upper lines (dashed); ``shape='positive'``: y = 0.
    active : bool, default True
        Shade the intervals whose β a term of the scheme chose
        (``ACTIVE_TERMS``: the bound or the monotone rule acted there).
    per_interval : int, default 32
        Samples per interval (the curve is exact at the samples).
    epoch : datetime-like, default none
        x counts ``unit`` since ``epoch``: the x axis shows dates
        (``AutoDateLocator``, ``ConciseDateFormatter``).
    unit : str, default 's'
        numpy's time unit of x when ``epoch`` is given.
    xscale, yscale : {'linear', 'log', ...}, default the axes' own
        matplotlib scales (``'log'``: ``LogLocator`` ticks).
    label : str, default 'trigspline'
        The curve's legend entry.
    color : matplotlib colour, default the axes' next colour
    xlabel, ylabel : str, default none

    Returns
    -------
    matplotlib Line2D: the curve (``.axes`` is the Axes).
    """
    if not isinstance(s, Spline):
        raise TypeError("spline() draws a trigspline.Spline, not %s" % type(s).__name__)
    if per_interval < 1:
        raise ValueError("per_interval must be >= 1, not %r" % (per_interval,))
    ax = _axes(ax)
    x = np.asarray(s.x, dtype=np.float64)
    f = np.asarray(s.values, dtype=np.float64)
    f = f.reshape(f.shape[0], -1)[:, 0] if f.ndim > 1 else f
    q = _samples(x, per_interval, xscale)
    y = np.asarray(s(q, extrapolate="clamp"), dtype=np.float64)
    y = y.reshape(y.shape[0], -1)[:, 0] if y.ndim > 1 else y
    (line,) = ax.plot(_dates(q, epoch, unit), y, color=color, lw=1.6,
                      label="trigspline" if label is None else label, zorder=3)
    if data:
        ax.plot(_dates(x, epoch, unit), f, "o", ms=3.5, color="black", label="data",
                zorder=4)
    if bounds:
        lo, up = s._lines
        for name, ln in (("lower", lo), ("upper", up)):
            if ln is not None:
                m, c = ln
                ends = x[[0, -1]]
                if yscale == "log" and not (m * ends + c > 0).all():
                    continue  # not on a log axis (y = 0 of 'positive')
                ax.plot(_dates(ends, epoch, unit), m * ends + c, "--", lw=1.0, color="0.35",
                        label="%s bound" % name, zorder=2)
    if active and s.shape != "none":
        shown = False
        for r in s.report():
            if r["term"] in ACTIVE_TERMS:
                a, b = _dates([r["x0"], r["x1"]], epoch, unit)
                ax.axvspan(a, b, color="#fdd49e", alpha=0.55, lw=0, zorder=0,
                           label=None if shown else "scheme active")
                shown = True
    _scale(ax, xscale, yscale, epoch)
    if xlabel is not None:
        ax.set_xlabel(xlabel)
    if ylabel is not None:
        ax.set_ylabel(ylabel)
    return line


def surface(srf, ax=None, *, samples=8, cmap=COLORMAP, vmin=None, vmax=None, colorbar=True,
            nodes=True, xscale=None, yscale=None, xlabel=None, ylabel=None, label=None):
    """Draw a :class:`~trigspline.Surface` as a heatmap on ``ax``.

    Parameters
    ----------
    srf : Surface
    ax : matplotlib Axes, default the current axes (``plt.gca()``)
    samples : int, default 8
        Samples per patch along each axis.
    cmap : str or Colormap, default 'viridis'
        A sequential map (the data are one quantity from low to high).
    vmin, vmax : float, default the surface's constant bounds, else its sampled range
        The ends of the colour scale.
    colorbar : bool, default True
        A colour bar with round labels (``MaxNLocator``), titled ``label``.
    nodes : bool, default True
        The data nodes as small dots.
    xscale, yscale : {'linear', 'log', ...}, default the axes' own
    xlabel, ylabel, label : str, default none

    Returns
    -------
    matplotlib QuadMesh (``.axes`` the Axes, ``.colorbar`` the colour bar
    or None).
    """
    if not isinstance(srf, Surface):
        raise TypeError("surface() draws a trigspline.Surface, not %s" % type(srf).__name__)
    if samples < 1:
        raise ValueError("samples must be >= 1, not %r" % (samples,))
    import matplotlib.ticker as mticker
    plt = _pyplot()
    ax = _axes(ax)
    x, y = np.asarray(srf.x, dtype=np.float64), np.asarray(srf.y, dtype=np.float64)
    xs, ys = _samples(x, samples, xscale), _samples(y, samples, yscale)
    z = np.asarray(srf(xs, ys), dtype=np.float64)          # (len(xs), len(ys))
    lo, hi = _constant_bounds(srf)
    if vmin is None:
        vmin = lo if lo is not None else float(np.nanmin(z))
    if vmax is None:
        vmax = hi if hi is not None else float(np.nanmax(z))
    mesh = ax.pcolormesh(xs, ys, z.T, cmap=cmap, vmin=vmin, vmax=vmax, shading="gouraud",
                         rasterized=True)
    if nodes:
        gx, gy = np.meshgrid(x, y, indexing="ij")
        ax.plot(gx.ravel(), gy.ravel(), "o", ms=2.2, color="white", mec="black", mew=0.4,
                zorder=3, label="data")
    _scale(ax, xscale, yscale, None)
    for axis, scale in ((ax.xaxis, xscale), (ax.yaxis, yscale)):
        if scale in (None, "linear"):
            axis.set_major_locator(mticker.MaxNLocator(nbins=6, steps=[1, 2, 5, 10]))
    ax.set_xlim(x[0], x[-1])
    ax.set_ylim(y[0], y[-1])
    if xlabel is not None:
        ax.set_xlabel(xlabel)
    if ylabel is not None:
        ax.set_ylabel(ylabel)
    if colorbar:
        cb = plt.colorbar(mesh, ax=ax, label=label)
        cb.locator = mticker.MaxNLocator(nbins=6, steps=[1, 2, 5, 10])
        cb.formatter = mticker.ScalarFormatter(useOffset=False)
        cb.update_ticks()
    return mesh


def _constant_bounds(srf):
    """The surface's flat bounds (lower, upper) as numbers, None where absent or sloped."""
    b = srf.bounds
    if b is None:
        return None, None
    out = []
    for p in b:
        out.append(float(p[2]) if p is not None and p[0] == 0 and p[1] == 0 else None)
    return tuple(out)
