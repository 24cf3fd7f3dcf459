/* tsu_io tables: the streaming CSV / TSV / white-space reader and the whole
 * table in memory (see tsu_io.h, 2. Reading tables). */
#define _POSIX_C_SOURCE 200809L

#include "tsu_io_internal.h"

#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* ================================================================== */
/* Streaming reader                                                     */
/* ================================================================== */

struct tsu_reader {
    FILE *fp;
    char *name;
    char *buf;
    size_t cap, pos, len, cap_max;
    int eof;
    int cr_pending; /* the last byte read is a CR whose next byte is not read yet */
    unsigned long long line;     /* physical lines consumed */
    unsigned long long rec_line; /* first line of the current record */
    unsigned long long row_line; /* line of the last row returned */
    unsigned long long rows;
    unsigned long long skip;
    unsigned long long header_line;
    tsu_delim delim;
    tsu_header header;
    int decimal_comma;
    int seen_content;
    size_t ncols;
    char **names;
    size_t nnames;
    double *row;
    size_t *fcol;  /* byte offset of each field of the row in its record */
    size_t rowcap;
    size_t missing;
    char **na;     /* missing-value words, NULL: none */
    size_t nna;
    int time_detect;
    size_t time_col; /* 1-based, 0 none */
    char *time_name;
    unsigned char *is_time; /* per column (ncols), once known */
    tsu_time_form *tform;
    char *tmp;      /* scratch: unquoted / decimal-comma field text */
    size_t tmpcap;
    const char *ls; /* start of the current record */
    unsigned char *use; /* per column (rowcap): 1 = parsed, when selected */
    int selected;       /* tsu_reader_use_columns was called */
    int pending;        /* tsu_reader_layout left a data record unparsed: */
    const char *pend_le; /* its content end (r->ls its start) */
    int rec_scanned;      /* its last line was quote-scanned: */
    const char *rec_hash; /* then its comment '#' (NULL: none) */
    char *time_format;    /* tsu_parse_time_format's, NULL: ISO 8601 */
    unsigned long long after_header; /* content lines still to skip after the header */
    unsigned long long skip_after;   /* tsu_read_options.skip_after_header */
    int sniffed;          /* the first bytes were checked for compressed data */
    int header_corner;    /* tsu_read_options.header_corner */
    int failed;
    tsu_io_error saved;
};

void tsu_read_options_init(tsu_read_options *opt)
{
    if (!opt)
        return;
    memset(opt, 0, sizeof *opt);
    opt->delim = TSU_DELIM_AUTO;
    opt->header = TSU_HEADER_AUTO;
    opt->ncols = 0;
    opt->max_line = TSU_IO_MAX_LINE;
    opt->buffer_size = TSU_IO_BUFFER;
    opt->track_lines = 1;
}

static void free_names(char **names, size_t n)
{
    size_t i;
    if (!names)
        return;
    for (i = 0; i < n; i++)
        free(names[i]);
    free(names);
}

/* Split the na list into words (trimmed); 0 or -1 (no memory). */
static int set_na(tsu_reader *r, const char *na)
{
    size_t n = 1, k = 0;
    for (const char *p = na; *p; p++)
        n += *p == ',';
    r->na = tsu_io__calloc(n, sizeof *r->na);
    if (!r->na)
        return -1;
    for (const char *p = na;;) {
        const char *e = strchr(p, ',');
        const char *we = e ? e : p + strlen(p);
        const char *ws = p;
        while (ws < we && IS_BLANK(*ws))
            ws++;
        while (we > ws && IS_BLANK(we[-1]))
            we--;
        if (we > ws) {
            if (!(r->na[k] = tsu_io__dup_str(ws, (size_t)(we - ws))))
                return -1;
            k++;
        }
        if (!e)
            break;
        p = e + 1;
    }
    r->nna = k;
    return 0;
}

void tsu_reader_free(tsu_reader *r)
{
    if (!r)
        return;
    free_names(r->names, r->nnames);
    free_names(r->na, r->nna);
    free(r->row);
    free(r->fcol);
    free(r->buf);
    free(r->name);
    free(r->time_name);
    free(r->time_format);
    free(r->is_time);
    free(r->tform);
    free(r->use);
    free(r->tmp);
    free(r);
}

tsu_io_status tsu_reader_open(tsu_reader **out, FILE *fp, const char *name,
                            const tsu_read_options *opt, tsu_io_error *err)
{
    tsu_read_options def;
    tsu_reader *r;
    tsu_io__err_clear(err);
    if (out)
        *out = NULL;
    if (!name)
        name = "<input>";
    if (!out || !fp) {
        tsu_io__err_set(err, TSU_IO_ERR_NULL, 0, name, 0, 0, 0, "null argument");
        return TSU_IO_ERR_NULL;
    }
    if (!opt) {
        tsu_read_options_init(&def);
        opt = &def;
    }
    if (!(opt->delim >= TSU_DELIM_AUTO && opt->delim <= TSU_DELIM_SEMICOLON) ||
        !(opt->header >= TSU_HEADER_AUTO && opt->header <= TSU_HEADER_YES) || opt->max_line < 16 ||
        opt->max_line >= SIZE_MAX / 4 || opt->buffer_size < 16 ||
        (opt->decimal_comma && opt->delim == TSU_DELIM_COMMA)) {
        tsu_io__err_set(err, TSU_IO_ERR_OPTION, 0, name, 0, 0, 0, "invalid option");
        return TSU_IO_ERR_OPTION;
    }
    r = tsu_io__calloc(1, sizeof *r);
    if (!r || !(r->name = tsu_io__dup_str(name, strlen(name)))) {
        free(r);
        tsu_io__err_set(err, TSU_IO_ERR_NOMEM, 0, name, 0, 0, 0, "out of memory");
        return TSU_IO_ERR_NOMEM;
    }
    r->fp = fp;
    r->cap_max = opt->max_line + 1; /* a line of max_line bytes plus its '\n' */
    r->cap = opt->buffer_size < r->cap_max ? opt->buffer_size : r->cap_max;
    r->buf = tsu_io__malloc(r->cap);
    if (!r->buf || (opt->na && set_na(r, opt->na) != 0) ||
        (opt->time_name && !(r->time_name = tsu_io__dup_str(opt->time_name, strlen(opt->time_name)))) ||
        (opt->time_format &&
         !(r->time_format = tsu_io__dup_str(opt->time_format, strlen(opt->time_format))))) {
        tsu_reader_free(r);
        tsu_io__err_set(err, TSU_IO_ERR_NOMEM, 0, name, 0, 0, 0, "out of memory");
        return TSU_IO_ERR_NOMEM;
    }
    r->delim = opt->delim;
    r->header = opt->header;
    r->ncols = opt->ncols;
    r->skip = opt->skip;
    r->decimal_comma = opt->decimal_comma;
    r->time_detect = opt->time_detect;
    r->time_col = opt->time_col;
    r->skip_after = opt->skip_after_header;
    r->header_corner = opt->header_corner;
    *out = r;
    return TSU_IO_OK;
}

