/* docs/method.md §6: slope estimates d_0..d_n.  Method details: comments at enum ts_slopes
 * in trigspline.h.  Secants are recomputed where needed: nothing is allocated. */
#include "internal.h"

#include <float.h>
#include <math.h>

/* (f1 − f0)/h, finite whenever the secant is: where f1 − f0 overflows (f of
 * both signs near ±DBL_MAX) the halves are subtracted (exact scaling).  One
 * division, the numerator and the factor 2 selected around it (the same
 * operations on each path), so that loops of it vectorise. */
TS_INLINE double secant_of(double f0, double f1, double h)
{
    double df = f1 - f0, half = 0.5 * f1 - 0.5 * f0;
    int ok = fabs(df) <= DBL_MAX;
    return (ok ? 1.0 : 2.0) * ((ok ? df : half) / h);
}

/* Δ_j, j = 0..n-1 (docs/method.md §1). */
static double secant(const double *x, const double *f, size_t j)
{
    return secant_of(f[j], f[j + 1], x[j + 1] - x[j]);
}

static int same_sign(double p, double q)
{
    return (p > 0.0 && q > 0.0) || (p < 0.0 && q < 0.0);
}

/* a / (a + b) for widths a, b > 0, also when a + b overflows (x near ±DBL_MAX):
 * halving both is exact there. */
static double share(double a, double b)
{
    double s = a + b;
    if (!(s <= DBL_MAX)) {
        a *= 0.5;
        b *= 0.5;
        s = a + b;
    }
    return a / s;
}

/* docs/method.md §6 three-point end formula at the end whose interval has width h0 and
 * secant D0, next interval h1, D1. */
static double end3(double h0, double h1, double D0, double D1)
{
    double t = (D0 - D1) * h0 / (h0 + h1);
    if (isfinite(h0 + h1) && isfinite((D0 - D1) * h0))
        return D0 + t;
    /* the same without an intermediate overflow (D0 − D1 or (D0 − D1) h0):
     * in quarters, |D0/4| + share·|D0/4 − D1/4| <= 3/4 DBL_MAX, so the
     * result overflows only where the end slope itself does */
    double q0 = 0.25 * D0, q1 = 0.25 * D1;
    return 4.0 * (q0 + (q0 - q1) * share(h0, h1));
}

/* docs/method.md §6 arithmetic mean of Dl = Δ_{i-1}, Dr = Δ_i with the three-point
 * weights hr/(hl + hr), hl/(hl + hr); both widths halved (exactly) when their
 * sum overflows, as share() does.  Branch-free, so that loops vectorise. */
TS_INLINE double mean_arith3(double hl, double hr, double Dl, double Dr)
{
    double sc = hr + hl <= DBL_MAX ? 1.0 : 0.5;
    double a = sc * hr, b = sc * hl, s = a + b;
    return Dl == Dr ? Dl : (a / s) * Dl + (b / s) * Dr;
}

/* Weighted means of D0 = Δ_{i-1}, D1 = Δ_i with weights w0 + w1 = 1. */

static double mean_geom(double D0, double D1, double w0, double w1)
{
    if (!same_sign(D0, D1))
        return 0.0;
    if (D0 == D1)
        return D0;
    double a = fabs(D0), b = fabs(D1), g;
    double r = b / a;
    if (isnormal(r))
        g = a * pow(r, w1);
    else /* ratio over/underflows: go through logarithms */
        g = exp(w0 * log(a) + w1 * log(b));
    return D0 > 0.0 ? g : -g;
}

static double mean_harm(double D0, double D1, double w0, double w1)
{
    if (!same_sign(D0, D1))
        return 0.0;
    if (D0 == D1)
        return D0;
    /* 1/d = w0/D0 + w1/D1, divided through by the secant of larger size so
     * the ratio is <= 1: no overflow for tiny or huge secants */
    if (fabs(D0) <= fabs(D1))
        return D0 / (w0 + w1 * (D0 / D1));
    return D1 / (w1 + w0 * (D1 / D0));
}

/* Weights (on Δ_{i-1}, Δ_i) at inner point i. */
static void weights_three_point(const double *x, size_t i, double *w0, double *w1)
{
    double hl = x[i] - x[i - 1], hr = x[i + 1] - x[i];
    *w0 = share(hr, hl);
    *w1 = share(hl, hr);
}

