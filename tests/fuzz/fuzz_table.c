/*
 * fuzz_table — the streaming table reader of tsu_io against a reference
 * reader written here from the reader's documentation (tsu_io.h, "Input
 * format"), not from its code: the whole input in memory, one character
 * state machine for records and quotes, strtod in the C locale for numbers
 * (after checking the documented grammar; correctly rounded like
 * tsu_parse_double), timegm for dates.
 *
 * Input: byte 0 picks the options (bit 0 decimal comma, bit 1 missing words
 * "NA,NaN,null", bit 2 date detection, bits 3-4 delimiter auto / ',' / ';' /
 * tab, bit 5 skip one line); the rest is the file.  Checked: both accept or
 * both refuse; when both accept, the same number of rows and columns, the
 * same header or none, and bit-identical values (NaN for missing).  Also:
 * the reader is run on the same input through tsu_read_table and must agree
 * with itself.
 *
 * A libFuzzer target (`make fuzz`); `make test` replays the seed corpus
 * tests/fuzz/corpus/table/ through it (replay_main.c, test_fuzz_table).
 */
#define _GNU_SOURCE /* timegm */
#include "tsu_io.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

typedef struct ropts {
    int dcomma, na, tdetect, skip;
    char delim; /* 0 auto, ',', ';', '\t' */
} ropts;

typedef struct ref {
    int ok, header;
    size_t nrows, ncols;
    double *v; /* nrows * ncols */
    size_t cap;
} ref;

static int blank(char c) { return c == ' ' || c == '\t'; }

/* ---- the documented number grammar, then strtod ---------------------- */
static int ref_number(const char *s, size_t n, int dcomma, double *v, int *nonfinite)
{
    char b[512];
    size_t i = 0;
    int digits = 0;
    *nonfinite = 0;
    if (n == 0 || n >= sizeof b || memchr(s, 0, n))
        return 0;
    memcpy(b, s, n);
    b[n] = 0;
    if (dcomma) {
        if (memchr(b, '.', n))
            return 0;
        char *c = memchr(b, ',', n);
        if (c)
            *c = '.';
    }
    {
        /* nan / inf / infinity words (the whole field) */
        const char *w = b + (b[0] == '+' || b[0] == '-');
        if (!strcasecmp(w, "nan") || !strcasecmp(w, "inf") || !strcasecmp(w, "infinity")) {
            *nonfinite = 1;
            return 0;
        }
    }
    if (b[i] == '+' || b[i] == '-')
        i++;
    while (b[i] >= '0' && b[i] <= '9')
        i++, digits++;
    if (b[i] == '.') {
        i++;
        while (b[i] >= '0' && b[i] <= '9')
            i++, digits++;
    }
    if (!digits)
        return 0;
    if (b[i] == 'e' || b[i] == 'E') {
        size_t j = i + 1, ed = 0;
        if (b[j] == '+' || b[j] == '-')
            j++;
        while (b[j] >= '0' && b[j] <= '9')
            j++, ed++;
        if (!ed)
            return 0;
        i = j;
    }
    if (i != n)
        return 0;
    *v = strtod(b, NULL);
    return isfinite(*v) ? 1 : 2; /* 2: the grammar of a number, out of range */
}

/* ---- dates: the documented forms, timegm ----------------------------- */
static int dig(const char *s, int k, int *v)
{
    int a = 0;
    for (int i = 0; i < k; i++) {
        if (s[i] < '0' || s[i] > '9')
            return 0;
        a = a * 10 + s[i] - '0';
    }
    *v = a;
    return 1;
}

