/* trigspline surface: certified surfaces through gridded data
 * (docs/method.md §11).  Reads the long format (x,y,z rows, a full grid in
 * any order) or the matrix layout (first row the x values, first column the
 * y values); writes samples on a finer grid (CSV, long or matrix), a JSON
 * report, an SVG heatmap with contours (docs/cli.md). */
#include "cli.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int parse_num(const char *s, double *v)
{
    const char *stop;
    return tsu_parse_double(s, s + strlen(s), v, &stop) == TSU_NUM_OK && *stop == '\0' &&
           isfinite(*v);
}

/* ---- reading the grid ------------------------------------------------------ */
typedef struct surf_grid {
    size_t nx, ny;
    double *x, *y, *z;
    unsigned long long *line; /* per node */
    const char *name;
} surf_grid;

static void grid_free(surf_grid *g)
{
    free(g->x);
    free(g->y);
    free(g->z);
    free(g->line);
}

static int cmp_double(const void *a, const void *b)
{
    double u = *(const double *)a, v = *(const double *)b;
    return (u > v) - (u < v);
}

/* sorted distinct values of v[0..n) into *out */
static size_t distinct(const double *v, size_t n, double **out)
{
    double *s = malloc((n ? n : 1) * sizeof *s);
    if (!s)
        return 0;
    memcpy(s, v, n * sizeof *s);
    qsort(s, n, sizeof *s, cmp_double);
    size_t k = 0;
    for (size_t i = 0; i < n; i++)
        if (k == 0 || s[i] != s[k - 1])
            s[k++] = s[i];
    *out = s;
    return k;
}

static size_t find(const double *v, size_t n, double key)
{
    size_t lo = 0, hi = n;
    while (hi - lo > 1) {
        size_t mid = lo + (hi - lo) / 2;
        if (v[mid] <= key)
            lo = mid;
        else
            hi = mid;
    }
    return lo;
}

/* path in the long format, or the matrix layout (matrix) */
static int read_grid(const char *path, int matrix, surf_grid *g)
{
    memset(g, 0, sizeof *g);
    g->name = strcmp(path, "-") == 0 ? "<stdin>" : path;
    tsu_read_options ro;
    tsu_read_options_init(&ro);
    ro.header_corner = matrix; /* ",x1,x2,...": pandas' empty corner cell */
    tsu_table t;
    tsu_io_error e;
    tsu_io_status st = tsu_read_table_path(path, &ro, &t, &e);
    if (st != TSU_IO_OK)
        return cli_report_io(&e);
    char nb[TSU_FMT_SIZE], nb2[TSU_FMT_SIZE];
    int rc = CLI_DATA;
    if (!matrix) {
        if (t.ncols != 3) {
            cli_error("%s: the long format needs 3 columns x,y,z (found %zu)", g->name, t.ncols);
            goto done;
        }
        size_t n = t.nrows;
        g->nx = distinct(t.cols[0], n, &g->x);
        g->ny = distinct(t.cols[1], n, &g->y);
        if (!g->x || !g->y || g->nx * g->ny / g->ny != g->nx) {
            rc = cli_nomem();
            goto done;
        }
        size_t nn = g->nx * g->ny;
        g->z = malloc(nn * sizeof *g->z);
        g->line = calloc(nn, sizeof *g->line);
        if (!g->z || !g->line) {
            rc = cli_nomem();
            goto done;
        }
        for (size_t r = 0; r < n; r++) {
            size_t i = find(g->x, g->nx, t.cols[0][r]), j = find(g->y, g->ny, t.cols[1][r]);
            size_t k = j * g->nx + i;
            if (g->line[k]) {
                cli_error("%s: line %llu: duplicate node (x=%s, y=%s), first on line %llu",
                          g->name, t.lines[r], cli_num(g->x[i], nb), cli_num(g->y[j], nb2),
                          g->line[k]);
                goto done;
            }
            g->line[k] = t.lines[r];
            g->z[k] = t.cols[2][r];
        }
        for (size_t k = 0; k < nn; k++)
            if (!g->line[k]) {
                cli_error("%s: missing node (x=%s, y=%s): the grid is %zu x %zu but has %zu rows",
                          g->name, cli_num(g->x[k % g->nx], nb), cli_num(g->y[k / g->nx], nb2),
                          g->nx, g->ny, n);
                goto done;
            }
    } else {
        /* the first row holds the x values: a header (parsed) or data */
        int hdr = t.names != NULL;
        size_t rows = t.nrows - (hdr ? 0 : 1);
        if (t.ncols < 3 || rows < 2) {
            cli_error("%s: the matrix layout needs at least 2 x values and 2 y rows", g->name);
            goto done;
        }
        g->nx = t.ncols - 1;
        g->ny = rows;
        g->x = malloc(g->nx * sizeof *g->x);
        g->y = malloc(g->ny * sizeof *g->y);
        g->z = malloc(g->nx * g->ny * sizeof *g->z);
        g->line = malloc(g->nx * g->ny * sizeof *g->line);
        if (!g->x || !g->y || !g->z || !g->line) {
            rc = cli_nomem();
            goto done;
        }
        for (size_t i = 0; i < g->nx; i++) {
            if (hdr) {
                if (!parse_num(t.names[i + 1], &g->x[i])) {
                    cli_error("%s: line 1: column %zu: x value \"%s\" is not a number", g->name,
                              i + 2, t.names[i + 1]);
                    goto done;
                }
            } else {
                g->x[i] = t.cols[i + 1][0];
            }
        }
        for (size_t i = 1; i < g->nx; i++)
            if (!(g->x[i] > g->x[i - 1])) {
                cli_error("%s: line %llu: column %zu: x = %s is not above the x before it",
                          g->name, hdr ? 1ULL : t.lines[0], i + 2, cli_num(g->x[i], nb));
                goto done;
            }
        for (size_t j = 0; j < g->ny; j++) {
            size_t r = j + (hdr ? 0 : 1);
            g->y[j] = t.cols[0][r];
            if (j > 0 && !(g->y[j] > g->y[j - 1])) {
                cli_error("%s: line %llu: y = %s is not above the y before it", g->name,
                          t.lines[r], cli_num(g->y[j], nb));
                goto done;
            }
            for (size_t i = 0; i < g->nx; i++) {
                g->z[j * g->nx + i] = t.cols[i + 1][r];
                g->line[j * g->nx + i] = t.lines[r];
            }
        }
    }
    rc = CLI_OK;
done:
    tsu_table_free(&t);
    if (rc != CLI_OK)
        grid_free(g);
    return rc;
}

