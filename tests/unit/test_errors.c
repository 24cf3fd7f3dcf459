/* Every error status of the core functions, provoked at least once, with the
 * index and kind reported through ts_error (header: include/trigspline.h).
 * Expected statuses come from the header's per-function lists. */
#include "th.h"
#include "th_options.h"
#include "internal.h"
#include "trigspline.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

static const double X5[5] = {0, 1, 2.5, 3, 4.75};
static const double F5[5] = {1, -2, 0.5, 3, 2};

/* ts_spline_new must fail with st, report (index, where) and leave *out NULL. */
static void expect_new(const double *x, const double *f, size_t np, const ts_spline_options *o, ts_status st,
                       size_t index, ts_where where, int line)
{
    ts_spline *s = (ts_spline *)(uintptr_t)1; /* must be reset to NULL */
    ts_error err = {TS_ERR_NOMEM, 12345, TS_WHERE_QUERY};
    ts_status got = ts_spline_new(x, f, np, o, &s, &err);
    CHECKF(got == st, "line %d: status %d (%s), want %d (%s)", line, (int)got, ts_strerror(got), (int)st,
           ts_strerror(st));
    CHECKF(st == TS_OK ? s != NULL : s == NULL, "line %d: *out wrong (NULL exactly on failure)", line);
    CHECKF(err.status == st, "line %d: err.status %d", line, (int)err.status);
    CHECKF(err.index == index && err.where == where, "line %d: err index %zu where %d, want %zu %d", line, err.index,
           (int)err.where, index, (int)where);
    if (got == TS_OK)
        ts_spline_free(s);
    /* err may be NULL */
    s = (ts_spline *)(uintptr_t)1;
    got = ts_spline_new(x, f, np, o, &s, NULL);
    CHECKF(got == st && (st == TS_OK) == (s != NULL), "line %d: without ts_error: %d", line, (int)got);
    if (got == TS_OK)
        ts_spline_free(s);
}
#define EXPECT_NEW(...) expect_new(__VA_ARGS__, __LINE__)
#define NOIDX TS_NO_INDEX, TS_WHERE_NONE

static void test_strerror(void)
{
    const char *seen[TS_STATUS_COUNT_];
    for (int c = 0; c < TS_STATUS_COUNT_; c++) {
        const char *m = ts_strerror((ts_status)c);
        CHECKF(m != NULL && m[0] != 0, "ts_strerror(%d)", c);
        seen[c] = m ? m : "";
        for (int k = 0; k < c; k++)
            CHECKF(strcmp(seen[k], seen[c]) != 0, "codes %d and %d share a message", k, c);
    }
    int unknown[3] = {TS_STATUS_COUNT_, 999, -1};
    for (int u = 0; u < 3; u++) {
        const char *m = ts_strerror((ts_status)unknown[u]);
        CHECKF(m != NULL && m[0] != 0, "ts_strerror(unknown %d)", unknown[u]);
        for (int c = 0; m && c < TS_STATUS_COUNT_; c++)
            CHECKF(strcmp(m, seen[c]) != 0, "unknown code %d has the message of %d", unknown[u], c);
    }
}