size_t tsu_reader_ncols(const tsu_reader *r) { return r ? r->ncols : 0; }
unsigned long long tsu_reader_line(const tsu_reader *r) { return r ? r->row_line : 0; }
unsigned long long tsu_reader_rows(const tsu_reader *r) { return r ? r->rows : 0; }
size_t tsu_reader_nnames(const tsu_reader *r) { return r ? r->nnames : 0; }
const char *tsu_reader_source(const tsu_reader *r) { return r ? r->name : NULL; }
tsu_delim tsu_reader_delim(const tsu_reader *r) { return r ? r->delim : TSU_DELIM_AUTO; }
size_t tsu_reader_missing(const tsu_reader *r) { return r ? r->missing : 0; }
unsigned long long tsu_reader_header_line(const tsu_reader *r) { return r ? r->header_line : 0; }

const char *tsu_reader_name(const tsu_reader *r, size_t j)
{
    return (r && r->names && j < r->nnames) ? r->names[j] : NULL;
}

int tsu_reader_set_time_column(tsu_reader *r, size_t j)
{
    if (!r || r->failed || r->rows || j >= r->ncols || !r->is_time)
        return -1;
    if (r->is_time[j] != 1)
        r->is_time[j] = 2; /* forced; form from the first value */
    return 0;
}

int tsu_reader_is_time(const tsu_reader *r, size_t j, tsu_time_form *form)
{
    if (!r || !r->is_time || j >= r->ncols || !r->is_time[j])
        return 0;
    if (form)
        *form = r->tform[j];
    return 1;
}

/* Set the reader's sticky error. */
#define RFAIL(r, st, sys, line, col, field, ...)                                    \
    (tsu_io__err_set(&(r)->saved, (st), (sys), (r)->name, (line), (col), (field), __VA_ARGS__), \
     (r)->failed = 1, (tsu_io_status)(st))

static char delim_char(tsu_delim d)
{
    return d == TSU_DELIM_COMMA ? ',' : d == TSU_DELIM_TAB ? '\t' : d == TSU_DELIM_SEMICOLON ? ';' : 0;
}

/* Could c end a field (for finding quoted fields before the delimiter is known)? */
/* After a value read by a fast path, ending at stop: the end of its field
 * (le, or the delimiter dc; with dc = 0 white space separates fields), past
 * trailing blanks (only spaces when the delimiter is a tab), or NULL if
 * something else follows the value there. */
static const char *fast_field_end(const char *stop, const char *le, char dc)
{
    const char *q = stop;
    if (dc == '\t')
        while (q < le && *q == ' ')
            q++;
    else
        while (q < le && IS_BLANK(*q))
            q++;
    return q == le || (dc ? *q == dc : q > stop) ? q : NULL;
}

static int field_sep(const tsu_reader *r, char c)
{
    char dc = delim_char(r->delim);
    if (r->delim == TSU_DELIM_AUTO)
        return c == ',' || c == ';' || c == '\t' || c == ' ';
    return dc ? c == dc : IS_BLANK(c);
}

/* Quote state over [p, e): *inq inside quotes, *fs at a field start, *cm in
 * a comment (*hash: where it starts). */
static void quote_scan(const tsu_reader *r, const char *p, const char *e, int *inq, int *fs, int *cm,
                       const char **hash)
{
    const char *seg = p;
    if (*cm)
        return;
    while (p < e) {
        if (*inq) {
            const char *q = memchr(p, '"', (size_t)(e - p));
            if (!q)
                return;
            if (q + 1 < e && q[1] == '"') {
                p = q + 2;
                continue;
            }
            *inq = 0;
            *fs = 0;
            p = q + 1;
            seg = p;
            continue;
        }
        /* outside quotes: the next '"' or '#' */
        const char *q = p;
        while (q < e && *q != '"' && *q != '#')
            q++;
        if (q == e) {
            /* the field-start state at the end, for a record continued by the caller */
            const char *b = e;
            while (b > seg && IS_BLANK(b[-1]) && !field_sep(r, b[-1]))
                b--;
            if (b > seg)
                *fs = field_sep(r, b[-1]);
            return;
        }
        if (*q == '#') {
            *cm = 1;
            *hash = q;
            return;
        }
        /* a '"' opens a quoted field at a field start: after blanks that follow a
         * separator, or the start of the scanned run with *fs set */
        {
            const char *b = q;
            int at_start;
            while (b > seg && IS_BLANK(b[-1]) && !field_sep(r, b[-1]))
                b--;
            at_start = b > seg ? field_sep(r, b[-1]) : *fs;
            if (at_start) {
                *inq = 1;
                *fs = 0;
            } else {
                *fs = 0;
                seg = q + 1;
            }
        }
        p = q + 1;
    }
}

/* A lone CR (old Mac OS line ends) is a line end: each one in the bytes read
 * from buf + from on becomes '\n' (CR LF stays as it is).  A CR last in the
 * buffer waits for the next read, or for the end of the input. */
static void lone_cr(tsu_reader *r, size_t from)
{
    char *p = r->buf + from, *e = r->buf + r->len;
    r->cr_pending = 0;
    while (p < e && (p = memchr(p, '\r', (size_t)(e - p))) != NULL) {
        if (p + 1 == e) {
            if (r->eof)
                *p = '\n';
            else
                r->cr_pending = 1;
            break;
        }
        if (p[1] != '\n')
            *p = '\n';
        p++;
    }
}

/* Next record (without its final '\n') into [*ls, *ls + *ll): 1, 0 at the
 * end, or the negative of an error status. */
/* The first bytes of a compressed file or an archive: its kind ("gzip") and
 * the command that decompresses it ("zcat"; NULL: an archive), else 0. */
static int compressed_kind(const unsigned char *b, size_t n, const char **kind,
                           const char **tool)
{
    static const struct {
        const char *magic;
        size_t len;
        const char *kind, *tool;
    } k[] = {{"\x1f\x8b", 2, "gzip", "zcat"},
             {"BZh", 3, "bzip2", "bzcat"},
             {"\xfd" "7zXZ\0", 6, "xz", "xzcat"},
             {"\x28\xb5\x2f\xfd", 4, "zstd", "zstdcat"},
             {"PK\x03\x04", 4, "zip", NULL}};
    for (size_t i = 0; i < sizeof k / sizeof k[0]; i++)
        if (n >= k[i].len && memcmp(b, k[i].magic, k[i].len) == 0) {
            *kind = k[i].kind;
            *tool = k[i].tool;
            return 1;
        }
    return 0;
}

