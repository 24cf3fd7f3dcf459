/* Review regressions: deterministic cases for the defects the review found
 * and fixed in slopes.c, shape.c, certify.c and curve.c (each case failed
 * before its fix), and the out-parameter conventions of the header
 * ("out-parameters are reset before any check").
 *
 * Expected values come from the closed forms of the header (enum ts_slopes,
 * docs/method.md §6) evaluated by hand, from exact power-of-two scaling, or from the
 * documented statuses; tolerances are stated at each check.
 */
#include "th.h"
#include "trigspline.h"

#include <float.h>
#include <math.h>
#include <string.h>

#define EPS DBL_EPSILON

static int all_nan(const double *v, size_t n)
{
    for (size_t i = 0; i < n; i++)
        if (!isnan(v[i]))
            return 0;
    return 1;
}

static int rel_close(double a, double b, double tol)
{
    return fabs(a - b) <= tol * fabs(b);
}

/* docs/method.md §6 weights h/(h_l + h_r) when h_l + h_r overflows (knots near
 * ±DBL_MAX, every width finite): the sum used to become inf, the weights 0,
 * and arithmetic / geometric slopes silently wrong, harmonic and
 * Fritsch–Carlson NaN (TS_ERR_NONFINITE on finite data). */
static void slopes_wide_knots(void)
{
    /* Δ0 = 1e300/1e308 = 1e-8, Δ1 = 2e-8, h0 = h1: w = 1/2 (header) */
    double x[] = {-1e308, 0, 1e308}, f[] = {0, 1e300, 3e300}, d[3];
    double D0 = (f[1] - f[0]) / (x[1] - x[0]), D1 = (f[2] - f[1]) / (x[2] - x[1]);
    /* tolerance 8ε relative: a few roundings of the closed forms */
    CHECK(ts_slopes_compute(TS_SLOPES_ARITHMETIC, x, f, 3, d, NULL) == TS_OK);
    CHECK(rel_close(d[1], 0.5 * (D0 + D1), 8 * EPS));            /* 1.5e-8 */
    CHECK(rel_close(d[0], D0 + 0.5 * (D0 - D1), 8 * EPS));       /* end3: 0.5e-8 */
    CHECK(rel_close(d[2], D1 + 0.5 * (D1 - D0), 8 * EPS));       /* 2.5e-8 */
    CHECK(ts_slopes_compute(TS_SLOPES_GEOMETRIC, x, f, 3, d, NULL) == TS_OK);
    CHECK(rel_close(d[1], sqrt(D0 * D1), 8 * EPS));              /* sqrt(2)e-8 */
    CHECK(ts_slopes_compute(TS_SLOPES_HARMONIC, x, f, 3, d, NULL) == TS_OK);
    CHECK(rel_close(d[1], 2 * D0 * D1 / (D0 + D1), 8 * EPS));    /* 4/3 e-8 */
    CHECK(ts_slopes_compute(TS_SLOPES_FRITSCH_CARLSON, x, f, 3, d, NULL) == TS_OK);
    CHECK(rel_close(d[1], 2 * D0 * D1 / (D0 + D1), 8 * EPS));    /* Brodlie, uniform */
    CHECK(ts_slopes_compute(TS_SLOPES_AKIMA, x, f, 3, d, NULL) == TS_OK); /* n = 2 forms */
    CHECK(rel_close(d[0], (3 * D0 - D1) / 2, 8 * EPS) && rel_close(d[1], (D0 + D1) / 2, 8 * EPS) &&
          rel_close(d[2], (3 * D1 - D0) / 2, 8 * EPS));
    /* periodic: f[0] == f[n]; secants 1e-8, -1e-8 with equal weights: 0 */
    double fp[] = {0, 1e300, 0};
    CHECK(ts_slopes_compute(TS_SLOPES_PERIODIC, x, fp, 3, d, NULL) == TS_OK);
    CHECK(d[0] == 0 && d[1] == 0 && d[2] == 0);
    /* the same data through ts_spline_new: interpolates, finite */
    ts_spline *s = NULL;
    CHECK(ts_spline_new(x, f, 3, NULL, &s, NULL) == TS_OK);
    CHECK(ts_spline_slopes(s) && rel_close(ts_spline_slopes(s)[1], 0.5 * (D0 + D1), 8 * EPS));
    ts_spline_free(s);

    /* a single width that overflows: ts_slopes_compute now refuses it as
     * ts_spline_new does (TS_ERR_WIDTH at point 1), d all NaN */
    double x2[] = {-1e308, 1e308}, d2[2];
    ts_error e;
    CHECK(ts_slopes_compute(TS_SLOPES_ARITHMETIC, x2, f, 2, d2, &e) == TS_ERR_WIDTH &&
          e.index == 1 && e.where == TS_WHERE_POINT && all_nan(d2, 2));
    CHECK(ts_spline_new(x2, f, 2, NULL, &s, &e) == TS_ERR_WIDTH && e.index == 1 && !s);
}