static void test_new(void)
{
    ts_spline_options o;
    double x[5], f[5];
    ts_spline *s = NULL;

    /* NULL pointers */
    EXPECT_NEW(NULL, F5, 5, NULL, TS_ERR_NULL, NOIDX);
    EXPECT_NEW(X5, NULL, 5, NULL, TS_ERR_NULL, NOIDX);
    CHECK(ts_spline_new(X5, F5, 5, NULL, NULL, NULL) == TS_ERR_NULL);
    /* too few points */
    EXPECT_NEW(X5, F5, 0, NULL, TS_ERR_TOO_FEW, NOIDX);
    EXPECT_NEW(X5, F5, 1, NULL, TS_ERR_TOO_FEW, NOIDX);
    EXPECT_NEW(X5, F5, 2, NULL, TS_OK, NOIDX); /* two points are fine */

    /* NaN / ±Inf in x and f: index of the first */
    const double bad[3] = {TH_NAN, TH_INF, -TH_INF};
    for (int b = 0; b < 3; b++) {
        for (size_t i = 0; i < 5; i += 2) {
            memcpy(x, X5, sizeof x);
            memcpy(f, F5, sizeof f);
            x[i] = bad[b];
            EXPECT_NEW(x, f, 5, NULL, TS_ERR_NONFINITE, i, TS_WHERE_POINT);
            memcpy(x, X5, sizeof x);
            f[i] = bad[b];
            if (i + 2 < 5)
                f[i + 2] = TH_NAN; /* a later one too: the first is reported */
            EXPECT_NEW(x, f, 5, NULL, TS_ERR_NONFINITE, i, TS_WHERE_POINT);
        }
    }
    /* x spacing that overflows (each x finite): must not succeed */
    {
        double xo[2] = {-1.5e308, 1.5e308}, fo[2] = {0, 1};
        ts_status st = ts_spline_new(xo, fo, 2, NULL, &s, NULL);
        CHECKF(st != TS_OK && s == NULL, "x spread overflowing to Inf accepted (%d)", (int)st);
        ts_spline_free(s);
        s = NULL;
    }

    /* unsorted and duplicate x: index i with x[i] <= x[i-1] */
    memcpy(f, F5, sizeof f);
    memcpy(x, X5, sizeof x);
    x[3] = 2.0; /* 0 1 2.5 2 4.75 */
    EXPECT_NEW(x, f, 5, NULL, TS_ERR_UNSORTED, 3, TS_WHERE_POINT);
    memcpy(x, X5, sizeof x);
    x[2] = 1.0; /* duplicate of x[1] */
    EXPECT_NEW(x, f, 5, NULL, TS_ERR_UNSORTED, 2, TS_WHERE_POINT);
    memcpy(x, X5, sizeof x);
    x[1] = -0.0; /* -0 == 0: duplicate */
    EXPECT_NEW(x, f, 5, NULL, TS_ERR_UNSORTED, 1, TS_WHERE_POINT);
    {
        double xr[5] = {4, 3, 2, 1, 0};
        EXPECT_NEW(xr, F5, 5, NULL, TS_ERR_UNSORTED, 1, TS_WHERE_POINT);
    }

    /* alpha <= 0, NaN, Inf: scalar (index 0) and per interval */
    const double bad_alpha[5] = {0.0, -1.0, TH_NAN, TH_INF, -0.0};
    for (int b = 0; b < 5; b++) {
        th_options_paper(&o);
        o.alpha = bad_alpha[b];
        EXPECT_NEW(X5, F5, 5, &o, TS_ERR_ALPHA, 0, TS_WHERE_INTERVAL);
        double al[4] = {1, 1, 1, 1};
        al[2] = bad_alpha[b];
        th_options_paper(&o);
        o.alphas = al, o.n_alphas = 4;
        EXPECT_NEW(X5, F5, 5, &o, TS_ERR_ALPHA, 2, TS_WHERE_INTERVAL);
    }
    /* beta < 0, NaN, Inf */
    const double bad_beta[4] = {-1e-300, -2.0, TH_NAN, TH_INF};
    for (int b = 0; b < 4; b++) {
        th_options_paper(&o);
        o.beta = bad_beta[b];
        EXPECT_NEW(X5, F5, 5, &o, TS_ERR_BETA, 0, TS_WHERE_INTERVAL);
        double be[4] = {0, 0.5, 0, 0};
        be[3] = bad_beta[b];
        th_options_paper(&o);
        o.betas = be, o.n_betas = 4;
        EXPECT_NEW(X5, F5, 5, &o, TS_ERR_BETA, 3, TS_WHERE_INTERVAL);
    }
    /* alpha + beta <= 0 cannot happen with alpha > 0 and beta >= 0; the sum can
     * only go wrong by overflowing to +Inf, which the header's BETA covers
     * ("beta ... not finite" is the nearest: a must be usable). */
    {
        th_options_paper(&o);
        o.alpha = 1.5e308;
        o.beta = 1.5e308;
        ts_status st = ts_spline_new(X5, F5, 5, &o, &s, NULL);
        CHECKF(st == TS_ERR_BETA && s == NULL, "alpha + beta = Inf gives %d", (int)st);
        ts_spline_free(s);
        s = NULL;
        /* beta = 0 and tiny alpha are legal */
        o.alpha = 1e-300;
        o.beta = 0;
        EXPECT_NEW(X5, F5, 5, &o, TS_OK, NOIDX);
    }

    /* per-interval arrays of the wrong length */
    {
        double v[6] = {1, 1, 1, 1, 1, 1};
        size_t lens[3] = {3, 5, 0};
        for (int k = 0; k < 3; k++) {
            th_options_paper(&o);
            o.alphas = v, o.n_alphas = lens[k];
            EXPECT_NEW(X5, F5, 5, &o, TS_ERR_LENGTH, NOIDX);
            th_options_paper(&o);
            o.betas = v, o.n_betas = lens[k];
            EXPECT_NEW(X5, F5, 5, &o, TS_ERR_LENGTH, NOIDX);
            th_options_paper(&o);
            o.slopes = TS_SLOPES_USER;
            o.user_slopes = v, o.n_user_slopes = lens[k] == 5 ? 4 : lens[k]; /* n_points = 5 */
            EXPECT_NEW(X5, F5, 5, &o, TS_ERR_LENGTH, NOIDX);
        }
        th_options_paper(&o);
        o.slopes = TS_SLOPES_USER;
        o.user_slopes = v, o.n_user_slopes = 5;
        EXPECT_NEW(X5, F5, 5, &o, TS_OK, NOIDX);
        /* user slopes missing */
        o.user_slopes = NULL;
        EXPECT_NEW(X5, F5, 5, &o, TS_ERR_NULL, NOIDX);
        /* NaN / Inf in user slopes: index of the first */
        double us[5] = {0, 1, 2, 3, 4};
        us[3] = TH_NAN;
        us[4] = TH_INF;
        o.user_slopes = us;
        EXPECT_NEW(X5, F5, 5, &o, TS_ERR_NONFINITE, 3, TS_WHERE_POINT);
        us[3] = 0;
        EXPECT_NEW(X5, F5, 5, &o, TS_ERR_NONFINITE, 4, TS_WHERE_POINT);
        us[4] = -TH_INF;
        EXPECT_NEW(X5, F5, 5, &o, TS_ERR_NONFINITE, 4, TS_WHERE_POINT);
    }

    /* bad enum values */
    {
        int bad_enum[3] = {-1, 99, 1 << 20};
        for (int k = 0; k < 3; k++) {
            th_options_paper(&o);
            o.form = (ts_form)bad_enum[k];
            EXPECT_NEW(X5, F5, 5, &o, TS_ERR_OPTION, NOIDX);
            th_options_paper(&o);
            o.slopes = (ts_slopes)bad_enum[k];
            EXPECT_NEW(X5, F5, 5, &o, TS_ERR_OPTION, NOIDX);
            th_options_paper(&o);
            o.shape = (ts_shape)bad_enum[k];
            EXPECT_NEW(X5, F5, 5, &o, TS_ERR_OPTION, NOIDX);
            th_options_paper(&o);
            o.extrapolate = (ts_extrap)bad_enum[k];
            EXPECT_NEW(X5, F5, 5, &o, TS_ERR_OPTION, NOIDX);
        }
        th_options_paper(&o);
        o.slopes = (ts_slopes)TS_SLOPES_COUNT_;
        EXPECT_NEW(X5, F5, 5, &o, TS_ERR_OPTION, NOIDX);
    }

    /* periodic slopes need f[0] == f[n] */
    {
        th_options_paper(&o);
        o.slopes = TS_SLOPES_PERIODIC;
        ts_status st = ts_spline_new(X5, F5, 5, &o, &s, NULL);
        CHECKF(st == TS_ERR_PERIODIC && s == NULL, "periodic with f0 != fn: %d", (int)st);
        ts_spline_free(s);
        s = NULL;
        double fp[5] = {1, -2, 0.5, 3, 1};
        CHECK(ts_spline_new(X5, fp, 5, &o, &s, NULL) == TS_OK);
        ts_spline_free(s);
        s = NULL;
    }

    /* every option fine: success, and the error record is reset */
    {
        ts_error err = {TS_ERR_NOMEM, 7, TS_WHERE_QUERY};
        CHECK(ts_spline_new(X5, F5, 5, NULL, &s, &err) == TS_OK && s != NULL);
        CHECK(err.status == TS_OK && err.index == TS_NO_INDEX && err.where == TS_WHERE_NONE);
        ts_spline_free(s);
        s = NULL;
    }
    ts_spline_free(NULL); /* no-op */
}

