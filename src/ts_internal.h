/* Internal layout shared by the library's source files.  Not installed. */
#ifndef TS_INTERNAL_H
#define TS_INTERNAL_H

#include "trigspline.h"

#include <stddef.h>

#define TS_PI 3.14159265358979323846
#define TS_HALF_PI 1.57079632679489661923

/* Doubles per interval reserved for fast.c's batch coefficients: none (fast.c
 * needs only x, h, f, b1, b2; every byte per knot costs construction time). */
#define TS_FAST_STRIDE 0

struct ts_spline {
    size_t n;            /* intervals */
    ts_form form;
    ts_shape shape;
    ts_extrap extrap;
    int has_lower, has_upper; /* boundaries of the shape scheme (positive: lower = 0) */
    ts_line lower, upper;
    int certified;       /* every interval certified (shape schemes) */
    int have_certs;      /* gap_* arrays hold exact certificates */

    double *x, *f, *d;   /* n+1: knots, values, slopes d_i (after shape adjustment) */
    double *h;           /* n: x[i+1] - x[i] */
    double *alpha, *beta;/* n */
    double *b1, *b2;     /* n: control values B1, B2 (B0 = f[i], B3 = f[i+1]) */
    double *xc1, *xc2;   /* n: geometric form abscissae X1, X2 (SPEC §4); else unused */
    double *gap_lo, *at_lo, *gap_up, *at_up; /* n: certificates (NaN when absent) */
    unsigned char *term; /* n: ts_term */
    double *cum;         /* n+1: cum[i] = ∫_{x0}^{x_i} S dx (set last by spline.c) */
    double *fast;        /* TS_FAST_STRIDE * n: fast.c coefficients */
};

/* ---- basis.c (SPEC §2) --------------------------------------------- */
/* Basis A0..A3 at (s, c) = (sin θ, cos θ). */
void ts__basis(double s, double c, double A[4]);
/* dA/dθ and d²A/dθ². */
void ts__basis_d1(double s, double c, double A[4]);
void ts__basis_d2(double s, double c, double A[4]);
/* ∫_0^θ A_l dθ' (θ with its sine and cosine). */
void ts__basis_int(double theta, double s, double c, double I[4]);
/* S, dS/dθ, d²S/dθ² of control values B at θ (out[0..2]; out[1], out[2]
 * computed only if want > 0, > 1). */
void ts__seg_theta(const double B[4], double theta, int want, double out[3]);
/* The same from (s, c) = (sin θ, cos θ) directly. */
void ts__seg_sc(const double B[4], double s, double c, int want, double out[3]);

/* ---- slopes.c (SPEC §6) -------------------------------------------- */
/* Unchecked: x strictly increasing and finite, np >= 2, method valid. */
ts_status ts__slopes(ts_slopes method, const double *x, const double *f, size_t np,
                     double *d, ts_error *err);

/* ---- spline.c -------------------------------------------------------- */
/* Every allocation of the library goes through these.  Tests only: when
 * ts__test_fail_alloc > 0 it counts allocations down and the one that
 * brings it to 0 fails (to provoke TS_ERR_NOMEM).  Not thread-safe. */
extern long ts__test_fail_alloc;
void *ts__malloc(size_t bytes);
void *ts__calloc(size_t count, size_t size);
void ts__error_set(ts_error *err, ts_status st, size_t index, ts_where where);
/* Recompute b1, b2 (and xc1, xc2) of intervals i0..i1-1 from x, f, d, alpha,
 * beta, per the form (SPEC §3, §4).  For the C¹ form the knots' d̂ depend on
 * both neighbours, so callers pass the widened range themselves. */
void ts__controls(ts_spline *sp, size_t i0, size_t i1);
/* The four control values of interval i. */
static inline void ts__B(const ts_spline *sp, size_t i, double B[4])
{
    B[0] = sp->f[i];
    B[1] = sp->b1[i];
    B[2] = sp->b2[i];
    B[3] = sp->f[i + 1];
}
/* Interval containing x (x already in [x0, xn]); hint may be NULL. */
size_t ts__locate(const ts_spline *sp, double x, ts_cursor *cur);

/* ---- shape.c (SPEC §5) ----------------------------------------------- */
/* For opt->shape != TS_SHAPE_NONE: check the data against the scheme, adjust
 * slopes where the scheme needs it (zeros, monotone sign fix), set beta[] and
 * term[], has_lower/has_upper/lower/upper.  alpha[] is already filled. */
ts_status ts__shape_apply(ts_spline *sp, const ts_options *opt, ts_error *err);

/* ---- certify.c (SPEC §5) --------------------------------------------- */
/* Exact minimum over θ in [0, π/2] of g(θ) = Σ A_l(θ) C_l − κ θ.  Returns the
 * minimum and stores its θ in *theta_min. */
double ts__trig_min(const double C[4], double kappa, double *theta_min);
/* Gap of interval i to a lower line (sign +1: min of S − L) or an upper
 * line (sign −1: min of L − S), exact; *at receives x of the minimum. */
double ts__interval_gap(const ts_spline *sp, size_t i, const ts_line *line, int sign, double *at);
/* Certify every interval of a freshly built shape spline, raising beta_i
 * where a gap is not positive (SPEC §5), filling gap_* / at_* and certified. */
ts_status ts__certify_build(ts_spline *sp, const ts_options *opt, ts_error *err);

/* ---- geometric.c (SPEC §4) ------------------------------------------- */
/* Called by ts_spline_new for TS_FORM_GEOMETRIC after beta[] is set and before
 * ts__controls: enforce the bound on a_i of SPEC §4 (raise beta_i or fail). */
ts_status ts__geo_check(ts_spline *sp, const ts_options *opt, ts_error *err);
/* Value and derivatives in x of interval i of a geometric-form spline at x. */
void ts__geo_eval(const ts_spline *sp, size_t i, double x, int want, double out[3]);
/* ∫_{x_i}^{x} S dx' on interval i (x in the interval). */
double ts__geo_integral(const ts_spline *sp, size_t i, double x);

/* ---- fast.c (batch kernels) ------------------------------------------ */
void ts__fast_prepare(ts_spline *sp);
/* Queries are taken in blocks of TS_FAST_BLOCK. */
#define TS_FAST_BLOCK 128
/* Evaluate a prefix of xq[0..m) (any order) and return its length k: all of
 * them when every query is inside [x0, xn]; else it stops before the first
 * block holding a query outside or NaN (so xq[k..k+TS_FAST_BLOCK) holds one)
 * and the caller handles that block.  cur (may be NULL) ends on the interval
 * of query k-1. */
size_t ts__fast_batch(const ts_spline *sp, int deriv, const double *xq, size_t m,
                      double *yq, ts_cursor *cur);
/* The same with a chosen kernel (tests, bench): isa 0 portable C, 1 x86-64
 * AVX2+FMA, 2 AVX-512F (-1 the best).  Returns 0 (and does nothing) if that
 * kernel is not available here, else 1 (*done, if not NULL, receives k). */
int ts__fast_batch_isa(const ts_spline *sp, int deriv, const double *xq, size_t m,
                       double *yq, ts_cursor *cur, int isa, size_t *done);

#endif
