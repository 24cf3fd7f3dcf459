"""Curve: open and closed parametric curves in 2-D and 3-D (docs/method.md §7)."""
import ctypes

from . import _ffi
from ._ffi import lib
from ._util import (Handle, PARAMS, SLOPE_ALIASES, SLOPES, c_doubles, enum_value, float_list, is_scalar,
                    np, num, to_float, WHERE_NAMES)
from .errors import _S, TrigsplineError, simple_error, strerror
from .spline import _per_interval, _report_dict


def _rows(points):
    """points -> (list of tuples, dim)."""
    if np is not None and isinstance(points, np.ndarray):
        a = np.asarray(points, dtype=np.float64)
        if a.ndim != 2:
            raise TrigsplineError(_S.DIMENSION, "points must be a 2-D array (rows of 2 or 3 "
                                  "coordinates), got shape %r" % (a.shape,))
        rows = [tuple(float(v) for v in r) for r in a]
        dim = a.shape[1]
    else:
        if isinstance(points, (str, bytes)):
            raise TypeError("points must be a sequence of points")
        rows = [tuple(float_list(p, "point %d" % i)) for i, p in enumerate(points)]
        dims = set(len(r) for r in rows)
        if len(dims) > 1:
            raise TrigsplineError(_S.DIMENSION, "points have different numbers of coordinates: "
                                  "%s" % sorted(dims))
        dim = dims.pop() if dims else 2
    if dim not in (2, 3):
        raise TrigsplineError(_S.DIMENSION, "points need 2 or 3 coordinates, not %d" % dim)
    return rows, dim


def _pt(row):
    return "(" + ", ".join(num(v) for v in row) + ")"


def _box(box, dim):
    """Box -> (has_lo, lo, has_hi, hi) lists of 3."""
    has_lo, lo, has_hi, hi = [0] * 3, [0.0] * 3, [0] * 3, [0.0] * 3
    items = list(box)
    if len(items) != dim:
        raise ValueError("box needs one (lo, hi) pair per coordinate (%d), got %d"
                         % (dim, len(items)))
    for k, pair in enumerate(items):
        if pair is None:
            continue
        pair = list(pair)
        if len(pair) != 2:
            raise ValueError("box[%d] must be a pair (lo, hi); use None for an open side" % k)
        if pair[0] is not None:
            has_lo[k], lo[k] = 1, to_float(pair[0], "box[%d][0]" % k)
        if pair[1] is not None:
            has_hi[k], hi[k] = 1, to_float(pair[1], "box[%d][1]" % k)
    return has_lo, lo, has_hi, hi


