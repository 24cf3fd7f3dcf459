/* Reading the data table and explaining data / scheme errors. */
#include "cli.h"

#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void cli_data_free(cli_data *d)
{
    for (int k = 0; k < 3; k++)
        free(d->col[k]);
    free(d->line);
    memset(d, 0, sizeof *d);
}

/* Append one row of dim values; 0 or -1 (no memory). */
static int push_row(cli_data *d, size_t *cap, const double *v, unsigned long long line)
{
    if (d->n == *cap) {
        size_t nc = *cap ? 2 * *cap : 4096;
        if (nc > SIZE_MAX / sizeof(unsigned long long))
            return -1;
        for (size_t k = 0; k < d->dim; k++) {
            double *p = realloc(d->col[k], nc * sizeof *p);
            if (!p)
                return -1;
            d->col[k] = p;
        }
        unsigned long long *l = realloc(d->line, nc * sizeof *l);
        if (!l)
            return -1;
        d->line = l;
        *cap = nc;
    }
    for (size_t k = 0; k < d->dim; k++)
        d->col[k][d->n] = v[k];
    d->line[d->n++] = line;
    return 0;
}

int cli_read_data(const cli_opts *o, cli_data *d)
{
    tsu_read_options ro;
    tsu_io_error e;
    tsu_reader *r = NULL;
    FILE *fp;
    size_t cap = 0;
    int rc = CLI_OK;
    memset(d, 0, sizeof *d);
    d->name = strcmp(o->data, "-") == 0 ? "<stdin>" : o->data;
    if (strcmp(o->data, "-") == 0) {
        fp = stdin;
    } else if (!(fp = fopen(o->data, "rb"))) {
        cli_error("%s: cannot open: %s", o->data, strerror(errno));
        return CLI_IO;
    }
    cli_read_options(o, &ro);
    if (tsu_reader_open(&r, fp, d->name, &ro, &e) != TSU_IO_OK) {
        rc = cli_report_io(&e);
        goto done;
    }
    if (o->cmd != CLI_CURVE && (rc = cli_cols_select(o, r, d->name, &d->cols)) != CLI_OK)
        goto done;
    for (;;) {
        const double *row;
        tsu_io_status st = tsu_reader_next(r, &row, &e);
        double v[3];
        if (st == TSU_IO_END)
            break;
        if (st != TSU_IO_OK) {
            rc = cli_report_io(&e);
            goto done;
        }
        if (tsu_reader_rows(r) == 1) {
            size_t nc = tsu_reader_ncols(r);
            if (o->cmd == CLI_CURVE) {
                if (nc != 2 && nc != 3) {
                    cli_error("%s:%llu: %zu field%s per row; a curve needs 2 (x, y) or 3 (x, y, z)",
                              d->name, tsu_reader_line(r), nc, nc == 1 ? "" : "s");
                    rc = CLI_DATA;
                    goto done;
                }
                d->dim = nc;
            } else {
                if ((rc = cli_cols_resolve(o, r, d->name, &d->cols)) != CLI_OK)
                    goto done;
                d->dim = 2;
            }
        }
        if (o->cmd == CLI_CURVE) {
            int miss = 0;
            for (size_t k = 0; k < d->dim; k++)
                miss |= isnan(v[k] = row[k]);
            if (miss) {
                unsigned long long l = tsu_reader_line(r);
                if (!o->missing_skip) {
                    cli_error("%s:%llu: missing value; use --missing skip to leave such rows out",
                              d->name, l);
                    rc = CLI_DATA;
                    goto done;
                }
                d->cols.skipped++;
                if (o->verbose)
                    cli_error("%s:%llu: missing value: row skipped", d->name, l);
                continue;
            }
        } else {
            int k = cli_cols_take(o, r, d->name, row, &d->cols, &v[0], &v[1]);
            if (k < 0) {
                rc = CLI_DATA;
                goto done;
            }
            if (k == 0)
                continue;
        }
        if (push_row(d, &cap, v, tsu_reader_line(r)) != 0) {
            rc = cli_nomem();
            goto done;
        }
    }
    if (d->n == 0) {
        cli_error("%s: no data rows (every row has a missing value)", d->name);
        rc = CLI_DATA;
    }
    if (o->verbose && d->cols.skipped)
        cli_error("%s: %llu row%s with missing values skipped", d->name, d->cols.skipped,
                  d->cols.skipped == 1 ? "" : "s");
done:
    tsu_reader_free(r);
    if (fp != stdin)
        fclose(fp);
    if (rc != CLI_OK)
        cli_data_free(d);
    return rc;
}

