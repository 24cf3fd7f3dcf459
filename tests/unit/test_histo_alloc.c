/* TS_ERR_NOMEM of ts_histo_new (docs/method.md §12): the library's test
 * hook (internal.h) makes the k-th allocation fail, for every k until the
 * build needs no more; nothing may leak (ASan) and *out stays NULL. */
#include "th.h"
#include "internal.h"
#include "trigspline.h"

#include <stdint.h>

int main(void)
{
    static const double e[5] = {0, 1, 2, 3, 4}, T[4] = {0, 3, 1, 0};
    int failed = 0;
    for (long k = 1; k <= 8; k++) {
        ts_histo *h = (ts_histo *)(uintptr_t)1;
        ts_error err;
        ts__test_fail_alloc = k;
        ts_status st = ts_histo_new(e, T, 4, NULL, &h, &err);
        long left = ts__test_fail_alloc;
        ts__test_fail_alloc = 0;
        if (left > 0) { /* fewer than k allocations: success */
            CHECK(st == TS_OK && h != NULL);
            ts_histo_free(h);
            break;
        }
        failed++;
        CHECKF(st == TS_ERR_NOMEM && h == NULL && err.status == TS_ERR_NOMEM, "allocation %ld: %d",
               k, (int)st);
    }
    CHECK(failed == 3); /* the handle, the work arrays, the block */
    return th_report("test_histo_alloc");
}
