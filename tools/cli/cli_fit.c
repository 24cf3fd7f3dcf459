/* trigspline fit and trigspline certify (in memory; streaming: cli_stream.c). */
#include "cli.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- sampling ------------------------------------------------------------ */

#define CLI_BLOCK 512

int cli_sample(const ts_spline *s, size_t i0, size_t i1, int with_end, size_t m, int deriv,
               cli_sink sink, void *ctx)
{
    double xs[CLI_BLOCK], ys[CLI_BLOCK];
    const double *X = ts_spline_x(s);
    size_t k = 0;
    ts_cursor cur = TS_CURSOR_INIT;
    ts_error e;
    int rc;
    double den = (double)(m - 1);
    for (size_t i = i0; i <= i1; i++) {
        size_t cnt = i < i1 ? m - 1 : (with_end ? 1 : 0);
        double x0 = X[i], h = i < i1 ? X[i + 1] - X[i] : 0.0;
        for (size_t j = 0; j < cnt; j++) {
            double x = x0;
            if (j > 0) {
                /* inside the interval; rounding may reach (not pass) x_{i+1} */
                x = x0 + h * ((double)j / den);
                if (x > X[i + 1])
                    x = X[i + 1];
            }
            xs[k++] = x;
            if (k == CLI_BLOCK) {
                (void)ts_eval_batch(s, deriv, xs, k, ys, &cur, &e);
                if ((rc = sink(ctx, xs, ys, k)) != 0)
                    return rc;
                k = 0;
            }
        }
    }
    if (k) {
        (void)ts_eval_batch(s, deriv, xs, k, ys, &cur, &e);
        if ((rc = sink(ctx, xs, ys, k)) != 0)
            return rc;
    }
    return 0;
}

typedef struct stats {
    double lo, hi;
    unsigned long long count;
} stats;

static int stats_sink(void *ctx, const double *x, const double *y, size_t k)
{
    stats *st = ctx;
    (void)x;
    for (size_t j = 0; j < k; j++) {
        if (y[j] < st->lo)
            st->lo = y[j];
        if (y[j] > st->hi)
            st->hi = y[j];
    }
    st->count += k;
    return 0;
}

static int xy_sink(void *ctx, const double *x, const double *y, size_t k)
{
    cli_xy *a = ctx;
    for (size_t j = 0; j < k; j++)
        cli_xy_push(a, x[j], y[j]);
    return a->failed ? ENOMEM : 0;
}

typedef struct csv_ctx {
    const ts_spline *s;
    size_t m;
    int deriv;
    tsu_writer *w;
} csv_ctx;

static int writer_sink(void *ctx, const double *x, const double *y, size_t k)
{
    csv_ctx *c = ctx;
    int rc = 0;
    for (size_t j = 0; j < k && !rc; j++)
        rc = tsu_writer_xy(c->w, x[j], y[j]);
    return rc;
}

/* cli_writer_fn: the dense samples as CSV. */
static int write_dense_csv(void *ctx, FILE *fp)
{
    csv_ctx *c = ctx;
    c->w = tsu_writer_new(fp, ',');
    if (!c->w)
        return ENOMEM;
    int rc = tsu_writer_text(c->w, "x,y\n", 4);
    if (!rc)
        rc = cli_sample(c->s, 0, ts_spline_intervals(c->s), 1, c->m, c->deriv, writer_sink, c);
    int rc2 = tsu_writer_free(c->w);
    c->w = NULL;
    return rc ? rc : rc2;
}

/* ---- options -------------------------------------------------------------- */

