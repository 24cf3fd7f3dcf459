/* The WebAssembly face of libtrigspline: the option structs of trigspline.h
 * flattened into plain arguments, and reports into rows of doubles, so the
 * JavaScript wrapper (trigspline.js) never depends on a struct layout.  No
 * numerics here: every call goes straight to the library. */
#define _DEFAULT_SOURCE /* sbrk */
#include "trigspline.h"

#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <unistd.h>

/* The wrapper reads ts_error as three 32-bit words: status, index, where. */
_Static_assert(sizeof(ts_error) == 12 && offsetof(ts_error, index) == 4 &&
                   offsetof(ts_error, where) == 8 && sizeof(size_t) == 4,
               "ts_error is read as three 32-bit words");

/* Doubles per report row (tsw_report_row). */
#define TSW_ROW 17

ts_status tsw_spline_new(const double *x, const double *f, size_t n, int form, int slopes,
                         const double *user_slopes, size_t n_user, double alpha,
                         const double *alphas, size_t n_alphas, double beta, const double *betas,
                         size_t n_betas, int shape, double lm, double lc, double um, double uc,
                         double margin, const double *margins, size_t n_margins, int certify,
                         int extrap, ts_spline **out, ts_error *err);
ts_status tsw_curve_new(const double *pts, size_t n, size_t dim, int param, int closed,
                        int slopes, double alpha, const double *alphas, size_t n_alphas,
                        double beta, const double *betas, size_t n_betas, const double *box,
                        double margin, ts_curve **out, ts_error *err);
void tsw_defaults(double *out);
void tsw_curve_defaults(double *out);
void tsw_constraints(const double *rec, size_t n, const double *pts);
ts_status tsw_constraint_report(const ts_spline *s, size_t k, size_t i, double *out);
ts_status tsw_report(const ts_spline *s, size_t i, double *row);
ts_status tsw_certify(const ts_spline *s, int has_lower, double lm, double lc, int has_upper,
                      double um, double uc, double *rows, ts_error *err);
ts_status tsw_curve_certify(const ts_curve *c, const double *box, double *rows, ts_error *err);
ts_status tsw_error_constants(int form, double a, double *out);
size_t tsw_heap_top(void);
int tsw_simd(void);
const char *tsw_message(void);
void tsw_message_clear(void);

/* The sentence (ts_error_message) of the last failed tsw_spline_new,
 * tsw_curve_new or tsw_disaggregate (its bins refused), written there with the call's data and options; "" after
 * tsw_message_clear.  Other failures have no context: the wrapper calls
 * ts_error_message itself. */
static char message[1024];

const char *tsw_message(void)
{
    return message;
}

void tsw_message_clear(void)
{
    message[0] = '\0';
}

/* ts_interval_report -> TSW_ROW doubles: x0 x1 alpha beta a B0..B3 term
 * has_lower has_upper gap_lower at_lower gap_upper at_upper certified. */
static void put_row(const ts_interval_report *r, double *row)
{
    row[0] = r->x0;
    row[1] = r->x1;
    row[2] = r->alpha;
    row[3] = r->beta;
    row[4] = r->a;
    for (int l = 0; l < 4; l++)
        row[5 + l] = r->B[l];
    row[9] = (double)r->term;
    row[10] = (double)r->has_lower;
    row[11] = (double)r->has_upper;
    row[12] = r->gap_lower;
    row[13] = r->at_lower;
    row[14] = r->gap_upper;
    row[15] = r->at_upper;
    row[16] = (double)r->certified;
}

/* Constraint records for the next tsw_spline_new (docs/method.md §13): rec
 * holds 5 doubles per record (kind, value, first, count, n_poly), pts the
 * polylines' x then y, record after record; taken by that one call.  n_poly
 * −1: a bound spline (§13.7), value its ts_spline pointer (a wasm32
 * address, exact in a double). */
static const double *con_rec, *con_pts;
static size_t con_n;
void tsw_constraints(const double *rec, size_t n, const double *pts)
{
    con_rec = rec;
    con_n = n;
    con_pts = pts;
}

/* The report of record k on interval i: out[5] = in_scope, active, gap, at,
 * certified. */
ts_status tsw_constraint_report(const ts_spline *s, size_t k, size_t i, double *out)
{
    ts_constraint_report r;
    ts_constraint_report_init(&r);
    ts_status st = ts_spline_constraint_report(s, k, i, &r);
    out[0] = r.in_scope;
    out[1] = r.active;
    out[2] = r.gap;
    out[3] = r.at;
    out[4] = r.certified;
    return st;
}

