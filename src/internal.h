/* The library's internal header: the spline's layout and the internal
 * functions, grouped by layer.  Not installed.
 *
 * Layers (a file includes this header and trigspline.h, and calls only
 * functions of files in lower layers; no file calls a public entry point of
 * the library; scripts/check_layers.py checks both):
 *   L0  status.c    status strings, the version, the error setter, allocation
 *       checks.c    input checks shared by the constructors
 *       vocab.c     canonical names of the enum values and statuses
 *       numfmt.c    shortest round-trip decimal form of a double
 *       basis.c     the basis, its derivatives and integrals, interval search
 *       trigmin.c   exact minimum of a trigonometric polynomial minus a line
 *       expansion.c exact sums and products of doubles (expansions), exact signs
 *   L1  slopes.c    slope estimates
 *       controls.c  control values of every form
 *       geometric.c the geometric form: X(θ) = x, value, integral, bound
 *       gridbound.c gridded surface bounds: bilinear value, exact side, maxima
 *   L2  interval.c  one interval of any form: value, derivatives, integral;
 *                   the per-form table (ts__form)
 *       deriv.c     derivatives of every order of one interval (paper, C¹)
 *       shape.c     the schemes' β rules and data checks
 *       certificate.c  interval gaps, hull and control-value proofs (read-only)
 *       surface_net.c  surfaces: control nets, patch bases, control gaps
 *       constrain_spline.c  a bound given by another spline: its copy, the
 *                   data's side, the certificate by subdivision, the minimum
 *   L3  kernels.c   batch evaluation kernels
 *       constrain.c constraint records: conditions, slopes, a_i, certificates
 *       repair.c    certification at build time: raise β until certified
 *       surface_cert.c  surfaces: the certificate of one patch (subdivision)
 *   L4  spline.c, curve.c, eval.c, report.c, accuracy.c: the public API
 *       constraint.c: the constraint records' public functions
 *       find.c, solve.c: interval search, the roots of S − y
 *       surface.c, surface_eval.c: the public surface API
 *       histo.c: rates from bin totals (the public histogram API)
 *   L5  errmsg.c    the full sentence of an error (ts_error_message)
 *   L6  deprecated.c  the 0.1 names, each calling its new public name (the
 *                     one file allowed to call public entry points) */
#ifndef TS_SRC_INTERNAL_H
#define TS_SRC_INTERNAL_H

#include "trigspline.h"

#include <float.h>
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

/* Every internal function is hidden from the shared library.  (A
 * TS_VECTOR_LOOP function must still be static: the ifunc resolver of one
 * with external linkage is exported whatever its visibility.) */
#if defined(__GNUC__)
#pragma GCC visibility push(hidden)
#endif

/* Construction loops that vectorise.  With GCC on x86-64 Linux
 * they are compiled for x86-64-v4 (AVX-512), x86-64-v3 (AVX2 with FMA, so
 * that the loops' fma() calls of docs/method.md §5.6 stay inline and
 * vectorise) and the baseline, one picked at load time (ifunc), vectorised
 * also at -O2, and without trapping-math so that loops with selects
 * vectorise.  Every version gives
 * the same values (bitwise: no contraction into FMA, fp-contract=off; no
 * reassociation).  A vector loop forms every lane's operations, also those
 * a select then discards, so those must not divide 0 by 0 or by 0 either:
 * no FE_INVALID or FE_DIVBYZERO may be raised on valid input (the header's
 * promise; tests/api/test_fenv.c, test_histo.c).  Loops meant to vectorise take their arrays as restrict
 * parameters (GCC 12 does not vectorise through pointers in a struct).
 * Not under ThreadSanitizer: the ifunc resolvers run before TSan is
 * initialised and crash (docs/design.md).  Only with glibc, whose loader
 * resolves ifuncs (IRELATIVE relocations): musl's refuses them, and a
 * musl-targeted GCC refuses target_clones (tests/test_musl.py). */
#if defined(TS_VECTOR_LOOP) /* given on the command line (tests of one version, make coverage) */
#elif defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__) && \
    defined(__GLIBC__) && !defined(TS_FAST_PORTABLE) && !defined(__SANITIZE_THREAD__)
#define TS_VECTOR_LOOP                                                                   \
    __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default"),       \
                   optimize("no-trapping-math", "fp-contract=off", "tree-vectorize",     \
                            "vect-cost-model=dynamic")))
#else
#define TS_VECTOR_LOOP
#endif

/* Small functions shared by a vector loop and a scalar path: always
 * inlined, also into the TS_VECTOR_LOOP functions (whose optimize attribute
 * would otherwise refuse an ordinary inline function).  Not in the coverage
 * build (TS_COVERAGE, with TS_VECTOR_LOOP empty): one copy per object, so
 * that gcov counts each branch once, not once per call site. */
#if defined(TS_COVERAGE)
#define TS_INLINE static inline
#elif defined(__GNUC__)
#define TS_INLINE static inline __attribute__((always_inline))
#else
#define TS_INLINE static inline
#endif

#define TS_PI 3.14159265358979323846
#define TS_HALF_PI 1.57079632679489661923

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

    /* Stored is what cannot be derived cheaply: the width h_i is
     * x[i+1] − x[i] (ts__h), bitwise what was once stored; the geometric
     * form's B1, B2 are f_i ± k_i d_i (ts__B, as controls.c forms them)
     * unless constraint records nudged them (then stored); the running
     * integral is kept at every TS_CUM_STEP-th knot (ts__cum).  The paper
     * and C¹ forms also store dθ/dx = (π/2)/h_i (w, ts__w): no division
     * in a single evaluation from the cursor's interval (sorted queries,
     * ts__trig_eval_in); the geometric form, whose bytes per knot are a
     * goal, has none. */
    double *x, *f, *d;   /* n+1: knots, values, slopes d_i (after shape adjustment) */
    double *alpha, *beta;/* n */
    double *b1, *b2;     /* n: control values B1, B2 (B0 = f[i], B3 = f[i+1]); NULL in
                          * the geometric form without constraint records (derived) */
    double *kappa;       /* n: geometric form only (NULL otherwise), κ_i = 2/(3π(α_i + β_i))
                          * (docs/method.md §4), the one expression every user of κ reads */
    double *w;           /* n: paper and C¹ forms only (NULL otherwise), w_i = (π/2)/h_i
                          * = dθ/dx (docs/method.md §2), bitwise ts__w's expression */
    unsigned char *term; /* n: ts_term */
    double *cum;         /* n/TS_CUM_STEP + 1: cum[j] = ∫_{x0}^{x_{j·TS_CUM_STEP}} S dx,
                          * the running sum of the wholes (set last by spline.c) */
    /* constraint records (docs/method.md §13), an owned copy (polyline points
     * in con_pts); NULL / 0 when built without */
    size_t ncon;
    ts_constraint *con;
    double *con_pts;
    int *con_bind;       /* n: the record whose a_i requirement was the largest, −1 none */
    int *con_by;         /* n+1: the record that changed slope d_j last, −1 none */
    ts_spline *con_spl;  /* ncon: copies of the bound splines (TS_BOUND_SPLINE; their
                          * arrays in con_pts), the stored records point to them */
};

/* A gridded bound (docs/method.md §11.7), an owned copy: nx × ny nodes
 * (points, not cells), z[j*nx + i]; err = 32 ε max|z| + 8·2⁻¹⁰⁷⁴ bounds the
 * error of ts__gb_value anywhere on it. */
typedef struct ts__gbound {
    size_t nx, ny;
    const double *x, *y, *z;
    double err;
} ts__gbound;

/* docs/method.md §11.  Node (i, j) at j*(nx+1) + i; patch (i, j) at j*nx + i. */
struct ts_surface {
    size_t nx, ny;                   /* patches along x, y */
    ts_form form;
    ts_surface_shape shape;
    int has_lower, has_upper;        /* the scheme's bounds (positive, range: constants) */
    ts_plane lower, upper;
    int certified;
    double *x, *y;                   /* nx+1, ny+1 */
    double *z, *p, *q, *r;           /* nodes: value, ∂z/∂x, ∂z/∂y, twist */
    double *ax, *ay;                 /* nx, ny */
    double *ks;                      /* each interval's k at its ends (ts__surf_ks): x's 2 nx,
                                        then y's 2 ny; the build's last, kept in its block */
    /* the control nets are derived per patch (ts__surf_patch), not stored */
    ts__gbound glo, gup;             /* TS_SURFACE_GRIDS: the fields (glo.x NULL when absent) */
    double *gblk;                    /* their owned arrays */
};

/* ==== L0 ============================================================ */

/* ---- vocab.c --------------------------------------------------------- */
/* ts_vocab_name, ts_status_name for the library's own files. */
const char *ts__vocab_name(ts_vocab vocab, int value);
const char *ts__status_name(ts_status status);

/* ---- numfmt.c -------------------------------------------------------- */
/* Room for any double in ts__format_double's form ("-1.2345678901234567e-308"). */
#define TS__NUM_SIZE 32
/* v in the shortest %g form that strtod reads back to v; "nan", "inf", "-inf". */
void ts__format_double(double v, char buf[TS__NUM_SIZE]);