static void weights_brodlie(const double *x, size_t i, double *w0, double *w1)
{
    double hl = x[i] - x[i - 1], hr = x[i + 1] - x[i];
    if (hl > 0x1p1000 || hr > 0x1p1000) { /* 3(hl + hr) could overflow; exact scaling */
        hl *= 0x1p-4;
        hr *= 0x1p-4;
    }
    double a = 2.0 * hr + hl, b = hr + 2.0 * hl;
    *w0 = a / (a + b);
    *w1 = b / (a + b);
}

/* Interior d_i, i in [p0, p1) ∩ [1, n-1], by one of the three means with the
 * given weights. */
static void interior(const double *x, const double *f, size_t n, double *d,
                     double (*mean)(double, double, double, double),
                     void (*weights)(const double *, size_t, double *, double *), size_t p0,
                     size_t p1)
{
    size_t lo = p0 > 1 ? p0 : 1, hi = p1 < n ? p1 : n; /* lo <= n: p0 <= n */
    double Dl = secant(x, f, lo - 1);
    for (size_t i = lo; i < hi; i++) {
        double Dr = secant(x, f, i), w0, w1;
        weights(x, i, &w0, &w1);
        d[i] = mean(Dl, Dr, w0, w1);
        Dl = Dr;
    }
}

/* The same for the arithmetic mean with three-point weights (the default),
 * in a loop that vectorises. */
TS_VECTOR_LOOP static void interior_arith(const double *restrict x, const double *restrict f,
                                          size_t n, double *restrict d, size_t p0, size_t p1)
{
    size_t lo = p0 > 1 ? p0 : 1, hi = p1 < n ? p1 : n;
    for (size_t i = lo; i < hi; i++) {
        double hl = x[i] - x[i - 1], hr = x[i + 1] - x[i];
        d[i] = mean_arith3(hl, hr, secant_of(f[i - 1], f[i], hl), secant_of(f[i], f[i + 1], hr));
    }
}

/* Both ends by the three-point formula; limit 0: sign-limited (d = 0 unless d
 * has the sign of the end secant); limit 1: also Fritsch–Carlson/Moler's
 * |d| <= 3|Δ| when the two end secants differ in sign; limit 2: also
 * Steffen's |d| <= 2|Δ| (his eq. 26). */
static void ends3(const double *x, const double *f, size_t n, double *d, int limit, size_t p0,
                  size_t p1)
{
    for (int side = 0; side < 2; side++) {
        if (side == 0 ? p0 > 0 : p1 <= n)
            continue; /* that end is outside [p0, p1) */
        double h0, h1, D0, D1;
        if (side == 0) {
            h0 = x[1] - x[0];
            h1 = x[2] - x[1];
            D0 = secant(x, f, 0);
            D1 = secant(x, f, 1);
        } else {
            h0 = x[n] - x[n - 1];
            h1 = x[n - 1] - x[n - 2];
            D0 = secant(x, f, n - 1);
            D1 = secant(x, f, n - 2);
        }
        double e = end3(h0, h1, D0, D1);
        if (limit >= 0 && !same_sign(e, D0))
            e = 0.0;
        else if (limit == 1 && !same_sign(D0, D1) && fabs(e) > fabs(3.0 * D0))
            e = 3.0 * D0;
        else if (limit == 2 && fabs(e) > 2.0 * fabs(D0))
            e = 2.0 * D0;
        d[side == 0 ? 0 : n] = e;
    }
}

/* Akima's extended secants m_j, j = -2..n+1 (n >= 2): ghosts continue the
 * secants linearly, m_{-1} = 2 m_0 - m_1, m_{-2} = 2 m_{-1} - m_0 (Akima 1970). */
static double akima_m(const double *x, const double *f, size_t n, long j)
{
    if (j >= 0 && (size_t)j < n)
        return secant(x, f, (size_t)j);
    double a, b;
    if (j < 0) {
        a = secant(x, f, 0);
        b = secant(x, f, 1);
    } else {
        a = secant(x, f, n - 1);
        b = secant(x, f, n - 2);
    }
    double g1 = 2.0 * a - b;
    if (j == -1 || (j >= 0 && (size_t)j == n))
        return g1;
    return 2.0 * g1 - a;
}

