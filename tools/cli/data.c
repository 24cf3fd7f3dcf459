/* Reading the data table and explaining data / scheme errors. */
#include "cli.h"

#include <errno.h>
#include <float.h>
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

/* "NAME:LINE" of point i, or "NAME" without line numbers. */
static void where(char *buf, size_t len, const char *name, const unsigned long long *lines,
                  size_t i)
{
    if (lines)
        snprintf(buf, len, "%s:%llu", name, lines[i]);
    else
        snprintf(buf, len, "%s", name);
}

/* Append the x of every point failing pred (at most 12, then "..."). */
typedef int (*point_pred)(const ts_spline_options *opt, double x, double f);

static int pred_negative(const ts_spline_options *opt, double x, double f)
{
    (void)opt;
    (void)x;
    return !(f >= 0.0);
}
static int pred_not_above(const ts_spline_options *opt, double x, double f)
{
    return !(f - (opt->lower.m * x + opt->lower.c) > 0.0);
}
static int pred_not_below(const ts_spline_options *opt, double x, double f)
{
    return !((opt->upper.m * x + opt->upper.c) - f > 0.0);
}

static void list_points(char *buf, size_t len, const ts_spline_options *opt, point_pred pred,
                        const cli_cols *cols, const double *x, const double *f, size_t n)
{
    size_t cnt = 0, used = 0;
    char b[TSU_TIME_SIZE];
    buf[0] = '\0';
    for (size_t i = 0; i < n; i++) {
        if (!pred(opt, x[i], f[i]))
            continue;
        int w;
        if (cnt == 12)
            w = snprintf(buf + used, len - used, ", ...");
        else if (cnt < 12)
            w = snprintf(buf + used, len - used, "%s%s", cnt ? ", " : "",
                         cli_x_text(cols, x[i], b));
        else
            w = 0;
        cnt++;
        if (w < 0 || (size_t)w >= len - used)
            return;
        used += (size_t)w;
    }
}

