/* TS_ERR_NOMEM of ts_surface_new (docs/method.md §11): the library's test
 * hook (internal.h) makes the k-th allocation fail, for every k until the
 * build needs no more; nothing may leak (ASan) and *out stays NULL. */
#include "th.h"
#include "internal.h"
#include "trigspline.h"

#include <stdint.h>

int main(void)
{
    static const double x[3] = {0, 1, 2}, y[3] = {0, 1, 3};
    static const double z[9] = {1, 2, 3, 4, 0, 6, 7, 8, 9};
    int failed = 0;
    for (long k = 1; k <= 8; k++) {
        ts_surface *s = (ts_surface *)(uintptr_t)1;
        ts_error err;
        ts__test_fail_alloc = k;
        ts_status st = ts_surface_new(x, 3, y, 3, z, NULL, &s, &err);
        long left = ts__test_fail_alloc;
        ts__test_fail_alloc = 0;
        if (left > 0) { /* fewer than k allocations: success */
            CHECK(st == TS_OK && s != NULL);
            ts_surface_free(s);
            break;
        }
        failed++;
        CHECKF(st == TS_ERR_NOMEM && s == NULL && err.status == TS_ERR_NOMEM, "allocation %ld: %d",
               k, (int)st);
    }
    CHECK(failed == 2); /* the handle and the block */

    /* between two gridded fields (docs/method.md §11.7): also the fields'
     * copy and the union of their grid lines (the fields' order) */
    static const double fx[2] = {-1, 4}, lo[4] = {-5, -5, -5, -5}, up[4] = {20, 20, 20, 20};
    ts_surface_options o;
    ts_surface_options_init(&o);
    o.shape = TS_SURFACE_GRIDS;
    o.has_lower = o.has_upper = 1;
    o.lower_grid = (ts_grid_bound){fx, 2, fx, 2, lo};
    o.upper_grid = (ts_grid_bound){fx, 2, fx, 2, up};
    failed = 0;
    for (long k = 1; k <= 8; k++) {
        ts_surface *s = (ts_surface *)(uintptr_t)1;
        ts_error err;
        ts__test_fail_alloc = k;
        ts_status st = ts_surface_new(x, 3, y, 3, z, &o, &s, &err);
        long left = ts__test_fail_alloc;
        ts__test_fail_alloc = 0;
        if (left > 0) {
            CHECK(st == TS_OK && s != NULL);
            ts_surface_free(s);
            break;
        }
        failed++;
        CHECKF(st == TS_ERR_NOMEM && s == NULL && err.status == TS_ERR_NOMEM, "grids, allocation %ld: %d",
               k, (int)st);
    }
    CHECK(failed == 4); /* the handle, the block, the fields, the union of their lines */
    return th_report("test_surface_alloc");
}
