/* "The library never allocates while evaluating": every allocation of the
 * test program, libtrigspline included, goes through --wrap'ed malloc, calloc,
 * realloc, aligned_alloc and posix_memalign (see CMakeLists.txt), which count
 * while `counting` is set.  Splines and curves of every form and scheme are
 * built first, then every evaluation, report and certificate function is
 * called; the count must stay 0.  ts_spline_eval_batch_mt is the documented
 * exception (it creates threads) and is not called here. */
#include "th.h"
#include "trigspline.h"

#include <stddef.h>

void *__real_malloc(size_t n);
void *__real_calloc(size_t a, size_t b);
void *__real_realloc(void *p, size_t n);
void *__real_aligned_alloc(size_t al, size_t n);
int __real_posix_memalign(void **p, size_t al, size_t n);
void *__wrap_malloc(size_t n);
void *__wrap_calloc(size_t a, size_t b);
void *__wrap_realloc(void *p, size_t n);
void *__wrap_aligned_alloc(size_t al, size_t n);
int __wrap_posix_memalign(void **p, size_t al, size_t n);

static volatile int counting;
static volatile long allocations;

void *__wrap_malloc(size_t n) { if (counting) allocations++; return __real_malloc(n); }
void *__wrap_calloc(size_t a, size_t b) { if (counting) allocations++; return __real_calloc(a, b); }
void *__wrap_realloc(void *p, size_t n) { if (counting) allocations++; return __real_realloc(p, n); }
void *__wrap_aligned_alloc(size_t al, size_t n) { if (counting) allocations++; return __real_aligned_alloc(al, n); }
int __wrap_posix_memalign(void **p, size_t al, size_t n) { if (counting) allocations++; return __real_posix_memalign(p, al, n); }

#define NP 40
#define NQ 3000

static double xq[NQ], yq[NQ];

static void exercise(const ts_spline *s, const ts_line *lo, const ts_line *up)
{
    const double *x = ts_spline_x(s);
    size_t n = ts_spline_intervals(s);
    double a = x[0], b = x[n], v, dv, d2v;
    ts_cursor cur = TS_CURSOR_INIT;
    ts_error err;
    ts_interval_report rep[NP];
    ts_interval_report_init(rep, sizeof rep / sizeof rep[0]);
    for (int j = 0; j < NQ; j++) /* sorted, then a scrambled tail, some outside */
        xq[j] = j < NQ / 2 ? a + (b - a) * j / (NQ / 2 - 1) : a - 1 + (b - a + 2) * ((j * 7919) % NQ) / NQ;
    xq[NQ - 1] = TH_NAN;
    counting = 1;
    for (int j = 0; j < NQ; j += 7) {
        (void)ts_spline_eval(s, xq[j], &cur, &v);
        (void)ts_spline_eval_deriv(s, xq[j], NULL, &v, &dv, &d2v);
    }
    for (int dd = 0; dd < 3; dd++) {
        (void)ts_spline_eval_batch(s, dd, xq, NQ, yq, &cur, &err);
        (void)ts_spline_eval_batch(s, dd, xq, NQ / 2, yq, NULL, NULL);
    }
    (void)ts_spline_integral(s, a, b, &v);
    (void)ts_spline_integral(s, b - 0.3 * (b - a), a + 0.1, &v);
    /* every order and per-call extrapolation, solve, the interval search */
    for (int nu = 0; nu <= 5; nu++) {
        (void)ts_spline_eval_batch(s, nu, xq, NQ, yq, &cur, &err);
        for (int ex = TS_EXTRAP_ERROR; ex <= TS_EXTRAP_LINEAR; ex++) {
            (void)ts_spline_eval_batch_mode(s, nu, (ts_extrap)ex, xq, NQ, yq, &cur, &err);
            for (int j = 0; j < NQ; j += 31)
                (void)ts_spline_eval_mode(s, xq[j], nu, (ts_extrap)ex, &cur, &v);
        }
    }
    for (int j = 0; j < NQ; j += 13) {
        size_t iv;
        (void)ts_spline_find_interval(s, xq[j], &cur, &iv);
    }
    for (int k = 0; k <= 20; k++) {
        size_t cnt;
        double fa = ts_spline_f(s)[0], fb = ts_spline_f(s)[n];
        (void)ts_spline_solve(s, fa + (fb - fa) * k / 20.0 + 0.3 * (k % 3), yq, NQ, &cnt);
        (void)ts_spline_solve(s, fa, NULL, 0, &cnt);
    }
    for (size_t i = 0; i < n; i++) {
        double B[4], X[4];
        (void)ts_spline_report(s, i, &rep[i]);
        (void)ts_spline_control(s, i, B, X);
        (void)ts_spline_a(s, i, &v);
    }
    (void)ts_spline_certified(s);
    if (lo || up)
        (void)ts_spline_certify(s, lo, up, rep, &err);
    (void)ts_spline_error_bound(s, 1.0, 1.0, 0, &v, NULL);
    counting = 0;
}

