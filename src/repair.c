/* docs/method.md §5: building a shape spline's certificates: every interval checked,
 * beta_i raised where it is not certified (the repair). */
#include "internal.h"

#include <float.h>
#include <math.h>

#define TS_CERT_BLOCK 256 /* intervals per ts__mono_certify call */

#define TS_A_MAX 1e307

static int ok_at(const ts__repair_ops *o, size_t i, double a)
{
    o->set_a(o->ctx, i, a);
    return o->inside(o->ctx, i);
}

static double margin_at(const ts__repair_ops *o, size_t i, double a)
{
    o->set_a(o->ctx, i, a);
    return o->margin(o->ctx, i);
}

static ts_status infeasible(const ts__repair_ops *o, size_t i, double a0)
{
    o->set_a(o->ctx, i, a0);
    return TS_ERR_INFEASIBLE;
}

/* No control value rounded onto its knot by the search (the tangent break
 * constrain.c's interval_ok rejects, docs/method.md §13.4): the a_i it
 * returns is within a factor 2 (doubling) or the bisection's width of the
 * smallest certified a, plus the caller's margin t.  A certified interval
 * has the gap at its knot above the certificate's guard, at least
 * 64ε|f_i| (§5.6), and the smallest certified a makes κ h |d_i − m| of
 * the order of that gap, far above the half ulp of f_i below which
 * B1 = f_i + κ h d_i would round to f_i.  What remains is the rounding
 * every interval has at any a: a slope with κ h |d_i| below half an ulp of
 * f_i while |d_i − m| is not (|d_i| ≪ |m|), not a search made a_i huge. */
ts_status ts__repair_search(const ts__repair_ops *o, size_t i, double al, double a0, double t)
{
    double lo, hi, amax;
    if (o->limit_inside(o->ctx, i)) {
        lo = a0;
        hi = 2.0 * a0;
        for (;;) { /* a_i stays <= TS_A_MAX: never an infinite a (k_i = 0) */
            if (!(hi <= TS_A_MAX))
                return infeasible(o, i, a0);
            if (ok_at(o, i, hi))
                break;
            lo = hi;
            hi *= 2.0;
        }
        amax = (double)INFINITY;
    } else {
        if (!o->margin)
            return infeasible(o, i, a0);
        const double r = 0.6180339887498949;
        /* u = 1/a in (0, 1/alpha]; a subnormal alpha would give ub = inf */
        double ua = 0.0, ub = 1.0 / al;
        if (!(ub <= DBL_MAX))
            ub = DBL_MAX;
        double u1 = ub - r * (ub - ua), u2 = ua + r * (ub - ua);
        double m1 = margin_at(o, i, 1.0 / u1), m2 = margin_at(o, i, 1.0 / u2);
        for (int it = 0; it < 90 && ub - ua > 1e-13 * ub; it++) {
            if (m1 < m2) {
                ua = u1;
                u1 = u2;
                m1 = m2;
                u2 = ua + r * (ub - ua);
                m2 = margin_at(o, i, 1.0 / u2);
            } else {
                ub = u2;
                u2 = u1;
                m2 = m1;
                u1 = ub - r * (ub - ua);
                m1 = margin_at(o, i, 1.0 / u1);
            }
        }
        amax = 1.0 / (m1 >= m2 ? u1 : u2);
        if (!(amax <= TS_A_MAX)) {
            if (!(al <= TS_A_MAX)) /* header: the a needed exceeds 1e307 */
                return infeasible(o, i, a0);
            amax = TS_A_MAX;
        }
        if (!ok_at(o, i, amax)) {
            /* infeasible only where the best gap is below minus its
             * rounding guard (a proof); within ±guard it cannot be decided
             * in double precision (docs/method.md §5) */
            double g = o->gap(o->ctx, i), m = o->margin(o->ctx, i);
            int precision = g + (g - m) >= 0.0; /* guard = g − m */
            (void)infeasible(o, i, a0);
            return precision ? TS_ERR_PRECISION : TS_ERR_INFEASIBLE;
        }
        if (ok_at(o, i, al)) {
            lo = hi = al;
        } else {
            lo = al;
            hi = amax;
        }
    }
    /* bisection: lo fails, hi is certified; each step halves hi − lo, so it
     * ends by the relative width (at most ~2100 steps from 1e307 down to a
     * subnormal a) or, for subnormal a, at adjacent doubles */
    while (lo != hi && fabs(hi - lo) > TS_LIMIT(repair_width) * hi) {
        double mid = lo + 0.5 * (hi - lo);
        if (mid == lo || mid == hi)
            break;
        if (ok_at(o, i, mid))
            hi = mid;
        else
            lo = mid;
    }
    /* the margin t, towards the best a, never past it */
    double cand = hi + t;
    if (cand > amax)
        cand = 0.5 * (hi + amax);
    if (!(cand <= TS_A_MAX)) /* a huge margin t (hi <= TS_A_MAX) */
        cand = TS_A_MAX;
    if (!ok_at(o, i, cand))
        (void)ok_at(o, i, hi); /* certified: every hi above was */
    return TS_OK;
}