/* ---- status.c -------------------------------------------------------- */
void ts__error_set(ts_error *err, ts_status st, size_t index, ts_where where);
/* ts_strerror for the library's own files. */
const char *ts__strerror(ts_status status);
/* ts__error_set, then return st. */
ts_status ts__fail(ts_error *err, ts_status st, size_t index, ts_where where);
/* Every allocation of the library goes through these.  With TS_TEST_HOOKS
 * (trigspline_internal, tests only): when ts__test_fail_alloc > 0 it counts
 * allocations down and the one that brings it to 0 fails (to provoke
 * TS_ERR_NOMEM).  Not thread-safe. */
#ifdef TS_TEST_HOOKS
extern long ts__test_fail_alloc;
#endif
/* The termination limits of the library's searches, each a safeguard the
 * tested inputs do not reach (docs/design.md, "Coverage").  The product
 * reads the constants TS_LIMIT_DEFAULT_<name>; with TS_TEST_HOOKS
 * (trigspline_internal, tests only) it reads ts__test_limits, which starts
 * at the same values and which tests/unit/test_safeguards.c lowers to
 * provoke each safeguard.  A lowered limit only ends a search sooner: the
 * buffers stay sized by the defaults.  Not thread-safe. */
#define TS_LIMIT_DEFAULT_curve_len_depth 48       /* curve.c, length bisection depth */
#define TS_LIMIT_DEFAULT_curve_len_pieces 20000   /* curve.c, pieces per segment */
#define TS_LIMIT_DEFAULT_repair_width 1e-12       /* repair.c, bisection's relative width */
#define TS_LIMIT_DEFAULT_repair_relax_steps 100   /* repair.c, relax_neighbours' bisection */
#define TS_LIMIT_DEFAULT_repair_budget_per 16     /* repair.c, repairs per interval ... */
#define TS_LIMIT_DEFAULT_repair_budget_base 64    /* ... plus these before the C¹ fallback */
#define TS_LIMIT_DEFAULT_trigmin_steps 200        /* trigmin.c, refine's iterations */
#define TS_LIMIT_DEFAULT_trigmin_depth 46         /* trigmin.c, subdivision depth */
#define TS_LIMIT_DEFAULT_surface_cert_depth 40    /* surface_cert.c, branch and bound depth */
#define TS_LIMIT_DEFAULT_surface_cert_nodes 200000 /* surface_cert.c, nodes */
#define TS_LIMIT_DEFAULT_solve_cap 64             /* solve.c, roots stored per interval */
#define TS_LIMIT_DEFAULT_solve_depth 52           /* solve.c, subdivision depth */
#define TS_LIMIT_DEFAULT_integral_steps 1152      /* eval.c, the integral's scale search */
#define TS_LIMIT_DEFAULT_con_doublings 60         /* constrain.c, doublings of a_i */
#define TS_LIMIT_DEFAULT_con_root_cap 64          /* constrain.c, candidates per minimum (ends + roots) */
#define TS_LIMIT_DEFAULT_con_root_depth 46        /* constrain.c, root isolation's subdivision depth */
#define TS_LIMIT_DEFAULT_con_root_steps 80        /* constrain.c, a root's bisection steps */
#define TS_LIMIT_DEFAULT_bcurve_cells 4096        /* constrain_spline.c, cells of a certificate */
#define TS_LIMIT_DEFAULT_bcurve_depth 48          /* constrain_spline.c, halvings of a cell */
#define TS_LIMIT_DEFAULT_bcurve_gap_steps 60      /* constrain_spline.c, the report's bisection steps */
#ifdef TS_TEST_HOOKS
typedef struct ts__limits {
    int curve_len_depth, curve_len_pieces;
    double repair_width;
    int repair_relax_steps;
    size_t repair_budget_per, repair_budget_base;
    int trigmin_steps, trigmin_depth;
    int surface_cert_depth;
    long surface_cert_nodes;
    size_t solve_cap;
    int solve_depth;
    int integral_steps;
    int con_doublings;
    int con_root_cap, con_root_depth, con_root_steps;
    int bcurve_cells, bcurve_depth, bcurve_gap_steps;
} ts__limits;
#define TS_LIMITS_DEFAULT                                                                        \
    {TS_LIMIT_DEFAULT_curve_len_depth, TS_LIMIT_DEFAULT_curve_len_pieces,                        \
     TS_LIMIT_DEFAULT_repair_width, TS_LIMIT_DEFAULT_repair_relax_steps,                         \
     TS_LIMIT_DEFAULT_repair_budget_per, TS_LIMIT_DEFAULT_repair_budget_base,                    \
     TS_LIMIT_DEFAULT_trigmin_steps, TS_LIMIT_DEFAULT_trigmin_depth,                             \
     TS_LIMIT_DEFAULT_surface_cert_depth, TS_LIMIT_DEFAULT_surface_cert_nodes,                   \
     TS_LIMIT_DEFAULT_solve_cap, TS_LIMIT_DEFAULT_solve_depth, TS_LIMIT_DEFAULT_integral_steps,  \
     TS_LIMIT_DEFAULT_con_doublings, TS_LIMIT_DEFAULT_con_root_cap,                              \
     TS_LIMIT_DEFAULT_con_root_depth, TS_LIMIT_DEFAULT_con_root_steps,                           \
     TS_LIMIT_DEFAULT_bcurve_cells, TS_LIMIT_DEFAULT_bcurve_depth,                               \
     TS_LIMIT_DEFAULT_bcurve_gap_steps}
extern ts__limits ts__test_limits;
#define TS_LIMIT(name) (ts__test_limits.name)
#else
#define TS_LIMIT(name) (TS_LIMIT_DEFAULT_##name)
#endif
void *ts__malloc(size_t bytes);
void *ts__calloc(size_t count, size_t size);
/* An array of count elements of size bytes (size > 0): NULL also when
 * count * size overflows (the n·sizeof check of caller-given counts). */
void *ts__malloc_n(size_t count, size_t size);
/* A large block (the spline's arrays); freed with free(). */
void *ts__alloc_block(size_t bytes);
/* |x1 − x0 − h| for h = fl(x1 − x0): the TwoSum error, exact (0 where the
 * knots are within a factor 2 of each other).  Evaluation measures x from
 * the nearer knot, so the curve of width h sits up to this much aside: the
 * certificates' guards (certificate.c, surface_net.c). */
TS_INLINE double ts__width_error(double x0, double x1, double h)
{
    double z = h - x1;
    return fabs((x1 - (h - z)) + (-x0 - z));
}
/* q[0] = a0 / b0 and q[1] = a1 / b1, one packed division where SSE2 has
 * it (each lane correctly rounded: the bits of two divisions). */
TS_INLINE void ts__div2(double a0, double b0, double a1, double b1, double q[2])
{
#if defined(__GNUC__) && defined(__SSE2__)
    typedef double ts__v2 __attribute__((vector_size(16)));
    ts__v2 a = {a0, a1}, b = {b0, b1}, r = a / b;
    q[0] = r[0];
    q[1] = r[1];
#else
    q[0] = a0 / b0;
    q[1] = a1 / b1;
#endif
}
/* c ? a : b by bit masks: no branch where c is as good as random
 * (scattered queries; sorted ones at every interval's midpoint), which a
 * compiler would otherwise make of it. */
TS_INLINE double ts__pick(int c, double a, double b)
{
    uint64_t ua, ub, m = (uint64_t)0 - (uint64_t)(c != 0);
#if defined(__GNUC__)
    __asm__("" : "+r"(m)); /* opaque: not turned back into a branch */
#endif
    memcpy(&ua, &a, sizeof ua);
    memcpy(&ub, &b, sizeof ub);
    ua = (ua & m) | (ub & ~m);
    memcpy(&a, &ua, sizeof a);
    return a;
}
/* docs/method.md §5.1, §5.8: does slope d at a knot where the data touch a
 * constant bound leave the region?  up = +1 for a lower bound, −1 for an
 * upper; an inner knot needs d = 0, the first up·d >= 0, the last
 * up·d <= 0 (splines, shape.c; curves per coordinate, curve.c). */
TS_INLINE int ts__touch_leaves(double d, int inner, int first, double up)
{
    return inner ? d != 0.0 : (first ? up * d < 0.0 : up * d > 0.0);
}

/* ---- checks.c -------------------------------------------------------- */
/* Knots x[0..np) (np >= 1) and values f (x itself where there are none):
 * in this order every x_i, f_i finite (TS_ERR_NONFINITE), x strictly
 * increasing (TS_ERR_UNSORTED), every width x_i − x_{i−1} in [wmin, wmax]
 * (TS_ERR_WIDTH, index i), every |f_i| <= vmax (TS_ERR_TOO_LARGE); the
 * first offender of the first check that fails (*index, a point; the
 * caller reports it, TS_WHERE_POINT). */
ts_status ts__check_knots(const double *x, const double *f, size_t np, double vmax, double wmin,
                          double wmax, size_t *index);
/* alpha_i > 0 and finite (TS_ERR_ALPHA); beta_i >= 0 with alpha_i + beta_i
 * positive and finite (TS_ERR_BETA; alpha_i already valid); a margin t > 0
 * and finite (TS_ERR_MARGIN).  NaN fails each; & so that loops vectorise. */
