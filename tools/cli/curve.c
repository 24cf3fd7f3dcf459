/* trigspline curve: parametric curves (docs/method.md §7).  The JSON
 * report is curve_json.c, the plot curve_plot.c. */
#include "cli.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The library's sentence (ts_error_message), but for the failures where the
 * command's own words say more (too few points, --alphas, --closed). */
static int curve_error(const cli_opts *o, const cli_data *d, const ts_curve_options *co,
                       const double *pts, ts_status st, const ts_error *e)
{
    char w[TSU_IO_MSG_SIZE], msg[1024];
    size_t i = e->index;
    if (e->where == TS_WHERE_POINT && i < d->n && d->line)
        snprintf(w, sizeof w, "%s:%llu", d->name, d->line[i]);
    else
        snprintf(w, sizeof w, "%s", d->name);
    switch (st) {
    case TS_ERR_TOO_FEW:
        cli_error("%s: %zu point%s; a curve needs at least 2 (a closed curve 3 distinct points)",
                  d->name, d->n, d->n == 1 ? "" : "s");
        return CLI_DATA;
    case TS_ERR_LENGTH:
        cli_error("--alphas/--betas need exactly one value per segment");
        return CLI_USAGE;
    case TS_ERR_OPTION:
        if (o->slopes == TS_SLOPES_PERIODIC && !o->closed)
            return cli_usage(o->cmd, "--slopes periodic needs --closed");
        break;
    default:
        break;
    }
    ts_error_context ctx;
    ts_error_context_init(&ctx);
    ctx.points = pts;
    ctx.n_points = d->n;
    ctx.dim = d->dim;
    ctx.curve_options = co;
    ts_error err = *e;
    err.status = st;
    ts_error_message(&err, &ctx, msg, sizeof msg);
    switch (st) {
    case TS_ERR_INFEASIBLE:
        cli_error("%s: %s", d->name, msg);
        return CLI_INFEASIBLE;
    case TS_ERR_OPTION:
    case TS_ERR_ALPHA:
    case TS_ERR_BETA:
    case TS_ERR_MARGIN:
        cli_error("%s", msg);
        return CLI_USAGE;
    case TS_ERR_NOMEM:
    case TS_ERR_OVERFLOW:
        cli_error("%s", msg);
        return CLI_IO;
    default:
        cli_error("%s: %s", w, msg);
        return CLI_DATA;
    }
}

/* Read DATA and build the curve: CLI_OK, or the exit status (message
 * printed; d freed). */
static int curve_build(const cli_opts *o, const ts_curve_options *co, cli_data *d, ts_curve **c)
{
    int rc;
    *c = NULL;
    if ((rc = cli_read_data(o, d)) != CLI_OK)
        return rc;
    size_t dim = d->dim, n = d->n;
    if (o->box_set && o->n_box / 2 > dim) {
        cli_data_free(d);
        return cli_usage(o->cmd, "--box has 6 values but the data have 2 columns");
    }
    double *pts = malloc((n ? n : 1) * dim * sizeof *pts);
    if (!pts) {
        cli_data_free(d);
        return cli_nomem();
    }
    for (size_t i = 0; i < n; i++)
        for (size_t k = 0; k < dim; k++)
            pts[i * dim + k] = d->col[k][i];
    ts_error e;
    ts_status st = ts_curve_new(pts, n, dim, co, c, &e);
    if (st != TS_OK)
        rc = curve_error(o, d, co, pts, st, &e);
    free(pts);
    if (st != TS_OK) {
        cli_data_free(d);
        return rc;
    }
    return CLI_OK;
}

/* --samples m per segment into *smp (rows of t, x, y[, z]; owned), at most
 * CLI_MAX_HELD_SAMPLES rows.  CLI_OK or the exit status (message printed). */
