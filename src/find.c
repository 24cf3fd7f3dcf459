/* The interval of a query: the one search of ts_spline_eval, curves and surfaces
 * (ts__search, basis.c), for callers outside the library. */
#include "internal.h"

ts_status ts_spline_find_interval(const ts_spline *s, double x, ts_cursor *cur, size_t *i)
{
    if (i)
        *i = TS_NO_INDEX;
    if (!s || !i)
        return TS_ERR_NULL;
    if (!(s->x[0] <= x && x <= s->x[s->n])) /* NaN fails */
        return TS_ERR_DOMAIN;
    *i = ts__locate(s, x, cur);
    return TS_OK;
}