static int get_record(tsu_reader *r, char **ls, size_t *ll)
{
    size_t scan = 0; /* bytes of the record scanned so far, from r->pos */
    unsigned long long nls = 0;
    int inq = 0, fs = 1, cm = 0;
    for (;;) {
        char *base = r->buf + r->pos;
        size_t avail = r->len - r->pos;
        char *nl = scan < avail ? memchr(base + scan, '\n', avail - scan) : NULL;
        if (nl || (r->eof && scan < avail)) {
            char *segend = nl ? nl : base + avail;
            if (r->line + nls < r->skip) { /* a skipped line */
                r->pos += (size_t)(segend - base) + (nl ? 1 : 0);
                r->line++;
                continue;
            }
            r->rec_scanned = 0;
            r->rec_hash = NULL;
            if (inq || memchr(base + scan, '"', (size_t)(segend - (base + scan)))) {
                const char *from = base + scan;
                if (r->line + nls == 0 && scan == 0 && segend - from >= 3 &&
                    memcmp(from, "\xef\xbb\xbf", 3) == 0)
                    from += 3; /* the byte-order mark is not part of the first field */
                quote_scan(r, from, segend, &inq, &fs, &cm, &r->rec_hash);
                r->rec_scanned = 1;
            }
            nls++;
            cm = 0;
            if (inq && nl) { /* a line break inside quotes */
                scan = (size_t)(nl - base) + 1;
                fs = 0;
                continue;
            }
            if (inq)
                return -(int)RFAIL(r, TSU_IO_ERR_QUOTE, 0, r->line + 1, 0, 0,
                                   "quote not closed (the quoted field starting on this line "
                                   "runs to the end of the input)");
            *ls = base;
            *ll = (size_t)(segend - base);
            r->pos += *ll + (nl ? 1 : 0);
            r->rec_line = r->line + 1;
            r->line += nls;
            return 1;
        }
        if (r->eof) {
            if (scan > 0)
                return -(int)RFAIL(r, TSU_IO_ERR_QUOTE, 0, r->line + 1, 0, 0,
                                   "quote not closed (the quoted field starting on this line "
                                   "runs to the end of the input)");
            return 0;
        }
        if (r->pos > 0) {
            memmove(r->buf, r->buf + r->pos, r->len - r->pos);
            r->len -= r->pos;
            r->pos = 0;
        }
        if (r->len == r->cap) {
            size_t nc;
            char *nb;
            if (r->cap >= r->cap_max)
                return -(int)RFAIL(r, TSU_IO_ERR_LINE, 0, r->line + 1, 0, 0,
                                   "line longer than %zu bytes", r->cap_max - 1);
            nc = r->cap <= r->cap_max / 2 ? 2 * r->cap : r->cap_max;
            nb = tsu_io__realloc(r->buf, nc);
            if (!nb)
                return -(int)RFAIL(r, TSU_IO_ERR_NOMEM, 0, 0, 0, 0, "out of memory");
            r->buf = nb;
            r->cap = nc;
        }
        {
            size_t want = r->cap - r->len, got, from = r->len - (r->cr_pending ? 1 : 0);
            errno = 0;
            got = fread(r->buf + r->len, 1, want, r->fp);
            r->len += got;
            if (got < want) { /* short read: end of file or error */
                if (ferror(r->fp)) {
                    int e = errno ? errno : EIO;
                    return -(int)RFAIL(r, TSU_IO_ERR_READ, e, 0, 0, 0, "read error: %s",
                                       strerror(e));
                }
                r->eof = 1;
            }
            lone_cr(r, from);
            if (!r->sniffed && (r->len >= 6 || r->eof)) {
                const char *kind, *tool;
                r->sniffed = 1;
                if (compressed_kind((const unsigned char *)r->buf, r->len, &kind, &tool)) {
                    if (!tool)
                        return -(int)RFAIL(r, TSU_IO_ERR_ENCODING, 0, 0, 0, 0,
                                           "a zip archive (or a spreadsheet: .xlsx, .ods): "
                                           "extract the table or save it as CSV first");
                    return -(int)RFAIL(r, TSU_IO_ERR_ENCODING, 0, 0, 0, 0,
                                       "%s-compressed input: decompress it first (%s %s | "
                                       "trigspline ...)", kind, tool,
                                       strcmp(r->name, "<stdin>") ? r->name : "FILE");
                }
            }
        }
    }
}

/* Line and column of p in the current record (records may span lines). */
static void pos_of(const tsu_reader *r, const char *p, unsigned long long *line, size_t *col)
{
    const char *ls = r->ls;
    unsigned long long ln = r->rec_line;
    for (const char *q = r->ls; q < p; q++)
        if (*q == '\n') {
            ln++;
            ls = q + 1;
        }
    *line = ln;
    *col = (size_t)(p - ls) + 1;
}

#define POS_FAIL(r, st, p, field, ...)                                                   \
    do {                                                                                 \
        unsigned long long ln_;                                                          \
        size_t col_;                                                                     \
        pos_of((r), (p), &ln_, &col_);                                                   \
        return RFAIL((r), (st), 0, ln_, col_, (field), __VA_ARGS__);                     \
    } while (0)

/* Content end of a record: before a '#' outside quotes, trailing blanks and '\r' removed. */
static const char *content_end(const tsu_reader *r, const char *ls, const char *le)
{
    const char *p;
    if (r->rec_scanned) {
        if (r->rec_hash)
            le = r->rec_hash;
    } else if (memchr(ls, '"', (size_t)(le - ls))) {
        int inq = 0, fs = 1;
        for (p = ls; p < le; p++) {
            char c = *p;
            if (inq) {
                if (c == '"') {
                    if (p + 1 < le && p[1] == '"')
                        p++;
                    else
                        inq = 0, fs = 0;
                }
                continue;
            }
            if (c == '#')
                break;
            if (c == '"' && fs)
                inq = 1, fs = 0;
            else if (field_sep(r, c))
                fs = 1;
            else if (!IS_BLANK(c))
                fs = 0;
        }
        le = p;
    } else if ((p = memchr(ls, '#', (size_t)(le - ls))) != NULL) {
        le = p;
    }
    while (le > ls && (le[-1] == ' ' || le[-1] == '\t' || le[-1] == '\r'))
        le--;
    return le;
}

/* A field of a record. */
typedef struct field {
    const char *at;   /* where it starts (after blanks; the quote if quoted) */
    const char *s, *e; /* its text: unquoted, trimmed ("" pairs still doubled) */
    int quoted, esc;  /* esc: contains "" */
} field;

/* Next field from *pp (first: at the record start).  1: a field, 0: end,
 * -1: quote error (reported). */
