/* Certificates (docs/method.md §2, §5): ts__trig_min against closed forms, an mpmath
 * reference (tests/ref/certify_trigmin_ref.py) and brute force; interval
 * gaps against dense sampling of ts_spline_eval; ts_spline_certify, ts_spline_report,
 * ts_spline_certified and their error paths. */
#include "th.h"
#include "th_options.h"
#include "common/th_basis.h"
#include "common/th_rng.h"
#include "trigspline.h"
#include "internal.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#define EPS DBL_EPSILON
static const double HALF_PI = 1.57079632679489661923;


/* g(θ) from docs/method.md §2 written out with libm sin/cos (not certify.c's form) */
static double g_ref(const double C[4], double k, double th)
{
    return th_seg(C, th) - k * th;
}

static double maxabs(const double C[4], double k)
{
    double m = fabs(k) * HALF_PI;
    for (int l = 0; l < 4; l++)
        m = fabs(C[l]) > m ? fabs(C[l]) : m;
    return m;
}

/* Tolerance for comparing a computed minimum with an exact one: the rounding
 * of evaluating g (certify.c bound (1): 16 ε (max|C| + |κ|π/2)) times 4, plus
 * the error of g_ref's own cancelling form 1 − s (≤ 8ε max|C| relative to
 * the scale, since A_l ≤ 1 and |1 − s| error ≤ ε): 64ε·scale in all. */
static double tol_eval(const double C[4], double k)
{
    return 64.0 * EPS * (maxabs(C, k) + fabs(k) * HALF_PI);
}

/* |g''| ≤ 8|C1−C0| + 8|C2−C0| + 6|C3−C0| (max|A_l''| on [0, π/2] is
 * 6, 8, 8, 6, computed numerically; Σ A_l'' = 0; (κθ)'' = 0). */
static double g2_bound(const double C[4])
{
    return 8 * fabs(C[1] - C[0]) + 8 * fabs(C[2] - C[0]) + 6 * fabs(C[3] - C[0]);
}

static void test_closed_forms(void)
{
    double th;
    double C1[4] = {1, 0, 0, 1};
    /* symmetric: min at π/4, value 2(1 − √2/2)³ */
    double v = ts__trig_min(C1, 0.0, &th);
    double s = sqrt(0.5);
    CHECK_CLOSE(v, 2 * (1 - s) * (1 - s) * (1 - s), 8 * EPS);
    CHECK_CLOSE(th, HALF_PI / 2, 1e-7); /* flat min: θ error ~ sqrt(ε) */
    /* constant: exactly the constant */
    double C2[4] = {3.25, 3.25, 3.25, 3.25};
    v = ts__trig_min(C2, 0.0, &th);
    CHECK(v == 3.25);
    CHECK(th >= 0 && th <= HALF_PI);
    /* constant minus κθ: min at π/2 for κ > 0, at 0 for κ < 0 */
    v = ts__trig_min(C2, 2.0, &th);
    CHECK_CLOSE(v, 3.25 - 2.0 * HALF_PI, 8 * EPS * 4);
    CHECK(th == HALF_PI);
    v = ts__trig_min(C2, -2.0, &th);
    CHECK(v == 3.25 && th == 0.0);
    /* zeros */
    double C3[4] = {0, 0, 0, 0};
    v = ts__trig_min(C3, 0.0, &th);
    CHECK(v == 0.0 && th == 0.0);
    /* monotone control polygon: S monotone (docs/method.md (2.1)), min at an end */
    double C4[4] = {1, 2, 3, 4};
    v = ts__trig_min(C4, 0.0, &th);
    CHECK(v == 1.0 && th == 0.0);
    double C5[4] = {4, 3, 2, 1};
    v = ts__trig_min(C5, 0.0, &th);
    CHECK_CLOSE(v, 1.0, 4 * EPS);
    CHECK(th == HALF_PI);
    /* the paper form misses the line y = x (docs/method.md §5): B = x-values of the
     * line at k = 2h/(3π) (a = 1, d = 1, h = 1), L(x) = x: C_l = B_l − 0,
     * κ = 2/π; its minimum is −0.00345 (docs/method.md §5, §8: "missed by up to
     * 0.00345·h"); computed here by brute force too below */
    double k = 2.0 / (3.0 * 3.14159265358979323846);
    double C6[4] = {0, k, 1 - k, 1};
    v = ts__trig_min(C6, 2.0 / 3.14159265358979323846, &th);
    CHECK(v < -0.0034 && v > -0.0035);
    /* NaN and infinities propagate to NaN */
    double C7[4] = {1, TH_NAN, 0, 1};
    v = ts__trig_min(C7, 0.0, &th);
    CHECK(isnan(v) && isnan(th));
    double C8[4] = {1, TH_INF, 0, 1};
    v = ts__trig_min(C8, 0.0, &th);
    CHECK(isnan(v));
    v = ts__trig_min(C1, TH_NAN, &th);
    CHECK(isnan(v));
    /* NULL theta allowed */
    v = ts__trig_min(C1, 0.0, NULL);
    CHECK_CLOSE(v, 2 * (1 - s) * (1 - s) * (1 - s), 8 * EPS);
}

