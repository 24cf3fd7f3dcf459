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
    return th_report("test_surface_alloc");
}
