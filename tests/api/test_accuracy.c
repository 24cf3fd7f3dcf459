/* Accuracy (docs/method.md §8, docs/accuracy.md): the counterexample to the paper's
 * Theorem 1, the error constants against tests/ref/accuracy_ref.csv
 * (mpmath, from the definition of the spline), the proven bound on the
 * study's functions, the measured orders within derived limits, lines in
 * every form. */
#include "th.h"
#include "th_options.h"
#include "common/th_rng.h"
#include "trigspline.h"

#include <float.h>
#include <string.h>

#define EPS DBL_EPSILON
#define PI_T 3.14159265358979323846

typedef struct fun {
    double lo, hi, (*f)(double), (*fp)(double), m1, m2;
} fun;
static double f_sin(double x) { return sin(x); }
static double fp_sin(double x) { return cos(x); }
static double f_exp(double x) { return exp(x); }
static double fp_exp(double x) { return exp(x); }
static double f_runge(double x) { return 1.0 / (1.0 + 25.0 * x * x); }
static double fp_runge(double x)
{
    double q = 1.0 + 25.0 * x * x;
    return -50.0 * x / (q * q);
}
static double f_pos(double x) { return (x - 0.3) * (x - 0.3) + 1e-3; }
static double fp_pos(double x) { return 2.0 * (x - 0.3); }
/* max |f'|, |f''| on the interval, closed forms (see accuracy/accuracy.c):
 * Runge f' = -50x/q², extreme at 25x² = 1/3: 90/(16√3); f'' max at 0: 50 */
static const fun funs[4] = {
    {0.0, 3.0, f_sin, fp_sin, 1.0, 1.0},
    {-1.0, 1.0, f_exp, fp_exp, 2.718281828459046, 2.718281828459046},
    {-1.0, 1.0, f_runge, fp_runge, 3.2475952641916446, 50.0},
    {0.0, 1.0, f_pos, fp_pos, 1.4, 2.0},
};


/* Build on n intervals (grid uniform or perturbed ±35% h), slopes exact or
 * a method, a > 0 scalar or a < 0: per-interval log-uniform in [0.5, 2].
 * Returns the max error over 15 points inside each interval; *bound gets
 * ts_spline_error_bound (exact slopes: the two-term bound too). */
static double study(const fun *F, size_t n, int pert, ts_form form, ts_slopes sl, double a,
                    double *bound)
{
    double *x = malloc((n + 1) * sizeof *x), *f = malloc((n + 1) * sizeof *f);
    double *d = malloc((n + 1) * sizeof *d), *al = malloc(n * sizeof *al);
    double e = TH_NAN, h = (F->hi - F->lo) / (double)n;
    *bound = TH_NAN;
    th_seed(12345u + n);
    for (size_t i = 0; i <= n; i++)
        x[i] = F->lo + h * (double)i;
    if (pert)
        for (size_t i = 1; i < n; i++)
            x[i] += 0.35 * h * (2 * th_unit() - 1);
    x[n] = F->hi;
    for (size_t i = 0; i <= n; i++)
        f[i] = F->f(x[i]), d[i] = F->fp(x[i]);
    for (size_t i = 0; i < n; i++)
        al[i] = 0.5 * pow(4.0, th_unit());
    if (sl != TS_SLOPES_USER)
        CHECK(ts_slopes_compute(sl, x, f, n + 1, d, NULL) == TS_OK);
    ts_spline_options o;
    th_options_paper(&o);
    o.form = form;
    o.slopes = TS_SLOPES_USER;
    o.user_slopes = d;
    o.n_user_slopes = n + 1;
    if (a > 0)
        o.alpha = a;
    else
        o.alphas = al, o.n_alphas = n;
    ts_spline *s = NULL;
    if (ts_spline_new(x, f, n + 1, &o, &s, NULL) == TS_OK) {
        e = 0;
        ts_cursor cur = TS_CURSOR_INIT;
        for (size_t i = 0; i < n; i++)
            for (int j = 1; j < 16; j++) {
                double xx = x[i] + (x[i + 1] - x[i]) * j / 16.0, y;
                ts_spline_eval(s, xx, &cur, &y);
                e = fmax(e, fabs(y - F->f(xx)));
            }
        CHECK(ts_spline_error_bound(s, F->m1, F->m2, sl == TS_SLOPES_USER, bound, NULL) == TS_OK);
    }
    CHECK(s != NULL);
    ts_spline_free(s);
    free(x), free(f), free(d), free(al);
    return e;
}

