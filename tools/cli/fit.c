/* trigspline fit, in memory (long CSV output streams: stream.c). */
#include "cli.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct csv_ctx {
    const cli_opts *o;
    const ts_spline *s;
    const cli_cols *cols;
    const char *name;
    const cli_step_grid *step;
} csv_ctx;

/* The samples fit writes: --samples per interval, or --samples-total / --grid
 * points evenly spaced.  Returns 0, an errno of the sink, or -1 (an
 * evaluation outside the data; message printed). */
static int fit_samples(const cli_opts *o, const ts_spline *s, const cli_cols *cols,
                       const cli_step_grid *step, cli_sink sink, void *ctx)
{
    size_t n = ts_spline_intervals(s);
    const double *X = ts_spline_x(s);
    if (!o->samples_total && !o->grid_set && !step)
        return cli_sample(s, 0, n, 1, o->samples, o->deriv, sink, ctx);
    ts_error e;
    double bad = 0;
    int rc = step          ? cli_sample_step(s, step, o->deriv, sink, ctx, &e, &bad)
             : o->grid_set ? cli_sample_even(s, o->grid_a, o->grid_b, o->grid_n, o->deriv, sink,
                                             ctx, &e, &bad)
                           : cli_sample_even(s, X[0], X[n], o->samples_total, o->deriv, sink, ctx,
                                             &e, &bad);
    if (rc == -1) {
        char bx[TSU_TIME_SIZE], b0[TSU_TIME_SIZE], b1[TSU_TIME_SIZE];
        cli_error("--grid: x = %s is outside the data range [%s, %s] (--extrapolate "
                  "clamp|extend|linear evaluates there)",
                  cli_x_text(cols, bad, bx), cli_x_text(cols, X[0], b0), cli_x_text(cols, X[n], b1));
    }
    return rc;
}

/* cli_writer_fn: the dense samples as CSV. */
static int write_dense_csv(void *ctx, FILE *fp)
{
    csv_ctx *c = ctx;
    tsu_plot_buf hb = TSU_PLOT_BUF_INIT;
    cli_csv_sink sk = {tsu_writer_new(fp, ','), c->cols};
    if (!sk.w)
        return ENOMEM;
    int rc = cli_header_line(c->cols, c->o->deriv, &hb) ? ENOMEM : 0;
    if (!rc)
        rc = tsu_writer_text(sk.w, hb.data, hb.len);
    tsu_plot_buf_free(&hb);
    if (!rc)
        rc = fit_samples(c->o, c->s, c->cols, c->step, cli_sink_writer, &sk);
    int rc2 = tsu_writer_free(sk.w);
    if (rc == -1)
        return ECANCELED; /* reported */
    return rc ? rc : rc2;
}

typedef struct at_vals {
    tsu_table t;
    const double *x;
    double *y;
    size_t m;
    const char *name;
} at_vals;

static int eval_at(const cli_opts *o, const ts_spline *s, const cli_cols *cols, at_vals *a)
{
    tsu_read_options ro;
    tsu_io_error ie;
    ts_error e;
    memset(a, 0, sizeof *a);
    a->name = "--at";
    if (o->at_list) {
        a->x = o->at_list;
        a->m = o->n_at;
    } else {
        cli_read_options(o, &ro);
        ro.skip = 0;
        ro.skip_after_header = 0;
        tsu_io_status st = tsu_read_table_path(o->at, &ro, &a->t, &ie);
        if (st != TSU_IO_OK)
            return cli_report_io(&ie);
        a->x = a->t.cols[0];
        a->m = a->t.nrows;
        a->name = strcmp(o->at, "-") == 0 ? "<stdin>" : o->at;
    }
    a->y = malloc((a->m ? a->m : 1) * sizeof *a->y);
    if (!a->y)
        return cli_nomem();
    ts_cursor cur = TS_CURSOR_INIT;
    ts_status es = ts_spline_eval_batch(s, o->deriv, a->x, a->m, a->y, &cur, &e);
    if (es != TS_OK) {
        size_t q = e.index < a->m ? e.index : 0;
        char bx[TSU_TIME_SIZE], b0[TSU_TIME_SIZE], b1[TSU_TIME_SIZE], ln[64] = "";
        const double *X = ts_spline_x(s);
        if (a->t.lines)
            snprintf(ln, sizeof ln, ":%llu", a->t.lines[q]);
        else
            snprintf(ln, sizeof ln, " value %zu", q + 1);
        cli_error("%s%s: x = %s is outside the data range [%s, %s] (--extrapolate "
                  "clamp|extend|linear evaluates there)",
                  a->name, ln, cli_x_text(cols, a->x[q], bx), cli_x_text(cols, X[0], b0),
                  cli_x_text(cols, X[ts_spline_intervals(s)], b1));
        return CLI_DATA;
    }
    return CLI_OK;
}