ts_status tsw_spline_new(const double *x, const double *f, size_t n, int form, int slopes,
                         const double *user_slopes, size_t n_user, double alpha,
                         const double *alphas, size_t n_alphas, double beta, const double *betas,
                         size_t n_betas, int shape, double lm, double lc, double um, double uc,
                         double margin, const double *margins, size_t n_margins, int certify,
                         int extrap, ts_spline **out, ts_error *err)
{
    ts_constraint cons[64];
    size_t nc = con_n < 64 ? con_n : 64;
    const double *pts = con_pts;
    for (size_t k = 0; k < nc; k++) {
        const double *r = con_rec + 5 * k;
        ts_constraint_init(&cons[k], (ts_constraint_kind)r[0]);
        cons[k].value = r[1];
        cons[k].first = (size_t)r[2];
        cons[k].count = (size_t)r[3];
        if (r[4] < 0) {
            cons[k].bound = TS_BOUND_SPLINE;
            cons[k].spline = (const ts_spline *)(uintptr_t)r[1];
            cons[k].value = 0.0;
        } else if (r[4] > 0) {
            cons[k].bound = TS_BOUND_POLYLINE;
            cons[k].n_poly = (size_t)r[4];
            cons[k].px = pts;
            cons[k].py = pts + cons[k].n_poly;
            pts += 2 * cons[k].n_poly;
        }
    }
    con_n = 0;
    ts_spline_options o;
    ts_spline_options_init(&o);
    o.form = (ts_form)form;
    o.slopes = (ts_slopes)slopes;
    o.user_slopes = user_slopes;
    o.n_user_slopes = n_user;
    o.alpha = alpha;
    o.alphas = alphas;
    o.n_alphas = n_alphas;
    o.beta = beta;
    o.betas = betas;
    o.n_betas = n_betas;
    o.shape = (ts_shape)shape;
    o.lower.m = lm;
    o.lower.c = lc;
    o.upper.m = um;
    o.upper.c = uc;
    o.margin = margin;
    o.margins = margins;
    o.n_margins = n_margins;
    o.certify = certify;
    o.extrapolate = (ts_extrap)extrap;
    o.constraints = nc ? cons : NULL;
    o.n_constraints = nc;
    ts_status st = ts_spline_new(x, f, n, &o, out, err);
    if (st != TS_OK && err) {
        ts_error_context ctx;
        ts_error_context_init(&ctx);
        ctx.x = x;
        ctx.f = f;
        ctx.n_points = n;
        ctx.spline_options = &o;
        ts_error_message(err, &ctx, message, sizeof message);
    }
    return st;
}

/* box: 12 doubles, has_lo[3] lo[3] has_hi[3] hi[3] (has_*: nonzero = active);
 * NULL = no box. */
ts_status tsw_curve_new(const double *pts, size_t n, size_t dim, int param, int closed,
                        int slopes, double alpha, const double *alphas, size_t n_alphas,
                        double beta, const double *betas, size_t n_betas, const double *box,
                        double margin, ts_curve **out, ts_error *err)
{
    ts_curve_options o;
    ts_curve_options_init(&o);
    o.param = (ts_param)param;
    o.closed = closed;
    o.slopes = (ts_slopes)slopes;
    o.alpha = alpha;
    o.alphas = alphas;
    o.n_alphas = n_alphas;
    o.beta = beta;
    o.betas = betas;
    o.n_betas = n_betas;
    o.margin = margin;
    for (int k = 0; box && k < 3; k++) {
        o.has_lo[k] = box[k] != 0.0;
        o.lo[k] = box[3 + k];
        o.has_hi[k] = box[6 + k] != 0.0;
        o.hi[k] = box[9 + k];
    }
    ts_status st = ts_curve_new(pts, n, dim, &o, out, err);
    if (st != TS_OK && err) {
        ts_error_context ctx;
        ts_error_context_init(&ctx);
        ctx.points = pts;
        ctx.n_points = n;
        ctx.dim = dim;
        ctx.curve_options = &o;
        ts_error_message(err, &ctx, message, sizeof message);
    }
    return st;
}

/* The library's defaults: form slopes alpha beta shape margin certify extrapolate. */
void tsw_defaults(double *out)
{
    ts_spline_options o;
    ts_spline_options_init(&o);
    out[0] = (double)o.form;
    out[1] = (double)o.slopes;
    out[2] = o.alpha;
    out[3] = o.beta;
    out[4] = (double)o.shape;
    out[5] = o.margin;
    out[6] = (double)o.certify;
    out[7] = (double)o.extrapolate;
}

/* param closed slopes alpha beta margin */
void tsw_curve_defaults(double *out)
{
    ts_curve_options o;
    ts_curve_options_init(&o);
    out[0] = (double)o.param;
    out[1] = (double)o.closed;
    out[2] = (double)o.slopes;
    out[3] = o.alpha;
    out[4] = o.beta;
    out[5] = o.margin;
}

ts_status tsw_report(const ts_spline *s, size_t i, double *row)
{
    ts_interval_report r = TS_INTERVAL_REPORT_INIT;
    ts_status st = ts_spline_report(s, i, &r);
    if (st == TS_OK)
        put_row(&r, row);
    return st;
}