/* ts_format_x_fn: x as the command writes it (cli_x_text: a date or a number). */
typedef struct x_form {
    const cli_cols *cols;
} x_form;

static int x_text(double x, char *buf, size_t len, void *user)
{
    char b[TSU_TIME_SIZE];
    return snprintf(buf, len, "%s", cli_x_text(((const x_form *)user)->cols, x, b));
}

int cli_report_build_error(const cli_opts *o, const ts_spline_options *opt, const char *name,
                           const cli_cols *cols, const double *x, const double *f,
                           const unsigned long long *lines, size_t n, const ts_error *e,
                           ts_status st, size_t off)
{
    (void)o;
    char w[TSU_IO_MSG_SIZE], msg[2048];
    size_t i = e->index;
    int point = e->where == TS_WHERE_POINT && i < n;
    int interval = e->where == TS_WHERE_INTERVAL && i + 1 < n;
    if (lines && point)
        snprintf(w, sizeof w, "%s:%llu", name, lines[i]);
    else if (lines && interval)
        snprintf(w, sizeof w, "%s:%llu-%llu", name, lines[i], lines[i + 1]);
    else
        snprintf(w, sizeof w, "%s", name);

    x_form xf = {cols};
    ts_error_context ctx;
    ts_error_context_init(&ctx);
    ctx.x = x;
    ctx.f = f;
    ctx.n_points = n;
    ctx.spline_options = opt;
    ctx.first_index = off;
    ctx.format_x = x_text;
    ctx.format_x_user = &xf;
    ts_error err = *e;
    err.status = st;
    ts_error_message(&err, &ctx, msg, sizeof msg);

    int rc;
    switch (st) {
    case TS_ERR_INFEASIBLE:
    case TS_ERR_PRECISION:
    case TS_ERR_UNPROVEN:
        rc = CLI_INFEASIBLE;
        break;
    case TS_ERR_GEOMETRIC:
    case TS_ERR_LENGTH:
    case TS_ERR_ALPHA:
    case TS_ERR_BETA:
    case TS_ERR_MARGIN:
    case TS_ERR_OPTION:
        rc = CLI_USAGE;
        break;
    case TS_ERR_NOMEM:
    case TS_ERR_OVERFLOW:
        rc = CLI_IO;
        break;
    default:
        rc = CLI_DATA;
        break;
    }
    char prev[64] = "";
    if (st == TS_ERR_UNSORTED && point && i > 0 && lines)
        snprintf(prev, sizeof prev, " (previous point: line %llu)", lines[i - 1]);
    if (rc == CLI_USAGE && !point && !interval) /* about the options, not the file */
        cli_error("%s", msg);
    else
        cli_error("%s: %s%s", w, msg, prev);
    return rc;
}

int cli_read_and_fit(const cli_opts *o, const ts_spline_options *opt, cli_data *d, ts_spline **s)
{
    int rc;
    *s = NULL;
    if ((rc = cli_read_data(o, d)) != CLI_OK)
        return rc;
    ts_error e;
    ts_status st = ts_spline_new(d->col[0], d->col[1], d->n, opt, s, &e);
    if (st != TS_OK) {
        rc = cli_report_build_error(o, opt, d->name, &d->cols, d->col[0], d->col[1], d->line, d->n,
                                    &e, st, 0);
        cli_data_free(d);
        return rc;
    }
    return CLI_OK;
}