/* --step (and --grid A:B): the points, checked against the kind of x.
 * CLI_OK or CLI_USAGE (message printed). */
static int make_step(const cli_opts *o, const ts_spline *s, const cli_cols *cols,
                     cli_step_grid *g)
{
    const double *X = ts_spline_x(s);
    size_t n = ts_spline_intervals(s);
    double base = 0.0;
    if (cols->x_time && o->step_unit == 0.0)
        return cli_usage(o->cmd, "--step %s: x holds dates, give the step a unit s, min, h or d "
                                 "(1h, 15min)", o->step_text);
    if (!cols->x_time && o->step_unit != 0.0)
        return cli_usage(o->cmd, "--step %s: a unit applies to dates only, x holds numbers",
                         o->step_text);
    if (cols->x_time && cols->tform.zone == 2)
        base = -60.0 * cols->tform.offset_min; /* midnight in x's own offset */
    int rc = o->grid_set ? cli_step_grid_make(o->step_text, o->step_unit, o->grid_a, o->grid_b, 0,
                                              0.0, 100000000, g)
                         : cli_step_grid_make(o->step_text, o->step_unit, X[0], X[n], 1, base,
                                              100000000, g);
    if (rc != 0)
        return cli_usage(o->cmd, "--step %s: more than 100000000 points", o->step_text);
    if (g->n == 0) {
        char b0[TSU_TIME_SIZE], b1[TSU_TIME_SIZE];
        return cli_usage(o->cmd, "--step %s: no multiple of the step in [%s, %s]", o->step_text,
                         cli_x_text(cols, o->grid_set ? o->grid_a : X[0], b0),
                         cli_x_text(cols, o->grid_set ? o->grid_b : X[n], b1));
    }
    return CLI_OK;
}

static void at_free(at_vals *a)
{
    tsu_table_free(&a->t);
    free(a->y);
    memset(a, 0, sizeof *a);
}