/* ---- the paper's Theorem 1 does not hold ------------------------------ */
static double ref_const(int form, double a, int which)
{
    FILE *fp = fopen(TS_SOURCE_DIR "/tests/ref/accuracy_ref.csv", "r");
    char line[512];
    double r = TH_NAN;
    while (fp && fgets(line, sizeof line, fp)) {
        int fo;
        double v[5];
        if (sscanf(line, "const,%d,%lf,%lf,%lf,%lf,%lf", &fo, &v[0], &v[1], &v[2], &v[3], &v[4]) == 6 &&
            fo == form && fabs(v[0] - a) <= 1e-15)
            r = v[which];
    }
    if (fp)
        fclose(fp);
    return r;
}

static void test_theorem1(void)
{
    /* f(x) = x, exact slope 1, paper form, a = 1: f''' = 0, so Theorem 1
     * promises |f − S| <= 0; the error is line(1)·h = 0.0034458·h
     * (reference: mpmath, the error of the spline built from f = t). */
    double line1 = ref_const(0, 1.0, 2);
    CHECK_CLOSE(line1, 0.0034458141157061154, 1e-15);
    const double hs[3] = {1.0, 0.01, 1e-6};
    for (int k = 0; k < 3; k++) {
        double x[2] = {2.0, 2.0 + hs[k]}, f[2] = {2.0, 2.0 + hs[k]}, d[2] = {1, 1};
        double h = x[1] - x[0]; /* the h the spline sees */
        ts_spline_options o;
        th_options_paper(&o);
        o.slopes = TS_SLOPES_USER;
        o.user_slopes = d;
        o.n_user_slopes = 2;
        ts_spline *s = NULL;
        CHECK(ts_spline_new(x, f, 2, &o, &s, NULL) == TS_OK);
        double worst = 0;
        for (int j = 0; j <= 4000; j++) {
            double xx = x[0] + h * j / 4000.0, y;
            ts_spline_eval(s, xx, NULL, &y);
            worst = fmax(worst, fabs(y - xx));
        }
        /* dense sampling (step h/4000 near a smooth maximum) gets within
         * 1e-6 relative; rounding adds ~4 ε |x| */
        CHECKF(fabs(worst - line1 * h) <= 1e-6 * line1 * h + 8 * EPS * 3,
               "h %g: error %.6g, expected %.6g", h, worst, line1 * h);
        CHECK(worst > 0.003 * h); /* > 0 = the Theorem 1 bound */
        /* the proven bounds hold and, for a line, are attained */
        double b1, b2;
        CHECK(ts_spline_error_bound(s, 1.0, 0.0, 1, &b2, NULL) == TS_OK); /* M2 = 0 */
        CHECK(ts_spline_error_bound(s, 1.0, TH_INF, 0, &b1, NULL) == TS_OK);
        CHECK(worst <= b2 && b2 <= worst * (1 + 1e-5) + 8 * EPS * 3);
        ts_error_constants c;
        CHECK(ts_error_constants_get(TS_FORM_PAPER, 1.0, &c) == TS_OK);
        CHECK_CLOSE(b1, c.first * h, 1e-12 * c.first * h); /* |d| = M1: docs/method.md §8 constant */
        ts_spline_free(s);
    }
}