/* rows: TSW_ROW * ts_spline_intervals(s) doubles (may be NULL). */
ts_status tsw_certify(const ts_spline *s, int has_lower, double lm, double lc, int has_upper,
                      double um, double uc, double *rows, ts_error *err)
{
    ts_line lo = {lm, lc}, hi = {um, uc};
    size_t n = s ? ts_spline_intervals(s) : 0;
    ts_interval_report *r = NULL;
    if (rows && n) {
        r = malloc(n * sizeof *r); /* n * sizeof: bounded by the spline's own arrays */
        if (!r)
            return TS_ERR_NOMEM;
        ts_interval_report_init(r, n);
    }
    ts_status st = ts_spline_certify(s, has_lower ? &lo : NULL, has_upper ? &hi : NULL, r, err);
    for (size_t i = 0; r && i < n; i++)
        put_row(&r[i], rows + i * TSW_ROW);
    free(r);
    return st;
}

/* box as for tsw_curve_new, or NULL: the curve's own box.  rows: TSW_ROW *
 * segments * dim doubles (may be NULL). */
ts_status tsw_curve_certify(const ts_curve *c, const double *box, double *rows, ts_error *err)
{
    size_t n = c ? ts_curve_segments(c) * ts_curve_dim(c) : 0;
    ts_interval_report *r = NULL;
    if (rows && n) {
        r = malloc(n * sizeof *r);
        if (!r)
            return TS_ERR_NOMEM;
        ts_interval_report_init(r, n);
    }
    ts_status st;
    if (box) {
        int hl[3], hh[3];
        for (int k = 0; k < 3; k++) {
            hl[k] = box[k] != 0.0;
            hh[k] = box[6 + k] != 0.0;
        }
        st = ts_curve_certify_box(c, hl, box + 3, hh, box + 9, r, err);
    } else {
        st = ts_curve_certify(c, r, err);
    }
    for (size_t i = 0; r && i < n; i++)
        put_row(&r[i], rows + i * TSW_ROW);
    free(r);
    return st;
}

/* first line second */
ts_status tsw_error_constants(int form, double a, double *out)
{
    ts_error_constants c = {(double)NAN, (double)NAN, (double)NAN};
    ts_status st = ts_error_constants_get((ts_form)form, a, &c);
    out[0] = c.first;
    out[1] = c.line;
    out[2] = c.second;
    return st;
}

/* The top of the malloc heap, for the leak test (create/free cycles must not
 * move it). */
size_t tsw_heap_top(void)
{
    return (size_t)(uintptr_t)sbrk(0);
}

/* 1 in the module compiled with -msimd128 (trigspline-simd.wasm), 0 in the
 * scalar one (Makefile, target web). */
int tsw_simd(void)
{
#if defined(__wasm_simd128__)
    return 1;
#else
    return 0;
#endif
}

/* ---- rates from bin totals (docs/method.md §12) ---------------------- */
void tsw_histo_defaults(double *out);
ts_status tsw_disaggregate(const double *edges, const double *totals, size_t n, const double *grid,
                           size_t m, int kind, double alpha, double lo, double hi, double *out,
                           ts_error *err);

/* alpha, lo, hi of ts_histo_options_init */
void tsw_histo_defaults(double *out)
{
    ts_histo_options o;
    ts_histo_options_init(&o);
    out[0] = o.alpha;
    out[1] = o.lo;
    out[2] = o.hi;
}

/* One call: the rate of n bins, then on the m grid points either the
 * m − 1 cell totals (kind 0), the rate (1) or its derivative (2) into out
 * (m values; kind 0 writes m − 1). */
ts_status tsw_disaggregate(const double *edges, const double *totals, size_t n, const double *grid,
                           size_t m, int kind, double alpha, double lo, double hi, double *out,
                           ts_error *err)
{
    ts_histo_options o;
    ts_histo_options_init(&o);
    o.alpha = alpha;
    o.lo = lo;
    o.hi = hi;
    ts_histo *h = NULL;
    ts_status st = ts_histo_new(edges, totals, n, &o, &h, err);
    if (st != TS_OK) {
        if (err) {
            ts_error_context ctx;
            ts_error_context_init(&ctx);
            ctx.x = edges;
            ctx.f = totals;
            ctx.n_points = n + 1;
            ctx.histo_options = &o;
            ts_error_message(err, &ctx, message, sizeof message);
        }
        return st;
    }
    if (kind == 0) {
        st = ts_histo_totals(h, grid, m, out, err);
    } else {
        double *r = kind == 2 ? malloc((m ? m : 1) * sizeof *r) : out;
        st = r ? ts_histo_eval_batch(h, grid, m, r, kind == 2 ? out : NULL, err) : TS_ERR_NOMEM;
        if (kind == 2)
            free(r);
    }
    ts_histo_free(h);
    return st;
}
