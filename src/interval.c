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

/* ∫_{x_i}^{x} S on interval i, x in the interval. */
double ts__interval_integral(const ts_spline *sp, size_t i, double x)
{
    if (sp->form == TS_FORM_GEOMETRIC)
        return ts__geo_integral(sp, i, x);
    return 4.0 * (width_factor(sp->h[i]) * theta_antiderivative(sp, i, x));
}

double ts__interval_integral_scaled(const ts_spline *sp, size_t i, double a, double b, int k)
{
    if (sp->form == TS_FORM_GEOMETRIC)
        return ldexp(ts__geo_integral(sp, i, b), -k) - ldexp(ts__geo_integral(sp, i, a), -k);
    double w = ldexp(width_factor(sp->h[i]), 2 - k);
    return w * (theta_antiderivative(sp, i, b) - theta_antiderivative(sp, i, a));
}