/* Akima weights |m_{i+1} − m_i| overflow for secants near ±DBL_MAX/2 while
 * the slope itself is finite.  Hand values (header formulas, uniform grid):
 * secants m = 0, 0, 1e308, −1.5e308, 1.5e308, −1e308, 0, 0;
 * d_3 = (|m4 − m3| m2 + |m2 − m1| m3)/(|m4 − m3| + |m2 − m1|)
 *     = (3e308·1e308 − 1e308·1.5e308)/4e308 = 0.375e308, d_5 = −d_3;
 * makima d_3 = (3e308·1e308 + 1.5e308·(−1.5e308))/4.5e308 = 1e308/6. */
static void akima_huge(void)
{
    double x[] = {0, 1, 2, 3, 4, 5, 6, 7, 8}, f[] = {0, 0, 0, 1e308, -0.5e308, 1e308, 0, 0, 0};
    double d[9];
    CHECK(ts_slopes_compute(TS_SLOPES_AKIMA, x, f, 9, d, NULL) == TS_OK);
    CHECK(rel_close(d[3], 0.375e308, 8 * EPS) && rel_close(d[5], -0.375e308, 8 * EPS));
    CHECK(d[0] == 0 && d[1] == 0 && d[7] == 0 && d[8] == 0);
    CHECK(ts_slopes_compute(TS_SLOPES_MAKIMA, x, f, 9, d, NULL) == TS_OK);
    CHECK(rel_close(d[3], 1e308 / 6, 8 * EPS) && rel_close(d[5], -1e308 / 6, 8 * EPS));
}

/* ts_slopes_compute: "fills d with NaN when it fails", also for NULL x / f */
static void slopes_out_params(void)
{
    double x[] = {0, 1, 2}, f[] = {0, 1, 0}, d[3] = {1, 2, 3};
    ts_error e;
    CHECK(ts_slopes_compute(TS_SLOPES_ARITHMETIC, NULL, f, 3, d, &e) == TS_ERR_NULL &&
          e.status == TS_ERR_NULL && all_nan(d, 3));
    d[0] = d[1] = d[2] = 1;
    CHECK(ts_slopes_compute(TS_SLOPES_ARITHMETIC, x, NULL, 3, d, &e) == TS_ERR_NULL && all_nan(d, 3));
    CHECK(ts_slopes_compute(TS_SLOPES_ARITHMETIC, x, f, 3, NULL, &e) == TS_ERR_NULL);
}

/* The certificate's control-value test accepted infinite control values
 * (B1 = +inf passes "B1 >= 0"), so a tiny alpha and margin gave a
 * "certified" positive spline that evaluates to NaN.  Now such an interval
 * fails the test and the repair raises a_i until the controls are finite. */
static void tiny_alpha_positive(void)
{
    double x[] = {0, 1, 2, 3}, f[] = {1, 2, 0, 3};
    for (int form = 0; form < 3; form++)
        for (int cert = 0; cert < 2; cert++) {
            ts_spline_options o;
            ts_spline_options_init(&o);
            o.form = (ts_form)form;
            o.shape = TS_SHAPE_POSITIVE;
            o.alpha = 1e-310;
            o.margin = 1e-310;
            o.certify = cert;
            ts_spline *s = NULL;
            ts_status st = ts_spline_new(x, f, 4, &o, &s, NULL);
            CHECKF(st == TS_OK && ts_spline_certified(s), "form %d certify %d: %s", form, cert,
                   ts_strerror(st));
            if (st != TS_OK)
                continue;
            int finite = 1, inside = 1;
            for (size_t i = 0; i < 3; i++) {
                double B[4], a;
                ts_spline_control(s, i, B, NULL);
                ts_spline_a(s, i, &a);
                finite = finite && isfinite(B[1]) && isfinite(B[2]) && isfinite(a);
                for (int k = 0; k <= 16; k++) {
                    double y;
                    /* S >= 0 up to evaluation rounding, 64 ε max|B| */
                    if (ts_spline_eval(s, x[i] + k / 16.0, NULL, &y) != TS_OK ||
                        !(y >= -64 * EPS * fmax(fabs(B[1]), fabs(B[2]))))
                        inside = 0;
                }
            }
            CHECKF(finite && inside, "form %d certify %d", form, cert);
            ts_spline_free(s);
        }
}

