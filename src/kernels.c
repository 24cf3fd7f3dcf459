/* Batch evaluation kernels for every form.
 *
 * ts__fast_batch works on blocks of TS_FAST_BLOCK queries; the block's scratch
 * is on the stack (< 16 KiB), nothing is allocated.
 *  1. check: a sorted block is inside [x0, xn] when its two ends are; an
 *     unsorted one is checked query by query (NaN fails every comparison).
 *     A block with a query outside goes back to eval.c.
 *  2. stage: the interval is ts__locate's (largest i <= n−1 with x_i <= x:
 *     the right-hand one at an inner knot).  A sorted block walks the cursor,
 *     galloping over gaps.  A dense block (runs of TS_FAST_RUN queries per
 *     interval on average) is not staged: its queries are evaluated a
 *     vector's width at a time with the interval's values in registers, the
 *     cursor tested once per vector (sorted_dense; the per-query stores
 *     and loads of the staging bounded the kernel when several queries share
 *     an interval); the same walk stages the geometric form's dense blocks
 *     by whole-vector stores.  A sparse block is staged query by query with the
 *     interval's values in registers.  An unsorted block runs one
 *     branch-free binary search per query, all queries advancing a level at
 *     a time so their cache misses overlap.
 *     Per query: tu = (x − x_i)·w, tv = (x_{i+1} − x)·w, w = (π/2)/h_i, and
 *     B0..B3 — exactly the products eval.c's eval_in forms.
 *  3. evaluate, in straight loops the compiler vectorises, so that a query's
 *     value does not depend on where it sits in the batch: a staged block
 *     always whole (a short one padded) into an aligned buffer, a dense
 *     block's runs in whole vectors (the last one of a run spilling into the
 *     next run's places, or into the buffers' slack): from the nearer
 *     end as eval.c (ϑ = tu or tv <= π/4, no range reduction: docs/method.md §1), sin
 *     and 1 − cos by polynomials, then docs/method.md §2 (value) or (2.1) and its
 *     θ-derivative, times w or w·w (eval_core: every query of every path).
 * Agreement with ts_spline_eval_deriv, derived and checked on 1e7 random points in
 * tests/unit/test_fast.c: measured |fast − plain| <= 3.9ε·M for the value
 * (M = max|B_l| of the interval), 12ε·M·w for S', 35ε·M·w² for S''; a
 * long-double reference finds both paths equally accurate.
 *
 * With GCC or Clang on x86-64 the whole pipeline is also compiled for AVX2+FMA
 * and for AVX-512F and chosen at run time (__builtin_cpu_supports); elsewhere,
 * or with -DTS_FAST_PORTABLE, only the portable C version exists.  The
 * geometric form (docs/method.md §4) stages its intervals' f, d, h, κ, solves
 * X̂(φ) = u for the block (Halley from a model root) and evaluates at φ with
 * the same polynomial sine and cosine (geo_eval_block below). */
#include "internal.h"

#include <math.h>
#include <stddef.h>

#if defined(__GNUC__) && defined(__x86_64__) && !defined(TS_FAST_PORTABLE)
#define TS_FAST_X86 1
#if defined(TS_COVERAGE) /* one copy per object, as TS_INLINE (internal.h) */
#define TS_ALWAYS_INLINE static inline
#else
#define TS_ALWAYS_INLINE static inline __attribute__((always_inline))
#endif
#if defined(__clang__)
#define TS_TARGET_512 "avx512f,fma"
#else /* GCC otherwise keeps 256-bit vectors */
#define TS_TARGET_512 "avx512f,fma,prefer-vector-width=512"
#endif
#else
#define TS_FAST_X86 0
#if defined(__GNUC__) && !defined(TS_COVERAGE) /* Clang for WebAssembly too: want_w, run and geo constant */
#define TS_ALWAYS_INLINE static inline __attribute__((always_inline))
#else
#define TS_ALWAYS_INLINE static inline
#endif
#endif
#if defined(__GNUC__)
#define TS_NOINLINE __attribute__((noinline))
#else
#define TS_NOINLINE
#endif

/* ---- locate ---------------------------------------------------------- */

/* Largest k in [lo, hi−1] with xs[k] <= x, given xs[lo] <= x. */
TS_ALWAYS_INLINE size_t search_range(const double *xs, size_t lo, size_t hi, double x)
{
    size_t len = hi - lo;
    while (len > 1) {
        size_t half = len / 2;
        lo += xs[lo + half] <= x ? half : 0;
        len -= half;
    }
    return lo;
}

/* xs[i+1] <= x, i+1 < n: largest k <= n−1 with xs[k] <= x, by galloping. */
TS_ALWAYS_INLINE size_t gallop(const double *xs, size_t n, size_t i, double x)
{
    size_t lo = i + 1, step = 1;
    while (step < n - lo && xs[lo + step] <= x) {
        lo += step;
        step *= 2;
    }
    size_t hi = step < n - lo ? lo + step : n;
    return search_range(xs, lo, hi, x);
}

