/* Derivatives of every order and the extrapolation per call
 * (ts_spline_eval_mode, ts_spline_eval_batch_mode(_mt), ts_spline_eval_batch with
 * deriv > 2).  The reference derivatives are re-derived here, not from the
 * library's phase-shift formula: the factored basis of docs/method.md §2,
 * A0 = (1 − s)³, A1 = s(1 − s)(3 − s), A2 = c(1 − c)(3 − c), A3 = (1 − c)³,
 * as truncated Taylor series in e around θ (sin(θ + e), cos(θ + e) have the
 * coefficients ±sin θ/k!, ±cos θ/k!), multiplied out in long double; the
 * ν-th derivative is ν! times the coefficient of e^ν, times (π/(2h))^ν. */
#include "th.h"
#include "trigspline.h"

#include <float.h>
#include <math.h>
#include <stddef.h>

#define ORD 8 /* series kept to e^7 */

static void ser_mul(const long double *a, const long double *b, long double *out)
{
    long double t[ORD] = {0};
    for (int i = 0; i < ORD; i++)
        for (int j = 0; i + j < ORD; j++)
            t[i + j] += a[i] * b[j];
    for (int i = 0; i < ORD; i++)
        out[i] = t[i];
}

/* d^nu S/dx^nu of interval i (control values B, knots xi, xi + h) at x, in
 * long double, from the factored basis. */
static long double deriv_ref(const double B[4], double xi, double h, double x, int nu)
{
    const long double hp = 1.57079632679489661923132169163975144L;
    long double th = hp * ((long double)x - (long double)xi) / (long double)h, S[ORD], C[ORD],
                one[ORD] = {1};
    long double sn = sinl(th), cs = cosl(th), fact = 1;
    for (int k = 0; k < ORD; k++) { /* sin(θ + e), cos(θ + e) */
        long double ds = (k % 4 == 0) ? sn : (k % 4 == 1) ? cs : (k % 4 == 2) ? -sn : -cs;
        long double dc = (k % 4 == 0) ? cs : (k % 4 == 1) ? -sn : (k % 4 == 2) ? -cs : sn;
        S[k] = ds / fact;
        C[k] = dc / fact;
        fact *= k + 1;
    }
    long double ms[ORD], mc[ORD], t3s[ORD], t3c[ORD], A[4][ORD], tmp[ORD];
    for (int k = 0; k < ORD; k++) {
        ms[k] = one[k] - S[k];
        mc[k] = one[k] - C[k];
        t3s[k] = 3 * one[k] - S[k];
        t3c[k] = 3 * one[k] - C[k];
    }
    ser_mul(ms, ms, tmp);
    ser_mul(tmp, ms, A[0]);
    ser_mul(S, ms, tmp);
    ser_mul(tmp, t3s, A[1]);
    ser_mul(C, mc, tmp);
    ser_mul(tmp, t3c, A[2]);
    ser_mul(mc, mc, tmp);
    ser_mul(tmp, mc, A[3]);
    long double v = 0, nf = 1;
    for (int k = 2; k <= nu; k++)
        nf *= k;
    for (int l = 0; l < 4; l++)
        v += A[l][nu] * (long double)B[l];
    return v * nf * powl(hp / (long double)h, nu);
}

static ts_spline *fit(const double *x, const double *f, size_t n, ts_form form, ts_extrap ex)
{
    ts_spline_options o;
    ts_spline_options_init(&o);
    o.form = form;
    o.extrapolate = ex;
    ts_spline *s = NULL;
    ts_status st = ts_spline_new(x, f, n, &o, &s, NULL);
    CHECKF(st == TS_OK, "fit: %s", ts_strerror(st));
    return s;
}

static const double X[8] = {-1, 0.5, 1, 2.5, 3, 4.25, 6, 7};
static const double F[8] = {2, 1.2, 1.9, 0.3, 0.31, 2.5, -1, 0};

static int same(double a, double b)
{
    return (isnan(a) && isnan(b)) || (a == b && signbit(a) == signbit(b));
}