/* a_i = alpha_i + beta_i must stay finite: alpha near DBL_MAX plus the
 * scheme's beta used to overflow (shape.c), and the repair's doubling
 * could end at a = inf (certify.c). */
static void huge_alpha(void)
{
    double x[] = {0, 1, 2, 3}, f[] = {1, 2, 1.5, 3}, fz[] = {1, 0, 2, 0.5};
    for (int form = 0; form < 3; form++)
        for (int shape = 1; shape <= 4; shape++)
            for (int k = 0; k < 3; k++) {
                ts_spline_options o;
                ts_spline_options_init(&o);
                o.form = (ts_form)form;
                o.shape = (ts_shape)shape;
                o.lower = (ts_line){0, -1};
                o.upper = (ts_line){0, 4};
                o.alpha = k == 0 ? DBL_MAX : k == 1 ? 1e300 : 0.5 * DBL_MAX;
                o.margin = k == 1 ? 1e300 : k == 2 ? 5e-324 : DBL_MAX;
                ts_spline *s = NULL;
                ts_error e;
                ts_status st = ts_spline_new(x, shape == 1 && k == 2 ? fz : f, 4, &o, &s, &e);
                /* documented: success, or INFEASIBLE when the a needed exceeds 1e307 */
                CHECKF(st == TS_OK || (st == TS_ERR_INFEASIBLE && e.where == TS_WHERE_INTERVAL),
                       "form %d shape %d k %d: %s", form, shape, k, ts_strerror(st));
                for (size_t i = 0; st == TS_OK && i < 3; i++) {
                    double a, B[4];
                    ts_spline_a(s, i, &a);
                    ts_spline_control(s, i, B, NULL);
                    CHECKF(isfinite(a) && a > 0 && isfinite(B[1]) && isfinite(B[2]),
                           "form %d shape %d k %d interval %zu: a = %g", form, shape, k, i, a);
                }
                if (st == TS_OK)
                    CHECK(ts_spline_certified(s));
                ts_spline_free(s);
            }
    /* the C¹ case the fuzz test found: alpha = DBL_MAX, subnormal margin */
    double xc[] = {-0x1.d9c6d9b0d3c42p+1, -0x1.d9745c12955cep+1, -0x1.d92fd234b200bp+1,
                   -0x1.d8e719189bb21p+1, -0x1.d8e70ee8aebd1p+1, -0x1.d8ae12c83eb26p+1,
                   -0x1.d85e248c1e40cp+1, -0x1.d85231e7a4502p+1, -0x1.d7fdce308a762p+1,
                   -0x1.d7d31dbe9d7bep+1, -0x1.d7ab310ad08d3p+1, -0x1.d74838595895ep+1,
                   -0x1.d72d5f3529b22p+1};
    double fc[] = {0x1.9d34ea5ac841ep-1, 0, 0x1.03764d8e6c22fp+0, 0x0.000000df944d9p-1022,
                   0x1.81f08e12a8291p+1, 0x1.db55abb43d223p-4, 0x1.ddd85dad06393p-1, 0,
                   0x1.1b6a6f6e42337p+2, 0x1.88f030d7ca60bp+1, 0x1.6b84baf122b91p-2, 0,
                   0x1.dd2d64cec7b4bp-2};
    ts_spline_options o;
    ts_spline_options_init(&o);
    o.form = TS_FORM_C1;
    o.slopes = TS_SLOPES_MAKIMA;
    o.shape = TS_SHAPE_POSITIVE;
    o.alpha = DBL_MAX;
    o.margin = 5e-324;
    o.certify = 0;
    ts_spline *s = NULL;
    ts_error e;
    ts_status st = ts_spline_new(xc, fc, 13, &o, &s, &e);
    CHECKF(st == TS_OK || st == TS_ERR_INFEASIBLE || st == TS_ERR_PRECISION, "%s",
           ts_strerror(st));
    for (size_t i = 0; st == TS_OK && i < 12; i++) {
        double a;
        ts_spline_a(s, i, &a);
        CHECK(isfinite(a));
    }
    ts_spline_free(s);
}

