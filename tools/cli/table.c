/* Reading DATA rows: reader options from the command line, the x / y
 * columns by number or header name, rows with missing values. */
#include "cli.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

void cli_read_options(const cli_opts *o, tsu_read_options *ro)
{
    tsu_read_options_init(ro);
    ro->delim = o->delim == ',' ? TSU_DELIM_COMMA : o->delim == ';' ? TSU_DELIM_SEMICOLON
                : o->delim == '\t' ? TSU_DELIM_TAB : o->delim == ' ' ? TSU_DELIM_SPACE
                                                                       : TSU_DELIM_AUTO;
    ro->decimal_comma = o->decimal_comma;
    ro->na = o->na;
    ro->skip = o->skip;
    ro->time_detect = o->cmd != CLI_CURVE;
    ro->time_format = o->date_format;
    ro->skip_after_header = o->units_row ? 1 : 0;
}

/* Column numbers up to this are given to the reader before the header test. */
#define CLI_MAX_PRESELECT 65536

/* spec as a 1-based column number: 1 and *k, or 0 (a name). */
static int col_number(const char *spec, size_t *k)
{
    size_t v = 0;
    const char *p = spec;
    for (; *p >= '0' && *p <= '9' && v < ((size_t)-1) / 10; p++)
        v = v * 10 + (size_t)(*p - '0');
    *k = v;
    return !*p && p > spec;
}

/* Column j (0-based) of spec: a 1-based number, or a header name. */
static int find_col(const tsu_reader *r, const char *name, unsigned long long line,
                    const char *opt, const char *spec, size_t def, size_t *j)
{
    size_t nc = tsu_reader_ncols(r), nn = tsu_reader_nnames(r);
    if (!spec) {
        *j = def;
        return CLI_OK;
    }
    size_t k;
    if (col_number(spec, &k)) {
        if (k < 1 || k > nc) {
            cli_error("%s:%llu: %s %s: the table has %zu column%s", name, line, opt, spec, nc,
                      nc == 1 ? "" : "s");
            return CLI_DATA;
        }
        *j = k - 1;
        return CLI_OK;
    }
    for (size_t i = 0; i < nn; i++)
        if (strcmp(tsu_reader_name(r, i), spec) == 0) {
            *j = i;
            return CLI_OK;
        }
    char list[400] = "";
    size_t used = 0;
    for (size_t i = 0; i < nn && used + 1 < sizeof list; i++) {
        int w = snprintf(list + used, sizeof list - used, "%s\"%s\"", i ? ", " : "",
                         tsu_reader_name(r, i));
        if (w < 0)
            break;
        used += (size_t)w;
    }
    if (nn)
        cli_error("%s: %s %s: no column of that name (the header, line %llu, has %s)", name, opt,
                  spec, tsu_reader_header_line(r), list);
    else
        cli_error("%s: %s %s: the file has no header line to find a column name in (use "
                  "numbers: %s 1,2)", name, opt, spec, opt);
    return CLI_DATA;
}

int cli_cols_select(const cli_opts *o, tsu_reader *r, const char *name, cli_cols *c)
{
    tsu_io_error ie;
    size_t kx = 1, ky = 2;
    int rc;
    const char *opt_x = o->columns_set && o->xcol && o->ycol ? "--columns" : "--x";
    const char *opt_y = o->columns_set && o->xcol && o->ycol ? "--columns" : "--y";
    /* numbers: only these columns count in the header test (a number beyond
     * any real table is left to the range check below, not allocated for) */
    if ((o->xcol || o->ycol) && (!o->xcol || col_number(o->xcol, &kx)) &&
        (!o->ycol || col_number(o->ycol, &ky)) && kx >= 1 && ky >= 1 &&
        kx <= CLI_MAX_PRESELECT && ky <= CLI_MAX_PRESELECT) {
        if (!o->ycol)
            ky = kx == 2 ? 1 : 2;
        size_t use[2] = {kx - 1, ky - 1};
        if (tsu_reader_use_columns(r, use, 2, &ie) != TSU_IO_OK)
            return cli_report_io(&ie);
    }
    if (tsu_reader_layout(r, &ie) != TSU_IO_OK)
        return cli_report_io(&ie);
    unsigned long long ln = tsu_reader_line(r);
    size_t nc = tsu_reader_ncols(r);
    if (!o->xcol && !o->ycol && nc != 2) {
        cli_error("%s:%llu: %zu field%s per row, expected 2 (x and f)%s", name, ln, nc,
                  nc == 1 ? "" : "s",
                  nc > 2 ? "; pick two with --columns X,Y (numbers or header names)" : "");
        return CLI_DATA;
    }
    if ((rc = find_col(r, name, ln, opt_x, o->xcol, 0, &c->ix)) != CLI_OK ||
        (rc = find_col(r, name, ln, opt_y, o->ycol, o->xcol && !o->ycol && c->ix == 1 ? 0 : 1,
                       &c->iy)) != CLI_OK)
        return rc;
    if (c->ix == c->iy) {
        cli_error("%s: x and y are the same column (%zu)", name, c->ix + 1);
        return CLI_DATA;
    }
    const char *xn = tsu_reader_name(r, c->ix), *yn = tsu_reader_name(r, c->iy);
    snprintf(c->xname, sizeof c->xname, "%s", xn && *xn ? xn : "x");
    snprintf(c->yname, sizeof c->yname, "%s", yn && *yn ? yn : "y");
    /* the other columns are not read: they may hold any text */
    size_t use[2] = {c->ix, c->iy};
    if (tsu_reader_use_columns(r, use, 2, &ie) != TSU_IO_OK)
        return cli_report_io(&ie);
    if (o->date_format)
        (void)tsu_reader_set_time_column(r, c->ix); /* "20240105" is a date too */
    return CLI_OK;
}