/* ---- building ---------------------------------------------------------------- */
static int report_error(const surf_grid *g, const surf_grid *fields, const ts_surface_options *so,
                        ts_status st, const ts_error *e)
{
    char msg[1024];
    ts_error_context ctx;
    ts_error_context_init(&ctx);
    ctx.x = g->x;
    ctx.n_points = g->nx;
    ctx.y = g->y;
    ctx.ny_points = g->ny;
    ctx.f = g->z;
    ctx.surface_options = so;
    ts_error err = *e;
    err.status = st;
    ts_error_message(&err, &ctx, msg, sizeof msg);
    if (e->where == TS_WHERE_POINT && e->index < g->nx * g->ny) {
        cli_error("%s: line %llu: %s", g->name, g->line[e->index], msg);
        return CLI_DATA;
    }
    /* a malformed field: named by its file */
    const char *name = st == TS_ERR_BOUND_GRID && e->index < 2 ? fields[e->index].name : g->name;
    cli_error("%s: %s", name, msg);
    if (e->where == TS_WHERE_INTERVAL)
        return st == TS_ERR_INFEASIBLE || st == TS_ERR_UNPROVEN ? CLI_INFEASIBLE : CLI_DATA;
    return st == TS_ERR_NOMEM ? CLI_IO : (st == TS_ERR_OPTION || st == TS_ERR_ALPHA ||
                                          st == TS_ERR_BETA || st == TS_ERR_MARGIN ||
                                          st == TS_ERR_GEOMETRIC)
                                             ? CLI_USAGE
                                             : CLI_DATA;
}

/* the sample abscissae: n per interval (knots included) or a uniform grid */
static double *sample_axis(const double *t, size_t np, size_t per, size_t uniform, size_t *m)
{
    size_t k = uniform ? uniform : (np - 1) * per + 1;
    double *v = malloc(k * sizeof *v);
    if (!v)
        return NULL;
    if (uniform) {
        for (size_t a = 0; a < k; a++)
            v[a] = t[0] + (t[np - 1] - t[0]) * (double)a / (double)(k - 1);
    } else {
        for (size_t i = 0; i + 1 < np; i++)
            for (size_t a = 0; a < per; a++)
                v[i * per + a] = t[i] + (t[i + 1] - t[i]) * (double)a / (double)per;
    }
    v[0] = t[0];
    v[k - 1] = t[np - 1];
    *m = k;
    return v;
}

