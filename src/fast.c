/* Batch evaluation kernels for the paper and C¹ forms (issue 6).
 *
 * ts__fast_batch works on blocks of TS_FAST_BLOCK queries:
 *  1. locate: a sorted block walks the cursor forward (galloping over gaps);
 *     an unsorted block runs one branch-free binary search per query, level
 *     by level over the whole block, so the cache misses of different
 *     queries overlap.  Same interval as ts__locate (largest i <= n-1 with
 *     x_i <= x: the right-hand interval at an inner knot).
 *  2. gather x_i, w_i = (π/2)/h_i (sp->fast, TS_FAST_STRIDE = 1), f_i, B1, B2,
 *     f_{i+1} into arrays on the stack (bounded: no allocation).
 *  3. a straight loop the compiler vectorises:
 *       θ = (x − x_i)·w_i                          (bitwise as eval.c)
 *       u = θ/2 ∈ [0, π/4]  (SPEC §1), z = u²
 *       σ = sin u, γ = cos u by the polynomials of bench/sincos_coeffs.py
 *           (truncation ≤ 5.4e-18; no range reduction needed)
 *       s = 2σγ,  c = (γ−σ)(γ+σ),  1−s = (γ−σ)²,  1−c = 2σ²   (no cancellation)
 *       S   = B0 + (1 − (1−s)³)(B1−B0) + s²(B2−B1) + (1−c)³(B3−B2)
 *             (Abel sum of SPEC §2: A1+A2+A3 = 1 − A0, A2+A3 = s², A3 = (1−c)³)
 *       S'  = 3(1−s)²c(B1−B0) + 2sc(B2−B1) + 3(1−c)²s(B3−B2)        SPEC (2.1)
 *       S'' = −(6(1−s)c² + 3(1−s)²s)(B1−B0) + 2(c²−s²)(B2−B1)
 *             + (6(1−c)s² + 3(1−c)²c)(B3−B2)
 *     times w (S') or w·w (S''), as eval.c.
 *
 * Agreement with ts_eval_deriv (bound derived in tests/test_fast.c, checked
 * there on 1e7 random points): |fast − plain| ≤ 8 ε·M for the value,
 * ≤ 8 ε·M·w for S', ≤ 16 ε·M·w² for S'', with ε = 2⁻⁵², M = max|B_l| of the
 * interval.  Measured maxima are printed by that test.
 *
 * On x86-64 with GCC or Clang the block kernel is also compiled for AVX2+FMA
 * and AVX-512F and picked at run time (__builtin_cpu_supports); everywhere
 * else, and with -DTS_FAST_PORTABLE, only the portable C version exists.
 * The geometric form (SPEC §4) is evaluated point by point by eval.c's path. */
#include "ts_internal.h"

#include <math.h>
#include <stddef.h>

#define TS_FAST_BLOCK 128

#if defined(__GNUC__) && defined(__x86_64__) && !defined(TS_FAST_PORTABLE)
#define TS_FAST_X86 1
#define TS_ALWAYS_INLINE static inline __attribute__((always_inline))
#else
#define TS_FAST_X86 0
#define TS_ALWAYS_INLINE static inline
#endif

/* π/2 = TS_PIO2_HI + TS_PIO2_LO to ~1e-33 */
#define TS_PIO2_HI 1.5707963267948966
#define TS_PIO2_LO 6.123233995736766e-17
/* bench/sincos_coeffs.py: sin u ≈ u + u z P(z), 1 − cos u ≈ z/2 − z² Q(z), u in [0, π/4] */
#define TS_S1 -0.16666666666666605
#define TS_S2 0.008333333333317107
#define TS_S3 -0.00019841269826329964
#define TS_S4 2.7557312659276103e-06
#define TS_S5 -2.5050615702547473e-08
#define TS_S6 1.5889377748304707e-10
#define TS_C1 0.0416666666666666
#define TS_C2 -0.0013888888888874372
#define TS_C3 2.4801587289632665e-05
#define TS_C4 -2.7557314394461076e-07
#define TS_C5 2.0875728820037434e-09
#define TS_C6 -1.1359926181679004e-11

void ts__fast_prepare(ts_spline *sp)
{
    /* same expression as eval.c's eval_in, so θ is bitwise identical */
    for (size_t i = 0; i < sp->n; i++)
        sp->fast[i] = TS_HALF_PI / sp->h[i];
}

/* ---- locate ---------------------------------------------------------- */

/* Largest k in [lo, hi-1] with xs[k] <= x, given xs[lo] <= x. */
static size_t search_range(const double *xs, size_t lo, size_t hi, double x)
{
    size_t len = hi - lo;
    while (len > 1) {
        size_t half = len / 2;
        lo += xs[lo + half] <= x ? half : 0;
        len -= half;
    }
    return lo;
}

