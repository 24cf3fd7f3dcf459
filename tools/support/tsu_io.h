/*
 * tsu_io — number conversion, table reading and safe output for the
 * command-line tool (tool side: part of the static library trigspline_support,
 * not of libtrigspline).  C11 plus POSIX (mkstemp, fsync, rename).
 *
 * Prefix tsu_ / TSU_ ("trigspline support"), never ts_: these are not the
 * library's API and know nothing of it (no trigspline.h, no src/internal.h).
 *
 * Four parts, one source file each (tsu_io.c: what they share):
 *
 *  1. Numbers (tsu_number.c).  tsu_parse_double() converts decimal text to the correctly
 *     rounded double (round-half-even, like glibc strtod) and
 *     tsu_format_double() writes the shortest text that converts back to the
 *     identical double.  Both are exact for every input, independent of the
 *     locale (the decimal point is always '.'), and faster than
 *     strtod / printf("%.17g") (see "Speed" below).
 *
 *  2. Reading tables of numbers (tsu_table.c; dates: tsu_time.c) (CSV, TSV or
 *     whitespace-separated, auto-detected) either all at once into column arrays (tsu_read_table) or one
 *     row at a time in constant memory (tsu_reader_*).  Errors name file, line
 *     and column:   data.csv:7:3: expected a number, found "abc"
 *
 *  3. Safe output files (tsu_output.c, tsu_out_*): written to a temporary file in the same
 *     directory and renamed over the target only on success, so a failed
 *     command never leaves a half-written file.  "-" is standard output.
 *
 *  4. A buffered writer of delimited rows of numbers (tsu_output.c, tsu_writer_*).
 *
 * Usage:
 *
 *     tsu_table t;  tsu_io_error e;
 *     if (tsu_read_table_path("data.csv", NULL, &t, &e) != TSU_IO_OK) {
 *         fprintf(stderr, "trigspline: %s\n", e.msg);   // data.csv:7:3: ...
 *         return 1;
 *     }
 *     ... t.cols[0][i], t.cols[1][i], i < t.nrows; t.lines[i] = its line ...
 *     tsu_table_free(&t);
 *
 *     tsu_out *o;  char msg[TSU_IO_MSG_SIZE];
 *     if (tsu_out_open(&o, "out.csv", 0, msg, sizeof msg)) { ...report msg... }
 *     tsu_writer *w = tsu_writer_new(tsu_out_file(o), ',');
 *     for (...) tsu_writer_xy(w, x, y);
 *     int rc = tsu_writer_free(w);                   // flushes; 0 or errno
 *     if (rc) tsu_out_abort(o);                      // removes the temp file
 *     else rc = tsu_out_commit(o, msg, sizeof msg);  // rename into place
 *
 * Thread safety: the number functions are reentrant.  A reader, table,
 * output or writer object must not be used by two threads at once.
 *
 * Speed (against libc: docs/design.md, tools/support/bench; tests/tools/test_io.c
 * prints its own figures too; one x86-64 core, gcc -O2, shared and
 * loaded machine, so indicative only): tsu_format_double ~16 M/s on random
 * bit patterns (snprintf "%.17g" ~2.8 M/s), tsu_parse_double ~18 M/s on
 * 17-digit numbers and ~40 M/s on short ones (strtod ~8 M/s), writer
 * ~8 M rows/s of "x,y", reader ~12 M rows/s (table) and ~15 M rows/s
 * (streaming) of the same.
 */
#ifndef TSU_IO_H
#define TSU_IO_H

#include <stddef.h>
#include <stdio.h>

