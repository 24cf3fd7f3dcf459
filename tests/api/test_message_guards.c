/* ts_error_message for a gridded-field surface when the error and the
 * context do not support a field's sentence: TS_ERR_SIDE at a node without
 * the grid's coordinates, TS_ERR_LINES with only a lower field.  The header
 * promises the generic form there ("node (I, J): TEXT" / "TEXT", TEXT =
 * ts_strerror(status)); the expected sentences are written out from it. */
#include "trigspline.h"
#include "th.h"

#include <stdio.h>
#include <string.h>

static void expect(const ts_error *e, const ts_error_context *c, const char *want)
{
    char buf[512];
    size_t m = ts_error_message(e, c, buf, sizeof buf);
    CHECKF(m == strlen(want) && strcmp(buf, want) == 0, "\n   got  \"%s\"\n   want \"%s\"", buf,
           want);
}

int main(void)
{
    double x[3] = {0, 1, 2}, y[3] = {0, 1, 2}, z[9] = {0};
    double gx[2] = {0, 2}, gy[2] = {0, 2}, lo[4] = {-1, -1, -1, -1};
    ts_surface_options o;
    ts_surface_options_init(&o);
    o.shape = TS_SURFACE_GRIDS;
    o.has_lower = 1;
    o.lower_grid = (ts_grid_bound){gx, 2, gy, 2, lo};
    ts_error_context c;
    ts_error_context_init(&c);
    c.n_points = 3;
    c.ny_points = 3;
    c.f = z;
    c.surface_options = &o;
    char want[512];

    TH_CASE("a node's side without the grid's x and y");
    ts_error e = {TS_ERR_SIDE, 4, TS_WHERE_POINT};
    snprintf(want, sizeof want, "node (1, 1): %s", ts_strerror(TS_ERR_SIDE));
    expect(&e, &c, want);

    TH_CASE("the fields' order with only a lower field");
    c.x = x;
    c.y = y;
    ts_error l = {TS_ERR_LINES, TS_NO_INDEX, TS_WHERE_NONE};
    expect(&l, &c, ts_strerror(TS_ERR_LINES));
    return th_report("test_message_guards");
}
