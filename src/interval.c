/* One interval of a spline, any form: value, derivatives and integral
 * (docs/method.md §2, §3; the geometric form in geometric.c, docs/method.md §4),
 * and the table of what differs between the forms (ts__form). */
#include "internal.h"

#include <math.h>

/* Value and derivatives (in x) of interval i at x, paper and C¹ forms; x
 * may lie outside the interval (TS_EXTRAP_EXTEND). */
static void trig_eval(const ts_spline *sp, size_t i, double x, int want, double o[3])
{
    double u = x - sp->x[i], v = sp->x[i + 1] - x;
    if (u >= 0.0 && v >= 0.0) {
        ts__trig_eval_in(sp, i, x, sp->w[i], want, o);
        return;
    }
    /* outside (TS_EXTRAP_EXTEND): θ from the nearer end, libm */
    double B[4];
    ts__B(sp, i, B);
    double w = sp->w[i]; /* dθ/dx, ts__w */
    if (u <= v) {
        ts__seg_sc(B, sin(u * w), cos(u * w), want, o);
    } else {
        ts__seg_sc(B, cos(v * w), sin(v * w), want, o);
    }
    o[1] *= w;
    o[2] *= w * w;
}

/* dx/dθ = 2h/π, also where 2h overflows (h near DBL_MAX). */
static double width_factor(double h)
{
    double w = 2.0 * h / TS_PI;
    return w <= DBL_MAX ? w : h * (2.0 / TS_PI);
}

/* A quarter of ∫_0^θ S dθ' on interval i at x (the antiderivative in θ; a
 * quarter, exactly, so that Σ I_l B_l <= (π/2) max|B| cannot overflow). */
static double theta_antiderivative(const ts_spline *sp, size_t i, double x)
{
    double h = ts__h(sp, i), B[4], I[4];
    double u = x - sp->x[i], theta = TS_HALF_PI * u / h;
    if (!(theta <= TS_PI)) /* (π/2) u overflowed (u near DBL_MAX) */
        theta = TS_HALF_PI * (u / h);
    ts__B(sp, i, B);
    ts__basis_int(theta, sin(theta), cos(theta), I);
    return I[0] * (0.25 * B[0]) + I[1] * (0.25 * B[1]) + I[2] * (0.25 * B[2]) +
           I[3] * (0.25 * B[3]);
}

/* 12-point Gauss–Legendre nodes and weights on [−1, 1] (positive half),
 * from tests/ref/accuracy_ref.py. */
static const double gl_node[6] = {
    0.9815606342467192506905, 0.9041172563704748566785, 0.7699026741943046870369,
    0.5873179542866174472967, 0.3678314989981801937527, 0.1252334085114689154724};
static const double gl_weight[6] = {
    0.04717533638651182719462, 0.1069393259953184309603, 0.1600783285433462263347,
    0.2031674267230659217491, 0.2334925365383548087608, 0.2491470458134027850006};

/* 2^-k ∫_a^b S, b − a <= h/16: the rule in x, with b − a (exact for a, b
 * this close) setting the scale.  S is analytic in x with its nearest
 * complex singularity O(h) away (paper, C¹: a trigonometric polynomial in
 * θ), so 12 points are exact to rounding on a sixteenth of the interval. */
static double short_piece(const ts_spline *sp, size_t i, double a, double b, int k)
{
    void (*eval)(const ts_spline *, size_t, double, int, double[3]) = ts__form(sp->form)->eval;
    double half = 0.5 * (b - a), mid = a + half, sum = 0.0;
    for (int j = 0; j < 12; j++) {
        double xi = j < 6 ? -gl_node[j] : gl_node[11 - j];
        double w = j < 6 ? gl_weight[j] : gl_weight[11 - j];
        double x = mid + half * xi, o[3];
        x = x < a ? a : x > b ? b : x;
        eval(sp, i, x, 0, o);
        sum += w * o[0];
    }
    return ldexp(half, -k) * sum;
}

/* The closed forms of 2^-k ∫_a^b S: paper and C¹ forms (the antiderivative
 * in θ), geometric (geometric.c). */
