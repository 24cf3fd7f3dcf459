/* tsu_io: what its parts share, the allocation test hook and error reports
 * (see tsu_io.h).  Tool side only (trigspline_support), not part of
 * libtrigspline.  The parts: tsu_number.c, tsu_time.c, tsu_table.c,
 * tsu_output.c. */
#define _POSIX_C_SOURCE 200809L

#include "tsu_io_internal.h"

#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

/* ================================================================== */
/* Allocation (with the test hook)                                      */
/* ================================================================== */

static long io_fail_after = -1;

void tsu_io__fail_alloc_after(long n) { io_fail_after = n < 0 ? -1 : n; }

static int io_alloc_fails(void)
{
    if (io_fail_after < 0)
        return 0;
    return io_fail_after-- == 0;
}
void *tsu_io__malloc(size_t n) { return io_alloc_fails() ? NULL : malloc(n); }
void *tsu_io__calloc(size_t n, size_t sz) { return io_alloc_fails() ? NULL : calloc(n, sz); }
void *tsu_io__realloc(void *p, size_t n) { return io_alloc_fails() ? NULL : realloc(p, n); }

/* ================================================================== */
/* Errors                                                               */
/* ================================================================== */

const char *tsu_io_strerror(tsu_io_status st)
{
    switch (st) {
    case TSU_IO_OK: return "success";
    case TSU_IO_END: return "end of input";
    case TSU_IO_ERR_NULL: return "null argument";
    case TSU_IO_ERR_NOMEM: return "out of memory";
    case TSU_IO_ERR_OVERFLOW: return "size overflow";
    case TSU_IO_ERR_OPTION: return "invalid option";
    case TSU_IO_ERR_OPEN: return "cannot open input";
    case TSU_IO_ERR_READ: return "read error";
    case TSU_IO_ERR_EMPTY: return "no data";
    case TSU_IO_ERR_NUMBER: return "not a number";
    case TSU_IO_ERR_NONFINITE: return "not a finite number";
    case TSU_IO_ERR_RANGE: return "number out of range";
    case TSU_IO_ERR_FIELDS: return "wrong number of fields";
    case TSU_IO_ERR_LINE: return "line too long";
    case TSU_IO_ERR_QUOTE: return "bad quoting";
    case TSU_IO_ERR_TIME: return "not a valid date or time";
    case TSU_IO_ERR_LAYOUT: return "ambiguous table layout";
    case TSU_IO_ERR_ENCODING: return "not UTF-8 text";
    case TSU_IO_STATUS_COUNT_: break;
    }
    return "unknown status";
}

void tsu_io__err_clear(tsu_io_error *e)
{
    if (e) {
        e->status = TSU_IO_OK;
        e->sys_errno = 0;
        e->line = 0;
        e->column = 0;
        e->field = 0;
        e->msg[0] = 0;
    }
}

void tsu_io__err_set(tsu_io_error *e, tsu_io_status st, int sys, const char *name,
                     unsigned long long line, size_t col, size_t field, const char *fmt, ...)
{
    va_list ap;
    int n;
    if (!e)
        return;
    e->status = st;
    e->sys_errno = sys;
    e->line = line;
    e->column = col;
    e->field = field;
    if (!name)
        name = "<input>";
    if (line && col)
        n = snprintf(e->msg, sizeof e->msg, "%s:%llu:%zu: ", name, line, col);
    else if (line)
        n = snprintf(e->msg, sizeof e->msg, "%s:%llu: ", name, line);
    else
        n = snprintf(e->msg, sizeof e->msg, "%s: ", name);
    if (n < 0)
        n = 0;
    if ((size_t)n >= sizeof e->msg)
        return;
    va_start(ap, fmt);
    vsnprintf(e->msg + n, sizeof e->msg - (size_t)n, fmt, ap);
    va_end(ap);
}

/* "text" with non-printable bytes as \xNN, cut after 40 bytes with "..." */
void tsu_io__quote_text(char *dst, size_t dsz, const char *s, const char *e)
{
    size_t k = 0, i, n = (size_t)(e - s);
    static const char hex[] = "0123456789abcdef";
    if (dsz < 60) { /* never leave dst unterminated */
        if (dsz)
            dst[0] = 0;
        return;
    }
    dst[k++] = '"';
    for (i = 0; i < n && i < 40; i++) {
        unsigned char ch = (unsigned char)s[i];
        if (ch >= 0x20 && ch < 0x7f) {
            dst[k++] = (char)ch;
        } else {
            dst[k++] = '\\';
            dst[k++] = 'x';
            dst[k++] = hex[ch >> 4];
            dst[k++] = hex[ch & 15];
        }
        if (k + 8 >= dsz)
            break;
    }
    dst[k++] = '"';
    if (i < n) {
        dst[k++] = '.';
        dst[k++] = '.';
        dst[k++] = '.';
    }
    dst[k] = 0;
}


char *tsu_io__dup_str(const char *s, size_t n)
{
    char *d = tsu_io__malloc(n + 1);
    if (d) {
        memcpy(d, s, n);
        d[n] = 0;
    }
    return d;
}
