/* Batch evaluation kernels for the paper and C¹ forms (issue 6).
 *
 * ts__fast_batch works on blocks of TS_FAST_BLOCK queries (no allocation: the
 * block's scratch is on the stack, < 8 KiB):
 *  1. stage: per query θ = (x − x_i)·w_i with w_i = (π/2)/h_i from sp->fast
 *     (bitwise the θ of eval.c) and the interval's control values B0..B3.
 *     The interval is ts__locate's (largest i <= n−1 with x_i <= x: the
 *     right-hand one at an inner knot).  A sorted block walks the cursor,
 *     keeping the current interval's values in registers and galloping over
 *     gaps; an unsorted block runs one branch-free binary search per query,
 *     all queries advancing one level at a time so their cache misses overlap.
 *  2. a straight loop the compiler vectorises, θ in [0, π/2] (SPEC §1), no
 *     range reduction: fast_trig gives s, c, 1−s, 1−c to <= 3u (u = 2⁻⁵³;
 *     measured 1.3u), then SPEC §2 (value) or (2.1) and its θ-derivative,
 *     times w or w·w as eval.c.
 * Agreement with ts_eval_deriv: bounds derived and checked on 1e7 random
 * points in tests/test_fast.c; measured |fast − plain| <= 3.9ε·M for the value
 * (M = max|B_l| of the interval), <= 12ε·M·w for S', <= 35ε·M·w² for S''
 * (both paths are equally far from a long-double reference).
 *
 * With GCC or Clang on x86-64 the pipeline is also compiled for AVX2+FMA and
 * AVX-512F and chosen at run time (__builtin_cpu_supports); elsewhere, or with
 * -DTS_FAST_PORTABLE, only the portable C version exists.  The geometric form
 * (SPEC §4) goes point by point through ts_eval_deriv. */
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
/* bench/sincos_coeffs.py: sin u ≈ u + u z P(z), 1 − cos u ≈ z/2 − z² Q(z),
 * z = u², u in [0, π/4]; truncation <= 5.4e-18 */
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
    /* the expression of eval.c's eval_in, so θ is bitwise identical */
    for (size_t i = 0; i < sp->n; i++)
        sp->fast[i] = TS_HALF_PI / sp->h[i];
}

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

typedef struct fast_b4 {
    double b0, b1, b2, b3;
} fast_b4;

typedef struct fast_stage {
    double th[TS_FAST_BLOCK], w[TS_FAST_BLOCK]; /* w: derivatives only */
    fast_b4 B[TS_FAST_BLOCK];
} fast_stage;

TS_ALWAYS_INLINE fast_b4 control4(const ts_spline *sp, size_t i)
{
    fast_b4 b = {sp->f[i], sp->b1[i], sp->b2[i], sp->f[i + 1]};
    return b;
}

