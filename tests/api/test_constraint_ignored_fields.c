/* Constraint records of kinds without a bound (convex, concave, monotone,
 * slope) ignore the bound fields (include/trigspline.h, ts_constraint:
 * "LOWER, UPPER" only): a convex record whose caller left bound =
 * TS_BOUND_POLYLINE with px = py = NULL and n_poly = 3, or TS_BOUND_SPLINE
 * with spline = NULL, builds the same spline bit for bit as the plain
 * record (the copy kept in the spline used to read px there).  And
 * ts_constraints_diagnose on data the records admit: TS_OK with the record
 * of "nothing failed" (header: condition TS_CONDITION_NONE, no index). */
#include "trigspline.h"
#include "th.h"

#include <string.h>

static ts_spline *fit(const double *x, const double *f, size_t n, const ts_constraint *c)
{
    ts_spline_options o;
    ts_spline_options_init(&o);
    o.constraints = c;
    o.n_constraints = 1;
    ts_spline *s = NULL;
    ts_error e;
    ts_status st = ts_spline_new(x, f, n, &o, &s, &e);
    CHECKF(st == TS_OK && e.status == TS_OK, "status %d", (int)st);
    return s;
}

int main(void)
{
    static const double x[5] = {0, 1, 2, 3, 4}, f[5] = {4, 1, 0, 1, 4}; /* convex */
    ts_constraint plain;
    ts_constraint_init(&plain, TS_CONSTRAINT_CONVEX);
    ts_spline *ref = fit(x, f, 5, &plain);

    TH_CASE("bound fields left in a convex record");
    for (int k = 0; k < 2; k++) {
        ts_constraint c = plain;
        c.bound = k ? TS_BOUND_SPLINE : TS_BOUND_POLYLINE;
        c.n_poly = 3; /* px, py, spline stay NULL */
        ts_spline *s = fit(x, f, 5, &c);
        if (!s || !ref)
            continue;
        for (int j = 0; j <= 40; j++) {
            double t = 0.1 * j, a = 0, b = 0;
            CHECK(ts_spline_eval(ref, t, NULL, &a) == TS_OK && ts_spline_eval(s, t, NULL, &b) == TS_OK);
            CHECKF(memcmp(&a, &b, sizeof a) == 0, "x = %g: %.17g vs %.17g", t, a, b);
        }
        ts_constraint_report r;
        ts_constraint_report_init(&r);
        CHECK(ts_spline_constraint_report(s, 0, 0, &r) == TS_OK && r.certified);
        ts_spline_free(s);
    }

    TH_CASE("ts_constraints_diagnose on admissible data");
    ts_spline_options o;
    ts_spline_options_init(&o);
    o.constraints = &plain;
    o.n_constraints = 1;
    ts_constraint_failure fl;
    ts_constraint_failure_init(&fl);
    fl.index = 7; /* reset by the call */
    CHECK(ts_constraints_diagnose(x, f, 5, &o, &fl) == TS_OK);
    CHECK(fl.status == TS_OK && fl.condition == TS_CONDITION_NONE && fl.index == TS_NO_INDEX &&
          fl.constraint == TS_NO_INDEX && fl.where == TS_WHERE_NONE);
    ts_spline_free(ref);
    return th_report("test_constraint_ignored_fields");
}