static int next_field(tsu_reader *r, const char **pp, const char *le, int first, field *f,
                      size_t fieldno)
{
    const char *p = *pp;
    char dc = delim_char(r->delim);
    if (!first) {
        if (p >= le)
            return 0;
        if (dc)
            p++; /* the delimiter */
    }
    if (dc == '\t')
        while (p < le && *p == ' ')
            p++;
    else
        while (p < le && IS_BLANK(*p))
            p++;
    if (!dc && p == le)
        return 0;
    f->at = p;
    f->quoted = f->esc = 0;
    if (p < le && *p == '"') {
        const char *q = p + 1;
        for (;;) {
            const char *c = memchr(q, '"', (size_t)(le - q));
            if (!c) {
                unsigned long long ln;
                size_t col;
                pos_of(r, p, &ln, &col);
                (void)RFAIL(r, TSU_IO_ERR_QUOTE, 0, ln, col, fieldno, "quote not closed");
                return -1;
            }
            if (c + 1 < le && c[1] == '"') {
                f->esc = 1;
                q = c + 2;
                continue;
            }
            q = c;
            break;
        }
        f->quoted = 1;
        f->s = p + 1;
        f->e = q;
        p = q + 1;
        if (dc)
            while (p < le && (dc == '\t' ? *p == ' ' : IS_BLANK(*p)))
                p++;
        if (!dc) {
            if (p < le && !IS_BLANK(*p)) {
                unsigned long long ln;
                size_t col;
                pos_of(r, p, &ln, &col);
                (void)RFAIL(r, TSU_IO_ERR_QUOTE, 0, ln, col, fieldno, "text after the closing quote");
                return -1;
            }
        } else if (p < le && *p != dc) {
            unsigned long long ln;
            size_t col;
            pos_of(r, p, &ln, &col);
            (void)RFAIL(r, TSU_IO_ERR_QUOTE, 0, ln, col, fieldno, "text after the closing quote");
            return -1;
        }
        while (f->s < f->e && IS_BLANK(*f->s))
            f->s++;
        while (f->e > f->s && IS_BLANK(f->e[-1]))
            f->e--;
        *pp = p;
        return 1;
    }
    f->s = p;
    while (p < le && (dc ? *p != dc : !IS_BLANK(*p)))
        p++;
    f->e = p;
    while (f->e > f->s && IS_BLANK(f->e[-1]))
        f->e--;
    *pp = p;
    return 1;
}

/* Scratch of at least n bytes; NULL: no memory (reported). */
static char *scratch(tsu_reader *r, size_t n)
{
    if (n > r->tmpcap) {
        size_t nc = n < 256 ? 256 : n;
        char *nb = tsu_io__realloc(r->tmp, nc);
        if (!nb) {
            (void)RFAIL(r, TSU_IO_ERR_NOMEM, 0, 0, 0, 0, "out of memory");
            return NULL;
        }
        r->tmp = nb;
        r->tmpcap = nc;
    }
    return r->tmp;
}

/* The text of f with "" undone (into scratch when needed); NULL: no memory. */
static const char *field_text(tsu_reader *r, const field *f, const char **e)
{
    if (!f->esc) {
        *e = f->e;
        return f->s;
    }
    char *d = scratch(r, (size_t)(f->e - f->s) + 1), *o;
    if (!d)
        return NULL;
    o = d;
    for (const char *q = f->s; q < f->e; q++) {
        *o++ = *q;
        if (*q == '"' && q + 1 < f->e && q[1] == '"')
            q++;
    }
    *e = o;
    return d;
}

static int is_na(const tsu_reader *r, const char *s, const char *e)
{
    size_t n = (size_t)(e - s);
    if (!r->na)
        return 0;
    if (n == 0)
        return 1;
    for (size_t k = 0; k < r->nna; k++) {
        const char *w = r->na[k];
        size_t i;
        if (strlen(w) != n)
            continue;
        for (i = 0; i < n; i++) {
            char a = s[i], b = w[i];
            if (a >= 'A' && a <= 'Z')
                a = (char)(a - 'A' + 'a');
            if (b >= 'A' && b <= 'Z')
                b = (char)(b - 'A' + 'a');
            if (a != b)
                break;
        }
        if (i == n)
            return 1;
    }
    return 0;
}

/* A whole-field number (decimal comma honoured): status, or -1 = no memory. */
static int num_field(tsu_reader *r, const char *s, const char *e, double *v)
{
    const char *stop;
    tsu_num_status ns;
    if (r->decimal_comma) {
        const char *c = memchr(s, ',', (size_t)(e - s));
        if (memchr(s, '.', (size_t)(e - s)))
            return TSU_NUM_SYNTAX;
        if (c) {
            char *d = scratch(r, (size_t)(e - s));
            if (!d)
                return -1;
            memcpy(d, s, (size_t)(e - s));
            d[c - s] = '.';
            e = d + (e - s);
            s = d;
        }
    }
    ns = tsu_parse_double(s, e, v, &stop);
    if (stop != e)
        return TSU_NUM_SYNTAX;
    return (int)ns;
}

#define IS_ALPHA(c) ((unsigned)(((unsigned char)(c) | 0x20) - 'a') < 26u)

/* A date of the reader's format (tsu_read_options.time_format, else ISO 8601). */
static int parse_time_r(const tsu_reader *r, const char *s, const char *e, double *t,
                        tsu_time_form *form, const char **stop)
{
    if (r->time_format)
        return tsu_parse_time_format(r->time_format, s, e, t, form, stop);
    return tsu_parse_time(s, e, t, form, stop);
}

/* A date or date-time followed by a time-zone name ("CET", " Europe/Paris",
 * "[Europe/Paris]": two letters or a '['), which is not accepted: 1 and
 * *name where the name starts, else 0. */
static int zone_name(const char *s, const char *e, const char **name)
{
    const char *stop, *p;
    if (!tsu_parse_time(s, e, NULL, NULL, &stop))
        return 0;
    for (p = stop; p < e && IS_BLANK(*p); p++)
        ;
    if (!(p < e && (*p == '[' || (p + 1 < e && IS_ALPHA(p[0]) && IS_ALPHA(p[1])))))
        return 0;
    *name = p;
    return 1;
}

/* The error for a field [s, e) at `at` that is a date with a zone name at `name`. */
#define ZONE_FAIL(r, at, fieldno, s, e, name)                                              \
    do {                                                                                   \
        char zq_[200], zn_[120];                                                           \
        tsu_io__quote_text(zq_, sizeof zq_, (s), (e));                                             \
        tsu_io__quote_text(zn_, sizeof zn_, (name), (e));                                          \
        POS_FAIL((r), TSU_IO_ERR_TIME, (at), (fieldno),                                    \
                 "time-zone name %s in %s: time-zone names are not accepted, write Z or a " \
                 "numeric UTC offset (+HH:MM, +HHMM or +HH)", zn_, zq_);                   \
    } while (0)

enum { FK_EMPTY, FK_NUMBER, FK_NA, FK_TIME, FK_TEXT, FK_NOMEM };

/* Is column j parsed (tsu_reader_use_columns)? */
static int col_used(const tsu_reader *r, size_t j)
{
    return !r->selected || (j < r->rowcap && r->use[j]);
}

static int classify(tsu_reader *r, const field *f)
{
    const char *e, *s = field_text(r, f, &e);
    double v;
    int ns;
    if (!s)
        return FK_NOMEM;
    if (s == e)
        return FK_EMPTY;
    if (is_na(r, s, e))
        return FK_NA;
    ns = num_field(r, s, e, &v);
    if (ns < 0)
        return FK_NOMEM;
    if (ns != TSU_NUM_SYNTAX)
        return FK_NUMBER;
    if (r->time_detect || r->time_col || r->time_name) {
        const char *stop;
        if (parse_time_r(r, s, e, NULL, NULL, &stop) && stop == e)
            return FK_TIME;
        if (!r->time_format && zone_name(s, e, &stop))
            return FK_TIME; /* a date all the same: data, refused when parsed */
    }
    return FK_TEXT;
}