class Curve(Handle):
    """The trigonometric spline curve through points (rows of 2 or 3 coordinates).

    Curve(points, *, closed=False, param='centripetal', alpha=1.0, beta=0.0,
          box=None, slopes='arithmetic', margin=None)

    param   'centripetal', 'chord' or 'uniform' (parameter knots, t_0 = 0)
    closed  a closed curve (the first point may be repeated at the end or not)
    alpha, beta  scalars or one value per segment
    box     one (lo, hi) pair per coordinate, None for an open side: each
            coordinate kept strictly inside (beta raised where needed, certified)
    """

    _free = "ts_curve_free"
    _kind = "Curve"

    def __init__(self, points, *, closed=False, param="centripetal", alpha=1.0, beta=0.0,
                 box=None, slopes="arithmetic", margin=None):
        self._h = None
        rows, dim = _rows(points)
        npts = len(rows)
        if closed:
            segs = npts - 1 if npts >= 2 and rows[0] == rows[-1] else npts
        else:
            segs = max(npts - 1, 0)
        opt = _ffi.TsCurveOptions()
        lib.ts_curve_options_init(ctypes.byref(opt))
        opt.param = enum_value(PARAMS, param, "param")
        opt.closed = 1 if closed else 0
        opt.slopes = enum_value(SLOPES, slopes, "slopes", SLOPE_ALIASES)
        keep = []
        opt.alpha, al = _per_interval(alpha, "alpha", segs)
        if al is not None:
            ca = c_doubles(al)
            keep.append(ca)
            opt.alphas, opt.n_alphas = ca.ptr, ca.n
        opt.beta, bl = _per_interval(beta, "beta", segs)
        if bl is not None:
            cb = c_doubles(bl)
            keep.append(cb)
            opt.betas, opt.n_betas = cb.ptr, cb.n
        if box is not None:
            has_lo, lo, has_hi, hi = _box(box, dim)
            for k in range(3):
                opt.has_lo[k], opt.lo[k] = has_lo[k], lo[k]
                opt.has_hi[k], opt.hi[k] = has_hi[k], hi[k]
        if margin is not None:
            opt.margin = to_float(margin, "margin")
        self._box = box
        flat = c_doubles([v for r in rows for v in r])
        handle = ctypes.c_void_p()
        err = _ffi.TsError()
        st = lib.ts_curve_new(flat.ptr, npts, dim, ctypes.byref(opt), ctypes.byref(handle),
                              ctypes.byref(err))
        if st != 0:
            raise self._error(err, rows)
        self._h = handle
        self._n = int(lib.ts_curve_segments(handle))
        self._dim = dim

    @staticmethod
    def _error(err, rows):
        st = int(err.status)
        where = WHERE_NAMES[err.where] if 0 <= err.where < len(WHERE_NAMES) else None
        idx = None if err.index == _ffi.NO_INDEX else int(err.index)
        base = strerror(st)
        msg = base
        if st == _S.TOO_FEW:
            msg = "too few points: %d given; an open curve needs 2, a closed one 3 distinct" \
                  % len(rows)
        elif idx is not None and where == "point" and idx < len(rows):
            loc = "point %d %s" % (idx, _pt(rows[idx]))
            if st == _S.SIDE:
                msg = "%s lies on or outside the box" % loc
            elif st == _S.UNSORTED:
                msg = "%s repeats its neighbour: consecutive points must differ" % loc
            else:
                msg = "%s: %s" % (loc, base)
            where = "point"
        elif idx is not None and where == "interval":
            msg = "segment %d: %s" % (idx, base)
        elif idx is not None and where is not None:
            msg = "%s %d: %s" % (where, idx, base)
        return TrigsplineError(st, msg, idx, where)

    # ---- life time ------------------------------------------------------
    def __repr__(self):
        if self._h is None:
            return "<trigspline.Curve (freed)>"
        return "<trigspline.Curve %s, %d segments in %d-D>" % (
            "closed" if self.closed else "open", self._n, self._dim)

    # ---- accessors ------------------------------------------------------
    @property
    def segments(self):
        self._handle()
        return self._n

    @property
    def dim(self):
        self._handle()
        return self._dim

    @property
    def closed(self):
        """True for a closed curve."""
        return bool(lib.ts_curve_closed(self._handle()))

    @property
    def knots(self):
        p = lib.ts_curve_knots(self._handle())
        return tuple(p[i] for i in range(self._n + 1))

    def _params(self):
        h = self._handle()
        al, be = ctypes.c_double(), ctypes.c_double()
        out = []
        for i in range(self._n):
            lib.ts_curve_params(h, i, ctypes.byref(al), ctypes.byref(be))
            out.append((al.value, be.value))
        return out

    @property
    def alpha(self):
        return tuple(p[0] for p in self._params())

    @property
    def beta(self):
        """beta_i per segment (with a box: the computed ones)."""
        return tuple(p[1] for p in self._params())

    def control(self, i):
        """The 4 control points of segment i, as tuples."""
        c = (ctypes.c_double * (4 * self._dim))()
        st = lib.ts_curve_control(self._handle(), int(i), c)
        if st != 0:
            raise simple_error(st, "segment %d does not exist (%d segments)" % (i, self._n), i,
                               "interval")
        d = self._dim
        return [tuple(c[l * d:(l + 1) * d]) for l in range(4)]

    # ---- evaluation -----------------------------------------------------
    def _eval_one(self, h, t, d, cur, bufs, j=None):
        st = lib.ts_curve_eval(h, t, cur, bufs[0], bufs[1] if d >= 1 else None,
                               bufs[2] if d >= 2 else None)
        if st != 0:
            if st == _S.DOMAIN:
                kn = self.knots
                what = "query %d (t = %s)" % (j, num(t)) if j is not None else "t = %s" % num(t)
                why = ("is NaN or infinite" if not (t == t and abs(t) != float("inf"))
                       else "lies outside [%s, %s] (open curve)" % (num(kn[0]), num(kn[-1])))
                raise TrigsplineError(st, "%s %s" % (what, why), j, "query")
            raise simple_error(st)
        return tuple(bufs[d])

    def __call__(self, t, derivative=0):
        """Point (derivative 0) or its first/second derivative in t.

        t a number: a tuple of dim floats; a numpy array: an array of shape
        t.shape + (dim,); another sequence: a list of tuples.  Closed curves
        wrap t periodically."""
        h = self._handle()
        if derivative not in (0, 1, 2):
            raise ValueError("derivative must be 0, 1 or 2, not %r" % (derivative,))
        d = int(derivative)
        bufs = [(ctypes.c_double * self._dim)() for _ in range(3)]
        if is_scalar(t):
            return self._eval_one(h, to_float(t, "t"), d, None, bufs)
        cur = _ffi.TsCursor(0)
        cp = ctypes.byref(cur)
        if np is not None and isinstance(t, np.ndarray):
            ta = np.asarray(t, dtype=np.float64)
            out = np.empty(ta.shape + (self._dim,), dtype=np.float64)
            flat_out = out.reshape(-1, self._dim)
            for j, tv in enumerate(ta.ravel()):
                flat_out[j] = self._eval_one(h, float(tv), d, cp, bufs, j)
            return out
        return [self._eval_one(h, tv, d, cp, bufs, j)
                for j, tv in enumerate(float_list(t, "t"))]

    def length(self, tol=0.0):
        """Arc length (ts_curve_length; tol <= 0 means 1e-12 relative)."""
        v = ctypes.c_double()
        st = lib.ts_curve_length(self._handle(), to_float(tol, "tol"), ctypes.byref(v))
        if st != 0:
            raise simple_error(st)
        return v.value

    def sample(self, m=32, array=False):
        """m samples per segment, knots included: rows (t, x, y[, z]).

        A list of tuples, or with array=True a numpy array (rows, 1 + dim)."""
        h = self._handle()
        m = int(m)
        if m < 2:
            raise simple_error(_S.OPTION, "sample needs m >= 2 samples per segment, not %d" % m)
        rows = ctypes.c_size_t()
        st = lib.ts_curve_sample(h, m, None, 0, ctypes.byref(rows))
        if st not in (0, _S.LENGTH):
            raise simple_error(st)
        nr, w = rows.value, 1 + self._dim
        if array:
            if np is None:
                raise ImportError("sample(array=True) needs numpy")
            out = np.empty((nr, w), dtype=np.float64)
            ptr = out.ctypes.data_as(ctypes.POINTER(ctypes.c_double))
        else:
            out = (ctypes.c_double * (nr * w))()
            ptr = out
        st = lib.ts_curve_sample(h, m, ptr, nr * w, ctypes.byref(rows))
        if st != 0:
            raise simple_error(st)
        if array:
            return out
        return [tuple(out[r * w:(r + 1) * w]) for r in range(nr)]

    def certify(self, box=None, *, report=False):
        """Exact check that every coordinate stays inside the box (by default
        the curve's own; True when it has none).  True/False, or (ok, list of
        report dicts, entry i*dim + k for segment i, coordinate k) with
        report=True."""
        h = self._handle()
        reps = (_ffi.TsIntervalReport * max(self._n * self._dim, 1))()
        err = _ffi.TsError()
        if box is None:
            st = lib.ts_curve_certify(h, reps, ctypes.byref(err))
        else:
            has_lo, lo, has_hi, hi = _box(box, self._dim)
            st = lib.ts_curve_certify_box(h, (ctypes.c_int * 3)(*has_lo),
                                          (ctypes.c_double * 3)(*lo),
                                          (ctypes.c_int * 3)(*has_hi),
                                          (ctypes.c_double * 3)(*hi), reps, ctypes.byref(err))
        if st not in (0, _S.VIOLATED):
            raise simple_error(st)
        ok = st == 0
        if report:
            return ok, [_report_dict(reps[i]) for i in range(self._n * self._dim)]
        return ok
