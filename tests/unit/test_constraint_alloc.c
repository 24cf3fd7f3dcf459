/* TS_ERR_NOMEM of ts_spline_new with constraint records, among them a bound
 * given by another spline (docs/method.md §13.7, whose copy the fitted
 * spline allocates): the library's test hook (internal.h) makes the k-th
 * allocation fail, for every k until the build needs no more; nothing may
 * leak (ASan) and *out stays NULL.  The fitted spline's copy of B: its
 * reports are unchanged after B is freed. */
#include "th.h"
#include "internal.h"
#include "trigspline.h"

#include <stdint.h>

int main(void)
{
    static const double bx[3] = {-1, 1.5, 4}, by[3] = {0, 0.5, 0};
    static const double x[4] = {0, 1, 2, 3}, f[4] = {1, 2, 1.5, 3};
    ts_spline *b = NULL;
    CHECK(ts_spline_new(bx, by, 3, NULL, &b, NULL) == TS_OK);
    ts_constraint c[2];
    ts_constraint_init(&c[0], TS_CONSTRAINT_LOWER);
    c[0].bound = TS_BOUND_SPLINE;
    c[0].spline = b;
    ts_constraint_init(&c[1], TS_CONSTRAINT_SLOPE_ABS);
    c[1].value = 10.0;
    ts_spline_options o;
    ts_spline_options_init(&o);
    o.constraints = c;
    o.n_constraints = 2;
    int failed = 0;
    for (long k = 1; k <= 32; k++) {
        ts_spline *s = (ts_spline *)(uintptr_t)1;
        ts_error err;
        ts__test_fail_alloc = k;
        ts_status st = ts_spline_new(x, f, 4, &o, &s, &err);
        long left = ts__test_fail_alloc;
        ts__test_fail_alloc = 0;
        if (left > 0) { /* fewer than k allocations: success */
            CHECK(st == TS_OK && s != NULL);
            ts_constraint_report r0, r1;
            ts_constraint_report_init(&r0);
            ts_constraint_report_init(&r1);
            CHECK(ts_spline_constraint_report(s, 0, 1, &r0) == TS_OK && r0.certified);
            ts_spline_free(b);
            b = NULL;
            CHECK(ts_spline_constraint_report(s, 0, 1, &r1) == TS_OK);
            CHECK(r1.gap == r0.gap && r1.at == r0.at && r1.certified == 1);
            ts_spline_free(s);
            break;
        }
        failed++;
        CHECKF(st == TS_ERR_NOMEM && s == NULL && err.status == TS_ERR_NOMEM, "allocation %ld: %d",
               k, (int)st);
    }
    /* the spline's own allocations, the records' work arrays, the stored
     * records, the polyline points and bound copies, the copies' headers */
    CHECK(failed >= 5);
    ts_spline_free(b);
    return th_report("test_constraint_alloc");
}