/* ---- stage ----------------------------------------------------------- */

/* Per query: θ measured from both ends, tu = (x − x_i)·w and tv = (x_{i+1} − x)·w
 * (w = (π/2)/h_i, dθ/dx; the products eval.c forms), and B0..B3, one array
 * each (the vector loop loads them without shuffles).  The evaluation uses
 * the nearer end, as eval.c: ϑ = min(tu, tv) <= π/4 and, from the right end,
 * the control values reversed (docs/method.md §2: A3(θ) = A0(π/2 − θ),
 * A2(θ) = A1(π/2 − θ)) and dϑ/dθ = −1.  Choosing in the vector loop keeps
 * this loop free of data-dependent branches.  A flat interval (B0 = B1 = B2
 * = B3) is staged with w = 0: ϑ = 0 gives A = (1, 0, 0, 0) exactly, so its
 * value is B0 (Σ A_l need not round to 1 elsewhere) and its derivatives 0,
 * without a test per query. */
#define TS_FAST_RUN 8 /* the widest vector, in doubles: the slack of run-wise arrays */
typedef struct fast_stage {
    double tu[TS_FAST_BLOCK], tv[TS_FAST_BLOCK], w[TS_FAST_BLOCK]; /* w: derivatives only */
    double b0[TS_FAST_BLOCK], b1[TS_FAST_BLOCK], b2[TS_FAST_BLOCK], b3[TS_FAST_BLOCK];
} fast_stage;

typedef struct fast_iv {
    double x0, x1, w, b0, b1, b2, b3;
} fast_iv;

/* h_i = x_{i+1} − x_i from the knots at hand, bitwise ts__h (internal.h):
 * a random query reads one cache line fewer. */
TS_ALWAYS_INLINE fast_iv fast_interval(const ts_spline *sp, size_t i)
{
    double x0 = sp->x[i], x1 = sp->x[i + 1];
    fast_iv v = {x0, x1, TS_HALF_PI / (x1 - x0), sp->f[i], sp->b1[i], sp->b2[i], sp->f[i + 1]};
    v.w = ((v.b0 == v.b1) & (v.b1 == v.b2) & (v.b2 == v.b3)) ? 0.0 : v.w; /* &: no branch */
    return v;
}

TS_ALWAYS_INLINE void stage_one(fast_stage *st, size_t j, double x, const fast_iv *v, int want_w)
{
    st->tu[j] = (x - v->x0) * v->w;
    st->tv[j] = (v->x1 - x) * v->w;
    if (want_w)
        st->w[j] = v->w;
    st->b0[j] = v->b0;
    st->b1[j] = v->b1;
    st->b2[j] = v->b2;
    st->b3[j] = v->b3;
}

/* Sorted q[0..nb), xs[i] <= q[0], a sparse block: walk the cursor with the
 * current interval's values in registers, staging query by query. */
TS_ALWAYS_INLINE size_t stage_sorted_sparse(const ts_spline *sp, const double *q, size_t nb, int want_w,
                                            fast_stage *st, size_t i)
{
    const double *xs = sp->x;
    size_t n = sp->n;
    fast_iv v = fast_interval(sp, i);
    double next = i + 1 < n ? v.x1 : (double)INFINITY; /* the last interval never advances */
    for (size_t j = 0; j < nb; j++) {
        double x = q[j];
        if (x >= next) {
            i++;
            if (i + 1 < n && xs[i + 1] <= x)
                i = gallop(xs, n, i, x);
            v = fast_interval(sp, i);
            next = i + 1 < n ? v.x1 : (double)INFINITY;
        }
        stage_one(st, j, x, &v, want_w);
    }
    return i;
}

/* The geometric form (docs/method.md §4), per query as geometric.c's
 * ts__geo_eval: the distances to both ends, the interval's h, κ = 2/(3π a),
 * f_i, f_{i+1}, d_i, d_{i+1}.  phi, u: the solve's scratch; s, c, ms, mc:
 * sin φ, cos φ, 1 − sin φ, 1 − cos φ at its root. */
typedef struct geo_stage {
    double dl[TS_FAST_BLOCK + TS_FAST_RUN], dr[TS_FAST_BLOCK + TS_FAST_RUN];
    double h[TS_FAST_BLOCK + TS_FAST_RUN], kappa[TS_FAST_BLOCK + TS_FAST_RUN];
    double f0[TS_FAST_BLOCK + TS_FAST_RUN], f1[TS_FAST_BLOCK + TS_FAST_RUN];
    double d0[TS_FAST_BLOCK + TS_FAST_RUN], d1[TS_FAST_BLOCK + TS_FAST_RUN];
    double phi[TS_FAST_BLOCK], u[TS_FAST_BLOCK];
    double s[TS_FAST_BLOCK], c[TS_FAST_BLOCK], ms[TS_FAST_BLOCK], mc[TS_FAST_BLOCK];
    double more[TS_FAST_BLOCK]; /* 1: the query's step was not small (geo_any_more) */
} geo_stage;