TS_INLINE int ts__alpha_ok(double alpha)
{
    return (alpha > 0.0) & (alpha <= DBL_MAX);
}
TS_INLINE int ts__beta_ok(double alpha, double beta)
{
    double a = alpha + beta;
    return (beta >= 0.0) & (beta <= DBL_MAX) & (a > 0.0) & (a <= DBL_MAX);
}
TS_INLINE int ts__margin_ok(double t)
{
    return (t > 0.0) & (t <= DBL_MAX);
}
/* The first i in [i0, i1) whose alpha_i (alphas ? alphas[i] : alpha),
 * resp. beta_i, fails its rule; i1 if none. */
size_t ts__first_bad_alpha(double alpha, const double *alphas, size_t i0, size_t i1);
size_t ts__first_bad_beta(double alpha, const double *alphas, double beta, const double *betas,
                          size_t i0, size_t i1);

/* docs/method.md §5 (upper boundary with §5.3's signs): the β terms of one
 * boundary line at both ends of an interval, sg = +1 for a lower line (gaps
 * g = f − L, slopes d relative to the line's), −1 for an upper (g = L − f):
 * −α ∓ sg K d/g at the left and right ends, taken into *b, *t (terms t0 and
 * t0 + 1) where the gap is > 0 (a knot on the line drops its term, §5.8) and
 * the term is strictly larger.  Splines (shape.c, per line) and curves
 * (curve.c, per coordinate against its box).  The divisor is 1 where the
 * term is not taken: it is computed before it is selected (vector loops),
 * and 0/0 or x/0 there would raise FE_INVALID or FE_DIVBYZERO on valid
 * data. */
TS_INLINE void ts__beta_line(double al, double K, double g0, double g1, double d0, double d1,
                             double sg, int t0, double *b, int *t)
{
    double v0 = -al - sg * K * d0 / (g0 > 0.0 ? g0 : 1.0);
    int take0 = g0 > 0.0 && v0 > *b;
    *b = take0 ? v0 : *b;
    *t = take0 ? t0 : *t;
    double v1 = -al + sg * K * d1 / (g1 > 0.0 ? g1 : 1.0);
    int take1 = g1 > 0.0 && v1 > *b;
    *b = take1 ? v1 : *b;
    *t = take1 ? t0 + 1 : *t;
}

/* Knots per stored running integral (struct ts_spline's cum). */
#define TS_CUM_STEP 8

/* ---- basis.c (docs/method.md §2) ----------------------------------------------- */
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
/* On increasing knots xs[0..n] (n >= 1 intervals): the largest i <= n-1 with
 * xs[i] <= x, trying the cursor (may be NULL) and its successor first. */
size_t ts__search(const double *xs, size_t n, double x, ts_cursor *cur);
/* The interval of a spline containing x (x already in [x0, xn]). */
/* The cursor's interval if it holds x (x >= x0), as ts__search tries it
 * first, else n; no call. */
static inline size_t ts__cursor_interval(const ts_spline *sp, double x, const ts_cursor *cur)
{
    size_t i = cur ? cur->interval : sp->n;
    return i < sp->n && sp->x[i] <= x && (x < sp->x[i + 1] || i + 1 == sp->n) ? i : sp->n;
}
/* For x anywhere (NaN too): the cursor's interval if it holds x, else the
 * next one (sorted queries), setting the cursor as ts__search sets it; n,
 * with the cursor unchanged, where ts__locate would search (or x is
 * outside [x0, xn]).  No call: ts_spline_eval's usual case. */
static inline size_t ts__cursor_step(const ts_spline *sp, double x, ts_cursor *cur)
{
    size_t n = sp->n, i = cur ? cur->interval : n;
    const double *xs = sp->x;
    if (!(i < n && xs[i] <= x)) /* NaN fails */
        return n;
    if (x < xs[i + 1])
        return i;
    if (++i == n) /* x >= xn: xn itself is in the last interval */
        return x == xs[n] ? n - 1 : n;
    if (!(x < xs[i + 1] || (i + 1 == n && x == xs[n])))
        return n;
    cur->interval = i;
    return i;
}
static inline size_t ts__locate(const ts_spline *sp, double x, ts_cursor *cur)
{
    size_t i = ts__cursor_interval(sp, x, cur);
    return i < sp->n ? i : ts__search(sp->x, sp->n, x, cur);
}

/* sin u, cos u, 1 − sin u, 1 − cos u for u in [0, π/4] (a hair beyond by
 * rounding: the angle from an interval's nearer end, docs/method.md §1) by
 * polynomials in z = u² (bench/sincos_coeffs.py: sin u ≈ u + u z P(z),
 * 1 − cos u ≈ z/2 − z² Q(z), truncation <= 5.4e-18).  1 − cos is summed
 * without the 1, so it carries no cancellation; 1 − sin >= 0.29 has none.
 * Used by the batch kernels and by single evaluation inside an interval. */
TS_INLINE void ts__sincos_q(double u, double *s, double *c, double *ms, double *mc)
{
    double z = u * u;
    double ps = -0.16666666666666605 +
                z * (0.008333333333317107 +
                     z * (-0.00019841269826329964 +
                          z * (2.7557312659276103e-06 + z * (-2.5050615702547473e-08 + z * 1.5889377748304707e-10))));
    double pc = 0.0416666666666666 +
                z * (-0.0013888888888874372 +
                     z * (2.4801587289632665e-05 +
                          z * (-2.7557314394461076e-07 + z * (2.0875728820037434e-09 + z * -1.1359926181679004e-11))));
    *s = u + u * (z * ps);        /* sin u */
    *mc = 0.5 * z - (z * z) * pc; /* 1 − cos u */
    *c = 1.0 - *mc;
    *ms = 1.0 - *s;
}
/* The geometric form's X̂(φ) = s² + κ(A1 − A2) = u, φ in [0, π/4]
 * (docs/method.md §4; geometric.c), as the batch kernel and single
 * evaluation solve it.  ts__geo_start: one Newton step on the quartic model
 * M(φ) = 3κφ + (1 − 5κ)φ² + c3 φ³ + c4 φ⁴ of X̂ (Taylor to second order at
 * 0; M(π/4) = 1/2, M'(π/4) = X̂'(π/4) = 1 − (8 − 9/√2)κ) from the root of
 * 3κφ + b φ², b the larger of 1 − 5κ (exact as κ → 0 and as u → 0) and the
 * chord's (1/2 − 3κπ/4)/(π/4)² (through X̂(π/4) = 1/2: the better one for κ
 * above about 0.2).  Within 3.0e-3 (relative) of the root for κ <= 2/(3π)
 * (a >= 1), 1.05e-2 for κ <= 0.4, 6.7e-2 for κ <= 1/2 (a >= 4/(3π)):
 * then two Halley steps, three for some u at κ above 0.4 (bench/geo_start.py,
 * numerically; the kernels take as many steps as a query needs). */
#define TS_GEO_G1 1.6360389693210722 /* 8 − 9/√2 */
#define TS_GEO_Q (0.25 * TS_PI)
/* c3 Q³ + c4 Q⁴ = v, 3 c3 Q² + 4 c4 Q³ = v' with v = 1/2 − 3κQ − (1 − 5κ)Q²,
 * v' = 1 − G1 κ − 3κ − 2(1 − 5κ)Q, both linear in κ: c = C·0 + C·1 κ */
#define TS_GEO_V0 (0.5 - TS_GEO_Q * TS_GEO_Q)
#define TS_GEO_V1 (5.0 * TS_GEO_Q * TS_GEO_Q - 3.0 * TS_GEO_Q)
#define TS_GEO_W0 (1.0 - 2.0 * TS_GEO_Q)
#define TS_GEO_W1 (10.0 * TS_GEO_Q - TS_GEO_G1 - 3.0)
#define TS_GEO_Q3 (TS_GEO_Q * TS_GEO_Q * TS_GEO_Q)
#define TS_GEO_C40 ((TS_GEO_W0 - 3.0 * TS_GEO_V0 / TS_GEO_Q) / TS_GEO_Q3)
#define TS_GEO_C41 ((TS_GEO_W1 - 3.0 * TS_GEO_V1 / TS_GEO_Q) / TS_GEO_Q3)
#define TS_GEO_C30 (TS_GEO_V0 / TS_GEO_Q3 - TS_GEO_C40 * TS_GEO_Q)
#define TS_GEO_C31 (TS_GEO_V1 / TS_GEO_Q3 - TS_GEO_C41 * TS_GEO_Q)
/* the chord's b = B0 − B1 κ */
#define TS_GEO_B0 (0.5 / (TS_GEO_Q * TS_GEO_Q))
#define TS_GEO_B1 (3.0 / TS_GEO_Q)
TS_INLINE double ts__geo_start(double u, double k)
{
    const double Q = TS_GEO_Q;
    double b = 1.0 - 5.0 * k, bc = TS_GEO_B0 - TS_GEO_B1 * k;
    double bq = bc > b ? bc : b, d = 9.0 * k * k + 4.0 * bq * u;
    /* max(d, 0) without a select, which a compiler could move past the
     * square root (FE_INVALID from a vector lane's negative d) */
    double phi = (u + u) / (3.0 * k + sqrt(0.5 * (d + fabs(d))));
    double c3 = TS_GEO_C30 + TS_GEO_C31 * k, c4 = TS_GEO_C40 + TS_GEO_C41 * k;
    phi = phi < Q ? phi : Q;
    double M = phi * (3.0 * k + phi * (b + phi * (c3 + phi * c4))) - u;
    /* M' > 0 at this φ: at least 0.18·3κ over a dense scan of u in [0, 1/2]
     * and every κ the library forms (tests/unit/test_cover_eval.c; M'
     * itself dips below 0 near π/4 for the largest κ, not at this φ) */
    double Mp = 3.0 * k + phi * (2.0 * b + phi * (3.0 * c3 + 4.0 * c4 * phi));
    phi = phi - M / Mp;
    phi = phi > 0.0 ? phi : 0.0;
    return phi < Q ? phi : Q;
}
/* One Halley step from φ (ts__sincos_q there): returns the next φ, clamped
 * to [0, π/4], and sin, cos, 1 − sin, 1 − cos at it by the step e's Taylor
 * rotation (exact to rounding once |e| <= 2^-20: e³/6 < 2^-62; a caller
 * stops after such a step, when Halley's error, of the order of e³, is
 * rounding). */