/* Is the first field of the record [ls, le) empty (a matrix's corner cell)? */
static int empty_first(tsu_reader *r, const char *ls, const char *le)
{
    const char *p = ls, *e, *s;
    field f;
    if (next_field(r, &p, le, 1, &f, 0) != 1) {
        r->failed = 0; /* a quote error: let the data parser report it */
        return 0;
    }
    s = field_text(r, &f, &e);
    return s && s == e && p < le;
}

/* Is the record [ls, le) a header (a field that is text)? -1: error (reported). */
static int is_header(tsu_reader *r, const char *ls, const char *le, int *all_text)
{
    const char *p = ls;
    field f;
    int first = 1, k, hdr = 0, any_value = 0;
    size_t j = 0;
    while ((k = next_field(r, &p, le, first, &f, 0)) == 1) {
        first = 0;
        if (!col_used(r, j++))
            continue;
        int c = classify(r, &f);
        if (c == FK_NOMEM)
            return -1;
        if (c == FK_TEXT)
            hdr = 1;
        if (c == FK_NUMBER || c == FK_TIME)
            any_value = 1;
    }
    if (k < 0) {
        r->failed = 0; /* a quote error: let the data parser report it */
        return 0;
    }
    if (all_text)
        *all_text = hdr && !any_value;
    return hdr;
}

static int grow_row(tsu_reader *r, size_t need)
{
    if (need <= r->rowcap)
        return 0;
    size_t nc = r->rowcap ? 2 * r->rowcap : 8;
    while (nc < need)
        nc *= 2;
    if (nc > SIZE_MAX / sizeof(double) || nc > SIZE_MAX / sizeof(size_t))
        return RFAIL(r, TSU_IO_ERR_OVERFLOW, 0, r->rec_line, 0, 0, "size overflow");
    double *nr = tsu_io__realloc(r->row, nc * sizeof *nr);
    if (!nr)
        return RFAIL(r, TSU_IO_ERR_NOMEM, 0, 0, 0, 0, "out of memory");
    r->row = nr;
    size_t *nf = tsu_io__realloc(r->fcol, nc * sizeof *nf);
    if (!nf)
        return RFAIL(r, TSU_IO_ERR_NOMEM, 0, 0, 0, 0, "out of memory");
    r->fcol = nf;
    unsigned char *it = tsu_io__realloc(r->is_time, nc);
    if (!it)
        return RFAIL(r, TSU_IO_ERR_NOMEM, 0, 0, 0, 0, "out of memory");
    memset(it + r->rowcap, 0, nc - r->rowcap);
    r->is_time = it;
    tsu_time_form *tf = tsu_io__realloc(r->tform, nc * sizeof *tf);
    if (!tf)
        return RFAIL(r, TSU_IO_ERR_NOMEM, 0, 0, 0, 0, "out of memory");
    r->tform = tf;
    unsigned char *us = tsu_io__realloc(r->use, nc);
    if (!us)
        return RFAIL(r, TSU_IO_ERR_NOMEM, 0, 0, 0, 0, "out of memory");
    memset(us + r->rowcap, 0, nc - r->rowcap);
    r->use = us;
    r->rowcap = nc;
    return 0;
}

/* Per-column time flags once the number of columns is known. */
static tsu_io_status set_columns(tsu_reader *r, size_t n)
{
    r->ncols = n;
    if (grow_row(r, n ? n : 1))
        return r->saved.status;
    if (r->time_col && r->time_col <= n)
        r->is_time[r->time_col - 1] = 2; /* forced; form from the first value */
    if (r->time_name) {
        size_t j;
        for (j = 0; j < r->nnames && strcmp(r->names[j], r->time_name) != 0; j++)
            ;
        if (j < r->nnames)
            r->is_time[j] = 2;
    }
    return TSU_IO_OK;
}

static tsu_io_status read_header(tsu_reader *r, const char *ls, const char *le)
{
    const char *p = ls;
    field f;
    int first = 1, k;
    size_t n = 0, cap = 0;
    char **names = NULL;
    while ((k = next_field(r, &p, le, first, &f, n + 1)) == 1) {
        const char *e, *s;
        first = 0;
        if (n == cap) {
            size_t nc = cap ? 2 * cap : 8;
            char **nn;
            if (nc > SIZE_MAX / sizeof *names) {
                free_names(names, n);
                return RFAIL(r, TSU_IO_ERR_OVERFLOW, 0, r->rec_line, 0, 0, "size overflow");
            }
            nn = tsu_io__realloc(names, nc * sizeof *names);
            if (!nn) {
                free_names(names, n);
                return RFAIL(r, TSU_IO_ERR_NOMEM, 0, 0, 0, 0, "out of memory");
            }
            names = nn;
            cap = nc;
        }
        s = field_text(r, &f, &e);
        if (!s || !(names[n] = tsu_io__dup_str(s, (size_t)(e - s)))) {
            free_names(names, n);
            return RFAIL(r, TSU_IO_ERR_NOMEM, 0, 0, 0, 0, "out of memory");
        }
        n++;
    }
    if (k < 0) {
        free_names(names, n);
        return r->saved.status;
    }
    if (r->ncols && n != r->ncols) {
        size_t col = (size_t)(le - r->ls) + 1;
        unsigned long long ln = r->rec_line;
        if (n > r->ncols) {
            p = ls;
            first = 1;
            for (size_t i = 0; i <= r->ncols && next_field(r, &p, le, first, &f, 0) == 1; i++)
                first = 0;
            pos_of(r, f.at, &ln, &col);
        }
        free_names(names, n);
        return RFAIL(r, TSU_IO_ERR_FIELDS, 0, ln, col, 0,
                     "wrong number of fields (%zu, expected %zu)", n, r->ncols);
    }
    r->names = names;
    r->nnames = n;
    r->header_line = r->rec_line;
    return set_columns(r, n);
}

/* Number of fields of [ls, le) (for messages; quote errors count as the end). */
static size_t count_fields(tsu_reader *r, const char *ls, const char *le)
{
    const char *p = ls;
    field f;
    size_t n = 0;
    int failed = r->failed;
    while (next_field(r, &p, le, n == 0, &f, 0) == 1)
        n++;
    r->failed = failed;
    return n;
}

/* " (the delimiter is ','; this line also has ';')" for a likely mix-up */
static void delim_hint(const tsu_reader *r, const char *ls, const char *le, char *buf, size_t len)
{
    static const char cand[] = ",;\t";
    char dc = delim_char(r->delim);
    buf[0] = 0;
    for (const char *c = cand; *c; c++) {
        if (*c == dc || (*c == ',' && r->decimal_comma) || !memchr(ls, *c, (size_t)(le - ls)))
            continue;
        snprintf(buf, len, " (the delimiter is %s; this line has %s: mixed delimiters? "
                 "see --delimiter)",
                 dc == ',' ? "','" : dc == ';' ? "';'" : dc == '\t' ? "tab" : "white space",
                 *c == ',' ? "','" : *c == ';' ? "';'" : "a tab");
        return;
    }
}