typedef struct geo_iv {
    double x0, x1, h, kappa, f0, f1, d0, d1;
} geo_iv;

/* h_i from the knots as fast_interval. */
TS_ALWAYS_INLINE geo_iv geo_interval(const ts_spline *sp, size_t i)
{
    double x0 = sp->x[i], x1 = sp->x[i + 1];
    geo_iv g = {x0, x1, x1 - x0, sp->kappa[i], sp->f[i], sp->f[i + 1], sp->d[i], sp->d[i + 1]};
    return g;
}

TS_ALWAYS_INLINE void geo_stage_one(geo_stage *st, size_t j, double x, const geo_iv *g)
{
    st->dl[j] = x - g->x0;
    st->dr[j] = g->x1 - x;
    st->h[j] = g->h;
    st->kappa[j] = g->kappa;
    st->f0[j] = g->f0;
    st->f1[j] = g->f1;
    st->d0[j] = g->d0;
    st->d1[j] = g->d1;
}

/* Sorted, sparse: stage_sorted_sparse for the geometric form. */
TS_ALWAYS_INLINE size_t geo_stage_sorted_sparse(const ts_spline *sp, const double *q, size_t nb,
                                                geo_stage *st, size_t i)
{
    const double *xs = sp->x;
    size_t n = sp->n;
    geo_iv g = geo_interval(sp, i);
    double next = i + 1 < n ? g.x1 : (double)INFINITY;
    for (size_t j = 0; j < nb; j++) {
        double x = q[j];
        if (x >= next) {
            i++;
            if (i + 1 < n && xs[i + 1] <= x)
                i = gallop(xs, n, i, x);
            g = geo_interval(sp, i);
            next = i + 1 < n ? g.x1 : (double)INFINITY;
        }
        geo_stage_one(st, j, x, &g);
    }
    return i;
}

/* ---- evaluate -------------------------------------------------------- */

/* s = sin ϑ, c = cos ϑ, ms = 1 − s, mc = 1 − c for ϑ in [0, π/4]: internal.h. */
#define fast_trig ts__sincos_q

/* One query from its nearer end: ϑ = min(tu, tv), left = tu <= tv (dϑ/dθ =
 * ±1) and the control values B' seen from that end as B'0 and differences:
 * e1, e2, e3 = B'1 − B'0, B'2 − B'0, B'3 − B'0 for the value (docs/method.md
 * §2, the expressions of ts__seg_scm: B0 + Σ A_l (B_l − B0)), B'1 − B'0,
 * B'2 − B'1, B'3 − B'2 for S' by (2.1) and S'' by its θ-derivative; deriv a
 * constant at each call.  eval_block forms the differences per query,
 * run_interval once per interval and end (the same subtractions, so the same
 * bits). */
TS_ALWAYS_INLINE double eval_core(int deriv, double tu, double tv, double w, double B0, double e1, double e2,
                                  double e3)
{
    int left = tu <= tv;
    double s, c, ms, mc;
    fast_trig(tv < tu ? tv : tu, &s, &c, &ms, &mc); /* minpd: left ? tu : tv */
    if (deriv == 0)
        return B0 + ((s * ms * (3.0 - s)) * e1 + (c * mc * (3.0 - c)) * e2 + (mc * mc * mc) * e3);
    if (deriv == 1) {
        double d = 3.0 * (ms * ms) * c * e1 + 2.0 * (s * c) * e2 + 3.0 * (mc * mc) * s * e3;
        return d * (left ? w : -w);
    }
    double a0 = 6.0 * ms * (c * c) + 3.0 * (ms * ms) * s;
    double a3 = 6.0 * mc * (s * s) + 3.0 * (mc * mc) * c;
    double d = (a3 * e3 - a0 * e1) + 2.0 * ((c * c - s * s) * e2);
    return d * (w * w);
}

/* eval_core of one staged query */
TS_ALWAYS_INLINE double eval_one(int deriv, double tu, double tv, double w, double b0, double b1, double b2,
                                 double b3)
{
    int left = tu <= tv;
    double B0 = left ? b0 : b3, B1 = left ? b1 : b2;
    double B2 = left ? b2 : b1, B3 = left ? b3 : b0;
    if (deriv == 0)
        return eval_core(0, tu, tv, w, B0, B1 - B0, B2 - B0, B3 - B0);
    return eval_core(deriv, tu, tv, w, B0, B1 - B0, B2 - B1, B3 - B2);
}

/* deriv a constant at each call */
TS_ALWAYS_INLINE void eval_loop(int deriv, const fast_stage *st, size_t nb, double *y)
{
    for (size_t j = 0; j < nb; j++)
        y[j] = eval_one(deriv, st->tu[j], st->tv[j], deriv > 0 ? st->w[j] : 0.0, st->b0[j], st->b1[j], st->b2[j],
                        st->b3[j]);
}