TS_INLINE double ts__geo_halley(double phi, double k, double u, double *so, double *co, double *mso,
                                double *mco)
{
    double s, c, ms, mc;
    ts__sincos_q(phi, &s, &c, &ms, &mc);
    double p1 = 3.0 - 8.0 * s + 3.0 * (s * s), p2 = 3.0 - 8.0 * c + 3.0 * (c * c);
    double F = s * s + k * (s * ms * (3.0 - s) - c * mc * (3.0 - c)) - u;
    double X1 = 2.0 * (s * c) + k * (c * p1 + s * p2);
    double X2 = 2.0 * (c * c - s * s) +
                k * ((c * c) * (6.0 * s - 8.0) - s * p1 + c * p2 - (s * s) * (6.0 * c - 8.0));
    /* 2X̂'² underflows at φ = 0 for κ below 1e-154 (a_i above 1e153): no 0/0 */
    double den = 2.0 * (X1 * X1) - F * X2;
    den = den > DBL_MIN ? den : DBL_MIN;
    double next = phi - 2.0 * (F * X1) / den;
    next = next > 0.0 ? next : 0.0;
    next = next < TS_GEO_Q ? next : TS_GEO_Q;
    double e = next - phi, e2 = 0.5 * (e * e);
    *so = s + (c * e - s * e2);
    *co = c - (s * e + c * e2);
    *mso = ms - (c * e - s * e2);
    *mco = mc + (s * e + c * e2);
    return next;
}
/* Halley steps from ts__geo_start, at least two (the batch kernel runs the
 * first without a test), then until one is below 2^-20 φ (Halley's error
 * after it is of the order of its cube: rounding), at most TS_GEO_PASSES; sin, cos, 1 − sin, 1 − cos at the root from that step's
 * rotation (s[4]).  A dense scan of u in [2^-1022, 1/2] and every κ the
 * library forms (a_i >= TS_GEOMETRIC_A_MIN) stops within 9 steps, the most
 * at a_i = 0.3472 and u near 1/2, where X̂' nearly vanishes
 * (tests/unit/test_cover_eval.c); a subnormal u, where the steps are rounding noise
 * of a few 2^-1074/κ, ends at the cap with such an iterate
 * (docs/method.md §4).  The batch kernel runs the same steps a pass at a
 * time. */
#define TS_GEO_PASSES 16
TS_INLINE double ts__geo_root(double u, double k, double sc[4])
{
    double phi = ts__geo_start(u, k);
    for (int it = 0; it < TS_GEO_PASSES; it++) {
        double next = ts__geo_halley(phi, k, u, &sc[0], &sc[1], &sc[2], &sc[3]);
        if (it > 0 && fabs(next - phi) <= 0x1p-20 * next)
            return next;
        phi = next;
    }
    return phi;
}
/* The geometric form at the solved φ, seen from the end φ is measured from
 * (docs/method.md §4; geometric.c's geo_side): F0, F1 the values there and
 * at the other end, D0, D1 the slopes (negated from the right end), h, κ;
 * (s, c, ms, mc) at φ.  deriv 0: the value (a flat interval exactly
 * constant: c² + s² need not round to 1); 1: dS/dx = ±Y'/(h X̂') (right:
 * x decreases with φ); 2: d²S/dx² = (Y''X̂' − Y'X̂'')/(h² X̂'³) (the signs
 * cancel).  The batch kernel and single evaluation both use this. */
TS_INLINE double ts__geo_y(int deriv, double F0, double F1, double D0, double D1, double h,
                           double kappa, int right, double s, double c, double ms, double mc)
{
    double k = kappa * h;
    if (deriv == 0) {
        /* F0 c² + F1 s² written as F0 + (F1 − F0) s²: F0 exactly at φ = 0,
         * and no c² + s² ≠ 1 wobble of an ulp of F0 where the interval
         * changes by less than that (monotone samples) */
        double v = F0 + ((F1 - F0) * (s * s) +
                         k * (D0 * (s * ms * (3.0 - s)) - D1 * (c * mc * (3.0 - c))));
        return (F0 == F1 && k * D0 == 0.0 && k * D1 == 0.0) ? F0 : v;
    }
    double p1 = 3.0 - 8.0 * s + 3.0 * (s * s), p2 = 3.0 - 8.0 * c + 3.0 * (c * c);
    double a1 = c * p1, a2 = -s * p2, dF = F1 - F0, sc2 = 2.0 * (s * c);
    double Yp = dF * sc2 + k * (D0 * a1 - D1 * a2);
    double Xp = sc2 + kappa * (a1 - a2);
    if (deriv == 1) {
        double v1 = Yp / Xp / h;
        return right ? -v1 : v1;
    }
    double b1 = -s * p1 + (c * c) * (6.0 * s - 8.0), b2 = -c * p2 + (s * s) * (6.0 * c - 8.0);
    double c2 = 2.0 * (c * c - s * s);
    double Ypp = dF * c2 + k * (D0 * b1 - D1 * b2);
    double Xpp = c2 + kappa * (b1 - b2);
    /* (Y''X̂' − Y'X̂'')/X̂'³ as (Y'' − (Y'/X̂')X̂'')/X̂'/X̂': X̂' >= 3κ·0.18 > 0
     * for every a_i (κ = 2/(3π a_i) >= 1e-309), but X̂'³ underflows to 0 from
     * a_i ≈ 1e103 on, where S'' is still finite (tests/api/test_fenv.c) */
    return (Ypp - (Yp / Xp) * Xpp) / Xp / Xp / h / h;
}
/* ts__seg_sc with 1 − s and 1 − c given (ms, mc); inline: single
 * evaluation's path (ts__trig_eval_in). */
TS_INLINE void ts__seg_scm(const double B[4], double s, double c, double ms, double mc, int want, double out[3])
{
    double A[4];
    A[1] = s * ms * (3.0 - s); /* ts__basis */
    A[2] = c * mc * (3.0 - c);
    A[3] = mc * mc * mc;
    /* Σ A_l B_l as B0 + Σ_{l>0} A_l (B_l − B0) (Σ A_l = 1, docs/method.md §2):
     * no ulp of B0 from Σ A_l ≠ 1 in rounding, so a rise of a few ulps
     * after a flat interval is not sampled below it (monotone data) */
    out[0] = B[0] + (A[1] * (B[1] - B[0]) + A[2] * (B[2] - B[0]) + A[3] * (B[3] - B[0]));
    if (want > 0) {
        /* docs/method.md (2.1) */
        out[1] = 3.0 * ms * ms * c * (B[1] - B[0]) + 2.0 * s * c * (B[2] - B[1]) +
                 3.0 * mc * mc * s * (B[3] - B[2]);
    }
    if (want > 1) {
        /* ts__basis_d2 */
        A[0] = 6.0 * ms * c * c + 3.0 * ms * ms * s;
        A[1] = -s * (3.0 - 8.0 * s + 3.0 * s * s) + c * c * (6.0 * s - 8.0);
        A[2] = -c * (3.0 - 8.0 * c + 3.0 * c * c) + s * s * (6.0 * c - 8.0);
        A[3] = 6.0 * mc * s * s + 3.0 * mc * mc * c;
        out[2] = A[0] * B[0] + A[1] * B[1] + A[2] * B[2] + A[3] * B[3];
    }
    /* a flat segment's value is B0 already (every difference is 0; a −0 B0
     * gives +0, as in the kernels); its derivatives are 0 (Σ A_l'' need not
     * round to 0) */
    if (want > 0 && B[0] == B[1] && B[1] == B[2] && B[2] == B[3]) {
        out[1] = 0.0;
        if (want > 1)
            out[2] = 0.0;
    }
}

/* ---- trigmin.c (docs/method.md §2, §5) ----------------------------------------- */
/* Exact minimum over θ in [0, π/2] of g(θ) = Σ A_l(θ) C_l − κ θ.  Returns the
 * minimum and stores its θ in *theta_min (may be NULL). */
double ts__trig_min(const double C[4], double kappa, double *theta_min);
/* The same; also *tbest, the t = tan(θ/2) of the minimum, and *errb, the
 * rounding guard of the returned value (NaN for non-finite input). */
double ts__trig_min_core(double C0, double C1, double C2, double C3, double kappa,
                         double *theta, double *tbest, double *errb);
/* The rounding guard of ts__trig_min_core (scaled problem, subdivision depth
 * reached, babs = 3|D0| + 3|D1| + 24|D2| + 8|κ|, Ms = max|c_l|, ak = |κ|). */
