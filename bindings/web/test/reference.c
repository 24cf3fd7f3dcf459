/* Reference values for the WebAssembly build (bindings/web/test/node.test.mjs):
 * fits splines and curves with the native library over a corpus (the paper's
 * tables and pseudo-random data for every form, slope method and scheme),
 * evaluates them and writes inputs and outputs, bit for bit, to a binary file
 * (little-endian; layout below).  The Node test rebuilds every case in wasm
 * and compares the bit patterns.
 *
 *   file   = "TSREF1\0\0" u32 count, then count cases
 *   spline = u32 0, u32 form slopes shape extrap, u32 n, f64 alpha beta margin
 *            lm lc um uc, f64 x[n] f[n], u32 status index, and when status is 0:
 *            u32 m, f64 xq[m], f64 scalar[3m] (y dy d2y of ts_spline_eval_deriv per query;
 *            NaN where it fails), f64 batch[3m] (ts_spline_eval_batch deriv 0, 1, 2),
 *            f64 report[17 (n-1)] (ts_spline_report rows, glue.c's order)
 *   curve  = u32 1, u32 param closed slopes, u32 n, f64 alpha beta margin,
 *            f64 box[12] (glue.c's order), f64 pts[2n], u32 status index, and when
 *            status is 0: u32 m, f64 t[m], f64 eval[6m] (p, dp, d2p)
 *   sorted = u32 2, u32 form, u32 n, f64 x[n] f[n] (the positive scheme, other
 *            options the defaults), u32 status, then u32 sets and per set: u32
 *            spread m, f64 batch[3m] (ts_spline_eval_batch deriv 0, 1, 2) of the m
 *            sorted queries sorted_query(spread, j, m) (computed, not stored:
 *            the same operations in node.test.mjs), the batch kernel's sorted
 *            path, dense and sparse blocks
 * Usage: reference OUT.bin
 *        reference --strerror   (code TAB ts_strerror(code), one line per code and
 *                               one unknown code) */
#include "trigspline.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define NQ 4000 /* queries per case */
#define MAXN 64

static FILE *out;
static uint64_t rng_state = 0x9e3779b97f4a7c15ULL;