int cli_cols_resolve(const cli_opts *o, const tsu_reader *r, const char *name, cli_cols *c)
{
    unsigned long long ln = tsu_reader_line(r);
    c->x_time = tsu_reader_is_time(r, c->ix, &c->tform);
    if (tsu_reader_is_time(r, c->iy, NULL)) {
        cli_error("%s:%llu: column %zu (\"%s\") holds dates; only x can be a time", name, ln,
                  c->iy + 1, c->yname);
        return CLI_DATA;
    }
    if (o->x_time && !c->x_time) {
        unsigned long long l;
        size_t col;
        tsu_reader_field_pos(r, c->ix, &l, &col);
        cli_error("%s:%llu:%zu: --x-time: column %zu (\"%s\") does not hold ISO 8601 dates "
                  "(YYYY-MM-DD[THH:MM[:SS]][Z|+HH:MM])", name, l, col, c->ix + 1, c->xname);
        return CLI_DATA;
    }
    return CLI_OK;
}

int cli_cols_take(const cli_opts *o, const tsu_reader *r, const char *name, const double *row,
                  cli_cols *c, double *x, double *y)
{
    *x = row[c->ix];
    *y = row[c->iy];
    if (!tsu_reader_missing(r) || (!isnan(*x) && !isnan(*y)))
        return 1;
    if (o->missing_skip) {
        c->skipped++;
        if (o->verbose)
            cli_error("%s:%llu: missing value in column %zu (\"%s\"): row skipped", name,
                      tsu_reader_line(r), isnan(*x) ? c->ix + 1 : c->iy + 1,
                      isnan(*x) ? c->xname : c->yname);
        return 0;
    }
    unsigned long long l;
    size_t col;
    size_t j = isnan(*x) ? c->ix : c->iy;
    tsu_reader_field_pos(r, j, &l, &col);
    cli_error("%s:%llu:%zu: missing value in column %zu (\"%s\"); use --missing skip to leave such "
              "rows out", name, l, col, j + 1, j == c->ix ? c->xname : c->yname);
    return -1;
}

void cli_cols_csv_name(const char *nm, char *buf, size_t len)
{
    /* RFC 4180: quote a name holding a delimiter, quote, line break or outer blanks */
    size_t n = strlen(nm), k = 0;
    int q = n == 0 || strpbrk(nm, ",;\"\n\r\t#") != NULL || nm[0] == ' ' || nm[n - 1] == ' ';
    if (!q) {
        snprintf(buf, len, "%s", nm);
        return;
    }
    if (len < 3) {
        if (len)
            buf[0] = 0;
        return;
    }
    buf[k++] = '"';
    for (const char *p = nm; *p && k + 3 < len; p++) {
        if (*p == '"')
            buf[k++] = '"';
        buf[k++] = *p;
    }
    buf[k++] = '"';
    buf[k] = 0;
}

void cli_cols_y_header(const cli_cols *c, int deriv, char *buf, size_t len)
{
    char raw[600];
    if (deriv == 1)
        snprintf(raw, sizeof raw, "d_%s_d%s", c->yname, c->xname);
    else if (deriv == 2)
        snprintf(raw, sizeof raw, "d2_%s_d%s2", c->yname, c->xname);
    else
        snprintf(raw, sizeof raw, "%s", c->yname);
    cli_cols_csv_name(raw, buf, len);
}

int cli_header_line(const cli_cols *c, int deriv, tsu_plot_buf *b)
{
    char xn[700], yn[700];
    cli_cols_csv_name(c->xname, xn, sizeof xn);
    cli_cols_y_header(c, deriv, yn, sizeof yn);
    return tsu_plot_buf_printf(b, "%s,%s\n", xn, yn) == TSU_PLOT_OK ? 0 : -1;
}

const char *cli_x_text(const cli_cols *c, double x, char buf[TSU_TIME_SIZE])
{
    if (c && c->x_time) {
        tsu_format_time(x, &c->tform, buf);
        return buf;
    }
    tsu_format_double(x, buf);
    return buf;
}
