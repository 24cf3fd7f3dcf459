/* The SVG plot of a spline (fit --svg, certify --svg). */
#include "cli.h"

#include <stdio.h>
#include <string.h>

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

int cli_spline_plot(const cli_opts *o, const char *name, const ts_spline *s, ts_shape shape,
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
        if (cli_sample(s, 0, n, 1, m, 0, cli_sink_xy, &curve) != 0)
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