/* ---- the repair of a spline's interval -------------------------------- */

typedef struct spline_ctx {
    ts_spline *sp;
    int exact;
} spline_ctx;

/* Set a_i (through beta_i) and recompute the controls it touches. */
static void set_a(ts_spline *sp, size_t i, double a)
{
    const ts__form_ops *form = ts__form(sp->form);
    size_t n = sp->n, i0 = i, i1 = i + 1;
    sp->beta[i] = a - sp->alpha[i];
    if (form->neighbours) {
        /* d̂ of both knots changes (docs/method.md §3) */
        i0 = i > 0 ? i - 1 : 0;
        i1 = i + 2 < n ? i + 2 : n;
    }
    form->controls(sp, i0, i1);
}

static void spline_set_a(void *ctx, size_t i, double a)
{
    set_a(((spline_ctx *)ctx)->sp, i, a);
}

static int spline_inside(void *ctx, size_t i)
{
    const spline_ctx *z = ctx;
    return ts__check_interval(z->sp, i, z->exact);
}

/* The limit a -> ∞: S -> f_i c² + f_{i+1} s² (geometric form: the chord). */
static int spline_limit_inside(void *ctx, size_t i)
{
    const spline_ctx *z = ctx;
    const ts_spline *sp = z->sp;
    double B[4], X[4];
    ts__cert cr;
    B[0] = B[1] = sp->f[i];
    B[2] = B[3] = sp->f[i + 1];
    X[0] = X[1] = 0.0; /* local abscissae (ts__controls_of): κ -> 0 */
    X[2] = X[3] = 1.0;
    return ts__check_ctl(sp, i, B, ts__form(sp->form)->geometric ? X : NULL, z->exact, &cr, 0);
}

/* Certification margin of interval i (lines only): min over the active
 * boundaries of gap − guard. */
static double spline_margin(void *ctx, size_t i)
{
    const ts_spline *sp = ((spline_ctx *)ctx)->sp;
    double B[4], r = (double)INFINITY, guard, at;
    ts__B(sp, i, B); /* paper and C¹ forms only (the geometric form has no margin) */
    if (sp->has_lower)
        r = ts__gap_ctl(sp, i, B, NULL, &sp->lower, 1, &at, &guard) - guard;
    if (sp->has_upper) {
        double g = ts__gap_ctl(sp, i, B, NULL, &sp->upper, -1, &at, &guard) - guard;
        if (!(g >= r))
            r = g;
    }
    return r;
}

/* The smallest gap over the active boundaries (no guard). */
static double spline_gap(void *ctx, size_t i)
{
    const ts_spline *sp = ((spline_ctx *)ctx)->sp;
    double B[4], r = (double)INFINITY, guard, at;
    ts__B(sp, i, B); /* paper and C¹ forms only, as spline_margin */
    if (sp->has_lower)
        r = fmin(r, ts__gap_ctl(sp, i, B, NULL, &sp->lower, 1, &at, &guard));
    if (sp->has_upper)
        r = fmin(r, ts__gap_ctl(sp, i, B, NULL, &sp->upper, -1, &at, &guard));
    return r;
}

/* docs/method.md §5: raise beta_i until interval i is certified (ts__repair_search);
 * the geometric form has no concave search (a line the chord crosses). */
