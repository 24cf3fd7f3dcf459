/* trigspline curve: parametric curves (docs/method.md §7). */
#include "cli.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int curve_error(const cli_opts *o, const cli_data *d, ts_status st, const ts_error *e)
{
    char w[TSU_IO_MSG_SIZE], b[3][TSU_FMT_SIZE];
    size_t i = e->index;
    int point = e->where == TS_WHERE_POINT && i < d->n;
    if (point && d->line)
        snprintf(w, sizeof w, "%s:%llu", d->name, d->line[i]);
    else
        snprintf(w, sizeof w, "%s", d->name);
    switch (st) {
    case TS_ERR_TOO_FEW:
        cli_error("%s: %zu point%s; a curve needs at least 2 (a closed curve 3 distinct points)",
                  d->name, d->n, d->n == 1 ? "" : "s");
        return CLI_DATA;
    case TS_ERR_UNSORTED:
        if (point) {
            cli_error("%s: point %zu (%s, %s) repeats the point before it (consecutive points "
                      "must differ)",
                      w, i, cli_num(d->col[0][i], b[0]), cli_num(d->col[1][i], b[1]));
            return CLI_DATA;
        }
        cli_error("%s: two consecutive points are equal or too close", d->name);
        return CLI_DATA;
    case TS_ERR_SIDE:
        if (point) {
            cli_error("%s: point %zu (%s, %s) is on or outside the --box", w, i,
                      cli_num(d->col[0][i], b[0]), cli_num(d->col[1][i], b[1]));
            return CLI_DATA;
        }
        break;
    case TS_ERR_INFEASIBLE:
        cli_error("%s: segment %zu: infeasible constraint: no beta keeps it inside the box",
                  d->name, i);
        return CLI_INFEASIBLE;
    case TS_ERR_LENGTH:
        cli_error("--alphas/--betas need exactly one value per segment");
        return CLI_USAGE;
    case TS_ERR_OPTION:
        if (o->slopes == TS_SLOPES_PERIODIC && !o->closed)
            return cli_usage(o->cmd, "--slopes periodic needs --closed");
        cli_error("%s", ts_strerror(st));
        return CLI_USAGE;
    case TS_ERR_ALPHA:
    case TS_ERR_BETA:
    case TS_ERR_MARGIN:
        cli_error("segment %zu: %s", i, ts_strerror(st));
        return CLI_USAGE;
    case TS_ERR_NOMEM:
    case TS_ERR_OVERFLOW:
        cli_error("%s", ts_strerror(st));
        return CLI_IO;
    default:
        break;
    }
    if (point)
        cli_error("%s: point %zu: %s", w, i, ts_strerror(st));
    else
        cli_error("%s: %s", d->name, ts_strerror(st));
    return CLI_DATA;
}

static void box_line(cli_xy *a, double x0, double y0, double x1, double y1)
{
    cli_xy_push(a, x0, y0);
    cli_xy_push(a, x1, y1);
}