/* Lines of a shape from --line / --lower / --upper (fit and certify). */
static int resolve_lines(const cli_opts *o, ts_shape *sh, ts_line *lo, int *has_lo, ts_line *up,
                         int *has_up)
{
    cli_cmd cmd = o->cmd;
    *has_lo = *has_up = 0;
    switch (*sh) {
    case TS_SHAPE_NONE:
        if (o->has_line)
            return cli_usage(cmd, "--line needs --shape above or --shape below (or use --lower "
                                  "/ --upper)");
        *has_lo = o->has_lower;
        *has_up = o->has_upper;
        *lo = o->lower;
        *up = o->upper;
        *sh = *has_lo && *has_up ? TS_SHAPE_BETWEEN
              : *has_lo          ? TS_SHAPE_ABOVE
              : *has_up          ? TS_SHAPE_BELOW
                                 : TS_SHAPE_NONE;
        return CLI_OK;
    case TS_SHAPE_POSITIVE:
    case TS_SHAPE_MONOTONE:
        if (o->has_line || o->has_lower || o->has_upper)
            return cli_usage(cmd, "--shape %s takes no --line, --lower or --upper",
                             cli_shape_name(*sh));
        if (*sh == TS_SHAPE_POSITIVE) {
            lo->m = lo->c = 0.0;
            *has_lo = 1;
        }
        return CLI_OK;
    case TS_SHAPE_ABOVE:
        if (o->has_upper)
            return cli_usage(cmd, "--shape above takes a lower line only (--upper given; use "
                                  "--shape between)");
        if (o->has_line && o->has_lower)
            return cli_usage(cmd, "give the line once: --line or --lower");
        if (!o->has_line && !o->has_lower)
            return cli_usage(cmd, "--shape above needs --line M,C");
        *lo = o->has_line ? o->line : o->lower;
        *has_lo = 1;
        return CLI_OK;
    case TS_SHAPE_BELOW:
        if (o->has_lower)
            return cli_usage(cmd, "--shape below takes an upper line only (--lower given; use "
                                  "--shape between)");
        if (o->has_line && o->has_upper)
            return cli_usage(cmd, "give the line once: --line or --upper");
        if (!o->has_line && !o->has_upper)
            return cli_usage(cmd, "--shape below needs --line M,C");
        *up = o->has_line ? o->line : o->upper;
        *has_up = 1;
        return CLI_OK;
    case TS_SHAPE_BETWEEN:
        if (o->has_line)
            return cli_usage(cmd, "--shape between takes --lower and --upper, not --line");
        if (!o->has_lower || !o->has_upper)
            return cli_usage(cmd, "--shape between needs both --lower M,C and --upper M,C");
        *lo = o->lower;
        *up = o->upper;
        *has_lo = *has_up = 1;
        return CLI_OK;
    }
    return CLI_OK;
}

/* Options of both commands that only make sense with others. */
static int check_output_opts(const cli_opts *o)
{
    if (!o->svg && (o->title || o->show_control || o->points_only))
        return cli_usage(o->cmd, "%s only applies to the plot (--svg FILE)",
                         o->title ? "--title" : o->show_control ? "--show-control" : "--points-only");
    if (o->show_control && o->points_only)
        return cli_usage(o->cmd, "--show-control and --points-only do not fit together");
    if (o->extrap_set && !o->at)
        return cli_usage(o->cmd, "--extrapolate only applies with --at FILE");
    return CLI_OK;
}