TS_INLINE double ts__trig_min_guard(int depth, double babs, double Ms, double ak)
{
    double eta = (6.0 * depth + 6.0) * DBL_EPSILON * babs;
    return 2.0 * (16.0 * DBL_EPSILON * (Ms + TS_HALF_PI * ak) + 2.0 * eta);
}
/* The first step of ts__trig_min_core on the scaled problem (c_l = C_l 2^-e,
 * ks = κ 2^-e): the differences, the Bernstein coefficients b[7] of P, the
 * end values.  Branch-free (certificate.c runs it over blocks of intervals).
 * Returns 1 when the minimum is at an end — g monotone by (2.1), or no
 * coefficient < 0 before one > 0, so no minimum inside — with *best the
 * least end value, *at1 = 1.0 if it is at θ = π/2 (else 0.0), and *babs
 * for the guard;
 * 0 when the roots must be isolated. */
TS_INLINE int ts__trig_min_ends(double c0, double c1, double c2, double c3, double ks,
                                    double b[7], double *best, double *at1, double *babs)
{
    double D0 = c1 - c0, D1 = c2 - c1, D2 = c3 - c2;
    double ak = fabs(ks), a0 = fabs(D0), a1 = fabs(D1), a2 = fabs(D2);
    *babs = 3.0 * a0 + 3.0 * a1 + 24.0 * a2 + 8.0 * ak;
    /* (2.1): a monotone control polygon with κ of the other sign makes g
     * monotone; then every Bernstein coefficient below has one sign (also as
     * computed: sums of rounded terms of one sign), no root.  Most intervals
     * of real data are so. */
    int mono = ((D0 >= 0.0) & (D1 >= 0.0) & (D2 >= 0.0) & (ks <= 0.0)) |
               ((D0 <= 0.0) & (D1 <= 0.0) & (D2 <= 0.0) & (ks >= 0.0));
    b[0] = 3.0 * D0 - ks;
    b[1] = D0 + (2.0 / 3.0) * D1 - ks;
    b[2] = (4.0 / 3.0) * D1 - 1.2 * ks;
    b[3] = 2.0 * D1 - 1.6 * ks;
    b[4] = (8.0 / 3.0) * D1 - 2.4 * ks;
    b[5] = (8.0 / 3.0) * D1 + 4.0 * D2 - 4.0 * ks;
    b[6] = 24.0 * D2 - 8.0 * ks;
    int neg = b[0] < 0.0, rise = 0; /* written out: a loop here would not vectorise */
    rise |= neg & (b[1] > 0.0), neg |= b[1] < 0.0;
    rise |= neg & (b[2] > 0.0), neg |= b[2] < 0.0;
    rise |= neg & (b[3] > 0.0), neg |= b[3] < 0.0;
    rise |= neg & (b[4] > 0.0), neg |= b[4] < 0.0;
    rise |= neg & (b[5] > 0.0), neg |= b[5] < 0.0;
    rise |= neg & (b[6] > 0.0);
    /* the ends with ts__basis_t's exact values there: A = e_0 at t = 0,
     * θ = 0, and A = e_3 at t = 1, θ = π/2 */
    double g0 = 1.0 * c0 + 0.0 * c1 + 0.0 * c2 + 0.0 * c3;
    double g1 = 0.0 * c0 + 0.0 * c1 + 0.0 * c2 + 1.0 * c3;
    g0 = ks != 0.0 ? g0 - ks * 0.0 : g0;
    g1 = ks != 0.0 ? g1 - ks * TS_HALF_PI : g1;
    *at1 = g1 < g0 ? 1.0 : 0.0;
    *best = g1 < g0 ? g1 : g0;
    return mono | !rise;
}
/* Basis at t = tan(θ/2), without cancellation; θ = 2 atan t (exact ends). */
void ts__basis_t(double t, double A[4]);
double ts__theta_of(double t);

/* ---- expansion.c (docs/method.md §5.8, §11.3, §11.7, §13.4) ---------- */
/* Exact sums and products of doubles as expansions (Shewchuk): e[0..n)
 * nonoverlapping, of increasing magnitude, zero components kept (their
 * lengths fixed by n).  Exact while no sum overflows and no product
 * underflows or overflows (the callers bound their inputs' range).
 * h = e + b: n + 1 components (h may be e). */
int ts__exp_grow(const double *e, int n, double b, double *h);
/* h = e b: 2n components (h not e; n >= 1). */
int ts__exp_scale(const double *e, int n, double b, double *h);
/* h = e f: 2nm components (h not e; 1 <= n <= TS_EXP_PRODUCT_MAX, m >= 1). */
#define TS_EXP_PRODUCT_MAX 16
int ts__exp_product(const double *e, int n, const double *f, int m, double *h);
/* The sign (−1, 0, 1) of the expansion e[0..n): that of its largest
 * nonzero component. */
int ts__exp_sign(const double *e, int n);
/* The sign (−1, 0, 1) of the exact sum of v[0..n), n <= TS_EXACT_TERMS,
 * each |v_j| <= 2^1020 (so that no partial sum overflows): Shewchuk's
 * expansion sum (ts__exp_grow term by term, then ts__exp_sign).  The data
 * checks' side of a line or plane (docs/method.md §5.8, §11.3) and the
 * constraint records' certificates (§13.4, up to 32 terms). */
#define TS_EXACT_TERMS 32
int ts__exact_sign(const double *v, int n);
/* sg times the two terms of a x = P + e (exact by fma) into v[0..2), for
 * ts__exact_sign: returns 2, or 0 where P is beyond its range or so small
 * (nonzero factors, |P| < 2^-960) that e is not exact. */
TS_INLINE int ts__exact_product(double a, double x, double sg, double v[2])
{
    double P = a * x;
    if (!(fabs(P) <= 0x1p1020) || (fabs(P) < 0x1p-960 && a != 0.0 && x != 0.0))
        return 0;
    v[0] = sg * P;
    v[1] = sg * fma(a, x, -P);
    return 2;
}

/* ==== L1 ============================================================ */

/* ---- gridbound.c (docs/method.md §11.7) ------------------------------- */
/* The field's value at (x, y) inside its grid, bilinear on the cell found by
 * ts__search; |value − exact| < g->err. */
double ts__gb_value(const ts__gbound *g, double x, double y);
/* Sign (−1, 0, 1) of v − field(x, y), exact (expansion arithmetic); 2 where
 * undecidable (an input nonzero and outside [2^-300, 2^300] in magnitude
 * while the rounded value does not decide). */
int ts__gb_side(const ts__gbound *g, double x, double y, double v);
/* An upper bound of sg · field over [xa, xb] × [ya, yb] (inside its grid):
 * the largest of its values at the rectangle's corners, where its edges
 * cross grid lines and at the grid nodes inside, plus g->err. */
double ts__gb_max(const ts__gbound *g, double sg, double xa, double xb, double ya, double yb);
/* 1 when [xa, xb] × [ya, yb] (inside the grid) lies in one cell, with upper
 * bounds of |∂field/∂x|, |∂field/∂y| there; else 0. */
int ts__gb_cell(const ts__gbound *g, double xa, double xb, double ya, double yb, double *gx,
                double *gy);
/* What is wrong with a caller's field for a surface on [x0, x1] × [y0, y1]
 * (TS__GB_SIZE: 4 nx_points ny_points doubles overflow size_t): *at the
 * index of the coordinate (x: i, y: nx_points + j) or node (j*nx_points + i). */
enum {
    TS__GB_OK, TS__GB_NULL, TS__GB_TOO_FEW, TS__GB_SIZE, TS__GB_AXIS, TS__GB_VALUE,
    TS__GB_COVER
};
int ts__gb_check(const ts_grid_bound *g, double x0, double x1, double y0, double y1, size_t *at);

/* ---- slopes.c (docs/method.md §6) ---------------------------------------------- */
/* Unchecked: x strictly increasing and finite, np >= 2, method valid and not
 * TS_SLOPES_USER (every caller checks its options first). */
ts_status ts__slopes(ts_slopes method, const double *x, const double *f, size_t np,
                     double *d, ts_error *err);
/* d[p0..p1) only (p0 < p1 <= np), the same values as ts__slopes (which
 * checks the periodic ends and finiteness; this does not).  For
 * construction in blocks. */
void ts__slopes_range(ts_slopes method, const double *x, const double *f, size_t np, double *d,
                      size_t p0, size_t p1);

/* ---- controls.c (docs/method.md §3, §4) ---------------------------------------- */
/* Recompute b1, b2 (and κ in the geometric form) of intervals
 * i0..i1-1 (i0 < i1 <= n) from x, f, d, alpha, beta, one function per form
 * (called through ts__form).  For the C¹ form the knots' d̂ depend on both
 * neighbours, so callers pass the widened range. */
void ts__controls_paper(ts_spline *sp, size_t i0, size_t i1);
void ts__controls_c1(ts_spline *sp, size_t i0, size_t i1);
void ts__controls_geo(ts_spline *sp, size_t i0, size_t i1);
/* The a that divides d_i and d_{i+1} in interval i's controls: a_i at
 * both ends (paper, geometric); the C¹ form's max(a_{j−1}, a_j) of each
 * knot (docs/method.md §3), one-sided at the ends. */