static int ref_time(const char *s, size_t n, double *t)
{
    char b[128];
    int Y, M, D, h = 0, mi = 0, sec = 0, oh = 0, om = 0, sign = 0;
    size_t i = 10;
    double frac = 0;
    if (n < 10 || n >= sizeof b || memchr(s, 0, n))
        return 0;
    memcpy(b, s, n);
    b[n] = 0;
    if (!dig(b, 4, &Y) || b[4] != '-' || !dig(b + 5, 2, &M) || b[7] != '-' || !dig(b + 8, 2, &D))
        return 0;
    if (i < n) {
        if (!(b[i] == 'T' || b[i] == 't' || b[i] == ' ') || n < i + 6 || !dig(b + i + 1, 2, &h) ||
            b[i + 3] != ':' || !dig(b + i + 4, 2, &mi))
            return 0;
        i += 6;
        if (i < n && b[i] == ':') {
            if (!dig(b + i + 1, 2, &sec))
                return 0;
            i += 3;
            if (i < n && b[i] == '.' && i + 1 < n && b[i + 1] >= '0' && b[i + 1] <= '9') {
                size_t j = i + 1;
                while (j < n && b[j] >= '0' && b[j] <= '9')
                    j++;
                char fb[128];
                memcpy(fb, b + i, j - i);
                fb[j - i] = 0;
                frac = strtod(fb, NULL);
                i = j;
            }
        }
        if (i < n && (b[i] == 'Z' || b[i] == 'z')) {
            i++;
        } else if (i < n && (b[i] == '+' || b[i] == '-')) {
            sign = b[i] == '-' ? -1 : 1;
            if (!dig(b + i + 1, 2, &oh))
                return 0;
            i += 3;
            if (i < n && b[i] == ':' && i + 2 < n + 0 && dig(b + i + 1, 2, &om))
                i += 3;
            else if (i + 1 < n && dig(b + i, 2, &om))
                i += 2;
            else
                om = 0;
        }
    }
    if (i != n || M < 1 || M > 12 || D < 1 || h > 23 || mi > 59 || sec > 59 || oh > 23 || om > 59)
        return 0;
    struct tm tm;
    memset(&tm, 0, sizeof tm);
    tm.tm_year = Y - 1900;
    tm.tm_mon = M - 1;
    tm.tm_mday = D;
    tm.tm_hour = h;
    tm.tm_min = mi;
    tm.tm_sec = sec;
    time_t tt = timegm(&tm);
    if (tm.tm_mday != D || tm.tm_mon != M - 1) /* normalised: no such day */
        return 0;
    *t = (double)((long long)tt - (long long)sign * (oh * 3600 + om * 60)) + frac;
    return 1;
}

/* A date or date-time followed by a time-zone name (blanks, then '[' or two
 * letters): the reader takes it for a date all the same and refuses it. */
static int ascii_letter(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }

static int ref_zone(const char *s, size_t n)
{
    for (size_t k = n; k >= 10; k--) {
        double t;
        if (!ref_time(s, k, &t))
            continue;
        while (k < n && blank(s[k]))
            k++;
        return k < n && (s[k] == '[' || (k + 1 < n && ascii_letter(s[k]) && ascii_letter(s[k + 1])));
    }
    return 0;
}

static int is_na_word(const char *s, size_t n)
{
    static const char *const w[3] = {"NA", "NaN", "null"};
    for (int k = 0; k < 3; k++)
        if (strlen(w[k]) == n && strncasecmp(s, w[k], n) == 0)
            return 1;
    return 0;
}

/* ---- fields ---------------------------------------------------------- */
typedef struct fld {
    char *t; /* unquoted, trimmed (malloc) */
    size_t n;
    int quoted;
} fld;

