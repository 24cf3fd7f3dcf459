/* ts_spline_new on fuzzer-chosen data and options (any form, slopes,
 * shape, extrapolation; knots at offsets up to 1.7e18 with small spacings),
 * then evaluation, integrals, reports and certification.  Checks:
 *  - a status from ts_spline_new's documented list, with a real message;
 *  - knots interpolated (to 2 ulps of max|B|: the evaluation's rounding);
 *  - batch = scalar to 8ε max|B| (kernels.c's measured 3.9ε) plus 64
 *    units of the subnormal spacing: where values are subnormal each of
 *    the expression's ~20 roundings errs by up to 2^-1075 absolutely;
 *  - every certified interval's dense samples inside its region, the line
 *    taken in long double (m x + c of a large x is not blurred by the
 *    double rounding of the line itself); tolerance the same for the
 *    evaluator's own rounding;
 *  - the monotone scheme's samples monotone in floating point;
 *  - integrals never NaN. */
#include "fuzz.h"
#include "trigspline.h"

#include <float.h>
#include <math.h>

#define NMAX 24
#define PER 24 /* samples per interval */

static double bits11(double m)
{
    if (!isfinite(m) || m == 0.0)
        return m;
    int e;
    double fr = frexp(m, &e);
    return ldexp(nearbyint(ldexp(fr, 11)), e - 11);
}

static int documented(ts_status st)
{
    switch (st) {
    case TS_OK: case TS_ERR_TOO_FEW: case TS_ERR_NONFINITE: case TS_ERR_UNSORTED:
    case TS_ERR_ALPHA: case TS_ERR_BETA: case TS_ERR_MARGIN: case TS_ERR_OPTION:
    case TS_ERR_PERIODIC: case TS_ERR_NEGATIVE: case TS_ERR_SIDE: case TS_ERR_LINES:
    case TS_ERR_NONMONOTONE: case TS_ERR_INFEASIBLE: case TS_ERR_GEOMETRIC:
    case TS_ERR_ZERO_SLOPE: case TS_ERR_SLOPE_OVERFLOW: case TS_ERR_TOO_LARGE:
    case TS_ERR_CONTROL_OVERFLOW: case TS_ERR_WIDTH: case TS_ERR_NOMEM:
    case TS_ERR_PRECISION: case TS_ERR_UNPROVEN:
        return 1;
    default:
        return 0;
    }
}

