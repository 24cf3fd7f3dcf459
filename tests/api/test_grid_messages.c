/* ts_error_message for surfaces between gridded fields when the context is
 * partial (no grid, too few nodes, no values) or the error does not match
 * a field's sentence (an index naming no side, a status the fields do not
 * explain, a malformed field in the options): the sentence the header
 * promises where it can be formed, else the generic "P: TEXT" / "TEXT"
 * with TEXT = ts_strerror(status) — never a sentence about a field the
 * context cannot support. */
#include "trigspline.h"
#include "th.h"

#include <string.h>

static void message(const ts_error *e, const double *x, size_t nx, const double *y, size_t ny,
                    const double *z, const ts_surface_options *o, char *buf, size_t len)
{
    ts_error_context c;
    ts_error_context_init(&c);
    c.x = x;
    c.n_points = nx;
    c.y = y;
    c.ny_points = ny;
    c.f = z;
    c.surface_options = o;
    size_t m = ts_error_message(e, &c, buf, len);
    CHECK(m > 0 && strlen(buf) == m);
}

static void has(const char *buf, const char *want)
{
    CHECKF(strstr(buf, want) != NULL, "\"%s\" lacks \"%s\"", buf, want);
}

static void lacks(const char *buf, const char *no)
{
    CHECKF(strstr(buf, no) == NULL, "\"%s\" has \"%s\"", buf, no);
}

int main(void)
{
    double x[3] = {0, 1, 2}, y[3] = {0, 1, 2}, z[9] = {0};
    double gx[2] = {0, 2}, gy[2] = {0, 2}, lo[4] = {-1, -1, -1, -1}, up[4] = {1, 1, 1, 1};
    double bad[2] = {2, 0};
    ts_surface_options o;
    ts_surface_options_init(&o);
    o.shape = TS_SURFACE_GRIDS;
    o.has_lower = o.has_upper = 1;
    o.lower_grid = (ts_grid_bound){gx, 2, gy, 2, lo};
    o.upper_grid = (ts_grid_bound){gx, 2, bad, 2, up};
    char buf[512];
    ts_error e;

    TH_CASE("malformed field, partial context");
    ts_surface *s = NULL;
    CHECK(ts_surface_new(x, 3, y, 3, z, &o, &s, &e) == TS_ERR_BOUND_GRID && e.index == 1);
    /* the field's own fault is named whatever the context lacks */
    const double *xs[4] = {NULL, x, x, x}, *ys[4] = {y, NULL, y, y};
    size_t nxs[4] = {3, 3, 1, 3}, nys[4] = {3, 3, 3, 1};
    for (int k = 0; k < 4; k++) {
        message(&e, xs[k], nxs[k], ys[k], nys[k], z, &o, buf, sizeof buf);
        has(buf, "the upper field's y[1] = 0 is not finite");
    }
    /* a field that covers nothing is only checked against a known grid:
     * without one, a well-formed field has no fault to name */
    double narrow[2] = {0, 1.5};
    o.upper_grid = (ts_grid_bound){gx, 2, narrow, 2, up};
    CHECK(ts_surface_new(x, 3, y, 3, z, &o, &s, &e) == TS_ERR_BOUND_GRID && e.index == 1);
    message(&e, x, 3, y, 3, z, &o, buf, sizeof buf);
    has(buf, "does not cover the surface's grid [0, 2] x [0, 2]");
    message(&e, NULL, 0, NULL, 0, NULL, &o, buf, sizeof buf);
    has(buf, "the upper field");
    lacks(buf, "does not cover the surface's grid [");
    has(buf, ts_strerror(TS_ERR_BOUND_GRID));

    TH_CASE("errors the fields do not explain");
    o.upper_grid = (ts_grid_bound){gx, 2, gy, 2, up};
    /* an index naming neither side */
    e = (ts_error){TS_ERR_BOUND_GRID, 2, TS_WHERE_NONE};
    message(&e, x, 3, y, 3, z, &o, buf, sizeof buf);
    lacks(buf, "field");
    has(buf, ts_strerror(TS_ERR_BOUND_GRID));
    /* TS_ERR_UNPROVEN not at a patch */
    e = (ts_error){TS_ERR_UNPROVEN, TS_NO_INDEX, TS_WHERE_NONE};
    message(&e, x, 3, y, 3, z, &o, buf, sizeof buf);
    lacks(buf, "gridded fields");
    /* TS_ERR_SIDE at a node beyond the grid, at a node without values, and
     * at a node above the lower field with no upper field in the options */
    e = (ts_error){TS_ERR_SIDE, 9, TS_WHERE_POINT};
    message(&e, x, 3, y, 3, z, &o, buf, sizeof buf);
    lacks(buf, "field, whose value");
    e.index = 4;
    message(&e, x, 3, y, 3, NULL, &o, buf, sizeof buf);
    lacks(buf, "field, whose value");
    o.has_upper = 0;
    message(&e, x, 3, y, 3, z, &o, buf, sizeof buf);
    lacks(buf, "field, whose value");
    /* a malformed field in the options: no value is read from it */
    o.has_upper = 1;
    o.upper_grid = (ts_grid_bound){gx, 2, bad, 2, up};
    z[4] = 3.0;
    message(&e, x, 3, y, 3, z, &o, buf, sizeof buf);
    lacks(buf, "upper field, whose value");
    o.lower_grid = (ts_grid_bound){gx, 1, gy, 2, lo};
    z[4] = -3.0;
    message(&e, x, 3, y, 3, z, &o, buf, sizeof buf);
    lacks(buf, "lower field, whose value");
    /* TS_ERR_LINES with one field malformed, and without a grid */
    e = (ts_error){TS_ERR_LINES, TS_NO_INDEX, TS_WHERE_NONE};
    message(&e, x, 3, y, 3, z, &o, buf, sizeof buf);
    lacks(buf, "is not above the lower field");
    o.lower_grid = (ts_grid_bound){gx, 2, gy, 2, lo};
    o.upper_grid = (ts_grid_bound){gx, 2, gy, 2, up};
    message(&e, NULL, 0, NULL, 0, z, &o, buf, sizeof buf);
    lacks(buf, "is not above the lower field");
    /* one side only: nothing to order; a side error not at a node */
    o.has_lower = 0;
    message(&e, x, 3, y, 3, z, &o, buf, sizeof buf);
    lacks(buf, "is not above the lower field");
    e = (ts_error){TS_ERR_SIDE, 4, TS_WHERE_NONE};
    message(&e, x, 3, y, 3, z, &o, buf, sizeof buf);
    lacks(buf, "field, whose value");
    o.has_lower = 1;
    message(&e, x, 3, y, 3, z, &o, buf, sizeof buf);
    lacks(buf, "field, whose value");
    e = (ts_error){TS_ERR_LINES, TS_NO_INDEX, TS_WHERE_NONE};
    /* well-formed fields that do not meet: nothing to place */
    message(&e, x, 3, y, 3, z, &o, buf, sizeof buf);
    lacks(buf, "is not above the lower field");
    has(buf, ts_strerror(TS_ERR_LINES));
    return th_report("test_grid_messages");
}