static void test_eval_errors(void)
{
    ts_spline *s = NULL;
    ts_spline_options po;
    th_options_paper(&po);
    CHECK(ts_spline_new(X5, F5, 5, &po, &s, NULL) == TS_OK);
    if (!s)
        return;
    double y = 0, dy = 0, d2y = 0;
    ts_cursor cur = TS_CURSOR_INIT;

    /* NULL spline: TS_ERR_NULL, NaN outputs */
    CHECK(ts_spline_eval(NULL, 1.0, NULL, &y) == TS_ERR_NULL && isnan(y));
    y = dy = d2y = 0;
    CHECK(ts_spline_eval_deriv(NULL, 1.0, &cur, &y, &dy, &d2y) == TS_ERR_NULL && isnan(y) && isnan(dy) && isnan(d2y));
    /* every output may be NULL */
    CHECK(ts_spline_eval_deriv(s, 1.0, NULL, NULL, NULL, NULL) == TS_OK);
    CHECK(ts_spline_eval(s, 1.0, NULL, NULL) == TS_OK);
    dy = 0;
    CHECK(ts_spline_eval_deriv(s, 1.0, NULL, NULL, &dy, NULL) == TS_OK && isfinite(dy) && dy != 0);

    /* NaN query: an error, not a NaN with success (every policy) */
    y = dy = d2y = 0;
    CHECK(ts_spline_eval_deriv(s, TH_NAN, &cur, &y, &dy, &d2y) == TS_ERR_DOMAIN && isnan(y) && isnan(dy) && isnan(d2y));
    y = 0;
    CHECK(ts_spline_eval(s, TH_NAN, NULL, &y) == TS_ERR_DOMAIN && isnan(y));
    /* out of range under the default policy, just outside each end, and ±Inf */
    const double outq[6] = {-1e-300, nextafter(0.0, -1.0), 4.75 + 1e-15 * 4.75 * 4, 1e308, TH_INF, -TH_INF};
    for (int k = 0; k < 6; k++) {
        y = dy = d2y = 0;
        CHECKF(ts_spline_eval_deriv(s, outq[k], NULL, &y, &dy, &d2y) == TS_ERR_DOMAIN && isnan(y) && isnan(dy) &&
                   isnan(d2y),
               "query %.17g", outq[k]);
    }
    /* the ends themselves are inside */
    CHECK(ts_spline_eval(s, 0.0, NULL, &y) == TS_OK && y == 1.0);
    CHECK(ts_spline_eval(s, 4.75, NULL, &y) == TS_OK && fabs(y - 2.0) < 1e-15);
    CHECK(ts_spline_eval(s, -0.0, NULL, &y) == TS_OK && y == 1.0);

    /* integral: NULLs, NaN / outside ends, NaN output */
    double r = 0;
    CHECK(ts_spline_integral(NULL, 0, 1, &r) == TS_ERR_NULL);
    CHECK(ts_spline_integral(s, 0, 1, NULL) == TS_ERR_NULL);
    const double ia[5] = {TH_NAN, -0.5, 0.0, 0.0, 5.0}, ib[5] = {1.0, 1.0, TH_NAN, 4.76, 4.0};
    for (int k = 0; k < 5; k++) {
        r = 0;
        CHECKF(ts_spline_integral(s, ia[k], ib[k], &r) == TS_ERR_DOMAIN, "integral %g..%g", ia[k], ib[k]);
        /* header convention: out-parameters are reset before any check */
        CHECKF(isnan(r), "integral output after a failure: %g", r);
    }
    CHECK(ts_spline_integral(s, 0, 4.75, &r) == TS_OK && isfinite(r));

    /* accessors */
    double a = 0, B[4] = {0, 0, 0, 0}, X[4];
    CHECK(ts_spline_a(NULL, 0, &a) == TS_ERR_NULL);
    CHECK(ts_spline_a(s, 0, NULL) == TS_ERR_NULL);
    CHECK(ts_spline_a(s, 4, &a) == TS_ERR_INDEX);
    CHECK(ts_spline_a(s, TS_NO_INDEX, &a) == TS_ERR_INDEX);
    CHECK(ts_spline_a(s, 3, &a) == TS_OK && a == 1.0);
    CHECK(ts_spline_control(NULL, 0, B, X) == TS_ERR_NULL);
    CHECK(ts_spline_control(s, 0, NULL, X) == TS_ERR_NULL);
    CHECK(ts_spline_control(s, 4, B, X) == TS_ERR_INDEX);
    CHECK(ts_spline_control(s, 4, B, NULL) == TS_ERR_INDEX);
    CHECK(ts_spline_control(s, 3, B, NULL) == TS_OK && B[0] == 3.0 && B[3] == 2.0);

    /* batch: NULLs, bad deriv, NaN and out-of-range queries */
    double xq[4] = {0.5, TH_NAN, 9.0, 1.0}, yq[4] = {0, 0, 0, 0};
    ts_error err;
    CHECK(ts_spline_eval_batch(NULL, 0, xq, 4, yq, NULL, &err) == TS_ERR_NULL && err.status == TS_ERR_NULL);
    CHECK(ts_spline_eval_batch(s, 0, NULL, 4, yq, NULL, &err) == TS_ERR_NULL);
    CHECK(ts_spline_eval_batch(s, 0, xq, 4, NULL, NULL, &err) == TS_ERR_NULL);
    /* deriv 3 is a valid order in the paper form: the NaN query fails */
    CHECK(ts_spline_eval_batch(s, 3, xq, 4, yq, NULL, &err) == TS_ERR_DOMAIN && err.index == 1);
    CHECK(ts_spline_eval_batch(s, -2, xq, 4, yq, NULL, &err) == TS_ERR_OPTION && err.status == TS_ERR_OPTION);
    CHECK(ts_spline_eval_batch(s, -1, xq, 4, yq, NULL, &err) == TS_ERR_OPTION);
    CHECK(ts_spline_eval_batch_mt(NULL, 0, xq, 4, yq, 2, &err) == TS_ERR_NULL);
    CHECK(ts_spline_eval_batch_mt(s, -7, xq, 4, yq, 2, &err) == TS_ERR_OPTION);
    CHECK(ts_spline_eval_batch_mt(s, 0, NULL, 4, yq, 2, &err) == TS_ERR_NULL);
    CHECK(ts_spline_eval_batch(s, 0, xq, 4, yq, NULL, &err) == TS_ERR_DOMAIN);
    CHECK(err.status == TS_ERR_DOMAIN && err.index == 1 && err.where == TS_WHERE_QUERY);
    CHECK(isfinite(yq[0]) && isnan(yq[1]) && isnan(yq[2]) && isfinite(yq[3]));
    CHECK(ts_spline_eval_batch(s, 0, xq, 4, yq, NULL, NULL) == TS_ERR_DOMAIN); /* err may be NULL */
    CHECK(ts_spline_eval_batch(s, 1, xq, 0, yq, NULL, &err) == TS_OK && err.status == TS_OK); /* m = 0 */
    ts_spline_free(s);
}

