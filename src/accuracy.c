/* docs/method.md §8: error constants and a-posteriori error bounds.  Derivations:
 * docs/accuracy.md §3. */
#include "internal.h"

#include <math.h>

#define GRID 128 /* cells in θ over [0, π/2] */

/* Basis values on the grid, computed once per call (no allocation). */
typedef struct grid_tab {
    double th[GRID + 1], s[GRID + 1], c[GRID + 1], A1[GRID + 1], A2[GRID + 1];
} grid_tab;

static void grid_fill(grid_tab *t)
{
    for (int j = 0; j <= GRID; j++) {
        double th = TS_HALF_PI * (double)j / GRID, A[4];
        double s = j == GRID ? 1.0 : sin(th), c = j == GRID ? 0.0 : cos(th);
        ts__basis(s, c, A);
        t->th[j] = th;
        t->s[j] = s;
        t->c[j] = c;
        t->A1[j] = A[1];
        t->A2[j] = A[2];
    }
}

/* One interval's bound function, in units of h (docs/accuracy.md §3):
 * mode 1: w1 (c²δ + s²(1−δ)) + kl w2 A1 + kr w3 A2
 * mode 2: w1 |ε| + w2 J,  ε = δ − s² − kl A1 + kr A2,
 *         J = ∫_0^δ |kl A1 − c² τ| dτ + ∫_0^{1−δ} |kr A2 − s² σ| dσ
 * with δ = 2θ/π, or δ = X̂(θ) = s² + κ(A1 − A2) in the geometric form. */
typedef struct bound_fn {
    int geo, mode;
    double kl, kr, w1, w2, w3;
} bound_fn;

/* ∫_0^L |α − β τ| dτ for α, β >= 0. */
static double abs_lin_int(double al, double be, double L)
{
    if (!(L > 0.0))
        return 0.0;
    if (be * L <= al)
        return al * L - 0.5 * be * L * L;
    double r = al / be, t = L - r;
    return 0.5 * al * r + 0.5 * be * t * t;
}

static double bound_eval(const bound_fn *b, double th, double s, double c, double A1, double A2)
{
    double s2 = s * s, c2 = c * c, del;
    /* δ in [0, 1] to rounding: mode 1 moves by a rounding (bound_max
     * enlarges by 1e-12), J's integrals over a length <= 0 are 0 */
    if (b->geo) {
        del = s2 + b->kl * (A1 - A2);
    } else {
        del = th / TS_HALF_PI;
    }
    if (b->mode == 1)
        return b->w1 * (c2 * del + s2 * (1.0 - del)) + b->kl * b->w2 * A1 + b->kr * b->w3 * A2;
    double eps = b->geo ? 0.0 : del - s2 - b->kl * A1 + b->kr * A2;
    double J = abs_lin_int(b->kl * A1, c2, del) + abs_lin_int(b->kr * A2, s2, 1.0 - del);
    return b->w1 * fabs(eps) + b->w2 * J;
}

static double bound_at(const bound_fn *b, double th)
{
    double s = sin(th), c = cos(th), A[4];
    ts__basis(s, c, A);
    return bound_eval(b, th, s, c, A[1], A[2]);
}

/* max over θ in [0, π/2]: grid, then golden section around every local
 * maximum of the grid values, enlarged by 1e-12 relative. */
static double bound_max(const bound_fn *b, const grid_tab *t)
{
    double v[GRID + 1], best = 0.0;
    for (int j = 0; j <= GRID; j++) {
        v[j] = bound_eval(b, t->th[j], t->s[j], t->c[j], t->A1[j], t->A2[j]);
        if (v[j] > best)
            best = v[j];
    }
    const double g = 0.6180339887498949;
    for (int j = 0; j <= GRID; j++) {
        if ((j > 0 && v[j] < v[j - 1]) || (j < GRID && v[j] < v[j + 1]))
            continue;
        if ((j > 0 && v[j] == v[j - 1]))
            continue; /* flat run: refined once */
        double lo = t->th[j > 0 ? j - 1 : 0], hi = t->th[j < GRID ? j + 1 : GRID];
        double p = hi - g * (hi - lo), q = lo + g * (hi - lo);
        double fp = bound_at(b, p), fq = bound_at(b, q);
        /* width 2π/256 times 0.618 a step: 55 steps to 1e-13 */
        while (hi - lo > 1e-13) {
            if (fp >= fq) {
                hi = q, q = p, fq = fp;
                p = hi - g * (hi - lo);
                fp = bound_at(b, p);
            } else {
                lo = p, p = q, fp = fq;
                q = lo + g * (hi - lo);
                fq = bound_at(b, q);
            }
        }
        if (fp > best)
            best = fp;
        if (fq > best)
            best = fq;
    }
    return best * (1.0 + 1e-12);
}