int cli_report_build_error(const cli_opts *o, const ts_spline_options *opt, const char *name,
                           const cli_cols *cols, const double *x, const double *f,
                           const unsigned long long *lines, size_t n, const ts_error *e,
                           ts_status st, size_t off)
{
    char w[TSU_IO_MSG_SIZE], bx[TSU_TIME_SIZE], bf[TSU_FMT_SIZE], b2[TSU_TIME_SIZE];
    char ln[160], list[400];
    size_t i = e->index;
    int point = e->where == TS_WHERE_POINT && i < n;
    int interval = e->where == TS_WHERE_INTERVAL && i + 1 < n;
    if (point || interval)
        where(w, sizeof w, name, lines, i);
    else
        snprintf(w, sizeof w, "%s", name);

    switch (st) {
    case TS_ERR_TOO_FEW:
        cli_error("%s: %zu data point%s; at least 2 are needed", name, n, n == 1 ? "" : "s");
        return CLI_DATA;
    case TS_ERR_UNSORTED:
        if (point && i > 0) {
            cli_error("%s: point %zu (x = %s) is not greater than the previous x = %s%s%s; x must "
                      "be strictly increasing",
                      w, off + i, cli_x_text(cols, x[i], bx), cli_x_text(cols, x[i - 1], b2),
                      lines ? " (line " : "",
                      lines ? (snprintf(ln, sizeof ln, "%llu)", lines[i - 1]), ln) : "");
            return CLI_DATA;
        }
        break;
    case TS_ERR_NONFINITE:
        if (point) {
            cli_error("%s: point %zu (x = %s, f = %s): the step from the previous point, or a "
                      "slope there, overflows a double",
                      w, off + i, cli_x_text(cols, x[i], bx), cli_num(f[i], bf));
            return CLI_DATA;
        }
        break;
    case TS_ERR_WIDTH:
        if (point && i > 0) {
            double h = x[i] - x[i - 1];
            cli_error("%s: point %zu (x = %s): the step %s from the previous x = %s %s", w,
                      off + i, cli_num(x[i], bx), cli_num(h, bf), cli_num(x[i - 1], b2),
                      h <= DBL_MAX ? "underflows: steps below 2.2250738585072014e-308 (the "
                                     "smallest normal double) are refused"
                                   : "overflows a double");
            return CLI_DATA;
        }
        break;
    case TS_ERR_PERIODIC:
        cli_error("%s: --slopes periodic needs the last value equal to the first: f = %s here, "
                  "f = %s%s%s",
                  w, cli_num(f[n - 1], bf), cli_num(f[0], b2), lines ? " at line " : " first",
                  lines ? (snprintf(ln, sizeof ln, "%llu", lines[0]), ln) : "");
        return CLI_DATA;
    case TS_ERR_NEGATIVE:
        if (point) {
            list_points(list, sizeof list, opt, pred_negative, cols, x, f, n);
            cli_error("%s: point %zu (x = %s, f = %s) is negative; --shape positive needs f >= 0 "
                      "(negative at x = %s)",
                      w, off + i, cli_x_text(cols, x[i], bx), cli_num(f[i], bf), list);
            return CLI_DATA;
        }
        break;
    case TS_ERR_SIDE:
        if (point) {
            int low = (opt->shape == TS_SHAPE_ABOVE || opt->shape == TS_SHAPE_BETWEEN) &&
                      pred_not_above(opt, x[i], f[i]);
            const ts_line *l = low ? &opt->lower : &opt->upper;
            cli_line_text(l, ln, sizeof ln);
            list_points(list, sizeof list, opt, low ? pred_not_above : pred_not_below, cols, x,
                        f, n);
            cli_error("%s: point %zu (x = %s, f = %s) is not %s the %s line %s; the data are on "
                      "or %s it at x = %s",
                      w, off + i, cli_x_text(cols, x[i], bx), cli_num(f[i], bf),
                      low ? "above" : "below", low ? "lower" : "upper", ln, low ? "below" : "above",
                      list);
            return CLI_DATA;
        }
        break;
    case TS_ERR_LINES:
        if (point) {
            char lo[160];
            cli_line_text(&opt->lower, lo, sizeof lo);
            cli_line_text(&opt->upper, ln, sizeof ln);
            cli_error("%s: at point %zu (x = %s) the lower line %s is not below the upper line %s",
                      w, off + i, cli_x_text(cols, x[i], bx), lo, ln);
            return CLI_DATA;
        }
        break;
    case TS_ERR_NONMONOTONE:
        if (point) {
            cli_error("%s: point %zu (x = %s, f = %s): the data change direction here; --shape "
                      "monotone needs monotone data",
                      w, off + i, cli_x_text(cols, x[i], bx), cli_num(f[i], bf));
            return CLI_DATA;
        }
        break;
    case TS_ERR_ZERO_SLOPE:
        break;
    case TS_ERR_INFEASIBLE:
        if (interval) {
            if (lines)
                snprintf(ln, sizeof ln, "%s:%llu-%llu", name, lines[i], lines[i + 1]);
            else
                snprintf(ln, sizeof ln, "%s", name);
            cli_error("%s: interval %zu [%s, %s]: infeasible constraint: no beta >= 0 keeps the "
                      "spline inside the region on this interval",
                      ln, off + i, cli_x_text(cols, x[i], bx), cli_x_text(cols, x[i + 1], b2));
            return CLI_INFEASIBLE;
        }
        cli_error("%s: infeasible constraint: %s", name, ts_strerror(st));
        return CLI_INFEASIBLE;
    case TS_ERR_PRECISION:
    case TS_ERR_UNPROVEN:
        if (lines && interval)
            snprintf(ln, sizeof ln, "%s:%llu-%llu", name, lines[i], lines[i + 1]);
        else
            snprintf(ln, sizeof ln, "%s", name);
        if (interval)
            cli_error("%s: interval %zu [%s, %s]: %s", ln, off + i, cli_num(x[i], bx),
                      cli_num(x[i + 1], b2), ts_strerror(st));
        else
            cli_error("%s: %s", ln, ts_strerror(st));
        return CLI_INFEASIBLE;
    case TS_ERR_GEOMETRIC:
        if (interval) {
            double a = (opt->alphas ? opt->alphas[off + i] : opt->alpha) +
                       (opt->betas ? opt->betas[off + i] : opt->beta);
            char lr[200];
            if (lines)
                snprintf(lr, sizeof lr, "%s:%llu-%llu", name, lines[i], lines[i + 1]);
            else
                snprintf(lr, sizeof lr, "%s", name);
            cli_error("%s: interval %zu [%s, %s]: alpha + beta = %s is below the geometric-form "
                      "bound %s; raise --alpha or --beta",
                      lr, off + i, cli_x_text(cols, x[i], bx), cli_x_text(cols, x[i + 1], b2),
                      cli_num(a, bf), cli_num(TS_GEOMETRIC_A_MIN, ln));
            return CLI_USAGE;
        }
        break;
    case TS_ERR_LENGTH:
        cli_error("%s has %zu values, but the data have %zu interval%s (exactly one value per "
                  "interval is needed)",
                  opt->alphas && opt->n_alphas != n - 1 ? "--alphas" : "--betas",
                  opt->alphas && opt->n_alphas != n - 1 ? opt->n_alphas : opt->n_betas, n - 1,
                  n == 2 ? "" : "s");
        return CLI_USAGE;
    case TS_ERR_ALPHA:
    case TS_ERR_BETA:
    case TS_ERR_MARGIN:
    case TS_ERR_OPTION:
        cli_error("%s", ts_strerror(st));
        return CLI_USAGE;
    case TS_ERR_NOMEM:
    case TS_ERR_OVERFLOW:
        cli_error("%s: %s", name, ts_strerror(st));
        return CLI_IO;
    default:
        break;
    }
    (void)o;
    if (point)
        cli_error("%s: point %zu (x = %s): %s", w, off + i, cli_x_text(cols, x[i], bx),
                  ts_strerror(st));
    else if (interval)
        cli_error("%s: interval %zu [%s, %s]: %s", w, off + i, cli_x_text(cols, x[i], bx),
                  cli_x_text(cols, x[i + 1], b2), ts_strerror(st));
    else
        cli_error("%s: %s", name, ts_strerror(st));
    return CLI_DATA;
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