static void test_slopes_compute(void)
{
    double d[5], x[5], f[5];
    ts_error err;
    CHECK(ts_slopes_compute(TS_SLOPES_ARITHMETIC, NULL, F5, 5, d, &err) == TS_ERR_NULL);
    CHECK(ts_slopes_compute(TS_SLOPES_ARITHMETIC, X5, NULL, 5, d, &err) == TS_ERR_NULL);
    CHECK(ts_slopes_compute(TS_SLOPES_ARITHMETIC, X5, F5, 5, NULL, &err) == TS_ERR_NULL);
    CHECK(ts_slopes_compute(TS_SLOPES_ARITHMETIC, X5, F5, 1, d, &err) == TS_ERR_TOO_FEW);
    CHECK(ts_slopes_compute(TS_SLOPES_ARITHMETIC, X5, F5, 0, d, &err) == TS_ERR_TOO_FEW);
    memcpy(x, X5, sizeof x);
    memcpy(f, F5, sizeof f);
    f[2] = TH_NAN;
    CHECK(ts_slopes_compute(TS_SLOPES_ARITHMETIC, x, f, 5, d, &err) == TS_ERR_NONFINITE);
    CHECK(err.status == TS_ERR_NONFINITE && err.index == 2 && err.where == TS_WHERE_POINT);
    x[4] = TH_INF;
    f[2] = 0.5;
    CHECK(ts_slopes_compute(TS_SLOPES_ARITHMETIC, x, f, 5, d, &err) == TS_ERR_NONFINITE && err.index == 4);
    memcpy(x, X5, sizeof x);
    x[3] = x[2];
    CHECK(ts_slopes_compute(TS_SLOPES_ARITHMETIC, x, f, 5, d, &err) == TS_ERR_UNSORTED);
    CHECK(err.index == 3 && err.where == TS_WHERE_POINT);
    CHECK(ts_slopes_compute(TS_SLOPES_USER, X5, F5, 5, d, &err) == TS_ERR_OPTION); /* not a computed method */
    CHECK(ts_slopes_compute((ts_slopes)42, X5, F5, 5, d, &err) == TS_ERR_OPTION);
    CHECK(ts_slopes_compute((ts_slopes)-3, X5, F5, 5, d, &err) == TS_ERR_OPTION);
    CHECK(ts_slopes_compute(TS_SLOPES_PERIODIC, X5, F5, 5, d, &err) == TS_ERR_PERIODIC);
    CHECK(ts_slopes_compute(TS_SLOPES_ARITHMETIC, X5, F5, 5, d, &err) == TS_OK && err.status == TS_OK);
    CHECK(ts_slopes_compute(TS_SLOPES_ARITHMETIC, X5, F5, 5, d, NULL) == TS_OK);
}

