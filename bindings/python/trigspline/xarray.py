"""xarray accessor: ``da.trigspline.interp(time=new_times, lower=0)``.

Importing this module registers the ``trigspline`` accessor on DataArray and
Dataset.  Interpolation runs one certified spline per series along one
dimension through ``trigspline.interp`` (a numpy gufunc in C).

* numpy-backed data: one gufunc call.
* dask-backed data with the dimension in one chunk: ``xarray.apply_ufunc``
  with ``dask='parallelized'``.
* dask-backed data chunked along the dimension: each chunk is fitted with a
  halo of ``halo_knots(...)`` knots on each side and evaluates the queries
  that fall between its first knot and the next chunk's first knot.  The
  schemes are local (docs/method.md §3, §5, §6: interval i depends on knots
  i-1..i+2, Akima slopes on i-2..i+3), so this gives the unchunked values
  bit for bit.  Missing values stay local too (each run of finite values
  is a spline of its own, see ``trigspline.interp``).  Options that are not
  local (the C¹ form, periodic or monotone schemes, gaps skipped with
  ``skipna``, constraint records: their slope rules and scopes reach
  along the series, docs/method.md §13.2) fall back to one chunk along the
  dimension, with a warning.

Datetime coordinates are fitted as float seconds since the first
coordinate value; queries are converted the same way.
"""
import warnings

import numpy as np
import xarray as xr

from . import _gufunc, _options
from .errors import _S, TrigsplineError
from .interp import DATA_GAPS, STATUS_OK, pack, resolve, sentence, status_message

__all__ = ["TrigsplineAccessor", "TrigsplineDatasetAccessor", "halo_knots", "summary"]

_LOCAL_FORMS = ("paper", "geometric")
_THREE_POINT = ("arithmetic", "geometric", "harmonic", "fritsch-carlson", "steffen")
_FIVE_POINT = ("akima", "makima")


def halo_knots(slopes):
    """Knots each chunk borrows from each neighbour: interval i uses the
    slopes d_i, d_{i+1}; a three-point slope at i reads knots i-1..i+1, an
    Akima slope i-2..i+2 (docs/method.md §6).  The queries of a chunk lie in
    its intervals s..e-1 (the last one ends at the next chunk's first knot e),
    so it needs knots s-1..e+1 (three-point) or s-2..e+2 (Akima)."""
    slopes = _options.name(_options.SLOPES, slopes, "slopes")
    if slopes in _THREE_POINT:
        return 2
    if slopes in _FIVE_POINT:
        return 3
    return None


def _to_float(values, epoch):
    """Coordinate values as float64: datetimes as seconds since epoch."""
    v = np.asarray(values)
    if v.dtype.kind == "M":
        return (v - epoch) / np.timedelta64(1, "s")
    if v.dtype.kind == "m":
        return v / np.timedelta64(1, "s")
    if v.dtype.kind not in "fiu":
        raise TypeError("coordinate values of dtype %s cannot be interpolated" % v.dtype)
    return v.astype(np.float64)


def _check_coordinate(name, values, xf):
    bad = ~np.isfinite(xf)
    if bad.any():
        i = int(np.argmax(bad))
        raise ValueError("coordinate %r: value %r at position %d is not finite"
                         % (name, values[i], i))
    if xf.size > 1:
        step = np.diff(xf)
        if not (step > 0).all():
            i = int(np.argmax(~(step > 0))) + 1
            raise ValueError("coordinate %r is not strictly increasing: position %d (%s) "
                             "follows position %d (%s)" % (name, i, values[i], i - 1, values[i - 1]))


def _series_label(da_dims, other_coords, where):
    parts = []
    for d, i in zip(da_dims, where):
        c = other_coords.get(d)
        parts.append("%s=%s" % (d, c[i] if c is not None else i))
    return ", ".join(parts) if parts else "the series"


