#!/usr/bin/env python3
"""Independent reference values for the slope estimates of docs/method.md §6.

Written from the published definitions, not from src/slopes.c:
  arithmetic  docs/method.md §6 (three-point mean, three-point ends)
  geometric   weighted geometric mean |D0|^w0 |D1|^w1 with the three-point
              weights w0 = h_i/(h_{i-1}+h_i), w1 = h_{i-1}/(h_{i-1}+h_i);
              0 unless D0, D1 have one sign; ends: three-point formula, 0 if
              its sign is not that of the end secant
  harmonic    weighted harmonic mean 1/d = w0/D0 + w1/D1, same weights/ends
  pchip       Fritsch-Carlson / Moler "Numerical Computing with MATLAB" pchip:
              Brodlie weights w1 = 2h_k + h_{k-1}, w2 = h_k + 2h_{k-1},
              d = (w1+w2)/(w1/D_{k-1} + w2/D_k); end formula
              ((2h1+h2)D1 - h1 D2)/(h1+h2), 0 if its sign differs from D1,
              3 D1 if D1, D2 differ in sign and |d| > |3 D1|
  akima       Akima (1970), ghost secants m_{-1} = 2m_0 - m_1,
              m_{-2} = 2m_{-1} - m_0 (and mirrored at the right end);
              0/0 -> (m_{i-1} + m_i)/2
  makima      Moler/Ionita (2019) weights |m_{i+1}-m_i| + |m_{i+1}+m_i|/2
  periodic    three-point mean with interval n-1 as left neighbour of point 0

Arithmetic is exact: the inputs are the exact binary values of the C doubles
(Fraction(float)), every method except the geometric mean is rational, and the
geometric mean uses decimal at 60 digits.  Standard library only.

Usage:  python3 slopes_ref.py          write slopes_ref.h next to this file
        python3 slopes_ref.py --check  exit 1 if slopes_ref.h is out of date
If numpy is importable, the pchip values are also cross-checked against a
vectorised re-statement of the textbook pchip formulas (float precision).
"""
import decimal
import os
import sys
from fractions import Fraction as Fr

decimal.getcontext().prec = 60
D = decimal.Decimal

METHODS = ["ARITHMETIC", "GEOMETRIC", "HARMONIC", "FRITSCH_CARLSON",
           "AKIMA", "MAKIMA", "USER", "PERIODIC"]


def sgn(v):
    return (v > 0) - (v < 0)


def secants(x, f):
    h = [x[i + 1] - x[i] for i in range(len(x) - 1)]
    return h, [(f[i + 1] - f[i]) / h[i] for i in range(len(h))]


def three_point_end(h0, h1, d0, d1):
    return d0 + (d0 - d1) * h0 / (h0 + h1)


def sign_limited(e, d0):
    return e if sgn(e) == sgn(d0) and d0 != 0 else Fr(0)


def arithmetic(x, f):
    h, m = secants(x, f)
    n = len(h)
    if n == 1:
        return [m[0], m[0]]
    d = [None] * (n + 1)
    for i in range(1, n):
        d[i] = (h[i] * m[i - 1] + h[i - 1] * m[i]) / (h[i - 1] + h[i])
    d[0] = three_point_end(h[0], h[1], m[0], m[1])
    d[n] = three_point_end(h[n - 1], h[n - 2], m[n - 1], m[n - 2])
    return d


def geometric(x, f):
    h, m = secants(x, f)
    n = len(h)
    if n == 1:
        return [m[0], m[0]]
    d = [None] * (n + 1)
    for i in range(1, n):
        a, b = m[i - 1], m[i]
        if a * b <= 0:
            d[i] = Fr(0)
            continue
        w0 = h[i] / (h[i - 1] + h[i])
        w1 = 1 - w0
        la = D(abs(a).numerator).ln() - D(abs(a).denominator).ln()
        lb = D(abs(b).numerator).ln() - D(abs(b).denominator).ln()
        g = (D(w0.numerator) / D(w0.denominator) * la
             + D(w1.numerator) / D(w1.denominator) * lb).exp()
        d[i] = g if a > 0 else -g
    d[0] = sign_limited(three_point_end(h[0], h[1], m[0], m[1]), m[0])
    d[n] = sign_limited(three_point_end(h[n - 1], h[n - 2], m[n - 1], m[n - 2]), m[n - 1])
    return d