static ts_status repair(ts_spline *sp, size_t i, double t, int exact, ts_error *err)
{
    spline_ctx z = {sp, exact};
    ts__repair_ops o = {&z, spline_set_a, spline_inside, spline_limit_inside,
                        ts__form(sp->form)->geometric ? NULL : spline_margin, spline_gap};
    ts_status st = ts__repair_search(&o, i, sp->alpha[i], sp->alpha[i] + sp->beta[i], t);
    if (st != TS_OK)
        return ts__fail(err, st, i, TS_WHERE_INTERVAL);
    sp->term[i] = (unsigned char)TS_TERM_CERTIFY;
    return TS_OK;
}

/* C¹ form: interval i could not be certified with its neighbours' a.  A
 * neighbour j with a_j > a_i caps d̂ at the shared knot; lower a_j to the
 * smallest value (>= alpha_j) that keeps j and its other neighbour
 * certified.  Returns 1 if some a_j was lowered. */
static int relax_neighbours(ts_spline *sp, size_t i, int exact)
{
    size_t n = sp->n;
    double ai = sp->alpha[i] + sp->beta[i];
    int changed = 0;
    for (int side = 0; side < 2; side++) {
        if ((side == 0 && i == 0) || (side == 1 && i + 1 >= n))
            continue;
        size_t j = side == 0 ? i - 1 : i + 1;
        double aj = sp->alpha[j] + sp->beta[j];
        if (!(aj > ai))
            continue;
        int has_o = side == 0 ? j > 0 : j + 1 < n;
        size_t o = side == 0 ? j - 1 : j + 1;
        double lo = sp->alpha[j], hi = aj;
#define TS_J_OK(a) ((set_a(sp, j, (a)), ts__check_interval(sp, j, exact)) && (!has_o || ts__check_interval(sp, o, exact)))
        if (TS_J_OK(lo)) {
            hi = lo;
        } else {
            for (int it = 0; it < TS_LIMIT(repair_relax_steps) && hi - lo > 1e-12 * hi; it++) {
                double mid = lo + 0.5 * (hi - lo);
                if (TS_J_OK(mid))
                    hi = mid;
                else
                    lo = mid;
            }
        }
#undef TS_J_OK
        set_a(sp, j, hi);
        (void)ts__check_interval(sp, j, exact);
        if (has_o)
            (void)ts__check_interval(sp, o, exact);
        if (hi < aj) {
            sp->term[j] = (unsigned char)TS_TERM_CERTIFY;
            changed = 1;
        }
    }
    return changed;
}

/* C¹ form: a_j = max(alpha_j, A) for every j, controls of all intervals;
 * 1 if every interval is then certified. */
static int c1_uniform_ok(ts_spline *sp, double A, int exact)
{
    size_t n = sp->n;
    for (size_t j = 0; j < n; j++) /* A >= every alpha_j (c1_uniform) */
        sp->beta[j] = A - sp->alpha[j];
    ts__controls_c1(sp, 0, n);
    for (size_t j = 0; j < n; j++)
        if (!ts__check_interval(sp, j, exact))
            return 0;
    return 1;
}

/* C¹ form, after the per-interval repair failed: the uniform family
 * (header, TS_SHAPE_*): A from max alpha_j up by factors 1.1 to 1e6 times
 * it; then bisection down to the smallest certified A, plus the margin t
 * where that is still certified.  1 with every interval certified. */
static int c1_uniform(ts_spline *sp, double t, int exact)
{
    size_t n = sp->n;
    double a0 = 0.0;
    for (size_t j = 0; j < n; j++)
        a0 = sp->alpha[j] > a0 ? sp->alpha[j] : a0;
    double lo = -1.0, hi = a0;
    while (!c1_uniform_ok(sp, hi, exact)) {
        lo = hi;
        hi = fmax(hi * 1.1, hi + DBL_MIN); /* grows also from a subnormal a0 */
        if (!(hi <= 1e6 * a0 && hi <= TS_A_MAX))
            return 0;
    }
    while (lo > 0.0 && hi - lo > 1e-12 * hi) { /* from hi = 1.1 lo: 37 halvings */
        double mid = lo + 0.5 * (hi - lo);
        if (c1_uniform_ok(sp, mid, exact))
            hi = mid;
        else
            lo = mid;
    }
    if (!c1_uniform_ok(sp, hi + t, exact))
        (void)c1_uniform_ok(sp, hi, exact);
    for (size_t j = 0; j < n; j++)
        if (sp->beta[j] > 0.0)
            sp->term[j] = (unsigned char)TS_TERM_CERTIFY;
    return 1;
}