/* Stages q[0..nb); i is the cursor; returns the last query's interval. */
TS_ALWAYS_INLINE size_t stage_block(const ts_spline *sp, const double *q, size_t nb, int want_w,
                                    fast_stage *st, size_t i)
{
    const double *xs = sp->x, *w = sp->fast;
    size_t n = sp->n;
    int sorted = 1;
    for (size_t j = 1; j < nb; j++)
        sorted &= q[j - 1] <= q[j];
    if (sorted) {
        if (!(xs[i] <= q[0]))
            i = search_range(xs, 0, i + 1, q[0]);
        /* the last interval never advances: x1 = +inf */
        double x0 = xs[i], x1 = i + 1 < n ? xs[i + 1] : (double)INFINITY, wi = w[i];
        fast_b4 b = control4(sp, i);
        for (size_t j = 0; j < nb; j++) {
            double x = q[j];
            if (x >= x1) {
                i++;
                if (i + 1 < n && xs[i + 1] <= x)
                    i = gallop(xs, n, i, x);
                x0 = xs[i];
                x1 = i + 1 < n ? xs[i + 1] : (double)INFINITY;
                wi = w[i];
                b = control4(sp, i);
            }
            st->th[j] = (x - x0) * wi;
            if (want_w)
                st->w[j] = wi;
            st->B[j] = b;
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
        size_t k = idx[j];
        st->th[j] = (q[j] - xs[k]) * w[k];
        st->w[j] = w[k];
        st->B[j] = control4(sp, k);
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

TS_ALWAYS_INLINE void eval_block(int deriv, const fast_stage *st, size_t nb, double *y)
{
    if (deriv == 0) {
        for (size_t j = 0; j < nb; j++) {
            double s, c, ms, mc;
            fast_trig(st->th[j], &s, &c, &ms, &mc);
            const fast_b4 *B = &st->B[j];
            /* SPEC §2, the expressions of basis.c */
            y[j] = (ms * ms * ms) * B->b0 + (s * ms * (3.0 - s)) * B->b1 +
                   (c * mc * (3.0 - c)) * B->b2 + (mc * mc * mc) * B->b3;
        }
    } else if (deriv == 1) {
        for (size_t j = 0; j < nb; j++) {
            double s, c, ms, mc;
            fast_trig(st->th[j], &s, &c, &ms, &mc);
            const fast_b4 *B = &st->B[j];
            double d01 = B->b1 - B->b0, d12 = B->b2 - B->b1, d23 = B->b3 - B->b2;
            /* SPEC (2.1) */
            double d = 3.0 * (ms * ms) * c * d01 + 2.0 * (s * c) * d12 + 3.0 * (mc * mc) * s * d23;
            y[j] = d * st->w[j];
        }
    } else {
        for (size_t j = 0; j < nb; j++) {
            double s, c, ms, mc;
            fast_trig(st->th[j], &s, &c, &ms, &mc);
            const fast_b4 *B = &st->B[j];
            double d01 = B->b1 - B->b0, d12 = B->b2 - B->b1, d23 = B->b3 - B->b2;
            /* d/dθ of (2.1) */
            double a0 = 6.0 * ms * (c * c) + 3.0 * (ms * ms) * s;
            double a3 = 6.0 * mc * (s * s) + 3.0 * (mc * mc) * c;
            double d = (a3 * d23 - a0 * d01) + 2.0 * ((c * c - s * s) * d12);
            y[j] = d * (st->w[j] * st->w[j]);
        }
    }
}

/* The whole batch; i is the cursor; returns the last query's interval. */
TS_ALWAYS_INLINE size_t pipeline(const ts_spline *sp, int deriv, const double *xq, size_t m,
                                 double *yq, size_t i)
{
    fast_stage st;
    for (size_t j0 = 0; j0 < m; j0 += TS_FAST_BLOCK) {
        size_t nb = m - j0 < TS_FAST_BLOCK ? m - j0 : TS_FAST_BLOCK;
        i = stage_block(sp, xq + j0, nb, deriv > 0, &st, i);
        eval_block(deriv, &st, nb, yq + j0);
    }
    return i;
}

typedef size_t (*pipeline_fn)(const ts_spline *, int, const double *, size_t, double *, size_t);

static size_t pipeline_portable(const ts_spline *sp, int deriv, const double *xq, size_t m,
                                double *yq, size_t i)
{
    return pipeline(sp, deriv, xq, m, yq, i);
}

#if TS_FAST_X86
__attribute__((target("avx2,fma"))) static size_t
pipeline_avx2(const ts_spline *sp, int deriv, const double *xq, size_t m, double *yq, size_t i)
{
    return pipeline(sp, deriv, xq, m, yq, i);
}

__attribute__((target("avx512f,fma,prefer-vector-width=512"))) static size_t
pipeline_avx512(const ts_spline *sp, int deriv, const double *xq, size_t m, double *yq, size_t i)
{
    return pipeline(sp, deriv, xq, m, yq, i);
}
#endif

/* isa: −1 best available, 0 portable C, 1 AVX2+FMA, 2 AVX-512F; NULL if not here. */
static pipeline_fn pick(int isa)
{
    if (isa < -1 || isa > 2)
        return NULL;
#if TS_FAST_X86
    __builtin_cpu_init();
    int has2 = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
    int has512 = has2 && __builtin_cpu_supports("avx512f");
    if ((isa == -1 || isa == 2) && has512)
        return pipeline_avx512;
    if ((isa == -1 || isa == 1) && has2)
        return pipeline_avx2;
#endif
    return isa <= 0 ? pipeline_portable : NULL;
}

static void batch(const ts_spline *sp, int deriv, const double *xq, size_t m, double *yq,
                  ts_cursor *cur, pipeline_fn fn)
{
    if (sp->form == TS_FORM_GEOMETRIC) {
        for (size_t j = 0; j < m; j++) {
            double o[3];
            (void)ts_eval_deriv(sp, xq[j], cur, &o[0], &o[1], &o[2]);
            yq[j] = o[deriv];
        }
        return;
    }
    if (m == 0)
        return;
    size_t i = cur && cur->interval < sp->n ? cur->interval : 0;
    i = fn(sp, deriv, xq, m, yq, i);
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
    pipeline_fn fn = pick(isa);
    if (!fn)
        return 0;
    batch(sp, deriv, xq, m, yq, cur, fn);
    return 1;
}