static double uniform(void) /* splitmix64 -> [0, 1) */
{
    uint64_t z = (rng_state += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    z ^= z >> 31;
    return (double)(z >> 11) * 0x1.0p-53;
}

static void u32(uint32_t v) { fwrite(&v, 4, 1, out); }
static void f64s(const double *v, size_t n) { fwrite(v, 8, n, out); }
static void f64(double v) { fwrite(&v, 8, 1, out); }

static void report_row(const ts_interval_report *r)
{
    double row[17] = {r->x0, r->x1, r->alpha, r->beta, r->a, r->B[0], r->B[1], r->B[2], r->B[3],
                      (double)r->term, (double)r->has_lower, (double)r->has_upper, r->gap_lower,
                      r->at_lower, r->gap_upper, r->at_upper, (double)r->certified};
    f64s(row, 17);
}

static void spline_case(int form, int slopes, int shape, int extrap, size_t n, double alpha,
                        double beta, double margin, ts_line lo, ts_line hi, const double *x,
                        const double *f)
{
    ts_spline_options o;
    ts_spline_options_init(&o);
    o.form = (ts_form)form;
    o.slopes = (ts_slopes)slopes;
    o.shape = (ts_shape)shape;
    o.extrapolate = (ts_extrap)extrap;
    o.alpha = alpha;
    o.beta = beta;
    o.margin = margin;
    o.lower = lo;
    o.upper = hi;
    ts_spline *s = NULL;
    ts_error e;
    ts_status st = ts_spline_new(x, f, n, &o, &s, &e);
    u32(0);
    u32((uint32_t)form), u32((uint32_t)slopes), u32((uint32_t)shape), u32((uint32_t)extrap);
    u32((uint32_t)n);
    double p[7] = {alpha, beta, margin, lo.m, lo.c, hi.m, hi.c};
    f64s(p, 7);
    f64s(x, n);
    f64s(f, n);
    u32((uint32_t)st);
    u32((uint32_t)e.index);
    if (st != TS_OK)
        return;
    static double xq[NQ], val[3 * NQ], bat[3 * NQ];
    double span = x[n - 1] - x[0], pad = extrap ? 0.1 * span : 0.0;
    for (size_t j = 0; j < NQ; j++)
        xq[j] = j < n ? x[j] : x[0] - pad + (span + 2 * pad) * uniform();
    ts_cursor cur = TS_CURSOR_INIT;
    for (size_t j = 0; j < NQ; j++)
        (void)ts_spline_eval_deriv(s, xq[j], &cur, &val[3 * j], &val[3 * j + 1], &val[3 * j + 2]);
    for (int d = 0; d < 3; d++)
        (void)ts_spline_eval_batch(s, d, xq, NQ, bat + (size_t)d * NQ, NULL, &e);
    u32(NQ);
    f64s(xq, NQ);
    f64s(val, 3 * NQ);
    f64s(bat, 3 * NQ);
    for (size_t i = 0; i + 1 < n; i++) {
        ts_interval_report r = TS_INTERVAL_REPORT_INIT;
        (void)ts_spline_report(s, i, &r);
        report_row(&r);
    }
    ts_spline_free(s);
}

static void curve_case(int param, int closed, int slopes, size_t n, double alpha, double beta,
                       const double box[12], const double *pts)
{
    ts_curve_options o;
    ts_curve_options_init(&o);
    o.param = (ts_param)param;
    o.closed = closed;
    o.slopes = (ts_slopes)slopes;
    o.alpha = alpha;
    o.beta = beta;
    for (int k = 0; k < 3; k++) {
        o.has_lo[k] = box[k] != 0.0;
        o.lo[k] = box[3 + k];
        o.has_hi[k] = box[6 + k] != 0.0;
        o.hi[k] = box[9 + k];
    }
    ts_curve *c = NULL;
    ts_error e;
    ts_status st = ts_curve_new(pts, n, 2, &o, &c, &e);
    u32(1);
    u32((uint32_t)param), u32((uint32_t)closed), u32((uint32_t)slopes);
    u32((uint32_t)n);
    f64(alpha), f64(beta), f64(o.margin);
    f64s(box, 12);
    f64s(pts, 2 * n);
    u32((uint32_t)st);
    u32((uint32_t)e.index);
    if (st != TS_OK)
        return;
    const double *t = ts_curve_knots(c);
    double t0 = t[0], t1 = t[ts_curve_segments(c)];
    static double tq[NQ], v[6 * NQ];
    ts_cursor cur = TS_CURSOR_INIT;
    for (size_t j = 0; j < NQ; j++) {
        tq[j] = t0 + (t1 - t0) * uniform();
        (void)ts_curve_eval(c, tq[j], &cur, &v[6 * j], &v[6 * j + 2], &v[6 * j + 4]);
    }
    u32(NQ);
    f64s(tq, NQ);
    f64s(v, 6 * NQ);
    ts_curve_free(c);
}

/* Sorted queries over [x0, x1]: spread 0 evenly, (j + 1/2)/m of the way;
 * spread 1 crowded at x0, the cube of that fraction (dense blocks there,
 * sparse ones towards x1). */
static double sorted_query(int spread, size_t j, size_t m, double x0, double x1)
{
    double t = ((double)j + 0.5) / (double)m;
    return x0 + (spread ? t * t * t : t) * (x1 - x0);
}

#define NSORTED 4000 /* knots of a sorted case */
static void sorted_case(int form, const double *x, const double *f)
{
    static const size_t sizes[][2] = {{0, 200000}, {0, 10000}, {1, 100000}};
    ts_spline_options o;
    ts_spline_options_init(&o);
    o.form = (ts_form)form;
    o.shape = TS_SHAPE_POSITIVE;
    ts_spline *s = NULL;
    ts_status st = ts_spline_new(x, f, NSORTED, &o, &s, NULL);
    u32(2), u32((uint32_t)form), u32(NSORTED);
    f64s(x, NSORTED);
    f64s(f, NSORTED);
    u32((uint32_t)st);
    if (st != TS_OK)
        return;
    u32(3);
    static double xq[200000], y[3 * 200000];
    for (size_t k = 0; k < 3; k++) {
        int spread = (int)sizes[k][0];
        size_t m = sizes[k][1];
        for (size_t j = 0; j < m; j++)
            xq[j] = sorted_query(spread, j, m, x[0], x[NSORTED - 1]);
        for (int d = 0; d < 3; d++)
            (void)ts_spline_eval_batch(s, d, xq, m, y + (size_t)d * m, NULL, NULL);
        u32((uint32_t)spread), u32((uint32_t)m);
        f64s(y, 3 * m);
    }
    ts_spline_free(s);
}

/* Random data suited to a scheme: lo/hi lines given for above/below/between. */
static void make_data(int shape, size_t n, double *x, double *f, ts_line lo, ts_line hi)
{
    x[0] = 10.0 * uniform() - 5.0;
    for (size_t i = 1; i < n; i++)
        x[i] = x[i - 1] + 0.05 + 2.0 * uniform();
    double acc = 0.0;
    for (size_t i = 0; i < n; i++) {
        double u = uniform(), L = lo.m * x[i] + lo.c, H = hi.m * x[i] + hi.c;
        switch (shape) {
        case TS_SHAPE_POSITIVE: f[i] = u < 0.15 ? 0.0 : exp(4.0 * uniform() - 3.0); break;
        case TS_SHAPE_ABOVE: f[i] = L + exp(3.0 * u - 2.5); break;
        case TS_SHAPE_BELOW: f[i] = H - exp(3.0 * u - 2.5); break;
        case TS_SHAPE_BETWEEN: f[i] = L + (H - L) * (0.03 + 0.94 * u); break;
        case TS_SHAPE_MONOTONE: acc += u < 0.2 ? 0.0 : exp(2.0 * uniform() - 1.0); f[i] = acc; break;
        default: f[i] = 4.0 * u - 2.0; break;
        }
    }
}

int main(int argc, char **argv)
{
    if (argc == 2 && strcmp(argv[1], "--strerror") == 0) {
        for (int c = 0; c <= TS_STATUS_COUNT_; c++)
            printf("%d\t%s\n", c, ts_strerror((ts_status)c));
        return 0;
    }
    if (argc != 2) {
        fprintf(stderr, "usage: reference OUT.bin\n");
        return 2;
    }
    out = fopen(argv[1], "wb");
    if (!out) {
        perror(argv[1]);
        return 1;
    }
    fwrite("TSREF1\0\0", 1, 8, out);
    long count_at = ftell(out);
    u32(0);
    uint32_t count = 0;
    double x[MAXN], f[MAXN];
    ts_line lo = {0.1, -1.0}, hi = {0.1, 2.0};
    for (int form = 0; form < 3; form++)
        for (int slopes = 0; slopes < 6; slopes++)
            for (int shape = 0; shape < 6; shape++) {
                size_t n = 5 + (size_t)(35.0 * uniform());
                make_data(shape, n, x, f, lo, hi);
                double alpha = 0.05 + 2.0 * uniform(), beta = shape ? 0.0 : 2.0 * uniform();
                int extrap = shape == 0 ? (slopes % 4) : 0;
                spline_case(form, slopes, shape, extrap, n, alpha, beta, TS_DEFAULT_MARGIN, lo,
                            hi, x, f);
                count++;
            }
    /* the paper's tables (data/paper, docs/method.md §10) with the paper's parameters */
    static const double t1x[] = {0, 2, 3, 5, 15, 25, 27, 28, 30},
                        t1f[] = {2, 1.58, 1.55, 1.54, 1.8, 1.54, 1.55, 1.58, 2};
    static const double t2x[] = {1, 2, 3, 9, 12, 14, 15}, t2f[] = {0.5, 3, 5, 25, 8, 2, 1};
    static const double t3x[] = {0, 0.4, 2, 3, 5}, t3f[] = {1.2, 0.5, 2, 5, 0.5};
    static const double t4x[] = {0, 1, 2, 4, 5, 6, 8}, t4f[] = {2.5, 7, 8, 29, 8, 21, 30};
    ts_line l2 = {0.03, 0.3}, l3 = {1, 2.5}, l4lo = {1, 0.1}, l4hi = {8, 6};
    for (int form = 0; form < 3; form++) {
        spline_case(form, 0, TS_SHAPE_POSITIVE, 0, 9, 0.15, 0, TS_DEFAULT_MARGIN, lo, hi, t1x, t1f);
        spline_case(form, 0, TS_SHAPE_NONE, 0, 9, 1.4, 1.9, TS_DEFAULT_MARGIN, lo, hi, t1x, t1f);
        spline_case(form, 0, TS_SHAPE_ABOVE, 0, 7, 0.01, 0, TS_DEFAULT_MARGIN, l2, hi, t2x, t2f);
        spline_case(form, 0, TS_SHAPE_BELOW, 0, 5, 0.001, 0, TS_DEFAULT_MARGIN, lo, l3, t3x, t3f);
        spline_case(form, 0, TS_SHAPE_BETWEEN, 0, 7, 0.1, 0, TS_DEFAULT_MARGIN, l4lo, l4hi, t4x,
                    t4f);
        count += 5;
    }
    /* infeasible or refused data: the status and index must agree too */
    {
        double xb[] = {0, 1, 2, 3}, fb[] = {1, -1, 2, 3};
        spline_case(0, 0, TS_SHAPE_POSITIVE, 0, 4, 1, 0, TS_DEFAULT_MARGIN, lo, hi, xb, fb);
        spline_case(0, 0, TS_SHAPE_MONOTONE, 0, 4, 1, 0, TS_DEFAULT_MARGIN, lo, hi, xb, fb);
        count += 2;
    }
    /* curves: the paper's closed figures, random open curves with and without a box */
    static const double fig2[] = {0, 1, 1, 4, 2, 1, 3, 4}, fig3[] = {-1, 0, 0, -1, 1, 0, 0, 1};
    double nobox[12] = {0};
    for (int p = 0; p < 3; p++) {
        curve_case(p, 1, 0, 4, 0.37, 0.01, nobox, fig2);
        curve_case(p, 1, 0, 4, 0.37, 0.05, nobox, fig3);
        count += 2;
    }
    for (int k = 0; k < 12; k++) {
        size_t n = 4 + (size_t)(20.0 * uniform());
        double pts[2 * MAXN];
        for (size_t i = 0; i < n; i++) {
            pts[2 * i] = 0.05 + 0.9 * uniform();
            pts[2 * i + 1] = 0.05 + 0.9 * uniform();
        }
        double box[12] = {1, 1, 0, 0, 0, 0, 1, 1, 0, 1, 1, 0};
        curve_case(k % 3, 0, k % 6, n, 0.2 + uniform(), 0.0, k % 2 ? box : nobox, pts);
        count++;
    }
    /* the sorted batch path of every form, on one positive data set */
    {
        static double xs[NSORTED], fs[NSORTED];
        ts_line none = {0, 0};
        make_data(TS_SHAPE_POSITIVE, NSORTED, xs, fs, none, none);
        for (int form = 0; form < 3; form++) {
            sorted_case(form, xs, fs);
            count++;
        }
    }
    fseek(out, count_at, SEEK_SET);
    u32(count);
    if (fclose(out) != 0) {
        perror(argv[1]);
        return 1;
    }
    return 0;
}