int cli_fit_options(const cli_opts *o, ts_options *opt)
{
    int rc;
    ts_options_init(opt);
    if ((rc = check_output_opts(o)) != CLI_OK)
        return rc;
    if (o->form_set)
        opt->form = o->form;
    opt->slopes = o->slopes;
    opt->alpha = o->alpha;
    opt->alphas = o->alphas;
    opt->n_alphas = o->n_alphas;
    opt->extrapolate = o->extrap_set ? o->extrap : TS_EXTRAP_ERROR;
    if (o->alpha_set && o->alphas)
        return cli_usage(o->cmd, "give --alpha or --alphas, not both");
    if (o->beta_set && o->betas)
        return cli_usage(o->cmd, "give --beta or --betas, not both");

    ts_shape sh = o->shape_set ? o->shape : TS_SHAPE_NONE;
    int hl, hu;
    if (o->cmd == CLI_CERTIFY) {
        if (sh == TS_SHAPE_MONOTONE)
            return cli_usage(o->cmd, "certify checks boundaries: --shape positive, above, below "
                                     "or between (or --lower / --upper)");
        if ((rc = resolve_lines(o, &sh, &opt->lower, &hl, &opt->upper, &hu)) != CLI_OK)
            return rc;
        if (!hl && !hu)
            return cli_usage(o->cmd, "certify needs a boundary: --shape positive, --lower M,C, "
                                     "--upper M,C, or --shape above|below --line M,C");
        if (!o->alpha_set && !o->alphas)
            return cli_usage(o->cmd, "certify needs your --alpha A (or --alphas)");
        if (!o->beta_set && !o->betas)
            return cli_usage(o->cmd, "certify needs your --beta B (or --betas)");
        /* the spline itself is built without a scheme */
        opt->shape = TS_SHAPE_NONE;
        opt->beta = o->beta;
        opt->betas = o->betas;
        opt->n_betas = o->n_betas;
        /* the boundaries themselves: certify_bounds */
        opt->lower.m = opt->lower.c = opt->upper.m = opt->upper.c = 0.0;
        return CLI_OK;
    }
    if ((rc = resolve_lines(o, &sh, &opt->lower, &hl, &opt->upper, &hu)) != CLI_OK)
        return rc;
    if (sh != TS_SHAPE_NONE && (o->beta_set || o->betas))
        return cli_usage(o->cmd, "--beta/--betas only with --shape none: the %s scheme computes "
                                 "beta (use --alpha, --margin)",
                         cli_shape_name(sh));
    if (sh == TS_SHAPE_NONE && o->margin_set)
        return cli_usage(o->cmd, "--margin only applies to a shape scheme (--shape ...)");
    opt->shape = sh;
    opt->margin = o->margin;
    opt->beta = o->beta;
    opt->betas = o->betas;
    opt->n_betas = o->n_betas;
    return CLI_OK;
}

/* The boundaries certify checks (after cli_fit_options succeeded). */
static void certify_bounds(const cli_opts *o, ts_shape *sh, ts_line *lo, int *hl, ts_line *up,
                           int *hu)
{
    *sh = o->shape_set ? o->shape : TS_SHAPE_NONE;
    (void)resolve_lines(o, sh, lo, hl, up, hu);
}

/* ---- JSON report ------------------------------------------------------------ */

