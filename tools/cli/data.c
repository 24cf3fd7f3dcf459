/* Reading the data table and explaining data / scheme errors. */
#include "cli.h"

#include <float.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

int cli_report_io(const tsu_io_error *e)
{
    cli_error("%s", e->msg);
    switch (e->status) {
    case TSU_IO_ERR_OPEN:
    case TSU_IO_ERR_READ:
    case TSU_IO_ERR_NOMEM:
    case TSU_IO_ERR_OVERFLOW:
    case TSU_IO_ERR_NULL:
    case TSU_IO_ERR_OPTION:
        return CLI_IO;
    default:
        return CLI_DATA;
    }
}

void cli_data_free(cli_data *d)
{
    tsu_table_free(&d->t);
    memset(d, 0, sizeof *d);
}

int cli_read_data(const cli_opts *o, cli_data *d)
{
    tsu_read_options ro;
    tsu_io_error e;
    memset(d, 0, sizeof *d);
    tsu_read_options_init(&ro);
    d->name = strcmp(o->data, "-") == 0 ? "<stdin>" : o->data;
    tsu_io_status st = tsu_read_table_path(o->data, &ro, &d->t, &e);
    if (st != TSU_IO_OK)
        return cli_report_io(&e);
    size_t nc = d->t.ncols;
    unsigned long long l0 = d->t.lines ? d->t.lines[0] : 0;
    d->n = d->t.nrows;
    d->line = d->t.lines;
    if (o->cmd == CLI_CURVE) {
        if (nc != 2 && nc != 3) {
            cli_error("%s:%llu: %zu field%s per row; a curve needs 2 (x, y) or 3 (x, y, z)",
                      d->name, l0, nc, nc == 1 ? "" : "s");
            cli_data_free(d);
            return CLI_DATA;
        }
        d->dim = nc;
        for (size_t k = 0; k < nc; k++)
            d->col[k] = d->t.cols[k];
        return CLI_OK;
    }
    size_t cx = 0, cy = 1;
    if (o->columns_set) {
        cx = o->col_x;
        cy = o->col_y;
        if (cx >= nc || cy >= nc) {
            cli_error("%s:%llu: --columns %zu,%zu: the table has only %zu field%s per row",
                      d->name, l0, cx + 1, cy + 1, nc, nc == 1 ? "" : "s");
            cli_data_free(d);
            return CLI_DATA;
        }
    } else if (nc != 2) {
        cli_error("%s:%llu: %zu field%s per row, expected 2 (x and f)%s", d->name, l0, nc,
                  nc == 1 ? "" : "s", nc > 2 ? "; use --columns X,Y to pick two" : "");
        cli_data_free(d);
        return CLI_DATA;
    }
    d->dim = 2;
    d->col[0] = d->t.cols[cx];
    d->col[1] = d->t.cols[cy];
    return CLI_OK;
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
typedef int (*point_pred)(const ts_options *opt, double x, double f);

static int pred_negative(const ts_options *opt, double x, double f)
{
    (void)opt;
    (void)x;
    return !(f >= 0.0);
}
static int pred_not_above(const ts_options *opt, double x, double f)
{
    return !(f - (opt->lower.m * x + opt->lower.c) > 0.0);
}
static int pred_not_below(const ts_options *opt, double x, double f)
{
    return !((opt->upper.m * x + opt->upper.c) - f > 0.0);
}

static void list_points(char *buf, size_t len, const ts_options *opt, point_pred pred,
                        const double *x, const double *f, size_t n)
{
    size_t cnt = 0, used = 0;
    char b[TSU_FMT_SIZE];
    buf[0] = '\0';
    for (size_t i = 0; i < n; i++) {
        if (!pred(opt, x[i], f[i]))
            continue;
        int w;
        if (cnt == 12)
            w = snprintf(buf + used, len - used, ", ...");
        else if (cnt < 12)
            w = snprintf(buf + used, len - used, "%s%s", cnt ? ", " : "", cli_num(x[i], b));
        else
            w = 0;
        cnt++;
        if (w < 0 || (size_t)w >= len - used)
            return;
        used += (size_t)w;
    }
}

int cli_report_build_error(const cli_opts *o, const ts_options *opt, const char *name,
                           const double *x, const double *f,
                           const unsigned long long *lines, size_t n, const ts_error *e,
                           ts_status st, size_t off)
{
    char w[TSU_IO_MSG_SIZE], bx[TSU_FMT_SIZE], bf[TSU_FMT_SIZE], b2[TSU_FMT_SIZE];
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
                      w, off + i, cli_num(x[i], bx), cli_num(x[i - 1], b2), lines ? " (line " : "",
                      lines ? (snprintf(ln, sizeof ln, "%llu)", lines[i - 1]), ln) : "");
            return CLI_DATA;
        }
        break;
    case TS_ERR_NONFINITE:
        if (point) {
            cli_error("%s: point %zu (x = %s, f = %s): the step from the previous point, or a "
                      "slope there, overflows a double",
                      w, off + i, cli_num(x[i], bx), cli_num(f[i], bf));
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
            list_points(list, sizeof list, opt, pred_negative, x, f, n);
            cli_error("%s: point %zu (x = %s, f = %s) is negative; --shape positive needs f >= 0 "
                      "(negative at x = %s)",
                      w, off + i, cli_num(x[i], bx), cli_num(f[i], bf), list);
            return CLI_DATA;
        }
        break;
    case TS_ERR_SIDE:
        if (point) {
            int low = (opt->shape == TS_SHAPE_ABOVE || opt->shape == TS_SHAPE_BETWEEN) &&
                      pred_not_above(opt, x[i], f[i]);
            const ts_line *l = low ? &opt->lower : &opt->upper;
            cli_line_text(l, ln, sizeof ln);
            list_points(list, sizeof list, opt, low ? pred_not_above : pred_not_below, x, f, n);
            cli_error("%s: point %zu (x = %s, f = %s) is not %s the %s line %s; the data are on "
                      "or %s it at x = %s",
                      w, off + i, cli_num(x[i], bx), cli_num(f[i], bf), low ? "above" : "below",
                      low ? "lower" : "upper", ln, low ? "below" : "above", list);
            return CLI_DATA;
        }
        break;
    case TS_ERR_LINES:
        if (point) {
            char lo[160];
            cli_line_text(&opt->lower, lo, sizeof lo);
            cli_line_text(&opt->upper, ln, sizeof ln);
            cli_error("%s: at point %zu (x = %s) the lower line %s is not below the upper line %s",
                      w, off + i, cli_num(x[i], bx), lo, ln);
            return CLI_DATA;
        }
        break;
    case TS_ERR_NONMONOTONE:
        if (point) {
            cli_error("%s: point %zu (x = %s, f = %s): the data change direction here; --shape "
                      "monotone needs monotone data",
                      w, off + i, cli_num(x[i], bx), cli_num(f[i], bf));
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
                      ln, off + i, cli_num(x[i], bx), cli_num(x[i + 1], b2));
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
            cli_error("interval %zu [%s, %s]: alpha + beta = %s is below the geometric-form bound "
                      "%s; raise --alpha or --beta",
                      off + i, cli_num(x[i], bx), cli_num(x[i + 1], b2), cli_num(a, bf),
                      cli_num(TS_GEOMETRIC_A_MIN, ln));
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
        cli_error("%s: point %zu (x = %s): %s", w, off + i, cli_num(x[i], bx), ts_strerror(st));
    else if (interval)
        cli_error("%s: interval %zu [%s, %s]: %s", w, off + i, cli_num(x[i], bx),
                  cli_num(x[i + 1], b2), ts_strerror(st));
    else
        cli_error("%s: %s", name, ts_strerror(st));
    return CLI_DATA;
}

int cli_read_and_fit(const cli_opts *o, const ts_options *opt, cli_data *d, ts_spline **s)
{
    int rc;
    *s = NULL;
    if ((rc = cli_read_data(o, d)) != CLI_OK)
        return rc;
    ts_error e;
    ts_status st = ts_spline_new(d->col[0], d->col[1], d->n, opt, s, &e);
    if (st != TS_OK) {
        rc = cli_report_build_error(o, opt, d->name, d->col[0], d->col[1], d->line, d->n, &e, st, 0);
        cli_data_free(d);
        return rc;
    }
    return CLI_OK;
}
