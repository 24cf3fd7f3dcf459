/* No floating-point exception flag on valid input: after every public call
 * on valid data (the paper's Table 1, data with exact zeros and flat runs,
 * every form, shape scheme and slope method; curves with a box), neither
 * FE_INVALID nor FE_DIVBYZERO is raised.  (Construction on data with zeros
 * raised both: the schemes' rules computed K d / g for g = 0 before
 * selecting the term.)  Expected values: none, by the header's promise. */
#include "th.h"
#include "trigspline.h"

#include <fenv.h>
#include <math.h>
#include <stddef.h>

static int flags(void)
{
    int f = fetestexcept(FE_INVALID | FE_DIVBYZERO);
    feclearexcept(FE_ALL_EXCEPT);
    return f;
}

int main(void)
{
    static const double x[9] = {0, 2, 3, 5, 15, 25, 27, 28, 30};
    static const double table1[9] = {2, 1.58, 1.55, 1.54, 1.8, 1.54, 1.55, 1.58, 2};
    static const double zeros[9] = {0, 0, 3, 0, 0, 1, 1, 2, 0};
    static const double rising[9] = {0, 0, 1, 1, 1, 4, 9, 9, 9};
    const double *data[3] = {table1, zeros, rising};
    TH_CASE("splines");
    for (int k = 0; k < 3; k++)
        for (int form = TS_FORM_PAPER; form <= TS_FORM_GEOMETRIC; form++)
            for (int shape = TS_SHAPE_NONE; shape <= TS_SHAPE_MONOTONE; shape++)
                for (int sl = 0; sl < TS_SLOPES_COUNT_; sl++) {
                    if (sl == TS_SLOPES_USER || (sl == TS_SLOPES_PERIODIC && k != 0) ||
                        (shape == TS_SHAPE_MONOTONE && k != 2))
                        continue;
                    ts_spline_options o;
                    ts_spline_options_init(&o);
                    o.form = (ts_form)form;
                    o.shape = (ts_shape)shape;
                    o.slopes = (ts_slopes)sl;
                    o.alpha = form == TS_FORM_GEOMETRIC && shape == TS_SHAPE_NONE ? 0.5 : 0.15;
                    o.lower = (ts_line){0, -1};
                    o.upper = (ts_line){0.01, 12};
                    feclearexcept(FE_ALL_EXCEPT);
                    ts_spline *s = NULL;
                    ts_error e;
                    ts_status st = ts_spline_new(x, data[k], 9, &o, &s, &e);
                    CHECKF(st == TS_OK, "data %d form %d shape %d slopes %d: %s", k, form, shape,
                           sl, ts_strerror(st));
                    CHECKF(flags() == 0, "ts_spline_new: data %d form %d shape %d slopes %d", k,
                           form, shape, sl);
                    if (!s)
                        continue;
                    double xs[61], ys[61], y, dy, d2y, I;
                    for (int j = 0; j <= 60; j++)
                        xs[j] = 0.5 * j;
                    for (int j = 0; j <= 60; j++)
                        (void)ts_spline_eval_deriv(s, xs[j], NULL, &y, &dy, &d2y);
                    for (int der = 0; der <= 2; der++)
                        (void)ts_spline_eval_batch(s, der, xs, 61, ys, NULL, NULL);
                    (void)ts_spline_integral(s, 0.5, 29.5, &I);
                    /* every order, every mode, ±Inf, beyond the data; solve */
                    double xo[67];
                    for (int j = 0; j < 61; j++)
                        xo[j] = xs[j];
                    xo[61] = -7, xo[62] = 31, xo[63] = 1e300, xo[64] = -1e300;
                    xo[65] = TH_INF, xo[66] = -TH_INF;
                    for (int nu = 0; nu <= 6; nu++)
                        for (int ex = TS_EXTRAP_ERROR; ex <= TS_EXTRAP_LINEAR; ex++) {
                            double yo[67];
                            (void)ts_spline_eval_batch_mode(s, nu, (ts_extrap)ex, xo, 67, yo,
                                                            NULL, NULL);
                            for (int j = 60; j < 67; j++)
                                (void)ts_spline_eval_mode(s, xo[j], nu, (ts_extrap)ex, NULL, &y);
                        }
                    for (int ky = -2; ky <= 26; ky++) {
                        double r[64];
                        size_t cnt;
                        (void)ts_spline_solve(s, 0.5 * ky, r, 64, &cnt);
                    }
                    for (size_t i = 0; i < 8; i++) {
                        ts_interval_report r;
                        (void)ts_spline_report(s, i, &r);
                    }
                    if (shape != TS_SHAPE_NONE && shape != TS_SHAPE_MONOTONE) {
                        ts_interval_report rs[8];
                        (void)ts_spline_certify(s, &o.lower, NULL, rs, NULL);
                    }
                    CHECKF(flags() == 0, "evaluation: data %d form %d shape %d slopes %d", k, form,
                           shape, sl);
                    ts_spline_free(s);
                }
    TH_CASE("geometric form, huge tension");
    /* a = α up to 1e300: κ = 2/(3π a) down to 2e-301, X̂'(0) = 3κ; κ³
     * underflows from a ≈ 2e102 on.  At the knot x_i (φ = 0, from the left
     * end) docs/method.md §4 gives, in closed form,
     *   S''·h² = (2/9)(Δf − h d_i)/κ² + (2/9) h (d_i − d_{i+1})/κ,
     * finite up to a ≈ 1e154 here; the S'' formula used to divide by X̂'³ and
     * returned ±inf (and, under clang, raised FE_DIVBYZERO even for S).
     * Tolerance: the closed form's terms are each rounded a few times, the
     * code's S'' passes through Y'/X' and two divisions: 64 ε relative is far
     * above both and far below the old inf. */
    {
        static const double xg[3] = {0, 1, 3}, fg[3] = {1, 2, 2.5};
        static const double avals[8] = {1e50, 1e100, 1e103, 1e105, 1e110, 1e150, 1e153, 1e300};
        for (int ka = 0; ka < 8; ka++) {
            ts_spline_options o;
            ts_spline_options_init(&o);
            o.form = TS_FORM_GEOMETRIC;
            o.alpha = avals[ka];
            feclearexcept(FE_ALL_EXCEPT);
            ts_spline *s = NULL;
            CHECKF(ts_spline_new(xg, fg, 3, &o, &s, NULL) == TS_OK, "a = %g", avals[ka]);
            if (!s)
                continue;
            const double *d = ts_spline_slopes(s);
            double y[3], dy[3], d2[3], yb[3];
            for (int j = 0; j < 3; j++)
                (void)ts_spline_eval_deriv(s, xg[j], NULL, &y[j], &dy[j], &d2[j]);
            for (int der = 0; der <= 2; der++)
                (void)ts_spline_eval_batch(s, der, xg, 3, yb, NULL, NULL);
            for (int j = 0; j < 3; j++)
                (void)ts_spline_eval(s, xg[j], NULL, &y[j]);
            CHECKF(flags() == 0, "a = %g: evaluation at the knots raised a flag", avals[ka]);
            /* x = 0 is interval 0 seen from its left end */
            double kappa = 2.0 / (3.0 * 3.14159265358979323846 * avals[ka]);
            double want = (2.0 / 9.0) * ((fg[1] - fg[0]) - d[0]) / kappa / kappa +
                          (2.0 / 9.0) * (d[0] - d[1]) / kappa;
            if (fabs(want) < 1e300)
                CHECKF(fabs(d2[0] - want) <= 64 * 2.220446049250313e-16 * fabs(want),
                       "a = %g: S''(x0) = %.17g, closed form %.17g", avals[ka], d2[0], want);
            else if (isinf(want))
                CHECKF(isinf(d2[0]) && (d2[0] > 0) == (want > 0), "a = %g: S''(x0) = %g, want %g",
                       avals[ka], d2[0], want);
            CHECKF(y[0] == fg[0] && y[1] == fg[1] && y[2] == fg[2], "a = %g: knots", avals[ka]);
            ts_spline_free(s);
            /* extension past x_2 by the end's osculating parabola: f_2 + d_2 δ
             * + S''(x_2) δ²/2, S''(x_2) from interval 1 seen from its right
             * end (F0 = f_2, F1 = f_1, D0 = −d_2, D1 = −d_1, h = 2) */
            o.extrapolate = TS_EXTRAP_EXTEND;
            CHECK(ts_spline_new(xg, fg, 3, &o, &s, NULL) == TS_OK);
            if (!s)
                continue;
            d = ts_spline_slopes(s);
            feclearexcept(FE_ALL_EXCEPT);
            double ye;
            (void)ts_spline_eval(s, 3.5, NULL, &ye);
            CHECKF(flags() == 0, "a = %g: extension raised a flag", avals[ka]);
            double s2 = ((2.0 / 9.0) * ((fg[1] - fg[2]) + 2.0 * d[2]) / kappa / kappa +
                         (2.0 / 9.0) * 2.0 * (d[1] - d[2]) / kappa) / 4.0;
            double wante = fg[2] + 0.5 * d[2] + 0.125 * s2;
            if (fabs(wante) < 1e300)
                CHECKF(fabs(ye - wante) <= 64 * 2.220446049250313e-16 * fabs(wante),
                       "a = %g: S(3.5) = %.17g, closed form %.17g", avals[ka], ye, wante);
            ts_spline_free(s);
        }
    }
    TH_CASE("curves");
    static const double pts[6][2] = {{-1, 0}, {0, -1}, {1, 0}, {1, 1}, {0, 2}, {-1, 1}};
    for (int closed = 0; closed < 2; closed++) {
        ts_curve_options co;
        ts_curve_options_init(&co);
        co.closed = closed;
        co.alpha = 0.37;
        co.has_lo[0] = co.has_lo[1] = co.has_hi[0] = co.has_hi[1] = 1;
        co.lo[0] = co.lo[1] = -1.5;
        co.hi[0] = co.hi[1] = 2.5;
        feclearexcept(FE_ALL_EXCEPT);
        ts_curve *c = NULL;
        CHECK(ts_curve_new(&pts[0][0], 6, 2, &co, &c, NULL) == TS_OK);
        double p[2], len;
        for (int j = 0; c && j <= 40; j++)
            (void)ts_curve_eval(c, ts_curve_knots(c)[ts_curve_segments(c)] * j / 40.0, NULL, p,
                                NULL, NULL);
        if (c)
            (void)ts_curve_length(c, 1e-10, &len);
        CHECKF(flags() == 0, "curve closed %d", closed);
        ts_curve_free(c);
    }
    return th_report("test_fenv");
}