def harmonic(x, f):
    h, m = secants(x, f)
    n = len(h)
    if n == 1:
        return [m[0], m[0]]
    d = [None] * (n + 1)
    for i in range(1, n):
        a, b = m[i - 1], m[i]
        if a * b <= 0:
            d[i] = Fr(0)
        else:
            d[i] = (h[i - 1] + h[i]) / (h[i] / a + h[i - 1] / b)
    d[0] = sign_limited(three_point_end(h[0], h[1], m[0], m[1]), m[0])
    d[n] = sign_limited(three_point_end(h[n - 1], h[n - 2], m[n - 1], m[n - 2]), m[n - 1])
    return d


def pchip_end(h1, h2, del1, del2):
    d = ((2 * h1 + h2) * del1 - h1 * del2) / (h1 + h2)
    if sgn(d) != sgn(del1):
        d = Fr(0)
    elif sgn(del1) != sgn(del2) and abs(d) > abs(3 * del1):
        d = 3 * del1
    return d


def pchip(x, f):
    h, delta = secants(x, f)
    n = len(h)
    if n == 1:
        return [delta[0], delta[0]]
    d = [Fr(0)] * (n + 1)
    for k in range(1, n):
        if sgn(delta[k - 1]) * sgn(delta[k]) > 0:
            w1 = 2 * h[k] + h[k - 1]
            w2 = h[k] + 2 * h[k - 1]
            d[k] = (w1 + w2) / (w1 / delta[k - 1] + w2 / delta[k])
    d[0] = pchip_end(h[0], h[1], delta[0], delta[1])
    d[n] = pchip_end(h[n - 1], h[n - 2], delta[n - 1], delta[n - 2])
    return d


def akima_family(x, f, modified):
    h, m = secants(x, f)
    n = len(h)
    if n == 1:
        return [m[0], m[0]]
    # extended list e[j + 2] = m_j, j = -2 .. n+1
    lm1 = 2 * m[0] - m[1]
    lm2 = 2 * lm1 - m[0]
    rp0 = 2 * m[n - 1] - m[n - 2]
    rp1 = 2 * rp0 - m[n - 1]
    e = [lm2, lm1] + list(m) + [rp0, rp1]
    d = []
    for i in range(n + 1):
        mm2, mm1, mi, mp1 = e[i], e[i + 1], e[i + 2], e[i + 3]
        w1 = abs(mp1 - mi)
        w2 = abs(mm1 - mm2)
        if modified:
            w1 += abs(mp1 + mi) / 2
            w2 += abs(mm1 + mm2) / 2
        if w1 + w2 == 0:
            d.append((mm1 + mi) / 2)
        else:
            d.append((w1 * mm1 + w2 * mi) / (w1 + w2))
    return d


def periodic(x, f):
    assert f[0] == f[-1]
    h, m = secants(x, f)
    n = len(h)
    d = [None] * (n + 1)
    for i in range(n + 1):
        il = (i - 1) % n        # interval on the left of point i (wraps)
        ir = i % n              # interval on the right (point n = point 0)
        d[i] = (h[ir] * m[il] + h[il] * m[ir]) / (h[il] + h[ir])
    return d


FUNCS = {
    "ARITHMETIC": arithmetic,
    "GEOMETRIC": geometric,
    "HARMONIC": harmonic,
    "FRITSCH_CARLSON": pchip,
    "AKIMA": lambda x, f: akima_family(x, f, False),
    "MAKIMA": lambda x, f: akima_family(x, f, True),
    "PERIODIC": periodic,
}

# (name, x literals, f literals).  The literals are written into the header
# verbatim, so C and Python start from the same doubles.
SETS = [
    # Fritsch & Carlson (1980), RPN 14 data: monotone, steep then flat
    ("rpn14",
     "7.99 8.09 8.19 8.7 9.2 10 12 15 20",
     "0 2.76429e-5 4.37498e-2 0.169183 0.469428 0.943740 0.998636 0.999919 0.999994"),
    # non-monotone, non-uniform, with a flat run and sign changes
    ("wavy",
     "0 0.5 1.7 2 3.1 4 4.4 6 7.25",
     "1 1.8 0.4 0.4 0.4 2.2 2.1 -0.5 0.3"),
    # closed data (f[0] == f[n]) on a non-uniform grid
    ("closed",
     "0 0.7 1.5 2.6 3.3 4.5 5.2 6",
     "0.5 1.2 0.9 -0.3 -1.1 -0.4 0.2 0.5"),
    # three points (n = 2)
    ("three",
     "0 1 3.5",
     "2 1 4"),
]