/* ts_spline_certify: the n reports are reset before the checks */
static void certify_out_params(void)
{
    double x[] = {0, 1, 2}, f[] = {1, 2, 1};
    ts_spline *s = NULL;
    CHECK(ts_spline_new(x, f, 3, NULL, &s, NULL) == TS_OK);
    ts_interval_report r[2];
    memset(r, 0, sizeof r);
    ts_line bad = {TH_NAN, 0}, lo = {0, 0};
    ts_error e;
    CHECK(ts_spline_certify(s, &bad, NULL, r, &e) == TS_ERR_NONFINITE && e.status == TS_ERR_NONFINITE);
    CHECK(isnan(r[0].a) && isnan(r[1].gap_lower) && r[1].certified == 0);
    memset(r, 0, sizeof r);
    CHECK(ts_spline_certify(s, NULL, NULL, r, &e) == TS_ERR_NULL && isnan(r[0].x0) && isnan(r[1].B[2]));
    CHECK(ts_spline_certify(s, &lo, NULL, r, &e) == TS_OK && r[0].certified && r[1].x1 == 2);
    ts_spline_free(s);
}

/* ts_spline_certify must accept what the build certified: in the geometric form
 * with certify = 0 the build's proof is the control-value test (S − L =
 * Σ A_l (Y_l − m X_l − c), all terms above their rounding), which holds
 * here while the exact gap is below ts_spline_certify's guard (values ~1e260):
 * ts_spline_certify said TS_ERR_VIOLATED for a spline that is provably above. */
static void certify_agrees_with_build(void)
{
    double x[] = {-0x1.fb083b9fee18fp+1, -0x1.d714e223bb238p-1};
    double f[] = {0x1.e79da258dfa3fp+864, -0x1.3267668252006p-3};
    ts_spline_options o;
    ts_spline_options_init(&o);
    o.form = TS_FORM_GEOMETRIC;
    o.shape = TS_SHAPE_ABOVE;
    o.alpha = 0x1.a7922c217b2eap-1;
    o.margin = 0x1.8207fca140cdbp-20;
    o.certify = 0;
    o.lower = (ts_line){-0x1.e27ed2dae18f6p-1, -0x1.1f4d007a1dc98p+0};
    ts_spline *s = NULL;
    CHECK(ts_spline_new(x, f, 2, &o, &s, NULL) == TS_OK && ts_spline_certified(s));
    ts_interval_report r;
    ts_status st = ts_spline_certify(s, &o.lower, NULL, &r, NULL);
    CHECKF(st == TS_OK && r.certified, "%s", ts_strerror(st));
    /* the same spline against a line above its right end is still refused */
    ts_line high = {0, 0};
    CHECK(ts_spline_certify(s, &high, NULL, &r, NULL) == TS_ERR_VIOLATED && !r.certified);
    ts_spline_free(s);
}

/* Closed curves: the slopes are computed on a periodic extension whose
 * knots t_r + T can coincide when a step is far below ulp(T).  That used to
 * divide by zero inside ts__slopes and report TS_ERR_NONFINITE with an index
 * into the extension (7 for 4 points).  Header: TS_ERR_UNSORTED, "a knot
 * step lost to rounding", index = the second point of the pair. */
static void closed_curve_lost_step(void)
{
    double p[] = {0, 0, 1e-40, 0, 1, 0, 0, 1};
    for (int par = 0; par < 2; par++) { /* centripetal: step 1e-20; chord: 1e-40 */
        ts_curve_options o;
        ts_curve_options_init(&o);
        o.closed = 1;
        o.param = (ts_param)par;
        ts_curve *c = NULL;
        ts_error e;
        ts_status st = ts_curve_new(p, 4, 2, &o, &c, &e);
        CHECKF(st == TS_ERR_UNSORTED && e.index == 1 && e.where == TS_WHERE_POINT && !c,
               "param %d: %s at %zu", par, ts_strerror(st), e.index);
        ts_curve_free(c);
    }
    /* overflowing slopes of a closed curve name a real point (< 5) */
    double q[] = {-0x1.16c0d9e423829p-13, -0x1.28bfa64a9677p-11, 0x1.a604b2a86209dp-13,
                  -0x1.d297ff9423528p-14, 0x1.4b198aa48b174p-15, -0x1.6741b1295e8aep-12,
                  -0x1.6b54c774ebe46p-13, DBL_MAX, -0x1.16c0d9e423829p-13, -0x1.28bfa64a9677p-11};
    ts_curve_options o;
    ts_curve_options_init(&o);
    o.closed = 1;
    o.param = TS_PARAM_UNIFORM;
    ts_curve *c = NULL;
    ts_error e;
    ts_status st = ts_curve_new(q, 5, 2, &o, &c, &e);
    CHECKF(st == TS_ERR_SLOPE_OVERFLOW && e.where == TS_WHERE_POINT && e.index < 4,
           "%s at %zu", ts_strerror(st), e.index);
    ts_curve_free(c);
}