def _raise_status(status, index, dims, coords, dim, dim_values, offset=None, values_from=0,
                  explain=None):
    """ValueError for the first series whose status is a data fault.
    offset: (positions of the block along the other dims, its first knot);
    dim_values: the coordinate from position values_from on; explain:
    (x, f, opt) of the block when it has constraint records, whose refusals
    get the library's sentence (the record and the condition)."""
    bad = (status != STATUS_OK) & ~np.isin(status, DATA_GAPS)
    if not bad.any():
        return
    where = tuple(int(i[0]) for i in np.nonzero(bad))
    code, i = int(status[where]), int(index[where])
    if explain is not None:
        x, f, opt = explain
        why = sentence(code, i, x, np.broadcast_to(f, status.shape + x.shape)[where], opt)
        if offset is not None:
            where = tuple(w + o for w, o in zip(where, offset[0]))
        raise ValueError("trigspline.interp along %r, series %s: %s"
                         % (dim, _series_label(dims, coords, where), why))
    if offset is not None:
        where = tuple(w + o for w, o in zip(where, offset[0]))
        i = i + offset[1] if i >= 0 else i
    at = ("at %s=%s (position %d)" % (dim, dim_values[i - values_from], i)
          if 0 <= i - values_from < len(dim_values) else "")
    raise ValueError("trigspline.interp along %r, series %s: %s %s"
                     % (dim, _series_label(dims, coords, where), status_message(code), at))


def _check_new(dim, newv, qf, old, xf):
    """extrapolate='error': the first new coordinate value outside the old ones."""
    if not xf.size:
        return
    with np.errstate(invalid="ignore"):
        out = (qf < xf[0]) | (qf > xf[-1])
    if out.any():
        i = int(np.argmax(out))
        raise TrigsplineError(_S.DOMAIN, "trigspline.interp along %r: new value %s (position "
                              "%d) lies outside [%s, %s] (extrapolate='error'; 'nan' gives "
                              "NaN outside, as xarray's interp)" % (
                                  dim, newv[i], i, old[0], old[-1]), i, "query")


def _status_block(f, x, q, opt):
    _, st, ix, gap = _gufunc.interp(x, f, q, opt)
    return np.stack([st.astype(np.float64), ix.astype(np.float64), gap], axis=-1)


def _chunk_plan(xf, sizes, q):
    """For chunks of the given sizes along x: which chunk evaluates each
    (sorted) query.  A query belongs to the chunk holding the last knot
    <= it (the right-hand interval at a knot, as the library), the first
    chunk takes the queries before x[0] and the last the ones after."""
    starts = np.cumsum((0,) + tuple(sizes[:-1]))
    k = np.searchsorted(xf[starts[1:]], q, side="right")
    counts = np.bincount(k, minlength=len(sizes))
    return starts, counts


def _interp_chunked(data, xf, qf, opt, halo, errors, dims, coords, dim, dim_values):
    """data: dask array with the dimension last (chunked along it)."""
    import dask.array as dsa
    n = data.shape[-1]
    sizes = data.chunks[-1]
    order = np.argsort(qf, kind="stable")
    qs = qf[order]
    starts, counts = _chunk_plan(xf, sizes, qs)
    pieces, status_pieces = [], []
    q0 = 0
    for k, (s, size) in enumerate(zip(starts, sizes)):
        lo, hi = max(0, s - halo), min(n, s + size + halo)
        qk = qs[q0:q0 + counts[k]]
        q0 += counts[k]
        fk = data[..., lo:hi].rechunk({data.ndim - 1: -1})
        # every chunk is fitted, also one without queries: its data are
        # checked as in the unchunked fit (errors='raise')
        pieces.append(dsa.map_blocks(
            _chunk_task, fk, chunks=fk.chunks[:-1] + ((len(qk),),), dtype=data.dtype
            if data.dtype == np.float32 else np.float64,
            x=xf[lo:hi], q=qk, opt=opt, lo=lo, errors=errors, dims=dims, coords=coords,
            dim=dim, dim_values=dim_values[lo:hi]))
        # the gaps of the chunk's own intervals s..s+size-1 (the last chunk:
        # s..n-2); halo intervals are fitted with other end slopes
        own = opt.copy()
        own[-2:] = (s - lo, s + size - lo if s + size < n else -1)
        status_pieces.append(dsa.map_blocks(
            _status_block, fk, chunks=fk.chunks[:-1] + ((3,),), dtype=np.float64,
            x=xf[lo:hi], q=qk, opt=own).map_blocks(_shift_index, lo, dtype=np.float64))
    if pieces:
        y = dsa.concatenate(pieces, axis=-1)
    else:
        y = dsa.zeros(data.shape[:-1] + (0,), chunks=data.chunks[:-1] + ((0,),),
                      dtype=data.dtype if data.dtype == np.float32 else np.float64)
    if not np.array_equal(order, np.arange(len(order))):
        inv = np.empty_like(order)
        inv[order] = np.arange(len(order))
        y = y[..., inv]
    return y, status_pieces