int cli_fit(cli_opts *o)
{
    ts_spline_options opt;
    int rc = cli_fit_options(o, &opt);
    if (rc != CLI_OK)
        return rc;
    if (cli_can_stream(o))
        return cli_fit_stream(o, &opt);

    cli_data d;
    ts_spline *s = NULL;
    if ((rc = cli_read_and_fit(o, &opt, &d, &s)) != CLI_OK)
        return rc;
    ts_shape shape = ts_spline_shape(s);
    const ts_line *lower = NULL, *upper = NULL;
    ts_line zero = {0.0, 0.0};
    if (shape == TS_SHAPE_POSITIVE)
        lower = &zero;
    if (shape == TS_SHAPE_ABOVE || shape == TS_SHAPE_BETWEEN)
        lower = &opt.lower;
    if (shape == TS_SHAPE_BELOW || shape == TS_SHAPE_BETWEEN)
        upper = &opt.upper;

    at_vals at;
    memset(&at, 0, sizeof at);
    cli_json j;
    cli_json_init(&j);
    tsu_plot_buf svg = TSU_PLOT_BUF_INIT, text = TSU_PLOT_BUF_INIT;
    cli_stats smp = CLI_STATS_INIT;
    cli_step_grid step;
    csv_ctx cc = {o, s, &d.cols, d.name, o->step_set ? &step : NULL};
    cli_writer_fn fn = NULL;
    if (o->step_set && (rc = make_step(o, s, &d.cols, &step)) != CLI_OK)
        goto done;
    if (o->grid_set && opt.extrapolate == TS_EXTRAP_ERROR) {
        /* before anything is written: the grid inside the data */
        const double *X = ts_spline_x(s);
        size_t n = ts_spline_intervals(s);
        double lo = o->grid_a, hi = o->step_set ? cli_step_x(&step, step.j0 + (double)(step.n - 1))
                                                : o->grid_b;
        if (!(X[0] <= lo && hi <= X[n])) {
            char bx[TSU_TIME_SIZE], b0[TSU_TIME_SIZE], b1[TSU_TIME_SIZE];
            cli_error("--grid: x = %s is outside the data range [%s, %s] (--extrapolate "
                      "clamp|extend|linear evaluates there)",
                      cli_x_text(&d.cols, !(X[0] <= lo && lo <= X[n]) ? lo : hi, bx), cli_x_text(&d.cols, X[0], b0),
                      cli_x_text(&d.cols, X[n], b1));
            rc = CLI_DATA;
            goto done;
        }
    }
    if (o->svg || (o->json && o->with_samples)) {
        /* held in memory: a documented limit */
        size_t n = ts_spline_intervals(s);
        double pts = o->samples_total ? (double)o->samples_total
                     : o->step_set    ? (double)step.n
                     : o->grid_set    ? (double)o->grid_n
                                      : (double)n * (double)(o->samples - 1) + 1.0;
        if (pts > CLI_MAX_HELD_SAMPLES) {
            cli_error("%s: %.0f sample points (--samples %zu over %zu intervals) exceed the limit "
                      "of %u that a plot or --with-samples holds in memory; lower --samples (the "
                      "CSV output streams without a limit)",
                      d.name, pts, o->samples, n, CLI_MAX_HELD_SAMPLES);
            rc = CLI_USAGE;
            goto done;
        }
    }

    if (o->at && (rc = eval_at(o, s, &d.cols, &at)) != CLI_OK)
        goto done;
    if (o->json) {
        cli_xy held = {0};
        if (o->at) {
            cli_sink_stats(&smp, at.x, at.y, at.m);
            if (o->with_samples)
                cli_sink_xy(&held, at.x, at.y, at.m);
        } else {
            if (fit_samples(o, s, &d.cols, cc.step, cli_sink_stats, &smp) == -1 ||
                (o->with_samples && fit_samples(o, s, &d.cols, cc.step, cli_sink_xy, &held) != 0)) {
                rc = held.failed ? cli_nomem() : CLI_DATA;
                cli_xy_free(&held);
                goto done;
            }
        }
        cli_spline_json(&j, o, s, shape, lower, upper, ts_spline_certified(s), NULL, &smp, &d,
                        o->with_samples ? &held : NULL);
        cli_xy_free(&held);
        if (j.failed) {
            rc = cli_nomem();
            goto done;
        }
    } else if (o->at) {
        char bx[TSU_TIME_SIZE], by[TSU_FMT_SIZE];
        int bad = cli_header_line(&d.cols, o->deriv, &text) != 0;
        for (size_t q = 0; q < at.m && !bad; q++)
            bad = tsu_plot_buf_printf(&text, "%s,%s\n", cli_x_text(&d.cols, at.x[q], bx),
                                     cli_num(at.y[q], by)) != TSU_PLOT_OK;
        if (bad) {
            rc = cli_nomem();
            goto done;
        }
    } else {
        fn = write_dense_csv;
    }
    if (o->svg && (rc = cli_spline_plot(o, &d, s, shape, lower, upper, NULL, &svg)) != CLI_OK)
        goto done;
    rc = cli_write_outputs(o->out, o->json ? &j.b : &text, fn, &cc, o->svg, o->plot_format, &svg);
    if (rc == CLI_OK) {
        cli_overshoot ov;
        cli_overshoot_init(&ov);
        cli_overshoot_add(&ov, s, 0, ts_spline_intervals(s), 0);
        cli_overshoot_warn(&ov, &d.cols);
    }
done:
    cli_json_free(&j);
    tsu_plot_buf_free(&svg);
    tsu_plot_buf_free(&text);
    at_free(&at);
    ts_spline_free(s);
    cli_data_free(&d);
    return rc;
}
