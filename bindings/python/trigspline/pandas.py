"""pandas: ``trigspline.pandas.interpolate(series, index=new_index, shape='positive')``.

A Series, or every numeric column of a DataFrame, interpolated at a new index
by one certified spline per column (``trigspline.interp``).  A DatetimeIndex
is fitted as float seconds since its first timestamp (time zones: the new
index is converted to the old one's zone first).
"""
import numpy as np
import pandas as pd

from . import _options
from .errors import _S, TrigsplineError
from .interp import DATA_GAPS, STATUS_OK, interp, resolve, sentence, status_message
from .interp import pack as interp_pack

__all__ = ["interpolate"]


def _as_float(index, epoch):
    if isinstance(index, pd.DatetimeIndex):
        return (index - epoch) / pd.Timedelta(seconds=1)
    if isinstance(index, pd.TimedeltaIndex):
        return index / pd.Timedelta(seconds=1)
    return np.asarray(index, dtype=np.float64)


def _check_index(index, xf):
    bad = ~np.isfinite(xf)
    if bad.any():
        i = int(np.argmax(bad))
        raise ValueError("index value %r at position %d is not finite" % (index[i], i))
    if xf.size > 1 and not (np.diff(xf) > 0).all():
        i = int(np.argmax(~(np.diff(xf) > 0))) + 1
        raise ValueError("index is not strictly increasing: position %d (%s) follows "
                         "position %d (%s)" % (i, index[i], i - 1, index[i - 1]))


def interpolate(obj, index, *, shape=None, lower=None, upper=None, form=None, alpha=None,
                slopes=None, margin=None, extrapolate=None, skipna=None, certify=None,
                errors=None, constraints=None, bounds=None):
    """Interpolate a Series or DataFrame at ``index``.

    The option keywords and their defaults are the package's one vocabulary
    (docs/options.md), those of :func:`trigspline.interp` and
    ``DataArray.trigspline.interp``.

    Parameters
    ----------
    obj : pandas.Series or pandas.DataFrame
        Indexed by a strictly increasing DatetimeIndex, TimedeltaIndex or
        numeric index.
    index : array_like or Index
        The new index (same kind as the old one).
    shape : {'none', 'positive', 'above', 'below', 'between', 'monotone'}, default inferred
        Left out, it follows from the bounds: ``lower=0`` alone
        ``'positive'``, another ``lower`` alone ``'above'``, ``upper`` alone
        ``'below'``, both ``'between'``, neither ${shape}.
    lower, upper : float or (m, c), default none
    form : {'paper', 'c1', 'geometric'}, default ${form}
    alpha : float, default ${alpha}
    slopes : str, default ${slopes}
    margin : float, default ${margin}
    certify : bool, default ${certify}
        As for ``DataArray.trigspline.interp``.
    extrapolate : {'error', 'nan', 'clamp', 'extend', 'linear', True, False}, default ${extrapolate}
        New index values outside the old ones: ``'error'`` raises a
        ``TrigsplineError`` naming the first, ``'nan'`` gives NaN, or the
        library's policies.
    skipna : bool, default ${skipna}
        ``False``: a NaN stays local (as in xarray's interp): each column
        is split at its NaN values into runs, each run of two or more
        values is fitted on its own, and new index values in an interval
        touching a NaN get NaN.  ``True``: fit through the finite values
        only, across the gaps (as pandas' own ``interpolate`` fills them).
    errors : {'raise', 'nan'}, default ${errors}
        Data the scheme refuses raise ValueError naming the column and the
        index value, or give a NaN column.
    constraints : list, default none
        Constraint records certified per interval of every column
        (docs/method.md §13), as for ``trigspline.interp``; a refusal
        raises the library's sentence naming the record and the condition.
    bounds : (lower, upper)
        Deprecated: give ``lower=`` and ``upper=``.

    Returns
    -------
    The same type, on the new index; name, column labels and attrs kept.
    """
    lower, upper = _options.split_bounds(bounds, lower, upper)
    o = resolve(shape, lower, upper, alpha=alpha, form=form, slopes=slopes,
                extrapolate=extrapolate, margin=margin, skipna=skipna, certify=certify,
                errors=errors, constraints=constraints)
    if not isinstance(obj, (pd.Series, pd.DataFrame)):
        raise TypeError("interpolate takes a pandas Series or DataFrame, not %s"
                        % type(obj).__name__)
    old = obj.index
    new = pd.Index(index)
    if isinstance(old, pd.DatetimeIndex):
        if not isinstance(new, pd.DatetimeIndex):
            new = pd.DatetimeIndex(new)
        if old.tz is not None or new.tz is not None:
            new = new.tz_convert(old.tz) if new.tz is not None else new.tz_localize(old.tz)
        epoch = old[0] if len(old) else None
    else:
        epoch = None
    xf = np.asarray(_as_float(old, epoch), dtype=np.float64)
    _check_index(old, xf)
    qf = np.asarray(_as_float(new, epoch), dtype=np.float64)
    if o["extrapolate"] == "error" and xf.size:
        with np.errstate(invalid="ignore"):
            out = (qf < xf[0]) | (qf > xf[-1])
        if out.any():
            i = int(np.argmax(out))
            raise TrigsplineError(_S.DOMAIN, "index value %s (position %d) lies outside [%s, "
                                  "%s] (extrapolate='error'; 'nan' gives NaN outside)"
                                  % (new[i], i, old[0], old[-1]), i, "query")
    frame = obj.to_frame() if isinstance(obj, pd.Series) else obj
    cols = [c for c in frame.columns if frame[c].dtype.kind in "fiu"]
    out = {}
    # float32 columns stay float32 (one gufunc call per dtype)
    for dtype in (np.float32, np.float64):
        group = [c for c in cols if (frame[c].dtype == np.float32) == (dtype == np.float32)]
        if not group:
            continue
        data = np.stack([np.asarray(frame[c], dtype=dtype) for c in group])
        r = interp(xf, data, qf, shape=o["shape"], lower=o["lower"], upper=o["upper"],
                   alpha=o["alpha"], form=o["form"], slopes=o["slopes"],
                   extrapolate="nan" if o["extrapolate"] == "error" else o["extrapolate"],
                   margin=o["margin"], skipna=o["skipna"], certify=o["certify"],
                   errors="nan", full=True, constraints=constraints)
        if o["errors"] == "raise":
            bad = (r.status != STATUS_OK) & ~np.isin(r.status, DATA_GAPS)
            if bad.any():
                j = int(np.argmax(bad))
                i = int(r.index[j])
                at = " at %s (position %d)" % (old[i], i) if 0 <= i < len(old) else ""
                if o["constraints"] is not None:  # the library's sentence: record, condition
                    raise ValueError("column %r: %s" % (group[j], sentence(
                        r.status[j], i, xf, data[j], interp_pack(o))))
                raise ValueError("column %r: %s%s" % (group[j], status_message(r.status[j]), at))
        for j, c in enumerate(group):
            out[c] = r.values[j]
    if isinstance(obj, pd.Series):
        res = pd.Series(out[obj.name if obj.name is not None else 0] if cols else np.nan,
                        index=new, name=obj.name)
    else:
        res = pd.DataFrame({c: out.get(c, np.nan) for c in frame.columns}, index=new,
                           columns=frame.columns)
    res.attrs = dict(obj.attrs)
    return res


_options.document(interpolate)