ts_status ts_error_constants_get(ts_form form, double a, ts_error_constants *c)
{
    if (c)
        c->first = c->line = c->second = (double)NAN;
    if (!c)
        return TS_ERR_NULL;
    if ((unsigned)form > (unsigned)TS_FORM_GEOMETRIC || !(a > 0.0 && isfinite(a)))
        return TS_ERR_OPTION;
    if (form == TS_FORM_GEOMETRIC && !(a >= TS_GEOMETRIC_A_MIN))
        return TS_ERR_GEOMETRIC;
    grid_tab t;
    grid_fill(&t);
    double kap = ts__kappa(a);
    int geo = form == TS_FORM_GEOMETRIC;
    bound_fn f1 = {geo, 1, kap, kap, 1.0, 1.0, 1.0};
    bound_fn fl = {geo, 2, kap, kap, 1.0, 0.0, 0.0};
    bound_fn f2 = {geo, 2, kap, kap, 0.0, 1.0, 0.0};
    c->first = bound_max(&f1, &t);
    c->line = geo ? 0.0 : bound_max(&fl, &t);
    c->second = bound_max(&f2, &t);
    return TS_OK;
}

ts_status ts_spline_error_bound(const ts_spline *s, double fprime_max, double fsecond_max,
                                int exact_slopes, double *bound, double *per_interval)
{
    if (bound)
        *bound = (double)NAN;
    if (s && per_interval)
        for (size_t i = 0; i < s->n; i++)
            per_interval[i] = (double)NAN;
    if (!s || !bound)
        return TS_ERR_NULL;
    if (!isfinite(fprime_max) || (exact_slopes && isnan(fsecond_max)))
        return TS_ERR_NONFINITE;
    if (fprime_max < 0.0 || (exact_slopes && fsecond_max < 0.0))
        return TS_ERR_OPTION;
    int second = exact_slopes && isfinite(fsecond_max);
    grid_tab t;
    grid_fill(&t);
    size_t n = s->n;
    const ts__form_ops *form = ts__form(s->form);
    int geo = form->geometric;
    double worst = 0.0, prev_key[3] = {(double)NAN, (double)NAN, (double)NAN}, prev2 = 0.0;
    for (size_t i = 0; i < n; i++) {
        double h = ts__h(s, i), aL, aR;
        form->ends_a(s, i, &aL, &aR); /* C¹: d̂ = d / max(a_{j−1}, a_j), docs/method.md §3 */
        double kl = ts__geo_k(1.0, aL), kr = ts__geo_k(1.0, aR); /* κ: k_i per unit width */
        bound_fn f1 = {geo, 1, kl, kr, fprime_max, fabs(s->d[i]), fabs(s->d[i + 1])};
        double b = h * bound_max(&f1, &t);
        if (second) {
            /* depends on (h, aL, aR) only: reuse on uniform stretches */
            double b2;
            if (h == prev_key[0] && aL == prev_key[1] && aR == prev_key[2]) {
                b2 = prev2;
            } else {
                bound_fn f2 = {geo, 2, kl, kr, fprime_max, fsecond_max * h, 0.0};
                b2 = h * bound_max(&f2, &t);
                prev_key[0] = h, prev_key[1] = aL, prev_key[2] = aR, prev2 = b2;
            }
            if (b2 < b)
                b = b2;
        }
        if (per_interval)
            per_interval[i] = b;
        if (b > worst) /* b >= 0, never NaN: bound_max only takes larger values */
            worst = b;
    }
    *bound = worst;
    return TS_OK;
}