/* Power-of-two scaling is exact in the method: same θ, value scaled. */
static void test_scaling(void)
{
    for (int r = 0; r < 200; r++) {
        double C[4], k = th_range(-2, 2), th0, th1, Cs[4];
        for (int l = 0; l < 4; l++)
            C[l] = th_range(-1, 1);
        int e = (int)th_range(-900, 900);
        for (int l = 0; l < 4; l++)
            Cs[l] = ldexp(C[l], e);
        double v0 = ts__trig_min(C, k, &th0);
        double v1 = ts__trig_min(Cs, ldexp(k, e), &th1);
        CHECKF(v1 == ldexp(v0, e) && th0 == th1, "e=%d v0=%g v1=%g", e, v0, v1);
    }
}

static void test_reference(void)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/tests/ref/certify_trigmin_ref.csv", TS_SOURCE_DIR);
    FILE *fp = fopen(path, "r");
    CHECKF(fp != NULL, "cannot open %s", path);
    if (!fp)
        return;
    char line[1024];
    int cases = 0;
    while (fgets(line, sizeof line, fp)) {
        if (line[0] == '#')
            continue;
        double C[4], k, ref, thr;
        if (sscanf(line, "%lf,%lf,%lf,%lf,%lf,%lf,%lf", &C[0], &C[1], &C[2], &C[3], &k, &ref,
                   &thr) != 7)
            continue;
        cases++;
        double th;
        double v = ts__trig_min(C, k, &th);
        double tol = tol_eval(C, k);
        /* value: within the evaluation bound of the 60-digit minimum */
        CHECKF(fabs(v - ref) <= tol, "case %d: got %.17g ref %.17g tol %.3g", cases, v, ref, tol);
        /* location: g at the returned θ is that minimum (θ itself is not
         * unique for flat or symmetric g) */
        CHECKF(th >= 0 && th <= HALF_PI && fabs(g_ref(C, k, th) - ref) <= tol,
               "case %d: g(theta=%.17g)=%.17g ref %.17g", cases, th, g_ref(C, k, th), ref);
    }
    fclose(fp);
    CHECKF(cases >= 300, "only %d reference cases", cases);
}

/* Random inputs against a dense sampling: the certificate is never above a
 * sampled value (soundness) and below the sampled minimum by at most the
 * sampling bound ½|g''| (Δ/2)² (the true minimum lies within Δ/2 of a
 * sample, where g' = 0 or it is an end, which is sampled). */