void ts__ends_a(const ts_spline *sp, size_t i, double *aL, double *aR);
void ts__ends_a_c1(const ts_spline *sp, size_t i, double *aL, double *aR);
/* docs/method.md §3, §4: K_i = (2/(3π)) h_i, the control offset of θ linear
 * in x (the paper and C¹ forms' abscissae X1 = x_i + K_i; the schemes' β
 * rules of §5 and §11.3); k_i = K_i / a_i (B1 = f_i + k_i d_i, and the
 * geometric form's X1 = x_i + k_i); κ = 2/(3π a) (the geometric form's
 * stored κ_i; the error constants; surfaces' X̂).  The one spelling of
 * each: every user reads these. */
TS_INLINE double ts__geo_K(double h)
{
    return 2.0 / (3.0 * TS_PI) * h;
}
TS_INLINE double ts__geo_k(double h, double a)
{
    return ts__geo_K(h) / a;
}
TS_INLINE double ts__kappa(double a)
{
    return 2.0 / (3.0 * TS_PI * a);
}
/* The width of interval i: bitwise spline.c's former stored h_i. */
static inline double ts__h(const ts_spline *sp, size_t i)
{
    return sp->x[i + 1] - sp->x[i];
}
/* dθ/dx = (π/2)/h_i of interval i (docs/method.md §2): the one expression,
 * whose bits struct ts_spline's w stores (paper and C¹ forms). */
TS_INLINE double ts__w(double x0, double x1)
{
    return TS_HALF_PI / (x1 - x0);
}
/* docs/method.md §4 B1, B2 of the geometric form from the knots (x_i,
 * x_{i+1}: h), f, d and a = α + β: the operations of controls.c, so the
 * bits it once stored (also in vector loops: no contraction there). */
TS_INLINE double ts__geo_b1(double x0, double x1, double f0, double d0, double a)
{
    return f0 + ts__geo_k(x1 - x0, a) * d0;
}
TS_INLINE double ts__geo_b2(double x0, double x1, double f1, double d1, double a)
{
    return f1 - ts__geo_k(x1 - x0, a) * d1;
}
/* The four control values of interval i. */
static inline void ts__B(const ts_spline *sp, size_t i, double B[4])
{
    B[0] = sp->f[i];
    B[3] = sp->f[i + 1];
    if (sp->b1) {
        B[1] = sp->b1[i];
        B[2] = sp->b2[i];
    } else {
        double a = sp->alpha[i] + sp->beta[i], x0 = sp->x[i], x1 = sp->x[i + 1];
        B[1] = ts__geo_b1(x0, x1, B[0], sp->d[i], a);
        B[2] = ts__geo_b2(x0, x1, B[3], sp->d[i + 1], a);
    }
}

/* ---- geometric.c (docs/method.md §4) ------------------------------------------- */
/* The bound on a_i of docs/method.md §4 on intervals [i0, i1) (beta set, controls
 * not yet): raise beta_i (shape schemes) or fail (TS_ERR_GEOMETRIC). */
ts_status ts__geo_check(ts_spline *sp, size_t i0, size_t i1, ts_error *err);
/* Value and derivatives in x of interval i of a geometric-form spline at x. */
void ts__geo_eval(const ts_spline *sp, size_t i, double x, int want, double out[3]);
/* φ in [0, π/4] with X̂(φ) = u, u in [0, 1/2], κ = 2/(3π a) (the solve of
 * ts__geo_eval; used by the surfaces of docs/method.md §11). */
double ts__geo_solve(double kappa, double u);
/* w[i − i0] = ∫ over interval i, i in [i0, i1) (ts__geo_integral_scaled at x_{i+1}, k = 0). */
void ts__geo_wholes(const ts_spline *sp, size_t i0, size_t i1, double *w);
/* The same times 2^-k, finite where that is (|f|, |B| <= TS_VALUE_MAX). */
double ts__geo_integral_scaled(const ts_spline *sp, size_t i, double x, int k);
/* S, S', S'' (out[0..want]) of interval i of a geometric-form spline at x
 * inside it (x_i <= x <= x_{i+1}), as the batch kernel computes them:
 * ts__geo_root, then ts__geo_y.  Inline: ts_spline_eval's path. */
TS_INLINE void ts__geo_in(const ts_spline *sp, size_t i, double x, int want, double o[3])
{
    double h = ts__h(sp, i), kappa = sp->kappa[i], dl = x - sp->x[i], dr = sp->x[i + 1] - x, sc[4];
    int right = dr < dl;
    (void)ts__geo_root((right ? dr : dl) / h, kappa, sc);
    size_t i0 = right ? i + 1 : i, i1 = right ? i : i + 1;
    double F0 = sp->f[i0], F1 = sp->f[i1];
    double D0 = right ? -sp->d[i0] : sp->d[i0], D1 = right ? -sp->d[i1] : sp->d[i1];
    for (int k = 0; k <= want; k++)
        o[k] = ts__geo_y(k, F0, F1, D0, D1, h, kappa, right, sc[0], sc[1], sc[2], sc[3]);
}

/* ==== L2 ============================================================ */

/* ---- interval.c (docs/method.md §2–§4) ----------------------------------------- */
/* What differs between the forms (docs/method.md §3, §4), one entry per
 * ts_form.  Read once per call: a loop over queries or intervals looks its
 * form up before it starts (ts_spline_eval's inline path and the batch kernels'
 * inner loops call nothing through it). */
typedef struct ts__form_ops {
    int geometric;  /* κ_i stored; abscissae X̂ = (0, κ, 1 − κ, 1); S solves X(θ) = x (§4) */
    int neighbours; /* an interval's controls read its neighbours' a_j (C¹, §3) */
    int kernel;     /* the batch kernels' family (kernels.c): 0 θ linear in x, 1 geometric */
    /* b1, b2 (κ) of intervals [i0, i1) (controls.c) */
    void (*controls)(ts_spline *sp, size_t i0, size_t i1);
    /* w[i − i0] = ∫ over interval i, i in [i0, i1) */
    void (*wholes)(const ts_spline *sp, size_t i0, size_t i1, double *w);
    /* value and derivatives of interval i at any x (ts__interval_eval) */
    void (*eval)(const ts_spline *sp, size_t i, double x, int want, double o[3]);
    /* 2^-k ∫_a^b S on interval i, the closed form (b − a > h/16) */
    double (*integral)(const ts_spline *sp, size_t i, double a, double b, int k);
    /* the control abscissae's offset: X1 = x_i + k, X2 = x_{i+1} − k */
    double (*k)(const ts_spline *sp, size_t i);
    /* the a dividing the slopes at the two ends of interval i (ts__ends_a) */
    void (*ends_a)(const ts_spline *sp, size_t i, double *aL, double *aR);
} ts__form_ops;
/* The entry of form (a valid ts_form). */
const ts__form_ops *ts__form(ts_form form);
/* ∫_{x0}^{x_i} S dx, i <= n: the stored running sum at the TS_CUM_STEP-th
 * knot below i plus the wholes after it, added in the order spline.c's
 * running sum added them (so its bits). */
double ts__cum(const ts_spline *sp, size_t i);
/* Value and derivatives (in x; out[1], out[2] only if want > 0, > 1) of
 * interval i at x, any form; x may lie outside the interval (extension). */
void ts__interval_eval(const ts_spline *sp, size_t i, double x, int want, double o[3]);
/* The same, paper and C¹ forms, x inside the interval (x_i <= x <= x_{i+1}):
 * ϑ from the nearer end (<= π/4), so the kernels' polynomial sine and cosine
 * (sin and cos of π/2 − θ are exact at the right knot: both knots are
 * interpolated exactly).  w = dθ/dx, the bits of ts__w: sp->w[i] where the
 * interval came from the cursor (sorted queries: no division), ts__w after
 * a search (random queries: no cache line of w to miss).  Inline:
 * ts_spline_eval's path. */
TS_INLINE void ts__trig_eval_in(const ts_spline *sp, size_t i, double x, double w, int want,
                                double o[3])
{
    double tu = (x - sp->x[i]) * w, tv = (sp->x[i + 1] - x) * w;
    /* from the right end as the kernels (the same test, on the products):
     * ϑ = π/2 − θ, the control values reversed (docs/method.md §2),
     * dϑ/dθ = −1; chosen by index and by masks (ts__pick), not by a
     * branch, which sorted queries would mispredict at every midpoint */
    size_t r = tv < tu;
    double b1 = sp->b1[i], b2 = sp->b2[i];
    double B[4] = {sp->f[i + r], ts__pick(r != 0, b2, b1), ts__pick(r != 0, b1, b2), sp->f[i + 1 - r]};
    double s, c, ms, mc;
    ts__sincos_q(tv < tu ? tv : tu, &s, &c, &ms, &mc);
    ts__seg_scm(B, s, c, ms, mc, want, o);
    if (want > 0)
        o[1] *= r ? -w : w;
    if (want > 1)
        o[2] *= w * w;
}
/* 2^-k ∫_a^b S on interval i (x_i <= a <= b <= x_{i+1}), the factors ordered
 * so that it stays finite where the integral times 2^-k is.  A piece shorter
 * than h/16 is integrated directly (12-point Gauss–Legendre in x), so its
 * relative error is a few ε of the piece, not of the interval. */
double ts__interval_integral_scaled(const ts_spline *sp, size_t i, double a, double b, int k);

/* ---- deriv.c (docs/method.md §2, derivatives of any order) ------------ */
/* d^ν S/dx^ν (ν >= 1; used for ν >= 3) of interval i of a paper or C¹ spline
 * at x, from the trigonometric form of S; x may lie outside the interval
 * (TS_EXTRAP_EXTEND). */