int main(void)
{
    double x[NP], f[NP];
    for (int i = 0; i < NP; i++) {
        x[i] = i + 0.3 * (i % 3);
        f[i] = 2.0 + (i % 5) * 0.7 + 0.01 * i * i;
    }
    ts_line lo = {0.01, 0.5}, up = {0.3, 9.0};
    TH_CASE("splines");
    for (int form = TS_FORM_PAPER; form <= TS_FORM_GEOMETRIC; form++) {
        for (int shape = TS_SHAPE_NONE; shape <= TS_SHAPE_BETWEEN; shape++) {
            for (int ex = TS_EXTRAP_ERROR; ex <= TS_EXTRAP_LINEAR; ex++) {
                ts_spline_options o;
                ts_spline_options_init(&o);
                o.form = (ts_form)form;
                o.shape = (ts_shape)shape;
                o.extrapolate = (ts_extrap)ex;
                o.alpha = 0.5;
                o.lower = lo;
                o.upper = up;
                ts_spline *s = NULL;
                ts_status st = ts_spline_new(x, f, NP, &o, &s, NULL);
                CHECKF(st == TS_OK, "form %d shape %d: %s", form, shape, ts_strerror(st));
                if (st != TS_OK)
                    continue;
                allocations = 0;
                exercise(s, &lo, &up);
                CHECKF(allocations == 0, "form %d shape %d extrap %d: %ld allocations while evaluating", form,
                       shape, ex, (long)allocations);
                ts_spline_free(s);
            }
        }
    }
    /* curves, open and closed */
    TH_CASE("curves");
    double pts[2 * 12];
    for (int i = 0; i < 12; i++) {
        pts[2 * i] = cos(0.5 * i) * (2 + 0.1 * i);
        pts[2 * i + 1] = sin(0.5 * i) * (2 + 0.1 * i);
    }
    for (int closed = 0; closed < 2; closed++) {
        ts_curve_options co;
        ts_curve_options_init(&co);
        co.closed = closed;
        co.has_lo[0] = co.has_hi[0] = co.has_lo[1] = co.has_hi[1] = 1;
        co.lo[0] = co.lo[1] = -10;
        co.hi[0] = co.hi[1] = 10;
        ts_curve *c = NULL;
        ts_status st = ts_curve_new(pts, 12, 2, &co, &c, NULL);
        CHECK(st == TS_OK);
        if (st != TS_OK)
            continue;
        static double buf[3 * 2000];
        double p[3], dp[3], d2p[3], len;
        size_t rows;
        ts_interval_report rep[2 * 13];
        ts_interval_report_init(rep, 2 * 13);
        ts_error err;
        allocations = 0;
        counting = 1;
        for (int j = 0; j < 200; j++)
            (void)ts_curve_eval(c, 0.05 * j, NULL, p, dp, d2p);
        (void)ts_curve_sample(c, 20, buf, sizeof buf / sizeof buf[0], &rows);
        (void)ts_curve_length(c, 1e-12, &len);
        (void)ts_curve_certify(c, rep, &err);
        for (size_t i = 0; i < ts_curve_segments(c); i++) {
            double ctrl[8], al, be;
            (void)ts_curve_control(c, i, ctrl);
            (void)ts_curve_params(c, i, &al, &be);
        }
        counting = 0;
        CHECKF(allocations == 0, "curve closed=%d: %ld allocations while evaluating", closed, (long)allocations);
        ts_curve_free(c);
    }
    TH_CASE("surfaces between gridded fields");
    for (int form = TS_FORM_PAPER; form <= TS_FORM_GEOMETRIC; form++) {
        static const double sx[4] = {0, 1, 2, 3}, fx[3] = {-1, 1.5, 4};
        double sz[16], lz[9], uz[9];
        for (int k = 0; k < 16; k++)
            sz[k] = 1.0 + 0.25 * ((k * 7) % 5);
        for (int k = 0; k < 9; k++) {
            lz[k] = -0.5 - 0.125 * (k % 3);
            uz[k] = 3.5 + 0.25 * (k % 2);
        }
        ts_surface_options so;
        ts_surface_options_init(&so);
        so.form = (ts_form)form;
        so.shape = TS_SURFACE_GRIDS;
        so.has_lower = so.has_upper = 1;
        so.lower_grid = (ts_grid_bound){fx, 3, fx, 3, lz};
        so.upper_grid = (ts_grid_bound){fx, 3, fx, 3, uz};
        ts_surface *sf = NULL;
        ts_status st = ts_surface_new(sx, 4, sx, 4, sz, &so, &sf, NULL);
        CHECKF(st == TS_OK, "form %d: %s", form, ts_strerror(st));
        if (st != TS_OK)
            continue;
        static double gq[64], gout[64 * 64];
        for (int k = 0; k < 64; k++)
            gq[k] = 3.0 * k / 63;
        double v, vx, vy;
        ts_error err;
        ts_patch_report prep = TS_PATCH_REPORT_INIT;
        allocations = 0;
        counting = 1;
        for (int k = 0; k < 64; k++)
            (void)ts_surface_eval(sf, gq[k], gq[63 - k], NULL, &v, &vx, &vy);
        (void)ts_surface_eval_batch(sf, gq, gq, 64, gout, NULL, NULL, &err);
        (void)ts_surface_eval_grid(sf, gq, 64, gq, 64, gout, &err);
        (void)ts_surface_report(sf, 1, 1, &prep);
        counting = 0;
        CHECKF(allocations == 0, "surface form %d: %ld allocations while evaluating", form,
               (long)allocations);
        ts_surface_free(sf);
    }
    TH_CASE("rates from bin totals");
    {
        static const double e[7] = {0, 1, 2, 3, 4.5, 5, 6}, T[6] = {0, 3, 0, 1, 2, 0.5};
        ts_histo *h = NULL;
        CHECK(ts_histo_new(e, T, 6, NULL, &h, NULL) == TS_OK);
        static double g[121], out[6 * 24], r[121], d[121];
        for (int k = 0; k <= 120; k++)
            g[k] = 0.05 * k;
        ts_bin_report rep;
        ts_bin_report_init(&rep);
        allocations = 0;
        counting = 1;
        for (int k = 0; k <= 120; k++) {
            double a, b;
            (void)ts_histo_eval(h, g[k], &a, &b);
            (void)ts_histo_integral(h, 0.0, g[k], &a);
        }
        (void)ts_histo_eval_batch(h, g, 121, r, d, NULL);
        (void)ts_histo_totals(h, g, 121, out, NULL);
        (void)ts_histo_subdivide(h, 24, out, NULL);
        for (size_t j = 0; j < 6; j++)
            (void)ts_histo_report(h, j, &rep);
        counting = 0;
        CHECKF(allocations == 0, "histo: %ld allocations while evaluating", (long)allocations);
        ts_histo_free(h);
    }
    /* the counter itself works: a construction allocates */
    allocations = 0;
    counting = 1;
    ts_spline *s = NULL;
    (void)ts_spline_new(x, f, NP, NULL, &s, NULL);
    counting = 0;
    CHECKF(allocations > 0, "the wrapper saw no allocation in ts_spline_new (%ld)", (long)allocations);
    ts_spline_free(s);
    return th_report("test_noalloc");
}