/* Arc length of a curve with control points near DBL_MAX: the sums of the
 * quadrature overflowed and |fine − I| became inf − inf = NaN.  Now the
 * control points are scaled by a power of two first, so the length of the
 * curve scaled by 2^1020 is exactly 2^1020 times the length (the knots, the
 * k_i, the control points and every quadrature value scale exactly). */
static void curve_length_scaled(void)
{
    double p[2 * 12], q[2 * 12];
    for (int i = 0; i < 12; i++) {
        double a = 2 * 3.14159265358979323846 * i / 12;
        p[2 * i] = cos(a) * (1 + 0.3 * (i % 3));
        p[2 * i + 1] = sin(a);
        q[2 * i] = ldexp(p[2 * i], 1020);
        q[2 * i + 1] = ldexp(p[2 * i + 1], 1020);
    }
    for (int par = 0; par < 3; par++)
        for (int closed = 0; closed < 2; closed++) {
            ts_curve_options o;
            ts_curve_options_init(&o);
            o.param = (ts_param)par;
            o.closed = closed;
            ts_curve *a = NULL, *b = NULL;
            CHECK(ts_curve_new(p, 12, 2, &o, &a, NULL) == TS_OK);
            CHECK(ts_curve_new(q, 12, 2, &o, &b, NULL) == TS_OK);
            double la = TH_NAN, lb = TH_NAN;
            CHECK(ts_curve_length(a, 1e-12, &la) == TS_OK && ts_curve_length(b, 1e-12, &lb) == TS_OK);
            CHECKF(isfinite(lb) && lb == ldexp(la, 1020), "param %d closed %d: %.17g vs %.17g",
                   par, closed, lb, ldexp(la, 1020));
            ts_curve_free(a);
            ts_curve_free(b);
        }
    /* alpha = DBL_MIN: control points ~1e307; the length is a number */
    double r[] = {0, 0, 1, 0, 1, 1, 0, 1};
    ts_curve_options o;
    ts_curve_options_init(&o);
    o.alpha = DBL_MIN;
    ts_curve *c = NULL;
    CHECK(ts_curve_new(r, 4, 2, &o, &c, NULL) == TS_OK);
    double len = TH_NAN;
    CHECK(ts_curve_length(c, 1e-9, &len) == TS_OK && !isnan(len) && len > 1e300);
    ts_curve_free(c);
    /* the fuzz test's case: two points, harmonic slopes; the length was NaN */
    double r2[] = {-0x1.24eac5650b7d4p+3, -0x1.78eb27004689ep+0, -0x1.035627ac9db9ap+4,
                   0x1.2467ce43884b1p+3};
    o.param = TS_PARAM_UNIFORM;
    o.slopes = TS_SLOPES_HARMONIC;
    CHECK(ts_curve_new(r2, 2, 2, &o, &c, NULL) == TS_OK);
    CHECK(ts_curve_length(c, 0x1.11f82622c46dcp-14, &len) == TS_OK && !isnan(len) && len > 0);
    ts_curve_free(c);
}

/* Chord knots of points ~1e-310 apart: dθ/dt = (π/2)/h overflowed and
 * dP/dt came out ±inf or NaN.  Chord parameters make the curve of s·P the
 * curve of P with t scaled by s, so dP/dt is scale-free: compare with the
 * same points scaled by 2^1030 (normal numbers).  Tolerance 1e-10 relative:
 * the tiny curve's control points are subnormal (>= 40 significant bits). */