/* xs[i+1] <= x, i+1 < n: largest k <= n-1 with xs[k] <= x, by galloping. */
static size_t gallop(const double *xs, size_t n, size_t i, double x)
{
    size_t lo = i + 1, step = 1;
    while (step < n - lo && xs[lo + step] <= x) {
        lo += step;
        step *= 2;
    }
    size_t hi = step < n - lo ? lo + step : n;
    return search_range(xs, lo, hi, x);
}

/* Per query of a block: θ = (x − x_i)·w_i, w_i (derivatives only) and the
 * interval's control values B0..B3. */
typedef struct fast_stage {
    double th[TS_FAST_BLOCK], w[TS_FAST_BLOCK];
    double c0[TS_FAST_BLOCK], c1[TS_FAST_BLOCK], c2[TS_FAST_BLOCK], c3[TS_FAST_BLOCK];
} fast_stage;

/* One interval's values, reloaded only when the interval changes. */
typedef struct fast_iv {
    double x0, x1, w, c0, c1, c2, c3;
} fast_iv;

static void load_iv(const ts_spline *sp, size_t i, fast_iv *v)
{
    v->x0 = sp->x[i];
    v->x1 = i + 1 < sp->n ? sp->x[i + 1] : (double)INFINITY; /* the last interval never advances */
    v->w = sp->fast[i];
    v->c0 = sp->f[i];
    v->c1 = sp->b1[i];
    v->c2 = sp->b2[i];
    v->c3 = sp->f[i + 1];
}

/* Stages q[0..nb) into st; i is the cursor; returns the last interval.
 * Sorted block: walk the cursor forward, galloping over gaps.  Otherwise one
 * branch-free binary search per query, all queries advancing one level at a
 * time so that their cache misses overlap. */
static size_t stage_block(const ts_spline *sp, const double *q, size_t nb, int want_w,
                          fast_stage *st, size_t i)
{
    const double *xs = sp->x;
    size_t n = sp->n;
    int sorted = 1;
    for (size_t j = 1; j < nb; j++)
        sorted &= q[j - 1] <= q[j];
    if (sorted) {
        if (!(xs[i] <= q[0]))
            i = search_range(xs, 0, i + 1, q[0]);
        fast_iv v;
        load_iv(sp, i, &v);
        for (size_t j = 0; j < nb; j++) {
            double x = q[j];
            if (x >= v.x1) {
                i++;
                if (i + 1 < n && xs[i + 1] <= x)
                    i = gallop(xs, n, i, x);
                load_iv(sp, i, &v);
            }
            st->th[j] = (x - v.x0) * v.w;
            if (want_w)
                st->w[j] = v.w;
            st->c0[j] = v.c0;
            st->c1[j] = v.c1;
            st->c2[j] = v.c2;
            st->c3[j] = v.c3;
        }
        return i;
    }
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
        fast_iv v;
        load_iv(sp, idx[j], &v);
        st->th[j] = (q[j] - v.x0) * v.w;
        st->w[j] = v.w;
        st->c0[j] = v.c0;
        st->c1[j] = v.c1;
        st->c2[j] = v.c2;
        st->c3[j] = v.c3;
    }
    return idx[nb - 1];
}

/* ---- evaluate -------------------------------------------------------- */

/* s = sin θ, c = cos θ, ms = 1 − s, mc = 1 − c for θ in [0, π/2] (a hair
 * beyond at x = x_{i+1}).  Above π/4 the polynomials take v = π/2 − θ (π/2 in
 * two parts; π/2 − θ is exact there): sin θ = cos v, cos θ = sin v.  1 − cos
 * is summed without the 1, so ms and mc carry no cancellation. */
TS_ALWAYS_INLINE void fast_trig(double th, double *s, double *c, double *ms, double *mc)
{
    double v = (TS_PIO2_HI - th) + TS_PIO2_LO;
    int big = v < th;
    double u = big ? v : th, z = u * u;
    double ps = TS_S1 + z * (TS_S2 + z * (TS_S3 + z * (TS_S4 + z * (TS_S5 + z * TS_S6))));
    double pc = TS_C1 + z * (TS_C2 + z * (TS_C3 + z * (TS_C4 + z * (TS_C5 + z * TS_C6))));
    double sn = u + u * (z * ps);       /* sin u */
    double om = 0.5 * z - (z * z) * pc; /* 1 − cos u */
    double cs = 1.0 - om, oms = 1.0 - sn;
    *s = big ? cs : sn;
    *c = big ? sn : cs;
    *ms = big ? om : oms;
    *mc = big ? oms : om;
}