/* ---- constants against the reference ----------------------------------- */
static void test_constants(void)
{
    const double as[6] = {0.3472, 0.42441318157838759, 0.5, 1.0, 2.0, 5.0};
    for (int j = 0; j < 6; j++)
        for (int g = 0; g < 2; g++) {
            ts_error_constants c;
            ts_form form = g ? TS_FORM_GEOMETRIC : TS_FORM_PAPER;
            CHECK(ts_error_constants_get(form, as[j], &c) == TS_OK);
            double rf = ref_const(g ? 2 : 0, as[j], 1), rl = ref_const(g ? 2 : 0, as[j], 2),
                   rs2 = ref_const(g ? 2 : 0, as[j], 3);
            /* the library's maximum is refined by golden section (location to
             * 1e-13, value to rounding) and enlarged by 1e-12; the reference's
             * quadrature is good to ~1e-15: agree to 1e-9 relative, never below */
            CHECKF(c.first >= rf * (1 - 1e-12) && c.first <= rf * (1 + 1e-9), "first a=%g g=%d: %.17g vs %.17g",
                   as[j], g, c.first, rf);
            CHECKF(c.line >= rl * (1 - 1e-12) && c.line <= rl * (1 + 1e-9) + 1e-300, "line a=%g g=%d: %.17g vs %.17g",
                   as[j], g, c.line, rl);
            CHECKF(c.second >= rs2 * (1 - 1e-9) && c.second <= rs2 * (1 + 1e-9), "second a=%g g=%d: %.17g vs %.17g",
                   as[j], g, c.second, rs2);
        }
    /* C¹ with one a is the paper form */
    ts_error_constants c1, cp;
    CHECK(ts_error_constants_get(TS_FORM_C1, 0.7, &c1) == TS_OK);
    CHECK(ts_error_constants_get(TS_FORM_PAPER, 0.7, &cp) == TS_OK);
    CHECK(c1.first == cp.first && c1.line == cp.line && c1.second == cp.second);
    /* error paths */
    CHECK(ts_error_constants_get(TS_FORM_PAPER, 1.0, NULL) == TS_ERR_NULL);
    CHECK(ts_error_constants_get((ts_form)3, 1.0, &c1) == TS_ERR_OPTION && isnan(c1.first));
    CHECK(ts_error_constants_get(TS_FORM_PAPER, 0.0, &c1) == TS_ERR_OPTION);
    CHECK(ts_error_constants_get(TS_FORM_PAPER, -1.0, &c1) == TS_ERR_OPTION);
    CHECK(ts_error_constants_get(TS_FORM_PAPER, TH_NAN, &c1) == TS_ERR_OPTION);
    CHECK(ts_error_constants_get(TS_FORM_PAPER, TH_INF, &c1) == TS_ERR_OPTION);
    CHECK(ts_error_constants_get(TS_FORM_GEOMETRIC, 0.347, &c1) == TS_ERR_GEOMETRIC);
    CHECK(ts_error_constants_get(TS_FORM_GEOMETRIC, TS_GEOMETRIC_A_MIN, &c1) == TS_OK);
}

static void test_bound_errors(void)
{
    double x[3] = {0, 1, 2}, f[3] = {0, 1, 0}, b = 0, per[2];
    ts_spline *s = NULL;
    CHECK(ts_spline_new(x, f, 3, NULL, &s, NULL) == TS_OK);
    CHECK(ts_spline_error_bound(NULL, 1, 1, 1, &b, NULL) == TS_ERR_NULL && isnan(b));
    CHECK(ts_spline_error_bound(s, 1, 1, 1, NULL, NULL) == TS_ERR_NULL);
    CHECK(ts_spline_error_bound(s, TH_NAN, 1, 0, &b, NULL) == TS_ERR_NONFINITE && isnan(b));
    CHECK(ts_spline_error_bound(s, TH_INF, 1, 0, &b, NULL) == TS_ERR_NONFINITE);
    CHECK(ts_spline_error_bound(s, -1, 1, 0, &b, NULL) == TS_ERR_OPTION);
    CHECK(ts_spline_error_bound(s, 1, TH_NAN, 1, &b, NULL) == TS_ERR_NONFINITE);
    CHECK(ts_spline_error_bound(s, 1, -1, 1, &b, NULL) == TS_ERR_OPTION);
    CHECK(ts_spline_error_bound(s, 1, TH_NAN, 0, &b, NULL) == TS_OK); /* ignored without exact slopes */
    CHECK(ts_spline_error_bound(s, 1, TH_INF, 1, &b, per) == TS_OK);
    CHECK(b == fmax(per[0], per[1]) && per[0] > 0);
    ts_spline_free(s);
}

