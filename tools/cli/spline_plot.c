/* The SVG plot of a spline (fit --svg, certify --svg). */
#include "cli.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define COL_DATA "#000000"
#define COL_CURVE "#0072b2"
#define COL_BOUND "#d55e00"
#define COL_BOUND2 "#e69f00"
#define COL_CTRL "#009e73"
#define COL_BAD "#cc79a7"

/* y as plotted: log10 y with --logy (NaN where y <= 0: not drawn) */
static double ploty(const cli_opts *o, double y)
{
    return o->logy ? (y > 0.0 ? log10(y) : (double)NAN) : y;
}

static tsu_plot_status plot_add_bound(const cli_opts *o, tsu_plot *p, const ts_line *l, int lower,
                                      double x0, double x1)
{
    char txt[200], lab[240];
    tsu_plot_style st;
    memset(&st, 0, sizeof st);
    st.color = lower ? COL_BOUND : COL_BOUND2;
    cli_line_text(l, txt, sizeof txt);
    snprintf(lab, sizeof lab, "%s %s", lower ? (l->m == 0.0 ? "floor" : "lower line")
                                             : (l->m == 0.0 ? "ceiling" : "upper line"),
             txt);
    if (o->logy) {
        /* the line is a curve on a log axis: drawn where it is positive */
        enum { K = 200 };
        double xs[K], ys[K];
        for (int k = 0; k < K; k++) {
            xs[k] = x0 + (x1 - x0) * k / (K - 1);
            ys[k] = ploty(o, l->m * xs[k] + l->c);
        }
        st.dash = 1;
        return tsu_plot_add_polyline(p, xs, ys, K, lab, &st);
    }
    if (l->m == 0.0)
        return lower ? tsu_plot_add_floor(p, l->c, lab, &st) : tsu_plot_add_ceiling(p, l->c, lab, &st);
    return tsu_plot_add_region(p, lower ? TSU_PLOT_FORBID_BELOW : TSU_PLOT_FORBID_ABOVE, l->m, l->c,
                              lab, &st);
}

tsu_plot_status cli_plot_axes(const cli_opts *o, tsu_plot *p, const cli_cols *c, const char *xdef,
                              const char *ydef)
{
    char ylab[300];
    const char *yl = o->ylabel ? o->ylabel : c ? c->yname : ydef;
    if (!o->ylabel && o->logy) {
        snprintf(ylab, sizeof ylab, "%s (log scale)", yl);
        yl = ylab;
    }
    tsu_plot_status ps = tsu_plot_set_labels(p, o->xlabel ? o->xlabel : c ? c->xname : xdef, yl);
    if (ps == TSU_PLOT_OK && c && c->x_time)
        ps = tsu_plot_set_tick_fn(p, 0, cli_time_ticks, (void *)&c->tform);
    if (ps == TSU_PLOT_OK && o->logy)
        ps = tsu_plot_set_tick_fn(p, 1, cli_log_ticks, NULL);
    return ps;
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

int cli_spline_plot(const cli_opts *o, const cli_data *d, const ts_spline *s, ts_shape shape,
                    const ts_line *lower, const ts_line *upper, cli_xy *bad,
                    tsu_plot_buf *svg)
{
    const char *name = d->name;
    tsu_plot *p = NULL;
    const double *X = ts_spline_x(s), *F = ts_spline_f(s);
    if (o->logy)
        for (size_t i = 0; i <= ts_spline_intervals(s); i++)
            if (!(F[i] > 0.0)) {
                char bf[TSU_FMT_SIZE], bx[TSU_TIME_SIZE];
                cli_error("%s:%llu: --logy: f = %s at x = %s is not positive; a log axis cannot "
                          "show it", name, d->line ? d->line[i] : 0ULL, cli_num(F[i], bf),
                          cli_x_text(&d->cols, X[i], bx));
                return CLI_DATA;
            }
    tsu_plot_status ps = tsu_plot_new(o->width, o->height, &p);
    cli_xy pts = {0};
    cli_xy curve = {0}, ctl = {0};
    char title[512];
    tsu_plot_style st;
    size_t n = ts_spline_intervals(s);
    int rc = CLI_OK;

    if (ps != TSU_PLOT_OK)
        return cli_nomem();
    ps = tsu_plot_set_title(p, o->title ? o->title : default_title(o, name, shape, title, sizeof title));
    if (ps == TSU_PLOT_OK)
        ps = cli_plot_axes(o, p, &d->cols, "x", "y");
    if (ps == TSU_PLOT_OK && lower && !(o->logy && lower->m == 0.0 && lower->c <= 0.0))
        ps = plot_add_bound(o, p, lower, 1, X[0], X[n]);
    if (ps == TSU_PLOT_OK && upper)
        ps = plot_add_bound(o, p, upper, 0, X[0], X[n]);
    if (ps == TSU_PLOT_OK && !o->points_only) {
        size_t m = o->samples;
        if (cli_sample(s, 0, n, 1, m, 0, cli_sink_xy, &curve) != 0)
            ps = TSU_PLOT_ERR_NOMEM;
        for (size_t k = 0; k < curve.n; k++)
            curve.y[k] = ploty(o, curve.y[k]);
        memset(&st, 0, sizeof st);
        st.color = COL_CURVE;
        if (ps == TSU_PLOT_OK)
            ps = tsu_plot_add_polyline(p, curve.x, curve.y, curve.n, "spline", &st);
        if (ps == TSU_PLOT_OK && o->show_control) {
            for (size_t i = 0; i < n; i++) {
                double B[4], Xc[4];
                (void)ts_spline_control(s, i, B, Xc);
                for (int l = i ? 1 : 0; l < 4; l++)
                    cli_xy_push(&ctl, Xc[l], ploty(o, B[l]));
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
    for (size_t i = 0; i <= n; i++)
        cli_xy_push(&pts, X[i], ploty(o, F[i]));
    if (ps == TSU_PLOT_OK && pts.failed)
        ps = TSU_PLOT_ERR_NOMEM;
    if (ps == TSU_PLOT_OK)
        ps = tsu_plot_add_points(p, pts.x, pts.y, pts.n, "data", &st);
    if (ps == TSU_PLOT_OK && bad && bad->n && !o->points_only) {
        memset(&st, 0, sizeof st);
        st.color = COL_BAD;
        st.marker_radius = 5.0;
        for (size_t k = 0; k < bad->n; k++)
            bad->y[k] = ploty(o, bad->y[k]);
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
    cli_xy_free(&pts);
    tsu_plot_free(p);
    return rc;
}