static int curve_sample(const cli_data *d, const ts_curve *c, size_t m, double **smp,
                        size_t *rows)
{
    size_t dim = d->dim;
    *smp = NULL;
    *rows = 0;
    ts_status st = ts_curve_sample(c, m, NULL, 0, rows);
    if (st != TS_ERR_LENGTH && st != TS_OK)
        return cli_nomem();
    if (*rows > CLI_MAX_HELD_SAMPLES) {
        cli_error("%s: %zu sample points (--samples %zu over %zu segments) exceed the limit of %u "
                  "that curve holds in memory; lower --samples",
                  d->name, *rows, m, ts_curve_segments(c), CLI_MAX_HELD_SAMPLES);
        return CLI_USAGE;
    }
    if (*rows > ((size_t)-1) / sizeof(double) / (1 + dim) ||
        !(*smp = malloc(*rows * (1 + dim) * sizeof **smp)))
        return cli_nomem();
    if (ts_curve_sample(c, m, *smp, *rows * (1 + dim), rows) != TS_OK)
        return cli_nomem();
    return CLI_OK;
}

/* The box certificate (dim reports per segment into *reps, owned), its
 * least gap and verdict into cr.  CLI_OK or the exit status. */
static int curve_certify(const ts_curve *c, cli_curve_run *cr, ts_interval_report **reps)
{
    ts_error e;
    size_t n = cr->seg * cr->dim;
    *reps = calloc(n, sizeof **reps);
    if (!*reps)
        return cli_nomem();
    ts_interval_report_init(*reps, n);
    cr->certified = ts_curve_certify(c, *reps, &e) == TS_OK;
    for (size_t i = 0; i < n; i++) {
        const ts_interval_report *r = &(*reps)[i];
        if (r->has_lower && !(r->gap_lower >= cr->min_gap))
            cr->min_gap = r->gap_lower;
        if (r->has_upper && !(r->gap_upper >= cr->min_gap))
            cr->min_gap = r->gap_upper;
    }
    cr->reps = *reps;
    return CLI_OK;
}

/* The samples as CSV "t,x,y[,z]".  CLI_OK or the exit status. */
static int curve_csv(const cli_curve_run *cr, tsu_plot_buf *text)
{
    size_t dim = cr->dim;
    int bad = tsu_plot_buf_puts(text, dim == 3 ? "t,x,y,z\n" : "t,x,y\n") != TSU_PLOT_OK;
    char b[TSU_FMT_SIZE];
    for (size_t r = 0; r < cr->rows && !bad; r++) {
        for (size_t k = 0; k <= dim && !bad; k++) {
            bad |= tsu_plot_buf_puts(text, cli_num(cr->smp[r * (1 + dim) + k], b)) != TSU_PLOT_OK;
            bad |= tsu_plot_buf_puts(text, k < dim ? "," : "\n") != TSU_PLOT_OK;
        }
    }
    return bad ? cli_nomem() : CLI_OK;
}

int cli_curve(cli_opts *o)
{
    int rc;
    ts_curve_options co;
    if ((rc = cli_curve_options(o, &co)) != CLI_OK)
        return rc;
    cli_data d;
    ts_curve *c;
    if ((rc = curve_build(o, &co, &d, &c)) != CLI_OK)
        return rc;

    double *smp = NULL;
    ts_interval_report *reps = NULL;
    cli_json j;
    cli_json_init(&j);
    tsu_plot_buf svg = TSU_PLOT_BUF_INIT, text = TSU_PLOT_BUF_INIT;
    cli_curve_run cr = {c, &co, d.dim, d.n, ts_curve_segments(c), 0, NULL, NULL, 0,
                        (double)INFINITY};
    int has_box = 0;
    for (size_t k = 0; k < 3; k++)
        has_box |= co.has_lo[k] | co.has_hi[k];

    if ((rc = curve_sample(&d, c, o->samples, &smp, &cr.rows)) != CLI_OK)
        goto done;
    cr.smp = smp;
    if (has_box && (rc = curve_certify(c, &cr, &reps)) != CLI_OK)
        goto done;
    if (o->json) {
        cli_curve_json(&j, o, &cr);
        if (j.failed) {
            rc = cli_nomem();
            goto done;
        }
    } else if ((rc = curve_csv(&cr, &text)) != CLI_OK) {
        goto done;
    }
    if (o->svg && (rc = cli_curve_plot(o, &d, &cr, &svg)) != CLI_OK)
        goto done;
    rc = cli_write_outputs(o->out, o->json ? &j.b : &text, NULL, NULL, o->svg, o->plot_format,
                           &svg);
done:
    tsu_plot_buf_free(&svg);
    tsu_plot_buf_free(&text);
    cli_json_free(&j);
    free(reps);
    free(smp);
    ts_curve_free(c);
    cli_data_free(&d);
    return rc;
}