static void orders(void)
{
    TH_CASE("orders 3..6 against the factored basis");
    for (int form = TS_FORM_PAPER; form <= TS_FORM_C1; form++) {
        ts_spline *s = fit(X, F, 8, (ts_form)form, TS_EXTRAP_EXTEND);
        if (!s)
            continue;
        double xq[400], yq[400];
        for (int j = 0; j < 400; j++) /* inside and 1.5 beyond each end */
            xq[j] = X[0] - 1.5 + (X[7] - X[0] + 3.0) * j / 399.0;
        for (int nu = 3; nu <= 6; nu++) {
            ts_error err;
            CHECK(ts_spline_eval_batch_mode(s, nu, TS_EXTRAP_EXTEND, xq, 400, yq, NULL, &err) ==
                  TS_OK);
            for (int j = 0; j < 400; j++) {
                size_t i = xq[j] < X[0] ? 0 : xq[j] >= X[7] ? 6 : 0;
                if (X[0] <= xq[j] && xq[j] <= X[7])
                    (void)ts_spline_find_interval(s, xq[j], NULL, &i);
                double B[4];
                (void)ts_spline_control(s, i, B, NULL);
                double h = X[i + 1] - X[i], M = 0;
                for (int l = 0; l < 4; l++)
                    M = fmax(M, fabs(B[l]));
                long double ref = deriv_ref(B, X[i], h, xq[j], nu);
                /* the library sums p sin(θ + νπ/2) + ... with |p|, |q| <= 7.5M,
                 * |r| <= 7M, |u|, |w| <= M/2 (M = max|B|): at most
                 * 3^ν·23M·(π/2h)^ν, each term to a few ε relative, the
                 * arguments (|θ + νπ/2| < 20) to 20ε absolute times k <= 3:
                 * below 3^ν·23M·(π/2h)^ν·100ε = 5e-13·3^ν·M·(π/2h)^ν */
                double tol = 5e-13 * pow(3.0, nu) * M * pow(TH_HALF_PI / h, nu);
                CHECKF(fabsl((long double)yq[j] - ref) <= (long double)tol,
                       "form %d nu %d x %.17g: %.17g vs %.17Lg", form, nu, xq[j], yq[j], ref);
                double y1;
                ts_cursor cur = TS_CURSOR_INIT;
                CHECK(ts_spline_eval_mode(s, xq[j], nu, TS_EXTRAP_EXTEND, &cur, &y1) == TS_OK &&
                      same(y1, yq[j]));
            }
            /* ts_spline_eval_batch with the stored mode: the same values */
            double yb[400];
            CHECK(ts_spline_eval_batch(s, nu, xq, 400, yb, NULL, NULL) == TS_OK);
            int eq = 1;
            for (int j = 0; j < 400; j++)
                eq &= same(yb[j], yq[j]);
            CHECK(eq);
        }
        /* orders 1, 2 of the reference against the library's own S', S''
         * (|B| < 4 here; those agree with long double to ~12ε M (π/2h)^ν,
         * tests/unit/test_fast.c): the reference is right where the
         * library's checked paths are */
        for (int j = 0; j < 400; j += 7) {
            if (!(X[0] <= xq[j] && xq[j] <= X[7]))
                continue;
            size_t i;
            double B[4], y, dy, d2y;
            (void)ts_spline_find_interval(s, xq[j], NULL, &i);
            (void)ts_spline_control(s, i, B, NULL);
            (void)ts_spline_eval_deriv(s, xq[j], NULL, &y, &dy, &d2y);
            double h = X[i + 1] - X[i];
            CHECK(fabsl(deriv_ref(B, X[i], h, xq[j], 1) - (long double)dy) <=
                  (long double)(1e-13 * 92 * pow(TH_HALF_PI / h, 1)));
            CHECK(fabsl(deriv_ref(B, X[i], h, xq[j], 2) - (long double)d2y) <=
                  (long double)(1e-12 * 92 * pow(TH_HALF_PI / h, 2)));
        }
        ts_spline_free(s);
    }
}

