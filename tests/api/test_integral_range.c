/* ts_spline_integral near the top of the double range: finite where the integral
 * is, ±Inf where it overflows, never NaN.  Expected values in closed form:
 * S ≡ c on an interval with equal control values, so ∫ = c (b − a); the
 * tolerance 8ε of the result's scale covers the few roundings of the
 * closed form (docs/method.md §2: ∫ A_l over [0, π/2]). */
#include "th.h"
#include "trigspline.h"

#include <float.h>
#include <math.h>

static ts_spline *flat_slopes(const double *x, const double *f, size_t np, double *zeros,
                              ts_form form)
{
    ts_spline_options o;
    ts_spline_options_init(&o);
    o.form = form;
    o.slopes = TS_SLOPES_USER;
    o.user_slopes = zeros;
    o.n_user_slopes = np;
    ts_spline *s = NULL;
    ts_error e;
    CHECKF(ts_spline_new(x, f, np, &o, &s, &e) == TS_OK, "%s at %zu", ts_strerror(e.status),
           e.index);
    return s;
}

int main(void)
{
    double zeros[8] = {0};
    double r;
    /* every form: the geometric form's whole-interval formula and its
     * Gauss–Legendre pieces take the same scaling */
    for (int fm = 0; fm < 3; fm++) {
        ts_form form = (ts_form)fm;
        TH_CASE("wide interval");
        {
            /* 2h overflows, h does not: true value h = 1.1e308 */
            const double x[2] = {-1e308, 1e307}, f[2] = {1, 1};
            ts_spline *s = flat_slopes(x, f, 2, zeros, form);
            if (s) {
                CHECK(ts_spline_integral(s, x[0], x[1], &r) == TS_OK);
                CHECK_CLOSE(r, 1.1e308, 8 * DBL_EPSILON * 1.1e308);
                CHECK(ts_spline_integral(s, -5e307, 0, &r) == TS_OK);
                CHECK_CLOSE(r, 5e307, 8 * DBL_EPSILON * 5e307);
                ts_spline_free(s);
            }
            const double x2[2] = {-0.6e308, 0.6e308}, f2[2] = {0, 0};
            s = flat_slopes(x2, f2, 2, zeros, form);
            if (s) {
                CHECK(ts_spline_integral(s, x2[0], x2[1], &r) == TS_OK && r == 0.0);
                ts_spline_free(s);
            }
        }
        TH_CASE("cumulative overflow");
        {
            /* pieces ±F over widths 4 (F = TS_VALUE_MAX, the largest value a
             * spline accepts): the running sum overflows, the total is 0 */
            const double x[6] = {0, 4, 8, 12, 16, 20};
            const double F = TS_VALUE_MAX, f[6] = {F, F, F, -F, -F, -F};
            ts_spline *s = flat_slopes(x, f, 6, zeros, form);
            if (s) {
                CHECK(ts_spline_integral(s, 0, 20, &r) == TS_OK);
                CHECKF(fabs(r) <= 64 * DBL_EPSILON * F, "r = %g", r);
                CHECK(ts_spline_integral(s, 2, 18, &r) == TS_OK);
                CHECKF(fabs(r) <= 64 * DBL_EPSILON * F, "r = %g", r);
                /* 8F overflows: +Inf, and the reverse -Inf */
                CHECK(ts_spline_integral(s, 0, 8, &r) == TS_OK && r == (double)INFINITY);
                CHECK(ts_spline_integral(s, 8, 0, &r) == TS_OK && r == -(double)INFINITY);
                CHECK(ts_spline_integral(s, 12, 20, &r) == TS_OK && r == -(double)INFINITY);
                /* finite pieces stay as they were: 3F/4 and 1/16 F (a short piece) */
                CHECK(ts_spline_integral(s, 0, 0.75, &r) == TS_OK);
                CHECK_CLOSE(r, 0.75 * F, 8 * DBL_EPSILON * F);
                CHECK(ts_spline_integral(s, 0, 0.0625, &r) == TS_OK);
                CHECK_CLOSE(r, 0.0625 * F, 8 * DBL_EPSILON * F);
                ts_spline_free(s);
            }
        }
        TH_CASE("overflowing whole interval");
        {
            /* interval 0 alone is 1.5 * 1.6e308 (overflows), the total
             * 2.4e308 + 0 - 1.125e308 = 1.275e308 is finite */
            const double x[4] = {-8e307, 8e307, 8.5e307, 1.6e308};
            const double f[4] = {1.5, 1.5, -1.5, -1.5};
            ts_spline *s = flat_slopes(x, f, 4, zeros, form);
            if (s) {
                CHECK(ts_spline_integral(s, x[0], x[3], &r) == TS_OK);
                CHECKF(fabs(r - 1.275e308) <= 16 * DBL_EPSILON * DBL_MAX, "form %d: r = %g", fm, r);
                CHECK(ts_spline_integral(s, x[0], x[1], &r) == TS_OK && r == (double)INFINITY);
                ts_spline_free(s);
            }
        }
    }
    TH_CASE("one piece of opposite overflowing terms (geometric, fuzz_spline)");
    {
        /* The whole-interval closed form of docs/method.md §4,
         * h (f0 + f1)/2 + k (d0 - d1)(2h/5 - Q k), k = 2h/(3πa): here both
         * terms overflow with opposite signs (inf - inf was NaN).  The true
         * value, in long double (range 1e4932), is about -1e1127: -Inf. */
        const double x[2] = {0x1.dcd6529p+29, 0x1.f350d836faf35p+763};
        const double f[2] = {0x1.dfdcp+14, -0x1.7f7f7f7f7f7f7p+896};
        double d[2] = {0.0, -0x1.893d775c89f62p+133};
        ts_spline *s = flat_slopes(x, f, 2, d, TS_FORM_GEOMETRIC);
        if (s) {
            long double h = (long double)x[1] - (long double)x[0];
            long double kk = 2.0L / (3.0L * 3.14159265358979323846264L) * h;
            long double Q = 56.0L / 5.0L - 111.0L * 3.14159265358979323846264L / 32.0L;
            long double I = h * ((long double)f[0] + (long double)f[1]) / 2.0L +
                            kk * ((long double)d[0] - (long double)d[1]) * (0.4L * h - Q * kk);
            CHECKF(I < -(long double)DBL_MAX, "reference %Lg", I);
            CHECK(ts_spline_integral(s, x[0], x[1], &r) == TS_OK && r == -(double)INFINITY);
            CHECK(ts_spline_integral(s, x[1], x[0], &r) == TS_OK && r == (double)INFINITY);
            ts_spline_free(s);
        }
    }
    return th_report("test_integral_range");
}