def compute():
    out = []
    for name, xs, fs in SETS:
        xl, fl = xs.split(), fs.split()
        x = [Fr(float(v)) for v in xl]
        f = [Fr(float(v)) for v in fl]
        res = {}
        for meth in METHODS:
            if meth == "USER" or (meth == "PERIODIC" and f[0] != f[-1]):
                continue
            res[meth] = [float(v) for v in FUNCS[meth](x, f)]
        out.append((name, xl, fl, res))
    return out


def render(data):
    L = ["/* Generated by tests/ref/slopes_ref.py -- do not edit.  Exact reference",
         " * slopes (docs/method.md §6) of the data sets below, correctly rounded to double. */",
         "#ifndef SLOPES_REF_H", "#define SLOPES_REF_H", "#include <stddef.h>", "",
         "typedef struct slopes_ref_set {",
         "    const char *name;",
         "    size_t np;",
         "    const double *x, *f;",
         "    const double *d[8]; /* by ts_slopes value; NULL: not computed */",
         "} slopes_ref_set;", ""]
    for name, xl, fl, res in data:
        np_ = len(xl)
        L.append("static const double slopes_ref_%s_x[%d] = {%s};" % (name, np_, ", ".join(xl)))
        L.append("static const double slopes_ref_%s_f[%d] = {%s};" % (name, np_, ", ".join(fl)))
        for meth, vals in res.items():
            L.append("static const double slopes_ref_%s_%s[%d] = {\n    %s};" % (
                name, meth.lower(), np_, ",\n    ".join(repr(v) for v in vals)))
        L.append("")
    L.append("static const slopes_ref_set slopes_ref_sets[%d] = {" % len(data))
    for name, xl, fl, res in data:
        ptrs = ", ".join(("slopes_ref_%s_%s" % (name, m.lower())) if m in res else "NULL"
                         for m in METHODS)
        L.append("    {\"%s\", %d, slopes_ref_%s_x, slopes_ref_%s_f,\n     {%s}}," % (
            name, len(xl), name, name, ptrs))
    L.append("};")
    L.append("#define SLOPES_REF_NSETS %d" % len(data))
    L.append("#endif")
    return "\n".join(L) + "\n"


def numpy_crosscheck(data):
    try:
        import numpy as np
    except ImportError:
        print("numpy not available: cross-check skipped")
        return True
    ok = True
    for name, xl, fl, res in data:
        x = np.array([float(v) for v in xl])
        y = np.array([float(v) for v in fl])
        hk = np.diff(x)
        mk = np.diff(y) / hk
        dk = np.zeros_like(x)
        smk = np.sign(mk)
        flat = (smk[1:] != smk[:-1]) | (mk[1:] == 0) | (mk[:-1] == 0)
        w1 = 2 * hk[1:] + hk[:-1]
        w2 = hk[1:] + 2 * hk[:-1]
        with np.errstate(divide="ignore", invalid="ignore"):
            whm = (w1 / mk[:-1] + w2 / mk[1:]) / (w1 + w2)
            dk[1:-1] = np.where(flat, 0.0, 1.0 / whm)

        def edge(h0, h1, m0, m1):
            d = ((2 * h0 + h1) * m0 - h0 * m1) / (h0 + h1)
            if np.sign(d) != np.sign(m0):
                return 0.0
            if np.sign(m0) != np.sign(m1) and abs(d) > abs(3 * m0):
                return 3 * m0
            return d
        dk[0] = edge(hk[0], hk[1], mk[0], mk[1])
        dk[-1] = edge(hk[-1], hk[-2], mk[-1], mk[-2])
        err = np.max(np.abs(dk - np.array(res["FRITSCH_CARLSON"])))
        scale = np.max(np.abs(mk))
        print("pchip cross-check %-7s max |diff| = %.3g (scale %.3g)" % (name, err, scale))
        if not err <= 1e-13 * scale:
            ok = False
    return ok


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    path = os.path.join(here, "slopes_ref.h")
    data = compute()
    text = render(data)
    ok = numpy_crosscheck(data)
    if "--check" in sys.argv[1:]:
        with open(path, encoding="utf-8") as fh:
            same = fh.read() == text
        print("slopes_ref.h " + ("up to date" if same else "OUT OF DATE"))
        return 0 if (same and ok) else 1
    with open(path, "w", encoding="utf-8") as fh:
        fh.write(text)
    print("wrote " + path)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
