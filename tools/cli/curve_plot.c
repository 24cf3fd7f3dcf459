/* The SVG plot of a parametric curve (curve --svg): the curve in equal
 * axes (x-y projection of 3-D data), its box, control polygon and data. */
#include "cli.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static void box_line(cli_xy *a, double x0, double y0, double x1, double y1)
{
    cli_xy_push(a, x0, y0);
    cli_xy_push(a, x1, y1);
}

int cli_curve_plot(const cli_opts *o, const cli_data *d, const cli_curve_run *cr,
                   tsu_plot_buf *svg)
{
    int rc = CLI_OK;
    tsu_plot *p = NULL;
    cli_xy cx = {0}, ctl = {0}, bx = {0};
    char title[512], ab[TSU_FMT_SIZE], bb[TSU_FMT_SIZE];
    tsu_plot_style sty;
    const char *base = strrchr(d->name, '/');
    base = base ? base + 1 : d->name;
    snprintf(title, sizeof title, "%s: %s curve, alpha = %s, beta = %s%s", base,
             o->closed ? "closed" : "open", o->alphas ? "per segment" : cli_num(o->alpha, ab),
             o->betas ? "per segment" : cli_num(o->beta, bb),
             cr->dim == 3 ? " (x-y projection)" : "");
    tsu_plot_status ps = tsu_plot_new(o->width, o->height, &p);
    if (ps == TSU_PLOT_OK)
        ps = tsu_plot_set_title(p, o->title ? o->title : title);
    if (ps == TSU_PLOT_OK)
        ps = cli_plot_axes(o, p, NULL, "x", "y");
    if (ps == TSU_PLOT_OK)
        ps = tsu_plot_set_equal_aspect(p, 1);
    /* box: shaded floor / ceiling in y, dashed lines at the x bounds */
    if (ps == TSU_PLOT_OK && cr->reps) {
        double ylo = (double)INFINITY, yhi = -(double)INFINITY;
        for (size_t r = 0; r < cr->rows; r++) {
            double v = cr->smp[r * (1 + cr->dim) + 2];
            ylo = v < ylo ? v : ylo;
            yhi = v > yhi ? v : yhi;
        }
        if (cr->co->has_lo[1])
            ylo = cr->co->lo[1] < ylo ? cr->co->lo[1] : ylo;
        if (cr->co->has_hi[1])
            yhi = cr->co->hi[1] > yhi ? cr->co->hi[1] : yhi;
        double pad = 0.1 * (yhi - ylo) + 1e-9;
        memset(&sty, 0, sizeof sty);
        sty.color = "#d55e00";
        if (cr->co->has_lo[1])
            ps = tsu_plot_add_floor(p, cr->co->lo[1], "box", &sty);
        if (ps == TSU_PLOT_OK && cr->co->has_hi[1])
            ps = tsu_plot_add_ceiling(p, cr->co->hi[1], cr->co->has_lo[1] ? NULL : "box", &sty);
        for (int s2 = 0; s2 < 2 && ps == TSU_PLOT_OK; s2++) {
            int on = s2 ? cr->co->has_hi[0] : cr->co->has_lo[0];
            if (!on)
                continue;
            double xb = s2 ? cr->co->hi[0] : cr->co->lo[0];
            bx.n = 0;
            box_line(&bx, xb, ylo - pad, xb, yhi + pad);
            sty.dash = 1;
            const char *label = cr->co->has_lo[1] || cr->co->has_hi[1] || s2 ? NULL : "box";
            ps = bx.failed ? TSU_PLOT_ERR_NOMEM
                           : tsu_plot_add_polyline(p, bx.x, bx.y, bx.n, label, &sty);
        }
    }
    if (ps == TSU_PLOT_OK && !o->points_only) {
        for (size_t r = 0; r < cr->rows; r++)
            cli_xy_push(&cx, cr->smp[r * (1 + cr->dim) + 1], cr->smp[r * (1 + cr->dim) + 2]);
        memset(&sty, 0, sizeof sty);
        sty.color = "#0072b2";
        ps = cx.failed ? TSU_PLOT_ERR_NOMEM
                       : tsu_plot_add_polyline(p, cx.x, cx.y, cx.n, "curve", &sty);
        if (ps == TSU_PLOT_OK && o->show_control) {
            double P[12];
            for (size_t i = 0; i < cr->seg; i++) {
                (void)ts_curve_control(cr->c, i, P);
                for (int l = i ? 1 : 0; l < 4; l++)
                    cli_xy_push(&ctl, P[(size_t)l * cr->dim], P[(size_t)l * cr->dim + 1]);
            }
            memset(&sty, 0, sizeof sty);
            sty.color = "#009e73";
            ps = ctl.failed ? TSU_PLOT_ERR_NOMEM
                            : tsu_plot_add_polygon(p, ctl.x, ctl.y, ctl.n, "control polygon",
                                                  &sty);
        }
    }
    memset(&sty, 0, sizeof sty);
    sty.color = "#000000";
    if (ps == TSU_PLOT_OK)
        ps = tsu_plot_add_points(p, d->col[0], d->col[1], cr->n, "data", &sty);
    if (ps == TSU_PLOT_OK)
        ps = tsu_plot_render(p, svg);
    if (ps != TSU_PLOT_OK) {
        cli_error("plot: %s", tsu_plot_strerror(ps));
        rc = CLI_IO;
    }
    tsu_plot_free(p);
    cli_xy_free(&cx);
    cli_xy_free(&ctl);
    cli_xy_free(&bx);
    return rc;
}
