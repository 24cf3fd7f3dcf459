/* The SVG heatmap of a surface (surface --svg): a sequential colour map
 * (viridis) for data on one side of 0, a diverging one centred on 0 for data
 * on both sides; contours at the colour bar's round values; axis ticks; the
 * patches where the shape scheme acts hatched. */
#include "cli.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* A tick label with the sign (and an exponent's sign) as a real minus. */
static void put_label(cli_text *w, const char *s)
{
    char out[TSU_PLOT_LABEL_MAX * 8];
    size_t k = 0;
    for (const char *p = s; *p && k + 8 < sizeof out; p++) {
        if (*p == '-' && (p == s || p[-1] == 'e')) {
            memcpy(out + k, "&#8722;", 7);
            k += 7;
        } else {
            out[k++] = *p;
        }
    }
    out[k] = 0;
    cli_text_printf(w, "%s", out);
}

/* viridis (matplotlib, van der Walt & Smith 2015) at 9 even stops */
static const unsigned char viridis[9][3] = {
    {0x44, 0x01, 0x54}, {0x47, 0x2c, 0x7a}, {0x3b, 0x51, 0x8b}, {0x2c, 0x71, 0x8e}, {0x21, 0x90, 0x8d},
    {0x27, 0xad, 0x81}, {0x5c, 0xc8, 0x63}, {0xaa, 0xdc, 0x32}, {0xfd, 0xe7, 0x25}};

/* The colour of u in [0, 1]: viridis, or blue - white - orange-red (diverging,
 * colour-blind safe ends, white at 0.5). */
static void colour(int diverging, double u, char col[8])
{
    double r, g, b;
    u = u < 0 ? 0 : u > 1 ? 1 : u;
    if (diverging) {
        if (u < 0.5) {
            double s = u / 0.5;
            r = 0.13 + 0.87 * s, g = 0.40 + 0.60 * s, b = 0.67 + 0.33 * s;
        } else {
            double s = (u - 0.5) / 0.5;
            r = 1.0 - 0.16 * s, g = 1.0 - 0.63 * s, b = 1.0 - 0.93 * s;
        }
    } else {
        double f = u * 8.0;
        int i = f >= 8.0 ? 7 : (int)f;
        double s = f - i;
        r = (viridis[i][0] + s * (viridis[i + 1][0] - viridis[i][0])) / 255.0;
        g = (viridis[i][1] + s * (viridis[i + 1][1] - viridis[i][1])) / 255.0;
        b = (viridis[i][2] + s * (viridis[i + 1][2] - viridis[i][2])) / 255.0;
    }
    snprintf(col, 8, "#%02x%02x%02x", (unsigned)(r * 255 + 0.5), (unsigned)(g * 255 + 0.5),
             (unsigned)(b * 255 + 0.5));
}

/* The bound planes of the scheme of so (the data range zl, zh for range). */
static void bound_planes(const ts_surface_options *so, double zl, double zh, ts_plane *lo,
                         int *hl, ts_plane *up, int *hu)
{
    ts_plane zero = {0, 0, 0};
    *hl = *hu = 0;
    switch (so->shape) {
    case TS_SURFACE_POSITIVE:
        *lo = zero, *hl = 1;
        break;
    case TS_SURFACE_BOUNDS:
    case TS_SURFACE_PLANES:
        if (so->has_lower)
            *lo = so->lower, *hl = 1;
        if (so->has_upper)
            *up = so->upper, *hu = 1;
        if (so->shape == TS_SURFACE_BOUNDS)
            lo->p = lo->q = up->p = up->q = 0;
        break;
    case TS_SURFACE_RANGE:
        *lo = (ts_plane){0, 0, zl}, *hl = 1;
        *up = (ts_plane){0, 0, zh}, *hu = 1;
        break;
    default:
        break;
    }
}

/* acted[c]: the surface built without the shape scheme (its other options
 * the same) leaves the bounds on patch c by more than 1 % of the data range,
 * so the scheme visibly changed it there.
 * 0, or -1 when that surface cannot be built (acted: the active flags). */