static void test_brute(void)
{
    const int N = 2000;
    const double D = HALF_PI / N;
    int fails = 0;
    for (int r = 0; r < 3000; r++) {
        double C[4], k, th;
        double sc = pow(10.0, th_range(-6, 6));
        int kind = r % 4;
        for (int l = 0; l < 4; l++)
            C[l] = th_range(-1, 1) * sc;
        if (kind == 1) { /* near-constant: tiny differences on a big offset */
            for (int l = 0; l < 4; l++)
                C[l] = sc * (1 + 1e-9 * th_range(-1, 1));
        } else if (kind == 2) { /* spline-like, positive and small slopes */
            double f0 = th_range(0.01, 1) * sc, f1 = th_range(0.01, 1) * sc;
            C[0] = f0;
            C[1] = f0 + th_range(-1, 1) * sc;
            C[2] = f1 - th_range(-1, 1) * sc;
            C[3] = f1;
        }
        k = (r % 3 == 0) ? 0.0 : th_range(-3, 3) * sc;
        double v = ts__trig_min(C, k, &th);
        double dmin = TH_INF;
        for (int j = 0; j <= N; j++) {
            double g = g_ref(C, k, j * D);
            dmin = g < dmin ? g : dmin;
        }
        double te = tol_eval(C, k), ts = 0.5 * g2_bound(C) * (D / 2) * (D / 2);
        int ok = v <= dmin + te && v >= dmin - ts - te;
        if (!ok && fails++ < 10)
            fprintf(stderr, "brute %d: v=%.17g dense=%.17g te=%.3g ts=%.3g\n", r, v, dmin, te, ts);
        CHECK(ok);
    }
}

/* ---- interval gaps, ts_spline_certify, reports ---------------------------- */

static const double X3[] = {0, 0.4, 2, 3, 5}, F3[] = {1.2, 0.5, 2, 5, 0.5};

static double line_at(const ts_line *l, double x) { return l->m * x + l->c; }

/* dense minimum of sign·(S − L) over interval i with M+1 samples of ts_spline_eval */
static double dense_gap(const ts_spline *s, size_t i, const ts_line *ln, int sign, int M)
{
    const double *x = ts_spline_x(s);
    double mn = TH_INF;
    for (int j = 0; j <= M; j++) {
        double xx = j == M ? x[i + 1] : x[i] + (x[i + 1] - x[i]) * j / M, y;
        ts_spline_eval(s, xx, NULL, &y);
        double g = sign * (y - line_at(ln, xx));
        mn = g < mn ? g : mn;
    }
    return mn;
}

/* Tolerances for a certificate against M+1 dense samples of interval i:
 * lower side te = 256 ε·scale (certify.c guard, typically ≤ 64 ε·scale;
 * ts_spline_eval 16 ε·M; θ = (x − x_i)(π/2)/h rounded ≤ 3 ε relative, times
 * |dS/dθ| ≤ 18 max|B|), upper side te + ½|g''|(Δ/2)². */
static void gap_tols(const ts_spline *s, size_t i, const ts_line *ln, int M, double *te,
                     double *ts)
{
    double B[4], X[4], C[4];
    ts_spline_control(s, i, B, X);
    const double *x = ts_spline_x(s);
    double L0 = line_at(ln, x[i]), sc = fabs(ln->c) + fabs(ln->m) * (fabs(x[i]) + fabs(x[i + 1]));
    for (int l = 0; l < 4; l++) {
        C[l] = B[l] - L0;
        sc = fabs(B[l]) > sc ? fabs(B[l]) : sc;
    }
    *te = 256.0 * EPS * sc;
    double D = HALF_PI / M;
    *ts = 0.5 * g2_bound(C) * (D / 2) * (D / 2);
}

static void test_gaps_vs_dense(void)
{
    ts_line up = {1.0, 2.5}, lo = {-0.5, -1.0};
    for (int form = 0; form < 2; form++) {
        for (int r = 0; r < 6; r++) {
            ts_spline_options o;
            th_options_paper(&o);
            o.form = (ts_form)form;
            o.alpha = r < 3 ? 0.02 * (r + 1) : 1.0 + r;
            o.beta = 0.01;
            ts_spline *s = NULL;
            CHECK(ts_spline_new(X3, F3, 5, &o, &s, NULL) == TS_OK);
            if (!s)
                continue;
            for (size_t i = 0; i < 4; i++) {
                for (int side = 0; side < 2; side++) {
                    const ts_line *ln = side ? &lo : &up;
                    int sign = side ? 1 : -1;
                    double at, te, ts;
                    double g = ts__interval_gap(s, i, ln, sign, &at);
                    double dg = dense_gap(s, i, ln, sign, 2000);
                    gap_tols(s, i, ln, 2000, &te, &ts);
                    CHECKF(g <= dg + te && g >= dg - ts - te, "form %d r %d i %zu side %d: %.17g vs %.17g",
                           form, r, i, side, g, dg);
                    /* the location is inside the interval and attains the gap */
                    double y;
                    CHECK(at >= X3[i] && at <= X3[i + 1]);
                    ts_spline_eval(s, at, NULL, &y);
                    CHECK_CLOSE(sign * (y - line_at(ln, at)), g, te + 1e-9 * fabs(g));
                }
            }
            ts_spline_free(s);
        }
    }
}