double ts__interval_deriv(const ts_spline *sp, size_t i, double x, int nu);

/* ---- shape.c (docs/method.md §5) ----------------------------------------------- */
/* For a scheme (opt->shape one of TS_SHAPE_POSITIVE..TS_SHAPE_MONOTONE, as
 * ts_spline_new has checked; sp, opt not NULL): ts__shape_begin checks the
 * margins' length and sets the boundaries (*dir: the
 * direction of the data f[0..n], monotone; f: the caller's values, sp->f need
 * not be filled yet); ts__shape_range then checks margins of intervals
 * [i0, i1), data of points [p0, p1), adjusts their slopes (d there already
 * computed: zeros, monotone sign fix) and sets beta[], term[] of [i0, i1). */
ts_status ts__shape_begin(ts_spline *sp, const ts_spline_options *opt, const double *f, int *dir,
                          ts_error *err);
ts_status ts__shape_range(ts_spline *sp, const ts_spline_options *opt, int dir, size_t p0, size_t p1,
                          size_t i0, size_t i1, ts_error *err);

/* ---- certificate.c (docs/method.md §4, §5) -------------------------------------- */
/* The exact gaps of one interval (NaN where absent or not computed). */
typedef struct ts__cert {
    double glo, alo, gup, aup;
} ts__cert;
/* B of interval i; in the geometric form (*geo = 1) X the local abscissae
 * X̂_l = [0, κ, 1 − κ, 1] of x = x_i + h X̂ (docs/method.md §4). */
void ts__controls_of(const ts_spline *sp, size_t i, double B[4], double X[4], int *geo);
/* Gap of a segment with control values B on [xi, xi + h] (paper and C¹
 * forms, and curve coordinates) to the line ln: sign +1 min of S − L, −1 min
 * of L − S, exact (ts__trig_min_core) in local coordinates (L_i = m xi + c
 * rounded once, docs/method.md §5.6); *theta (and *tpar = tan(θ/2)) of the
 * minimum, *guard its rounding guard (h taken as exact: ts__gap_ctl adds
 * |m| times its rounding), *proven = 1 when the line is constant
 * and every control gap ±(B_l − c) is > 0 (a proof by itself: S − L =
 * Σ A_l C_l, A_l >= 0, Σ A_l = 1).  theta is required; the other
 * out-pointers may be NULL. */
double ts__gap_segment(const double B[4], double xi, double h, const ts_line *ln, int sign,
                       double *theta, double *tpar, double *guard, int *proven);
/* Gap of interval i with control values B (abscissae X in the geometric
 * form, else NULL) to a line: sign +1 min of S − L, −1 min of L − S; *at its
 * x, *guard (may be NULL) the rounding guard of the value. */
double ts__gap_ctl(const ts_spline *sp, size_t i, const double B[4], const double *X,
                   const ts_line *ln, int sign, double *at, double *guard);
/* Range of interval i with controls B (X in the geometric form, else NULL):
 * the exact min and max of S (its gaps to the line y = 0, docs/method.md §5.9)
 * with their x, and the excursions beyond B0, B3, into rep's y_min,
 * at_y_min, y_max, at_y_max, excursion_above, excursion_below. */
void ts__range_ctl(const ts_spline *sp, size_t i, const double B[4], const double *X,
                   ts_interval_report *rep);
/* The same for a segment with controls B on [ti, ti + h] (curve coordinates;
 * the places in the parameter). */
void ts__range_segment(const double B[4], double ti, double h, ts_interval_report *rep);
/* The same for interval i as stored. */
double ts__interval_gap(const ts_spline *sp, size_t i, const ts_line *line, int sign, double *at);
/* The control gaps' proof (docs/method.md §5.6): geometric form (X the local
 * abscissae of ts__controls_of), every local control gap above its rounding
 * and the evaluator's; paper and C¹ forms (X NULL), a constant line strictly
 * below (sign +1) or above (−1) every B_l, or any line whose larger end
 * value is below min B_l (above max B_l) by more than its rounding guard
 * (item 8). */
int ts__hull_inside(const ts_spline *sp, size_t i, const double B[4], const double *X,
                    const ts_line *ln, int sign);
/* Is interval i with controls B (X) inside the region of sp's scheme?  exact:
 * with the trig-min certificates (into *cr, places if want_at); else only
 * the control-value proof. */
int ts__check_ctl(const ts_spline *sp, size_t i, const double B[4], const double *X, int exact,
                  ts__cert *cr, int want_at);
int ts__check_interval(const ts_spline *sp, size_t i, int exact);
/* Does certification of a spline built with opt compute the exact trig-min
 * certificates?  (Only meaningful for opt->shape != TS_SHAPE_NONE.) */
int ts__certify_exact(const ts_spline_options *opt);
/* First interval in [i, i1) that ts__check_ctl (not exact) would not pass;
 * line schemes: that it would not pass by the line bound (paper and C¹
 * forms, docs/method.md §5.6 item 8) or the control gaps (geometric form,
 * §4), exact or not. */
size_t ts__skip_proven(const ts_spline *sp, size_t i, size_t i1);
/* ok[i - i0] = 1 where ts__check_ctl (exact, paper form, one boundary
 * m x + c with sign sg) passes interval i by an end minimum, else 0. */
void ts__mono_certify(const double *restrict f, const double *restrict b1,
                      const double *restrict b2, const double *restrict x, size_t i0, size_t i1,
                      double m, double c, double sg, int positive, unsigned char *restrict ok);

/* ---- surface_net.c (docs/method.md §11) ---------------------------------------- */
/* The basis of one direction at a query: knots t[0..n], shape parameters
 * a[0..n-1], interval i (t in it), form.  A[4] the basis, dA[4] (may be NULL)
 * its derivative in t (dA/dθ · dθ/dt). */
void ts__surf_basis(const double *t, const double *a, size_t i, ts_form form, double v,
                    double A[4], double *dA);
/* Local control abscissae X̂_0..3 of interval i in units of its width:
 * (0, κ, 1 − κ, 1), κ = 2/(3π a_i) (geometric) or 2/(3π) (paper, C¹: the
 * abscissae of θ linear in t, for plotting). */
void ts__surf_xhat(const double *a, size_t i, ts_form form, double X[4]);
/* ∫ A_k dt over [ta, tb] in interval i (both in it): W[4]. */
void ts__surf_basis_int(const double *t, const double *a, size_t i, ts_form form, double ta,
                        double tb, double W[4]);
/* k of interval i (knots t, n intervals) at its end node (node = i or i + 1):
 * K/a_i, K = 2h_i/(3π), in the paper and geometric forms; K/max(a of the
 * node's intervals) in the C¹ form (docs/method.md §11.2). */
double ts__surf_k(const double *t, const double *a, size_t n, size_t i, size_t node,
                  ts_form form);
/* The control net of patch (i, j) from z, p, q, r, ax, ay (docs/method.md
 * §11.1): B[4k + l]. */
void ts__surf_patch(const ts_surface *s, size_t i, size_t j, double B[16]);
/* Its parts: u[0], u[1] the k (ts__surf_k) of interval i along x (dir 0)
 * or y (dir 1) at its two end nodes; the net from those of i and j (so
 * that a caller evaluating many patches of one row or column forms them
 * once). */
void ts__surf_ks(const ts_surface *s, int dir, size_t i, double u[2]);
TS_INLINE void ts__surf_patch_k(const ts_surface *s, size_t i, size_t j, const double ux[2],
                                const double uy[2], double B[16])
{
    size_t np = s->nx + 1;
    /* the four corners: (k, l) of the corner, σ the inward signs */
    for (int cy = 0; cy < 2; cy++) {
        for (int cx = 0; cx < 2; cx++) {
            size_t n = (j + (size_t)cy) * np + i + (size_t)cx;
            double sx = cx ? -1.0 : 1.0, sy = cy ? -1.0 : 1.0;
            double ex = sx * ux[cx] * s->p[n], ey = sy * uy[cy] * s->q[n];
            int k0 = cx ? 3 : 0, l0 = cy ? 3 : 0, k1 = cx ? 2 : 1, l1 = cy ? 2 : 1;
            B[4 * k0 + l0] = s->z[n];
            B[4 * k1 + l0] = s->z[n] + ex;
            B[4 * k0 + l1] = s->z[n] + ey;
            B[4 * k1 + l1] = s->z[n] + ex + ey + sx * sy * ux[cx] * uy[cy] * s->r[n];
        }
    }
}
/* p x + q y + c to about one rounding of the result (error-free products
 * and sums, docs/method.md §11.3); *err (if not NULL) bounds its error.
 * x, y finite. */
double ts__surf_plane_at(const ts_plane *pl, double x, double y, double *err);
/* Control gaps of patch (i, j) with net B to a plane in local coordinates: G[16] =
 * sign (B − plane at the control abscissae), the plane taken at the patch's
 * corner and its rise to the abscissae; *guard the rounding of forming them
 * and of where evaluation places a point (0 for a constant plane: then the
 * signs are exact). */
void ts__surf_gaps(const ts_surface *s, size_t i, size_t j, const double B[16], const ts_plane *pl,
                   int sign, double G[16], double *guard);
/* Are all 16 gaps >= guard (nonzero corners: > guard)?  Proves the patch on
 * the plane's side (docs/method.md §11.3). */