static void curve_tiny_steps(void)
{
    double p[] = {0, 0, 1e-310, 0, 1e-310, 1e-310, 0, 2e-310}, q[8];
    for (int i = 0; i < 8; i++)
        q[i] = ldexp(p[i], 1030);
    ts_curve_options o;
    ts_curve_options_init(&o);
    o.param = TS_PARAM_CHORD;
    ts_curve *a = NULL, *b = NULL;
    CHECK(ts_curve_new(p, 4, 2, &o, &a, NULL) == TS_OK);
    CHECK(ts_curve_new(q, 4, 2, &o, &b, NULL) == TS_OK);
    if (!a || !b) {
        ts_curve_free(a);
        ts_curve_free(b);
        return;
    }
    const double *ta = ts_curve_knots(a), *tb = ts_curve_knots(b);
    for (int k = 0; k <= 12; k++) {
        double P[2], dP[2], Q[2], dQ[2];
        CHECK(ts_curve_eval(a, ta[3] * k / 12.0, NULL, P, dP, NULL) == TS_OK);
        CHECK(ts_curve_eval(b, tb[3] * k / 12.0, NULL, Q, dQ, NULL) == TS_OK);
        for (int d = 0; d < 2; d++)
            CHECKF(fabs(dP[d] - dQ[d]) <= 1e-10 * (fabs(dQ[0]) + fabs(dQ[1])),
                   "k %d coord %d: %.17g vs %.17g", k, d, dP[d], dQ[d]);
    }
    /* at t_0 (open end): d_0/a_0 with the docs/method.md §6 end formula:
     * x: Δ0 = 1, Δ1 = 0 -> 1.5; y: Δ0 = 0, Δ1 = 1 -> -0.5 */
    double P[2], dP[2];
    CHECK(ts_curve_eval(a, 0.0, NULL, P, dP, NULL) == TS_OK);
    CHECK(fabs(dP[0] - 1.5) <= 1e-10 && fabs(dP[1] + 0.5) <= 1e-10);
    ts_curve_free(a);
    ts_curve_free(b);
}

/* Curves: alpha + beta that overflows is TS_ERR_BETA (as for splines);
 * certify_box resets its reports before the checks. */
static void curve_params_and_reports(void)
{
    double p[] = {0, 0, 1, 0, 1, 1};
    ts_curve_options o;
    ts_curve_options_init(&o);
    o.alpha = DBL_MAX;
    o.beta = DBL_MAX;
    ts_curve *c = NULL;
    ts_error e;
    CHECK(ts_curve_new(p, 3, 2, &o, &c, &e) == TS_ERR_BETA && e.index == 0 &&
          e.where == TS_WHERE_INTERVAL && !c);
    ts_curve_options_init(&o);
    CHECK(ts_curve_new(p, 3, 2, &o, &c, &e) == TS_OK);
    ts_interval_report r[4];
    memset(r, 0, sizeof r);
    int has[3] = {1, 0, 0};
    double lo[3] = {TH_NAN, 0, 0};
    CHECK(ts_curve_certify_box(c, has, lo, NULL, NULL, r, &e) == TS_ERR_NONFINITE);
    CHECK(isnan(r[0].x0) && isnan(r[3].gap_lower) && r[2].certified == 0);
    memset(r, 0, sizeof r);
    CHECK(ts_curve_certify_box(c, has, NULL, NULL, NULL, r, &e) == TS_ERR_NULL && isnan(r[1].a));
    lo[0] = -1;
    CHECK(ts_curve_certify_box(c, has, lo, NULL, NULL, r, &e) == TS_OK && r[0].certified &&
          r[0].has_lower == 1 && r[1].has_lower == 0);
    ts_curve_free(c);
}

int main(void)
{
    TH_CASE("slopes_wide_knots");
    slopes_wide_knots();
    TH_CASE("akima_huge");
    akima_huge();
    TH_CASE("slopes_out_params");
    slopes_out_params();
    TH_CASE("tiny_alpha_positive");
    tiny_alpha_positive();
    TH_CASE("huge_alpha");
    huge_alpha();
    TH_CASE("certify_out_params");
    certify_out_params();
    TH_CASE("certify_agrees_with_build");
    certify_agrees_with_build();
    TH_CASE("closed_curve_lost_step");
    closed_curve_lost_step();
    TH_CASE("curve_length_scaled");
    curve_length_scaled();
    TH_CASE("curve_tiny_steps");
    curve_tiny_steps();
    TH_CASE("curve_params_and_reports");
    curve_params_and_reports();
    return th_report("test_api_contract");
}