/* Margin (gap − guard) of interval i of a C¹ spline with the capped slopes'
 * factors uL = 1/max(a_{i-1}, a_i), uR = 1/max(a_i, a_{i+1}); *gap receives
 * gap + guard (above the true gap). */
static double c1_margin(const ts_spline *sp, size_t i, double uL, double uR, double *gap)
{
    double K = ts__geo_K(ts__h(sp, i)), r = (double)INFINITY, g = r, guard, at;
    double B[4] = {sp->f[i], sp->f[i] + K * (sp->d[i] * uL), sp->f[i + 1] - K * (sp->d[i + 1] * uR),
                   sp->f[i + 1]};
    for (int side = 0; side < 2; side++) {
        if (!(side == 0 ? sp->has_lower : sp->has_upper))
            continue;
        double gs = ts__gap_ctl(sp, i, B, NULL, side == 0 ? &sp->lower : &sp->upper,
                                side == 0 ? 1 : -1, &at, &guard);
        g = fmin(g, gs + guard);
        r = fmin(r, gs - guard);
    }
    *gap = g;
    return r;
}

/* Best margin over uR in [0, UR] at uL (golden section; the gap is concave
 * in (uL, uR), a minimum of affine functions); *gap the largest gap seen. */
static double c1_best_right(const ts_spline *sp, size_t i, double uL, double UR, double *gap)
{
    const double r = 0.6180339887498949;
    double a = 0.0, b = UR, u1 = b - r * (b - a), u2 = a + r * (b - a), g1, g2;
    double m1 = c1_margin(sp, i, uL, u1, &g1), m2 = c1_margin(sp, i, uL, u2, &g2);
    *gap = fmax(g1, g2);
    while (b - a > 1e-12 * UR) { /* 0.618 a step: 58 steps */
        if (m1 < m2) {
            a = u1, u1 = u2, m1 = m2;
            u2 = a + r * (b - a);
            m2 = c1_margin(sp, i, uL, u2, &g2);
        } else {
            b = u2, u2 = u1, m2 = m1;
            u1 = b - r * (b - a);
            m1 = c1_margin(sp, i, uL, u1, &g2);
        }
        *gap = fmax(*gap, g2);
    }
    return fmax(m1, m2);
}

/* C¹ form: why interval i was refused.  Its gap depends on a_{i-1}, a_i,
 * a_{i+1} only through uL, uR, each anywhere in (0, 1/max of the two
 * alphas]; the interval alone is infeasible where the best gap over that
 * box is below minus its guard (TS_ERR_INFEASIBLE, a proof), not decidable
 * in double precision where it is within ±guard (TS_ERR_PRECISION); else
 * the search gave up (TS_ERR_UNPROVEN). */
static ts_status c1_refusal(const ts_spline *sp, size_t i)
{
    size_t n = sp->n;
    double al = sp->alpha[i];
    double aL = i > 0 && sp->alpha[i - 1] > al ? sp->alpha[i - 1] : al;
    double aR = i + 1 < n && sp->alpha[i + 1] > al ? sp->alpha[i + 1] : al;
    double UL = 1.0 / aL, UR = 1.0 / aR;
    UL = UL <= DBL_MAX ? UL : DBL_MAX;
    UR = UR <= DBL_MAX ? UR : DBL_MAX;
    const double r = 0.6180339887498949;
    double a = 0.0, b = UL, u1 = b - r * (b - a), u2 = a + r * (b - a), g, gbest;
    double m1 = c1_best_right(sp, i, u1, UR, &gbest), m2 = c1_best_right(sp, i, u2, UR, &g);
    gbest = fmax(gbest, g);
    while (b - a > 1e-12 * UL) {
        if (m1 < m2) {
            a = u1, u1 = u2, m1 = m2;
            u2 = a + r * (b - a);
            m2 = c1_best_right(sp, i, u2, UR, &g);
        } else {
            b = u2, u2 = u1, m2 = m1;
            u1 = b - r * (b - a);
            m1 = c1_best_right(sp, i, u1, UR, &g);
        }
        gbest = fmax(gbest, g);
    }
    if (fmax(m1, m2) > 0.0)
        return TS_ERR_UNPROVEN;
    return gbest > 0.0 ? TS_ERR_PRECISION : TS_ERR_INFEASIBLE;
}