/* Split a record (content only) into fields; -1 on a quote error. */
static long split(const char *s, size_t n, char dc, fld **out)
{
    size_t cap = 8, k = 0, i = 0;
    fld *f = malloc(cap * sizeof *f);
    for (;;) {
        size_t st;
        if (dc == '\t')
            while (i < n && s[i] == ' ')
                i++;
        else
            while (i < n && blank(s[i]))
                i++;
        if (!dc && i == n)
            break;
        if (k == cap)
            f = realloc(f, (cap *= 2) * sizeof *f);
        f[k].quoted = 0;
        if (i < n && s[i] == '"') {
            char *t = malloc(n + 1);
            size_t m = 0, j = i + 1;
            for (;;) {
                if (j >= n) {
                    free(t);
                    goto fail;
                }
                if (s[j] == '"') {
                    if (j + 1 < n && s[j + 1] == '"') {
                        t[m++] = '"';
                        j += 2;
                        continue;
                    }
                    break;
                }
                t[m++] = s[j++];
            }
            j++;
            if (dc)
                while (j < n && (dc == '\t' ? s[j] == ' ' : blank(s[j])))
                    j++;
            if (j < n && (dc ? s[j] != dc : !blank(s[j]))) {
                free(t);
                goto fail;
            }
            size_t a = 0;
            while (a < m && blank(t[a]))
                a++;
            while (m > a && blank(t[m - 1]))
                m--;
            memmove(t, t + a, m - a);
            f[k].t = t;
            f[k].n = m - a;
            f[k].quoted = 1;
            k++;
            i = j;
        } else {
            st = i;
            while (i < n && (dc ? s[i] != dc : !blank(s[i])))
                i++;
            size_t e = i;
            while (e > st && blank(s[e - 1]))
                e--;
            f[k].t = malloc(e - st + 1);
            memcpy(f[k].t, s + st, e - st);
            f[k].n = e - st;
            k++;
        }
        if (i >= n)
            break;
        if (dc)
            i++;
    }
    *out = f;
    return (long)k;
fail:
    for (size_t q = 0; q < k; q++)
        free(f[q].t);
    free(f);
    return -1;
}

static void free_fields(fld *f, long k)
{
    for (long q = 0; q < k; q++)
        free(f[q].t);
    free(f);
}

