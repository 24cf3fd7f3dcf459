/* docs/method.md §11.7: a surface bound given as a gridded field, bilinear
 * on each cell of its own grid: its value with an error bound, the exact
 * side of a value, and an upper bound of its maximum over a rectangle. */
#include "internal.h"

#include <float.h>
#include <math.h>
#include <stdint.h>

/* The position of v in cell i of knots t, in [0, 1]. */
static double frac(const double *t, size_t i, double v)
{
    double d = (v - t[i]) / (t[i + 1] - t[i]);
    return d > 0.0 ? (d < 1.0 ? d : 1.0) : 0.0;
}

/* (1 − w) a + w b: exactly a at w = 0 and b at w = 1. */
static double lerp(double a, double b, double w)
{
    return (1.0 - w) * a + w * b;
}

static double cell_value(const ts__gbound *g, size_t i, size_t j, double x, double y)
{
    const double *z0 = g->z + j * g->nx + i, *z1 = z0 + g->nx;
    double wx = frac(g->x, i, x);
    return lerp(lerp(z0[0], z0[1], wx), lerp(z1[0], z1[1], wx), frac(g->y, j, y));
}

double ts__gb_value(const ts__gbound *g, double x, double y)
{
    return cell_value(g, ts__search(g->x, g->nx - 1, x, NULL),
                      ts__search(g->y, g->ny - 1, y, NULL), x, y);
}

/* a − b exactly as an expansion of two components (TwoSum) */
static int diff(double a, double b, double *h)
{
    return ts__exp_grow(&a, 1, -b, h);
}

/* zero, or 2^-300 <= |v| <= 2^300: then every product of three values and
 * of their rounding errors (multiples of 2^-352 below 2^301) is exact */
static int tame(double v)
{
    double a = fabs(v);
    return a == 0.0 || (0x1p-300 <= a && a <= 0x1p300);
}

int ts__gb_side(const ts__gbound *g, double x, double y, double v)
{
    size_t i = ts__search(g->x, g->nx - 1, x, NULL), j = ts__search(g->y, g->ny - 1, y, NULL);
    double d = v - cell_value(g, i, j, x, y);
    if (fabs(d) > 2.0 * g->err)
        return (d > 0.0) - (d < 0.0);
    /* hx hy (v − b) = Σ_corners (v − z_c)·wx_c·wy_c, the weights the
     * distances to the opposite grid lines (docs/method.md §11.7) */
    const double *X = g->x + i, *Y = g->y + j;
    double in[7] = {v, x, y, X[0], X[1], Y[0], Y[1]};
    for (int k = 0; k < 7; k++)
        if (!tame(in[k]))
            return 2;
    /* components: 2 per difference, 8 per product of two, 32 per corner */
    double acc[4 * 32], wx[2][2], wy[2][2], dz[2], t1[8], t2[32];
    int na = 0;
    diff(X[1], x, wx[0]);
    diff(x, X[0], wx[1]);
    diff(Y[1], y, wy[0]);
    diff(y, Y[0], wy[1]);
    for (int cy = 0; cy < 2; cy++)
        for (int cx = 0; cx < 2; cx++) {
            double zc = g->z[(j + (size_t)cy) * g->nx + i + (size_t)cx];
            if (!tame(zc))
                return 2;
            int nd = diff(v, zc, dz);
            int n1 = ts__exp_product(dz, nd, wx[cx], 2, t1);
            int n2 = ts__exp_product(t1, n1, wy[cy], 2, t2);
            for (int l = 0; l < n2; l++)
                na = ts__exp_grow(acc, na, t2[l], acc);
        }
    return ts__exp_sign(acc, na);
}

/* The p-th place along an axis (p = i0 .. i1 + 1): a, the grid lines strictly
 * inside (a, b), b; with the cell to evaluate it in.  0 for none. */
static int place(const double *t, size_t i0, size_t i1, double a, double b, size_t p, double *v,
                 size_t *cell)
{
    if (p == i0) {
        *v = a;
        *cell = i0;
    } else if (p <= i1) {
        if (!(t[p] < b))
            return 0;
        *v = t[p];
        *cell = p - 1;
    } else {
        *v = b;
        *cell = i1;
    }
    return 1;
}

double ts__gb_max(const ts__gbound *g, double sg, double xa, double xb, double ya, double yb)
{
    /* the field is bilinear on every piece of the rectangle cut by the grid
     * lines, so its extremes are at the pieces' corners */
    size_t i0 = ts__search(g->x, g->nx - 1, xa, NULL), i1 = ts__search(g->x, g->nx - 1, xb, NULL);
    size_t j0 = ts__search(g->y, g->ny - 1, ya, NULL), j1 = ts__search(g->y, g->ny - 1, yb, NULL);
    double best = -(double)INFINITY;
    for (size_t p = i0; p <= i1 + 1; p++) {
        double xv, yv;
        size_t ci, cj;
        if (!place(g->x, i0, i1, xa, xb, p, &xv, &ci))
            continue;
        for (size_t q = j0; q <= j1 + 1; q++) {
            if (!place(g->y, j0, j1, ya, yb, q, &yv, &cj))
                continue;
            double v = sg * cell_value(g, ci, cj, xv, yv);
            best = v > best ? v : best;
        }
    }
    return best + g->err;
}

int ts__gb_check(const ts_grid_bound *g, double x0, double x1, double y0, double y1, size_t *at)
{
    *at = 0;
    if (!g->x || !g->y || !g->z)
        return TS__GB_NULL;
    if (g->nx_points < 2 || g->ny_points < 2)
        return TS__GB_TOO_FEW;
    if (g->ny_points > SIZE_MAX / 4 / sizeof(double) / g->nx_points)
        return TS__GB_SIZE;
    for (int d = 0; d < 2; d++) {
        const double *t = d ? g->y : g->x;
        size_t n = d ? g->ny_points : g->nx_points;
        for (size_t k = 0; k < n; k++) {
            *at = d ? g->nx_points + k : k;
            if (!isfinite(t[k]) || (k > 0 && !(t[k] > t[k - 1] && isfinite(t[k] - t[k - 1]))))
                return TS__GB_AXIS;
        }
    }
    for (size_t n = 0; n < g->nx_points * g->ny_points; n++) {
        *at = n;
        if (!(fabs(g->z[n]) <= TS_VALUE_MAX))
            return TS__GB_VALUE;
    }
    *at = 0;
    if (!(g->x[0] <= x0 && x1 <= g->x[g->nx_points - 1] && g->y[0] <= y0 &&
          y1 <= g->y[g->ny_points - 1]))
        return TS__GB_COVER;
    return TS__GB_OK;
}

int ts__gb_cell(const ts__gbound *g, double xa, double xb, double ya, double yb, double *gx,
                double *gy)
{
    size_t i = ts__search(g->x, g->nx - 1, xa, NULL), j = ts__search(g->y, g->ny - 1, ya, NULL);
    if (!(xb <= g->x[i + 1] && yb <= g->y[j + 1]))
        return 0;
    const double *z0 = g->z + j * g->nx + i, *z1 = z0 + g->nx;
    /* the partials of a bilinear are linear: largest at the cell's edges;
     * doubled for the rounding of these quotients */
    *gx = 2.0 * fmax(fabs(z0[1] - z0[0]), fabs(z1[1] - z1[0])) / (g->x[i + 1] - g->x[i]);
    *gy = 2.0 * fmax(fabs(z1[0] - z0[0]), fabs(z1[1] - z0[1])) / (g->y[j + 1] - g->y[j]);
    return 1;
}