def _chunk_task(f, x, q, opt, lo, errors, dims, coords, dim, dim_values, block_info=None):
    """One block: knots from position lo on (dim_values: their coordinate)."""
    y, st, ix, _ = _gufunc.interp(x, f, q, opt)
    if errors == "raise":
        off = None
        if block_info is not None and 0 in block_info:
            loc = block_info[0]["array-location"]
            off = ([a for a, _ in loc[:-1]], lo)
        _raise_status(st, ix, dims, coords, dim, dim_values, off, values_from=lo,
                      explain=(x, f, opt) if len(opt) > _gufunc.OPT_LEN else None)
    return y


def _shift_index(s, lo):
    s = s.copy()
    ok = s[..., 1] >= 0
    s[..., 1][ok] += lo
    return s


def _combine_status(pieces):
    """Per-chunk (status, index, gap) -> per series: the first failing chunk's
    status and index, the least gap."""
    import dask.array as dsa
    st = dsa.stack(pieces, axis=-2)  # (..., K, 3)
    return st.map_blocks(_first_failure, drop_axis=[st.ndim - 2], dtype=np.float64)


def _first_failure(a):
    """A run that fails makes the series fail (its first such chunk); else a
    data gap (missing values) is reported by the first chunk that sees one,
    as the unchunked fit reports the first missing point."""
    status, index, gap = a[..., 0], a[..., 1], a[..., 2]
    hard = (status != STATUS_OK) & ~np.isin(status, DATA_GAPS)
    failed = status != STATUS_OK
    k = np.where(hard.any(axis=-1), np.argmax(hard, axis=-1),
                 np.argmax(failed, axis=-1))[..., None]
    out = np.empty(a.shape[:-2] + (3,))
    out[..., 0] = np.take_along_axis(status, k, -1)[..., 0]
    out[..., 1] = np.take_along_axis(index, k, -1)[..., 0]
    with np.errstate(all="ignore"):
        g = np.where(np.isnan(gap), np.inf, gap).min(axis=-1)
    out[..., 2] = np.where(np.isinf(g), np.nan, g)
    return out


def summary(certificate):
    """{'all_certified', 'least_gap', 'failed', 'messages'} of a certificate
    Dataset (computes it if lazy)."""
    c = certificate.compute()
    st = np.asarray(c["status"].values)
    g = np.asarray(c["gap"].values)
    g = g[np.isfinite(g)]
    codes = np.unique(st[st != STATUS_OK])
    return {"all_certified": bool((st == STATUS_OK).all()),
            "least_gap": float(g.min()) if g.size else float("nan"),
            "failed": int((st != STATUS_OK).sum()),
            "messages": {int(k): status_message(k) for k in codes}}