/* ---- the reference reader -------------------------------------------- */
static void ref_read(const char *d0, size_t n, const ropts *o, ref *r)
{
    size_t pos = 0, line = 0;
    int seen = 0; /* a content record was read (UTF-16 is looked for before it) */
    /* a lone CR ends a line like LF: the whole input translated first */
    char *d = malloc(n + 1);
    memcpy(d, d0, n);
    for (size_t i = 0; i < n; i++)
        if (d[i] == '\r' && (i + 1 == n || d[i + 1] != '\n'))
            d[i] = '\n';
    char dc = o->delim; /* 0: auto until known (then ' ' stands for white space) */
    int known = o->delim != 0, first = 1;
    unsigned char is_time[4096];
    memset(r, 0, sizeof *r);
    memset(is_time, 0, sizeof is_time);
    char *rec = malloc(n + 1);
    /* a compressed file or an archive, by its first bytes, whatever --skip
     * says (docs/cli.md, "Compressed input"): gzip, bzip2, xz, zstd, zip */
    static const unsigned char magic[5][6] = {{0x1f, 0x8b}, {'B', 'Z', 'h'},
                                              {0xfd, '7', 'z', 'X', 'Z', 0},
                                              {0x28, 0xb5, 0x2f, 0xfd}, {'P', 'K', 3, 4}};
    static const size_t magic_len[5] = {2, 3, 6, 4, 4};
    for (int k = 0; k < 5; k++)
        if (n >= magic_len[k] && memcmp(d, magic[k], magic_len[k]) == 0) {
            r->ok = 0;
            goto out;
        }
    while (pos < n) {
        /* one record: physical lines joined while a quote is open */
        size_t rl = 0, rec_line = line + 1, cend = (size_t)-1;
        int inq = 0, fs = 1, utf8 = 0; /* utf8: line 1 began with UTF-8's byte-order mark */
        if (line < (size_t)o->skip) {
            const char *nl = memchr(d + pos, '\n', n - pos);
            pos = nl ? (size_t)(nl - d) + 1 : n;
            line++;
            continue;
        }
        for (;;) {
            const char *nl = memchr(d + pos, '\n', n - pos);
            size_t e = nl ? (size_t)(nl - d) : n, i = pos;
            line++;
            if (line == 1 && e - pos >= 3 && memcmp(d + pos, "\xef\xbb\xbf", 3) == 0)
                i += 3, pos += 3, utf8 = 1;
            for (; i < e; i++) {
                char c = d[i];
                if (inq) {
                    if (c == '"') {
                        if (i + 1 < e && d[i + 1] == '"')
                            i++;
                        else
                            inq = 0, fs = 0;
                    }
                    continue;
                }
                if (cend != (size_t)-1)
                    break;
                if (c == '#') {
                    cend = rl + (i - pos);
                    break;
                }
                int sep = known ? (dc == ' ' ? blank(c) : c == dc) : (c == ',' || c == ';' ||
                                                                    c == '\t' || c == ' ');
                if (c == '"' && fs)
                    inq = 1, fs = 0;
                else if (sep)
                    fs = 1;
                else if (!blank(c))
                    fs = 0;
            }
            memcpy(rec + rl, d + pos, e - pos);
            rl += e - pos;
            pos = nl ? e + 1 : n;
            if (!inq)
                break;
            if (!nl) {
                r->ok = 0;
                goto out;
            }
            rec[rl++] = '\n';
        }
        /* UTF-16: its byte-order mark at the start of the file (after UTF-8's
         * mark the file is UTF-8 and FE FF are text), or a NUL before the
         * first content */
        if ((rec_line == 1 && !utf8 && rl >= 2 && ((unsigned char)rec[0] == 0xff || (unsigned char)rec[0] == 0xfe) &&
             (unsigned char)rec[1] == ((unsigned char)rec[0] ^ 1u)) ||
            (!seen && memchr(rec, '\0', rl))) {
            r->ok = 0;
            goto out;
        }
        if (cend != (size_t)-1)
            rl = cend;
        while (rl > 0 && (rec[rl - 1] == ' ' || rec[rl - 1] == '\t' || rec[rl - 1] == '\r'))
            rl--;
        size_t b = 0;
        while (b < rl && blank(rec[b]))
            b++;
        if (b == rl)
            continue;
        seen = 1;
        (void)rec_line;
        if (!known) {
            int q = 0, semi = 0, comma = 0, tab = 0;
            for (size_t i = 0; i < rl; i++) {
                if (rec[i] == '"')
                    q = !q;
                else if (!q)
                    semi |= rec[i] == ';', comma |= rec[i] == ',', tab |= rec[i] == '\t';
            }
            dc = semi ? ';' : comma && !o->dcomma ? ',' : tab ? '\t' : ' ';
            known = 1;
        }
        fld *f;
        long k = split(rec, rl, dc == ' ' ? 0 : dc, &f);
        if (first) {
            first = 0;
            int hdr = 0;
            for (long q = 0; k > 0 && q < k; q++) {
                double v;
                int nf;
                if (f[q].n == 0 || (o->na && is_na_word(f[q].t, f[q].n)))
                    continue;
                if (ref_number(f[q].t, f[q].n, o->dcomma, &v, &nf) || nf)
                    continue;
                if (o->tdetect && (ref_time(f[q].t, f[q].n, &v) || ref_zone(f[q].t, f[q].n)))
                    continue;
                hdr = 1;
            }
            if (hdr) {
                r->header = 1;
                r->ncols = (size_t)k;
                free_fields(f, k);
                continue;
            }
        }
        if (k < 0 || (r->ncols && (size_t)k != r->ncols) || k > 4000) {
            if (k >= 0)
                free_fields(f, k);
            r->ok = 0;
            goto out;
        }
        if (!r->ncols)
            r->ncols = (size_t)k;
        if ((r->nrows + 1) * r->ncols > r->cap) {
            r->cap = 2 * (r->nrows + 1) * r->ncols + 16;
            r->v = realloc(r->v, r->cap * sizeof *r->v);
        }
        for (long q = 0; q < k; q++) {
            double v = 0;
            int nf = 0;
            const char *t = f[q].t;
            size_t tn = f[q].n;
            if (tn == 0 || (o->na && is_na_word(t, tn))) {
                if (!o->na) {
                    free_fields(f, k);
                    r->ok = 0;
                    goto out;
                }
                v = (double)NAN;
            } else if (is_time[q]) {
                if (!ref_time(t, tn, &v)) {
                    free_fields(f, k);
                    r->ok = 0;
                    goto out;
                }
            } else if (ref_number(t, tn, o->dcomma, &v, &nf) != 1) {
                if (isfinite(v) && !nf && o->tdetect && r->nrows == 0 && ref_time(t, tn, &v)) {
                    is_time[q] = 1;
                } else {
                    free_fields(f, k);
                    r->ok = 0;
                    goto out;
                }
            }
            r->v[r->nrows * r->ncols + (size_t)q] = v;
        }
        free_fields(f, k);
        r->nrows++;
    }
    r->ok = r->nrows > 0;
out:
    free(rec);
    free(d);
}