static void akima(const double *x, const double *f, size_t n, double *d, int modified, size_t p0,
                  size_t p1)
{
    for (size_t i = p0; i < p1; i++) {
        long k = (long)i;
        double m0 = akima_m(x, f, n, k - 2), m1 = akima_m(x, f, n, k - 1);
        double m2 = akima_m(x, f, n, k), m3 = akima_m(x, f, n, k + 1);
        if (m1 == m2) {
            d[i] = m1;
            continue;
        }
        double w1, w2, s;
        for (double sc = 1.0;; sc = 0.125) { /* sc: huge secants, weights overflow */
            double a0 = sc * m0, a1 = sc * m1, a2 = sc * m2, a3 = sc * m3;
            w1 = fabs(a3 - a2);
            w2 = fabs(a1 - a0);
            if (modified) { /* Moler 2019 */
                w1 += 0.5 * fabs(a3 + a2);
                w2 += 0.5 * fabs(a1 + a0);
            }
            s = w1 + w2;
            if (isfinite(s) || sc != 1.0)
                break;
        }
        if (s == 0.0) /* Akima's 0/0: the plain average */
            d[i] = 0.5 * m1 + 0.5 * m2;
        else
            d[i] = (w1 / s) * m1 + (w2 / s) * m2;
    }
}

/* docs/method.md §6 periodic: three-point mean, interval n-1 is the left neighbour of point 0. */
static void periodic(const double *x, const double *f, size_t n, double *d, size_t p0, size_t p1)
{
    interior_arith(x, f, n, d, p0, p1);
    if (p0 > 0 && p1 <= n)
        return;
    double e = mean_arith3(x[n] - x[n - 1], x[1] - x[0], secant(x, f, n - 1), secant(x, f, 0));
    if (p0 == 0)
        d[0] = e;
    if (p1 > n)
        d[n] = e;
}

/* Secants Δ_j, j in [j0, j1), into S[j − j0], in a loop that vectorises. */
TS_VECTOR_LOOP static void secants(const double *restrict x, const double *restrict f, size_t j0,
                                   size_t j1, double *restrict S)
{
    for (size_t j = j0; j < j1; j++)
        S[j - j0] = secant_of(f[j], f[j + 1], x[j + 1] - x[j]);
}

/* docs/method.md §6 Steffen (1990): inner d_i = (sgn Δ_{i-1} + sgn Δ_i)
 * min(|Δ_{i-1}|, |Δ_i|, |p_i|/2), p_i the three-point slope; 2 min(..) <= |p_i|,
 * so no overflow; i in [i0, i1), Δ_j = S[j − i0 + 1].  Branch-free, so that
 * it vectorises: where the signs differ the mean is taken of 1 and 1 (no
 * exception from secants it does not need) and d_i = 0 selected.  fmin of
 * non-negative numbers (no NaN: the secants of one sign are not infinite
 * of both signs) is the smaller, either zero +0. */
TS_VECTOR_LOOP static void steffen_inner(const double *restrict x, const double *restrict S,
                                         size_t i0, size_t i1, double *restrict d)
{
    for (size_t i = i0; i < i1; i++) {
        double hl = x[i] - x[i - 1], hr = x[i + 1] - x[i];
        double Dl = S[i - i0], Dr = S[i - i0 + 1];
        int same = ((Dl > 0.0) & (Dr > 0.0)) | ((Dl < 0.0) & (Dr < 0.0));
        Dl = same ? Dl : 1.0;
        Dr = same ? Dr : 1.0;
        double p = mean_arith3(hl, hr, Dl, Dr);
        double al = fabs(Dl), ar = fabs(Dr), ap = 0.5 * fabs(p);
        double m = al < ar ? al : ar;
        m = m < ap ? m : ap;
        double v = Dl > 0.0 ? 2.0 * m : -2.0 * m;
        d[i] = same ? v : 0.0;
    }
}

/* Knots per steffen_inner call (its secants on the stack). */
#define TS_SLOPE_CHUNK 1024

/* Ends (his eq. 26): the three-point end value, 0 unless it has the sign
 * of Δ_0, at most 2Δ_0. */
static void steffen(const double *x, const double *f, size_t n, double *d, size_t p0, size_t p1)
{
    size_t lo = p0 > 1 ? p0 : 1, hi = p1 < n ? p1 : n;
    double S[TS_SLOPE_CHUNK + 1];
    for (size_t c0 = lo; c0 < hi; c0 += TS_SLOPE_CHUNK) {
        size_t c1 = hi - c0 > TS_SLOPE_CHUNK ? c0 + TS_SLOPE_CHUNK : hi;
        secants(x, f, c0 - 1, c1, S);
        steffen_inner(x, S, c0, c1, d);
    }
    ends3(x, f, n, d, 2, p0, p1);
}

