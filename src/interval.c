/* One interval of a spline, any form: value, derivatives and integral
 * (docs/method.md §2, §3; the geometric form in geometric.c, docs/method.md §4). */
#include "internal.h"

#include <math.h>

/* Value and derivatives (in x) of interval i at x; x may lie outside the
 * interval (TS_EXTRAP_EXTEND). */
void ts__interval_eval(const ts_spline *sp, size_t i, double x, int want, double o[3])
{
    if (sp->form == TS_FORM_GEOMETRIC) {
        ts__geo_eval(sp, i, x, want, o);
        return;
    }
    double u = x - sp->x[i], v = sp->x[i + 1] - x;
    if (u >= 0.0 && v >= 0.0) {
        ts__trig_eval_in(sp, i, x, want, o);
        return;
    }
    /* outside (TS_EXTRAP_EXTEND): θ from the nearer end, libm */
    double h = sp->h[i], B[4];
    ts__B(sp, i, B);
    double w = TS_HALF_PI / h; /* dθ/dx */
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
    double h = sp->h[i], B[4], I[4];
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
    double half = 0.5 * (b - a), mid = a + half, sum = 0.0;
    for (int j = 0; j < 12; j++) {
        double xi = j < 6 ? -gl_node[j] : gl_node[11 - j];
        double w = j < 6 ? gl_weight[j] : gl_weight[11 - j];
        double x = mid + half * xi, o[3];
        x = x < a ? a : x > b ? b : x;
        ts__interval_eval(sp, i, x, 0, o);
        sum += w * o[0];
    }
    return ldexp(half, -k) * sum;
}

double ts__interval_integral_scaled(const ts_spline *sp, size_t i, double a, double b, int k)
{
    if (b - a <= 0.0625 * sp->h[i])
        return short_piece(sp, i, a, b, k);
    if (sp->form == TS_FORM_GEOMETRIC)
        return ts__geo_integral_scaled(sp, i, b, k) - ts__geo_integral_scaled(sp, i, a, k);
    double w = ldexp(width_factor(sp->h[i]), 2 - k);
    return w * (theta_antiderivative(sp, i, b) - theta_antiderivative(sp, i, a));
}