TS_ALWAYS_INLINE void eval_block(int deriv, const fast_stage *st, size_t nb, double *y)
{
    if (deriv == 0)
        eval_loop(0, st, nb, y);
    else if (deriv == 1)
        eval_loop(1, st, nb, y);
    else
        eval_loop(2, st, nb, y);
}

/* Per-interval constants of a dense block's lanes (sorted_dense): x_i,
 * x_{i+1}, w, and B'0 and the differences from either end (eval_one's,
 * formed once per interval). */
typedef struct run_iv {
    double x0, x1, w, b0, b3, l1, l2, l3, r1, r2, r3;
} run_iv;

TS_ALWAYS_INLINE run_iv run_interval(const ts_spline *sp, int deriv, size_t i)
{
    fast_iv v = fast_interval(sp, i);
    double b0 = v.b0, b1 = v.b1, b2 = v.b2, b3 = v.b3;
    double l1 = b1 - b0, l2 = deriv ? b2 - b1 : b2 - b0, l3 = deriv ? b3 - b2 : b3 - b0;
    double r1 = b2 - b3, r2 = deriv ? b1 - b2 : b1 - b3, r3 = deriv ? b0 - b1 : b0 - b3;
    run_iv r = {v.x0, v.x1, v.w, b0, b3, l1, l2, l3, r1, r2, r3};
    return r;
}

/* One lane of a dense block: query x_ of interval r into y_. */
#define TS_RUN_LANE(deriv, r, x_, y_)                                                          \
    do {                                                                                       \
        double x = (x_), tu = (x - (r).x0) * (r).w, tv = ((r).x1 - x) * (r).w;                 \
        int left = tu <= tv;                                                                   \
        (y_) = eval_core(deriv, tu, tv, (r).w, left ? (r).b0 : (r).b3, left ? (r).l1 : (r).r1, \
                         left ? (r).l2 : (r).r2, left ? (r).l3 : (r).r3);                      \
    } while (0)

/* Sorted q[0..nb), xs[i] <= q[0], a dense block (long runs): a vector's
 * width (run) of queries at a time with the current interval's values in
 * registers, evaluated (gs NULL: eval_core in each lane, as eval_block) or,
 * for the geometric form, staged into gs (geo_stage_one's values by
 * whole-vector stores), while the next vector's first query is below the
 * next knot (one compare per vector, not per query); the vector that
 * reaches it is taken up to the first query at or above it, k (its lanes
 * from k on are done again in their interval), counted without a branch
 * but in the block's last vector.  That vector spills into the slack of q,
 * y and gs (TS_FAST_RUN places).  gs and deriv are constants at each call.
 * The lane loop carries GCC unroll 1: GCC 12 unrolled it at some places
 * into scalar code with other contractions (other bits). */
#if defined(__wasm__)
/* emscripten's Clang vectorises the lanes of a whole run in one loop, not
 * those of one vector (no fused multiply-add there: the bits do not depend
 * on the loop's shape): the run is evaluated after its walk */
#define TS_RUN_AFTER 1
#else
#define TS_RUN_AFTER 0
#endif
#define TS_RUN_VECTOR(j_)                                            \
    do {                                                             \
        if (gs) {                                                    \
            for (size_t l = 0; l < run; l++) {                       \
                double x = q[(j_) + l];                              \
                gs->dl[(j_) + l] = x - g.x0;                         \
                gs->dr[(j_) + l] = g.x1 - x;                         \
                gs->h[(j_) + l] = g.h;                               \
                gs->kappa[(j_) + l] = g.kappa;                       \
                gs->f0[(j_) + l] = g.f0;                             \
                gs->f1[(j_) + l] = g.f1;                             \
                gs->d0[(j_) + l] = g.d0;                             \
                gs->d1[(j_) + l] = g.d1;                             \
            }                                                        \
        } else {                                                     \
            _Pragma("GCC unroll 1") for (size_t l = 0; l < run; l++) \
                TS_RUN_LANE(deriv, r, q[(j_) + l], y[(j_) + l]);     \
        }                                                            \
    } while (0)