/* ---- the study, small ---------------------------------------------------- */
static void test_bound_holds(void)
{
    const ts_slopes sls[4] = {TS_SLOPES_USER, TS_SLOPES_ARITHMETIC, TS_SLOPES_FRITSCH_CARLSON,
                              TS_SLOPES_AKIMA};
    const double as[4] = {0.5, 1.0, 2.0, -1.0};
    const size_t ns[3] = {10, 100, 1000};
    int checked = 0, violated = 0;
    for (int fi = 0; fi < 4; fi++)
        for (int g = 0; g < 2; g++)
            for (int fo = 0; fo < 3; fo++)
                for (int si = 0; si < 4; si++)
                    for (int ai = 0; ai < 4; ai++)
                        for (int k = 0; k < 3; k++) {
                            if (ns[k] == 1000 && (si > 1 || g))
                                continue; /* keep the run short */
                            double b, e = study(&funs[fi], ns[k], g, (ts_form)fo, sls[si], as[ai], &b);
                            checked++;
                            if (!(e <= b)) {
                                violated++;
                                fprintf(stderr, "bound violated: f%d g%d form%d slopes%d a%g n%zu: %g > %g\n",
                                        fi, g, fo, (int)sls[si], as[ai], ns[k], e, b);
                            }
                        }
    CHECKF(violated == 0 && checked > 700, "%d of %d violated", violated, checked);
    /* and it is not vacuous: paper form, a = 1, exact slopes, sin, n = 1000:
     * error ≈ line h max|f'| (at x near 0), bound = line h + second h² (at the
     * same θ: <= (1 + second h/line) ≈ 1.06 times it); allow 1.1 */
    double b, e = study(&funs[0], 1000, 0, TS_FORM_PAPER, TS_SLOPES_USER, 1.0, &b);
    CHECKF(b <= 1.1 * e, "bound %g error %g", b, e);
    /* geometric, a = 1, exact: the bound is second·h²·max|f''| with second =
     * max ∫|K|; for a smooth f (f'' nearly constant over an interval) the
     * error is h² |f''| |∫K|, and the f''-kernel changes sign: max |∫K| is
     * 0.0242 against max ∫|K| = 0.0648 at a = 1 (docs/accuracy.md §3), a
     * factor 2.7; allow 3 */
    e = study(&funs[0], 1000, 0, TS_FORM_GEOMETRIC, TS_SLOPES_USER, 1.0, &b);
    CHECKF(e <= b && b <= 3.0 * e, "geometric bound %g error %g", b, e);
}

/* least-squares order over n = 100, 316, 1000 */
static double order(const fun *F, int pert, ts_form fo, ts_slopes sl, double a)
{
    const size_t ns[3] = {100, 316, 1000};
    double sx = 0, sy = 0, sxx = 0, sxy = 0, b;
    for (int k = 0; k < 3; k++) {
        double X = log((double)ns[k]), Y = -log(study(F, ns[k], pert, fo, sl, a, &b));
        sx += X, sy += Y, sxx += X * X, sxy += X * Y;
    }
    return (3 * sxy - sx * sy) / (3 * sxx - sx * sx);
}

/* Expected orders (docs/accuracy.md §3):
 *  paper/C¹ form, exact slopes: e = f'(x) h ε(θ) + h² ∫K f'': first order,
 *    local order 1 + B h/(A + B h) with A = line·|f'|, B = second·|f''|.
 *    For a = 0.5, 2 (line 0.099, 0.054) and h <= 0.03, B h/A <= 0.05 (sin,
 *    exp, pos: |f''|/|f'| <= ~1.4 where the max sits): order in [0.85, 1.15];
 *    for a = 1 (line 0.00345) B h/A reaches ~0.5 at n = 100: [0.85, 1.35].
 *  estimated slopes: a slope error η adds k η A1; for the paper form η is
 *    O(h) at worst, so still first order: [0.8, 1.3].
 *  geometric form: e = h² ∫K f'' exactly (lines reproduced), so order 2;
 *    arithmetic-mean slopes are O(h²) accurate on uniform grids: [1.85, 2.15];
 *    perturbed grids, random a_i and other methods: [1.7, 2.4] (the max
 *    over random intervals makes a 3-point fit noisy).
 *  Runge at n = 100 is not yet asymptotic (h = 0.02 vs its width 0.2): the
 *    loose limits for it. */