/* Last: sizes whose byte counts overflow size_t.  The data pointer is a tiny
 * array: the library must detect the overflow before reading x[1] onwards
 * (a crash here is a library bug). */
static void test_overflow(void)
{
    static const double two[2] = {0, 1};
    size_t sizes[3] = {SIZE_MAX / 2, SIZE_MAX, SIZE_MAX / sizeof(double) + 2};
    for (int k = 0; k < 3; k++) {
        ts_spline *s = (ts_spline *)(uintptr_t)1;
        ts_error err;
        fflush(stdout);
        ts_status st = ts_spline_new(two, two, sizes[k], NULL, &s, &err);
        CHECKF(st == TS_ERR_OVERFLOW && s == NULL && err.status == TS_ERR_OVERFLOW, "n_points %zu: %d", sizes[k],
               (int)st);
    }
    /* each later step of the layout's count (spline.c: 3 arrays of n + 1,
     * per-interval arrays, then n/8 + 1 running integrals, TS_CUM_STEP = 8)
     * overflowing while the earlier ones fit: the paper form's 4 arrays of
     * n when 3 (n + 1) fits; the geometric form's 3 (n + 1) + 3 n = 6 n + 3
     * fits but the integrals do not */
    ts_spline_options paper;
    ts_spline_options_init(&paper);
    paper.form = TS_FORM_PAPER;
    size_t n6 = (SIZE_MAX - 3) / 6; /* 6 n6 + 3 <= SIZE_MAX < 6 n6 + 3 + n6/8 + 1 */
    size_t later[2] = {SIZE_MAX / 3, n6 + 1};
    const ts_spline_options *lopt[2] = {&paper, NULL};
    for (int k = 0; k < 2; k++) {
        ts_spline *s = (ts_spline *)(uintptr_t)1;
        ts_error err;
        ts_status st = ts_spline_new(two, two, later[k], lopt[k], &s, &err);
        CHECKF(st == TS_ERR_OVERFLOW && s == NULL && err.status == TS_ERR_OVERFLOW,
               "n_points %zu: %d", later[k], (int)st);
    }
    /* the allocation helper's own n·sizeof check (internal.h) */
    CHECK(ts__malloc_n(SIZE_MAX / 8 + 1, 8) == NULL);
    CHECK(ts__malloc_n(SIZE_MAX, 2) == NULL);
    double *three = ts__malloc_n(3, sizeof *three);
    CHECK(three != NULL);
    free(three);
}