static tsu_io_status fields_error(tsu_reader *r, const char *ls, const char *le, const char *at,
                                  size_t got)
{
    unsigned long long ln;
    size_t col;
    char hint[160];
    pos_of(r, at, &ln, &col);
    delim_hint(r, ls, le, hint, sizeof hint);
    if (!hint[0] && r->nnames == 1 && r->rows == 0)
        snprintf(hint, sizeof hint, " (the header, line %llu, has one field: metadata lines "
                 "before the header? skip them with --skip N)", r->header_line);
    return RFAIL(r, TSU_IO_ERR_FIELDS, 0, ln, col, 0, "wrong number of fields (%zu, expected %zu)%s",
                 got, r->ncols, hint);
}

/* "12,5": a number up to a ',' and a digit after it */
static int number_comma(const char *s, const char *e)
{
    const char *stop;
    double v;
    return tsu_parse_double(s, e, &v, &stop) == TSU_NUM_OK && stop + 1 < e && *stop == ',' &&
           IS_DIGIT(stop[1]);
}

static tsu_io_status value_error(tsu_reader *r, int ns, const field *f, const char *s,
                                 const char *e, size_t fieldno, const char *ls, const char *le)
{
    char q[200], hint[200] = "";
    int all_text = 0;
    const char *zn;
    tsu_io__quote_text(q, sizeof q, s, e);
    if (ns == TSU_NUM_SYNTAX && r->time_detect && r->rows == 0 && !r->time_format &&
        zone_name(s, e, &zn))
        ZONE_FAIL(r, f->at, fieldno, s, e, zn);
    if (ns == TSU_NUM_NONFINITE)
        POS_FAIL(r, TSU_IO_ERR_NONFINITE, f->at, fieldno, "not a finite number: %s", q);
    if (ns == TSU_NUM_RANGE)
        POS_FAIL(r, TSU_IO_ERR_RANGE, f->at, fieldno, "number out of range: %s", q);
    if (r->decimal_comma && memchr(s, '.', (size_t)(e - s)))
        snprintf(hint, sizeof hint, " ('.' is not accepted with a decimal comma)");
    else if (!r->decimal_comma && number_comma(s, e))
        snprintf(hint, sizeof hint, " (digit grouping is not accepted; a decimal comma needs "
                 "--decimal-comma)");
    else if (!delim_char(r->delim) && fieldno > 1 && fieldno - 2 < r->ncols &&
             r->is_time[fieldno - 2] && e - s >= 5 && IS_DIGIT(s[0]) && IS_DIGIT(s[1]) &&
             s[2] == ':')
        snprintf(hint, sizeof hint, " (white space separates fields: write a date-time with T, "
                 "YYYY-MM-DDTHH:MM)");
    else
        delim_hint(r, ls, le, hint, sizeof hint);
    if (!hint[0] && r->rows == 0 && r->header_line && is_header(r, ls, le, &all_text) > 0 &&
        all_text)
        POS_FAIL(r, TSU_IO_ERR_LAYOUT, f->at, fieldno,
                 "every field of this line is text: a second header line (units?) after the "
                 "header on line %llu? skip it with --units-row (lines before the header: "
                 "--skip N)",
                 r->header_line);
    POS_FAIL(r, TSU_IO_ERR_NUMBER, f->at, fieldno, "expected a number, found %s%s", q, hint);
}

/* The fields of the data record [ls, le) (no comment, not blank) into r->row. */
static tsu_io_status parse_data(tsu_reader *r, const char *ls, const char *le)
{
    const char *p = ls;
    char dc = delim_char(r->delim);
    size_t nf = 0;
    r->missing = 0;
    for (;;) {
        field f;
        const char *s, *e;
        double v;
        int k;
        if (dc == '\t')
            while (p < le && *p == ' ')
                p++;
        else
            while (p < le && IS_BLANK(*p))
                p++;
        if (r->ncols && nf == r->ncols)
            return fields_error(r, ls, le, p, count_fields(r, ls, le));
        if (grow_row(r, nf + 1))
            return r->saved.status;
        r->fcol[nf] = (size_t)(p - ls);
        if (!col_used(r, nf)) { /* any text: split off, not read */
            const char *fp = p;
            if (next_field(r, &fp, le, 1, &f, nf + 1) < 0)
                return r->saved.status;
            p = fp;
            r->row[nf++] = (double)NAN;
            goto next;
        }
        /* fast path: an unquoted number in a number column */
        if (p < le && *p != '"' && r->is_time[nf] == 1) {
            const char *stop, *q, *fe = le;
            tsu_time_form tf;
            if (!dc) /* white space ends the field: "date HH:MM" is two fields */
                for (fe = p; fe < le && !IS_BLANK(*fe); fe++)
                    ;
            if (parse_time_r(r, p, fe, &v, &tf, &stop)) {
                if ((q = fast_field_end(stop, le, dc)) != NULL) {
                    r->row[nf++] = v;
                    if (q == le)
                        break;
                    p = dc ? q + 1 : q;
                    continue;
                }
            }
        }
        if (p < le && *p != '"' && !r->is_time[nf]) {
            const char *stop, *q;
            tsu_num_status ns = tsu_parse_double(p, le, &v, &stop);
            if (ns == TSU_NUM_OK && stop > p &&
                !(r->decimal_comma && memchr(p, '.', (size_t)(stop - p)))) {
                if ((q = fast_field_end(stop, le, dc)) != NULL) {
                    r->row[nf++] = v;
                    if (q == le)
                        break;
                    p = dc ? q + 1 : q;
                    continue;
                }
            }
        }
        /* fast path: a quoted field without "" in a number or time column */
        if (p < le && *p == '"') {
            const char *q = memchr(p + 1, '"', (size_t)(le - p - 1)), *stop, *t;
            if (q && !(q + 1 < le && q[1] == '"')) {
                const char *fs = p + 1, *fe = q;
                int good;
                while (fs < fe && IS_BLANK(*fs))
                    fs++;
                while (fe > fs && IS_BLANK(fe[-1]))
                    fe--;
                if (r->is_time[nf]) {
                    tsu_time_form tf;
                    good = fs < fe && r->is_time[nf] == 1 &&
                           parse_time_r(r, fs, fe, &v, &tf, &stop) && stop == fe;
                } else {
                    good = fs < fe && !r->decimal_comma &&
                           tsu_parse_double(fs, fe, &v, &stop) == TSU_NUM_OK && stop == fe;
                }
                t = q + 1;
                if (dc)
                    while (t < le && (dc == '\t' ? *t == ' ' : IS_BLANK(*t)))
                        t++;
                if (good && (t == le || (dc ? *t == dc : IS_BLANK(*t)))) {
                    r->row[nf++] = v;
                    if (t >= le)
                        break;
                    p = dc ? t + 1 : t;
                    continue;
                }
            }
        }
        /* general path */
        {
            const char *fp = p;
            k = next_field(r, &fp, le, 1, &f, nf + 1);
            if (k < 0)
                return r->saved.status;
            p = fp;
        }
        s = field_text(r, &f, &e);
        if (!s)
            return r->saved.status;
        if (s == e || is_na(r, s, e)) {
            if (!r->na) {
                if (s == e)
                    POS_FAIL(r, TSU_IO_ERR_NUMBER, f.at, nf + 1, "empty field");
            } else {
                r->row[nf++] = (double)NAN;
                r->missing++;
                goto next;
            }
        }
        if (r->is_time[nf]) {
            const char *stop;
            tsu_time_form tf;
            char q[200];
            if (!parse_time_r(r, s, e, &v, &tf, &stop) || stop != e) {
                const char *zn;
                if (!r->time_format && zone_name(s, e, &zn))
                    ZONE_FAIL(r, f.at, nf + 1, s, e, zn);
                tsu_io__quote_text(q, sizeof q, s, e);
                if (r->time_format) {
                    char fq[200];
                    tsu_io__quote_text(fq, sizeof fq, r->time_format,
                                       r->time_format + strlen(r->time_format));
                    POS_FAIL(r, TSU_IO_ERR_TIME, f.at, nf + 1,
                             "not a date of the format %s: %s", fq, q);
                }
                POS_FAIL(r, TSU_IO_ERR_TIME, f.at, nf + 1,
                         "not a valid ISO 8601 date or date-time: %s (YYYY-MM-DD[THH:MM[:SS]]"
                         "[Z|+HH:MM])", q);
            }
            if (r->is_time[nf] == 2 || r->rows == 0) {
                r->tform[nf] = tf;
                r->is_time[nf] = 1;
            }
            r->row[nf++] = v;
            goto next;
        }
        k = num_field(r, s, e, &v);
        if (k < 0)
            return r->saved.status;
        if (k != TSU_NUM_OK) {
            const char *stop;
            tsu_time_form tf;
            if (k == TSU_NUM_SYNTAX && r->time_detect && r->rows == 0 &&
                parse_time_r(r, s, e, &v, &tf, &stop) && stop == e) {
                r->is_time[nf] = 1;
                r->tform[nf] = tf;
                r->row[nf++] = v;
                goto next;
            }
            return value_error(r, k, &f, s, e, nf + 1, ls, le);
        }
        r->row[nf++] = v;
    next:
        if (p >= le)
            break;
        if (dc)
            p++;
    }
    if (r->ncols && nf != r->ncols)
        return fields_error(r, ls, le, le, nf);
    if (!r->ncols)
        r->ncols = nf;
    return TSU_IO_OK;
}