/* C¹ form, interval i not certified by the per-interval repair: the uniform
 * family, else the reason (c1_refusal). */
static ts_status c1_fallback(ts_spline *sp, size_t i, double t, int exact, ts_error *err)
{
    if (c1_uniform(sp, t, exact)) {
        ts__error_set(err, TS_OK, TS_NO_INDEX, TS_WHERE_NONE);
        return TS_OK;
    }
    return ts__fail(err, c1_refusal(sp, i), i, TS_WHERE_INTERVAL);
}

/* The certification loop over [i0, i1).  In the paper and geometric forms
 * every interval is checked (and repaired) on its own; the C¹ form steps back
 * after a repair, so it runs once over [0, n). */
static ts_status certify_loop(ts_spline *sp, const ts_spline_options *opt, size_t i0, size_t i1,
                              ts_error *err)
{
    int exact = ts__certify_exact(opt), neighbours = ts__form(sp->form)->neighbours;
    /* every repair moves on (paper, geometric) or may step back once (C¹) */
    size_t budget = TS_LIMIT(repair_budget_per) * sp->n + TS_LIMIT(repair_budget_base);
    size_t i = i0;
    /* exact, paper form: mono_certify decides most intervals a block at a
     * time (a repair there changes only its own interval) */
    int batch = exact && sp->form == TS_FORM_PAPER && !(sp->has_lower && sp->has_upper) &&
                (sp->has_lower || sp->has_upper);
    unsigned char ok[TS_CERT_BLOCK];
    size_t k0 = i, k1 = i; /* ok[] covers [k0, k1) */
    while (i < i1) {
        /* the control-value proof first: it decides most intervals, exact or not */
        i = ts__skip_proven(sp, i, i1);
        if (i >= i1)
            break;
        if (batch && i >= k1) {
            const ts_line *ln = sp->has_lower ? &sp->lower : &sp->upper;
            k0 = i;
            k1 = i1 - i > TS_CERT_BLOCK ? i + TS_CERT_BLOCK : i1;
            ts__mono_certify(sp->f, sp->b1, sp->b2, sp->x, k0, k1, ln->m, ln->c,
                         sp->has_lower ? 1.0 : -1.0, sp->shape == TS_SHAPE_POSITIVE, ok);
        }
        if ((batch && ok[i - k0]) || ts__check_interval(sp, i, exact)) {
            i++;
            continue;
        }
        double t = opt->margins ? opt->margins[i] : opt->margin;
        if (budget-- == 0) /* only the C¹ form steps back */
            return c1_fallback(sp, i, t, exact, err);
        ts_status st = repair(sp, i, t, exact, err);
        if (st != TS_OK && neighbours && relax_neighbours(sp, i, exact)) {
            ts__error_set(err, TS_OK, TS_NO_INDEX, TS_WHERE_NONE);
            st = repair(sp, i, t, exact, err);
        }
        if (st != TS_OK && neighbours)
            return c1_fallback(sp, i, t, exact, err);
        if (st != TS_OK)
            return st;
        /* C¹: the repair changed d̂_i, so re-check the left neighbour */
        if (neighbours && i > 0)
            i--;
        else
            i++;
    }
    return TS_OK;
}

ts_status ts__certify_range(ts_spline *sp, const ts_spline_options *opt, size_t i0, size_t i1,
                            ts_error *err)
{
    sp->certified = 0;
    sp->have_certs = 0;
    return certify_loop(sp, opt, i0, i1 < sp->n ? i1 : sp->n, err);
}

void ts__certify_done(ts_spline *sp, const ts_spline_options *opt)
{
    sp->have_certs = ts__certify_exact(opt);
    sp->certified = 1;
}
