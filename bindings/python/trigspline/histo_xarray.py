"""``da.trigspline.disaggregate(time="1h")``: bin totals to a finer grid
(docs/method.md §12) on xarray data, numpy- or dask-backed.

The coordinate values along the dimension are the bins' starts; each bin
ends where the next starts, the last one as wide as the one before it (or
give ``width``).  The finer grid starts at the first bin and steps by the
given step up to the end of the last bin (which it must reach exactly).
Datetime coordinates take a step such as ``"1h"`` (pandas.Timedelta),
numeric ones a number.  Every series is one call of the gufunc
``trigspline._histo.disaggregate``; dask-backed data are processed chunk by
chunk across the other dimensions (the dimension itself in one chunk), so
chunked and unchunked results are equal bit for bit.
"""
import numpy as np
import xarray as xr

from . import histo

__all__ = ["disaggregate_dataarray", "disaggregate_dataset"]


def _step_and_positions(coord, step, width):
    """Bin edges and grid in units of the step (float64), and the grid's
    coordinate values (cell starts)."""
    v = np.asarray(coord)
    if v.size == 0:
        raise ValueError("disaggregate: no bins")
    if v.dtype.kind == "M":
        import pandas as pd
        st = np.timedelta64(pd.Timedelta(step).value, "ns")
        wd = None if width is None else np.timedelta64(pd.Timedelta(width).value, "ns")
        t = v.astype("datetime64[ns]")
        rel = (t - t[0]) / st
        end = (t[-1] + (wd if wd is not None else (t[-1] - t[-2]) if t.size > 1 else st) - t[0]) / st
        to_coord = lambda k: t[0] + k * st  # noqa: E731
    elif v.dtype.kind in "fiu":
        st = float(step)
        t = v.astype(np.float64)
        rel = (t - t[0]) / st
        wd = width if width is not None else (t[-1] - t[-2] if t.size > 1 else st)
        end = (t[-1] + float(wd) - t[0]) / st
        to_coord = lambda k: t[0] + k * st  # noqa: E731
    else:
        raise TypeError("disaggregate: coordinate of dtype %s" % v.dtype)
    if not (st > st * 0):
        raise ValueError("disaggregate: the step must be positive")
    k = int(round(float(end)))
    if k < 1 or abs(float(end) - k) > 1e-9 * max(1, k):
        raise ValueError("disaggregate: the bins (%g steps long) are not a whole number of "
                         "steps" % float(end))
    edges = np.concatenate([rel.astype(np.float64), [float(k)]])
    grid = np.arange(k + 1, dtype=np.float64)
    return edges, grid, to_coord(np.arange(k))


def disaggregate_dataarray(da, indexers=None, *, kind="totals", lo=None, hi=None, alpha=None,
                           width=None, errors="raise", **kwargs):
    """Totals over a finer grid (or the rate, per step) from bin totals along
    one dimension: ``da.trigspline.disaggregate(time="1h")``.

    Parameters
    ----------
    indexers, **kwargs
        One ``dim=step``: the dimension holding the bins and the finer step.
    kind : {"totals", "rate"}
        ``"totals"``: the total of each finer cell (they add up to the bins');
        ``"rate"``: r at each cell's start, in total per step.
    lo, hi, alpha : float, optional
        Bounds of the rate (default r >= 0) and the tension; see
        ``trigspline.disaggregate``.
    width : optional
        Width of the last bin (default: as the one before it).
    errors : {"raise", "nan"}

    Returns
    -------
    xarray.DataArray
        The dimension replaced by the finer cells (labelled by their starts).
    """
    ind = dict(indexers or {}, **kwargs)
    if len(ind) != 1:
        raise ValueError("disaggregate: give exactly one dim=step (got %s)" % (list(ind),))
    (dim, step), = ind.items()
    if dim not in da.dims:
        raise ValueError("%r is not a dimension of this DataArray (dims %s)" % (dim, da.dims))
    if kind not in ("totals", "rate"):
        raise ValueError("kind must be 'totals' or 'rate', not %r" % (kind,))
    coord = da[dim].values if dim in da.coords else np.arange(da.sizes[dim])
    edges, grid, newc = _step_and_positions(coord, step, width)
    m = grid.size - 1
    pts = grid[:-1] if kind == "rate" else grid

    widths = np.diff(edges)
    sub = int(widths[0])
    if kind == "totals" and (widths == sub).all():
        # bins of a whole number of steps each (daily to hourly): the fast
        # path, every bin cut into `sub` cells
        def run(a):
            return histo.disaggregate(edges, a, per_bin=sub, lo=lo, hi=hi, alpha=alpha,
                                      errors=errors)
    else:
        def run(a):
            return histo.disaggregate(edges, a, pts, kind=kind, lo=lo, hi=hi, alpha=alpha,
                                      errors=errors)

    obj = da
    if obj.chunks is not None:
        obj = obj.chunk({dim: -1})
    new = "__trigspline_cells__"
    out = xr.apply_ufunc(run, obj, input_core_dims=[[dim]], output_core_dims=[[new]],
                         dask="parallelized", output_dtypes=[np.float64],
                         dask_gufunc_kwargs={"output_sizes": {new: m}})
    out = out.rename({new: dim}).assign_coords({dim: newc})
    return out.transpose(*da.dims)


def disaggregate_dataset(ds, indexers=None, **kwargs):
    """``ds.trigspline.disaggregate(time="1h")``: every numeric data variable
    holding the dimension, as ``DataArray.trigspline.disaggregate``; the
    others are kept, those without the dimension unchanged."""
    ind = dict(indexers or {}, **{k: v for k, v in kwargs.items() if k in ds.dims})
    opts = {k: v for k, v in kwargs.items() if k not in ds.dims}
    if len(ind) != 1:
        raise ValueError("disaggregate: give exactly one dim=step (got %s)" % (list(ind),))
    (dim, _), = ind.items()
    out = {}
    for name, var in ds.data_vars.items():
        if dim in var.dims and var.dtype.kind in "fiu":
            out[name] = disaggregate_dataarray(var, ind, **opts)
        elif dim not in var.dims:
            out[name] = var
    return xr.Dataset(out, attrs=ds.attrs)
