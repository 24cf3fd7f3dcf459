/* The property test at large offsets (finding 1 and its extension): knots
 * at x0 = 1e9, 1e12, 1e15, 1.7e18 with spacings of a few to a few hundred
 * ulps of x0 (at 1e15: 1 to 100; at 1.7e18: 1e3 to 1e5), every form and
 * every shape scheme, and data near the top of the double range (values
 * and lines scaled by 2^1015); every
 * certified interval is sampled densely (2048 points) and each sample is
 * checked against its region with the line taken in long double: the
 * slopes m have at most 11 significant bits, so m·x is exact in the 64-bit
 * significand and m x + c is rounded once, far below the tolerance.  The
 * tolerance is 8ε max|B_l| of the interval: the evaluator's own rounding,
 * which the certificate does not cover (src/certificate.c).  Expected: 0
 * violations. */
#include "th.h"
#include "common/th_rng.h"
#include "trigspline.h"

#include <float.h>
#include <math.h>

#define NP 9
#define PER 2048

static double bits11(double m)
{
    int e;
    double fr = frexp(m, &e);
    return ldexp(nearbyint(ldexp(fr, 11)), e - 11);
}

static long violations(const ts_spline *s, const ts_spline_options *o, long *samples)
{
    size_t n = ts_spline_intervals(s);
    const double *x = ts_spline_x(s);
    long bad = 0;
    for (size_t i = 0; i < n; i++) {
        ts_interval_report r;
        ts_spline_report(s, i, &r);
        if (!r.certified)
            continue;
        double B[4], bm = 0;
        ts_spline_control(s, i, B, NULL);
        for (int l = 0; l < 4; l++)
            bm = fabs(B[l]) > bm ? fabs(B[l]) : bm;
        long double tol = (long double)(8 * DBL_EPSILON * bm);
        double prev = 0;
        for (int k = 0; k <= PER; k++) {
            double q = x[i] + (x[i + 1] - x[i]) * (k / (double)PER), y;
            q = q > x[i + 1] ? x[i + 1] : q;
            ts_spline_eval(s, q, NULL, &y);
            long double Y = (long double)y, Q = (long double)q;
            (*samples)++;
            switch (o->shape) {
            case TS_SHAPE_POSITIVE:
                bad += !(Y >= -tol);
                break;
            case TS_SHAPE_ABOVE:
                bad += !(Y - ((long double)o->lower.m * Q + (long double)o->lower.c) > -tol);
                break;
            case TS_SHAPE_BELOW:
                bad += !(((long double)o->upper.m * Q + (long double)o->upper.c) - Y > -tol);
                break;
            case TS_SHAPE_BETWEEN:
                bad += !(Y - ((long double)o->lower.m * Q + (long double)o->lower.c) > -tol);
                bad += !(((long double)o->upper.m * Q + (long double)o->upper.c) - Y > -tol);
                break;
            case TS_SHAPE_MONOTONE:
                if (k > 0)
                    bad += ts_spline_f(s)[n] > ts_spline_f(s)[0] ? y < prev : y > prev;
                break;
            default:
                break;
            }
            prev = y;
        }
    }
    return bad;
}

static void large_offsets(void)
{
    /* the fifth: x from 0, values and lines scaled by 2^1015 (exactly), so
     * that data, control values and lines are near the top of the range */
    static const double offsets[5] = {1e9, 1e12, 1e15, 1.7e18, 0};
    static const double spacing[5][2] = {{1e-6, 1e-4}, {1e-3, 1e-1}, {1, 100}, {1e3, 1e5},
                                         {0.5, 5}};
    th_rng r = TH_RNG_INIT(1801);
    for (int form = 0; form < 3; form++)
        for (int shape = TS_SHAPE_POSITIVE; shape <= TS_SHAPE_MONOTONE; shape++) {
            long sets = 0, built = 0, bad = 0, samples = 0;
            for (int oi = 0; oi < 5; oi++)
                for (int rep = 0; rep < 12; rep++) {
                    double x[NP], f[NP];
                    x[0] = offsets[oi];
                    for (int i = 1; i < NP; i++)
                        x[i] = x[i - 1] + th_rng_logu(&r, spacing[oi][0], spacing[oi][1]);
                    double span = x[NP - 1] - x[0];
                    ts_spline_options o;
                    ts_spline_options_init(&o);
                    o.form = (ts_form)form;
                    o.shape = (ts_shape)shape;
                    o.slopes = (ts_slopes)th_rng_below(&r, 6);
                    o.alpha = th_rng_logu(&r, 0.5, 2);
                    /* lines through the data's range with an O(1) slope per
                     * unit of span: m x is huge, m x + c of order one */
                    double ml = bits11(th_rng_range(&r, -2, 2) / span);
                    double mu = bits11(ml + th_rng_range(&r, -1, 1) / span);
                    o.lower.m = ml;
                    o.lower.c = -ml * x[0] - 1.0;
                    o.upper.m = mu;
                    o.upper.c = -mu * x[0] + 3.0;
                    for (int i = 0; i < NP; i++) {
                        long double lo = (long double)ml * (long double)x[i] + (long double)o.lower.c;
                        long double hi = (long double)mu * (long double)x[i] + (long double)o.upper.c;
                        double u = th_rng_range(&r, 0.05, 0.95);
                        switch (shape) {
                        case TS_SHAPE_POSITIVE: f[i] = th_rng_range(&r, 0, 3); break;
                        case TS_SHAPE_ABOVE: f[i] = (double)(lo + 2 * (long double)u); break;
                        case TS_SHAPE_BELOW: f[i] = (double)(hi - 2 * (long double)u); break;
                        case TS_SHAPE_BETWEEN: f[i] = (double)(lo + (hi - lo) * (long double)u); break;
                        default: f[i] = i == 0 ? 0 : f[i - 1] + th_rng_range(&r, 0, 1); break;
                        }
                    }
                    if (oi == 4) {
                        const double top = 0x1p1015;
                        for (int i = 0; i < NP; i++)
                            f[i] *= top;
                        o.lower.m *= top, o.lower.c *= top, o.upper.m *= top, o.upper.c *= top;
                    }
                    sets++;
                    ts_spline *s = NULL;
                    ts_status st = ts_spline_new(x, f, NP, &o, &s, NULL);
                    CHECKF(st == TS_OK || st == TS_ERR_INFEASIBLE || st == TS_ERR_PRECISION ||
                               st == TS_ERR_UNPROVEN || st == TS_ERR_SIDE || st == TS_ERR_LINES,
                           "form %d shape %d offset %g: %s", form, shape, x[0], ts_strerror(st));
                    if (!s)
                        continue;
                    built++;
                    bad += violations(s, &o, &samples);
                    ts_spline_free(s);
                }
            CHECKF(bad == 0, "form %d shape %d: %ld samples outside", form, shape, bad);
            printf("form %d shape %d: %ld sets, %ld built, %ld samples checked, %ld outside\n",
                   form, shape, sets, built, samples, bad);
        }
}

int main(void)
{
    TH_CASE("large offsets");
    large_offsets();
    return th_report("test_large_offsets");
}
