/* ts_error_message for TS_ERR_CONDITION of constraint records: the
 * sentences for an upper bound (inside-bound, and a touch on a polyline's
 * inner breakpoint past the first), and without the data in the context
 * the generic "P: TEXT" (TEXT = ts_strerror) instead of a sentence that
 * would need them. */
#include "trigspline.h"
#include "th.h"

#include <string.h>

static void message(const ts_error *e, const double *x, const double *f, size_t n,
                    const ts_spline_options *o, char *buf)
{
    ts_error_context c;
    ts_error_context_init(&c);
    c.x = x;
    c.f = f;
    c.n_points = n;
    c.spline_options = o;
    CHECK(ts_error_message(e, &c, buf, 512) > 0);
}

int main(void)
{
    char buf[512];
    ts_spline_options o;
    ts_spline_options_init(&o);
    ts_constraint c;
    ts_spline *s = NULL;
    ts_error e;

    TH_CASE("upper bound crossed");
    double x[4] = {0, 1, 2, 3}, f[3] = {0, 2, 0};
    ts_constraint_init(&c, TS_CONSTRAINT_UPPER);
    c.value = 1.0;
    o.constraints = &c;
    o.n_constraints = 1;
    CHECK(ts_spline_new(x, f, 3, &o, &s, &e) == TS_ERR_CONDITION && e.index == 1 && !s);
    message(&e, x, f, 3, &o, buf);
    CHECKF(strstr(buf, "is not below the upper bound") != NULL, "%s", buf);
    /* without the values, or without the abscissae: no sentence about them */
    message(&e, x, NULL, 3, &o, buf);
    CHECKF(strstr(buf, ts_strerror(TS_ERR_CONDITION)) != NULL, "%s", buf);
    CHECKF(strstr(buf, "is not below") == NULL, "%s", buf);
    message(&e, NULL, f, 3, &o, buf);
    CHECKF(strstr(buf, "is not below") == NULL, "%s", buf);
    CHECKF(strstr(buf, ts_strerror(TS_ERR_CONDITION)) != NULL, "%s", buf);

    TH_CASE("touch at an upper polyline's peak");
    /* breakpoints 0, 1, 2, 3; the datum (2, 10) on the peak at the third:
     * slopes 5 then −5, a corner turning into the region (upper: the slope
     * falls there), so no C¹ curve below it passes through the datum */
    double px[4] = {0, 1, 2, 3}, py[4] = {5, 5, 10, 5}, g[4] = {0, 0, 10, 0};
    ts_constraint_init(&c, TS_CONSTRAINT_UPPER);
    c.bound = TS_BOUND_POLYLINE;
    c.px = px;
    c.py = py;
    c.n_poly = 4;
    CHECK(ts_spline_new(x, g, 4, &o, &s, &e) == TS_ERR_CONDITION && e.index == 2 && !s);
    message(&e, x, g, 4, &o, buf);
    CHECKF(strstr(buf, "lies on the upper bound at its breakpoint, where the polyline's slope "
                       "goes from 5 to -5") != NULL,
           "%s", buf);
    return th_report("test_condition_messages");
}
