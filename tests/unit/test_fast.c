/* The batch kernels of src/kernels.c against plain ts_spline_eval_deriv.
 *
 * Expected values: ts_spline_eval_deriv (the plain path, itself checked against the
 * mpmath reference in test_core.c); the knot values f_i exactly; a
 * long-double evaluation of docs/method.md §2/(2.1) written here says which side an
 * error is on (printed, not asserted).
 *
 * Tolerances: a first-order worst-case bound (u = 2⁻⁵³, ε = 2u = DBL_EPSILON,
 * M = max|B_l| of the query's interval, w = (π/2)/h = dθ/dx).  Both paths
 * evaluate from the nearer end of the interval at the same double angle
 * ϑ = (x − x_i)·w or (x_{i+1} − x)·w (<= π/4), so only the evaluation at ϑ
 * differs -- except when (x − x_i)·w and (x_{i+1} − x)·w round to the same
 * value although x − x_i > x_{i+1} − x: fast.c then takes the left end and
 * eval.c the right, two angles <= 2 ulp(π/4) apart, which adds <= |S'|·4u·w^k
 * with |dS/dθ| <= 14M, |d²S/dθ²| <= 56M, |d³S/dθ³| <= 196M (docs/method.md §2, |D_k| <= 2M).
 *  Inputs.  fast.c: polynomials of bench/sincos_coeffs.py (truncation
 *    <= 0.05u; correction term <= 0.081 with relative error <= 5u; final
 *    rounding <= 0.71u), 1 − cos summed without the 1, then c = 1 − (1 − cos),
 *    1 − s one subtraction each: s, c, 1−s, 1−c carry <= e = 2.5u.  basis.c:
 *    libm sin, cos (< 1 ulp <= u on [0, 1]); one_minus = c²/(1+s) or 1 − s:
 *    <= 3u.  Take e = 3u for both.
 *  Value.  Same expressions in both: A0 = (1−s)³ <= 3e + 2u = 11u;
 *    A1 = s(1−s)(3−s): s(1−s) <= e + u/4, (3−s) <= e + 2u, product <= 11.7u;
 *    A2, A3 alike.  Σ|ΔA_l|·M + 4 product and 3 sum roundings (each <= u·M):
 *    <= 49.4u·M per path; both paths and the tie term (56u·M):
 *    <= 155u·M = 77ε·M:  TOL0 = 80.
 *  S' (docs/method.md (2.1)): weights 3(1−s)²c, 2sc, 3(1−c)²s (<= 3, 1, 3) carry
 *    <= 36u, 9.5u, 36u; times D_k = B_k − B_{k−1} (|D_k| <= 2M, one rounding),
 *    2 sums over <= 14M, one product by w: <= 233u·M·w per path; with the tie
 *    term (224u): <= 690u = 345ε:  TOL1 = 360.
 *  S'': fast's weights 6(1−s)c² + 3(1−s)²s etc. (<= 6, 2, 6) carry <= 114u,
 *    30u, 114u: <= 684u·M·w² (342ε); basis.c sums Σ A_l''B_l with
 *    Σ|A_l''| <= 28 (test_basis.c) and terms of the same size: < 860ε; tie
 *    term 392ε:  TOL2 = 1600.
 *  These are loose worst-case sums.  The measured maxima over >= 1e7 points
 *  are printed below in units of ε·M·w^k (about 4, 12, 35: the numbers to
 *  quote); the long-double comparison shows fast.c is as accurate as basis.c.
 *  A wrong coefficient, sign or interval is off by >= 1e-6·M and fails.
 *
 * Points: 10 million random queries (6 splines, random order and sorted,
 * every 97th exactly on a knot) for the value and 2 million each for S' and
 * S'', for every kernel this CPU has; 1/10 of that under ASan.  The plain
 * reference is computed once per query set and shared by the kernels.
 * structure() checks the contract of ts__fast_batch (prefix up to the first
 * block with a query outside, cursor, kernels chosen by number), knots
 * exactly, the geometric form's prefix and knots, sparse sorted queries (galloping) and
 * ts_spline_eval_batch / ts_spline_eval_batch_mt against the kernel.  flat() checks flat
 * intervals exactly (value f_i, derivatives 0).  order() checks that sorted
 * and shuffled batches give the same bits (widths that round included).
 */
#include "th.h"
#include "common/th_rng.h"
#include "trigspline.h"
#include "internal.h"

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#if TH_ASAN
#define TF_SCALE 10
#endif
#ifndef TF_SCALE
#define TF_SCALE 1
#endif

#define EPS DBL_EPSILON
#define TOL0 80.0
#define TOL1 360.0
#define TOL2 1600.0
#define NREF 8 /* long-double check on every NREF-th query */


/* Long-double S^(k) at θ of control values B (docs/method.md §2, (2.1)); derivatives in θ. */
static long double ref_theta(const double B[4], long double th, int k)
{
    long double s = sinl(th), c = cosl(th), ms = 1.0L - s, mc = 1.0L - c;
    long double b0 = (long double)B[0], b1 = (long double)B[1], b2 = (long double)B[2],
                b3 = (long double)B[3];
    if (k == 0)
        return ms * ms * ms * b0 + s * ms * (3 - s) * b1 + c * mc * (3 - c) * b2 + mc * mc * mc * b3;
    if (k == 1)
        return 3 * ms * ms * c * (b1 - b0) + 2 * s * c * (b2 - b1) + 3 * mc * mc * s * (b3 - b2);
    return -(6 * ms * c * c + 3 * ms * ms * s) * (b1 - b0) + 2 * (c * c - s * s) * (b2 - b1) +
           (6 * mc * s * s + 3 * mc * mc * c) * (b3 - b2);
}

/* Interval of x as the library defines it (largest i <= n-1 with x_i <= x). */
static size_t interval_of(const ts_spline *s, double x)
{
    const double *X = ts_spline_x(s);
    size_t lo = 0, hi = ts_spline_intervals(s);
    while (hi - lo > 1) {
        size_t mid = lo + (hi - lo) / 2;
        if (X[mid] <= x)
            lo = mid;
        else
            hi = mid;
    }
    return lo;
}