TS_ALWAYS_INLINE size_t sorted_dense(const ts_spline *sp, int deriv, const double *q, size_t nb,
                                     double *y, geo_stage *gs, size_t i, size_t run)
{
    const double *xs = sp->x;
    size_t n = sp->n, j = 0;
    /* dense (stage_block): every query is below xs[probe] with probe < n, so
     * the walk stays in intervals below probe and i + 1 <= probe < n: the
     * next knot always exists and the last interval is never reached */
    double next = xs[i + 1];
    for (;;) {
        run_iv r = {0};
        geo_iv g = {0};
        if (gs)
            g = geo_interval(sp, i);
        else
            r = run_interval(sp, deriv, i);
        size_t j0 = j;
        int more;
        do {
            size_t e = j + run, k = e;
            more = e < nb && q[e] < next; /* the next vector starts in this interval too */
            if (!more) {
                k = j; /* the first query at or above the next knot */
                if (e <= nb)
                    for (size_t l = 0; l < run; l++)
                        k += q[j + l] < next;
                else /* the block's last vector: its lanes past nb are slack */
                    while (k < nb && q[k] < next)
                        k++;
            }
            if (gs || !TS_RUN_AFTER)
                TS_RUN_VECTOR(j);
            j = k;
        } while (more);
        if (!gs && TS_RUN_AFTER) /* the run q[j0..j) in one loop over whole vectors */
            for (size_t l = j0; l < j0 + (j - j0 + run - 1) / run * run; l++)
                TS_RUN_LANE(deriv, r, q[l], y[l]);
        if (j >= nb)
            return i;
        i++;
        if (xs[i + 1] <= q[j])
            i = gallop(xs, n, i, q[j]);
        next = xs[i + 1];
    }
}
#undef TS_RUN_VECTOR
#undef TS_RUN_AFTER
#undef TS_RUN_LANE

/* Every q[j] in [x0, xn] (none NaN). */
TS_ALWAYS_INLINE int all_inside(const double *q, size_t nb, double x0, double xn)
{
    double outside = 0.0; /* a double flag: this form vectorises */
    for (size_t j = 0; j < nb; j++)
        outside = x0 <= q[j] && q[j] <= xn ? outside : 1.0;
    return outside == 0.0;
}

/* Stages q[0..nb) (1 <= nb <= TS_FAST_BLOCK) into st, or into gs for the
 * geometric form (gs != NULL), and returns 1; a dense sorted block of the
 * other forms is evaluated into y instead (sorted_dense; q and y with
 * TS_FAST_RUN places of slack), returning 2; *cur is the cursor, left on the
 * last query's interval.  Returns 0, without staging, if a query is outside
 * [x0, xn] or NaN. */
TS_ALWAYS_INLINE int stage_block(const ts_spline *sp, const double *q, size_t nb, int deriv,
                                 fast_stage *st, geo_stage *gs, double *y, size_t *cur, size_t run)
{
    int want_w = deriv > 0;
    const double *xs = sp->x;
    size_t n = sp->n, i = *cur;
    /* flags kept as doubles: this form vectorises */
    /* sorted (a NaN fails every comparison, so counts as unsorted): the ends
     * tell whether all are inside [x0, xn]; otherwise each query is checked */
    double x0 = xs[0], xn = xs[n], unsorted = 0.0; /* a double flag: this form vectorises */
    for (size_t j = 1; j < nb; j++)
        unsorted = q[j - 1] <= q[j] ? unsorted : 1.0;
    if (unsorted == 0.0 ? !(x0 <= q[0] && q[nb - 1] <= xn) : !all_inside(q, nb, x0, xn))
        return 0;
    if (unsorted == 0.0) {
        if (!(xs[i] <= q[0]))
            i = search_range(xs, 0, i + 1, q[0]);
        /* dense: the block ends before knot i + nb/TS_FAST_RUN, so its runs
         * average at least TS_FAST_RUN queries; the staging by runs pays
         * there (and costs 15 % at one query per interval) */
        size_t probe = i + nb / TS_FAST_RUN;
        int dense = probe < n && q[nb - 1] < xs[probe];
        if (gs)
            *cur = dense ? sorted_dense(sp, 0, q, nb, NULL, gs, i, run) : geo_stage_sorted_sparse(sp, q, nb, gs, i);
        else if (dense) {
            *cur = deriv == 0   ? sorted_dense(sp, 0, q, nb, y, NULL, i, run)
                   : deriv == 1 ? sorted_dense(sp, 1, q, nb, y, NULL, i, run)
                                : sorted_dense(sp, 2, q, nb, y, NULL, i, run);
            return 2;
        } else
            *cur = want_w ? stage_sorted_sparse(sp, q, nb, 1, st, i)
                          : stage_sorted_sparse(sp, q, nb, 0, st, i);
        return 1;
    }
    /* one binary search per query, all advancing a level at a time */
    size_t idx[TS_FAST_BLOCK];
    for (size_t j = 0; j < nb; j++)
        idx[j] = 0;
    for (size_t len = n; len > 1;) {
        size_t half = len / 2;
        for (size_t j = 0; j < nb; j++)
            idx[j] += xs[idx[j] + half] <= q[j] ? half : 0;
        len -= half;
    }
    for (size_t j = 0; j < nb; j++) {
        i = idx[j];
        if (gs) {
            geo_iv g = geo_interval(sp, i);
            geo_stage_one(gs, j, q[j], &g);
        } else {
            fast_iv v = fast_interval(sp, i);
            stage_one(st, j, q[j], &v, want_w);
        }
    }
    *cur = i;
    return 1;
}