static int scheme_acted(const double *x, size_t nx, const double *y, size_t ny, const double *z,
                        const ts_surface_options *so, int *acted)
{
    size_t np = (nx - 1) * (ny - 1);
    double zl = (double)INFINITY, zh = -(double)INFINITY;
    for (size_t k = 0; k < nx * ny; k++)
        zl = fmin(zl, z[k]), zh = fmax(zh, z[k]);
    ts_plane lo = {0, 0, 0}, up = {0, 0, 0};
    int hl, hu;
    bound_planes(so, zl, zh, &lo, &hl, &up, &hu);
    if (!hl && !hu)
        return -1;
    ts_surface_options o0 = *so;
    o0.shape = TS_SURFACE_NONE;
    o0.has_lower = o0.has_upper = 0;
    o0.beta = 0;
    ts_surface *s0 = NULL;
    ts_error e;
    ts_patch_report *r0 = malloc(np * sizeof *r0);
    if (!r0 || ts_surface_new(x, nx, y, ny, z, &o0, &s0, &e) != TS_OK) {
        free(r0);
        return -1;
    }
    ts_patch_report_init(r0, np);
    ts_status st = ts_surface_certify(s0, hl ? &lo : NULL, hu ? &up : NULL, r0, &e);
    int rc = st == TS_OK || st == TS_ERR_VIOLATED ? 0 : -1;
    /* visibly: by more than 1 % of the data range (rounding-level dips near
     * nodes on the bound are left out) */
    double tol = 0.01 * (zh - zl);
    for (size_t c = 0; rc == 0 && c < np; c++)
        acted[c] = (r0[c].has_lower && r0[c].sampled_lower < -tol) ||
                   (r0[c].has_upper && r0[c].sampled_upper < -tol);
    ts_surface_free(s0);
    free(r0);
    return rc;
}