/* ---- the command ------------------------------------------------------------ */
int cli_surface(int argc, char **argv)
{
    cli_surface_opts o;
    int rc = cli_surface_parse(argc, argv, &o);
    if (rc == CLI_HELP) {
        cli_print_help(CLI_SURFACE);
        return fflush(stdout) == 0 ? CLI_OK : CLI_IO;
    }
    if (rc != CLI_OK)
        return rc;
    /* gridded fields: shape grids (the default with them; no other shape) */
    if (o.lower_grid || o.upper_grid) {
        if (o.so.shape == TS_SURFACE_NONE)
            o.so.shape = TS_SURFACE_GRIDS;
        else if (o.so.shape != TS_SURFACE_GRIDS)
            return cli_usage(CLI_SURFACE, "--lower-grid and --upper-grid need --shape grids");
    }
    if (o.so.shape == TS_SURFACE_GRIDS && !o.lower_grid && !o.upper_grid)
        return cli_usage(CLI_SURFACE, "--shape grids needs --lower-grid FILE or --upper-grid FILE");
    surf_grid g, fields[2];
    memset(fields, 0, sizeof fields);
    if ((rc = read_grid(o.data, o.matrix_in, &g)) != CLI_OK)
        return rc;
    for (int k = 0; k < 2; k++) {
        const char *path = k ? o.upper_grid : o.lower_grid;
        if (!path)
            continue;
        if ((rc = read_grid(path, o.matrix_in, &fields[k])) != CLI_OK) {
            grid_free(&fields[0]);
            grid_free(&g);
            return rc;
        }
        ts_grid_bound *b = k ? &o.so.upper_grid : &o.so.lower_grid;
        *b = (ts_grid_bound){fields[k].x, fields[k].nx, fields[k].y, fields[k].ny, fields[k].z};
    }
    /* every sample is held in memory (text, JSON range, plot): a documented limit */
    double px = o.grid_x ? (double)o.grid_x : (double)(g.nx - 1) * (double)o.samples + 1.0;
    double py = o.grid_y ? (double)o.grid_y : (double)(g.ny - 1) * (double)o.samples + 1.0;
    if (px * py > CLI_MAX_HELD_SAMPLES) {
        cli_error("%s: %.0f x %.0f sample points exceed the limit of %u that surface holds in "
                  "memory; lower --samples or --grid",
                  g.name, px, py, CLI_MAX_HELD_SAMPLES);
        grid_free(&g);
        grid_free(&fields[0]);
        grid_free(&fields[1]);
        return CLI_USAGE;
    }
    ts_surface *s = NULL;
    ts_error e;
    ts_status st = ts_surface_new(g.x, g.nx, g.y, g.ny, g.z, &o.so, &s, &e);
    if (st != TS_OK) {
        rc = report_error(&g, fields, &o.so, st, &e);
        grid_free(&g);
        grid_free(&fields[0]);
        grid_free(&fields[1]);
        return rc;
    }
    size_t np = (g.nx - 1) * (g.ny - 1);
    ts_patch_report *rep = NULL;
    int *active = NULL;
    double *xq = NULL, *yq = NULL, *zq = NULL;
    size_t mx = 0, my = 0;
    tsu_plot_buf text, svg;
    tsu_plot_buf_init(&text);
    tsu_plot_buf_init(&svg);
    int shaped = o.so.shape != TS_SURFACE_NONE;
    if (o.json || o.svg) {
        rep = calloc(np, sizeof *rep);
        active = calloc(np, sizeof *active);
        if (!rep || !active) {
            rc = cli_nomem();
            goto out;
        }
        ts_patch_report_init(rep, np);
        double zl = (double)INFINITY, zh = -(double)INFINITY;
        for (size_t k = 0; k < g.nx * g.ny; k++)
            zl = fmin(zl, g.z[k]), zh = fmax(zh, g.z[k]);
        for (size_t c = 0; c < np; c++) {
            ts_surface_report(s, c % (g.nx - 1), c / (g.nx - 1), &rep[c]);
            double tol = 0.01 * (zh - zl);
            active[c] = shaped && ((rep[c].has_lower && rep[c].proven_lower <= tol) ||
                                   (rep[c].has_upper && rep[c].proven_upper <= tol));
        }
    }
    xq = sample_axis(g.x, g.nx, o.samples, o.grid_x, &mx);
    yq = sample_axis(g.y, g.ny, o.samples, o.grid_y, &my);
    zq = xq && yq ? malloc(mx * my * sizeof *zq) : NULL;
    if (!zq) {
        rc = cli_nomem();
        goto out;
    }
    ts_surface_eval_grid(s, xq, mx, yq, my, zq, NULL);
    double smin = (double)INFINITY, smax = -(double)INFINITY;
    for (size_t k = 0; k < mx * my; k++)
        smin = fmin(smin, zq[k]), smax = fmax(smax, zq[k]);
    char nb[TSU_FMT_SIZE];
    cli_text tw = {&text, 0};
    if (o.json) {
        cli_json j;
        cli_json_init(&j);
        cli_json_begin(&j, '{');
        cli_json_kstr(&j, "command", "surface");
        cli_json_kstr(&j, "data", g.name);
        cli_json_kuint(&j, "nx_points", g.nx);
        cli_json_kuint(&j, "ny_points", g.ny);
        cli_json_kstr(&j, "form", cli_form_name(o.so.form));
        cli_json_kstr(&j, "shape", ts_vocab_name(TS_VOCAB_SURFACE_SHAPE, (int)o.so.shape));
        cli_json_kstr(&j, "slopes", cli_slopes_name(o.so.slopes));
        cli_json_kbool(&j, "certified", ts_surface_certified(s));
        cli_json_knum(&j, "sample_min", smin);
        cli_json_knum(&j, "sample_max", smax);
        cli_json_kuint(&j, "samples", (unsigned long long)(mx * my));
        cli_json_key(&j, "patches");
        cli_json_begin(&j, '[');
        for (size_t c = 0; c < np; c++) {
            cli_json_nl(&j);
            cli_json_begin(&j, '{');
            cli_json_kuint(&j, "i", rep[c].i);
            cli_json_kuint(&j, "j", rep[c].j);
            cli_json_knum(&j, "ax", rep[c].ax);
            cli_json_knum(&j, "ay", rep[c].ay);
            if (rep[c].has_lower) {
                cli_json_knum(&j, "proven_lower", rep[c].proven_lower);
                cli_json_knum(&j, "sampled_lower", rep[c].sampled_lower);
                cli_json_key(&j, "at_lower");
                cli_json_begin(&j, '[');
                cli_json_num(&j, rep[c].at_lower[0]);
                cli_json_num(&j, rep[c].at_lower[1]);
                cli_json_end(&j, ']');
            }
            if (rep[c].has_upper) {
                cli_json_knum(&j, "proven_upper", rep[c].proven_upper);
                cli_json_knum(&j, "sampled_upper", rep[c].sampled_upper);
                cli_json_key(&j, "at_upper");
                cli_json_begin(&j, '[');
                cli_json_num(&j, rep[c].at_upper[0]);
                cli_json_num(&j, rep[c].at_upper[1]);
                cli_json_end(&j, ']');
            }
            cli_json_kbool(&j, "certified", rep[c].certified);
            cli_json_kbool(&j, "active", active[c]);
            cli_json_end(&j, '}');
        }
        cli_json_end(&j, ']');
        cli_json_end(&j, '}');
        cli_json_raw(&j, "\n");
        if (j.failed) {
            cli_json_free(&j);
            rc = cli_nomem();
            goto out;
        }
        text = j.b;
    } else if (o.matrix_out) {
        cli_text_puts(&tw, "y\\x");
        for (size_t a = 0; a < mx; a++)
            cli_text_printf(&tw, ",%s", cli_num(xq[a], nb));
        cli_text_puts(&tw, "\n");
        for (size_t b = 0; b < my; b++) {
            cli_text_puts(&tw, cli_num(yq[b], nb));
            for (size_t a = 0; a < mx; a++)
                cli_text_printf(&tw, ",%s", cli_num(zq[b * mx + a], nb));
            cli_text_puts(&tw, "\n");
        }
    } else {
        cli_text_puts(&tw, "x,y,z\n");
        for (size_t b = 0; b < my; b++)
            for (size_t a = 0; a < mx; a++) {
                char n1[TSU_FMT_SIZE], n2[TSU_FMT_SIZE];
                cli_text_printf(&tw, "%s,%s,%s\n", cli_num(xq[a], n1), cli_num(yq[b], n2),
                       cli_num(zq[b * mx + a], nb));
            }
    }
    if (tw.bad) {
        rc = cli_nomem();
        goto out;
    }
    if (o.svg && cli_surface_plot(g.x, g.nx, g.y, g.ny, g.z, s, &o.so, rep, active, &svg) != 0) {
        rc = cli_nomem();
        goto out;
    }
    rc = cli_write_outputs(o.out, &text, NULL, NULL, o.svg, o.fmt, o.svg ? &svg : NULL);
out:
    tsu_plot_buf_free(&text);
    tsu_plot_buf_free(&svg);
    free(rep);
    free(active);
    free(xq);
    free(yq);
    free(zq);
    ts_surface_free(s);
    grid_free(&g);
    grid_free(&fields[0]);
    grid_free(&fields[1]);
    return rc;
}