static void test_certify_api(void)
{
    ts_spline_options o;
    th_options_paper(&o);
    o.alpha = 0.001; /* small a: Table 3 overshoots y = x + 2.5 (docs/method.md §5.3) */
    ts_spline *s = NULL;
    ts_error e;
    CHECK(ts_spline_new(X3, F3, 5, &o, &s, &e) == TS_OK);
    if (!s)
        return;
    ts_line up = {1.0, 2.5}, lo = {0.0, -1000.0}, bad = {TH_NAN, 0.0}, bad2 = {0.0, TH_INF};
    ts_interval_report rep[4];
    ts_interval_report_init(rep, sizeof rep / sizeof rep[0]);
    ts_status st = ts_spline_certify(s, NULL, &up, rep, &e);
    CHECK(st == TS_ERR_VIOLATED);
    CHECK(e.status == TS_ERR_VIOLATED && e.where == TS_WHERE_INTERVAL);
    /* first violating interval: the first whose dense gap is negative */
    size_t first = TS_NO_INDEX;
    for (size_t i = 0; i < 4 && first == TS_NO_INDEX; i++)
        if (dense_gap(s, i, &up, -1, 2000) < 0)
            first = i;
    CHECK(first != TS_NO_INDEX && e.index == first);
    for (size_t i = 0; i < 4; i++) {
        double dg = dense_gap(s, i, &up, -1, 2000), te, ts;
        gap_tols(s, i, &up, 2000, &te, &ts);
        CHECK(rep[i].has_upper == 1 && rep[i].has_lower == 0 && isnan(rep[i].gap_lower));
        CHECK(rep[i].certified == (rep[i].gap_upper > 0));
        CHECK(rep[i].gap_upper <= dg + te && rep[i].gap_upper >= dg - ts - te);
        CHECK(rep[i].x0 == X3[i] && rep[i].x1 == X3[i + 1]);
        CHECK(rep[i].alpha == 0.001 && rep[i].beta == 0.0 && rep[i].term == TS_TERM_USER);
        CHECK(rep[i].a == 0.001);
    }
    /* a far line: OK; reports may be NULL; err may be NULL */
    CHECK(ts_spline_certify(s, &lo, NULL, NULL, &e) == TS_OK && e.status == TS_OK &&
          e.index == TS_NO_INDEX);
    CHECK(ts_spline_certify(s, &lo, NULL, NULL, NULL) == TS_OK);
    CHECK(ts_spline_certify(s, &lo, &up, NULL, NULL) == TS_ERR_VIOLATED);
    /* errors */
    CHECK(ts_spline_certify(NULL, &lo, &up, NULL, &e) == TS_ERR_NULL && e.status == TS_ERR_NULL);
    CHECK(ts_spline_certify(s, NULL, NULL, NULL, &e) == TS_ERR_NULL && e.index == TS_NO_INDEX);
    CHECK(ts_spline_certify(s, &bad, NULL, rep, &e) == TS_ERR_NONFINITE && e.status == TS_ERR_NONFINITE);
    CHECK(ts_spline_certify(s, &lo, &bad2, rep, &e) == TS_ERR_NONFINITE);

    /* report / certified of a TS_SHAPE_NONE spline: nothing promised */
    ts_interval_report r = TS_INTERVAL_REPORT_INIT;
    CHECK(ts_spline_report(s, 0, &r) == TS_OK);
    CHECK(r.has_lower == 0 && r.has_upper == 0 && isnan(r.gap_lower) && isnan(r.gap_upper) &&
          r.certified == 0 && r.term == TS_TERM_USER);
    CHECK(ts_spline_certified(s) == 0);
    CHECK(ts_spline_certified(NULL) == 0);
    CHECK(ts_spline_report(s, 4, &r) == TS_ERR_INDEX && isnan(r.x0));
    CHECK(ts_spline_report(NULL, 0, &r) == TS_ERR_NULL);
    CHECK(ts_spline_report(s, 0, NULL) == TS_ERR_NULL);
    ts_spline_free(s);
}