/* TS_ERR_NOMEM: the library's test hook (internal.h) makes the k-th
 * allocation fail; nothing may leak (ASan/valgrind) and *out stays NULL. */
static void test_nomem(void)
{
    static const double x[4] = {0, 1, 2, 3}, f[4] = {1, 2, 1, 3};
    static const double pts[8] = {0, 0, 1, 0, 1, 1, 0, 1};
    for (long k = 1; k <= 2; k++) {
        ts_spline *s = (ts_spline *)(uintptr_t)1;
        ts_error err;
        ts__test_fail_alloc = k;
        ts_status st = ts_spline_new(x, f, 4, NULL, &s, &err);
        ts__test_fail_alloc = 0;
        CHECKF(st == TS_ERR_NOMEM && s == NULL && err.status == TS_ERR_NOMEM, "spline, allocation %ld: %d", k,
               (int)st);
    }
    int failed = 0;
    for (long k = 1; k <= 16; k++) {
        ts_curve *c = (ts_curve *)(uintptr_t)1;
        ts__test_fail_alloc = k;
        ts_status st = ts_curve_new(pts, 4, 2, NULL, &c, NULL);
        long left = ts__test_fail_alloc;
        ts__test_fail_alloc = 0;
        if (left > 0) { /* fewer than k allocations: success expected */
            CHECK(st == TS_OK && c != NULL);
            ts_curve_free(c);
            break;
        }
        failed++;
        CHECKF(st == TS_ERR_NOMEM && c == NULL, "curve, allocation %ld: %d", k, (int)st);
    }
    CHECK(failed >= 1);
}