/* The next data record (header and blank lines consumed) into r->ls and
 * *le: 1, 0 at the end, -1 on an error (r->saved). */
static int next_record(tsu_reader *r, const char **lep)
{
    while (!r->failed) {
        char *ls, *h;
        const char *le, *p;
        size_t ll;
        int g = get_record(r, &ls, &ll);
        if (g == 0) {
            if (r->rows == 0) {
                (void)RFAIL(r, TSU_IO_ERR_EMPTY, 0, 0, 0, 0,
                            r->seen_content ? "no data rows" : "no data (empty input)");
                break;
            }
            return 0;
        }
        if (g < 0)
            break;
        int bom16 = r->rec_line == 1 && ll >= 2 &&
                    (memcmp(ls, "\xff\xfe", 2) == 0 || memcmp(ls, "\xfe\xff", 2) == 0);
        if (bom16 || (!r->seen_content && memchr(ls, '\0', ll))) {
            (void)RFAIL(r, TSU_IO_ERR_ENCODING, 0, r->rec_line, 0, 0,
                        "the file is UTF-16 text (%s): convert it to UTF-8 (for example "
                        "iconv -f UTF-16 -t UTF-8)",
                        bom16 ? "a UTF-16 byte-order mark" : "NUL bytes in its first line");
            break;
        }
        if (r->rec_line == 1 && ll >= 3 && memcmp(ls, "\xef\xbb\xbf", 3) == 0) {
            ls += 3; /* UTF-8 byte-order mark */
            ll -= 3;
        }
        r->ls = ls;
        le = content_end(r, ls, ls + ll);
        p = ls;
        while (p < le && IS_BLANK(*p))
            p++;
        if (p == le)
            continue;
        if (r->delim == TSU_DELIM_AUTO) {
            /* the first candidate outside quotes */
            int inq = 0, semi = 0, comma = 0, tab = 0;
            for (h = ls; h < le; h++) {
                if (*h == '"')
                    inq = !inq;
                else if (!inq)
                    semi |= *h == ';', comma |= *h == ',', tab |= *h == '\t';
            }
            r->delim = semi                        ? TSU_DELIM_SEMICOLON
                       : comma && !r->decimal_comma ? TSU_DELIM_COMMA
                       : tab                        ? TSU_DELIM_TAB
                                                    : TSU_DELIM_SPACE;
        }
        if (!r->seen_content) {
            int hd;
            r->seen_content = 1;
            hd = r->header == TSU_HEADER_YES ||
                 (r->header == TSU_HEADER_AUTO && is_header(r, ls, le, NULL) != 0) ||
                 (r->header == TSU_HEADER_AUTO && r->header_corner && !r->failed &&
                  empty_first(r, ls, le));
            if (r->failed)
                break;
            if (hd) {
                if (read_header(r, ls, le) != TSU_IO_OK)
                    break;
                r->after_header = r->skip_after;
                continue;
            }
            if (r->ncols && set_columns(r, r->ncols) != TSU_IO_OK)
                break;
        }
        if (r->after_header) { /* a units row under the header */
            r->after_header--;
            continue;
        }
        *lep = le;
        return 1;
    }
    return -1;
}

tsu_io_status tsu_reader_layout(tsu_reader *r, tsu_io_error *err)
{
    const char *le;
    int g;
    tsu_io__err_clear(err);
    if (!r) {
        tsu_io__err_set(err, TSU_IO_ERR_NULL, 0, NULL, 0, 0, 0, "null argument");
        return TSU_IO_ERR_NULL;
    }
    if (r->failed || r->pending || r->rows)
        goto out;
    g = next_record(r, &le);
    if (g <= 0)
        goto out; /* g == 0 cannot happen before a row: TSU_IO_ERR_EMPTY */
    if (!r->ncols) {
        const char *p = r->ls;
        field f;
        size_t n = 0;
        int k;
        while ((k = next_field(r, &p, le, n == 0, &f, n + 1)) == 1)
            n++;
        if (k < 0 || set_columns(r, n) != TSU_IO_OK)
            goto out; /* a quote error in the first row: reported as such */
    }
    r->pending = 1;
    r->pend_le = le;
    r->row_line = r->rec_line;
out:
    if (r->failed && err)
        *err = r->saved;
    return r->failed ? r->saved.status : TSU_IO_OK;
}