static double trig_integral(const ts_spline *sp, size_t i, double a, double b, int k)
{
    double w = ldexp(width_factor(ts__h(sp, i)), 2 - k);
    return w * (theta_antiderivative(sp, i, b) - theta_antiderivative(sp, i, a));
}

static double geo_integral(const ts_spline *sp, size_t i, double a, double b, int k)
{
    return ts__geo_integral_scaled(sp, i, b, k) - ts__geo_integral_scaled(sp, i, a, k);
}

double ts__interval_integral_scaled(const ts_spline *sp, size_t i, double a, double b, int k)
{
    if (b - a <= 0.0625 * ts__h(sp, i))
        return short_piece(sp, i, a, b, k);
    return ts__form(sp->form)->integral(sp, i, a, b, k);
}

/* ∫ of interval i into wh[i − i0], i in [i0, i1) (paper and C¹ forms). */
TS_VECTOR_LOOP static void trig_wholes_loop(const double *restrict x, const double *restrict f,
                                            const double *restrict b1, const double *restrict b2,
                                            double *restrict wh, size_t i0, size_t i1)
{
    /* ∫ A_l over [0, π/2]: 5π/4 - 11/3 (l = 0, 3), 11/3 - π (l = 1, 2) */
    const double e = 1.25 * TS_PI - 11.0 / 3.0, m = 11.0 / 3.0 - TS_PI;
    for (size_t i = i0; i < i1; i++) {
        double h = x[i + 1] - x[i];
        double w = 2.0 * h / TS_PI; /* dx/dθ, also where 2h overflows */
        w = w <= DBL_MAX ? w : h * (2.0 / TS_PI);
        wh[i - i0] = w * (e * (f[i] + f[i + 1]) + m * (b1[i] + b2[i]));
    }
}

static void trig_wholes(const ts_spline *sp, size_t i0, size_t i1, double *wh)
{
    trig_wholes_loop(sp->x, sp->f, sp->b1, sp->b2, wh, i0, i1);
}

/* docs/method.md §3: θ linear in x, X1 = x_i + K_i; §4: X1 = x_i + k_i. */
static double trig_k(const ts_spline *sp, size_t i)
{
    return ts__geo_K(ts__h(sp, i));
}

static double geo_k(const ts_spline *sp, size_t i)
{
    return ts__geo_k(ts__h(sp, i), sp->alpha[i] + sp->beta[i]);
}

_Static_assert(TS_FORM_PAPER == 0 && TS_FORM_C1 == 1 && TS_FORM_GEOMETRIC == 2,
               "forms[] is indexed by ts_form");
static const ts__form_ops forms[3] = {
    /* TS_FORM_PAPER (docs/method.md §3) */
    {0, 0, 0, ts__controls_paper, trig_wholes, trig_eval, trig_integral, trig_k, ts__ends_a},
    /* TS_FORM_C1 (docs/method.md §3, the C¹ option) */
    {0, 1, 0, ts__controls_c1, trig_wholes, trig_eval, trig_integral, trig_k, ts__ends_a_c1},
    /* TS_FORM_GEOMETRIC (docs/method.md §4) */
    {1, 0, 1, ts__controls_geo, ts__geo_wholes, ts__geo_eval, geo_integral, geo_k, ts__ends_a},
};

const ts__form_ops *ts__form(ts_form form)
{
    return &forms[form];
}

double ts__cum(const ts_spline *sp, size_t i)
{
    size_t j0 = i / TS_CUM_STEP * TS_CUM_STEP;
    double sum = sp->cum[i / TS_CUM_STEP], wh[TS_CUM_STEP];
    if (i > j0) {
        forms[sp->form].wholes(sp, j0, i, wh);
        for (size_t j = j0; j < i; j++)
            sum += wh[j - j0];
    }
    return sum;
}

void ts__interval_eval(const ts_spline *sp, size_t i, double x, int want, double o[3])
{
    forms[sp->form].eval(sp, i, x, want, o);
}