int cli_surface_plot(const double *x, size_t nx, const double *y, size_t ny, const double *z,
                     const ts_surface *s, const ts_surface_options *so,
                     const ts_patch_report *rep, const int *active, tsu_plot_buf *svg)
{
    enum { N = 120 };
    const double W = 560, H = 420, L = 72, T = 20, R = 130, B = 64;
    const double x0 = x[0], x1 = x[nx - 1], y0 = y[0], y1 = y[ny - 1];
    size_t np = (nx - 1) * (ny - 1);
    double xs[N], ys[N], *v = malloc((size_t)N * N * sizeof *v);
    int *acted = rep ? calloc(np, sizeof *acted) : NULL;
    if (!v || (rep && !acted)) {
        free(v);
        free(acted);
        return ENOMEM;
    }
    cli_text w = {svg, 0};
    for (size_t a = 0; a < N; a++) {
        xs[a] = x0 + (x1 - x0) * ((double)a + 0.5) / (double)N;
        ys[a] = y0 + (y1 - y0) * ((double)a + 0.5) / (double)N;
    }
    ts_surface_eval_grid(s, xs, N, ys, N, v, NULL);
    double lo = (double)INFINITY, hi = -(double)INFINITY;
    for (size_t k = 0; k < (size_t)N * N; k++)
        lo = fmin(lo, v[k]), hi = fmax(hi, v[k]);
    if (!(hi > lo))
        hi = lo + 1;
    /* diverging only when the values straddle 0: white at 0 */
    int div = lo < 0 && hi > 0;
    double m = fmax(-lo, hi);
    double clo = div ? -m : lo, chi = div ? m : hi;
#define PX(xx) (L + W * ((xx) - x0) / (x1 - x0))
#define PY(yy) (T + H * (1.0 - ((yy) - y0) / (y1 - y0)))
#define U(val) (((val) - clo) / (chi - clo))
    cli_text_printf(&w, "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%g\" height=\"%g\" "
            "viewBox=\"0 0 %g %g\" font-family=\"sans-serif\" font-size=\"12\">\n",
        L + W + R, T + H + B, L + W + R, T + H + B);
    cli_text_printf(&w, "<rect width=\"100%%\" height=\"100%%\" fill=\"#fff\"/>\n");
    /* the hatching's id: unique per data (plots inlined in one HTML page
     * share the id namespace), the same for the same data */
    unsigned long long hsh = 1469598103934665603ULL;
    for (size_t k = 0; k < nx * ny; k++) {
        unsigned char bytes[sizeof(double)];
        memcpy(bytes, &z[k], sizeof bytes);
        for (size_t q = 0; q < sizeof bytes; q++)
            hsh = (hsh ^ bytes[q]) * 1099511628211ULL;
    }
    char pid[32];
    snprintf(pid, sizeof pid, "acted-%08llx", hsh & 0xffffffffULL);
    cli_text_printf(&w, "<defs><pattern id=\"%s\" patternUnits=\"userSpaceOnUse\" width=\"8\" "
            "height=\"8\"><path d=\"M-1 9L9 -1\" stroke=\"#fff\" stroke-width=\"0.9\" "
            "stroke-opacity=\"0.4\"/></pattern></defs>\n", pid);
    cli_text_printf(&w, "<g shape-rendering=\"crispEdges\">\n");
    double cw = W / (double)N, ch = H / (double)N;
    for (size_t b = 0; b < N; b++)
        for (size_t a = 0; a < N; a++) {
            char col[8];
            colour(div, U(v[b * N + a]), col);
            cli_text_printf(&w, "<rect x=\"%.2f\" y=\"%.2f\" width=\"%.2f\" height=\"%.2f\" fill=\"%s\"/>\n",
                L + cw * (double)a, T + H - ch * (double)(b + 1), cw + 0.3, ch + 0.3, col);
        }
    cli_text_printf(&w, "</g>\n");
    /* contours at the colour bar's ticks (marching squares on the cell centres) */
    tsu_plot_ticks ct;
    int have_ct = tsu_plot_ticks_compute(lo, hi, TSU_PLOT_RANGE_FIXED, &ct) == TSU_PLOT_OK;
    cli_text_printf(&w, "<g stroke=\"#000\" stroke-opacity=\"0.55\" stroke-width=\"0.7\" fill=\"none\">\n");
    for (size_t c = 0; have_ct && c < ct.n; c++) {
        double level = ct.value[c];
        if (!(lo < level && level < hi))
            continue;
        for (size_t b = 0; b + 1 < N; b++)
            for (size_t a = 0; a + 1 < N; a++) {
                double q[4] = {v[b * N + a], v[b * N + a + 1], v[(b + 1) * N + a + 1],
                               v[(b + 1) * N + a]};
                double px[4] = {xs[a], xs[a + 1], xs[a + 1], xs[a]};
                double py[4] = {ys[b], ys[b], ys[b + 1], ys[b + 1]};
                double ex[4], ey[4];
                int k = 0;
                for (int e = 0; e < 4 && k < 4; e++) {
                    double f0 = q[e] - level, f1 = q[(e + 1) % 4] - level;
                    if ((f0 < 0) != (f1 < 0)) {
                        double u = f0 / (f0 - f1);
                        ex[k] = px[e] + u * (px[(e + 1) % 4] - px[e]);
                        ey[k] = py[e] + u * (py[(e + 1) % 4] - py[e]);
                        k++;
                    }
                }
                for (int mm = 0; mm + 1 < k; mm += 2)
                    cli_text_printf(&w, "<path d=\"M%.2f %.2fL%.2f %.2f\"/>\n", PX(ex[mm]), PY(ey[mm]),
                        PX(ex[mm + 1]), PY(ey[mm + 1]));
            }
    }
    cli_text_printf(&w, "</g>\n");
    /* where the scheme acts: hatched */
    size_t n_acted = 0;
    if (rep) {
        if (scheme_acted(x, nx, y, ny, z, so, acted) != 0)
            for (size_t c = 0; c < np; c++)
                acted[c] = active[c];
        cli_text_printf(&w, "<g fill=\"url(#%s)\" stroke=\"none\">\n", pid);
        for (size_t c = 0; c < np; c++)
            if (acted[c]) {
                n_acted++;
                cli_text_printf(&w, "<rect x=\"%.2f\" y=\"%.2f\" width=\"%.2f\" height=\"%.2f\"><title>patch "
                        "(%zu, %zu): the shape scheme acts here</title></rect>\n",
                    PX(rep[c].x0), PY(rep[c].y1), PX(rep[c].x1) - PX(rep[c].x0),
                    PY(rep[c].y0) - PY(rep[c].y1), rep[c].i, rep[c].j);
            }
        cli_text_printf(&w, "</g>\n");
    }
    cli_text_printf(&w, "<g fill=\"#fff\" stroke=\"#000\" stroke-width=\"0.8\">\n");
    for (size_t k = 0; k < nx * ny; k++)
        cli_text_printf(&w, "<circle cx=\"%.2f\" cy=\"%.2f\" r=\"2.2\"/>\n", PX(x[k % nx]), PY(y[k / nx]));
    cli_text_printf(&w, "</g>\n");
    cli_text_printf(&w, "<rect x=\"%g\" y=\"%g\" width=\"%g\" height=\"%g\" fill=\"none\" stroke=\"#000\"/>\n",
        L, T, W, H);
    /* axis ticks */
    tsu_plot_ticks tx, ty;
    cli_text_printf(&w, "<g stroke=\"#000\">\n");
    int have_tx = tsu_plot_ticks_compute(x0, x1, TSU_PLOT_RANGE_FIXED, &tx) == TSU_PLOT_OK;
    int have_ty = tsu_plot_ticks_compute(y0, y1, TSU_PLOT_RANGE_FIXED, &ty) == TSU_PLOT_OK;
    for (size_t k = 0; have_tx && k < tx.n; k++)
        cli_text_printf(&w, "<path d=\"M%.2f %gv5\"/>\n", PX(tx.value[k]), T + H);
    for (size_t k = 0; have_ty && k < ty.n; k++)
        cli_text_printf(&w, "<path d=\"M%g %.2fh-5\"/>\n", L, PY(ty.value[k]));
    cli_text_printf(&w, "</g>\n<g fill=\"#000\">\n");
    for (size_t k = 0; have_tx && k < tx.n; k++) {
        cli_text_printf(&w, "<text x=\"%.2f\" y=\"%g\" text-anchor=\"middle\">", PX(tx.value[k]), T + H + 19);
        put_label(&w, tx.label[k]);
        cli_text_printf(&w, "</text>\n");
    }
    for (size_t k = 0; have_ty && k < ty.n; k++) {
        cli_text_printf(&w, "<text x=\"%g\" y=\"%.2f\" text-anchor=\"end\">", L - 8, PY(ty.value[k]) + 4);
        put_label(&w, ty.label[k]);
        cli_text_printf(&w, "</text>\n");
    }
    cli_text_printf(&w, "<text x=\"%g\" y=\"%g\" text-anchor=\"middle\">x</text>\n", L + W / 2, T + H + 40);
    if (have_tx && tx.exponent)
        cli_text_printf(&w, "<text x=\"%g\" y=\"%g\" text-anchor=\"end\">&#215;10<tspan dy=\"-5\" "
                "font-size=\"9\">%d</tspan></text>\n", L + W, T + H + 40, tx.exponent);
    cli_text_printf(&w, "<text x=\"%g\" y=\"%g\" transform=\"rotate(-90 %g %g)\" text-anchor=\"middle\">y"
            "</text>\n", L - 50, T + H / 2, L - 50, T + H / 2);
    if (have_ty && ty.exponent)
        cli_text_printf(&w, "<text x=\"%g\" y=\"%g\">&#215;10<tspan dy=\"-5\" font-size=\"9\">%d</tspan>"
                "</text>\n", 4.0, T - 6 > 10 ? T - 6 : 12, ty.exponent);
    cli_text_printf(&w, "</g>\n");
    /* colour bar: the colour range, its round values labelled */
    double bx = L + W + 18, bw = 16;
#define BY(val) (T + H * (1.0 - ((val) - clo) / (chi - clo)))
    cli_text_printf(&w, "<g shape-rendering=\"crispEdges\">\n");
    for (int c = 0; c < 64; c++) {
        char col[8];
        colour(div, (c + 0.5) / 64.0, col);
        cli_text_printf(&w, "<rect x=\"%g\" y=\"%.2f\" width=\"%g\" height=\"%.2f\" fill=\"%s\"/>\n", bx,
            T + H - H * (c + 1) / 64.0, bw, H / 64.0 + 0.3, col);
    }
    cli_text_printf(&w, "</g>\n<rect x=\"%g\" y=\"%g\" width=\"%g\" height=\"%g\" fill=\"none\" "
            "stroke=\"#000\"/>\n", bx, T, bw, H);
    tsu_plot_ticks bt;
    if (tsu_plot_ticks_compute(clo, chi, TSU_PLOT_RANGE_FIXED, &bt) == TSU_PLOT_OK) {
        for (size_t k = 0; k < bt.n; k++) {
            double yy = BY(bt.value[k]);
            cli_text_printf(&w, "<path d=\"M%g %.2fh4\" stroke=\"#000\"/>\n<text x=\"%g\" y=\"%.2f\">",
                bx + bw, yy, bx + bw + 7, yy + 4);
            put_label(&w, bt.label[k]);
            cli_text_printf(&w, "</text>\n");
        }
        if (bt.exponent)
            cli_text_printf(&w, "<text x=\"%g\" y=\"%g\">&#215;10<tspan dy=\"-5\" font-size=\"9\">%d</tspan>"
                    "</text>\n", bx, T + H + 19, bt.exponent);
    }
#undef BY
    if (n_acted) {
        cli_text_printf(&w, "<rect x=\"%g\" y=\"%g\" width=\"14\" height=\"10\" fill=\"#3b518b\"/>"
                "<rect x=\"%g\" y=\"%g\" width=\"14\" height=\"10\" fill=\"url(#%s)\" "
                "stroke=\"#000\" stroke-width=\"0.5\"/>\n",
            L, T + H + 48, L, T + H + 48, pid);
        cli_text_printf(&w, "<text x=\"%g\" y=\"%g\" font-size=\"11\">patches where the shape scheme acts "
                "(%zu of %zu: without it the surface leaves the bounds there)</text>\n",
            L + 20, T + H + 57, n_acted, np);
    }
    cli_text_printf(&w, "</svg>\n");
#undef PX
#undef PY
#undef U
    free(v);
    free(acted);
    return w.bad ? ENOMEM : 0;
}