/* 1 if every d[0..np) is finite. */
TS_VECTOR_LOOP static int all_finite(const double *restrict d, size_t np)
{
    int ok = 1;
    for (size_t i = 0; i < np; i++)
        ok &= fabs(d[i]) <= DBL_MAX;
    return ok;
}

void ts__slopes_range(ts_slopes method, const double *x, const double *f, size_t np, double *d,
                      size_t p0, size_t p1)
{
    size_t n = np - 1;
    if (n == 1) { /* docs/method.md §6: two points */
        double D = secant(x, f, 0);
        for (size_t i = p0; i < p1; i++)
            d[i] = D;
        return;
    }
    switch (method) {
    case TS_SLOPES_GEOMETRIC:
        interior(x, f, n, d, mean_geom, weights_three_point, p0, p1);
        ends3(x, f, n, d, 0, p0, p1);
        break;
    case TS_SLOPES_HARMONIC:
        interior(x, f, n, d, mean_harm, weights_three_point, p0, p1);
        ends3(x, f, n, d, 0, p0, p1);
        break;
    case TS_SLOPES_FRITSCH_CARLSON:
        interior(x, f, n, d, mean_harm, weights_brodlie, p0, p1);
        ends3(x, f, n, d, 1, p0, p1);
        break;
    case TS_SLOPES_AKIMA:
        akima(x, f, n, d, 0, p0, p1);
        break;
    case TS_SLOPES_MAKIMA:
        akima(x, f, n, d, 1, p0, p1);
        break;
    case TS_SLOPES_PERIODIC:
        periodic(x, f, n, d, p0, p1);
        break;
    case TS_SLOPES_STEFFEN:
        steffen(x, f, n, d, p0, p1);
        break;
    case TS_SLOPES_ARITHMETIC:
    case TS_SLOPES_USER:
    default:
        interior_arith(x, f, n, d, p0, p1);
        ends3(x, f, n, d, -1, p0, p1);
        break;
    }
}

ts_status ts__slopes(ts_slopes method, const double *x, const double *f, size_t np,
                     double *d, ts_error *err)
{
    size_t n = np - 1;
    if (method == TS_SLOPES_PERIODIC && f[0] != f[n]) {
        ts__error_set(err, TS_ERR_PERIODIC, n, TS_WHERE_POINT);
        return TS_ERR_PERIODIC;
    }
    ts__slopes_range(method, x, f, np, d, 0, np);
    /* finite data can still overflow (huge f over a tiny h): the first one */
    if (all_finite(d, np))
        return TS_OK;
    size_t i = 0;
    while (i < n && isfinite(d[i]))
        i++;
    ts__error_set(err, TS_ERR_SLOPE_OVERFLOW, i, TS_WHERE_POINT);
    return TS_ERR_SLOPE_OVERFLOW;
}

ts_status ts_slopes_compute(ts_slopes method, const double *x, const double *f,
                            size_t n_points, double *d, ts_error *err)
{
    ts_status st = TS_OK;
    size_t at = TS_NO_INDEX;
    ts__error_set(err, TS_OK, TS_NO_INDEX, TS_WHERE_NONE);
    if (!x || !f || !d) {
        st = TS_ERR_NULL;
        goto fail; /* d, if given, is still filled with NaN */
    }
    if (n_points < 2) {
        st = TS_ERR_TOO_FEW;
        goto fail;
    }
    /* widths only finite: no dθ/dx here */
    if ((st = ts__check_knots(x, f, n_points, DBL_MAX, 0.0, DBL_MAX, &at)) != TS_OK)
        goto fail;
    if (!((int)method >= 0 && (int)method < TS_SLOPES_COUNT_) || method == TS_SLOPES_USER) {
        st = TS_ERR_OPTION;
        goto fail;
    }
    st = ts__slopes(method, x, f, n_points, d, err);
    if (st == TS_OK)
        return TS_OK;
    for (size_t i = 0; i < n_points; i++)
        d[i] = (double)NAN;
    return st;
fail:
    ts__error_set(err, st, at, at == TS_NO_INDEX ? TS_WHERE_NONE : TS_WHERE_POINT);
    for (size_t i = 0; d && i < n_points; i++)
        d[i] = (double)NAN;
    return st;
}