static void modes(void)
{
    TH_CASE("extrapolation per call");
    const ts_extrap all[4] = {TS_EXTRAP_ERROR, TS_EXTRAP_CLAMP, TS_EXTRAP_EXTEND, TS_EXTRAP_LINEAR};
    double xq[9] = {-3, -1, 0.7, 3, 7, 7.5, 100, TH_INF, -TH_INF};
    for (int form = TS_FORM_PAPER; form <= TS_FORM_GEOMETRIC; form++) {
        ts_spline *base = fit(X, F, 8, (ts_form)form, TS_EXTRAP_ERROR);
        if (!base)
            continue;
        double e0[3], e1[3];
        (void)ts_spline_eval_deriv(base, X[0], NULL, &e0[0], &e0[1], &e0[2]);
        (void)ts_spline_eval_deriv(base, X[7], NULL, &e1[0], &e1[1], &e1[2]);
        for (int k = 0; k < 4; k++) {
            /* finite queries: the bits of a spline built with that mode */
            ts_spline *s = fit(X, F, 8, (ts_form)form, all[k]);
            if (!s)
                continue;
            int top = form == TS_FORM_GEOMETRIC ? 2 : 5;
            for (int nu = 0; nu <= top; nu++) {
                double a[9], b[9];
                ts_error ea, eb;
                ts_status sa = ts_spline_eval_batch_mode(base, nu, all[k], xq, 7, a, NULL, &ea);
                ts_status sb = ts_spline_eval_batch(s, nu, xq, 7, b, NULL, &eb);
                int eq = sa == sb && ea.index == eb.index;
                for (int j = 0; j < 7; j++) {
                    double y = 0;
                    ts_status st = ts_spline_eval_mode(base, xq[j], nu, all[k], NULL, &y);
                    /* batch against batch, scalar against scalar (the
                     * kernels agree with the scalar path only to rounding) */
                    eq &= same(a[j], b[j]) && (nu <= 2 || same(y, a[j]));
                    eq &= (st == TS_OK) == !isnan(a[j]);
                    if (nu <= 2) { /* and the scalar path of ts_spline_eval_deriv */
                        double o[3];
                        (void)ts_spline_eval_deriv(s, xq[j], NULL, &o[0], &o[1], &o[2]);
                        eq &= same(y, o[nu]);
                    }
                }
                CHECKF(eq, "form %d mode %d nu %d", form, (int)all[k], nu);
            }
            ts_spline_free(s);
            /* ±Inf and NaN */
            for (int nu = 0; nu <= top; nu++) {
                for (int side = 0; side < 2; side++) {
                    double x = side ? TH_INF : -TH_INF, y = 0, *e = side ? e1 : e0;
                    ts_status st = ts_spline_eval_mode(base, x, nu, all[k], NULL, &y);
                    switch (all[k]) {
                    case TS_EXTRAP_CLAMP: CHECK(st == TS_OK && y == (nu == 0 ? e[0] : 0.0)); break;
                    case TS_EXTRAP_LINEAR: { /* the limit of f + d (x − x_end) */
                        double want = nu == 0   ? (e[1] == 0.0 ? e[0] : e[1] * x)
                                      : nu == 1 ? e[1]
                                                : 0.0;
                        CHECKF(st == TS_OK && y == want, "form %d nu %d: %g", form, nu, y);
                        break;
                    }
                    default: CHECK(st == TS_ERR_DOMAIN && isnan(y));
                    }
                }
                double y = 0;
                CHECK(ts_spline_eval_mode(base, TH_NAN, nu, all[k], NULL, &y) == TS_ERR_DOMAIN &&
                      isnan(y));
            }
        }
        /* the batch's first invalid query */
        double q[5] = {0.5, 2, TH_NAN, -TH_INF, 9}, y[5];
        ts_error err;
        CHECK(ts_spline_eval_batch_mode(base, 1, TS_EXTRAP_CLAMP, q, 5, y, NULL, &err) ==
                  TS_ERR_DOMAIN &&
              err.index == 2 && err.where == TS_WHERE_QUERY && isnan(y[2]) && y[3] == 0.0 &&
              y[4] == 0.0);
        CHECK(ts_spline_eval_batch_mode(base, 0, TS_EXTRAP_ERROR, q, 5, y, NULL, &err) ==
                  TS_ERR_DOMAIN &&
              err.index == 2 && !isnan(y[0]) && !isnan(y[1]) && isnan(y[3]) && isnan(y[4]));
        ts_spline_free(base);
    }
    TH_CASE("geometric form: a line continues as the line");
    /* f = 2x + 1 on integer knots: S is the line (docs/method.md §4) with
     * end slopes 2 to rounding; linear extrapolation continues it: within a
     * few ε of |x| times the slope (1e-13 at |x| <= 50) */
    static const double xl[5] = {0, 1, 3, 4, 6};
    double fl[5];
    for (int i = 0; i < 5; i++)
        fl[i] = 2.0 * xl[i] + 1.0;
    ts_spline *s = fit(xl, fl, 5, TS_FORM_GEOMETRIC, TS_EXTRAP_ERROR);
    if (s) {
        for (double x = -44; x <= 50; x += 0.75) {
            double y;
            CHECK(ts_spline_eval_mode(s, x, 0, TS_EXTRAP_LINEAR, NULL, &y) == TS_OK &&
                  fabs(y - (2.0 * x + 1.0)) <= 1e-13);
        }
        ts_spline_free(s);
    }
}