/* Geometric form (docs/method.md §4): the gap is the trig minimum of
 * C_l = ±(Y_l − m X_l − c) with κ = 0; checked against a brute-force scan
 * of the parametric curve built here from the control points (not through
 * geometric.c's evaluation), and its location X(θ*). */
static void test_geometric_gap(void)
{
    ts_line lines[3] = {{1.0, 2.5}, {-0.5, -1.0}, {0.0, 0.0}};
    const double X3g[] = {0, 0.4, 2, 3, 5}, F3g[] = {1.2, 0.5, 2, 5, 0.5};
    for (int r = 0; r < 3; r++) {
        ts_spline_options o;
        th_options_paper(&o);
        o.form = TS_FORM_GEOMETRIC;
        o.alpha = 0.45 + r;
        ts_spline *s = NULL;
        ts_status st = ts_spline_new(X3g, F3g, 5, &o, &s, NULL);
        CHECK(st == TS_OK);
        if (!s)
            continue;
        for (size_t i = 0; i < 4; i++) {
            double B[4], X[4];
            ts_spline_control(s, i, B, X);
            for (int k = 0; k < 3; k++) {
                for (int sign = -1; sign <= 1; sign += 2) {
                    double C[4], at, sc = 0;
                    for (int l = 0; l < 4; l++) {
                        C[l] = sign * (B[l] - (lines[k].m * X[l] + lines[k].c));
                        sc = fabs(B[l]) + fabs(lines[k].m * X[l]) + fabs(lines[k].c) > sc
                                 ? fabs(B[l]) + fabs(lines[k].m * X[l]) + fabs(lines[k].c)
                                 : sc;
                    }
                    double g = ts__interval_gap(s, i, &lines[k], sign, &at);
                    const int N = 4000;
                    double D = HALF_PI / N, mn = TH_INF;
                    for (int j = 0; j <= N; j++) {
                        double v = g_ref(C, 0.0, j * D);
                        mn = v < mn ? v : mn;
                    }
                    double te = 64 * EPS * sc, ts = 0.5 * g2_bound(C) * (D / 2) * (D / 2);
                    CHECKF(g <= mn + te && g >= mn - ts - te, "geo i %zu k %d: %.17g vs %.17g", i,
                           k, g, mn);
                    CHECK(at >= X3g[i] && at <= X3g[i + 1]);
                }
            }
        }
        ts_spline_free(s);
    }
    /* a geometric shape spline is certified, with exact line conditions */
    ts_spline_options o;
    th_options_paper(&o);
    o.form = TS_FORM_GEOMETRIC;
    o.shape = TS_SHAPE_BELOW;
    o.upper.m = 1;
    o.upper.c = 2.5;
    o.alpha = 0.001;
    ts_spline *s = NULL;
    CHECK(ts_spline_new(X3g, F3g, 5, &o, &s, NULL) == TS_OK);
    CHECK(ts_spline_certified(s) == 1);
    for (size_t i = 0; s && i < 4; i++) {
        ts_interval_report rep = TS_INTERVAL_REPORT_INIT;
        ts_spline_report(s, i, &rep);
        CHECK(rep.certified && rep.gap_upper > 0);
    }
    ts_spline_free(s);
}

int main(void)
{
    TH_CASE("closed_forms");
    test_closed_forms();
    TH_CASE("scaling");
    test_scaling();
    TH_CASE("reference");
    test_reference();
    TH_CASE("brute");
    test_brute();
    TH_CASE("gaps_vs_dense");
    test_gaps_vs_dense();
    TH_CASE("certify_api");
    test_certify_api();
    TH_CASE("geometric_gap");
    test_geometric_gap();
    return th_report("test_certify");
}
