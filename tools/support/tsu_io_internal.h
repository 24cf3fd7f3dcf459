/* What the parts of tsu_io (tsu_io.c, tsu_number.c, tsu_time.c, tsu_table.c,
 * tsu_output.c) share; not installed, not for callers of tsu_io.h. */
#ifndef TSU_IO_INTERNAL_H
#define TSU_IO_INTERNAL_H

#include "tsu_io.h"

#include <stddef.h>

#if defined(__GNUC__)
#define IO_PRINTF(a, b) __attribute__((format(printf, a, b)))
#else
#define IO_PRINTF(a, b)
#endif

#define IS_DIGIT(c) ((unsigned)((unsigned char)(c) - '0') < 10u)
#define IS_BLANK(c) ((c) == ' ' || (c) == '\t')

/* malloc, calloc, realloc failing on request (tsu_io__fail_alloc_after). */
void *tsu_io__malloc(size_t n);
void *tsu_io__calloc(size_t n, size_t sz);
void *tsu_io__realloc(void *p, size_t n);
/* A NUL-terminated copy of s[0..n) (tsu_io__malloc); NULL: no memory. */
char *tsu_io__dup_str(const char *s, size_t n);

/* Reset *e (NULL ok). */
void tsu_io__err_clear(tsu_io_error *e);
/* Fill *e (NULL ok): the message is "NAME:LINE:COL: " (LINE, COL left out
 * when 0; NAME "<input>" when NULL) followed by fmt. */
void tsu_io__err_set(tsu_io_error *e, tsu_io_status st, int sys, const char *name,
                     unsigned long long line, size_t col, size_t field, const char *fmt, ...)
    IO_PRINTF(8, 9);
/* "text" with non-printable bytes as \xNN, cut after 40 bytes with "...";
 * dsz at least 60 (else dst is made empty). */
void tsu_io__quote_text(char *dst, size_t dsz, const char *s, const char *e);

#endif