int cli_curve(cli_opts *o)
{
    int rc;
    ts_curve_options co;
    if ((rc = cli_curve_options(o, &co)) != CLI_OK)
        return rc;

    cli_data d;
    if ((rc = cli_read_data(o, &d)) != CLI_OK)
        return rc;
    size_t dim = d.dim, n = d.n;
    if (o->box_set && o->n_box / 2 > dim) {
        cli_data_free(&d);
        return cli_usage(o->cmd, "--box has 6 values but the data have 2 columns");
    }
    double *pts = malloc((n ? n : 1) * dim * sizeof *pts);
    if (!pts) {
        cli_data_free(&d);
        return cli_nomem();
    }
    for (size_t i = 0; i < n; i++)
        for (size_t k = 0; k < dim; k++)
            pts[i * dim + k] = d.col[k][i];

    ts_curve *c = NULL;
    ts_error e;
    ts_status st = ts_curve_new(pts, n, dim, &co, &c, &e);
    if (st != TS_OK) {
        rc = curve_error(o, &d, st, &e);
        free(pts);
        cli_data_free(&d);
        return rc;
    }
    size_t seg = ts_curve_segments(c), rows = 0, m = o->samples;
    double *smp = NULL;
    ts_interval_report *reps = NULL;
    cli_json j;
    cli_json_init(&j);
    tsu_plot_buf svg = TSU_PLOT_BUF_INIT, text = TSU_PLOT_BUF_INIT;
    cli_xy cx = {0}, ctl = {0}, bx = {0};
    tsu_plot *p = NULL;
    int certified = 0, has_box = 0;
    double min_gap = (double)INFINITY;

    st = ts_curve_sample(c, m, NULL, 0, &rows);
    if (st != TS_ERR_LENGTH && st != TS_OK) {
        rc = cli_nomem();
        goto done;
    }
    if (rows > CLI_MAX_HELD_SAMPLES) {
        cli_error("%s: %zu sample points (--samples %zu over %zu segments) exceed the limit of %u "
                  "that curve holds in memory; lower --samples",
                  d.name, rows, m, seg, CLI_MAX_HELD_SAMPLES);
        rc = CLI_USAGE;
        goto done;
    }
    if (rows > ((size_t)-1) / sizeof(double) / (1 + dim) ||
        !(smp = malloc(rows * (1 + dim) * sizeof *smp))) {
        rc = cli_nomem();
        goto done;
    }
    if (ts_curve_sample(c, m, smp, rows * (1 + dim), &rows) != TS_OK) {
        rc = cli_nomem();
        goto done;
    }
    for (size_t k = 0; k < 3; k++)
        has_box |= co.has_lo[k] | co.has_hi[k];
    if (has_box) {
        reps = calloc(seg * dim, sizeof *reps);
        if (!reps) {
            rc = cli_nomem();
            goto done;
        }
        ts_interval_report_init(reps, seg * dim);
        st = ts_curve_certify(c, reps, &e);
        certified = st == TS_OK;
        for (size_t i = 0; i < seg * dim; i++) {
            if (reps[i].has_lower && !(reps[i].gap_lower >= min_gap))
                min_gap = reps[i].gap_lower;
            if (reps[i].has_upper && !(reps[i].gap_upper >= min_gap))
                min_gap = reps[i].gap_upper;
        }
    }

    if (o->json) {
        double len = (double)NAN, mn[3] = {(double)INFINITY, (double)INFINITY, (double)INFINITY}, mx[3] = {-(double)INFINITY, -(double)INFINITY,
                                                                            -(double)INFINITY};
        const char *axn[3] = {"x", "y", "z"};
        char key[16];
        (void)ts_curve_length(c, 0.0, &len);
        for (size_t r = 0; r < rows; r++)
            for (size_t k = 0; k < dim; k++) {
                double v = smp[r * (1 + dim) + 1 + k];
                if (v < mn[k])
                    mn[k] = v;
                if (v > mx[k])
                    mx[k] = v;
            }
        cli_json_begin(&j, '{');
        cli_json_kstr(&j, "command", "curve");
        cli_json_kbool(&j, "closed", ts_curve_closed(c));
        cli_json_kstr(&j, "param", cli_param_name(o->param));
        cli_json_kstr(&j, "slopes", cli_slopes_name(o->slopes));
        cli_json_kuint(&j, "dim", dim);
        cli_json_kuint(&j, "n_points", n);
        cli_json_kuint(&j, "n_segments", seg);
        cli_json_key(&j, "box");
        if (has_box) {
            cli_json_begin(&j, '{');
            for (size_t k = 0; k < dim; k++) {
                snprintf(key, sizeof key, "%smin", axn[k]);
                cli_json_key(&j, key);
                if (co.has_lo[k])
                    cli_json_num(&j, co.lo[k]);
                else
                    cli_json_null(&j);
                snprintf(key, sizeof key, "%smax", axn[k]);
                cli_json_key(&j, key);
                if (co.has_hi[k])
                    cli_json_num(&j, co.hi[k]);
                else
                    cli_json_null(&j);
            }
            cli_json_end(&j, '}');
        } else {
            cli_json_null(&j);
        }
        cli_json_kbool(&j, "certified", certified);
        cli_json_key(&j, "min_gap");
        if (has_box)
            cli_json_num(&j, min_gap);
        else
            cli_json_null(&j);
        cli_json_knum(&j, "length", len);
        cli_json_nl(&j);
        cli_json_key(&j, "knots");
        cli_json_begin(&j, '[');
        const double *t = ts_curve_knots(c);
        for (size_t i = 0; i <= seg; i++)
            cli_json_num(&j, t[i]);
        cli_json_end(&j, ']');
        cli_json_nl(&j);
        cli_json_key(&j, "segments");
        cli_json_begin(&j, '[');
        for (size_t i = 0; i < seg; i++) {
            double al, be, P[12];
            (void)ts_curve_params(c, i, &al, &be);
            (void)ts_curve_control(c, i, P);
            cli_json_nl(&j);
            cli_json_begin(&j, '{');
            cli_json_kuint(&j, "i", i);
            cli_json_knum(&j, "t0", t[i]);
            cli_json_knum(&j, "t1", t[i + 1]);
            cli_json_knum(&j, "alpha", al);
            cli_json_knum(&j, "beta", be);
            cli_json_knum(&j, "a", al + be);
            cli_json_key(&j, "P");
            cli_json_begin(&j, '[');
            for (int l = 0; l < 4; l++) {
                cli_json_begin(&j, '[');
                for (size_t k = 0; k < dim; k++)
                    cli_json_num(&j, P[(size_t)l * dim + k]);
                cli_json_end(&j, ']');
            }
            cli_json_end(&j, ']');
            cli_json_key(&j, "min_gap");
            if (has_box) {
                double g = (double)INFINITY;
                int ok = 1;
                for (size_t k = 0; k < dim; k++) {
                    const ts_interval_report *r = &reps[i * dim + k];
                    if (r->has_lower && !(r->gap_lower >= g))
                        g = r->gap_lower;
                    if (r->has_upper && !(r->gap_upper >= g))
                        g = r->gap_upper;
                    ok &= r->certified || (!r->has_lower && !r->has_upper);
                }
                cli_json_num(&j, g);
                cli_json_kbool(&j, "certified", ok);
            } else {
                cli_json_null(&j);
                cli_json_key(&j, "certified");
                cli_json_null(&j);
            }
            cli_json_end(&j, '}');
        }
        cli_json_end(&j, ']');
        cli_json_nl(&j);
        cli_json_key(&j, "samples");
        cli_json_begin(&j, '{');
        cli_json_kuint(&j, "count", rows);
        for (size_t k = 0; k < dim; k++) {
            snprintf(key, sizeof key, "min_%s", axn[k]);
            cli_json_knum(&j, key, mn[k]);
            snprintf(key, sizeof key, "max_%s", axn[k]);
            cli_json_knum(&j, key, mx[k]);
        }
        cli_json_end(&j, '}');
        cli_json_end(&j, '}');
        cli_json_raw(&j, "\n");
        if (j.failed) {
            rc = cli_nomem();
            goto done;
        }
    } else {
        int bad = tsu_plot_buf_puts(&text, dim == 3 ? "t,x,y,z\n" : "t,x,y\n") != TSU_PLOT_OK;
        char b[TSU_FMT_SIZE];
        for (size_t r = 0; r < rows && !bad; r++) {
            for (size_t k = 0; k <= dim && !bad; k++) {
                bad |= tsu_plot_buf_puts(&text, cli_num(smp[r * (1 + dim) + k], b)) != TSU_PLOT_OK;
                bad |= tsu_plot_buf_puts(&text, k < dim ? "," : "\n") != TSU_PLOT_OK;
            }
        }
        if (bad) {
            rc = cli_nomem();
            goto done;
        }
    }

    if (o->svg) {
        char title[512], ab[TSU_FMT_SIZE], bb[TSU_FMT_SIZE];
        tsu_plot_style sty;
        const char *base = strrchr(d.name, '/');
        base = base ? base + 1 : d.name;
        snprintf(title, sizeof title, "%s: %s curve, alpha = %s, beta = %s%s", base,
                 o->closed ? "closed" : "open", o->alphas ? "per segment" : cli_num(o->alpha, ab),
                 o->betas ? "per segment" : cli_num(o->beta, bb),
                 dim == 3 ? " (x-y projection)" : "");
        tsu_plot_status ps = tsu_plot_new(o->width, o->height, &p);
        if (ps == TSU_PLOT_OK)
            ps = tsu_plot_set_title(p, o->title ? o->title : title);
        if (ps == TSU_PLOT_OK)
            ps = cli_plot_axes(o, p, NULL, "x", "y");
        if (ps == TSU_PLOT_OK)
            ps = tsu_plot_set_equal_aspect(p, 1);
        /* box: shaded floor / ceiling in y, dashed lines at the x bounds */
        if (ps == TSU_PLOT_OK && has_box) {
            double ylo = (double)INFINITY, yhi = -(double)INFINITY;
            for (size_t r = 0; r < rows; r++) {
                double v = smp[r * (1 + dim) + 2];
                ylo = v < ylo ? v : ylo;
                yhi = v > yhi ? v : yhi;
            }
            if (co.has_lo[1])
                ylo = co.lo[1] < ylo ? co.lo[1] : ylo;
            if (co.has_hi[1])
                yhi = co.hi[1] > yhi ? co.hi[1] : yhi;
            double pad = 0.1 * (yhi - ylo) + 1e-9;
            memset(&sty, 0, sizeof sty);
            sty.color = "#d55e00";
            if (co.has_lo[1])
                ps = tsu_plot_add_floor(p, co.lo[1], "box", &sty);
            if (ps == TSU_PLOT_OK && co.has_hi[1])
                ps = tsu_plot_add_ceiling(p, co.hi[1], co.has_lo[1] ? NULL : "box", &sty);
            for (int s2 = 0; s2 < 2 && ps == TSU_PLOT_OK; s2++) {
                int on = s2 ? co.has_hi[0] : co.has_lo[0];
                if (!on)
                    continue;
                double xb = s2 ? co.hi[0] : co.lo[0];
                bx.n = 0;
                box_line(&bx, xb, ylo - pad, xb, yhi + pad);
                sty.dash = 1;
                ps = bx.failed ? TSU_PLOT_ERR_NOMEM
                               : tsu_plot_add_polyline(p, bx.x, bx.y, bx.n,
                                                      co.has_lo[1] || co.has_hi[1] || s2 ? NULL
                                                                                         : "box",
                                                      &sty);
            }
        }
        if (ps == TSU_PLOT_OK && !o->points_only) {
            for (size_t r = 0; r < rows; r++)
                cli_xy_push(&cx, smp[r * (1 + dim) + 1], smp[r * (1 + dim) + 2]);
            memset(&sty, 0, sizeof sty);
            sty.color = "#0072b2";
            ps = cx.failed ? TSU_PLOT_ERR_NOMEM
                           : tsu_plot_add_polyline(p, cx.x, cx.y, cx.n, "curve", &sty);
            if (ps == TSU_PLOT_OK && o->show_control) {
                double P[12];
                for (size_t i = 0; i < seg; i++) {
                    (void)ts_curve_control(c, i, P);
                    for (int l = i ? 1 : 0; l < 4; l++)
                        cli_xy_push(&ctl, P[(size_t)l * dim], P[(size_t)l * dim + 1]);
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
            ps = tsu_plot_add_points(p, d.col[0], d.col[1], n, "data", &sty);
        if (ps == TSU_PLOT_OK)
            ps = tsu_plot_render(p, &svg);
        if (ps != TSU_PLOT_OK) {
            cli_error("plot: %s", tsu_plot_strerror(ps));
            rc = CLI_IO;
            goto done;
        }
    }
    rc = cli_write_outputs(o->out, o->json ? &j.b : &text, NULL, NULL, o->svg, o->plot_format, &svg);
done:
    tsu_plot_free(p);
    cli_xy_free(&cx);
    cli_xy_free(&ctl);
    cli_xy_free(&bx);
    tsu_plot_buf_free(&svg);
    tsu_plot_buf_free(&text);
    cli_json_free(&j);
    free(reps);
    free(smp);
    ts_curve_free(c);
    free(pts);
    cli_data_free(&d);
    return rc;
}
