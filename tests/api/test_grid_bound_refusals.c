/* Every way a gridded field (ts_grid_bound) is malformed, on each side:
 * the header's TS_ERR_BOUND_GRID with index 0 (lower) or 1 (upper) and
 * where = TS_WHERE_NONE, and ts_error_message's sentence naming what is
 * wrong; each array of the triple NULL, too few nodes in either direction,
 * a non-finite coordinate, a step that overflows, an unsorted y, and a grid
 * short of the surface's on each of its four sides. */
#include "trigspline.h"
#include "th.h"

#include <stdio.h>
#include <string.h>

static void message_has(const ts_error *e, const double *x, const double *y, const double *z,
                        const ts_surface_options *o, const char *want)
{
    ts_error_context c;
    ts_error_context_init(&c);
    c.x = x;
    c.n_points = 3;
    c.y = y;
    c.ny_points = 3;
    c.f = z;
    c.surface_options = o;
    char buf[512];
    ts_error_message(e, &c, buf, sizeof buf);
    CHECKF(strstr(buf, want) != NULL, "\"%s\" lacks \"%s\"", buf, want);
}

int main(void)
{
    double x[3] = {0, 1, 2}, y[3] = {0, 1, 2}, z[9] = {0};
    double gx[2] = {0, 2}, gy[2] = {0, 2}, lo[4] = {-1, -1, -1, -1}, up[4] = {1, 1, 1, 1};
    double nan_x[2] = {TH_NAN, 2}, inf_y[2] = {0, TH_INF}, wide[2] = {-0x1p1023, 0x1p1023};
    double down_y[3] = {0, 2, 1}, short_lo[2] = {0.5, 2}, short_hi[2] = {0, 1.5};
    double up6[6] = {1, 1, 1, 1, 1, 1};
    struct {
        ts_grid_bound g;
        const char *want;
    } cases[] = {
        {{gx, 2, NULL, 2, up}, "field's x, y or z is NULL"},
        {{gx, 2, gy, 2, NULL}, "field's x, y or z is NULL"},
        {{gx, 2, gy, 1, up}, "has 2 x 1 nodes; at least 2 in each direction"},
        {{nan_x, 2, gy, 2, up}, "field's x[0] = nan is not finite"},
        {{gx, 2, inf_y, 2, up}, "field's y[1] = inf is not finite"},
        {{wide, 2, gy, 2, up}, "field's x[1] = 8.98846567431158e+307 is not finite, or not greater "
                               "than the previous one by a finite step"},
        {{gx, 2, down_y, 3, up6}, "field's y[2] = 1 is not finite"},
        {{short_lo, 2, gy, 2, up}, "does not cover the surface's grid [0, 2] x [0, 2]"},
        {{short_hi, 2, gy, 2, up}, "does not cover the surface's grid [0, 2] x [0, 2]"},
        {{gx, 2, short_lo, 2, up}, "does not cover the surface's grid [0, 2] x [0, 2]"},
        {{gx, 2, short_hi, 2, up}, "does not cover the surface's grid [0, 2] x [0, 2]"},
    };
    for (int side = 0; side < 2; side++) {
        TH_CASE(side ? "upper" : "lower");
        for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
            ts_surface_options o;
            ts_surface_options_init(&o);
            o.shape = TS_SURFACE_GRIDS;
            o.has_lower = o.has_upper = 1;
            o.lower_grid = (ts_grid_bound){gx, 2, gy, 2, lo};
            o.upper_grid = (ts_grid_bound){gx, 2, gy, 2, up};
            ts_grid_bound g = cases[k].g;
            if (!side && g.z == up)
                g.z = lo;
            *(side ? &o.upper_grid : &o.lower_grid) = g;
            ts_surface *s = NULL;
            ts_error e;
            CHECKF(ts_surface_new(x, 3, y, 3, z, &o, &s, &e) == TS_ERR_BOUND_GRID && !s &&
                       e.index == (size_t)side && e.where == TS_WHERE_NONE,
                   "side %d case %zu: %s", side, k, ts_status_name(e.status));
            message_has(&e, x, y, z, &o, side ? "the upper field" : "the lower field");
            message_has(&e, x, y, z, &o, cases[k].want);
            ts_surface_free(s);
        }
    }
    return th_report("test_grid_bound_refusals");
}
