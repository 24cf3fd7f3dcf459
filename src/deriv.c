/* Derivatives of every order of one interval, paper and C¹ forms
 * (docs/method.md §2, derivatives of any order). */
#include "internal.h"

#include <math.h>

double ts__interval_deriv(const ts_spline *sp, size_t i, double x, int nu)
{
    double B[4];
    ts__B(sp, i, B);
    double xi = sp->x[i], h = sp->x[i + 1] - sp->x[i];
    /* S = a0 + p sin θ + q cos θ + r cos 2θ + u sin 3θ + w cos 3θ */
    double p = 3.75 * (B[1] - B[0]), q = 3.75 * (B[2] - B[3]);
    double r = 1.5 * (B[3] - B[0]) + 2.0 * (B[1] - B[2]);
    double u = 0.25 * (B[0] - B[1]), w = 0.25 * (B[2] - B[3]);
    double th = TS_HALF_PI * (x - xi) / h, sh = nu * TS_HALF_PI;
    /* d^ν/dθ^ν sin kθ = k^ν sin(kθ + ν π/2), likewise cos */
    double y = p * sin(th + sh) + q * cos(th + sh) + r * pow(2.0, nu) * cos(2.0 * th + sh) +
               pow(3.0, nu) * (u * sin(3.0 * th + sh) + w * cos(3.0 * th + sh));
    return y * pow(sp->w[i], nu); /* (π/2)/h (ts__w) */
}