static void json_report(cli_json *j, const cli_opts *o, const ts_spline *s, ts_shape shape,
                        const ts_line *lower, const ts_line *upper, int certified,
                        const ts_interval_report *reps, const stats *smp)
{
    size_t n = ts_spline_intervals(s);
    const double *x = ts_spline_x(s), *f = ts_spline_f(s), *d = ts_spline_slopes(s);
    ts_interval_report r;
    double gl = INFINITY, gu = INFINITY;

    for (size_t i = 0; i < n; i++) {
        if (reps)
            r = reps[i];
        else
            (void)ts_spline_report(s, i, &r);
        if (lower && !(r.gap_lower >= gl))
            gl = r.gap_lower;
        if (upper && !(r.gap_upper >= gu))
            gu = r.gap_upper;
    }
    cli_json_begin(j, '{');
    cli_json_kstr(j, "command", cli_cmd_name(o->cmd));
    cli_json_kstr(j, "form", cli_form_name(ts_spline_form(s)));
    cli_json_kstr(j, "shape", cli_shape_name(shape));
    cli_json_kstr(j, "slopes", cli_slopes_name(o->slopes));
    cli_json_kuint(j, "n_points", n + 1);
    cli_json_kuint(j, "n_intervals", n);
    cli_json_kline(j, "lower", lower);
    cli_json_kline(j, "upper", upper);
    cli_json_kbool(j, "certified", certified);
    cli_json_key(j, "min_gap_lower");
    if (lower)
        cli_json_num(j, gl);
    else
        cli_json_null(j);
    cli_json_key(j, "min_gap_upper");
    if (upper)
        cli_json_num(j, gu);
    else
        cli_json_null(j);
    cli_json_nl(j);

    cli_json_key(j, "knots");
    cli_json_begin(j, '[');
    for (size_t i = 0; i <= n; i++) {
        cli_json_nl(j);
        cli_json_begin(j, '{');
        cli_json_knum(j, "x", x[i]);
        cli_json_knum(j, "f", f[i]);
        cli_json_knum(j, "d", d[i]);
        cli_json_end(j, '}');
    }
    cli_json_end(j, ']');
    cli_json_nl(j);

    cli_json_key(j, "intervals");
    cli_json_begin(j, '[');
    for (size_t i = 0; i < n; i++) {
        double B[4], X[4];
        if (reps)
            r = reps[i];
        else
            (void)ts_spline_report(s, i, &r);
        (void)ts_spline_control(s, i, B, X);
        cli_json_nl(j);
        cli_json_begin(j, '{');
        cli_json_kuint(j, "i", i);
        cli_json_knum(j, "x0", r.x0);
        cli_json_knum(j, "x1", r.x1);
        cli_json_knum(j, "alpha", r.alpha);
        cli_json_knum(j, "beta", r.beta);
        cli_json_knum(j, "a", r.a);
        cli_json_kstr(j, "term", cli_term_name(r.term));
        cli_json_key(j, "B");
        cli_json_begin(j, '[');
        for (int l = 0; l < 4; l++)
            cli_json_num(j, B[l]);
        cli_json_end(j, ']');
        cli_json_key(j, "X");
        cli_json_begin(j, '[');
        for (int l = 0; l < 4; l++)
            cli_json_num(j, X[l]);
        cli_json_end(j, ']');
        cli_json_key(j, "gap_lower");
        if (r.has_lower)
            cli_json_num(j, r.gap_lower);
        else
            cli_json_null(j);
        cli_json_key(j, "at_lower");
        if (r.has_lower)
            cli_json_num(j, r.at_lower);
        else
            cli_json_null(j);
        cli_json_key(j, "gap_upper");
        if (r.has_upper)
            cli_json_num(j, r.gap_upper);
        else
            cli_json_null(j);
        cli_json_key(j, "at_upper");
        if (r.has_upper)
            cli_json_num(j, r.at_upper);
        else
            cli_json_null(j);
        cli_json_kbool(j, "certified", r.certified);
        cli_json_end(j, '}');
    }
    cli_json_end(j, ']');
    cli_json_nl(j);

    cli_json_key(j, "samples");
    cli_json_begin(j, '{');
    cli_json_key(j, "min_y");
    if (smp->count)
        cli_json_num(j, smp->lo);
    else
        cli_json_null(j);
    cli_json_key(j, "max_y");
    if (smp->count)
        cli_json_num(j, smp->hi);
    else
        cli_json_null(j);
    cli_json_kuint(j, "count", smp->count);
    cli_json_end(j, '}');
    cli_json_end(j, '}');
    cli_json_raw(j, "\n");
}

/* ---- plot ------------------------------------------------------------------- */

#define COL_DATA "#000000"
#define COL_CURVE "#0072b2"
#define COL_BOUND "#d55e00"
#define COL_BOUND2 "#e69f00"
#define COL_CTRL "#009e73"
#define COL_BAD "#cc79a7"

static tsu_plot_status plot_add_bound(tsu_plot *p, const ts_line *l, int lower)
{
    char txt[200], lab[240];
    tsu_plot_style st;
    memset(&st, 0, sizeof st);
    st.color = lower ? COL_BOUND : COL_BOUND2;
    cli_line_text(l, txt, sizeof txt);
    snprintf(lab, sizeof lab, "%s %s", lower ? (l->m == 0.0 ? "floor" : "lower line")
                                             : (l->m == 0.0 ? "ceiling" : "upper line"),
             txt);
    if (l->m == 0.0)
        return lower ? tsu_plot_add_floor(p, l->c, lab, &st) : tsu_plot_add_ceiling(p, l->c, lab, &st);
    return tsu_plot_add_region(p, lower ? TSU_PLOT_FORBID_BELOW : TSU_PLOT_FORBID_ABOVE, l->m, l->c,
                              lab, &st);
}