int ts__surf_gaps_inside(const double G[16], double guard);

/* ---- constrain_spline.c (docs/method.md §13.7) ------------------------- */
/* b: a bound spline (any form), sg +1 lower, −1 upper.  sg (f − B(x)) > 0
 * proved (1), not proved (0: across, touching, or within B(x)'s enclosure),
 * x outside B's knots (−1). */
int ts__bcurve_side(const ts_spline *b, double sg, double x, double f);
/* [*lo, *hi] contains B over [xa, xb] ∩ [x_0, x_m] of b; 0 when empty. */
int ts__bcurve_range(const ts_spline *b, double xa, double xb, double *lo, double *hi);
/* sg (S − B) > 0 proved on interval i of the geometric spline sp (where B
 * is defined), by subdivision and rigorous hulls: 1; 0 not proved. */
int ts__bcurve_certify(const ts_spline *sp, size_t i, const ts_spline *b, double sg);
/* The minimum of sg (S − B) over interval i where B is defined, *at its x;
 * B must overlap the interval (x_0 of b < x_{i+1}, x_i < x_m of b). */
double ts__bcurve_gap(const ts_spline *sp, size_t i, const ts_spline *b, double sg, double *at);
/* Doubles of a copy of b (knots, values, slopes, controls, κ or w);
 * ts__bcurve_copy fills dst (zeroed first) with arrays in q. */
size_t ts__bcurve_doubles(const ts_spline *b);
void ts__bcurve_copy(const ts_spline *b, ts_spline *dst, double *q);

/* ==== L3 ============================================================ */

/* ---- surface_cert.c (docs/method.md §11.4) -------------------------------------- */
/* Certificate of patch (i, j) against a gridded field (§11.7; sign +1: S −
 * field, −1: field − S): *proven a proven lower bound of the gap, *sampled
 * the least gap found at a point (*ax, *ay); returns 1 when certified
 * (*proven > 0). */
int ts__surf_certify_grid(const ts_surface *s, size_t i, size_t j, const ts__gbound *g,
                          int sign, double *proven, double *sampled, double *ax, double *ay);
/* Certificate of patch (i, j) against one plane (sign +1: S − plane,
 * −1: plane − S): *proven a proven lower bound of the gap, *sampled the
 * least gap found at a point (*ax, *ay); returns 1 when certified. */
int ts__surf_certify_patch(const ts_surface *s, size_t i, size_t j, const ts_plane *pl,
                           int sign, double *proven, double *sampled, double *ax, double *ay);

/* ---- kernels.c (batch kernels) ----------------------------------------- */
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
/* The kernel for isa (−1 the best available, 0 portable C, 1 AVX2+FMA,
 * 2 AVX-512F) on a CPU with AVX2+FMA (has2) and AVX-512F (has512): 0, 1, 2,
 * or −1 if that kernel cannot run there or isa is none of these. */
int ts__fast_pick(int isa, int has2, int has512);

/* ---- repair.c (docs/method.md §5) ---------------------------------------------- */
/* One interval (of a spline or a curve) as the repair search sees it. */
typedef struct ts__repair_ops {
    void *ctx;
    void (*set_a)(void *ctx, size_t i, double a);  /* a_i = a; controls updated */
    int (*inside)(void *ctx, size_t i);            /* certified as it stands */
    int (*limit_inside)(void *ctx, size_t i);      /* certified in the limit a -> ∞ */
    double (*margin)(void *ctx, size_t i);         /* min of gap − guard; NULL: none */
    double (*gap)(void *ctx, size_t i);            /* min of the gaps (with margin) */
} ts__repair_ops;
/* docs/method.md §5: the a_i that certifies interval i, starting from a0 (alpha al).
 *  - If the limit a -> ∞ is certified, a is raised: doubling, then bisection
 *    to the smallest certified a (relative 1e-12), plus the margin t.
 *  - Otherwise (a sloped line in the paper or C¹ form; ops with a margin)
 *    the gap is concave in u = 1/a in the paper form (a minimum of functions
 *    affine in u), so its maximum over a >= al is found by golden section; if
 *    it is not certified no a is (TS_ERR_INFEASIBLE); else the smallest
 *    certified a >= al, plus t towards the maximum.  In the C¹ form the gap
 *    also depends on the neighbours' a (fixed here): a heuristic there.
 * TS_OK with a_i set, or TS_ERR_INFEASIBLE (TS_ERR_PRECISION where the best
 * gap is positive but not above its guard) with a_i = a0 again. */
ts_status ts__repair_search(const ts__repair_ops *o, size_t i, double al, double a0, double t);
/* Certify intervals [i0, i1) of a shape spline (shape != TS_SHAPE_NONE; their controls set), raising
 * beta_i where a gap is not positive; in order.  The C¹ form steps back after
 * a repair: call it once on [0, n).  After the last range ts__certify_done
 * sets certified and have_certs. */
ts_status ts__certify_range(ts_spline *sp, const ts_spline_options *opt, size_t i0, size_t i1,
                            ts_error *err);
void ts__certify_done(ts_spline *sp, const ts_spline_options *opt);

/* ---- constrain.c (docs/method.md §13) ------------------------------------ */
/* Records of opt (n_constraints > 0) valid for n intervals: TS_ERR_NULL,
 * TS_ERR_OPTION (also a form other than geometric, a shape), TS_ERR_VERSION,
 * TS_ERR_NONFINITE, TS_ERR_UNSORTED, TS_ERR_LENGTH; fail (may be NULL) too. */
/* §12.6: the largest |mean − lo| of a bin ts_histo_new accepts (control
 * values stay below 6 times it, TS_VALUE_MAX); beyond, TS_ERR_TOO_LARGE
 * (histo.c; the sentence of errmsg.c) */
#define TS__HISTO_MEAN_MAX 0x1p1019
ts_status ts__con_validate(const ts_spline_options *o, size_t n, ts_error *err,
                           ts_constraint_failure *fail);
/* The data's necessary conditions (TS_ERR_CONDITION) and the slopes d[0..n]
 * (estimates in, constrained out; by[j] the record that changed d_j, −1);
 * TS_ERR_INFEASIBLE where the required slopes exclude each other. */
ts_status ts__con_prepare(const double *x, const double *f, size_t n, const ts_spline_options *o,
                          double *d, int *by, ts_error *err, ts_constraint_failure *fail);
/* Validation and the necessary conditions alone (no slopes, no allocation):
 * the sentence of TS_ERR_CONDITION (errmsg.c). */
ts_status ts__con_conditions(const double *x, const double *f, size_t n,
                             const ts_spline_options *o, ts_constraint_failure *fail);
/* docs/method.md §13.1 curvature-slope: record k's slope rule at knot j
 * (its scope) against every convex / concave record's secant there: 1 when
 * they exclude each other, *kc that record, *iv its interval (j − 1 or j),
 * *slope the rule's slope (rounded); else 0.  x, f, cs validated. */
int ts__con_knot_conflict(const double *x, const double *f, size_t n, const ts_constraint *cs,
                          size_t nc, size_t k, size_t j, size_t *kc, size_t *iv, double *slope);
#ifdef TS_TEST_HOOKS
/* errmsg.c: the sentence ts_error_message gives for the failure record fl
 * of the data checks, for any record (tests): ctx with x, f, n_points and
 * spline_options set, len > 0; 0 (buf "") when fl names nothing those
 * data and validated records have, else the sentence's length. */
size_t ts__failure_message(const ts_constraint_failure *fl, const ts_error_context *ctx, char *buf,
                           size_t len);
#endif
/* beta[0..n) from the closed-form requirements; bind[i] the record that set it. */
void ts__con_betas(const double *x, const double *f, size_t n, const ts_spline_options *o,
                   const double *d, double *beta, int *bind);
/* Certify every interval against the records, doubling a_i where one
 * fails (controls recomputed; the caller recomputes the integrals);
 * TS_ERR_UNPROVEN. */
ts_status ts__con_certify(ts_spline *sp, const ts_constraint *cs, size_t nc, ts_error *err,
                          ts_constraint_failure *fail);
/* The report of stored record k on interval i (struct_size checked by the caller). */
void ts__con_report(const ts_spline *sp, size_t k, size_t i, ts_constraint_report *rep);

/* ==== L4 ============================================================ */

/* ---- surface.c (docs/method.md §11.7) ---------------------------------------- */
/* TS_ERR_LINES (where none) unless the upper field exceeds the lower one by
 * more than 5 (lo->err + up->err) at every node of the union of their grids
 * and the lines x0, x1, y0, y1 within [x0, x1] × [y0, y1]; the first node
 * that does not into *px, *py (may be NULL); TS_ERR_NOMEM. */
ts_status ts__surf_grids_order(const ts__gbound *lo, const ts__gbound *up, double x0, double x1,
                               double y0, double y1, double *px, double *py, ts_error *err);

/* ---- spline.c --------------------------------------------------------- */
/* The defaults of ts_spline_options (ts_spline_options_init), for the library's own files. */
void ts__options_defaults(ts_spline_options *opt);

/* ---- eval.c ----------------------------------------------------------- */
/* Threads of ts_spline_eval_batch_mt: asked, or if 0 the online processors (1 if
 * that count is not positive), at most 64. */
unsigned ts__mt_threads(unsigned asked, long online);

#if defined(__GNUC__)
#pragma GCC visibility pop
#endif

#endif