def _interp_dataarray(da, dim, new, o, certificate):
    """o: the resolved options (interp.resolve)."""
    if dim not in da.dims:
        raise ValueError("%r is not a dimension of this DataArray (dims %s)" % (dim, da.dims))
    errors = o["errors"]
    opt = pack(o, want_gap=bool(certificate))
    old = da[dim].values
    epoch = old[0] if old.dtype.kind == "M" and old.size else None
    xf = _to_float(old, epoch)
    _check_coordinate(dim, old, xf)
    newv = np.asarray(new.values if isinstance(new, (xr.DataArray, xr.Variable)) else new)
    if newv.ndim != 1:
        raise ValueError("new %r values must be one-dimensional" % dim)
    if (newv.dtype.kind == "M") != (old.dtype.kind == "M"):
        raise TypeError("new %r values are %s, the coordinate is %s" % (dim, newv.dtype, old.dtype))
    qf = _to_float(newv.astype(old.dtype) if old.dtype.kind == "M" else newv, epoch)
    if o["extrapolate"] == "error":
        _check_new(dim, newv, qf, old, xf)
    f = da.variable.data
    if f.dtype.kind not in "f" or f.dtype.itemsize not in (4, 8):
        f = f.astype(np.float64)
    axis = da.dims.index(dim)
    other = [d for d in da.dims if d != dim]
    coords = {d: da[d].values for d in other if d in da.coords}
    fm = f if axis == f.ndim - 1 else _moveaxis(f, axis, -1)
    common = dict(dims=other, coords=coords, dim=dim, dim_values=old)
    cert = None
    chunked = _is_dask(fm) and len(fm.chunks[-1]) > 1
    if chunked:
        halo = halo_knots(o["slopes"])
        local = (halo is not None and o["form"] in _LOCAL_FORMS
                 and not o["skipna"] and o["shape"] != "monotone"
                 and o.get("constraints") is None)
        if not local:
            warnings.warn("trigspline.interp along %r: these options (form=%r, slopes=%r, "
                          "shape=%r, skipna=%r%s) are not local; the dimension is rechunked "
                          "into one chunk" % (dim, o["form"], o["slopes"], o["shape"],
                                              o["skipna"], ", constraints" if
                                              o.get("constraints") is not None else ""),
                          RuntimeWarning, stacklevel=4)
            fm = fm.rechunk({fm.ndim - 1: -1})
            chunked = False
    if chunked:
        y, pieces = _interp_chunked(fm, xf, qf, opt, halo, errors, **common)
        if errors == "nan" or certificate:
            comb = _combine_status(pieces)
            if errors == "nan":
                y = y.map_blocks(_mask_failed, comb[..., :1], dtype=y.dtype)
            if certificate:
                cert = comb
    elif _is_dask(fm):
        import dask.array as dsa
        out_dtype = np.float32 if fm.dtype == np.float32 else np.float64
        y = dsa.map_blocks(_chunk_task, fm, chunks=fm.chunks[:-1] + ((len(qf),),),
                           dtype=out_dtype, x=xf, q=qf, opt=opt, lo=0, errors=errors, **common)
        if certificate:
            cert = dsa.map_blocks(_status_block, fm, chunks=fm.chunks[:-1] + ((3,),),
                                  dtype=np.float64, x=xf, q=qf, opt=opt)
    else:
        fm = np.asarray(fm)
        y, st, ix, gap = _gufunc.interp(xf, fm, qf, opt)
        if errors == "raise":
            _raise_status(st, ix, other, coords, dim, old,
                          explain=(xf, fm, opt) if len(opt) > _gufunc.OPT_LEN else None)
        if certificate:
            cert = np.stack([st.astype(np.float64), ix.astype(np.float64), gap], axis=-1)
    if axis != f.ndim - 1:
        y = _moveaxis(y, -1, axis)
    out_coords = {k: v for k, v in da.coords.items() if dim not in v.dims}
    out_coords[dim] = (dim, newv, da[dim].attrs)
    result = xr.DataArray(y, dims=da.dims, coords=out_coords, name=da.name, attrs=da.attrs)
    if not certificate:
        return result
    cdims = tuple(other)
    cds = xr.Dataset({"status": (cdims, cert[..., 0].astype(np.int32)),
                      "index": (cdims, cert[..., 1].astype(np.int64)),
                      "gap": (cdims, cert[..., 2])},
                     coords={k: v for k, v in da.coords.items() if dim not in v.dims})
    cds["status"].attrs["description"] = "0: fitted and certified; else a ts_status code"
    cds["index"].attrs["description"] = "position along %r named by the status (-1: none)" % dim
    cds["gap"].attrs["description"] = "least certified gap of the series"
    if not _is_dask(cert):
        s = summary(cds)
        cds.attrs.update(all_certified=int(s["all_certified"]), least_gap=s["least_gap"])
    return result, cds