static char *default_title(const cli_opts *o, const char *name, ts_shape shape, char *buf,
                           size_t len)
{
    const char *base = strrchr(name, '/');
    base = base ? base + 1 : name;
    char a[TSU_FMT_SIZE], b[TSU_FMT_SIZE];
    if (o->cmd == CLI_CERTIFY || shape == TS_SHAPE_NONE) {
        snprintf(buf, len, "%s: %s, alpha = %s, beta = %s", base,
                 o->cmd == CLI_CERTIFY ? "certify" : "fit",
                 o->alphas ? "per interval" : cli_num(o->alpha, a),
                 o->betas ? "per interval" : cli_num(o->beta, b));
    } else {
        snprintf(buf, len, "%s: %s scheme, alpha = %s", base, cli_shape_name(shape),
                 o->alphas ? "per interval" : cli_num(o->alpha, a));
    }
    return buf;
}

/* Render the plot of a spline to svg.  bad: points to mark (may be empty). */
static int plot_spline(const cli_opts *o, const char *name, const ts_spline *s, ts_shape shape,
                       const ts_line *lower, const ts_line *upper, const cli_xy *bad,
                       tsu_plot_buf *svg)
{
    tsu_plot *p = NULL;
    tsu_plot_status ps = tsu_plot_new(0, 0, &p);
    cli_xy curve = {0}, ctl = {0};
    char title[512];
    tsu_plot_style st;
    size_t n = ts_spline_intervals(s);
    int rc = CLI_OK;

    if (ps != TSU_PLOT_OK)
        return cli_nomem();
    ps = tsu_plot_set_title(p, o->title ? o->title : default_title(o, name, shape, title, sizeof title));
    if (ps == TSU_PLOT_OK)
        ps = tsu_plot_set_labels(p, "x", "y");
    if (ps == TSU_PLOT_OK && lower)
        ps = plot_add_bound(p, lower, 1);
    if (ps == TSU_PLOT_OK && upper)
        ps = plot_add_bound(p, upper, 0);
    if (ps == TSU_PLOT_OK && !o->points_only) {
        size_t m = o->samples;
        if (cli_sample(s, 0, n, 1, m, 0, xy_sink, &curve) != 0)
            ps = TSU_PLOT_ERR_NOMEM;
        memset(&st, 0, sizeof st);
        st.color = COL_CURVE;
        if (ps == TSU_PLOT_OK)
            ps = tsu_plot_add_polyline(p, curve.x, curve.y, curve.n, "spline", &st);
        if (ps == TSU_PLOT_OK && o->show_control) {
            for (size_t i = 0; i < n; i++) {
                double B[4], X[4];
                (void)ts_spline_control(s, i, B, X);
                for (int l = i ? 1 : 0; l < 4; l++)
                    cli_xy_push(&ctl, X[l], B[l]);
            }
            if (ctl.failed)
                ps = TSU_PLOT_ERR_NOMEM;
            memset(&st, 0, sizeof st);
            st.color = COL_CTRL;
            if (ps == TSU_PLOT_OK)
                ps = tsu_plot_add_polygon(p, ctl.x, ctl.y, ctl.n, "control polygon", &st);
        }
    }
    memset(&st, 0, sizeof st);
    st.color = COL_DATA;
    if (ps == TSU_PLOT_OK)
        ps = tsu_plot_add_points(p, ts_spline_x(s), ts_spline_f(s), n + 1, "data", &st);
    if (ps == TSU_PLOT_OK && bad && bad->n && !o->points_only) {
        memset(&st, 0, sizeof st);
        st.color = COL_BAD;
        st.marker_radius = 5.0;
        ps = tsu_plot_add_points(p, bad->x, bad->y, bad->n, "least gap (violated)", &st);
    }
    if (ps == TSU_PLOT_OK)
        ps = tsu_plot_render(p, svg);
    if (ps != TSU_PLOT_OK) {
        cli_error("plot: %s", tsu_plot_strerror(ps));
        rc = CLI_IO;
    }
    cli_xy_free(&curve);
    cli_xy_free(&ctl);
    tsu_plot_free(p);
    return rc;
}

/* ---- --at ------------------------------------------------------------------- */

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

