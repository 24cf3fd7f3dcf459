/* Status strings, the version, the error setter and the library's
 * allocation (docs/method.md is not involved: this is bookkeeping). */
#define _DEFAULT_SOURCE /* MADV_HUGEPAGE */
#include "internal.h"

#include <stdint.h>
#include <stdlib.h>
#if defined(__linux__)
#include <sys/mman.h>
#endif

const char *ts_version(void)
{
    return TS_VERSION_STRING;
}

static const char *const ts_messages[TS_STATUS_COUNT_] = {
    [TS_OK] = "success",
    [TS_ERR_NULL] = "a required pointer argument is NULL",
    [TS_ERR_NOMEM] = "out of memory",
    [TS_ERR_OVERFLOW] = "size overflow: too many points",
    [TS_ERR_TOO_FEW] = "too few points: at least 2 are needed",
    [TS_ERR_NONFINITE] = "NaN or infinite value in the input",
    [TS_ERR_UNSORTED] = "x values are not strictly increasing (unsorted or duplicate)",
    [TS_ERR_ALPHA] = "alpha must be finite and > 0",
    [TS_ERR_BETA] = "beta must be finite and >= 0, and alpha + beta > 0",
    [TS_ERR_MARGIN] = "margin must be finite and > 0",
    [TS_ERR_LENGTH] = "a per-interval or per-point array has the wrong length",
    [TS_ERR_OPTION] = "invalid option value or combination",
    [TS_ERR_PERIODIC] = "periodic slopes need the first and last values equal",
    [TS_ERR_DOMAIN] = "query is NaN or outside the data range",
    [TS_ERR_NEGATIVE] = "negative data value for the positive scheme",
    [TS_ERR_SIDE] = "a data point lies on or across a constraint line",
    [TS_ERR_LINES] = "the lower line is not strictly below the upper line at a data point",
    [TS_ERR_NONMONOTONE] = "data are not monotone",
    [TS_ERR_INFEASIBLE] = "no beta keeps this interval inside the region",
    [TS_ERR_VIOLATED] = "the spline leaves the region on some interval",
    [TS_ERR_GEOMETRIC] = "alpha + beta below the geometric-form bound",
    [TS_ERR_DIMENSION] = "curve dimension must be 2 or 3",
    [TS_ERR_INDEX] = "index out of range",
    [TS_ERR_ZERO_SLOPE] = "slope of the wrong sign at a knot on the boundary",
    [TS_ERR_SLOPE_OVERFLOW] = "a slope overflows: the data change too fast for the interval width",
    [TS_ERR_TOO_LARGE] = "a data or control value exceeds DBL_MAX/4: the spline could overflow",
    [TS_ERR_CONTROL_OVERFLOW] = "control values overflow: alpha + beta is too small for the slopes",
    [TS_ERR_PRECISION] = "cannot be certified in double precision: gap below the rounding bound",
    [TS_ERR_UNPROVEN] = "no certified beta found, and no proof that none exists (C1 search gave up)",
    [TS_ERR_WIDTH] = "an interval width overflows, or underflows below the smallest normal double",
    [TS_ERR_VERSION] = "a struct's struct_size does not match this library (use its *_init)",
    [TS_ERR_CONDITION] = "the data violate a necessary condition of a constraint",
    [TS_ERR_BOUND_GRID] = "a gridded bound is malformed or does not cover the surface's grid",
};

const char *ts_strerror(ts_status status)
{
    return ts__strerror(status);
}

const char *ts__strerror(ts_status status)
{
    /* every status has its message (tests/unit/test_cover_api.c checks) */
    if ((unsigned)status < (unsigned)TS_STATUS_COUNT_)
        return ts_messages[status];
    return "unknown status code";
}

void ts__error_set(ts_error *err, ts_status st, size_t index, ts_where where)
{
    if (err) {
        err->status = st;
        err->index = index;
        err->where = where;
    }
}

#ifdef TS_TEST_HOOKS
long ts__test_fail_alloc;
ts__limits ts__test_limits = TS_LIMITS_DEFAULT;
#endif

/* One definition for both builds (coverage tools merge the two by line). */
static int alloc_should_fail(void)
{
#ifdef TS_TEST_HOOKS
    return ts__test_fail_alloc > 0 && --ts__test_fail_alloc == 0;
#else
    return 0;
#endif
}

void *ts__malloc(size_t bytes)
{
    return alloc_should_fail() ? NULL : malloc(bytes);
}

void *ts__malloc_n(size_t count, size_t size)
{
    return count > SIZE_MAX / size ? NULL : ts__malloc(count * size);
}

void *ts__calloc(size_t count, size_t size)
{
    return alloc_should_fail() ? NULL : calloc(count, size);
}

/* The spline's one block.  Large blocks are 2 MiB-aligned and marked for
 * transparent huge pages where Linux offers them: first-touch page faults
 * dominate construction time at large n (bench/RESULTS.md), and huge
 * pages cut them severalfold.  Freed with free() either way. */
void *ts__alloc_block(size_t bytes)
{
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    const size_t huge = (size_t)2 << 20;
    /* 4 huge <= bytes <= SIZE_MAX - huge (rounding up cannot overflow) */
    if (bytes - 4 * huge <= SIZE_MAX - 5 * huge) {
        if (alloc_should_fail())
            return NULL;
        size_t rounded = (bytes + huge - 1) / huge * huge;
        void *p = aligned_alloc(huge, rounded);
        if (p) {
            (void)madvise(p, rounded, MADV_HUGEPAGE); /* advice only: failure is harmless */
            return p;
        }
        return malloc(bytes);
    }
#endif
    return ts__malloc(bytes);
}

ts_status ts__fail(ts_error *err, ts_status st, size_t index, ts_where where)
{
    ts__error_set(err, st, index, where);
    return st;
}
