/* The exact side of a node within rounding of a gridded field (docs/method.md
 * §11.7), where the field's values and weights are not short binary
 * fractions (their products and sums round): a node 8 ulps below the field's
 * bilinear value is refused (TS_ERR_SIDE at that node), 8 ulps above it is
 * not.  The value is computed here in double from the corner values and the
 * weights 1/3, 2/3: a handful of roundings, each at most half an ulp of
 * values below 1, so at most 4 ulps from the exact bilinear value, while 8
 * ulps lie well inside the field's rounding bound (32 ε max|z| = 115 ulps of
 * the value here), where only the exact test decides.
 *
 * Where an input of that exact test is nonzero and outside [2^-300, 2^300]
 * in magnitude, its products are not proven exact: the side is undecided
 * and the node refused as across (docs/method.md §11.7; TS_ERR_SIDE at that
 * node), although each node below is above its field: a node 2^-1000 above
 * a field 0 there, a node 2 ulps above a field 1 at x = 2^301, and a node 2
 * ulps above a field 1 in a cell with a corner value 2^-400 (every other
 * input of that node in range).  Each lies within the field's rounding
 * bound 2 e_F = 64 ε max|z| + 16·2^-1074 of it. */
#include "trigspline.h"
#include "th.h"

#include <math.h>

int main(void)
{
    double x[3] = {0, 1, 2}, y[3] = {0, 1, 2}, z[9];
    double gx[2] = {0, 3}, gz[4] = {0.1, 0.7, 0.3, 0.9};
    /* (1, 1) in the field's cell: weights 2/3 on the near corner's side */
    double wx = 1.0 / 3.0, wy = 1.0 / 3.0;
    double v = (1 - wy) * ((1 - wx) * gz[0] + wx * gz[1]) + wy * ((1 - wx) * gz[2] + wx * gz[3]);
    double ulp = nextafter(v, 1.0) - v;
    ts_surface_options o;
    ts_surface_options_init(&o);
    o.shape = TS_SURFACE_GRIDS;
    o.has_lower = 1;
    for (int sgn = 0; sgn < 2; sgn++) {
        TH_CASE(sgn ? "lower field" : "upper field");
        /* the upper case mirrors the field and the data */
        double fz[4];
        for (int k = 0; k < 4; k++)
            fz[k] = sgn ? gz[k] : -gz[k];
        o.has_lower = sgn, o.has_upper = !sgn;
        *(sgn ? &o.lower_grid : &o.upper_grid) = (ts_grid_bound){gx, 2, gx, 2, fz};
        for (int side = -1; side <= 1; side += 2) {
            for (int k = 0; k < 9; k++)
                z[k] = sgn ? 5.0 : -5.0;
            double zn = v + side * 8.0 * ulp;
            z[4] = sgn ? zn : -zn;
            ts_surface *s = NULL;
            ts_error e;
            ts_status st = ts_surface_new(x, 3, y, 3, z, &o, &s, &e);
            if (side < 0)
                CHECKF(st == TS_ERR_SIDE && e.index == 4 && !s, "%s", ts_status_name(st));
            else
                CHECKF(st != TS_ERR_SIDE, "%s at %zu", ts_status_name(st), e.index);
            ts_surface_free(s);
        }
    }
    TH_CASE("inputs outside 2^-300 .. 2^300 near a node: undecided, refused");
    {
        const double u = 0x1p-52; /* 1 ulp of 1 upwards */
        struct {
            const char *what;
            double x[2], f[4], z[4];
            size_t at;
        } c[3] = {
            {"a value below 2^-300", {0, 1}, {0, 1, 1, 1}, {0x1p-1000, 2, 2, 2}, 0},
            {"a coordinate above 2^300", {0x1p301, 0x1p302}, {1, 1, 1, 1}, {2, 1 + 2 * u, 2, 2}, 1},
            {"a corner of the field's cell below 2^-300", {0, 1}, {1, 1, 1, 0x1p-400},
             {1 + 2 * u, 2, 2, 0.5}, 0},
        };
        for (int k = 0; k < 3; k++) {
            TH_CASE(c[k].what);
            ts_surface_options_init(&o);
            o.shape = TS_SURFACE_GRIDS;
            o.has_lower = 1;
            o.lower_grid = (ts_grid_bound){c[k].x, 2, c[k].x, 2, c[k].f};
            ts_surface *s = NULL;
            ts_error e;
            ts_status st = ts_surface_new(c[k].x, 2, c[k].x, 2, c[k].z, &o, &s, &e);
            CHECKF(st == TS_ERR_SIDE && e.index == c[k].at && e.where == TS_WHERE_POINT && !s,
                   "%s at %zu", ts_status_name(st), e.index);
            ts_surface_free(s);
        }
    }
    return th_report("test_grid_exact_side");
}