tsu_io_status tsu_reader_use_columns(tsu_reader *r, const size_t *cols, size_t n,
                                     tsu_io_error *err)
{
    size_t need = 1;
    tsu_io__err_clear(err);
    if (!r || (n && !cols)) {
        tsu_io__err_set(err, TSU_IO_ERR_NULL, 0, r ? r->name : NULL, 0, 0, 0, "null argument");
        return TSU_IO_ERR_NULL;
    }
    for (size_t k = 0; k < n; k++)
        if (cols[k] >= need)
            need = cols[k] + 1;
    if (!r->failed && grow_row(r, need) == 0) {
        memset(r->use, 0, r->rowcap);
        for (size_t k = 0; k < n; k++)
            r->use[cols[k]] = 1;
        r->selected = 1;
        return TSU_IO_OK;
    }
    if (err)
        *err = r->saved;
    return r->saved.status;
}

tsu_io_status tsu_reader_next(tsu_reader *r, const double **row, tsu_io_error *err)
{
    tsu_io__err_clear(err);
    if (row)
        *row = NULL;
    if (!r) {
        tsu_io__err_set(err, TSU_IO_ERR_NULL, 0, NULL, 0, 0, 0, "null argument");
        return TSU_IO_ERR_NULL;
    }
    if (!r->failed) {
        const char *le;
        int g = 1;
        if (r->pending) {
            r->pending = 0;
            le = r->pend_le;
        } else {
            g = next_record(r, &le);
        }
        if (g == 0)
            return TSU_IO_END;
        if (g > 0 && parse_data(r, r->ls, le) == TSU_IO_OK) {
            r->rows++;
            r->row_line = r->rec_line;
            if (row)
                *row = r->row;
            return TSU_IO_OK;
        }
    }
    if (err)
        *err = r->saved;
    return r->saved.status;
}

void tsu_reader_field_pos(const tsu_reader *r, size_t j, unsigned long long *line, size_t *col)
{
    *line = r ? r->row_line : 0;
    *col = 0;
    if (r && j < r->ncols && r->fcol && r->rows)
        *col = r->fcol[j] + 1; /* within the record's first line in the usual case */
}

/* ================================================================== */
/* Whole table                                                          */
/* ================================================================== */

void tsu_table_free(tsu_table *t)
{
    size_t j;
    if (!t)
        return;
    if (t->cols)
        for (j = 0; j < t->ncols; j++)
            free(t->cols[j]);
    free(t->cols);
    free_names(t->names, t->names ? t->ncols : 0);
    free(t->lines);
    t->cols = NULL;
    t->names = NULL;
    t->lines = NULL;
    t->nrows = t->ncols = 0;
}

/* Grow every column (and lines) to cap rows. */
static int table_grow(tsu_table *t, size_t cap, int track)
{
    size_t j;
    if (cap > SIZE_MAX / sizeof(double) || cap > SIZE_MAX / sizeof(unsigned long long))
        return TSU_IO_ERR_OVERFLOW;
    for (j = 0; j < t->ncols; j++) {
        double *nc = tsu_io__realloc(t->cols[j], cap * sizeof(double));
        if (!nc)
            return TSU_IO_ERR_NOMEM;
        t->cols[j] = nc;
    }
    if (track) {
        unsigned long long *nl = tsu_io__realloc(t->lines, cap * sizeof(unsigned long long));
        if (!nl)
            return TSU_IO_ERR_NOMEM;
        t->lines = nl;
    }
    return TSU_IO_OK;
}

tsu_io_status tsu_read_table(FILE *fp, const char *name, const tsu_read_options *opt,
                           tsu_table *out, tsu_io_error *err)
{
    tsu_reader *r;
    tsu_io_status st;
    const double *row;
    size_t cap = 0, n = 0, j;
    int track = opt ? opt->track_lines : 1;
    tsu_io__err_clear(err);
    if (!out) {
        tsu_io__err_set(err, TSU_IO_ERR_NULL, 0, name, 0, 0, 0, "null argument");
        return TSU_IO_ERR_NULL;
    }
    memset(out, 0, sizeof *out);
    st = tsu_reader_open(&r, fp, name, opt, err);
    if (st != TSU_IO_OK)
        return st;
    while ((st = tsu_reader_next(r, &row, err)) == TSU_IO_OK) {
        if (!out->cols) {
            out->ncols = tsu_reader_ncols(r);
            out->cols = tsu_io__calloc(out->ncols, sizeof *out->cols);
            if (!out->cols) {
                st = TSU_IO_ERR_NOMEM;
                break;
            }
        }
        if (n == cap) {
            size_t nc = cap ? cap * 2 : 4096;
            if (nc < cap) {
                st = TSU_IO_ERR_OVERFLOW;
                break;
            }
            st = (tsu_io_status)table_grow(out, nc, track);
            if (st != TSU_IO_OK)
                break;
            cap = nc;
        }
        for (j = 0; j < out->ncols; j++)
            out->cols[j][n] = row[j];
        if (track)
            out->lines[n] = tsu_reader_line(r);
        n++;
        out->nrows = n;
    }
    if (st == TSU_IO_END) {
        out->names = r->names; /* taken over */
        r->names = NULL;
        r->nnames = 0;
        if (n < cap) { /* give back the spare capacity; failure is harmless */
            for (j = 0; j < out->ncols; j++) {
                double *nc = tsu_io__realloc(out->cols[j], n * sizeof(double));
                if (nc)
                    out->cols[j] = nc;
            }
            if (track) {
                unsigned long long *nl = tsu_io__realloc(out->lines, n * sizeof(unsigned long long));
                if (nl)
                    out->lines = nl;
            }
        }
        tsu_reader_free(r);
        return TSU_IO_OK;
    }
    if (st == TSU_IO_ERR_NOMEM || st == TSU_IO_ERR_OVERFLOW) {
        if (err && err->status == TSU_IO_OK)
            tsu_io__err_set(err, st, 0, r->name, 0, 0, 0, "%s",
                    st == TSU_IO_ERR_NOMEM ? "out of memory" : "size overflow");
    }
    tsu_reader_free(r);
    tsu_table_free(out);
    return st;
}

tsu_io_status tsu_read_table_path(const char *path, const tsu_read_options *opt, tsu_table *out,
                                tsu_io_error *err)
{
    FILE *fp;
    tsu_io_status st;
    tsu_io__err_clear(err);
    if (out)
        memset(out, 0, sizeof *out);
    if (!path || !out) {
        tsu_io__err_set(err, TSU_IO_ERR_NULL, 0, path, 0, 0, 0, "null argument");
        return TSU_IO_ERR_NULL;
    }
    if (strcmp(path, "-") == 0)
        return tsu_read_table(stdin, "<stdin>", opt, out, err);
    fp = fopen(path, "rb");
    if (!fp) {
        int e = errno;
        tsu_io__err_set(err, TSU_IO_ERR_OPEN, e, path, 0, 0, 0, "cannot open: %s", strerror(e));
        return TSU_IO_ERR_OPEN;
    }
    st = tsu_read_table(fp, path, opt, out, err);
    fclose(fp);
    return st;
}