static void test_orders(void)
{
    for (int fi = 0; fi < 4; fi++) {
        int runge = fi == 2;
        double lo1 = runge ? 0.75 : 0.85, hi1 = runge ? 1.4 : 1.15;
        double p;
        p = order(&funs[fi], 0, TS_FORM_PAPER, TS_SLOPES_USER, 0.5);
        CHECKF(p >= lo1 && p <= hi1, "f%d paper a=0.5 order %.3f", fi, p);
        p = order(&funs[fi], 0, TS_FORM_PAPER, TS_SLOPES_USER, 2.0);
        CHECKF(p >= lo1 && p <= hi1, "f%d paper a=2 order %.3f", fi, p);
        p = order(&funs[fi], 0, TS_FORM_PAPER, TS_SLOPES_USER, 1.0);
        CHECKF(p >= 0.85 && p <= (runge ? 1.5 : 1.35), "f%d paper a=1 order %.3f", fi, p);
        p = order(&funs[fi], 1, TS_FORM_C1, TS_SLOPES_ARITHMETIC, -1.0);
        CHECKF(p >= 0.75 && p <= 1.4, "f%d C1 mixed perturbed order %.3f", fi, p);
        p = order(&funs[fi], 0, TS_FORM_PAPER, TS_SLOPES_AKIMA, 1.0);
        CHECKF(p >= 0.8 && p <= (runge ? 1.5 : 1.3), "f%d paper akima order %.3f", fi, p);
        p = order(&funs[fi], 0, TS_FORM_GEOMETRIC, TS_SLOPES_USER, 1.0);
        CHECKF(p >= 1.85 && p <= 2.15, "f%d geometric order %.3f", fi, p);
        p = order(&funs[fi], 0, TS_FORM_GEOMETRIC, TS_SLOPES_ARITHMETIC, 0.5);
        CHECKF(p >= 1.85 && p <= 2.15, "f%d geometric arith order %.3f", fi, p);
        p = order(&funs[fi], 1, TS_FORM_GEOMETRIC, TS_SLOPES_FRITSCH_CARLSON, 2.0);
        CHECKF(p >= 1.7 && p <= 2.4, "f%d geometric FC perturbed order %.3f", fi, p);
        p = order(&funs[fi], 0, TS_FORM_GEOMETRIC, TS_SLOPES_USER, -1.0);
        CHECKF(p >= 1.7 && p <= 2.4, "f%d geometric mixed-a order %.3f", fi, p);
    }
}

/* Lines in every form: paper and C¹ miss y = m x + c by line(a)·h·|m| (the
 * maximum over the interval, attained); the geometric form is exact. */
static void test_lines_forms(void)
{
    double x[41], f[41], d[41], m = -2.5, c = 0.75;
    for (int i = 0; i <= 40; i++)
        x[i] = 0.1 * i + 0.02 * sin(7.0 * i), f[i] = m * x[i] + c, d[i] = m;
    for (int fo = 0; fo < 3; fo++)
        for (int ai = 0; ai < 3; ai++) {
            double a = ai == 0 ? 0.5 : ai == 1 ? 1.0 : 3.0;
            ts_spline_options o;
            th_options_paper(&o);
            o.form = (ts_form)fo;
            o.slopes = TS_SLOPES_USER;
            o.user_slopes = d;
            o.n_user_slopes = 41;
            o.alpha = a;
            ts_spline *s = NULL;
            CHECK(ts_spline_new(x, f, 41, &o, &s, NULL) == TS_OK);
            ts_error_constants k;
            ts_error_constants_get((ts_form)fo, a, &k);
            double worst_rel = 0, worst_abs = 0, worst_slope = 0;
            for (int i = 0; i < 40; i++) {
                double h = x[i + 1] - x[i], e = 0;
                for (int j = 0; j <= 800; j++) {
                    double xx = x[i] + h * j / 800.0, y, dy;
                    ts_spline_eval_deriv(s, xx, NULL, &y, &dy, NULL);
                    e = fmax(e, fabs(y - (m * xx + c)));
                    if (j == 0)
                        worst_slope = fmax(worst_slope, fabs(dy - m));
                }
                worst_abs = fmax(worst_abs, e);
                worst_rel = fmax(worst_rel, e / (h * fabs(m)));
            }
            if (fo == 2) {
                /* rounding: ~16 ulps of the values (|y| <= 10) */
                CHECKF(worst_abs <= 16 * EPS * 10, "geometric line a=%g: %g", a, worst_abs);
                CHECKF(worst_slope <= 16 * EPS * 10, "geometric knot slope a=%g: %g", a, worst_slope);
            } else {
                /* sampling at h/800 finds the maximum to 1e-5 relative */
                CHECKF(fabs(worst_rel - k.line) <= 1e-5 * k.line, "form %d a=%g: %g vs %g", fo, a,
                       worst_rel, k.line);
                /* and the knot slope is d/a, not d (docs/method.md §3) */
                CHECK_CLOSE(worst_slope, fabs(m / a - m), 1e-12);
            }
            ts_spline_free(s);
        }
}

int main(void)
{
    TH_CASE("theorem1");
    test_theorem1();
    TH_CASE("constants");
    test_constants();
    TH_CASE("bound_errors");
    test_bound_errors();
    TH_CASE("lines_forms");
    test_lines_forms();
    TH_CASE("bound_holds");
    test_bound_holds();
    TH_CASE("orders");
    test_orders();
    return th_report("test_accuracy");
}