static void check_spline(const ts_spline *s, const ts_spline_options *o)
{
    size_t n = ts_spline_intervals(s);
    const double *x = ts_spline_x(s), *f = ts_spline_f(s);
    double q[PER * NMAX + 1], yb[PER * NMAX + 1], Bmax[NMAX];
    size_t m = 0;
    for (size_t i = 0; i < n; i++) {
        double B[4];
        ts_spline_control(s, i, B, NULL);
        Bmax[i] = fmax(fmax(fabs(B[0]), fabs(B[1])), fmax(fabs(B[2]), fabs(B[3])));
        for (int k = 0; k < PER; k++) {
            double t = x[i] + (x[i + 1] - x[i]) * (k / (double)PER);
            q[m++] = t < x[i] ? x[i] : t > x[i + 1] ? x[i + 1] : t;
        }
    }
    q[m++] = x[n];
    ts_error e;
    ts_status st = ts_spline_eval_batch(s, 0, q, m, yb, NULL, &e);
    FUZZ_CHECK(st == TS_OK, "batch: %s at %zu", ts_strerror(st), e.index);
    for (size_t i = 0; i <= n; i++) {
        double y, bm = Bmax[i < n ? i : n - 1];
        ts_spline_eval(s, x[i], NULL, &y);
        FUZZ_CHECK(fabs(y - f[i]) <= 2 * DBL_EPSILON * bm, "knot %zu: %.17g vs %.17g", i, y, f[i]);
    }
    ts_shape shape = ts_spline_shape(s);
    int certified = ts_spline_certified(s);
    for (size_t j = 0; j < m; j++) {
        size_t i = j / PER < n ? j / PER : n - 1;
        double y, tol = 8 * DBL_EPSILON * Bmax[i] + 64 * DBL_TRUE_MIN;
        ts_spline_eval(s, q[j], NULL, &y);
        FUZZ_CHECK(fabs(y - yb[j]) <= tol || (isnan(y) && isnan(yb[j])),
                   "batch %.17g vs scalar %.17g at x = %.17g", yb[j], y, q[j]);
        if (!certified)
            continue;
        ts_interval_report r;
        ts_spline_report(s, i, &r);
        if (!r.certified)
            continue;
        if (shape == TS_SHAPE_POSITIVE)
            FUZZ_CHECK(y >= -tol, "positive: S(%.17g) = %.17g", q[j], y);
        if (shape == TS_SHAPE_ABOVE || shape == TS_SHAPE_BETWEEN) {
            long double L = (long double)o->lower.m * (long double)q[j] + (long double)o->lower.c;
            FUZZ_CHECK((long double)y - L > -(long double)tol,
                       "above: S(%.17g) = %.17g, line %.17Lg", q[j], y, L);
        }
        if (shape == TS_SHAPE_BELOW || shape == TS_SHAPE_BETWEEN) {
            long double U = (long double)o->upper.m * (long double)q[j] + (long double)o->upper.c;
            FUZZ_CHECK(U - (long double)y > -(long double)tol,
                       "below: S(%.17g) = %.17g, line %.17Lg", q[j], y, U);
        }
    }
    if (shape == TS_SHAPE_MONOTONE) {
        int up = f[n] > f[0], down = f[n] < f[0];
        for (size_t j = 1; j < m; j++)
            FUZZ_CHECK(!(up && yb[j] < yb[j - 1]) && !(down && yb[j] > yb[j - 1]),
                       "monotone: %.17g then %.17g at x = %.17g", yb[j - 1], yb[j], q[j]);
    }
    double I;
    FUZZ_CHECK(ts_spline_integral(s, x[0], x[n], &I) == TS_OK && !isnan(I), "integral %g", I);
    FUZZ_CHECK(ts_spline_integral(s, q[m / 3], q[m / 2], &I) == TS_OK && !isnan(I), "integral %g", I);
    if (shape == TS_SHAPE_ABOVE || shape == TS_SHAPE_BELOW || shape == TS_SHAPE_BETWEEN) {
        ts_interval_report reps[NMAX];
        const ts_line *lo = shape != TS_SHAPE_BELOW ? &o->lower : NULL;
        const ts_line *hi = shape != TS_SHAPE_ABOVE ? &o->upper : NULL;
        st = ts_spline_certify(s, lo, hi, reps, &e);
        FUZZ_CHECK(st == TS_OK || st == TS_ERR_VIOLATED, "certify: %s", ts_strerror(st));
        FUZZ_CHECK(!certified || st == TS_OK, "certified spline fails ts_spline_certify at %zu", e.index);
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_in in = {data, size};
    ts_spline_options o;
    ts_spline_options_init(&o);
    unsigned b0 = fuzz_byte(&in), b1 = fuzz_byte(&in);
    o.form = (ts_form)(b0 % 3);
    o.slopes = (ts_slopes)(b0 / 3 % 8);
    o.shape = (ts_shape)(b1 % 6);
    o.extrapolate = (ts_extrap)(b1 / 6 % 4);
    o.certify = (b1 & 0x80) == 0;
    size_t np = 2 + fuzz_byte(&in) % (NMAX - 1);
    /* knots: an offset (0, 1e9, 1e12, 1e15, 1.7e18 or fuzzed) plus spacings */
    static const double offsets[6] = {0, 1e9, 1e12, 1e15, 1.7e18, 0};
    unsigned ob = fuzz_byte(&in);
    double x[NMAX + 1], f[NMAX + 1], d[NMAX + 1], al[NMAX];
    x[0] = ob % 6 == 5 ? fuzz_double(&in) : offsets[ob % 6];
    for (size_t i = 1; i < np; i++) {
        unsigned sb = fuzz_byte(&in);
        x[i] = sb < 200 ? x[i - 1] + (1 + sb % 100) : x[i - 1] + fuzz_double(&in);
    }
    for (size_t i = 0; i < np; i++)
        f[i] = fuzz_double(&in);
    o.alpha = (fuzz_byte(&in) + 1) / 64.0;
    unsigned ab = fuzz_byte(&in);
    if (ab >= 250)
        o.alpha = fuzz_double(&in);
    if (ab % 5 == 0) {
        for (size_t i = 0; i + 1 < np; i++)
            al[i] = (fuzz_byte(&in) + 1) / 64.0;
        o.alphas = al;
        o.n_alphas = np - 1;
    }
    o.beta = fuzz_byte(&in) / 64.0;
    o.margin = (fuzz_byte(&in) + 1) / 256.0;
    o.lower.m = fuzz_double(&in);
    o.lower.c = fuzz_double(&in);
    o.upper.m = o.lower.m;
    o.upper.c = fuzz_double(&in);
    if (fuzz_byte(&in) & 1) {
        o.upper.m = fuzz_double(&in);
        o.upper.c = fuzz_double(&in);
    }
    /* slopes of at most 11 significant bits: m x is then exact in long
     * double, and the check of the samples is not blurred by the line */
    o.lower.m = bits11(o.lower.m);
    o.upper.m = bits11(o.upper.m);
    if (o.slopes == TS_SLOPES_USER) {
        for (size_t i = 0; i < np; i++)
            d[i] = fuzz_double(&in);
        o.user_slopes = d;
        o.n_user_slopes = np;
    }
    if (o.slopes == TS_SLOPES_PERIODIC && (fuzz_byte(&in) & 1))
        f[np - 1] = f[0];
    ts_spline *s = NULL;
    ts_error e;
    ts_status st = ts_spline_new(x, f, np, &o, &s, &e);
    FUZZ_CHECK(documented(st), "status %d", (int)st);
    FUZZ_CHECK(strcmp(ts_strerror(st), "unknown status code") != 0, "status %d", (int)st);
    FUZZ_CHECK((st == TS_OK) == (s != NULL), "status %d, spline %p", (int)st, (void *)s);
    if (s)
        check_spline(s, &o);
    ts_spline_free(s);
    return 0;
}