/* Overflowing control values (tiny alpha, no scheme) and subnormal widths
 * ((π/2)/h overflows) are refused: TS_ERR_NONFINITE with the interval /
 * the right point of the width. */
static void test_overflowing_controls(void)
{
    static const double x[4] = {0, 1, 2, 3}, f[4] = {1, 2, 0, 3};
    static const double x2[3] = {0, 1e-310, 1}, f2[3] = {1, 1, 3};
    for (int form = TS_FORM_PAPER; form <= TS_FORM_C1; form++) {
        ts_spline_options o;
        th_options_paper(&o);
        o.form = (ts_form)form;
        o.alpha = 1e-310;
        ts_spline *s = NULL;
        ts_error e;
        ts_status st = ts_spline_new(x, f, 4, &o, &s, &e);
        CHECKF(st == TS_ERR_CONTROL_OVERFLOW && s == NULL && e.index == 0 &&
                   e.where == TS_WHERE_INTERVAL,
               "form %d: %d index %zu", form, (int)st, e.index);
    }
    ts_spline *s = NULL;
    ts_error e;
    ts_status st = ts_spline_new(x2, f2, 3, NULL, &s, &e);
    CHECKF(st == TS_ERR_WIDTH && s == NULL && e.index == 1 && e.where == TS_WHERE_POINT, "%d index %zu",
           (int)st, e.index);
}

int main(void)
{
    TH_CASE("overflowing_controls");
    test_overflowing_controls();
    TH_CASE("nomem");
    test_nomem();
    TH_CASE("strerror");
    test_strerror();
    TH_CASE("new");
    test_new();
    TH_CASE("eval_errors");
    test_eval_errors();
    TH_CASE("slopes_compute");
    test_slopes_compute();
    TH_CASE("overflow");
    test_overflow();
    return th_report("test_errors");
}