#ifdef __cplusplus
extern "C" {
#endif

/* ------------------------------------------------------------------ */
/* 1. Numbers                                                           */
/* ------------------------------------------------------------------ */

typedef enum tsu_num_status {
    TSU_NUM_OK = 0,
    TSU_NUM_SYNTAX = 1,    /* no number at s; *stop = first character that does not fit */
    TSU_NUM_RANGE = 2,     /* |value| rounds to infinity (>= DBL_MAX + half an ulp); *out = ±HUGE_VAL */
    TSU_NUM_NONFINITE = 3  /* the words nan, inf, infinity (any case, optional sign); *out = NaN / ±inf */
} tsu_num_status;

/*
 * Parse the longest prefix of [s, end) that is a decimal number:
 *
 *     [+-] ( digits [ "." [digits] ] | "." digits ) [ (e|E) [+-] digits ]
 *
 * No leading white space is skipped, no hexadecimal ("0x1p3" parses as 0
 * with *stop at the 'x'), no digit grouping.  An exponent letter not
 * followed by digits is not part of the number ("1e" is 1, *stop at 'e').
 * end may be NULL: s is then NUL-terminated.  stop may be NULL.
 *
 * The result is the double nearest to the exact decimal value, ties to
 * even, for any number of digits and any exponent (correctly rounded, like
 * glibc strtod).  Results below the smallest subnormal round to ±0 or a
 * subnormal as IEEE 754 says (that is not an error); results that round to
 * infinity are TSU_NUM_RANGE.  "-0" gives -0.0.
 *
 * On TSU_NUM_OK and TSU_NUM_RANGE *stop is just past the number, on
 * TSU_NUM_NONFINITE just past the word; on TSU_NUM_SYNTAX *out = 0 and *stop
 * points at the first character where no number can continue: s for "abc"
 * or "", s+1 for "-x" or ".", s+2 for "-.e5".
 *
 * Method: digits up to 2^53 with a power of ten up to 1e22 use one exact
 * floating-point operation (Clinger 1990); otherwise the decimal is scaled
 * with a 128-bit approximation of 10^e whose error is bounded, and only when
 * the bound cannot decide the rounding is it settled by exact big-integer
 * comparison with the halfway point.  Inputs with more than 19 significant
 * digits are rounded as their 19-digit truncation t and t + 1 unit; when
 * those two disagree (rare) the C library strtod decides on a locale-free
 * normalised copy.  Assumes the default floating-point environment
 * (round to nearest) and FLT_EVAL_METHOD == 0 (else the fast path is off).
 */
tsu_num_status tsu_parse_double(const char *s, const char *end, double *out, const char **stop);

/* Longest output of tsu_format_double incl. the NUL ("-2.2250738585072014e-308" is 25). */
#define TSU_FMT_SIZE 32

/*
 * Write the shortest decimal that tsu_parse_double (or any correctly
 * rounding strtod) converts back to exactly v; among several shortest ones
 * the nearest to v (ties: even last digit).  Returns the length (excluding
 * the NUL written after it).  The layout is that of printf("%.17g") with
 * the shortest digits, i.e. with P = 17 and X the decimal exponent of the
 * first digit:
 *
 *   -4 <= X < 17:  plain notation, no exponent, no trailing zeros after the
 *                  point, no trailing point: "0.1", "-2.5", "123456789",
 *                  "100", "0.0001", "10000000000000000" (1e16)
 *   otherwise:     d[.ddd]e±XX with a sign and at least two exponent digits:
 *                  "1e-05", "1e+17", "1e-300", "5e-324",
 *                  "1.7976931348623157e+308"
 *
 * Zeros: "0" and "-0".  Non-finite: "nan" (any sign), "inf", "-inf".
 * Locale independent.  Exact: integer arithmetic on a 128-bit approximation
 * of 10^k with a proven error bound, and exact big-integer comparisons for
 * the rare decisions the bound leaves open; no printf.
 */
size_t tsu_format_double(double v, char buf[TSU_FMT_SIZE]);

/* ------------------------------------------------------------------ */
/* Status and error report of the reader / table functions              */
/* ------------------------------------------------------------------ */

typedef enum tsu_io_status {
    TSU_IO_OK = 0,
    TSU_IO_END = 1,          /* tsu_reader_next: no more rows (not an error) */
    TSU_IO_ERR_NULL = 2,     /* a required pointer argument is NULL */
    TSU_IO_ERR_NOMEM = 3,    /* allocation failed */
    TSU_IO_ERR_OVERFLOW = 4, /* a size would overflow size_t */
    TSU_IO_ERR_OPTION = 5,   /* an option out of range */
    TSU_IO_ERR_OPEN = 6,     /* cannot open the input file (sys_errno set) */
    TSU_IO_ERR_READ = 7,     /* read error (sys_errno set) */
    TSU_IO_ERR_EMPTY = 8,    /* no data rows (empty input, or only blank/comment/header lines) */
    TSU_IO_ERR_NUMBER = 9,   /* a field is not a number (or is empty) */
    TSU_IO_ERR_NONFINITE = 10, /* a field is nan / inf / infinity */
    TSU_IO_ERR_RANGE = 11,   /* a number overflows a double */
    TSU_IO_ERR_FIELDS = 12,  /* wrong number of fields in a row */
    TSU_IO_ERR_LINE = 13,    /* a line longer than tsu_read_options.max_line */
    TSU_IO_ERR_QUOTE = 14,   /* a quote never closed, or text after a closing quote */
    TSU_IO_ERR_TIME = 15,    /* a field of a time column is not a valid date / date-time */
    TSU_IO_ERR_LAYOUT = 16,  /* the file's layout is ambiguous (second header line, ...) */
    TSU_IO_ERR_ENCODING = 17, /* UTF-16 text (a UTF-16 byte-order mark or NUL bytes) */
    TSU_IO_STATUS_COUNT_ = 18
} tsu_io_status;

/* A fixed, never-NULL English string for any value. */
const char *tsu_io_strerror(tsu_io_status st);

#define TSU_IO_MSG_SIZE 512

/*
 * Detail of a failure.  Functions taking a tsu_io_error* clear it first
 * (status TSU_IO_OK, empty msg) and fill it on failure.  msg is the complete
 * message, ready to print:
 *
 *     NAME:LINE:COLUMN: TEXT     about one field
 *     NAME:LINE: TEXT            about a whole line
 *     NAME: TEXT                 about the input as a whole
 *
 * LINE counts every physical line from 1; COLUMN is the 1-based byte
 * offset in that line (a UTF-8 byte-order mark at the start of the input is
 * not counted).  The texts:
 *
 *     expected a number, found "abc"     (field text quoted, non-printable
 *                                         bytes as \xNN, long text cut with ...)
 *     empty field
 *     not a finite number: "NaN"
 *     number out of range: "1e999"
 *     wrong number of fields (3, expected 2)    column: first extra field,
 *                                               or just past the last one
 *     line longer than 16777216 bytes
 *     read error: <strerror>
 *     cannot open: <strerror>
 *     no data (empty input)               nothing but blank / comment lines
     no data rows                        a header and no row
 *     out of memory | size overflow | invalid option | null argument
 */
typedef struct tsu_io_error {
    tsu_io_status status;
    int sys_errno;             /* errno for TSU_IO_ERR_OPEN / TSU_IO_ERR_READ, else 0 */
    unsigned long long line;   /* 1-based, 0 when not about a line */
    size_t column;             /* 1-based, 0 when not about a field */
    size_t field;              /* 1-based field number, 0 when none */
    char msg[TSU_IO_MSG_SIZE];
} tsu_io_error;

/* ------------------------------------------------------------------ */
/* 2. Reading tables                                                    */
/* ------------------------------------------------------------------ */

/*
 * Dates and times (ISO 8601, the subset real files use):
 *
 *     YYYY-MM-DD                               a date (midnight UTC)
 *     YYYY-MM-DD(T|t| )HH:MM[:SS[.fraction]]    a date-time
 *     ... followed by Z, z, +HH:MM, -HH:MM, +HHMM or +HH   its UTC offset
 *
 * A date-time without an offset is taken as UTC.  Time-zone names are not
 * accepted: a date followed by one (two letters or '[': "CET", " UTC",
 * "[Europe/Paris]") counts as a date in the header test and is an error
 * TSU_IO_ERR_TIME naming the name ("time-zone name ... not accepted, write Z
 * or a numeric UTC offset") in a time column or in the first data row.  Years 0000-9999; month,
 * day, hour (00-23), minute and second (00-59) are range-checked (day
 * against the month, leap years by the Gregorian rule).  Leap seconds do
 * not exist on this time scale (POSIX time): ":60" is an error.  The value
 * is seconds since 1970-01-01T00:00:00Z as a double: the whole seconds
 * exactly (below 2^53), plus the fraction correctly rounded.
 *
 * tsu_parse_time: 1 when [s, end) starts with a date or date-time (*stop
 * just past it, *t its value, *form how it was written), else 0 (*stop at
 * the first character that does not fit).  end may be NULL (NUL-terminated).
 * tsu_format_time: t written in form (TSU_TIME_SIZE bytes incl. the NUL):
 * the time in form's UTC offset, with its separator and zone designator;
 * a date-only form writes a date when t is midnight there and a date-time
 * ("T" separator) otherwise; a form without seconds writes them only when
 * they are not zero; fractional seconds get the fewest digits (at most 9)
 * that tsu_parse_time reads back as the same double.  Returns the length.
 */
typedef struct tsu_time_form {
    int date_only;  /* 1: YYYY-MM-DD */
    char sep;       /* 'T', 't' or ' ' */
    int seconds;    /* 1: ":SS" was written */
    int zone;       /* 0: none, 1: "Z", 2: numeric offset */
    int colon;      /* numeric offset written as +HH:MM */
    int offset_min; /* zone 2: minutes east of UTC */
} tsu_time_form;

#define TSU_TIME_SIZE 48

int tsu_parse_time(const char *s, const char *end, double *t, tsu_time_form *form,
                   const char **stop);

/*
 * tsu_parse_time_format: the same for a strptime-like format fmt (POSIX
 * strptime's conversions that name fields of a date, read from exactly
 * these texts):
 *
 *     %Y 4-digit year      %y 2-digit year (69-99: 19xx, 00-68: 20xx)
 *     %m month 1-12        %b %B %h English month name (full or 3 letters, any case)
 *     %d %e day 1-31       %j day of the year 1-366
 *     %H hour 00-23        %I hour 1-12 with %p AM / PM (any case)
 *     %M minute 00-59      %S second 00-59 (no leap second)
 *     %f digits of a fraction of the second (after %S and a '.' written in fmt)
 *     %z Z or a numeric UTC offset (+HH:MM, +HHMM, +HH)
 *     %F = %Y-%m-%d   %T = %H:%M:%S   %R = %H:%M   %% a '%'
 *
 * Numeric fields take one or two digits (%m, %d, %H ...; %j up to three);
 * a blank in fmt (or %n, %t) matches any run of blanks, none included; any
 * other character matches itself.  Fields left out are 1970, January, day 1,
 * 00:00:00 UTC.  form says: date only when fmt has no time of day, seconds
 * when it has %S or %T, the zone of %z.  Returns 1 when [s, end) starts with
 * a match (*stop just past it), else 0.
 */
int tsu_parse_time_format(const char *fmt, const char *s, const char *end, double *t,
                          tsu_time_form *form, const char **stop);
size_t tsu_format_time(double t, const tsu_time_form *form, char buf[TSU_TIME_SIZE]);

/*
 * Input format (one table per input):
 *  - UTF-8; its byte-order mark at the start is skipped.  UTF-16 text is
 *    TSU_IO_ERR_ENCODING: a UTF-16 byte-order mark at the start of the
 *    first line read (not after UTF-8's: FE FF there are text), or a NUL
 *    byte in a line before the first content line.
 *  - Records end in "\n", "\r\n" or a lone "\r"; the last needs no
 *    terminator.  A record is one line, except that a quoted field may
 *    contain line breaks.
 *  - tsu_read_options.skip leading lines are skipped unread.
 *  - '#' outside quotes starts a comment running to the end of the line.
 *  - Blank lines (only spaces/tabs, or only a comment) are skipped.
 *  - Fields (RFC 4180): a field that starts with '"' (after blanks) is
 *    quoted: it runs to the next lone '"', "" inside stands for one '"', and
 *    delimiters, '#' and line breaks inside are text; after the closing
 *    quote only blanks may come before the delimiter ("text after the
 *    closing quote" otherwise); a quote never closed is an error naming the
 *    line where it opened.  A '"' inside an unquoted field is text.  Quotes
 *    only group: a quoted number is a number.
 *  - Delimiter, when TSU_DELIM_AUTO, is chosen from the first non-blank,
 *    non-comment line (outside quotes, each '"' toggling "inside"): ';' if it
 *    contains one, else ',' (not with decimal_comma), else tab, else white
 *    space.  Until it is known, any of ',' ';' tab space ends a field when
 *    finding where quoted fields start.  With ',', ';'
 *    and tab exactly one delimiter separates two fields and blanks around a
 *    field are ignored (with ',' and ';' tabs too); with white space any run
 *    of spaces and tabs separates fields.
 *  - Header: the first content line is a header (TSU_HEADER_AUTO) when one
 *    of its fields (of the columns chosen by tsu_reader_use_columns, when it
 *    was called first), unquoted and trimmed, is none of: empty, a number
 *    (nan/inf included, so "nan,1" is data; "nanoseconds" is a name), a
 *    missing-value word (when na is set), a date (when time columns are on).
 *    Names are unquoted and trimmed.
 *  - Every other line has the same number of fields: that of the header,
 *    or tsu_read_options.ncols when not 0, or else the first data row's.
 *  - A field of a column not chosen by tsu_reader_use_columns (when it was
 *    called) is any text.  Every other field is a number of tsu_parse_double
 *    and nothing else (surrounding blanks aside); with decimal_comma the
 *    decimal mark is ',' and '.' is an error (it may be a digit-group
 *    separator).  nan/inf, overflow and text
 *    are errors.  With na set, an empty field and the words of na (ASCII
 *    case-insensitive) are missing values: the row holds NaN there and
 *    tsu_reader_missing() counts them.  In a time column every field is a
 *    date or date-time (tsu_parse_time; seconds since the epoch in the row).
 *  - Errors that look like a misread layout say so: a first data row all of
 *    text after a header ("a second header line?"), a field count that
 *    differs from a one-field header ("metadata lines before the header?"),
 *    another delimiter character in a row with the wrong number of fields.
 */

typedef enum tsu_delim {
    TSU_DELIM_AUTO = 0,
    TSU_DELIM_COMMA = 1,
    TSU_DELIM_TAB = 2,
    TSU_DELIM_SPACE = 3,  /* runs of spaces and tabs */
    TSU_DELIM_SEMICOLON = 4
} tsu_delim;

typedef enum tsu_header {
    TSU_HEADER_AUTO = 0,  /* first content line is a header if it has a non-numeric field */
    TSU_HEADER_NONE = 1,  /* no header: a text field in the first line is an error */
    TSU_HEADER_YES = 2    /* the first content line is a header whatever it contains */
} tsu_header;

typedef struct tsu_read_options {
    tsu_delim delim;       /* default TSU_DELIM_AUTO */
    tsu_header header;     /* default TSU_HEADER_AUTO */
    size_t ncols;         /* required number of fields per row; 0 (default) = any, same in every row */
    size_t max_line;      /* longest accepted line in bytes, default TSU_IO_MAX_LINE; >= 16 */
    size_t buffer_size;   /* initial read buffer, default TSU_IO_BUFFER (1 MiB); >= 16; grows
                             up to max_line for a longer line */
    int track_lines;      /* tsu_read_table: also fill tsu_table.lines (default 1) */
    unsigned long long skip; /* leading lines skipped unread (default 0) */
    int decimal_comma;    /* 1: ',' is the decimal mark (default 0) */
    const char *na;       /* comma-separated words read as missing values, besides the empty
                             field; NULL (default): missing values are errors */
    int time_detect;      /* 1: a column whose first data field is a date is a time column */
    size_t time_col;      /* 1-based column that must hold dates (0: none) */
    const char *time_name; /* or the header name of that column (NULL: none) */
    const char *time_format; /* dates are read with tsu_parse_time_format(time_format)
                                instead of as ISO 8601 (NULL: ISO 8601) */
    unsigned long long skip_after_header; /* content lines after the header skipped
                                             unread (units rows; default 0) */
    int header_corner;    /* 1: with TSU_HEADER_AUTO a first content line whose first
                             field is empty is the header too (the corner cell of a
                             matrix layout, as pandas DataFrame.to_csv writes it) */
} tsu_read_options;

#define TSU_IO_MAX_LINE ((size_t)16 << 20)
#define TSU_IO_BUFFER ((size_t)1 << 20)

void tsu_read_options_init(tsu_read_options *opt);

/* ---- streaming: one row at a time, memory O(buffer + row) ---------- */

typedef struct tsu_reader tsu_reader;

/*
 * Start reading fp (not closed by the reader; may be stdin).  name is used
 * in messages (copied; NULL gives "<input>").  opt may be NULL (defaults).
 * Nothing is read yet.  TSU_IO_OK, TSU_IO_ERR_NULL, TSU_IO_ERR_NOMEM,
 * TSU_IO_ERR_OPTION.  *out is NULL on failure.
 */
tsu_io_status tsu_reader_open(tsu_reader **out, FILE *fp, const char *name,
                            const tsu_read_options *opt, tsu_io_error *err);

/*
 * Next data row: *row points at tsu_reader_ncols(r) doubles, valid until the
 * next call.  Returns TSU_IO_OK, TSU_IO_END after the last row, or an error
 * (TSU_IO_ERR_EMPTY when the input has no data row at all; TSU_IO_ERR_READ,
 * _NUMBER, _NONFINITE, _RANGE, _FIELDS, _LINE, _NOMEM, _OVERFLOW, _NULL).
 * After an error every later call returns the same error and message.
 */
tsu_io_status tsu_reader_next(tsu_reader *r, const double **row, tsu_io_error *err);

/*
 * Read up to the first data row without parsing it: the delimiter, the
 * header (names, tsu_reader_header_line) and the number of columns are then
 * known, and tsu_reader_line gives the line of that row (the next
 * tsu_reader_next returns it).  Only before the first row is returned (later
 * calls do nothing).  TSU_IO_OK, or an error of tsu_reader_next
 * (TSU_IO_ERR_EMPTY when there is no data row).
 */
tsu_io_status tsu_reader_layout(tsu_reader *r, tsu_io_error *err);

/*
 * Parse only the columns cols[0..n) (0-based) of the rows returned from now
 * on: the other fields are split off (quotes honoured, a quote error there
 * is still an error) but not read, so they may hold any text; their row
 * entries are NaN and count neither as missing values nor as dates.  Called
 * before the header is known (before tsu_reader_layout or the first
 * tsu_reader_next), the header test looks only at these columns, so a text
 * field elsewhere does not make the first line a header.  Columns beyond a
 * row's fields are ignored.  TSU_IO_OK, TSU_IO_ERR_NOMEM, TSU_IO_ERR_NULL.
 */
tsu_io_status tsu_reader_use_columns(tsu_reader *r, const size_t *cols, size_t n,
                                     tsu_io_error *err);

size_t tsu_reader_ncols(const tsu_reader *r);               /* 0 until known */
unsigned long long tsu_reader_line(const tsu_reader *r);    /* line of the last row returned */
unsigned long long tsu_reader_rows(const tsu_reader *r);    /* data rows returned so far */
size_t tsu_reader_nnames(const tsu_reader *r);              /* header fields, 0 if no header (yet) */
const char *tsu_reader_name(const tsu_reader *r, size_t j); /* header name j, NULL if none */
const char *tsu_reader_source(const tsu_reader *r);         /* the display name */
tsu_delim tsu_reader_delim(const tsu_reader *r);             /* the delimiter in use (AUTO until known) */
/* Missing fields (NaN) in the last row returned (0 without na). */
size_t tsu_reader_missing(const tsu_reader *r);
/* 1 when column j holds dates; *form (may be NULL) how its first value was written. */
int tsu_reader_is_time(const tsu_reader *r, size_t j, tsu_time_form *form);
/* Line and 1-based byte column of field j of the last row returned (for messages). */
void tsu_reader_field_pos(const tsu_reader *r, size_t j, unsigned long long *line, size_t *col);
/* Line of the header, 0 if none. */
unsigned long long tsu_reader_header_line(const tsu_reader *r);
/* Column j (0-based) holds dates whatever its first value looks like (a
 * date format of digits only, "20240105"): call after tsu_reader_layout,
 * before the first row.  0, or -1 when too late or j is not a column. */
int tsu_reader_set_time_column(tsu_reader *r, size_t j);
void tsu_reader_free(tsu_reader *r);                        /* NULL ok; does not close fp */

/* ---- whole table in memory ---------------------------------------- */

typedef struct tsu_table {
    size_t nrows, ncols;
    double **cols;              /* cols[j][i]: field j of row i (ncols arrays of nrows) */
    char **names;               /* ncols header names, or NULL without header */
    unsigned long long *lines;  /* line of each row, or NULL (track_lines == 0) */
} tsu_table;

/*
 * Read every row of fp into *out (zeroed first; after a failure nothing is
 * left allocated, tsu_table_free is still safe).  Arrays grow geometrically
 * with overflow checks.  Same statuses as tsu_reader_next (TSU_IO_ERR_EMPTY
 * for no data).
 */
tsu_io_status tsu_read_table(FILE *fp, const char *name, const tsu_read_options *opt,
                           tsu_table *out, tsu_io_error *err);

/* The same for a path; "-" reads stdin under the name "<stdin>".
 * Adds TSU_IO_ERR_OPEN ("NAME: cannot open: No such file or directory"). */
tsu_io_status tsu_read_table_path(const char *path, const tsu_read_options *opt,
                                tsu_table *out, tsu_io_error *err);

void tsu_table_free(tsu_table *t);  /* NULL ok; leaves *t zeroed */

/* ------------------------------------------------------------------ */
/* 3. Safe output files                                                 */
/* ------------------------------------------------------------------ */

/*
 * These return 0 on success or a positive errno value, and on failure write
 * one of these messages into errbuf (NUL-terminated, truncated to errlen;
 * errbuf may be NULL; on success it is set to ""):
 *     cannot create temporary file for "out/x.csv": No such file or directory
 *     error writing "out/x.csv": No space left on device    (write/flush/close)
 *     cannot replace "out/x.csv": Is a directory            (rename)
 *     error writing to standard output: Broken pipe
 *     no output path | invalid output flags | out of memory  (EINVAL, ENOMEM)
 *
 * tsu_out_open(path): "-" is standard output (written directly; nothing
 * to rename; commit flushes it).  Otherwise creates "PATH.tmp.XXXXXX" with
 * mkstemp in the same directory, gives it the permissions of an existing
 * regular file PATH or else 0666 minus the umask, and opens it for
 * writing.  Write with tsu_out_file() (stdio) or a tsu_writer.
 *
 * tsu_out_commit: flushes, optionally fsyncs (TSU_OUT_FSYNC: also the
 * directory after the rename), closes and renames the temporary file onto
 * PATH (replacing a file or symbolic link there).  Any write, flush, close
 * or rename error removes the temporary file and is returned; PATH is then
 * untouched.  Frees o in every case.
 *
 * tsu_out_abort: closes and removes the temporary file, frees o (NULL ok).
 * For "-" it only flushes (what was written cannot be taken back).
 *
 * The temporary files open at a time (up to 16) are removed if the process
 * gets SIGINT, SIGTERM, SIGHUP or SIGQUIT (the first tsu_out_open installs
 * handlers for those not ignored; a handler removes the files and re-raises
 * the signal with its default action).  It also ignores SIGXFSZ unless the
 * caller handles it, so that exceeding the file size limit is a write error
 * (EFBIG) like any other.  SIGKILL or a crash leave them.
 */
typedef struct tsu_out tsu_out;

#define TSU_OUT_FSYNC 1u

int tsu_out_open(tsu_out **out, const char *path, unsigned flags, char *errbuf, size_t errlen);
FILE *tsu_out_file(const tsu_out *o);         /* the stream to write to */
const char *tsu_out_path(const tsu_out *o);   /* the final path ("-" for stdout) */
const char *tsu_out_temp(const tsu_out *o);   /* the temporary file, NULL for "-" */
int tsu_out_commit(tsu_out *o, char *errbuf, size_t errlen);
void tsu_out_abort(tsu_out *o);

/* ------------------------------------------------------------------ */
/* 4. Fast row writer                                                   */
/* ------------------------------------------------------------------ */

/*
 * Rows of numbers written with tsu_format_double, fields separated by delim
 * (',' '\t' ' ' ';' allowed), "\n" at the end of each row, through a 64 KiB
 * buffer and fwrite.  Errors are sticky: every call returns 0 or the first
 * errno met (ENOSPC, EIO, ...); after an error nothing more is written.
 * Does not close fp.
 */
typedef struct tsu_writer tsu_writer;

tsu_writer *tsu_writer_new(FILE *fp, char delim);   /* NULL: no memory, NULL fp or bad delim */
int tsu_writer_row(tsu_writer *w, const double *v, size_t n);
int tsu_writer_xy(tsu_writer *w, double x, double y);
int tsu_writer_text(tsu_writer *w, const char *s, size_t len);  /* raw bytes, e.g. a header line */
int tsu_writer_flush(tsu_writer *w);                /* buffer -> fwrite -> fflush */
int tsu_writer_free(tsu_writer *w);                 /* flush + free; returns the first error; NULL ok */

/* ------------------------------------------------------------------ */
/* Internal, for tests only                                             */
/* ------------------------------------------------------------------ */

/* Entry a (-13 <= a <= 12) of the table of 10^(27a) ≈ (hi·2^64 + lo)·2^s
 * with 2^127 <= hi·2^64+lo < 2^128, truncated; *exact = 1 when equal.
 * Returns 0, or -1 for a out of range. */
int tsu_io__pow10_entry(int a, unsigned long long *hi, unsigned long long *lo, int *s, int *exact);

/* Make the (n+1)-th allocation of this module from now on fail, once
 * (n < 0: never, the default).  A global: not thread-safe, tests only. */
void tsu_io__fail_alloc_after(long n);

#ifdef __cplusplus
}
#endif
#endif /* TSU_IO_H */