static void errors(void)
{
    TH_CASE("every status");
    ts_spline *p = fit(X, F, 8, TS_FORM_PAPER, TS_EXTRAP_ERROR);
    ts_spline *g = fit(X, F, 8, TS_FORM_GEOMETRIC, TS_EXTRAP_ERROR);
    if (!p || !g)
        return;
    double y = 0, xq[3] = {0, 1, 2}, yq[3] = {0, 0, 0};
    ts_error err;
    CHECK(ts_spline_eval_mode(NULL, 1, 0, TS_EXTRAP_ERROR, NULL, &y) == TS_ERR_NULL && isnan(y));
    CHECK(ts_spline_eval_mode(p, 1, 0, TS_EXTRAP_ERROR, NULL, NULL) == TS_ERR_NULL);
    y = 0;
    CHECK(ts_spline_eval_mode(p, 1, -1, TS_EXTRAP_ERROR, NULL, &y) == TS_ERR_OPTION && isnan(y));
    CHECK(ts_spline_eval_mode(g, 1, 3, TS_EXTRAP_ERROR, NULL, &y) == TS_ERR_OPTION && isnan(y));
    CHECK(ts_spline_eval_mode(g, 1, 2, TS_EXTRAP_ERROR, NULL, &y) == TS_OK && !isnan(y));
    CHECK(ts_spline_eval_mode(p, 1, 0, (ts_extrap)4, NULL, &y) == TS_ERR_OPTION);
    CHECK(ts_spline_eval_mode(p, 1, 0, (ts_extrap)-1, NULL, &y) == TS_ERR_OPTION);
    CHECK(ts_spline_eval_mode(p, 9, 4, TS_EXTRAP_ERROR, NULL, &y) == TS_ERR_DOMAIN && isnan(y));
    CHECK(ts_spline_eval_batch_mode(NULL, 0, TS_EXTRAP_ERROR, xq, 3, yq, NULL, &err) ==
              TS_ERR_NULL &&
          err.status == TS_ERR_NULL);
    CHECK(ts_spline_eval_batch_mode(p, 0, TS_EXTRAP_ERROR, NULL, 3, yq, NULL, &err) == TS_ERR_NULL);
    CHECK(ts_spline_eval_batch_mode(p, 0, TS_EXTRAP_ERROR, xq, 3, NULL, NULL, &err) == TS_ERR_NULL);
    CHECK(ts_spline_eval_batch_mode(g, 3, TS_EXTRAP_ERROR, xq, 3, yq, NULL, &err) ==
              TS_ERR_OPTION &&
          err.index == TS_NO_INDEX && isnan(yq[0]) && isnan(yq[2]));
    CHECK(ts_spline_eval_batch_mode(p, -1, TS_EXTRAP_ERROR, xq, 3, yq, NULL, &err) ==
          TS_ERR_OPTION);
    CHECK(ts_spline_eval_batch_mode(p, 0, (ts_extrap)7, xq, 3, yq, NULL, &err) == TS_ERR_OPTION);
    CHECK(ts_spline_eval_batch(g, 3, xq, 3, yq, NULL, &err) == TS_ERR_OPTION && isnan(yq[1]));
    CHECK(ts_spline_eval_batch_mt(g, 4, xq, 3, yq, 2, &err) == TS_ERR_OPTION);
    CHECK(ts_spline_eval_batch_mode_mt(NULL, 0, TS_EXTRAP_ERROR, xq, 3, yq, 2, &err) ==
          TS_ERR_NULL);
    CHECK(ts_spline_eval_batch_mode_mt(p, 0, (ts_extrap)7, xq, 3, yq, 2, &err) == TS_ERR_OPTION);

    TH_CASE("threads: the same bits, the global index");
    static double q[2 * 8192 + 11], a[2 * 8192 + 11], b[2 * 8192 + 11];
    size_t m = sizeof q / sizeof *q;
    for (size_t j = 0; j < m; j++)
        q[j] = X[0] - 0.5 + (X[7] - X[0] + 1.0) * (double)((j * 7919) % m) / (double)m;
    for (int nu = 0; nu <= 4; nu++) {
        ts_error e1, e2;
        ts_status s1 = ts_spline_eval_batch_mode(p, nu, TS_EXTRAP_LINEAR, q, m, a, NULL, &e1);
        ts_status s2 = ts_spline_eval_batch_mode_mt(p, nu, TS_EXTRAP_LINEAR, q, m, b, 2, &e2);
        int eq = s1 == TS_OK && s2 == TS_OK;
        for (size_t j = 0; j < m; j++)
            eq &= same(a[j], b[j]);
        CHECKF(eq, "nu %d", nu);
    }
    size_t bad = 8192 + 50;
    double keep = q[bad];
    q[bad] = TH_NAN;
    CHECK(ts_spline_eval_batch_mode_mt(p, 3, TS_EXTRAP_CLAMP, q, m, b, 2, &err) == TS_ERR_DOMAIN &&
          err.index == bad && isnan(b[bad]));
    q[bad] = keep;
    ts_spline_free(p);
    ts_spline_free(g);
}

int main(void)
{
    orders();
    modes();
    errors();
    return th_report("test_eval_mode");
}