/* The geometric form: solve X̂(φ) = u for φ in [0, π/4] (u = distance to
 * the nearer end / h; geometric.c), all queries of the block a step at a
 * time.  Start: ts__geo_start (internal.h: one Newton step on a quartic
 * model of X̂; within 3.0e-3 of the root for a_i >= 1, 6.7e-2 for
 * a_i >= 4/(3π)).  Then Halley steps on X̂ with the polynomial sine and
 * cosine, at least two, until every step of the block is below 2^-20 φ (Halley's error
 * after such a step is of the order of its cube: rounding; two steps for
 * κ <= 0.4, three for some u up to κ = 1/2).  The last step is applied to
 * (sin φ, cos φ) by its Taylor rotation (|e| <= 2^-20: the dropped e³/6 is
 * below 2^-62), so the evaluation needs no further sine.  Every query stops
 * within TS_GEO_PASSES steps but one with a subnormal u, which takes the
 * last iterate (ts__geo_root, internal.h: the same steps, which single
 * evaluation runs). */

TS_ALWAYS_INLINE void geo_side(const geo_stage *st, size_t j, int *right, double *u)
{
    double dl = st->dl[j], dr = st->dr[j];
    *right = dr < dl;
    *u = (*right ? dr : dl) / st->h[j];
}

/* Whether a query of the block still moves (st->more).  The flag is
 * gathered here, not in the step loops: Clang takes no select of a double
 * as a reduction, so a step loop with it would stay scalar (WebAssembly
 * SIMD128), and GCC has no SSE2 OR reduction of an integer flag as wide. */
TS_ALWAYS_INLINE int geo_any_more(const geo_stage *st, size_t nb)
{
    double open = 0.0; /* a double flag: this loop vectorises with GCC */
    for (size_t j = 0; j < nb; j++)
        open = st->more[j] > 0.0 ? 1.0 : open;
    return open != 0.0;
}

/* Passes p0 .. TS_GEO_PASSES − 1 from st->phi, st->u. */
TS_ALWAYS_INLINE void geo_solve_block(geo_stage *st, size_t nb, int p0)
{
    for (int pass = p0; pass < TS_GEO_PASSES; pass++) {
        for (size_t j = 0; j < nb; j++) {
            /* A query stops at its own first small step (below 2^-20 φ)
             * from the second on, whatever the others of the block still need, so that its value
             * does not depend on them: its φ stays where that step started,
             * and every later pass repeats the same step from there, giving
             * the same bits.  s, c, ms, mc: at the step's end, for the
             * evaluation. */
            double phi = st->phi[j], s, c, ms, mc;
            double next = ts__geo_halley(phi, st->kappa[j], st->u[j], &s, &c, &ms, &mc);
            double more = fabs(next - phi) <= 0x1p-20 * next ? 0.0 : 1.0; /* NaN: 1 */
            st->more[j] = more;
            st->phi[j] = more > 0.0 ? next : phi;
            st->s[j] = s;
            st->c[j] = c;
            st->ms[j] = ms;
            st->mc[j] = mc;
        }
        if (!geo_any_more(st, nb))
            return;
    }
}

/* docs/method.md §4 at the solved φ from the nearer end: the value, or its
 * first or second derivative in x (ts__geo_y, as single evaluation);
 * deriv a constant at each call. */
TS_ALWAYS_INLINE double geo_value(int deriv, const geo_stage *st, size_t j, double s, double c,
                                   double ms, double mc)
{
    int right = st->dr[j] < st->dl[j];
    double f0 = st->f0[j], f1 = st->f1[j], d0 = st->d0[j], d1 = st->d1[j]; /* loads, then selects */
    double F0 = right ? f1 : f0, F1 = right ? f0 : f1;
    double D0 = right ? -d1 : d0, D1 = right ? -d0 : d1;
    return ts__geo_y(deriv, F0, F1, D0, D1, st->h[j], st->kappa[j], right, s, c, ms, mc);
}

/* geo_value of every query at its stored (s, c, ms, mc). */
TS_ALWAYS_INLINE void geo_values(int deriv, const geo_stage *st, size_t nb, double *y)
{
    for (size_t j = 0; j < nb; j++)
        y[j] = geo_value(deriv, st, j, st->s[j], st->c[j], st->ms[j], st->mc[j]);
}

/* What nearly every query needs, with the fewest arrays between loops
 * (docs/method.md §4): u and the start; the first Halley step, untested
 * (ts__geo_root); the second step, its stop test and the value.  (One loop
 * for all of it is not vectorised by GCC 12: jump threading leaves control
 * flow in it.)  A query whose second step is not small (some u at κ above
 * 0.4) leaves the block to geo_solve_block's remaining passes from where
 * ts__geo_root takes its third step, and the whole block's values are then
 * formed again (a stopped query repeats its stopping step from where it
 * started: the same bits). */