typedef struct stats {
    double worst[3];       /* max |fast − plain| / (ε M w^k) */
    double worst_ref[3];   /* max |fast − long double| / (ε M w^k) */
    double worst_plain[3]; /* max |plain − long double| / (ε M w^k) */
    long count[3];
} stats;

/* A spline with hard features: h over 6 decades, |f| up to 1e6 with offsets
 * (cancellation), a over 4 decades (B1 − B0 large or tiny), big slopes. */
static ts_spline *random_spline(size_t np, int kind, int form)
{
    double *x = malloc(np * sizeof *x), *f = malloc(np * sizeof *f), *d = malloc(np * sizeof *d);
    double *al = malloc((np - 1) * sizeof *al);
    ts_spline *s = NULL;
    if (!x || !f || !d || !al) {
        CHECKF(0, "out of memory in the test");
        goto done;
    }
    x[0] = kind == 2 ? 1e6 : -3.0;
    for (size_t i = 1; i < np; i++)
        x[i] = x[i - 1] + (kind == 1 ? pow(10.0, -3.0 + 6.0 * th_unit()) : 0.2 + th_unit());
    for (size_t i = 0; i < np; i++) {
        double base = kind == 2 ? 1e6 : kind == 3 ? -500.0 : 0.0;
        f[i] = base + (kind == 2 ? 1e-3 : 10.0) * (th_unit() - 0.5);
        d[i] = (kind == 3 ? 1e4 : 5.0) * (th_unit() - 0.5);
    }
    for (size_t i = 0; i + 1 < np; i++)
        al[i] = pow(10.0, -2.0 + 4.0 * th_unit());
    ts_spline_options o;
    ts_spline_options_init(&o);
    o.form = form ? TS_FORM_C1 : TS_FORM_PAPER;
    o.slopes = TS_SLOPES_USER;
    o.user_slopes = d;
    o.n_user_slopes = np;
    o.alphas = al;
    o.n_alphas = np - 1;
    ts_error e;
    ts_status st = ts_spline_new(x, f, np, &o, &s, &e);
    CHECKF(st == TS_OK, "random spline kind %d: %s at %zu", kind, ts_strerror(st), e.index);
done:
    free(x);
    free(f);
    free(d);
    free(al);
    return s;
}

/* One query set with its plain values, intervals and error units. */
typedef struct qset {
    const ts_spline *s;
    size_t m;
    const char *what;
    double *q, *ref[3], *unit[3];
    long double *lref[3]; /* every NREF-th query */
} qset;

static int qset_fill(qset *Q)
{
    const double *X = ts_spline_x(Q->s);
    for (int k = 0; k < 3; k++) {
        Q->ref[k] = malloc(Q->m * sizeof(double));
        Q->unit[k] = malloc(Q->m * sizeof(double));
        Q->lref[k] = malloc((Q->m / NREF + 1) * sizeof(long double));
        if (!Q->ref[k] || !Q->unit[k] || !Q->lref[k])
            return 0;
    }
    long bad = 0;
    for (size_t j = 0; j < Q->m; j++) {
        double o[3], B[4];
        bad += ts_spline_eval_deriv(Q->s, Q->q[j], NULL, &o[0], &o[1], &o[2]) != TS_OK;
        size_t i = interval_of(Q->s, Q->q[j]);
        ts_spline_control(Q->s, i, B, NULL);
        double M = fmax(fmax(fabs(B[0]), fabs(B[1])), fmax(fabs(B[2]), fabs(B[3])));
        double w = (3.14159265358979323846 / 2) / (X[i + 1] - X[i]);
        for (int k = 0; k < 3; k++) {
            Q->ref[k][j] = o[k];
            Q->unit[k][j] = EPS * M * (k == 0 ? 1.0 : k == 1 ? w : w * w);
        }
        if (j % NREF == 0) {
            /* the double angle both paths use: from the nearer end, decided
             * on the products (internal.h's ts__trig_eval_in, the kernels) */
            double tu = (Q->q[j] - X[i]) * w, tv = (X[i + 1] - Q->q[j]) * w;
            long double th = tv < tu ? 1.57079632679489661923132169163975144L - (long double)tv : (long double)tu;
            for (int k = 0; k < 3; k++)
                Q->lref[k][j / NREF] = ref_theta(B, th, k) * (k == 0 ? 1.0L : k == 1 ? (long double)w
                                                                                   : (long double)w * (long double)w);
        }
    }
    CHECKF(bad == 0, "%s: ts_spline_eval_deriv failed at %ld queries", Q->what, bad);
    return 1;
}

static void qset_free(qset *Q)
{
    for (int k = 0; k < 3; k++) {
        free(Q->ref[k]);
        free(Q->unit[k]);
        free(Q->lref[k]);
    }
}