def _mask_failed(y, status):
    """errors='nan': a series whose fit failed is NaN (data gaps are local)."""
    keep = (status == STATUS_OK) | np.isin(status, DATA_GAPS)
    return np.where(keep, y, np.array(np.nan, dtype=y.dtype))


def _is_dask(a):
    return type(a).__module__.startswith("dask.")


def _moveaxis(a, src, dst):
    if _is_dask(a):
        import dask.array as dsa
        return dsa.moveaxis(a, src, dst)
    return np.moveaxis(a, src, dst)


def _split_kwargs(indexers, kwargs):
    coords = dict(indexers or {})
    coords.update(kwargs)
    if len(coords) != 1:
        raise ValueError("interpolate along exactly one dimension, got %s" % list(coords))
    return next(iter(coords.items()))


_DOC = """Interpolate along one dimension with certified trigonometric splines.

    The option keywords and their defaults are the package's one vocabulary
    (docs/options.md), shared with :func:`trigspline.interp`,
    :class:`trigspline.Spline` and :func:`trigspline.pandas.interpolate`.

    Parameters
    ----------
    indexers : dict, optional
        {dim: new coordinate values}; or give them as a keyword (time=...).
    shape : {'none', 'positive', 'above', 'below', 'between', 'monotone'}, default inferred
        The scheme.  Left out, it follows from the bounds: ``lower=0``
        alone ``'positive'`` (every output >= 0, zeros in the data allowed),
        another ``lower`` alone ``'above'``, ``upper`` alone ``'below'``,
        both ``'between'`` (kept strictly), neither ${shape}.
    lower, upper : float or (m, c), default none
        Bounds: a constant or the line y = m x + c.
    form : {'paper', 'c1', 'geometric'}, default ${form}
    alpha : float, default ${alpha}
    slopes : str, default ${slopes}
    margin : float, default ${margin}
    certify : bool, default ${certify}
        As for trigspline.Spline.
    extrapolate : {'error', 'nan', 'clamp', 'extend', 'linear', True, False}, default ${extrapolate}
        New coordinate values outside the old ones: ``'error'`` raises a
        ``TrigsplineError`` naming the first (before anything is computed),
        ``'nan'`` (``False``) gives NaN (as xarray's own interp), or the
        library's policies.
    skipna : bool, default ${skipna}
        ``False``: a missing value (NaN) stays local, as in xarray's own
        interp: each series is split at its NaN points into runs of finite
        values, each run of two or more points is a spline of its own, and
        the new values in an interval touching a NaN point are NaN (the
        others are the runs' values; beyond the data, the end runs
        extrapolate only when they reach the ends).  ``True``: the spline
        goes through the finite points, across the gaps (this makes a dask
        chunking along the dimension non-local: one chunk).  No warning
        either way; ``certificate=True`` reports a series with NaN as
        status 5 (TS_ERR_NONFINITE) at its first NaN position.
    errors : {'raise', 'nan'}, default ${errors}
        Data the scheme refuses (negative values for lower=0, points
        outside the lines, ...) raise ValueError naming the series and the
        position ('raise') or give NaN for that series ('nan').  A series
        with fewer than two points is NaN either way.
    constraints : list, default none
        Constraint records certified per interval of every series
        (docs/method.md §13), as for trigspline.Spline and
        trigspline.interp: ``['convex', 'decreasing', 'lower=0']``,
        ``'upper=poly:X,Y;X,Y'``, ``'slope<=5'``, ...  A refusal raises the
        library's sentence naming the record and the condition the data
        break (``errors='raise'``) or gives that series' status
        (``certificate=True``: 31 TS_ERR_CONDITION, 29 TS_ERR_UNPROVEN, ...).
        A dask array chunked along the dimension is fitted in one chunk
        (the records are not local).
    certificate : bool, default False
        Also return a Dataset with per-series ``status`` (0 = certified),
        ``index`` and ``gap`` (the least certified gap), and, when computed
        eagerly, attrs ``all_certified`` and ``least_gap``
        (see trigspline.xarray.summary).
    bounds : (lower, upper)
        Deprecated: give ``lower=`` and ``upper=``.
    """