TS_ALWAYS_INLINE void geo_fused(int deriv, geo_stage *st, size_t nb, double *y)
{
    for (size_t j = 0; j < nb; j++) {
        int right;
        double u;
        geo_side(st, j, &right, &u);
        st->u[j] = u;
        st->phi[j] = ts__geo_start(u, st->kappa[j]);
    }
    for (size_t j = 0; j < nb; j++) {
        double s, c, ms, mc;
        st->phi[j] = ts__geo_halley(st->phi[j], st->kappa[j], st->u[j], &s, &c, &ms, &mc);
    }
    for (size_t j = 0; j < nb; j++) {
        double k = st->kappa[j], s, c, ms, mc, phi1 = st->phi[j];
        double phi2 = ts__geo_halley(phi1, k, st->u[j], &s, &c, &ms, &mc);
        double more = fabs(phi2 - phi1) <= 0x1p-20 * phi2 ? 0.0 : 1.0; /* NaN: 1 */
        st->more[j] = more;
        st->phi[j] = more > 0.0 ? phi2 : phi1;
        y[j] = geo_value(deriv, st, j, s, c, ms, mc);
    }
    if (!geo_any_more(st, nb))
        return;
    geo_solve_block(st, nb, 2);
    geo_values(deriv, st, nb, y);
}

/* deriv a constant in each loop */
TS_ALWAYS_INLINE void geo_eval_block(int deriv, geo_stage *st, size_t nb, double *y)
{
    if (deriv == 0)
        geo_fused(0, st, nb, y);
    else if (deriv == 1)
        geo_fused(1, st, nb, y);
    else
        geo_fused(2, st, nb, y);
}

/* Fills the stage's unused places [nb, TS_FAST_BLOCK) with its first query. */
TS_ALWAYS_INLINE void geo_pad(geo_stage *st, size_t nb)
{
    for (size_t j = nb; j < TS_FAST_BLOCK; j++) {
        st->dl[j] = st->dl[0];
        st->dr[j] = st->dr[0];
        st->h[j] = st->h[0];
        st->kappa[j] = st->kappa[0];
        st->f0[j] = st->f0[0];
        st->f1[j] = st->f1[0];
        st->d0[j] = st->d0[0];
        st->d1[j] = st->d1[0];
    }
}

/* q[0..nb) with TS_FAST_RUN places of slack (sorted_dense): the batch's
 * next queries (left places of it), or at its end a copy in qt. */
TS_ALWAYS_INLINE const double *pad_queries(const double *q, size_t nb, size_t left, double *qt)
{
    if (left >= nb + TS_FAST_RUN)
        return q;
    for (size_t j = 0; j < nb; j++)
        qt[j] = q[j];
    for (size_t j = nb; j < TS_FAST_BLOCK + TS_FAST_RUN; j++)
        qt[j] = qt[nb - 1];
    return qt;
}

/* The whole batch, or its prefix up to the first block with a query outside
 * [x0, xn]; *cur is the cursor; returns the number of queries evaluated. */
TS_ALWAYS_INLINE size_t pipeline(const ts_spline *sp, int deriv, const double *xq, size_t m,
                                 double *yq, size_t *cur, int geo, size_t run)
{
    union {
        fast_stage p;
        geo_stage g;
    } st;
    _Alignas(64) double yt[TS_FAST_BLOCK + TS_FAST_RUN], qt[TS_FAST_BLOCK + TS_FAST_RUN];
    size_t j0 = 0;
    if (geo) {
        while (j0 < m) {
            size_t nb = m - j0 < TS_FAST_BLOCK ? m - j0 : TS_FAST_BLOCK;
            const double *q = pad_queries(xq + j0, nb, m - j0, qt); /* as below */
            if (!stage_block(sp, q, nb, 0, NULL, &st.g, NULL, cur, run))
                break;
            geo_pad(&st.g, nb); /* as below */
            geo_eval_block(deriv, &st.g, TS_FAST_BLOCK, yt);
            for (size_t j = 0; j < nb; j++)
                yq[j0 + j] = yt[j];
            j0 += nb;
        }
        return j0;
    }
    while (j0 < m) {
        size_t nb = m - j0 < TS_FAST_BLOCK ? m - j0 : TS_FAST_BLOCK;
        const double *q = pad_queries(xq + j0, nb, m - j0, qt);
        int got = stage_block(sp, q, nb, deriv, &st.p, NULL, yt, cur, run);
        if (!got)
            break;
        if (got == 2) {
            for (size_t j = 0; j < nb; j++)
                yq[j0 + j] = yt[j];
            j0 += nb;
            continue;
        }
        /* A short block is padded with its first query and every block is
         * evaluated whole into an aligned buffer: no loop tail and no
         * alignment peel, so each query runs the same instructions wherever
         * it sits in the batch (split batches, threads and chunked callers
         * agree bit for bit). */
        for (size_t j = nb; j < TS_FAST_BLOCK; j++) {
            st.p.tu[j] = st.p.tu[0];
            st.p.tv[j] = st.p.tv[0];
            st.p.w[j] = deriv > 0 ? st.p.w[0] : 0.0;
            st.p.b0[j] = st.p.b0[0];
            st.p.b1[j] = st.p.b1[0];
            st.p.b2[j] = st.p.b2[0];
            st.p.b3[j] = st.p.b3[0];
        }
        eval_block(deriv, &st.p, TS_FAST_BLOCK, yt);
        for (size_t j = 0; j < nb; j++)
            yq[j0 + j] = yt[j];
        j0 += nb;
    }
    return j0;
}

