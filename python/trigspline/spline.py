"""Spline: the GC¹ cubic trigonometric spline of a function (docs/method.md §3–§6)."""
import ctypes
import math

from . import _ffi
from ._ffi import lib
from ._util import (Handle, EXTRAPS, FORMS, SHAPES, SLOPE_ALIASES, SLOPES, TERMS, c_doubles,
                    enum_value, finish_output, float_list, given_output, input_array,
                    is_scalar, num, output_array, to_float)
from .errors import _S, TrigsplineError, domain_error, simple_error, spline_error, strerror

def _line(value, what):
    """(m, c) from any pair of numbers."""
    if value is None:
        return None
    try:
        items = list(value)
    except TypeError:
        raise TypeError("%s must be a pair (m, c) for the line y = m*x + c" % what) from None
    if len(items) != 2:
        raise ValueError("%s must be a pair (m, c) for the line y = m*x + c, got %d values"
                         % (what, len(items)))
    return (to_float(items[0], what + "[0]"), to_float(items[1], what + "[1]"))


def _per_interval(value, name, n):
    """(scalar, list or None) for a scalar-or-per-interval parameter."""
    if is_scalar(value):
        return to_float(value, name), None
    vals = float_list(value, name)
    if len(vals) != n:
        raise TrigsplineError(_S.LENGTH, "%s has %d values; a per-interval %s needs exactly "
                              "n = %d (one per interval)" % (name, len(vals), name, n))
    return 0.0, vals


def _report_dict(r):
    term = int(r.term)
    return {"x0": r.x0, "x1": r.x1, "alpha": r.alpha, "beta": r.beta, "a": r.a,
            "B": [r.B[k] for k in range(4)],
            "term": TERMS[term] if 0 <= term < len(TERMS) else term,
            "has_lower": bool(r.has_lower), "has_upper": bool(r.has_upper),
            "gap_lower": r.gap_lower, "at_lower": r.at_lower,
            "gap_upper": r.gap_upper, "at_upper": r.at_upper,
            "certified": bool(r.certified)}


def estimate_slopes(x, f, method="arithmetic"):
    """Slopes d_i of docs/method.md §6 at every point (ts_slopes_compute), as a list."""
    xs, fs = float_list(x, "x"), float_list(f, "f")
    if len(xs) != len(fs):
        raise TrigsplineError(_S.LENGTH, "x has %d values but f has %d" % (len(xs), len(fs)))
    m = enum_value(SLOPES, method, "method", SLOPE_ALIASES)
    if SLOPES[m] == "user":
        raise ValueError("method 'user' has nothing to estimate")
    cx, cf = c_doubles(xs), c_doubles(fs)
    out = c_doubles([0.0] * len(xs))
    err = _ffi.TsError()
    st = lib.ts_slopes_compute(m, cx.ptr, cf.ptr, len(xs), out.ptr, ctypes.byref(err))
    if st != 0:
        raise spline_error(err, {"x": xs, "f": fs})
    return [out.ptr[i] for i in range(len(xs))]