def _resolve(bounds, lower, upper, shape, form, alpha, slopes, margin, extrapolate, skipna,
             certify, errors, constraints=None):
    lower, upper = _options.split_bounds(bounds, lower, upper)
    return resolve(shape, lower, upper, alpha=alpha, form=form, slopes=slopes,
                   extrapolate=extrapolate, margin=margin, skipna=skipna, certify=certify,
                   errors=errors, constraints=constraints)


class TrigsplineAccessor:
    """``DataArray.trigspline``: certified interpolation (see interp)."""

    def __init__(self, obj):
        self._obj = obj

    def interp(self, indexers=None, *, shape=None, lower=None, upper=None, form=None,
               alpha=None, slopes=None, margin=None, extrapolate=None, skipna=None,
               certify=None, errors=None, constraints=None, certificate=False, bounds=None,
               **kwargs):
        dim, new = _split_kwargs(indexers, kwargs)
        o = _resolve(bounds, lower, upper, shape, form, alpha, slopes, margin, extrapolate,
                     skipna, certify, errors, constraints)
        return _interp_dataarray(self._obj, dim, new, o, certificate)

    interp.__doc__ = _options.fill(_DOC)

    def disaggregate(self, indexers=None, **kwargs):
        from .histo_xarray import disaggregate_dataarray
        return disaggregate_dataarray(self._obj, indexers, **kwargs)


class TrigsplineDatasetAccessor:
    """``Dataset.trigspline``: every data variable holding the dimension is
    interpolated (numeric ones), the others are kept."""

    def __init__(self, obj):
        self._obj = obj

    def interp(self, indexers=None, *, shape=None, lower=None, upper=None, form=None,
               alpha=None, slopes=None, margin=None, extrapolate=None, skipna=None,
               certify=None, errors=None, constraints=None, certificate=False, bounds=None,
               **kwargs):
        dim, new = _split_kwargs(indexers, kwargs)
        ds = self._obj
        if dim not in ds.dims:
            raise ValueError("%r is not a dimension of this Dataset (dims %s)"
                             % (dim, tuple(ds.dims)))
        o = _resolve(bounds, lower, upper, shape, form, alpha, slopes, margin, extrapolate,
                     skipna, certify, errors, constraints)
        out, certs = {}, {}
        for name, var in ds.data_vars.items():
            if dim in var.dims and var.dtype.kind in "fiu":
                r = _interp_dataarray(var, dim, new, o, certificate)
                if certificate:
                    r, certs[name] = r
                out[name] = r
            elif dim not in var.dims:
                out[name] = var
        coords = {k: v for k, v in ds.coords.items() if dim not in v.dims}
        newv = np.asarray(new.values if isinstance(new, (xr.DataArray, xr.Variable)) else new)
        coords[dim] = (dim, newv, ds[dim].attrs)
        result = xr.Dataset(out, coords=coords, attrs=ds.attrs)
        if certificate:
            return result, certs
        return result

    interp.__doc__ = TrigsplineAccessor.interp.__doc__

    def disaggregate(self, indexers=None, **kwargs):
        from .histo_xarray import disaggregate_dataset
        return disaggregate_dataset(self._obj, indexers, **kwargs)


def _register():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # re-import: xarray warns about overriding
        xr.register_dataarray_accessor("trigspline")(TrigsplineAccessor)
        xr.register_dataset_accessor("trigspline")(TrigsplineDatasetAccessor)


_register()