/* ---- commands --------------------------------------------------------------- */

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
    if ((rc = cli_read_data(o, &d)) != CLI_OK)
        return rc;
    ts_spline *s = NULL;
    ts_error e;
    ts_status st = ts_spline_new(d.col[0], d.col[1], d.n, &opt, &s, &e);
    if (st != TS_OK) {
        rc = cli_report_build_error(o, &opt, d.name, d.col[0], d.col[1], d.line, d.n, &e, st, 0);
        cli_data_free(&d);
        return rc;
    }
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
    stats smp = {INFINITY, -INFINITY, 0};
    csv_ctx cc = {s, o->samples, o->deriv, NULL};
    cli_writer_fn fn = NULL;

    if (o->at && (rc = eval_at(o, s, &at)) != CLI_OK)
        goto done;
    if (o->json) {
        if (o->at)
            stats_sink(&smp, at.t.cols[0], at.y, at.m);
        else
            cli_sample(s, 0, ts_spline_intervals(s), 1, o->samples, o->deriv, stats_sink, &smp);
        json_report(&j, o, s, shape, lower, upper, ts_spline_certified(s), NULL, &smp);
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
    if (o->svg && (rc = plot_spline(o, d.name, s, shape, lower, upper, NULL, &svg)) != CLI_OK)
        goto done;
    rc = cli_write_outputs(o->out, o->json ? &j.b : &text, fn, &cc, o->svg, &svg);
done:
    cli_json_free(&j);
    tsu_plot_buf_free(&svg);
    tsu_plot_buf_free(&text);
    at_free(&at);
    ts_spline_free(s);
    cli_data_free(&d);
    return rc;
}

/* Text report of certify. */
static int certify_text(tsu_plot_buf *b, const cli_opts *o, const char *name, const ts_spline *s,
                        const ts_line *lower, const ts_line *upper,
                        const ts_interval_report *reps, int certified)
{
    size_t n = ts_spline_intervals(s), bad = 0;
    char t1[200], t2[200];
    char v[8][TSU_FMT_SIZE];
    int ok = 1;
    if (lower)
        cli_line_text(lower, t1, sizeof t1);
    if (upper)
        cli_line_text(upper, t2, sizeof t2);
    ok &= tsu_plot_buf_printf(b, "# trigspline certify %s: %zu intervals, form %s, slopes %s%s%s%s%s\n",
                             name, n, cli_form_name(ts_spline_form(s)), cli_slopes_name(o->slopes),
                             lower ? ", lower " : "", lower ? t1 : "", upper ? ", upper " : "",
                             upper ? t2 : "") == TSU_PLOT_OK;
    ok &= tsu_plot_buf_puts(b, "interval x0 x1 alpha beta gap_lower at_lower gap_upper at_upper "
                              "certified\n") == TSU_PLOT_OK;
    for (size_t i = 0; i < n && ok; i++) {
        const ts_interval_report *r = &reps[i];
        bad += !r->certified;
        ok &= tsu_plot_buf_printf(
                  b, "%zu %s %s %s %s %s %s %s %s %s\n", i, cli_num(r->x0, v[0]),
                  cli_num(r->x1, v[1]), cli_num(r->alpha, v[2]), cli_num(r->beta, v[3]),
                  r->has_lower ? cli_num(r->gap_lower, v[4]) : "-",
                  r->has_lower ? cli_num(r->at_lower, v[5]) : "-",
                  r->has_upper ? cli_num(r->gap_upper, v[6]) : "-",
                  r->has_upper ? cli_num(r->at_upper, v[7]) : "-",
                  r->certified ? "yes" : "NO") == TSU_PLOT_OK;
    }
    if (ok) {
        if (certified)
            ok &= tsu_plot_buf_puts(b, "# certified: yes\n") == TSU_PLOT_OK;
        else
            ok &= tsu_plot_buf_printf(b, "# certified: no (%zu of %zu intervals leave the region)\n",
                                     bad, n) == TSU_PLOT_OK;
    }
    return ok ? CLI_OK : cli_nomem();
}

