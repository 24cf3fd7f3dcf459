/* trigspline fit, in memory (long CSV output streams: stream.c). */
#include "cli.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct csv_ctx {
    const ts_spline *s;
    size_t m;
    int deriv;
    tsu_writer *w;
} csv_ctx;

/* cli_writer_fn: the dense samples as CSV. */
static int write_dense_csv(void *ctx, FILE *fp)
{
    csv_ctx *c = ctx;
    c->w = tsu_writer_new(fp, ',');
    if (!c->w)
        return ENOMEM;
    int rc = tsu_writer_text(c->w, "x,y\n", 4);
    if (!rc)
        rc = cli_sample(c->s, 0, ts_spline_intervals(c->s), 1, c->m, c->deriv, cli_sink_writer,
                        c->w);
    int rc2 = tsu_writer_free(c->w);
    c->w = NULL;
    return rc ? rc : rc2;
}

typedef struct at_vals {
    tsu_table t;
    double *y;
    size_t m;
} at_vals;

static int eval_at(const cli_opts *o, const ts_spline *s, at_vals *a)
{
    tsu_read_options ro;
    tsu_io_error ie;
    ts_error e;
    memset(a, 0, sizeof *a);
    tsu_read_options_init(&ro);
    tsu_io_status st = tsu_read_table_path(o->at, &ro, &a->t, &ie);
    if (st != TSU_IO_OK)
        return cli_report_io(&ie);
    a->m = a->t.nrows;
    a->y = malloc((a->m ? a->m : 1) * sizeof *a->y);
    if (!a->y)
        return cli_nomem();
    ts_cursor cur = TS_CURSOR_INIT;
    ts_status es = ts_eval_batch(s, o->deriv, a->t.cols[0], a->m, a->y, &cur, &e);
    if (es != TS_OK) {
        size_t q = e.index < a->m ? e.index : 0;
        char bx[TSU_FMT_SIZE], b0[TSU_FMT_SIZE], b1[TSU_FMT_SIZE];
        const double *X = ts_spline_x(s);
        cli_error("%s:%llu: x = %s is outside the data range [%s, %s] (--extrapolate "
                  "clamp|extend|linear evaluates there)",
                  strcmp(o->at, "-") == 0 ? "<stdin>" : o->at, a->t.lines ? a->t.lines[q] : 0ULL,
                  cli_num(a->t.cols[0][q], bx), cli_num(X[0], b0),
                  cli_num(X[ts_spline_intervals(s)], b1));
        return CLI_DATA;
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
    ts_options opt;
    int rc = cli_fit_options(o, &opt);
    if (rc != CLI_OK)
        return rc;
    if (o->at && strcmp(o->at, "-") == 0 && strcmp(o->data, "-") == 0)
        return cli_usage(o->cmd, "DATA and --at cannot both be standard input");
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
    csv_ctx cc = {s, o->samples, o->deriv, NULL};
    cli_writer_fn fn = NULL;

    if (o->at && (rc = eval_at(o, s, &at)) != CLI_OK)
        goto done;
    if (o->json) {
        if (o->at)
            cli_sink_stats(&smp, at.t.cols[0], at.y, at.m);
        else
            cli_sample(s, 0, ts_spline_intervals(s), 1, o->samples, o->deriv, cli_sink_stats, &smp);
        cli_spline_json(&j, o, s, shape, lower, upper, ts_spline_certified(s), NULL, &smp);
        if (j.failed) {
            rc = cli_nomem();
            goto done;
        }
    } else if (o->at) {
        char bx[TSU_FMT_SIZE], by[TSU_FMT_SIZE];
        int bad = tsu_plot_buf_puts(&text, "x,y\n") != TSU_PLOT_OK;
        for (size_t q = 0; q < at.m && !bad; q++)
            bad = tsu_plot_buf_printf(&text, "%s,%s\n", cli_num(at.t.cols[0][q], bx),
                                     cli_num(at.y[q], by)) != TSU_PLOT_OK;
        if (bad) {
            rc = cli_nomem();
            goto done;
        }
    } else {
        fn = write_dense_csv;
    }
    if (o->svg && (rc = cli_spline_plot(o, d.name, s, shape, lower, upper, NULL, &svg)) != CLI_OK)
        goto done;
    rc = cli_write_outputs(o->out, o->json ? &j.b : &text, fn, &cc, o->svg, &svg);
    if (rc == CLI_OK) {
        cli_overshoot ov;
        cli_overshoot_init(&ov);
        cli_overshoot_add(&ov, s, 0, ts_spline_intervals(s), 0);
        cli_overshoot_warn(&ov);
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
