/* Input checks shared by the constructors (spline, curve, surface) and
 * ts_slopes_compute: knots, values, shape parameters and margins.  Each
 * rule is written once; each caller keeps its own order of stages. */
#include "internal.h"

#include <float.h>
#include <math.h>

/* The knots' rules on points [i0, i1) (i0 >= 1), one pass of flags so that
 * it vectorises. */
TS_VECTOR_LOOP static int knots_block(const double *restrict x, const double *restrict f,
                                      size_t i0, size_t i1, double vmax, double wmin,
                                      double wmax)
{
    int ok = 1;
    for (size_t i = i0; i < i1; i++)
        ok &= (fabs(x[i]) <= DBL_MAX) & (fabs(f[i]) <= vmax) & (x[i] > x[i - 1]) &
              (x[i] - x[i - 1] <= wmax) & (x[i] - x[i - 1] >= wmin);
    return ok;
}

ts_status ts__check_knots(const double *x, const double *f, size_t np, double vmax, double wmin,
                          double wmax, size_t *index)
{
    int ok = fabs(x[0]) <= DBL_MAX && fabs(f[0]) <= vmax;
    for (size_t i0 = 1; i0 < np && ok; i0 += 4096)
        ok = knots_block(x, f, i0, np - i0 > 4096 ? i0 + 4096 : np, vmax, wmin, wmax);
    *index = TS_NO_INDEX;
    if (ok)
        return TS_OK;
    /* the checks again in order: the first offender of the first that fails */
    size_t i;
    for (i = 0; i < np; i++)
        if (!isfinite(x[i]) || !isfinite(f[i]))
            return *index = i, TS_ERR_NONFINITE;
    for (i = 1; i < np; i++)
        if (!(x[i] > x[i - 1]))
            return *index = i, TS_ERR_UNSORTED;
    for (i = 1; i < np; i++)
        if (!(x[i] - x[i - 1] <= wmax && x[i] - x[i - 1] >= wmin))
            return *index = i, TS_ERR_WIDTH;
    i = 0; /* the one check left: there is an offender */
    while (i + 1 < np && fabs(f[i]) <= vmax)
        i++;
    return *index = i, TS_ERR_TOO_LARGE;
}

size_t ts__first_bad_alpha(double alpha, const double *alphas, size_t i0, size_t i1)
{
    size_t i = i0;
    while (i < i1 && ts__alpha_ok(alphas ? alphas[i] : alpha))
        i++;
    return i;
}

size_t ts__first_bad_beta(double alpha, const double *alphas, double beta, const double *betas,
                          size_t i0, size_t i1)
{
    size_t i = i0;
    while (i < i1 && ts__beta_ok(alphas ? alphas[i] : alpha, betas ? betas[i] : beta))
        i++;
    return i;
}