int cli_certify(cli_opts *o)
{
    ts_options opt;
    int rc = cli_fit_options(o, &opt);
    if (rc != CLI_OK)
        return rc;
    ts_shape shape;
    ts_line lo, up;
    int hl, hu;
    certify_bounds(o, &shape, &lo, &hl, &up, &hu);
    const ts_line *lower = hl ? &lo : NULL, *upper = hu ? &up : NULL;

    cli_data d;
    if ((rc = cli_read_data(o, &d)) != CLI_OK)
        return rc;
    ts_spline *s = NULL;
    ts_error e;
    ts_status st = ts_spline_new(d.col[0], d.col[1], d.n, &opt, &s, &e);
    if (st != TS_OK) {
        rc = cli_report_build_error(o, &opt, d.name, d.col[0], d.col[1], d.line, d.n, &e, st, 0);
        cli_data_free(&d);
        return rc;
    }
    size_t n = ts_spline_intervals(s);
    ts_interval_report *reps = calloc(n, sizeof *reps);
    cli_json j;
    cli_json_init(&j);
    tsu_plot_buf svg = TSU_PLOT_BUF_INIT, text = TSU_PLOT_BUF_INIT;
    cli_xy bad = {0};
    stats smp = {INFINITY, -INFINITY, 0};
    int certified = 0;
    if (!reps) {
        rc = cli_nomem();
        goto done;
    }
    st = ts_certify(s, lower, upper, reps, &e);
    if (st != TS_OK && st != TS_ERR_VIOLATED) {
        cli_error("certify: %s", ts_strerror(st));
        rc = st == TS_ERR_NONFINITE ? CLI_USAGE : CLI_DATA;
        goto done;
    }
    certified = st == TS_OK;
    for (size_t i = 0; i < n; i++) {
        const ts_interval_report *r = &reps[i];
        if (r->certified)
            continue;
        double at = r->has_lower && !(r->gap_lower > 0.0) ? r->at_lower : r->at_upper;
        double y;
        if (!isfinite(at) || ts_eval(s, at, NULL, &y) != TS_OK)
            continue;
        cli_xy_push(&bad, at, y);
    }
    if (o->json) {
        cli_sample(s, 0, n, 1, o->samples, 0, stats_sink, &smp);
        json_report(&j, o, s, shape, lower, upper, certified, reps, &smp);
        if (j.failed) {
            rc = cli_nomem();
            goto done;
        }
    } else if ((rc = certify_text(&text, o, d.name, s, lower, upper, reps, certified)) != CLI_OK) {
        goto done;
    }
    if (o->svg && (rc = plot_spline(o, d.name, s, shape, lower, upper, &bad, &svg)) != CLI_OK)
        goto done;
    rc = cli_write_outputs(o->out, o->json ? &j.b : &text, NULL, NULL, o->svg, &svg);
    if (rc == CLI_OK && !certified) {
        size_t cnt = 0;
        for (size_t i = 0; i < n; i++)
            cnt += !reps[i].certified;
        cli_error("certificate violated on %zu of %zu intervals:", cnt, n);
        for (size_t i = 0; i < n; i++) {
            const ts_interval_report *r = &reps[i];
            char b[6][TSU_FMT_SIZE];
            if (r->certified)
                continue;
            fprintf(stderr, "  interval %zu [%s, %s] (lines %llu-%llu):", i, cli_num(r->x0, b[0]),
                    cli_num(r->x1, b[1]), d.line ? d.line[i] : 0ULL, d.line ? d.line[i + 1] : 0ULL);
            if (r->has_lower && !(r->gap_lower > 0.0))
                fprintf(stderr, " min gap above the lower boundary %s at x = %s;",
                        cli_num(r->gap_lower, b[2]), cli_num(r->at_lower, b[3]));
            if (r->has_upper && !(r->gap_upper > 0.0))
                fprintf(stderr, " min gap below the upper boundary %s at x = %s;",
                        cli_num(r->gap_upper, b[4]), cli_num(r->at_upper, b[5]));
            if ((!r->has_lower || r->gap_lower > 0.0) && (!r->has_upper || r->gap_upper > 0.0))
                fprintf(stderr, " gap within rounding of zero;");
            fputc('\n', stderr);
        }
        rc = CLI_VIOLATED;
    }
done:
    free(reps);
    cli_xy_free(&bad);
    cli_json_free(&j);
    tsu_plot_buf_free(&svg);
    tsu_plot_buf_free(&text);
    ts_spline_free(s);
    cli_data_free(&d);
    return rc;
}
