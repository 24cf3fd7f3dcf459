/* Internal layout shared by the library's source files.  Not installed. */
#ifndef TS_SRC_INTERNAL_H
#define TS_SRC_INTERNAL_H

#include "trigspline.h"

#include <stddef.h>

/* Construction loops that vectorise (issue 6).  With GCC on x86-64 Linux
 * they are compiled for x86-64-v4 (AVX-512), AVX2 and the baseline, one
 * picked at load time (ifunc), vectorised also at -O2, and without
 * trapping-math so that loops with selects vectorise.  Every version gives
 * the same values (bitwise: no contraction into FMA, fp-contract=off; no
 * reassociation); no floating-point exception flag is part of the library's
 * behaviour.  Loops meant to vectorise take their arrays as restrict
 * parameters (GCC 12 does not vectorise through pointers in a struct). */
#if defined(TS_VECTOR_LOOP) /* given on the command line (tests of one version) */
#elif defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__) && \
    !defined(TS_FAST_PORTABLE)
#define TS_VECTOR_LOOP                                                                   \
    __attribute__((target_clones("arch=x86-64-v4", "avx2", "default"),                 \
                   optimize("no-trapping-math", "fp-contract=off", "tree-vectorize",     \
                            "vect-cost-model=dynamic")))
#else
#define TS_VECTOR_LOOP
#endif

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
    int have_certs;      /* built with exact certificates (ts__certify_exact); not stored:
                          * ts_spline_report recomputes them, the same computation */

    double *x, *f, *d;   /* n+1: knots, values, slopes d_i (after shape adjustment) */
    double *h;           /* n: x[i+1] - x[i] */
    double *alpha, *beta;/* n */
    double *b1, *b2;     /* n: control values B1, B2 (B0 = f[i], B3 = f[i+1]) */
    double *xc1, *xc2;   /* n: geometric form abscissae X1, X2 (SPEC §4); NULL in the
                          * other forms (X1 = x_i + K_i, X2 = x_{i+1} - K_i there) */
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
/* d[p0..p1) only, the same values as ts__slopes (which checks method, periodic
 * ends and finiteness; this does not).  For construction in blocks. */
void ts__slopes_range(ts_slopes method, const double *x, const double *f, size_t np, double *d,
                      size_t p0, size_t p1);

/* ---- spline.c -------------------------------------------------------- */
/* Every allocation of the library goes through these.  Tests only: when
 * ts__test_fail_alloc > 0 it counts allocations down and the one that
 * brings it to 0 fails (to provoke TS_ERR_NOMEM).  Not thread-safe. */
#ifdef TS_TEST_HOOKS
extern long ts__test_fail_alloc;
#endif
void *ts__malloc(size_t bytes);
void *ts__calloc(size_t count, size_t size);
void ts__error_set(ts_error *err, ts_status st, size_t index, ts_where where);
/* Recompute b1, b2 (and xc1, xc2 in the geometric form) of intervals
 * i0..i1-1 from x, f, d, alpha, beta, per the form (SPEC §3, §4).  For the C¹
 * form the knots' d̂ depend on both neighbours, so callers pass the widened
 * range themselves. */
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
/* The same on any increasing knots xs[0..n] (n >= 1 intervals): the largest
 * i <= n-1 with xs[i] <= x, trying the cursor and its successor first. */
size_t ts__search(const double *xs, size_t n, double x, ts_cursor *cur);

/* ---- shape.c (SPEC §5) ----------------------------------------------- */
/* For opt->shape != TS_SHAPE_NONE: check the data against the scheme, adjust
 * slopes where the scheme needs it (zeros, monotone sign fix), set beta[] and
 * term[], has_lower/has_upper/lower/upper.  alpha[] is already filled. */
ts_status ts__shape_apply(ts_spline *sp, const ts_options *opt, ts_error *err);
/* The same in blocks (construction, issue 6): ts__shape_begin checks the
 * options and sets the boundaries (*dir: the direction of the data f[0..n],
 * monotone; f: the caller's values, sp->f need not be filled yet);
 * ts__shape_range then checks margins of intervals [i0, i1), data of points
 * [p0, p1), adjusts their slopes (d there already computed) and sets beta[],
 * term[] of [i0, i1) (d up to i1 adjusted).  Values as ts__shape_apply; an
 * error need not be the one ts__shape_apply reports first. */
ts_status ts__shape_begin(ts_spline *sp, const ts_options *opt, const double *f, int *dir,
                          ts_error *err);
ts_status ts__shape_range(ts_spline *sp, const ts_options *opt, int dir, size_t p0, size_t p1,
                          size_t i0, size_t i1, ts_error *err);

/* ---- certify.c (SPEC §5) --------------------------------------------- */
/* Exact minimum over θ in [0, π/2] of g(θ) = Σ A_l(θ) C_l − κ θ.  Returns the
 * minimum and stores its θ in *theta_min. */
double ts__trig_min(const double C[4], double kappa, double *theta_min);
/* Gap of interval i to a lower line (sign +1: min of S − L) or an upper
 * line (sign −1: min of L − S), exact; *at receives x of the minimum. */
double ts__interval_gap(const ts_spline *sp, size_t i, const ts_line *line, int sign, double *at);
/* Does certification of a spline built with opt compute the exact trig-min
 * certificates?  (Only meaningful for opt->shape != TS_SHAPE_NONE.) */
int ts__certify_exact(const ts_options *opt);
/* Certify every interval of a freshly built shape spline, raising beta_i
 * where a gap is not positive (SPEC §5); sets certified and have_certs. */
ts_status ts__certify_build(ts_spline *sp, const ts_options *opt, ts_error *err);
/* The same in blocks (paper and geometric forms only, where every interval is
 * certified on its own; TS_ERR_OPTION for the C¹ form): ts__certify_range
 * certifies intervals [i0, i1) (their controls set), in order; after the last
 * block ts__certify_done sets certified and have_certs. */
ts_status ts__certify_range(ts_spline *sp, const ts_options *opt, size_t i0, size_t i1,
                            ts_error *err);
void ts__certify_done(ts_spline *sp, const ts_options *opt);

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