typedef size_t (*pipeline_fn)(const ts_spline *, int, const double *, size_t, double *, size_t *);

/* Per ISA, the geometric form's pipeline and the others' in functions of
 * their own (one's loops do not change the other's register allocation),
 * with the ISA's vector width in doubles as sorted_dense's run (AVX-512:
 * 8 measured faster than 4);
 * pick chooses by ISA and form. */
#define TS_PIPELINE_ARGS const ts_spline *sp, int deriv, const double *xq, size_t m, double *yq, size_t *cur
static TS_NOINLINE size_t pipeline_geo_portable(TS_PIPELINE_ARGS)
{
    return pipeline(sp, deriv, xq, m, yq, cur, 1, 2);
}

static TS_NOINLINE size_t pipeline_trig_portable(TS_PIPELINE_ARGS)
{
    return pipeline(sp, deriv, xq, m, yq, cur, 0, 2);
}

#if TS_FAST_X86
__attribute__((target("avx2,fma"))) static TS_NOINLINE size_t pipeline_geo_avx2(TS_PIPELINE_ARGS)
{
    return pipeline(sp, deriv, xq, m, yq, cur, 1, 4);
}

__attribute__((target("avx2,fma"))) static TS_NOINLINE size_t pipeline_trig_avx2(TS_PIPELINE_ARGS)
{
    return pipeline(sp, deriv, xq, m, yq, cur, 0, 4);
}

__attribute__((target(TS_TARGET_512))) static TS_NOINLINE size_t pipeline_geo_avx512(TS_PIPELINE_ARGS)
{
    return pipeline(sp, deriv, xq, m, yq, cur, 1, 8);
}

__attribute__((target(TS_TARGET_512))) static TS_NOINLINE size_t pipeline_trig_avx512(TS_PIPELINE_ARGS)
{
    return pipeline(sp, deriv, xq, m, yq, cur, 0, 8);
}
#endif

/* not inlined: one copy, whose every branch the unit test takes */
TS_NOINLINE int ts__fast_pick(int isa, int has2, int has512)
{
    if (isa < -1 || isa > 2)
        return -1;
    if ((isa == -1 || isa == 2) && has512)
        return 2;
    if ((isa == -1 || isa == 1) && has2)
        return 1;
    return isa <= 0 ? 0 : -1;
}

/* The kernel ts__fast_pick chooses on this CPU for the form's family
 * (geo: ts__form_ops.kernel); NULL if none. */
static TS_NOINLINE pipeline_fn pick(int isa, int geo)
{
#if TS_FAST_X86
    static const pipeline_fn fn[3][2] = {{pipeline_trig_portable, pipeline_geo_portable},
                                         {pipeline_trig_avx2, pipeline_geo_avx2},
                                         {pipeline_trig_avx512, pipeline_geo_avx512}};
    __builtin_cpu_init();
    /* & rather than &&: no branch on a CPU feature, so every path runs on any CPU */
    int has2 = (__builtin_cpu_supports("avx2") != 0) & (__builtin_cpu_supports("fma") != 0);
    int has512 = has2 & (__builtin_cpu_supports("avx512f") != 0);
#else
    static const pipeline_fn fn[3][2] = {{pipeline_trig_portable, pipeline_geo_portable}, {NULL, NULL}, {NULL, NULL}};
    int has2 = 0, has512 = 0;
#endif
    int k = ts__fast_pick(isa, has2, has512);
    return k < 0 ? NULL : fn[k][geo != 0];
}

static size_t batch(const ts_spline *sp, int deriv, const double *xq, size_t m, double *yq,
                    ts_cursor *cur, pipeline_fn fn)
{
    size_t i = cur && cur->interval < sp->n ? cur->interval : 0;
    size_t done = fn(sp, deriv, xq, m, yq, &i);
    if (cur && done)
        cur->interval = i;
    return done;
}

size_t ts__fast_batch(const ts_spline *sp, int deriv, const double *xq, size_t m,
                      double *yq, ts_cursor *cur)
{
    return batch(sp, deriv, xq, m, yq, cur, pick(-1, ts__form(sp->form)->kernel));
}

int ts__fast_batch_isa(const ts_spline *sp, int deriv, const double *xq, size_t m,
                       double *yq, ts_cursor *cur, int isa, size_t *done)
{
    pipeline_fn fn = pick(isa, ts__form(sp->form)->kernel);
    if (!fn)
        return 0;
    size_t k = batch(sp, deriv, xq, m, yq, cur, fn);
    if (done)
        *done = k;
    return 1;
}