class Spline(Handle):
    """The spline through (x[i], f[i]).

    Spline(x, f, *, shape='none', alpha=1.0, beta=0.0, margin=None, line=None,
           lower=None, upper=None, slopes='arithmetic', form='paper',
           extrapolate='error', slopes_values=None, certify=True)

    shape        'none' (beta as given), 'positive', 'above' (line or lower),
                 'below' (line or upper), 'between' (lower and upper), 'monotone'
    alpha, beta  scalars or one value per interval; beta only with shape='none'
                 (the schemes choose beta)
    margin       the t of docs/method.md §5 (None = the library default 0.01), scalar or
                 per interval
    line, lower, upper  (m, c) for y = m*x + c
    slopes       'arithmetic', 'geometric', 'harmonic', 'fritsch_carlson'
                 ('pchip'), 'akima', 'makima', 'periodic'; slopes_values gives
                 your own d_i (one per point) instead
    form         'paper', 'c1' or 'geometric'
    extrapolate  'error', 'clamp', 'extend' or 'linear'
    certify      False skips the exact certificate where the scheme is a
                 proof by itself (ts_options.certify)

    Errors raise TrigsplineError (a ValueError) naming the point or interval.
    Free the C object with close() or a with-block; it is also freed when the
    Spline is garbage collected.
    """

    _free = "ts_spline_free"
    _kind = "Spline"

    def __init__(self, x, f, *, shape="none", alpha=1.0, beta=0.0, margin=None, line=None,
                 lower=None, upper=None, slopes="arithmetic", form="paper",
                 extrapolate="error", slopes_values=None, certify=True):
        self._h = None
        xs, fs = float_list(x, "x"), float_list(f, "f")
        if len(xs) != len(fs):
            raise TrigsplineError(_S.LENGTH, "x has %d values but f has %d" % (len(xs), len(fs)))
        n = max(len(xs) - 1, 0)
        opt = _ffi.TsOptions()
        lib.ts_options_init(ctypes.byref(opt))
        opt.form = enum_value(FORMS, form, "form")
        opt.extrapolate = enum_value(EXTRAPS, extrapolate, "extrapolate")
        shp = SHAPES[enum_value(SHAPES, shape, "shape")]
        opt.shape = SHAPES.index(shp)
        keep = []  # C arrays that must live until ts_spline_new returns

        # lines
        line, lower, upper = _line(line, "line"), _line(lower, "lower"), _line(upper, "upper")
        if shp == "above":
            if line is not None and lower is not None and line != lower:
                raise ValueError("shape='above': give line or lower, not both")
            lower = lower if lower is not None else line
            if lower is None or upper is not None:
                raise ValueError("shape='above' needs the line: line=(m, c)")
        elif shp == "below":
            if line is not None and upper is not None and line != upper:
                raise ValueError("shape='below': give line or upper, not both")
            upper = upper if upper is not None else line
            if upper is None or lower is not None:
                raise ValueError("shape='below' needs the line: line=(m, c)")
        elif shp == "between":
            if line is not None:
                raise ValueError("shape='between' takes lower=(m, c) and upper=(m, c), not line")
            if lower is None or upper is None:
                raise ValueError("shape='between' needs lower=(m, c) and upper=(m, c)")
        elif line is not None or lower is not None or upper is not None:
            raise ValueError("line, lower and upper go with shape='above', 'below' or "
                             "'between', not %r" % shp)
        if lower is not None:
            opt.lower.m, opt.lower.c = lower
        if upper is not None:
            opt.upper.m, opt.upper.c = upper
        if shp == "positive":
            lower = (0.0, 0.0)

        # alpha, beta, margin
        opt.alpha, al = _per_interval(alpha, "alpha", n)
        if al is not None:
            ca = c_doubles(al)
            keep.append(ca)
            opt.alphas, opt.n_alphas = ca.ptr, ca.n
        if shp == "none":
            opt.beta, bl = _per_interval(beta, "beta", n)
            if bl is not None:
                cb = c_doubles(bl)
                keep.append(cb)
                opt.betas, opt.n_betas = cb.ptr, cb.n
        elif not (is_scalar(beta) and float(beta) == 0.0):
            raise ValueError("beta is chosen by the shape scheme (shape=%r); leave it at 0 "
                             "and set alpha and margin instead" % shp)
        if margin is not None:
            opt.margin, ml = _per_interval(margin, "margin", n)
            if ml is not None:
                cm = c_doubles(ml)
                keep.append(cm)
                opt.margins, opt.n_margins = cm.ptr, cm.n

        # slopes
        sv = None
        if slopes_values is not None:
            if slopes not in ("arithmetic", "user"):
                raise ValueError("slopes_values gives the slopes: leave slopes at its default")
            sv = float_list(slopes_values, "slopes_values")
            if len(sv) != len(xs):
                raise TrigsplineError(_S.LENGTH, "slopes_values has %d values; it needs one "
                                      "per point (%d)" % (len(sv), len(xs)))
            cs = c_doubles(sv)
            keep.append(cs)
            opt.slopes = SLOPES.index("user")
            opt.user_slopes, opt.n_user_slopes = cs.ptr, cs.n
        else:
            opt.slopes = enum_value(SLOPES, slopes, "slopes", SLOPE_ALIASES)
            if SLOPES[opt.slopes] == "user":
                raise ValueError("slopes='user' needs slopes_values (one slope per point)")
        opt.certify = 1 if certify else 0

        cx, cf = c_doubles(xs), c_doubles(fs)
        handle = ctypes.c_void_p()
        err = _ffi.TsError()
        st = lib.ts_spline_new(cx.ptr, cf.ptr, len(xs), ctypes.byref(opt), ctypes.byref(handle),
                               ctypes.byref(err))
        self._ctx = {"x": xs, "f": fs, "shape": shp, "lower": lower, "upper": upper,
                     "slopes_values": sv}
        if st != 0:
            if st == _S.TOO_FEW:
                raise TrigsplineError(st, "too few points: %d given, at least 2 are needed"
                                      % len(xs))
            if st == _S.LENGTH:
                raise TrigsplineError(st, strerror(st))
            raise spline_error(err, self._ctx)
        self._h = handle
        self._n = int(lib.ts_spline_intervals(handle))
        self._x0 = xs[0]
        self._xn = xs[-1]
        self._extrap = EXTRAPS[opt.extrapolate]

    # ---- life time ------------------------------------------------------
    def __repr__(self):
        if self._h is None:
            return "<trigspline.Spline (closed)>"
        return "<trigspline.Spline %d intervals on [%s, %s], shape=%r, form=%r>" % (
            self._n, num(self._x0), num(self._xn), self.shape, self.form)

    # ---- accessors ------------------------------------------------------
    def _vector(self, fn, count):
        p = fn(self._handle())
        return tuple(p[i] for i in range(count))

    @property
    def intervals(self):
        """Number of intervals n (points - 1)."""
        self._handle()
        return self._n

    @property
    def knots(self):
        return self._vector(lib.ts_spline_x, self._n + 1)

    @property
    def values(self):
        return self._vector(lib.ts_spline_f, self._n + 1)

    @property
    def slopes(self):
        """The slopes d_i actually used (after any shape adjustment)."""
        return self._vector(lib.ts_spline_slopes, self._n + 1)

    @property
    def alpha(self):
        return self._vector(lib.ts_spline_alpha, self._n)

    @property
    def beta(self):
        return self._vector(lib.ts_spline_beta, self._n)

    @property
    def a(self):
        """a_i = alpha_i + beta_i per interval."""
        return tuple(al + be for al, be in zip(self.alpha, self.beta))

    @property
    def form(self):
        return FORMS[lib.ts_spline_form(self._handle())]

    @property
    def shape(self):
        return SHAPES[lib.ts_spline_shape(self._handle())]

    @property
    def extrapolate(self):
        return EXTRAPS[lib.ts_spline_extrapolation(self._handle())]

    @property
    def domain(self):
        return (self._x0, self._xn)

    def control(self, i):
        """(B, X): the control values B0..B3 of interval i and their abscissae."""
        B, X = (ctypes.c_double * 4)(), (ctypes.c_double * 4)()
        st = lib.ts_spline_control(self._handle(), int(i), B, X)
        if st != 0:
            raise simple_error(st, "interval %d does not exist (n = %d)" % (i, self._n), i,
                               "interval")
        return list(B), list(X)

    # ---- evaluation -----------------------------------------------------
    def __call__(self, x, derivative=0, *, threads=1, out=None):
        """S(x), S'(x) or S''(x) (derivative = 0, 1, 2).

        x: a number (returns a float), a numpy array (returns a new array of
        the same shape; the input is read in place, without a copy, when it
        is C-contiguous float64), an array.array('d') (returns one) or any
        other sequence (returns a list).  out: a writable C-contiguous float64
        numpy array or an array.array('d') with one element per query, filled
        in place and returned.  threads != 1 splits a batch over threads
        (None or 0: all cores)."""
        h = self._handle()
        if derivative not in (0, 1, 2):
            raise ValueError("derivative must be 0, 1 or 2, not %r" % (derivative,))
        d = int(derivative)
        if is_scalar(x):
            xv = to_float(x, "x")
            o = [ctypes.c_double(), ctypes.c_double(), ctypes.c_double()]
            st = lib.ts_eval_deriv(h, xv, None, ctypes.byref(o[0]),
                                   ctypes.byref(o[1]) if d >= 1 else None,
                                   ctypes.byref(o[2]) if d >= 2 else None)
            if st != 0:
                if st == _S.DOMAIN:
                    raise domain_error(xv, None, self._x0, self._xn, self._extrap)
                raise simple_error(st)
            return o[d].value
        xin, kind, shape = input_array(x, "x")
        if out is None:
            out, result = output_array(kind, shape, xin.n)
        else:
            out, result = given_output(out, xin.n)
            kind = "given"
        err = _ffi.TsError()
        if threads == 1:
            st = lib.ts_eval_batch(h, d, xin.ptr, xin.n, out.ptr, None, ctypes.byref(err))
        else:
            nt = 0 if threads is None else int(threads)
            if nt < 0:
                raise ValueError("threads must be >= 0 or None")
            st = lib.ts_eval_batch_mt(h, d, xin.ptr, xin.n, out.ptr, nt, ctypes.byref(err))
        if st != 0:
            if st == _S.DOMAIN and err.index != _ffi.NO_INDEX:
                j = int(err.index)
                raise domain_error(xin.ptr[j], j, self._x0, self._xn, self._extrap)
            raise simple_error(st)
        return finish_output(kind, result, xin.n)

    def integral(self, a, b):
        """Exact integral of S over [a, b] (b < a gives the negative)."""
        av, bv = to_float(a, "a"), to_float(b, "b")
        o = ctypes.c_double()
        st = lib.ts_integral(self._handle(), av, bv, ctypes.byref(o))
        if st != 0:
            if st == _S.DOMAIN:
                raise TrigsplineError(st, "integral bounds a = %s, b = %s must lie in [%s, %s]"
                                      % (num(av), num(bv), num(self._x0), num(self._xn)))
            raise simple_error(st)
        return o.value

    # ---- certificates ---------------------------------------------------
    @property
    def certified(self):
        """True when every interval of a shape-constrained spline is certified
        (False for shape='none': nothing was promised)."""
        return bool(lib.ts_spline_certified(self._handle()))

    def report(self):
        """One dict per interval (ts_spline_report): x0, x1, alpha, beta, a, B,
        term (which rule chose beta), has_lower/has_upper, gap_lower, at_lower,
        gap_upper, at_upper (exact minimum distance to each boundary and where),
        certified."""
        h = self._handle()
        r = _ffi.TsIntervalReport()
        out = []
        for i in range(self._n):
            st = lib.ts_spline_report(h, i, ctypes.byref(r))
            if st != 0:
                raise simple_error(st, None, i, "interval")
            out.append(_report_dict(r))
        return out

    def certify(self, lower=None, upper=None, *, report=False):
        """Exact check that lower < S < upper on every interval (ts_certify).

        lower/upper: (m, c) lines; with neither, the spline's own scheme lines
        (positive: y = 0).  Returns True/False, or (ok, list of report dicts)
        with report=True."""
        h = self._handle()
        lo, up = _line(lower, "lower"), _line(upper, "upper")
        if lo is None and up is None:
            lo, up = self._ctx["lower"], self._ctx["upper"]
            if lo is None and up is None:
                raise ValueError("certify needs lower=(m, c) and/or upper=(m, c) (this spline "
                                 "has no boundary of its own: shape=%r)" % self._ctx["shape"])
        lp = ctypes.byref(_ffi.TsLine(*lo)) if lo is not None else None
        upp = ctypes.byref(_ffi.TsLine(*up)) if up is not None else None
        reps = (_ffi.TsIntervalReport * max(self._n, 1))()
        err = _ffi.TsError()
        st = lib.ts_certify(h, lp, upp, reps, ctypes.byref(err))
        if st not in (0, _S.VIOLATED):
            raise simple_error(st, "certify: %s (lower = %r, upper = %r)" % (strerror(st), lo, up))
        ok = st == 0
        if report:
            return ok, [_report_dict(reps[i]) for i in range(self._n)]
        return ok

    def error_bound(self, fprime_max, fsecond_max=math.inf, exact_slopes=False,
                    per_interval=False):
        """Bound on max|f - S| for any f through the data with max|f'| <=
        fprime_max (ts_error_bound); with per_interval=True also the list."""
        per = (ctypes.c_double * max(self._n, 1))()
        b = ctypes.c_double()
        st = lib.ts_error_bound(self._handle(), to_float(fprime_max, "fprime_max"),
                                to_float(fsecond_max, "fsecond_max"), 1 if exact_slopes else 0,
                                ctypes.byref(b), per)
        if st != 0:
            raise simple_error(st)
        if per_interval:
            return b.value, [per[i] for i in range(self._n)]
        return b.value