TS_ALWAYS_INLINE void eval_body(int deriv, const fast_stage *st, size_t nb, double *y)
{
    if (deriv == 0) {
        for (size_t j = 0; j < nb; j++) {
            double s, c, ms, mc;
            fast_trig(st->th[j], &s, &c, &ms, &mc);
            /* SPEC §2 */
            y[j] = (ms * ms * ms) * st->c0[j] + (s * ms * (3.0 - s)) * st->c1[j] +
                   (c * mc * (3.0 - c)) * st->c2[j] + (mc * mc * mc) * st->c3[j];
        }
    } else if (deriv == 1) {
        for (size_t j = 0; j < nb; j++) {
            double s, c, ms, mc;
            fast_trig(st->th[j], &s, &c, &ms, &mc);
            double d01 = st->c1[j] - st->c0[j], d12 = st->c2[j] - st->c1[j], d23 = st->c3[j] - st->c2[j];
            /* SPEC (2.1) */
            double d = 3.0 * (ms * ms) * c * d01 + 2.0 * (s * c) * d12 + 3.0 * (mc * mc) * s * d23;
            y[j] = d * st->w[j];
        }
    } else {
        for (size_t j = 0; j < nb; j++) {
            double s, c, ms, mc;
            fast_trig(st->th[j], &s, &c, &ms, &mc);
            double d01 = st->c1[j] - st->c0[j], d12 = st->c2[j] - st->c1[j], d23 = st->c3[j] - st->c2[j];
            /* d/dθ of (2.1) */
            double a0 = 6.0 * ms * (c * c) + 3.0 * (ms * ms) * s;
            double a3 = 6.0 * mc * (s * s) + 3.0 * (mc * mc) * c;
            double d = (a3 * d23 - a0 * d01) + 2.0 * ((c * c - s * s) * d12);
            y[j] = d * (st->w[j] * st->w[j]);
        }
    }
}

typedef void (*block_fn)(int, const fast_stage *, size_t, double *);

static void eval_portable(int deriv, const fast_stage *st, size_t nb, double *y)
{
    eval_body(deriv, st, nb, y);
}

#if TS_FAST_X86
__attribute__((target("avx2,fma"))) static void eval_avx2(int deriv, const fast_stage *st,
                                                          size_t nb, double *y)
{
    eval_body(deriv, st, nb, y);
}

__attribute__((target("avx512f,fma,prefer-vector-width=512"))) static void
eval_avx512(int deriv, const fast_stage *st, size_t nb, double *y)
{
    eval_body(deriv, st, nb, y);
}
#endif

/* isa: -1 best available, 0 portable, 1 AVX2+FMA, 2 AVX-512F; NULL if unavailable. */
static block_fn pick(int isa)
{
    if (isa < -1 || isa > 2)
        return NULL;
#if TS_FAST_X86
    __builtin_cpu_init();
    int has512 = __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("fma");
    int has2 = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
    if ((isa == -1 || isa == 2) && has512)
        return eval_avx512;
    if ((isa == -1 || isa == 1) && has2)
        return eval_avx2;
    if (isa == 1 || isa == 2)
        return NULL;
#else
    if (isa > 0)
        return NULL;
#endif
    return eval_portable;
}

static void batch(const ts_spline *sp, int deriv, const double *xq, size_t m, double *yq,
                  ts_cursor *cur, block_fn fn)
{
    if (sp->form == TS_FORM_GEOMETRIC) {
        for (size_t j = 0; j < m; j++) {
            double o[3];
            (void)ts_eval_deriv(sp, xq[j], cur, &o[0], &o[1], &o[2]);
            yq[j] = o[deriv];
        }
        return;
    }
    fast_stage st;
    size_t i = cur && cur->interval < sp->n ? cur->interval : 0;
    for (size_t j0 = 0; j0 < m; j0 += TS_FAST_BLOCK) {
        size_t nb = m - j0 < TS_FAST_BLOCK ? m - j0 : TS_FAST_BLOCK;
        i = stage_block(sp, xq + j0, nb, deriv > 0, &st, i);
        fn(deriv, &st, nb, yq + j0);
    }
    if (cur)
        cur->interval = i;
}

void ts__fast_batch(const ts_spline *sp, int deriv, const double *xq, size_t m,
                    double *yq, ts_cursor *cur)
{
    batch(sp, deriv, xq, m, yq, cur, pick(-1));
}

int ts__fast_batch_isa(const ts_spline *sp, int deriv, const double *xq, size_t m,
                       double *yq, ts_cursor *cur, int isa)
{
    block_fn fn = pick(isa);
    if (!fn)
        return 0;
    batch(sp, deriv, xq, m, yq, cur, fn);
    return 1;
}