/* Kernel isa on the first m queries of Q for derivative deriv. */
static void compare(const qset *Q, size_t m, int deriv, int isa, stats *S)
{
    double *y = malloc(m * sizeof *y);
    if (!y) {
        CHECKF(0, "out of memory in the test");
        return;
    }
    ts_cursor cur = TS_CURSOR_INIT;
    CHECK(ts__fast_batch_isa(Q->s, deriv, Q->q, m, y, &cur, isa, NULL) == 1);
    double tol = deriv == 0 ? TOL0 : deriv == 1 ? TOL1 : TOL2;
    long bad = 0;
    size_t first = 0;
    for (size_t j = 0; j < m; j++) {
        double e = fabs(y[j] - Q->ref[deriv][j]) / Q->unit[deriv][j];
        if (!(e <= tol) && !bad++)
            first = j;
        if (e > S->worst[deriv])
            S->worst[deriv] = e;
        if (j % NREF == 0) {
            long double r = Q->lref[deriv][j / NREF];
            double er = (double)fabsl((long double)y[j] - r) / Q->unit[deriv][j];
            double ep = (double)fabsl((long double)Q->ref[deriv][j] - r) / Q->unit[deriv][j];
            S->worst_ref[deriv] = fmax(S->worst_ref[deriv], er);
            S->worst_plain[deriv] = fmax(S->worst_plain[deriv], ep);
        }
    }
    S->count[deriv] += (long)m;
    CHECKF(bad == 0, "kernel %d %s deriv %d: %ld queries off, first x = %.17g: fast %.17g plain %.17g", isa,
           Q->what, deriv, bad, Q->q[first], y[first], Q->ref[deriv][first]);
    /* the cursor ends on the last query's interval */
    CHECKF(cur.interval == interval_of(Q->s, Q->q[m - 1]), "kernel %d %s: cursor %zu, want %zu", isa, Q->what,
           cur.interval, interval_of(Q->s, Q->q[m - 1]));
    free(y);
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

static int have_kernel(int isa)
{
    ts_spline *probe = random_spline(3, 0, 0);
    double q = 0.0, y;
    int have = probe && ts__fast_batch_isa(probe, 0, &q, 0, &y, NULL, isa, NULL);
    ts_spline_free(probe);
    return have;
}

static void accuracy(void)
{
    const size_t per = 10000000 / 12 / TF_SCALE + 1; /* 6 splines × (random, sorted) */
    int have[3];
    stats S[3];
    memset(S, 0, sizeof S);
    for (int isa = 0; isa <= 2; isa++) {
        have[isa] = have_kernel(isa);
        if (!have[isa])
            printf("test_fast: kernel %d not available on this CPU (skipped)\n", isa);
    }
    CHECK(have[0]); /* the portable kernel always exists */
    th_seed(0x243F6A8885A308D3u);
    for (int kind = 0; kind < 6; kind++) {
        ts_spline *s = random_spline(kind == 5 ? 20001 : 201, kind % 4, kind >= 4);
        if (!s)
            continue;
        const double *X = ts_spline_x(s);
        size_t n = ts_spline_intervals(s);
        for (int sorted = 0; sorted <= 1; sorted++) {
            qset Q = {s, per, sorted ? "sorted" : "random", malloc(per * sizeof(double)), {0}, {0}, {0}};
            if (!Q.q) {
                CHECKF(0, "out of memory in the test");
                continue;
            }
            for (size_t j = 0; j < per; j++) {
                if (j % 97 == 0) /* knots exactly: the right-hand interval */
                    Q.q[j] = X[(size_t)(th_unit() * (double)(n + 1)) % (n + 1)];
                else
                    Q.q[j] = X[0] + (X[n] - X[0]) * th_unit();
            }
            if (sorted)
                qsort(Q.q, per, sizeof *Q.q, cmp_double);
            if (qset_fill(&Q)) {
                for (int isa = 0; isa <= 2; isa++) {
                    if (!have[isa])
                        continue;
                    compare(&Q, per, 0, isa, &S[isa]);
                    compare(&Q, per / 5, 1, isa, &S[isa]);
                    compare(&Q, per / 5, 2, isa, &S[isa]);
                }
            } else {
                CHECKF(0, "out of memory in the test");
            }
            qset_free(&Q);
            free(Q.q);
        }
        ts_spline_free(s);
    }
    for (int isa = 0; isa <= 2; isa++) {
        if (!have[isa])
            continue;
        printf("test_fast: kernel %d: max |fast - plain| / (eps M w^k) = %.2f, %.2f, %.2f for S, S', S'' "
               "(bounds %.0f, %.0f, %.0f) over %ld, %ld, %ld points\n",
               isa, S[isa].worst[0], S[isa].worst[1], S[isa].worst[2], TOL0, TOL1, TOL2, S[isa].count[0],
               S[isa].count[1], S[isa].count[2]);
        printf("test_fast:   vs long double (every %dth): fast %.2f, %.2f, %.2f; plain %.2f, %.2f, %.2f\n",
               NREF, S[isa].worst_ref[0], S[isa].worst_ref[1], S[isa].worst_ref[2], S[isa].worst_plain[0],
               S[isa].worst_plain[1], S[isa].worst_plain[2]);
        CHECK(S[isa].count[0] >= 10000000 / TF_SCALE);
    }
}

/* Flat intervals (B0 = B1 = B2 = B3 = f_i: constant data, zero slopes): the
 * value is f_i exactly and both derivatives 0 exactly (docs/method.md §2: a
 * constant is reproduced; in floating point Σ A_l need not round to 1, so a
 * kernel that summed A_l·B_l there would be off by an ulp at some queries),
 * for every kernel, form and order of the queries. */
static void flat(void)
{
    enum { NP = 41, M = 4000 };
    static double x[NP], f[NP], q[M], y[M];
    th_seed(0x13198A2E03707344u);
    x[0] = 0.0;
    for (size_t i = 1; i < NP; i++)
        x[i] = x[i - 1] + 0.05 + th_unit();
    for (int c = 0; c < 3; c++) {
        const double level[3] = {0.1, 3.3, -7.7e5}; /* not sums of powers of two */
        for (size_t i = 0; i < NP; i++)
            f[i] = level[c];
        for (int form = 0; form < 2; form++) {
            ts_spline_options o;
            ts_spline_options_init(&o);
            o.form = form ? TS_FORM_C1 : TS_FORM_PAPER;
            ts_spline *s = NULL;
            ts_error e;
            CHECK(ts_spline_new(x, f, NP, &o, &s, &e) == TS_OK);
            if (!s)
                continue;
            for (int sorted = 0; sorted <= 1; sorted++) {
                for (size_t j = 0; j < M; j++)
                    q[j] = x[NP - 1] * th_unit();
                if (sorted)
                    qsort(q, M, sizeof *q, cmp_double);
                for (int isa = 0; isa <= 2; isa++) {
                    if (!have_kernel(isa))
                        continue;
                    for (int deriv = 0; deriv <= 2; deriv++) {
                        ts_cursor cur = TS_CURSOR_INIT;
                        CHECK(ts__fast_batch_isa(s, deriv, q, M, y, &cur, isa, NULL) == 1);
                        long bad = 0;
                        for (size_t j = 0; j < M; j++)
                            bad += !(y[j] == (deriv ? 0.0 : level[c]));
                        CHECKF(bad == 0, "flat %g, form %d, kernel %d, deriv %d, %s: %ld queries not exact",
                               level[c], form, isa, deriv, sorted ? "sorted" : "random", bad);
                    }
                }
                /* single evaluation: the value from its differences (all 0),
                 * the derivatives by the flat test */
                long bad = 0;
                ts_cursor cur = TS_CURSOR_INIT;
                for (size_t j = 0; j < M; j++) {
                    double v0, v1, v2, v;
                    bad += ts_spline_eval(s, q[j], &cur, &v) != TS_OK || !(v == level[c]);
                    bad += ts_spline_eval_deriv(s, q[j], NULL, &v0, &v1, &v2) != TS_OK || !(v0 == level[c]) ||
                           !(v1 == 0.0) || !(v2 == 0.0);
                }
                CHECKF(bad == 0, "flat %g, form %d, ts_spline_eval/ts_spline_eval_deriv, %s: %ld queries not exact", level[c],
                       form, sorted ? "sorted" : "random", bad);
            }
            ts_spline_free(s);
        }
    }
}


/* A small spline with features (non-uniform, mixed signs). */
static ts_spline *small_spline(size_t np, ts_form form)
{
    double *x = malloc(np * sizeof *x), *f = malloc(np * sizeof *f);
    ts_spline *s = NULL;
    if (!x || !f) {
        CHECKF(0, "out of memory in the test");
        free(x);
        free(f);
        return NULL;
    }
    x[0] = -1.0;
    for (size_t i = 1; i < np; i++)
        x[i] = x[i - 1] + 0.1 + th_unit();
    for (size_t i = 0; i < np; i++)
        f[i] = 3.0 + 2.0 * sin(x[i]) + th_unit();
    ts_spline_options o;
    ts_spline_options_init(&o);
    o.form = form;
    ts_error e;
    ts_status st = ts_spline_new(x, f, np, &o, &s, &e);
    if (form == TS_FORM_GEOMETRIC && st != TS_OK)
        s = NULL; /* reported by the caller */
    else
        CHECKF(st == TS_OK, "small spline: %s", ts_strerror(st));
    free(x);
    free(f);
    return s;
}

/* |a − b| within TOL0 of the interval of x. */
static int close_value(const ts_spline *s, double x, double a, double b)
{
    double B[4];
    ts_spline_control(s, interval_of(s, x), B, NULL);
    double M = fmax(fmax(fabs(B[0]), fabs(B[1])), fmax(fabs(B[2]), fabs(B[3])));
    return fabs(a - b) <= TOL0 * EPS * M;
}

static void structure(void)
{
    th_seed(0x9E3779B97F4A7C15u);
    ts_spline *s = small_spline(301, TS_FORM_PAPER);
    if (!s)
        return;
    const double *X = ts_spline_x(s), *F = ts_spline_f(s);
    size_t n = ts_spline_intervals(s);
    enum { M = 1000 };
    static double q[M], y[M], ref[M];
    size_t done = 99;

    /* kernels by number: 0 always, -1 the best, others unknown */
    CHECK(ts__fast_batch_isa(s, 0, q, 0, y, NULL, 0, &done) == 1 && done == 0);
    CHECK(ts__fast_batch_isa(s, 0, q, 0, y, NULL, -1, NULL) == 1);
    CHECK(ts__fast_batch_isa(s, 0, q, 0, y, NULL, 3, NULL) == 0);
    CHECK(ts__fast_batch_isa(s, 0, q, 0, y, NULL, -2, NULL) == 0);
    CHECK(ts__fast_batch(s, 0, q, 0, y, NULL) == 0);

    /* every knot exactly (the right-hand interval, and x_n from the right end) */
    for (size_t i = 0; i <= n; i++)
        q[i] = X[i];
    for (int isa = 0; isa <= 2; isa++) {
        if (!have_kernel(isa))
            continue;
        ts_cursor c = TS_CURSOR_INIT;
        CHECK(ts__fast_batch_isa(s, 0, q, n + 1, y, &c, isa, &done) == 1 && done == n + 1);
        int exact = 1;
        for (size_t i = 0; i <= n; i++)
            exact &= y[i] == F[i];
        CHECKF(exact, "kernel %d: knot values not exact", isa);
        CHECK(c.interval == n - 1);
    }

    /* prefix contract: sorted queries, one outside at 300 -> blocks before it */
    for (size_t j = 0; j < M; j++)
        q[j] = X[0] + (X[n] - X[0]) * ((double)j / (double)(M - 1));
    q[M - 1] = X[n]; /* (the division can round past x_n) */
    const double bad[4] = {TH_NAN, X[n] + 1.0, X[0] - 1e-9, -HUGE_VAL};
    for (int b = 0; b < 4; b++) {
        double keep = q[300];
        q[300] = bad[b];
        for (size_t j = 0; j < M; j++)
            y[j] = 12345.0;
        ts_cursor c = TS_CURSOR_INIT;
        size_t k = ts__fast_batch(s, 0, q, M, y, &c);
        CHECKF(k == 300 / TS_FAST_BLOCK * TS_FAST_BLOCK, "bad query %d: prefix %zu", b, k);
        int ok = 1;
        for (size_t j = 0; j < k; j++) {
            double r;
            ts_spline_eval(s, q[j], NULL, &r);
            ok &= close_value(s, q[j], y[j], r);
        }
        for (size_t j = k; j < M; j++)
            ok &= y[j] == 12345.0;
        CHECKF(ok, "bad query %d: prefix values", b);
        CHECK(k == 0 || c.interval == interval_of(s, q[k - 1]));
        /* the public batch: NaN / DOMAIN there, every other query evaluated */
        ts_error e;
        ts_status st = ts_spline_eval_batch(s, 0, q, M, y, NULL, &e);
        CHECK(st == TS_ERR_DOMAIN && e.index == 300 && e.where == TS_WHERE_QUERY && isnan(y[300]));
        ok = 1;
        for (size_t j = 0; j < M; j++) {
            double r;
            if (j != 300 && ts_spline_eval(s, q[j], NULL, &r) == TS_OK)
                ok &= close_value(s, q[j], y[j], r);
        }
        CHECKF(ok, "bad query %d: ts_spline_eval_batch values", b);
        q[300] = keep;
    }
    /* an unsorted block with a NaN: stops before it; a NaN first: nothing */
    for (size_t j = 0; j < M; j++)
        q[j] = X[0] + (X[n] - X[0]) * th_unit();
    q[200] = TH_NAN;
    CHECK(ts__fast_batch(s, 0, q, M, y, NULL) == 128);
    q[0] = TH_NAN;
    CHECK(ts__fast_batch(s, 0, q, M, y, NULL) == 0);

    /* ts_spline_eval_batch, ts_spline_eval_batch_mt and the best kernel agree bitwise on
     * valid queries (one kernel), for every derivative and query order */
    for (int order = 0; order < 3; order++) {
        for (size_t j = 0; j < M; j++)
            q[j] = X[0] + (X[n] - X[0]) * th_unit();
        if (order == 1)
            qsort(q, M, sizeof *q, cmp_double);
        if (order == 2) { /* descending */
            qsort(q, M, sizeof *q, cmp_double);
            for (size_t j = 0; j < M / 2; j++) {
                double t = q[j];
                q[j] = q[M - 1 - j];
                q[M - 1 - j] = t;
            }
        }
        for (int deriv = 0; deriv <= 2; deriv++) {
            ts_cursor c = {n + 7}; /* stale */
            CHECK(ts__fast_batch_isa(s, deriv, q, M, ref, &c, -1, &done) == 1 && done == M);
            CHECK(c.interval == interval_of(s, q[M - 1]));
            CHECK(ts_spline_eval_batch(s, deriv, q, M, y, NULL, NULL) == TS_OK);
            CHECKF(!memcmp(y, ref, sizeof y), "order %d deriv %d: ts_spline_eval_batch differs from the kernel", order,
                   deriv);
            CHECK(ts_spline_eval_batch_mt(s, deriv, q, M, y, 2, NULL) == TS_OK);
            CHECKF(!memcmp(y, ref, sizeof y), "order %d deriv %d: ts_spline_eval_batch_mt differs", order, deriv);
        }
    }
    ts_spline_free(s);

    /* sparse sorted queries over many knots: the cursor gallops */
    s = small_spline(100001, TS_FORM_PAPER);
    if (s) {
        X = ts_spline_x(s);
        n = ts_spline_intervals(s);
        for (size_t j = 0; j < M; j++)
            q[j] = X[0] + (X[n] - X[0]) * th_unit() * th_unit(); /* dense near x0, sparse later */
        qsort(q, M, sizeof *q, cmp_double);
        ts_cursor c = {n - 1}; /* ahead of the first query: searched back */
        CHECK(ts__fast_batch(s, 0, q, M, y, &c) == M);
        int ok = 1;
        for (size_t j = 0; j < M; j++) {
            double r;
            ts_spline_eval(s, q[j], NULL, &r);
            ok &= close_value(s, q[j], y[j], r);
        }
        CHECK(ok);
        CHECK(c.interval == interval_of(s, q[M - 1]));
        ts_spline_free(s);
    }

    /* two points (one interval) */
    {
        double x2[2] = {1.0, 3.5}, f2[2] = {-2.0, 7.0}, q2[5] = {1.0, 1.7, 2.25, 3.0, 3.5}, y2[5];
        ts_spline *t = NULL;
        CHECK(ts_spline_new(x2, f2, 2, NULL, &t, NULL) == TS_OK);
        if (t) {
            CHECK(ts__fast_batch(t, 0, q2, 5, y2, NULL) == 5);
            CHECK(y2[0] == -2.0 && y2[4] == 7.0);
            for (int j = 0; j < 5; j++) {
                double r;
                ts_spline_eval(t, q2[j], NULL, &r);
                CHECK(close_value(t, q2[j], y2[j], r));
            }
            ts_spline_free(t);
        }
    }

    /* the geometric form: prefix contract as above (block granularity) */
    s = small_spline(40, TS_FORM_GEOMETRIC);
    if (!s) {
        CHECKF(0, "geometric form: small spline not built");
        return;
    }
    X = ts_spline_x(s);
    n = ts_spline_intervals(s);
    for (size_t j = 0; j < M; j++)
        q[j] = X[0] + (X[n] - X[0]) * th_unit();
    double keep = q[700];
    for (int deriv = 0; deriv <= 2; deriv++) {
        ts_cursor c = TS_CURSOR_INIT;
        q[700] = deriv == 1 ? TH_NAN : keep; /* S': stops before the block of a NaN */
        size_t k = ts__fast_batch(s, deriv, q, M, y, &c);
        CHECK(k == (deriv == 1 ? 700 / TS_FAST_BLOCK * TS_FAST_BLOCK : M));
        /* and ts_spline_eval_batch equals the kernel bitwise on every valid query */
        CHECK(ts_spline_eval_batch(s, deriv, q, M, ref, NULL, NULL) == (deriv == 1 ? TS_ERR_DOMAIN : TS_OK));
        int same = 1;
        for (size_t j = 0; j < k; j++)
            same &= !memcmp(&ref[j], &y[j], sizeof y[j]);
        CHECKF(same, "geometric deriv %d: ts_spline_eval_batch differs from the kernel", deriv);
    }
    q[700] = keep;
    /* knots exactly */
    for (size_t i = 0; i <= n; i++)
        q[i] = X[i];
    for (int isa = 0; isa <= 2; isa++) {
        if (!have_kernel(isa))
            continue;
        CHECK(ts__fast_batch_isa(s, 0, q, n + 1, y, NULL, isa, &done) == 1 && done == n + 1);
        int exact = 1;
        for (size_t i = 0; i <= n; i++)
            exact &= y[i] == ts_spline_f(s)[i];
        CHECKF(exact, "geometric kernel %d: knot values not exact", isa);
    }
    ts_spline_free(s);
}

/* ---- the geometric form's kernel (docs/method.md §4) ------------------
 * Expected values: docs/method.md §4 re-derived here in long double
 * (geo_ref: X̂(φ) = u from the nearer end by Newton's method inside a
 * bisection bracket with sinl and cosl, then Y, Y', Y'' and the quotients
 * of §4); ts_spline_eval_deriv itself is checked against the mpmath reference in
 * test_geometric.c.  Single evaluation runs the kernels' solve (internal.h:
 * ts__geo_root, ts__geo_y): without FMA (the portable kernel on x86-64,
 * where neither contracts) its values are the portable kernel's bit for bit.
 * Unit: ε·(M/h^k + |S^(k)|), M = max(|f_i|, |f_{i+1}|, |k d_i|, |k d_{i+1}|)
 * (k = κh), the coefficients of Y.  Tolerance (derived for the difference
 * of two double paths, so it bounds one path against a more exact
 * reference too): both find φ to a few ulps (Halley's error after a step
 * below 2^-20 φ is of the order of the step's cube); |dY/dφ| <= 2|f_{i+1} −
 * f_i| + k(|d_i||A1'| + |d_{i+1}||A2'|) <= 10M (|A_l'| <= 3 on [0, π/4]), so
 * φ's error adds <= 10M·(π/4)·4ε; Y's own evaluation (as the paper form's
 * value above: <= 77ε·M with both paths' trigonometric inputs) -> TOLG0 =
 * 120.  S' = Y'/(h X̂') and S'' = (Y''X̂' − Y'X̂'')/(h² X̂'³) divide by X̂'
 * (>= 0.31 at π/4 for a_i >= 1/2, but 3κ at φ = 0, small for large a_i,
 * where S'' can be far above M/h²): the relative error of the quotient is
 * that of its terms times at most 2 and 4 roundings more, hence the
 * |S^(k)| term in the unit; TOLG1 = 120·2/0.31 ≈ 800, TOLG2 = 1600·3/0.31³
 * ≈ 1.7e5 — loose worst-case products; the measured maxima are printed.  A
 * wrong coefficient, sign or side is off by >= 1e-6·M and fails.  Splines:
 * α_i in [1/2, 100]; a second set with α_i just above a* (0.3472..0.36),
 * where X̂'(π/4) = 1 − (8 − 9/√2)κ nearly vanishes, checks the value only
 * (the derivatives are ill-conditioned there): φ's rounding error there is
 * ε/X̂'(π/4), so the unit is ε·M/X̂'(π/4), same TOLG0. */
#define TOLG0 120.0
#define TOLG1 800.0
#define TOLG2 170000.0

static ts_spline *geo_spline(size_t np, double amin, double amax)
{
    double *x = malloc(np * sizeof *x), *f = malloc(np * sizeof *f), *al = malloc(np * sizeof *al);
    ts_spline *s = NULL;
    if (!x || !f || !al) {
        CHECKF(0, "out of memory in the test");
        goto done;
    }
    x[0] = -2.0;
    for (size_t i = 1; i < np; i++)
        x[i] = x[i - 1] + pow(10.0, -2.0 + 3.0 * th_unit());
    for (size_t i = 0; i < np; i++)
        f[i] = 40.0 * (th_unit() - 0.5);
    for (size_t i = 0; i + 1 < np; i++)
        al[i] = amin * pow(amax / amin, th_unit());
    ts_spline_options o;
    ts_spline_options_init(&o);
    o.form = TS_FORM_GEOMETRIC;
    o.alphas = al;
    o.n_alphas = np - 1;
    ts_error e;
    ts_status st = ts_spline_new(x, f, np, &o, &s, &e);
    CHECKF(st == TS_OK, "geometric spline: %s at %zu", ts_strerror(st), e.index);
done:
    free(x);
    free(f);
    free(al);
    return s;
}

/* S, S', S'' of interval i at x (docs/method.md §4) in long double. */
static void geo_ref(const ts_spline *s, size_t i, double x, double out[3])
{
    const double *X = ts_spline_x(s), *F = ts_spline_f(s), *D = ts_spline_slopes(s);
    const long double PI = 3.141592653589793238462643383279502884L;
    long double x0 = (long double)X[i], x1 = (long double)X[i + 1], xl = (long double)x;
    long double h = x1 - x0, dl = xl - x0, dr = x1 - xl;
    long double a = (long double)ts_spline_alpha(s)[i] + (long double)ts_spline_beta(s)[i], kap = 2 / (3 * PI * a);
    int right = dr < dl;
    size_t i0 = right ? i + 1 : i, i1 = right ? i : i + 1;
    long double u = (right ? dr : dl) / h, F0 = (long double)F[i0], F1 = (long double)F[i1];
    long double D0 = right ? -(long double)D[i0] : (long double)D[i0];
    long double D1 = right ? -(long double)D[i1] : (long double)D[i1];
    long double lo = 0, hi = PI / 4, phi = fminl(u / (3 * kap), asinl(sqrtl(u))), s1 = 0, c1 = 1;
    for (int it = 0; it < 200 && hi - lo > 4 * LDBL_EPSILON; it++) {
        s1 = sinl(phi), c1 = cosl(phi);
        long double g = s1 * s1 + kap * (s1 * (1 - s1) * (3 - s1) - c1 * (1 - c1) * (3 - c1)) - u;
        long double gp = 2 * s1 * c1 + kap * (c1 * (3 - 8 * s1 + 3 * s1 * s1) + s1 * (3 - 8 * c1 + 3 * c1 * c1));
        if (g == 0)
            break;
        if (g < 0)
            lo = phi;
        else
            hi = phi;
        long double next = phi - g / gp;
        if (fabsl(next - phi) <= 2 * LDBL_EPSILON * phi)
            break;
        phi = next > lo && next < hi ? next : (lo + hi) / 2;
    }
    s1 = sinl(phi), c1 = cosl(phi);
    long double k = kap * h, p1 = 3 - 8 * s1 + 3 * s1 * s1, p2 = 3 - 8 * c1 + 3 * c1 * c1;
    long double A1 = s1 * (1 - s1) * (3 - s1), A2 = c1 * (1 - c1) * (3 - c1);
    long double Y = F0 * c1 * c1 + F1 * s1 * s1 + k * (D0 * A1 - D1 * A2);
    long double a1 = c1 * p1, a2 = -s1 * p2, Yp = (F1 - F0) * 2 * s1 * c1 + k * (D0 * a1 - D1 * a2);
    long double Xp = 2 * s1 * c1 + kap * (a1 - a2);
    long double b1 = -s1 * p1 + c1 * c1 * (6 * s1 - 8), b2 = -c1 * p2 + s1 * s1 * (6 * c1 - 8);
    long double c2 = 2 * (c1 * c1 - s1 * s1), Ypp = (F1 - F0) * c2 + k * (D0 * b1 - D1 * b2);
    long double Xpp = c2 + kap * (b1 - b2);
    out[0] = (double)Y;
    out[1] = (double)((right ? -Yp : Yp) / (h * Xp));
    out[2] = (double)((Ypp * Xp - Yp * Xpp) / (Xp * Xp * Xp) / (h * h));
}

static void geometric(void)
{
    th_seed(0x452821E638D01377u);
    const size_t m = 1000000 / TF_SCALE;
    double *q = malloc(m * sizeof *q), *y = malloc(m * sizeof *y), *ref = malloc(3 * m * sizeof *ref);
    double *y1 = malloc(3 * m * sizeof *y1), *yd = malloc(3 * m * sizeof *yd);
    if (!q || !y || !ref || !y1 || !yd) {
        CHECKF(0, "out of memory in the test");
        goto done;
    }
    for (int set = 0; set < 2; set++) {
        ts_spline *s = set == 0 ? geo_spline(2001, 0.5, 100.0) : geo_spline(2001, 0.3472, 0.36);
        if (!s)
            continue;
        const double *X = ts_spline_x(s), *F = ts_spline_f(s), *D = ts_spline_slopes(s);
        const double *Al = ts_spline_alpha(s), *Be = ts_spline_beta(s);
        size_t n = ts_spline_intervals(s);
        for (size_t j = 0; j < m; j++)
            q[j] = j % 97 == 0 ? X[(size_t)(th_unit() * (double)(n + 1)) % (n + 1)]
                               : X[0] + (X[n] - X[0]) * th_unit();
        if (set == 0)
            qsort(q, m / 2, sizeof *q, cmp_double); /* half sorted, half random */
        for (size_t j = 0; j < m; j++) {
            double o[3];
            geo_ref(s, interval_of(s, q[j]), q[j], o);
            ref[j] = o[0], ref[m + j] = o[1], ref[2 * m + j] = o[2];
            CHECK(ts_spline_eval_deriv(s, q[j], NULL, &yd[j], &yd[m + j], &yd[2 * m + j]) == TS_OK);
        }
        for (int isa = 0; isa <= 2; isa++) {
            if (!have_kernel(isa))
                continue;
            double worst[3] = {0, 0, 0};
            for (int deriv = 0; deriv <= (set == 0 ? 2 : 0); deriv++) {
                ts_cursor c = TS_CURSOR_INIT;
                CHECK(ts__fast_batch_isa(s, deriv, q, m, y, &c, isa, NULL) == 1);
#if defined(__x86_64__)
                if (isa == 0)
                    CHECKF(!memcmp(yd + (size_t)deriv * m, y, m * sizeof *y),
                           "geometric set %d deriv %d: ts_spline_eval_deriv differs from the portable kernel",
                           set, deriv);
#endif
                /* a query's value does not depend on its block: alone (a
                 * block of one) it gets the bits it got in the batch, also
                 * where its block ran more than two steps (set 1: most
                 * blocks; kernels.c runs those passes in another loop) */
                long alone = 0;
                for (size_t j = 0; j < m; j += 89) {
                    double y1q;
                    CHECK(ts__fast_batch_isa(s, deriv, &q[j], 1, &y1q, NULL, isa, NULL) == 1);
                    alone += memcmp(&y1q, &y[j], sizeof y1q) != 0;
                }
                CHECKF(alone == 0, "geometric set %d kernel %d deriv %d: %ld queries differ alone", set, isa,
                       deriv, alone);
                double tol = deriv == 0 ? TOLG0 : deriv == 1 ? TOLG1 : TOLG2;
                long bad = 0;
                size_t first = 0;
                for (size_t j = 0; j < m; j++) {
                    size_t i = interval_of(s, q[j]);
                    double h = X[i + 1] - X[i], k = 2.0 / (3.0 * 3.14159265358979323846 * (Al[i] + Be[i])) * h;
                    double M = fmax(fmax(fabs(F[i]), fabs(F[i + 1])), fmax(fabs(k * D[i]), fabs(k * D[i + 1])));
                    double kappa = k / h, r = ref[(size_t)deriv * m + j];
                    /* set 1: the value's condition 1/X̂'(π/4); derivatives: relative */
                    double unit = set == 1 ? EPS * M / (1.0 - 1.6360389693210722 * kappa)
                                           : EPS * (M / pow(h, deriv) + (deriv ? fabs(r) : 0.0));
                    double e = fabs(y[j] - r) / unit;
                    if (!(e <= tol) && !bad++)
                        first = j;
                    worst[deriv] = fmax(worst[deriv], e);
                }
                CHECKF(bad == 0, "geometric set %d kernel %d deriv %d: %ld off, first x = %.17g: %.17g vs %.17g", set,
                       isa, deriv, bad, q[first], y[first], ref[(size_t)deriv * m + first]);
                /* AVX2+FMA and AVX-512F run the same operations (both contract
                 * into FMA), lane by lane: bitwise the same values */
                if (isa == 1)
                    memcpy(y1 + (size_t)deriv * m, y, m * sizeof *y);
                if (isa == 2 && have_kernel(1))
                    CHECKF(!memcmp(y1 + (size_t)deriv * m, y, m * sizeof *y),
                           "geometric set %d deriv %d: AVX2 and AVX-512 kernels differ", set, deriv);
            }
            printf("test_fast: geometric %s, kernel %d: max |kernel - long double| / unit = %.2f, %.2f, %.2f\n",
                   set == 0 ? "a in [1/2, 100]" : "a in [0.3472, 0.36], value only", isa, worst[0], worst[1],
                   worst[2]);
        }
        ts_spline_free(s);
    }
done:
    free(q);
    free(y);
    free(ref);
    free(y1);
    free(yd);
}

/* The order of a batch does not change a value: sorted queries take the
 * cursor walk, shuffled ones the binary search per query, whose staging
 * takes h_i as x_{i+1} − x_i from the knots instead of the stored width;
 * both must give the same bits for every form, kernel and derivative.
 * Knots of both signs growing by factors 1.5 to 4.5, so that many widths
 * x_{i+1} − x_i round (x_{i+1} > 2x_i: no Sterbenz): the stored h_i is that same rounded
 * difference (spline.c), checked here too.  Expected values: the sorted
 * batch, so the check is exact; a staged width one ulp off changes values
 * and fails it (the geometric form's sorted path reads the stored width). */
static void order(void)
{
    enum { NP = 40, M = 3000 };
    static double x[NP], f[NP], qs[M], q[M], ys[M], y[M];
    static size_t perm[M];
    th_seed(0xA4093822299F31D0u);
    x[0] = -1.0 - th_unit();
    size_t inexact = 0;
    for (size_t i = 1; i < NP; i++) {
        x[i] = x[i - 1] + (0.5 + 3.0 * th_unit()) * (fabs(x[i - 1]) + 0.1); /* ×1.5..4.5 above 0 */
        inexact += (long double)x[i] - (long double)x[i - 1] != (long double)(x[i] - x[i - 1]);
    }
    CHECKF(inexact >= 8, "only %zu rounded widths: the data do not test what they should", inexact);
    for (size_t i = 0; i < NP; i++)
        f[i] = 2.0 + sin(0.7 * (double)i) + th_unit();
    for (size_t j = 0; j < M; j++) { /* an interval, then a point in it; every 13th a knot */
        size_t i = (size_t)(th_unit() * (NP - 1)) % (NP - 1);
        double t = x[i] + (x[i + 1] - x[i]) * th_unit();
        qs[j] = j % 13 == 0 ? x[j / 13 % NP] : t <= x[i + 1] ? t : x[i + 1];
    }
    qsort(qs, M, sizeof *qs, cmp_double);
    for (size_t j = 0; j < M; j++)
        perm[j] = j;
    for (size_t j = M - 1; j > 0; j--) { /* Fisher-Yates */
        size_t k = (size_t)(th_unit() * (double)(j + 1)) % (j + 1), t = perm[j];
        perm[j] = perm[k];
        perm[k] = t;
    }
    for (size_t j = 0; j < M; j++)
        q[j] = qs[perm[j]];
    const ts_form forms[3] = {TS_FORM_PAPER, TS_FORM_C1, TS_FORM_GEOMETRIC};
    for (int k = 0; k < 3; k++) {
        ts_spline_options o;
        ts_spline_options_init(&o);
        o.form = forms[k];
        ts_spline *s = NULL;
        ts_error e;
        CHECKF(ts_spline_new(x, f, NP, &o, &s, &e) == TS_OK, "order: form %d not built", k);
        if (!s)
            continue;
        for (int isa = 0; isa <= 2; isa++) {
            if (!have_kernel(isa))
                continue;
            for (int deriv = 0; deriv <= 2; deriv++) {
                size_t dn = 0, dr = 0;
                CHECK(ts__fast_batch_isa(s, deriv, qs, M, ys, NULL, isa, &dn) == 1 && dn == M);
                CHECK(ts__fast_batch_isa(s, deriv, q, M, y, NULL, isa, &dr) == 1 && dr == M);
                long bad = 0;
                for (size_t j = 0; j < M; j++)
                    bad += memcmp(&y[j], &ys[perm[j]], sizeof y[j]) != 0;
                CHECKF(bad == 0, "order: form %d, kernel %d, deriv %d: %ld shuffled queries differ from sorted",
                       k, isa, deriv, bad);
            }
        }
        ts_spline_free(s);
    }
}


/* ts_spline_eval's value inside the data is the portable kernel's, bit for bit:
 * the same products tu, tv and nearer-end test, the same polynomials and
 * B0 + Σ A_l (B_l − B0) (internal.h's ts__trig_eval_in).  Only where neither
 * is contracted into FMA: an x86-64 build without FMA (the default); the
 * kernels' derivatives group their products differently (tolerances above). */
static void scalar(void)
{
#if defined(__x86_64__) && !defined(__FMA__)
    enum { M = 200000 };
    double *q = malloc(M * sizeof *q), *y = malloc(M * sizeof *y);
    if (!q || !y) {
        CHECKF(0, "out of memory in the test");
        free(q);
        free(y);
        return;
    }
    th_seed(0x452821E638D01377u);
    for (int kind = 0; kind < 4; kind++) {
        for (int form = 0; form < 2; form++) {
            ts_spline *s = random_spline(2001, kind, form);
            if (!s)
                continue;
            const double *X = ts_spline_x(s);
            double x0 = X[0], xn = X[ts_spline_intervals(s)];
            for (int sorted = 0; sorted <= 1; sorted++) {
                /* knots, a few ulps around each midpoint (where u > v can
                 * round to tu = tv: both must take the left end), the rest
                 * uniform */
                for (size_t j = 0; j < M; j++) {
                    size_t i = (j / 8) % 2000;
                    double mid = X[i] + 0.5 * (X[i + 1] - X[i]);
                    for (size_t k = j % 8; k > 4; k--)
                        mid = nextafter(mid, HUGE_VAL);
                    for (size_t k = j % 8; k > 0 && k <= 4; k--)
                        mid = nextafter(mid, -HUGE_VAL);
                    q[j] = j % 97 == 0 ? X[(j / 97) % 2001] : j % 3 == 0 ? mid : x0 + (xn - x0) * th_unit();
                }
                if (sorted)
                    qsort(q, M, sizeof *q, cmp_double);
                ts_cursor cur = TS_CURSOR_INIT;
                CHECK(ts__fast_batch_isa(s, 0, q, M, y, &cur, 0, NULL) == 1);
                long bad = 0;
                size_t first = 0;
                ts_cursor c1 = TS_CURSOR_INIT;
                for (size_t j = 0; j < M; j++) {
                    double v;
                    int off = ts_spline_eval(s, q[j], &c1, &v) != TS_OK || memcmp(&v, &y[j], sizeof v) != 0;
                    if (off && !bad++)
                        first = j;
                }
                CHECKF(bad == 0, "kind %d form %d %s: ts_spline_eval differs from the portable kernel at %ld queries, first x = %.17g",
                       kind, form, sorted ? "sorted" : "random", bad, q[first]);
            }
            ts_spline_free(s);
        }
    }
    free(q);
    free(y);
#else
    printf("scalar: skipped (FMA contraction possible in this build)\n");
#endif
}

int main(void)
{
    TH_CASE("structure");
    structure();
    TH_CASE("accuracy");
    accuracy();
    TH_CASE("geometric");
    geometric();
    TH_CASE("flat");
    flat();
    TH_CASE("order");
    order();
    TH_CASE("scalar");
    scalar();
    return th_report("test_fast");
}