static int same(double a, double b)
{
    return (isnan(a) && isnan(b)) || memcmp(&a, &b, sizeof a) == 0;
}

static void fail(const char *what, const uint8_t *data, size_t size)
{
    fprintf(stderr, "fuzz_table: %s on input of %zu bytes: \"", what, size);
    for (size_t i = 0; i < size && i < 200; i++)
        fprintf(stderr, data[i] >= 32 && data[i] < 127 ? "%c" : "\\x%02x", data[i]);
    fprintf(stderr, "\"\n");
    abort();
}

#include "fuzz.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 2 || size > 4096)
        return 0;
    ropts o;
    uint8_t b = data[0];
    static const char dl[4] = {0, ',', ';', '\t'};
    o.dcomma = b & 1;
    o.na = (b >> 1) & 1;
    o.tdetect = (b >> 2) & 1;
    o.delim = dl[(b >> 3) & 3];
    o.skip = (b >> 5) & 1;
    const char *text = (const char *)data + 1;
    size_t n = size - 1;

    tsu_read_options ro;
    tsu_read_options_init(&ro);
    ro.decimal_comma = o.dcomma;
    ro.na = o.na ? "NA,NaN,null" : NULL;
    ro.time_detect = o.tdetect;
    ro.delim = o.delim == ',' ? TSU_DELIM_COMMA : o.delim == ';' ? TSU_DELIM_SEMICOLON
               : o.delim == '\t' ? TSU_DELIM_TAB : TSU_DELIM_AUTO;
    ro.skip = (unsigned long long)o.skip;
    ro.buffer_size = 16u + (size_t)(b >> 6) * 7u; /* small buffers: refills inside records */

    FILE *fp = fmemopen((void *)text, n, "r");
    if (!fp)
        return 0;
    tsu_table t;
    tsu_io_error e;
    tsu_io_status st = tsu_read_table(fp, "fuzz", &ro, &t, &e);
    fclose(fp);
    if (o.dcomma && o.delim == ',') {
        if (st != TSU_IO_ERR_OPTION)
            fail("decimal comma with ',' accepted", data, size);
        return 0;
    }
    ref r;
    ref_read(text, n, &o, &r);
    int ok = st == TSU_IO_OK;
    if (ok != r.ok) {
        fprintf(stderr, "reader: %s; reference: %s\n", ok ? "ok" : e.msg, r.ok ? "ok" : "error");
        fail("accept / refuse differ", data, size);
    }
    if (ok) {
        if (t.nrows != r.nrows || t.ncols != r.ncols || (t.names != NULL) != r.header)
            fail("shape differs", data, size);
        for (size_t i = 0; i < t.nrows; i++)
            for (size_t j = 0; j < t.ncols; j++)
                if (!same(t.cols[j][i], r.v[i * r.ncols + j]))
                    fail("value differs", data, size);
        tsu_table_free(&t);
    }
    free(r.v);
    return 0;
}
