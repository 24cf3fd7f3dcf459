/* docs/method.md §11: building a surface (slopes, twists, the scheme's
 * shape parameters), accessors, reports and certificates. */
#include "internal.h"

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

static void defaults(ts_surface_options *opt)
{
    memset(opt, 0, sizeof *opt);
    opt->struct_size = sizeof *opt;
    opt->form = TS_FORM_PAPER;
    opt->slopes = TS_SLOPES_ARITHMETIC;
    opt->alpha = 1.0;
    opt->beta = 0.0;
    opt->margin = TS_DEFAULT_MARGIN;
    opt->shape = TS_SURFACE_NONE;
}

void ts_surface_options_init(ts_surface_options *opt)
{
    if (opt)
        defaults(opt);
}

/* docs/method.md §11.3: accurate to its own rounding, not to that of p x */
static double plane_at(const ts_plane *pl, double x, double y)
{
    return ts__surf_plane_at(pl, x, y, NULL);
}

/* sg times the terms of p x + q y + c (p x = P + e, q y = Q + f exactly by
 * fma) into v[0..5), or none where a term is beyond ts__exact_sign's range
 * or a product is so small that its fma error is not exact (undecided). */
static int plane_terms(const ts_plane *pl, double x, double y, double sg, double *v)
{
    if (!ts__exact_product(pl->p, x, sg, v) || !ts__exact_product(pl->q, y, sg, v + 2) ||
        !(fabs(pl->c) <= 0x1p1020))
        return 0;
    v[4] = sg * pl->c;
    return 5;
}

/* Sign of z − (p x + q y + c), exact (docs/method.md §5.8, §11.3): decided
 * by the accurate plane value where z is farther from it than its error
 * bound (fl(z − L) has the sign of z − L), else by the exact sum; 0 (on the
 * plane) where undecidable. */
static int plane_side(double z, const ts_plane *pl, double x, double y)
{
    double err, L = ts__surf_plane_at(pl, x, y, &err), t[6];
    double g = z - L;
    if (fabs(g) > 2.0 * err)
        return (g > 0.0) - (g < 0.0);
    if (pl->p == 0.0 && pl->q == 0.0) /* the exact sum below is z − c */
        return fabs(pl->c) <= 0x1p1020 && fabs(z) <= 0x1p1020 ? (z > pl->c) - (z < pl->c) : 0;
    int n = plane_terms(pl, x, y, -1.0, t);
    t[n] = z;
    return n && fabs(z) <= 0x1p1020 ? ts__exact_sign(t, n + 1) : 0;
}

/* Sign of up(x, y) − lo(x, y), exact as plane_side. */
static int plane_order(const ts_plane *lo, const ts_plane *up, double x, double y)
{
    double el, eu, Ll = ts__surf_plane_at(lo, x, y, &el), Lu = ts__surf_plane_at(up, x, y, &eu);
    double g = Lu - Ll, t[10];
    if (fabs(g) > 2.0 * (el + eu))
        return (g > 0.0) - (g < 0.0);
    int n = plane_terms(up, x, y, 1.0, t), k = plane_terms(lo, x, y, -1.0, t + 5);
    return n && k ? ts__exact_sign(t, 10) : 0;
}

static int finite_plane(const ts_plane *pl)
{
    return isfinite(pl->p) && isfinite(pl->q) && isfinite(pl->c);
}

static int sloped(const ts_plane *pl)
{
    return pl->p != 0.0 || pl->q != 0.0;
}

/* Arguments and options (everything before the data). */
static ts_status check_options(const ts_surface_options *o, ts_error *err)
{
    if ((unsigned)o->form > TS_FORM_GEOMETRIC || (unsigned)o->slopes >= TS_SLOPES_COUNT_ ||
        o->slopes == TS_SLOPES_USER || o->slopes == TS_SLOPES_PERIODIC ||
        (unsigned)o->shape > TS_SURFACE_GRIDS)
        return ts__fail(err, TS_ERR_OPTION, TS_NO_INDEX, TS_WHERE_NONE);
    int sides = o->shape == TS_SURFACE_BOUNDS || o->shape == TS_SURFACE_PLANES ||
                o->shape == TS_SURFACE_GRIDS;
    if (sides && !o->has_lower && !o->has_upper)
        return ts__fail(err, TS_ERR_OPTION, TS_NO_INDEX, TS_WHERE_NONE);
    if (o->shape == TS_SURFACE_PLANES && o->form != TS_FORM_GEOMETRIC &&
        ((o->has_lower && sloped(&o->lower)) || (o->has_upper && sloped(&o->upper))))
        return ts__fail(err, TS_ERR_OPTION, TS_NO_INDEX, TS_WHERE_NONE);
    if (!ts__alpha_ok(o->alpha))
        return ts__fail(err, TS_ERR_ALPHA, TS_NO_INDEX, TS_WHERE_NONE);
    if (!ts__beta_ok(o->alpha, o->beta))
        return ts__fail(err, TS_ERR_BETA, TS_NO_INDEX, TS_WHERE_NONE);
    if (!ts__margin_ok(o->margin))
        return ts__fail(err, TS_ERR_MARGIN, TS_NO_INDEX, TS_WHERE_NONE);
    if (o->form == TS_FORM_GEOMETRIC && o->shape == TS_SURFACE_NONE &&
        !(o->alpha + o->beta >= TS_GEOMETRIC_A_MIN))
        return ts__fail(err, TS_ERR_GEOMETRIC, TS_NO_INDEX, TS_WHERE_NONE);
    if (sides && o->shape != TS_SURFACE_GRIDS && ((o->has_lower && !finite_plane(&o->lower)) ||
                  (o->has_upper && !finite_plane(&o->upper))))
        return ts__fail(err, TS_ERR_NONFINITE, TS_NO_INDEX, TS_WHERE_NONE);
    if (o->shape == TS_SURFACE_BOUNDS && o->has_lower && o->has_upper &&
        !(o->lower.c < o->upper.c))
        return ts__fail(err, TS_ERR_LINES, TS_NO_INDEX, TS_WHERE_NONE);
    return TS_OK;
}

/* finite and strictly increasing (every non-finite knot first, as
 * ts_spline_new); widths are not checked here: one that overflows or is
 * subnormal gives a non-finite slope or control value (TS_ERR_NONFINITE) */
static ts_status check_axis(const double *t, size_t np, ts_error *err)
{
    size_t at;
    ts_status st = ts__check_knots(t, t, np, DBL_MAX, 0.0, (double)INFINITY, &at);
    return st == TS_OK ? TS_OK : ts__fail(err, st, at, TS_WHERE_POINT);
}

/* docs/method.md §11.7: each side's field covers the surface's grid. */
static ts_status check_grids(const ts_surface_options *o, const double *x, size_t nxp,
                             const double *y, size_t nyp, ts_error *err)
{
    for (int side = 0; side < 2; side++) {
        size_t at;
        if (!(side ? o->has_upper : o->has_lower))
            continue;
        int w = ts__gb_check(side ? &o->upper_grid : &o->lower_grid, x[0], x[nxp - 1], y[0],
                             y[nyp - 1], &at);
        if (w == TS__GB_SIZE)
            return ts__fail(err, TS_ERR_OVERFLOW, TS_NO_INDEX, TS_WHERE_NONE);
        if (w != TS__GB_OK)
            return ts__fail(err, TS_ERR_BOUND_GRID, (size_t)side, TS_WHERE_NONE);
    }
    return TS_OK;
}

static size_t grid_doubles(const ts_grid_bound *g)
{
    return g->nx_points + g->ny_points + g->nx_points * g->ny_points;
}

/* The owned copy of a field into blk (grid_doubles of it). */
static void copy_grid(ts__gbound *d, const ts_grid_bound *g, double *blk)
{
    size_t nn = g->nx_points * g->ny_points;
    memcpy(blk, g->x, g->nx_points * sizeof(double));
    memcpy(blk + g->nx_points, g->y, g->ny_points * sizeof(double));
    memcpy(blk + g->nx_points + g->ny_points, g->z, nn * sizeof(double));
    d->nx = g->nx_points;
    d->ny = g->ny_points;
    d->x = blk;
    d->y = blk + g->nx_points;
    d->z = blk + g->nx_points + g->ny_points;
    double m = 0.0;
    for (size_t n = 0; n < nn; n++)
        m = fabs(d->z[n]) > m ? fabs(d->z[n]) : m;
    d->err = 32.0 * DBL_EPSILON * m + 8.0 * DBL_TRUE_MIN;
}

/* The grid lines of a and b strictly inside (lo, hi), with lo and hi, in
 * increasing order into out (na + nb + 2 room); their number. */
static size_t merge_lines(const double *a, size_t na, const double *b, size_t nb, double lo,
                          double hi, double *out)
{
    size_t k = 0, i = 0, j = 0;
    out[k++] = lo;
    while (i < na || j < nb) {
        double v = j >= nb || (i < na && a[i] <= b[j]) ? a[i++] : b[j++];
        if (lo < v && v < hi && v > out[k - 1])
            out[k++] = v;
    }
    out[k++] = hi;
    return k;
}

/* docs/method.md §11.7: the upper field above the lower one by more than
 * 5 (err_lo + err_up) at every node of the union of their grids and the
 * surface's border (both are bilinear on each cell of it, so is their
 * difference: then everywhere). */
ts_status ts__surf_grids_order(const ts__gbound *lo, const ts__gbound *up, double x0, double x1,
                               double y0, double y1, double *px, double *py, ts_error *err)
{
    size_t nx = lo->nx + up->nx + 2, ny = lo->ny + up->ny + 2;
    double *xs = ts__malloc((nx + ny) * sizeof(double));
    if (!xs)
        return ts__fail(err, TS_ERR_NOMEM, TS_NO_INDEX, TS_WHERE_NONE);
    double *ys = xs + nx, need = 5.0 * (lo->err + up->err);
    nx = merge_lines(lo->x, lo->nx, up->x, up->nx, x0, x1, xs);
    ny = merge_lines(lo->y, lo->ny, up->y, up->ny, y0, y1, ys);
    ts_status st = TS_OK;
    for (size_t b = 0; b < ny && st == TS_OK; b++)
        for (size_t a = 0; a < nx && st == TS_OK; a++)
            if (!(ts__gb_value(up, xs[a], ys[b]) - ts__gb_value(lo, xs[a], ys[b]) > need)) {
                if (px)
                    *px = xs[a];
                if (py)
                    *py = ys[b];
                st = ts__fail(err, TS_ERR_LINES, TS_NO_INDEX, TS_WHERE_NONE);
            }
    free(xs);
    return st;
}

/* The scheme's bounds into s (docs/method.md §11.3), then the nodes. */
static ts_status check_nodes(ts_surface *s, const ts_surface_options *o, const double *z,
                             ts_error *err)
{
    size_t np = s->nx + 1, nn = np * (s->ny + 1);
    double zmin = (double)INFINITY, zmax = -(double)INFINITY;
    for (size_t n = 0; n < nn; n++) {
        if (!isfinite(z[n]))
            return ts__fail(err, TS_ERR_NONFINITE, n, TS_WHERE_POINT);
        zmin = z[n] < zmin ? z[n] : zmin;
        zmax = z[n] > zmax ? z[n] : zmax;
    }
    ts_plane zero = {0.0, 0.0, 0.0};
    s->lower = s->upper = zero;
    s->has_lower = s->has_upper = 0;
    switch (o->shape) {
    case TS_SURFACE_POSITIVE:
        s->has_lower = 1;
        break;
    case TS_SURFACE_BOUNDS:
        s->has_lower = o->has_lower != 0;
        s->has_upper = o->has_upper != 0;
        s->lower.c = o->lower.c;
        s->upper.c = o->upper.c;
        break;
    case TS_SURFACE_PLANES:
        s->has_lower = o->has_lower != 0;
        s->has_upper = o->has_upper != 0;
        s->lower = o->lower;
        s->upper = o->upper;
        break;
    case TS_SURFACE_RANGE:
        s->has_lower = s->has_upper = 1;
        s->lower.c = zmin;
        s->upper.c = zmax;
        break;
    case TS_SURFACE_GRIDS:
        s->has_lower = o->has_lower != 0;
        s->has_upper = o->has_upper != 0;
        break;
    default:
        break;
    }
    if (o->shape == TS_SURFACE_GRIDS) {
        ts_status st;
        if (s->has_lower && s->has_upper &&
            (st = ts__surf_grids_order(&s->glo, &s->gup, s->x[0], s->x[s->nx], s->y[0],
                                       s->y[s->ny], NULL, NULL, err)) != TS_OK)
            return st;
        /* every node strictly between, decided exactly (2: undecidable) */
        for (size_t n = 0; n < nn; n++) {
            double xv = s->x[n % np], yv = s->y[n / np];
            if ((s->has_lower && ts__gb_side(&s->glo, xv, yv, z[n]) != 1) ||
                (s->has_upper && ts__gb_side(&s->gup, xv, yv, z[n]) != -1))
                return ts__fail(err, TS_ERR_SIDE, n, TS_WHERE_POINT);
        }
        return TS_OK;
    }
    int strict = o->shape == TS_SURFACE_PLANES;
    for (size_t n = 0, i = 0, j = 0; n < nn; n++, i = i + 1 == np ? 0 : i + 1, j += i == 0) {
        double xv = s->x[i], yv = s->y[j];
        if (o->shape == TS_SURFACE_POSITIVE && z[n] < 0.0)
            return ts__fail(err, TS_ERR_NEGATIVE, n, TS_WHERE_POINT);
        if (strict && s->has_lower && s->has_upper && plane_order(&s->lower, &s->upper, xv, yv) <= 0)
            return ts__fail(err, TS_ERR_LINES, n, TS_WHERE_POINT);
        int below = s->has_lower ? plane_side(z[n], &s->lower, xv, yv) : 1;
        int above = s->has_upper ? plane_side(z[n], &s->upper, xv, yv) : -1;
        if ((strict ? below <= 0 : below < 0) || (strict ? above >= 0 : above > 0))
            return ts__fail(err, TS_ERR_SIDE, n, TS_WHERE_POINT);
    }
    return TS_OK;
}

/* Partial slopes along every grid line: d[j*np + i] = slope in x of row j
 * (dir 0), or in y of column i (dir 1), of the node values v. */
static ts_status line_slopes(const ts_surface *s, ts_slopes method, int dir, const double *v,
                             double *d, double *tmp, ts_error *err)
{
    size_t np = s->nx + 1, nq = s->ny + 1;
    size_t lines = dir ? np : nq, len = dir ? nq : np;
    const double *t = dir ? s->y : s->x;
    for (size_t L = 0; L < lines; L++) {
        /* a row in place; a column through tmp */
        const double *f = dir ? tmp : v + L * np;
        double *g = dir ? tmp + len : d + L * np;
        for (size_t k = 0; dir && k < len; k++)
            tmp[k] = v[k * np + L];
        ts_error e;
        if (ts__slopes(method, t, f, len, g, &e) != TS_OK)
            return ts__fail(err, TS_ERR_NONFINITE, dir ? e.index * np + L : L * np + e.index,
                            TS_WHERE_POINT);
        for (size_t k = 0; dir && k < len; k++)
            d[k * np + L] = g[k];
    }
    return TS_OK;
}

/* The same without the check (twists: their sum is checked), for the two
 * uses r needs: rows (dir 0) straight into d; columns (dir 1) as the mean
 * 0.5 (d + slope) of what d holds and the slopes. */
static void line_slopes_raw(const ts_surface *s, ts_slopes method, int dir, const double *v,
                            double *d, double *tmp)
{
    size_t np = s->nx + 1, nq = s->ny + 1;
    if (!dir) {
        for (size_t L = 0; L < nq; L++)
            ts__slopes_range(method, s->x, v + L * np, np, d + L * np, 0, np);
        return;
    }
    double *f = tmp, *g = tmp + nq;
    for (size_t L = 0; L < np; L++) {
        for (size_t k = 0; k < nq; k++)
            f[k] = v[k * np + L];
        ts__slopes_range(method, s->y, f, nq, g, 0, nq);
        for (size_t k = 0; k < nq; k++)
            d[k * np + L] = 0.5 * (d[k * np + L] + g[k]);
    }
}

/* docs/method.md §11.3: a node on a constant bound (gap 0) needs slopes that
 * point into the region: 0 inside, one-signed at the grid's edges. */
static double clamp_touch(double d, size_t idx, size_t n, double into)
{
    if (idx == 0)
        return into * d > 0.0 ? d : 0.0;
    if (idx == n)
        return into * d < 0.0 ? d : 0.0;
    return 0.0;
}

static void touch_slopes(ts_surface *s)
{
    size_t np = s->nx + 1, nn = np * (s->ny + 1);
    if (s->shape == TS_SURFACE_GRIDS) /* nodes strictly inside */
        return;
    for (size_t n = 0, i = 0, j = 0; n < nn; n++, i = i + 1 == np ? 0 : i + 1, j += i == 0) {
        for (int side = 0; side < 2; side++) {
            int has = side ? s->has_upper : s->has_lower;
            double c = side ? s->upper.c : s->lower.c;
            if (has && s->z[n] == c) {
                double into = side ? -1.0 : 1.0;
                s->p[n] = clamp_touch(s->p[n], i, s->nx, into);
                s->q[n] = clamp_touch(s->q[n], j, s->ny, into);
            }
        }
    }
}

/* The gap of node n to side (0 lower, 1 upper) and the slopes relative to
 * the plane, all with the sign that makes "inside" positive.  A field
 * (docs/method.md §11.7): its rounded value, and its secants along the
 * edges of patch (pi, pj) through the node as its slopes. */
static void field_gap(const ts_surface *s, size_t n, int side, size_t pi, size_t pj, double *g,
                      double *pp, double *qq)
{
    size_t np = s->nx + 1;
    double sg = side ? -1.0 : 1.0;
    const ts__gbound *f = side ? &s->gup : &s->glo;
    double xv = s->x[n % np], yv = s->y[n / np];
    double bx = (ts__gb_value(f, s->x[pi + 1], yv) - ts__gb_value(f, s->x[pi], yv)) /
                (s->x[pi + 1] - s->x[pi]);
    double by = (ts__gb_value(f, xv, s->y[pj + 1]) - ts__gb_value(f, xv, s->y[pj])) /
                (s->y[pj + 1] - s->y[pj]);
    *g = sg * (s->z[n] - ts__gb_value(f, xv, yv));
    *pp = sg * (s->p[n] - bx);
    *qq = sg * (s->q[n] - by);
}

static inline void node_gap(const ts_surface *s, size_t n, int side, size_t pi, size_t pj,
                            double *g, double *pp, double *qq)
{
    if (s->shape == TS_SURFACE_GRIDS) {
        field_gap(s, n, side, pi, pj, g, pp, qq);
        return;
    }
    size_t np = s->nx + 1;
    const ts_plane *pl = side ? &s->upper : &s->lower;
    double sg = side ? -1.0 : 1.0;
    /* a constant plane's value is c + 0 at every finite point (ts__surf_plane_at) */
    double L = pl->p == 0.0 && pl->q == 0.0 ? pl->c + 0.0
                                            : plane_at(pl, s->x[n % np], s->y[n / np]);
    *g = sg * (s->z[n] - L);
    *pp = sg * (s->p[n] - pl->p);
    *qq = sg * (s->q[n] - pl->q);
}

/* The need of one edge term d at a node with gap g (docs/method.md §11.3):
 * the inward term ±k d' must keep at least half the gap, so T rises to
 * 2K(−d)/g; 0 where a would pass 1e300 (refused as in 1-D, §5.7: a gap
 * near the underflow threshold). */
static int need_of(double K, double d, double g, double *T)
{
    if (d < 0.0) {
        if (2.0 * K * -d > 1e300 * g)
            return 0;
        double need = 2.0 * K * -d / g;
        *T = need > *T ? need : *T;
    }
    return 1;
}

/* a from the need T: the margin additive as in 1-D and relative on the
 * rule's value, so that F of (11.4) keeps t/(1 + t) of the gap however
 * large a is. */
static double rule_a(const ts_surface_options *o, double T)
{
    T *= 1.0 + o->margin;
    double a = o->margin + (T > o->alpha ? T : o->alpha);
    return o->form == TS_FORM_GEOMETRIC && a < TS_GEOMETRIC_A_RAISE ? TS_GEOMETRIC_A_RAISE : a;
}

/* docs/method.md §11.3: a^x_i (dir 0) or a^y_j (dir 1) of the scheme
 * against fields (their slopes depend on the patch). */
static ts_status scheme_a(ts_surface *s, const ts_surface_options *o, int dir, ts_error *err)
{
    size_t np = s->nx + 1, n = dir ? s->ny : s->nx, lines = dir ? s->nx + 1 : s->ny + 1;
    const double *t = dir ? s->y : s->x;
    double *a = dir ? s->ay : s->ax;
    for (size_t i = 0; i < n; i++) {
        double K = ts__geo_K(t[i + 1] - t[i]), T = 0.0;
        for (size_t L = 0; L < lines; L++) {
            for (int end = 0; end < 2; end++) {
                size_t node = dir ? (i + (size_t)end) * np + L : L * np + i + (size_t)end;
                for (int side = 0; side < 2; side++) {
                    if (!(side ? s->has_upper : s->has_lower))
                        continue;
                    double g, pp, qq;
                    size_t pl = L < lines - 1 ? L : lines - 2;
                    node_gap(s, node, side, dir ? pl : i, dir ? i : pl, &g, &pp, &qq);
                    if (!need_of(K, (end ? -1.0 : 1.0) * (dir ? qq : pp), g, &T))
                        return ts__fail(err, TS_ERR_INFEASIBLE,
                                        dir ? i * s->nx + pl : pl * s->nx + i,
                                        TS_WHERE_INTERVAL);
                }
            }
        }
        a[i] = rule_a(o, T);
    }
    return TS_OK;
}

/* The same against planes and constants, whose gaps at a node are the same
 * for all its patches: one pass over the nodes in memory order, both
 * directions, each node's gaps formed once (T accumulated in ax, ay; the
 * maximum does not depend on the order).  The refusal is the one scheme_a
 * meets first: x before y, the least interval, then the least line. */
static ts_status scheme_a_nodes(ts_surface *s, const ts_surface_options *o, ts_error *err)
{
    size_t nx = s->nx, ny = s->ny, np = nx + 1;
    size_t bad[2][2] = {{SIZE_MAX, 0}, {SIZE_MAX, 0}}; /* per direction: interval, line */
    for (size_t i = 0; i < nx; i++)
        s->ax[i] = 0.0;
    for (size_t j = 0; j < ny; j++)
        s->ay[j] = 0.0;
    for (size_t j = 0; j <= ny; j++) {
        double Ky0 = j < ny ? ts__geo_K(s->y[j + 1] - s->y[j]) : 0.0;
        double Ky1 = j > 0 ? ts__geo_K(s->y[j] - s->y[j - 1]) : 0.0;
        for (size_t i = 0; i <= nx; i++) {
            double Kx0 = i < nx ? ts__geo_K(s->x[i + 1] - s->x[i]) : 0.0;
            double Kx1 = i > 0 ? ts__geo_K(s->x[i] - s->x[i - 1]) : 0.0;
            for (int side = 0; side < 2; side++) {
                if (!(side ? s->has_upper : s->has_lower))
                    continue;
                double g, pp, qq;
                node_gap(s, j * np + i, side, 0, 0, &g, &pp, &qq);
                /* (interval, line) of each end of the node's four edges */
                size_t e[4][3] = {{0, i, j}, {0, i - 1, j}, {1, j, i}, {1, j - 1, i}};
                int ok[4] = {i < nx ? need_of(Kx0, 1.0 * pp, g, &s->ax[i]) : 1,
                             i > 0 ? need_of(Kx1, -1.0 * pp, g, &s->ax[i - 1]) : 1,
                             j < ny ? need_of(Ky0, 1.0 * qq, g, &s->ay[j]) : 1,
                             j > 0 ? need_of(Ky1, -1.0 * qq, g, &s->ay[j - 1]) : 1};
                for (int k = 0; !(ok[0] && ok[1] && ok[2] && ok[3]) && k < 4; k++) {
                    size_t *b = bad[e[k][0]];
                    if (!ok[k] && (e[k][1] < b[0] || (e[k][1] == b[0] && e[k][2] < b[1]))) {
                        b[0] = e[k][1];
                        b[1] = e[k][2];
                    }
                }
            }
        }
    }
    if (bad[0][0] != SIZE_MAX) /* the last line's nodes belong to the patches before it */
        return ts__fail(err, TS_ERR_INFEASIBLE,
                        (bad[0][1] < ny ? bad[0][1] : ny - 1) * nx + bad[0][0], TS_WHERE_INTERVAL);
    if (bad[1][0] != SIZE_MAX)
        return ts__fail(err, TS_ERR_INFEASIBLE,
                        bad[1][0] * nx + (bad[1][1] < nx ? bad[1][1] : nx - 1), TS_WHERE_INTERVAL);
    for (size_t i = 0; i < nx; i++)
        s->ax[i] = rule_a(o, s->ax[i]);
    for (size_t j = 0; j < ny; j++)
        s->ay[j] = rule_a(o, s->ay[j]);
    return TS_OK;
}

/* fmax and fmin as glibc's x86-64 ones: the second argument where they are
 * equal (±0), the first where the second is NaN; written as the compare
 * and select that SSE's maxsd / minsd are, then the NaN's select, so that
 * no branch is taken on the data (a random one of the twist's bounds
 * binds) */
static double max_of(double a, double b)
{
    double m = a > b ? a : b; /* b where equal or unordered */
    return b == b ? m : a;
}
static double min_of(double a, double b)
{
    double m = a < b ? a : b;
    return b == b ? m : a;
}

/* The bound of one patch and side on a node's twist (c r >= -F/2, F of
 * docs/method.md §11.3): into lo where c > 0, hi where c < 0. */
static inline void twist_bound(double g, double pp, double qq, double sg, double sx, double sy,
                               double ux, double uy, double *lo, double *hi)
{
    double F = g + sx * ux * pp + sy * uy * qq;
    double c = sg * sx * sy * ux * uy, v = -0.5 * F / c;
    if (c > 0.0)
        *lo = max_of(*lo, v);
    if (c < 0.0)
        *hi = min_of(*hi, v);
}

/* The twists' clamp below against planes and constants, whose gaps at a
 * node are the same for its patches: the same bounds in the same order
 * (patch (i, j), (i, j − 1), (i − 1, j), (i − 1, j − 1); lower side before
 * upper), unrolled, the sides' presence hoisted (lower: 1, upper: 2). */
static inline void clamp_row(ts_surface *s, const double *kx, double ky0, double ky1, size_t j,
                             int sides)
{
    size_t nx = s->nx, ny = s->ny, n = j * (nx + 1);
    int up = j > 0, down = j < ny;
    for (size_t i = 0; i <= nx; i++, n++) {
        double lo = -(double)INFINITY, hi = (double)INFINITY;
        double g0 = 0.0, p0 = 0.0, q0 = 0.0, g1 = 0.0, p1 = 0.0, q1 = 0.0;
        if (sides & 1)
            node_gap(s, n, 0, 0, 0, &g0, &p0, &q0);
        if (sides & 2)
            node_gap(s, n, 1, 0, 0, &g1, &p1, &q1);
        if (i < nx) {
            double ux = kx[i];
            if (down) {
                if (sides & 1)
                    twist_bound(g0, p0, q0, 1.0, 1.0, 1.0, ux, ky0, &lo, &hi);
                if (sides & 2)
                    twist_bound(g1, p1, q1, -1.0, 1.0, 1.0, ux, ky0, &lo, &hi);
            }
            if (up) {
                if (sides & 1)
                    twist_bound(g0, p0, q0, 1.0, 1.0, -1.0, ux, ky1, &lo, &hi);
                if (sides & 2)
                    twist_bound(g1, p1, q1, -1.0, 1.0, -1.0, ux, ky1, &lo, &hi);
            }
        }
        if (i > 0) {
            double ux = kx[i - 1];
            if (down) {
                if (sides & 1)
                    twist_bound(g0, p0, q0, 1.0, -1.0, 1.0, ux, ky0, &lo, &hi);
                if (sides & 2)
                    twist_bound(g1, p1, q1, -1.0, -1.0, 1.0, ux, ky0, &lo, &hi);
            }
            if (up) {
                if (sides & 1)
                    twist_bound(g0, p0, q0, 1.0, -1.0, -1.0, ux, ky1, &lo, &hi);
                if (sides & 2)
                    twist_bound(g1, p1, q1, -1.0, -1.0, -1.0, ux, ky1, &lo, &hi);
            }
        }
        double r = s->r[n], in = r > hi ? hi : r;
        s->r[n] = ts__pick(r < lo, lo, in); /* r < lo ? lo : (r > hi ? hi : r) */
    }
}

static void clamp_twists_planes(ts_surface *s, const double *kx, const double *ky)
{
    int sides = (s->has_lower ? 1 : 0) | (s->has_upper ? 2 : 0);
    for (size_t j = 0; j <= s->ny; j++) {
        double ky0 = j < s->ny ? ky[j] : 0.0, ky1 = j > 0 ? ky[j - 1] : 0.0;
        if (sides == 1)
            clamp_row(s, kx, ky0, ky1, j, 1);
        else if (sides == 2)
            clamp_row(s, kx, ky0, ky1, j, 2);
        else
            clamp_row(s, kx, ky0, ky1, j, 3);
    }
}

/* docs/method.md §11.3: clamp every twist so that on each of its patches the
 * inner control gap keeps at least half of what the edges leave.  k: nx + ny
 * scratch doubles (each interval's k, formed once). */
static void clamp_twists(ts_surface *s, double *k)
{
    double *kx = k, *ky = k + s->nx;
    for (size_t i = 0; i < s->nx; i++)
        kx[i] = ts__geo_k(s->x[i + 1] - s->x[i], s->ax[i]);
    for (size_t j = 0; j < s->ny; j++)
        ky[j] = ts__geo_k(s->y[j + 1] - s->y[j], s->ay[j]);
    if (s->shape != TS_SURFACE_GRIDS) {
        clamp_twists_planes(s, kx, ky);
        return;
    }
    for (size_t j = 0, n = 0; j <= s->ny; j++) {
        for (size_t i = 0; i <= s->nx; i++, n++) {
            double lo = -(double)INFINITY, hi = (double)INFINITY;
            for (int cx = 0; cx < 2; cx++) {
                if (cx ? i == 0 : i == s->nx)
                    continue;
                for (int cy = 0; cy < 2; cy++) {
                    /* patch (i - cx, j - cy); the node is its corner (cx, cy) */
                    if (cy ? j == 0 : j == s->ny)
                        continue;
                    size_t pi = i - (size_t)cx, pj = j - (size_t)cy;
                    double sx = cx ? -1.0 : 1.0, sy = cy ? -1.0 : 1.0;
                    for (int side = 0; side < 2; side++) {
                        if (!(side ? s->has_upper : s->has_lower))
                            continue;
                        /* a field's slopes depend on the patch (§11.7) */
                        double g, pp, qq;
                        node_gap(s, n, side, pi, pj, &g, &pp, &qq);
                        twist_bound(g, pp, qq, side ? -1.0 : 1.0, sx, sy, kx[pi], ky[pj], &lo,
                                    &hi);
                    }
                }
            }
            s->r[n] = s->r[n] < lo ? lo : (s->r[n] > hi ? hi : s->r[n]);
        }
    }
}

/* Are the control gaps of patch c with net B inside every side
 * (docs/method.md §11.3)? */
static int patch_inside(const ts_surface *s, size_t c, const double B[16])
{
    for (int side = 0; side < 2; side++) {
        if (!(side ? s->has_upper : s->has_lower))
            continue;
        if (s->shape == TS_SURFACE_GRIDS) { /* docs/method.md §11.7 */
            double pv, sv, ax, ay;
            if (!ts__surf_certify_grid(s, c % s->nx, c / s->nx, side ? &s->gup : &s->glo,
                                       1 - 2 * side, &pv, &sv, &ax, &ay))
                return 0;
            continue;
        }
        double G[16], guard;
        ts__surf_gaps(s, c % s->nx, c / s->nx, B, side ? &s->upper : &s->lower, 1 - 2 * side, G,
                      &guard);
        if (!ts__surf_gaps_inside(G, guard))
            return 0;
    }
    return 1;
}

/* docs/method.md §11.6: every patch's net must be finite (TS_ERR_NONFINITE
 * at the first that is not); where rounding leaves a patch's control values
 * on or across a side, raise a^x and a^y of its column and row tenfold (at
 * most REPAIR_ROUNDS times, a <= 1e300) and clamp the twists again, until
 * every patch is proven; else TS_ERR_INFEASIBLE at the first patch that is
 * not.  Each net is formed once per round (ts__surf_patch).  flag: 3 (nx +
 * ny) scratch doubles. */
#define REPAIR_ROUNDS 12
static ts_status repair(ts_surface *s, double *flag, ts_error *err)
{
    size_t nx = s->nx, ny = s->ny;
    /* fields: the certificate of §11.7 failing is no proof of infeasibility */
    ts_status fail = s->shape == TS_SURFACE_GRIDS ? TS_ERR_UNPROVEN : TS_ERR_INFEASIBLE;
    /* constant sides: ts__surf_gaps gives B − c (c − B) with guard 0, whose
     * sign is that of B − c for finite B: compared directly */
    const ts_plane *lo = s->has_lower ? &s->lower : NULL, *up = s->has_upper ? &s->upper : NULL;
    int constant = s->shape != TS_SURFACE_GRIDS && !(lo && sloped(lo)) && !(up && sloped(up));
    double *ks = flag + nx + ny; /* each interval's k at its ends (ts__surf_ks), per round;
                                    those of the round that returns TS_OK are s->ks */
    double cl = lo ? lo->c : -(double)INFINITY, cu = up ? up->c : (double)INFINITY;
    for (int round = 0;; round++) {
        size_t bad = SIZE_MAX;
        for (size_t k = 0; k < nx + ny; k++) {
            flag[k] = 0.0;
            ts__surf_ks(s, k >= nx, k < nx ? k : k - nx, ks + 2 * k);
        }
        for (size_t c = 0, i = 0, j = 0; c < nx * ny;
             c++, i = i + 1 == nx ? 0 : i + 1, j += i == 0) {
            double B[16];
            ts__surf_patch_k(s, i, j, ks + 2 * i, ks + 2 * (nx + j), B);
            /* zero: NaN unless every B[k] is finite (in any order of the
             * sums); mn, mx: the least and greatest (their compares with the
             * sides do not depend on which zero where ±0 tie): four lanes */
            double zero[4] = {0.0, 0.0, 0.0, 0.0}, mn[4], mx[4];
            for (size_t l = 0; l < 4; l++)
                mn[l] = mx[l] = B[l];
            for (size_t k = 0; k < 16; k += 4) {
                for (size_t l = 0; l < 4; l++) {
                    zero[l] += 0.0 * B[k + l];
                    mn[l] = B[k + l] < mn[l] ? B[k + l] : mn[l];
                    mx[l] = B[k + l] > mx[l] ? B[k + l] : mx[l];
                }
            }
            int in = (mn[0] >= cl) & (mn[1] >= cl) & (mn[2] >= cl) & (mn[3] >= cl) &
                     (mx[0] <= cu) & (mx[1] <= cu) & (mx[2] <= cu) & (mx[3] <= cu);
            if ((zero[0] + zero[1]) + (zero[2] + zero[3]) != 0.0)
                return ts__fail(err, TS_ERR_NONFINITE, c, TS_WHERE_INTERVAL);
            if (bad == SIZE_MAX || flag[i] == 0.0 || flag[nx + j] == 0.0) {
                if (!(constant ? in : patch_inside(s, c, B))) {
                    bad = bad == SIZE_MAX ? c : bad;
                    flag[i] = flag[nx + j] = 1.0;
                }
            }
        }
        if (bad == SIZE_MAX)
            return TS_OK;
        if (round == REPAIR_ROUNDS)
            return ts__fail(err, fail, bad, TS_WHERE_INTERVAL);
        for (size_t k = 0; k < nx + ny; k++) {
            double *a = k < nx ? s->ax + k : s->ay + (k - nx);
            if (flag[k] != 0.0) {
                if (!(*a * 10.0 <= 1e300))
                    return ts__fail(err, fail, bad, TS_WHERE_INTERVAL);
                *a *= 10.0;
            }
        }
        clamp_twists(s, flag); /* the flags are spent */
    }
}

static void release(ts_surface *s)
{
    if (!s)
        return;
    free(s->x);
    free(s->gblk);
    free(s);
}

ts_status ts_surface_new(const double *x, size_t nx_points, const double *y, size_t ny_points,
                         const double *z, const ts_surface_options *opt, ts_surface **out,
                         ts_error *err)
{
    ts__error_set(err, TS_OK, TS_NO_INDEX, TS_WHERE_NONE);
    if (out)
        *out = NULL;
    if (!x || !y || !z || !out)
        return ts__fail(err, TS_ERR_NULL, TS_NO_INDEX, TS_WHERE_NONE);
    if (opt && opt->struct_size != sizeof *opt)
        return ts__fail(err, TS_ERR_VERSION, TS_NO_INDEX, TS_WHERE_NONE);
    if (nx_points < 2 || ny_points < 2)
        return ts__fail(err, TS_ERR_TOO_FEW, TS_NO_INDEX, TS_WHERE_NONE);
    ts_surface_options def;
    defaults(&def);
    const ts_surface_options *o = opt ? opt : &def;
    ts_status st = check_options(o, err);
    if (st != TS_OK)
        return st;
    /* 4 (nx+1)(ny+1) + 10 max(nx+1, ny+1) doubles <= 32 (nx+1)(ny+1) */
    if (ny_points > SIZE_MAX / 32 / sizeof(double) / nx_points)
        return ts__fail(err, TS_ERR_OVERFLOW, TS_NO_INDEX, TS_WHERE_NONE);
    if ((st = check_axis(x, nx_points, err)) != TS_OK ||
        (st = check_axis(y, ny_points, err)) != TS_OK)
        return st;
    int grids = o->shape == TS_SURFACE_GRIDS;
    if (grids && (st = check_grids(o, x, nx_points, y, ny_points, err)) != TS_OK)
        return st;
    size_t nx = nx_points - 1, ny = ny_points - 1, nn = nx_points * ny_points;
    size_t total = nx_points + ny_points + 4 * nn + nx + ny + 3 * (nx_points + ny_points);
    ts_surface *s = ts__calloc(1, sizeof *s);
    double *blk = s ? ts__alloc_block(total * sizeof(double)) : NULL;
    if (!blk) {
        free(s);
        return ts__fail(err, TS_ERR_NOMEM, TS_NO_INDEX, TS_WHERE_NONE);
    }
    if (grids) {
        size_t gl = o->has_lower ? grid_doubles(&o->lower_grid) : 0;
        size_t gu = o->has_upper ? grid_doubles(&o->upper_grid) : 0;
        s->gblk = ts__malloc((gl + gu) * sizeof(double));
        if (!s->gblk) {
            free(blk);
            release(s);
            return ts__fail(err, TS_ERR_NOMEM, TS_NO_INDEX, TS_WHERE_NONE);
        }
        if (o->has_lower)
            copy_grid(&s->glo, &o->lower_grid, s->gblk);
        if (o->has_upper)
            copy_grid(&s->gup, &o->upper_grid, s->gblk + gl);
    }
    s->nx = nx;
    s->ny = ny;
    s->form = o->form;
    s->shape = o->shape;
    s->x = blk;
    s->y = s->x + nx_points;
    s->z = s->y + ny_points;
    s->p = s->z + nn;
    s->q = s->p + nn;
    s->r = s->q + nn;
    s->ax = s->r + nn;
    s->ay = s->ax + nx;
    double *tmp = s->ay + ny;
    memcpy(s->x, x, nx_points * sizeof(double));
    memcpy(s->y, y, ny_points * sizeof(double));
    if ((st = check_nodes(s, o, z, err)) != TS_OK)
        goto fail;
    memcpy(s->z, z, nn * sizeof(double));
    if ((st = line_slopes(s, o->slopes, 0, s->z, s->p, tmp, err)) != TS_OK ||
        (st = line_slopes(s, o->slopes, 1, s->z, s->q, tmp, err)) != TS_OK)
        goto fail;
    if (o->zero_twist) {
        for (size_t n = 0; n < nn; n++)
            s->r[n] = 0.0;
    } else {
        /* r = (∂q/∂x + ∂p/∂y)/2: symmetric under transposition */
        line_slopes_raw(s, o->slopes, 0, s->q, s->r, tmp);
        line_slopes_raw(s, o->slopes, 1, s->p, s->r, tmp);
        for (size_t n = 0; n < nn; n++) {
            if (!isfinite(s->r[n])) {
                st = ts__fail(err, TS_ERR_NONFINITE, n, TS_WHERE_POINT);
                goto fail;
            }
        }
    }
    if (o->shape == TS_SURFACE_NONE) {
        for (size_t i = 0; i < nx; i++)
            s->ax[i] = o->alpha + o->beta;
        for (size_t j = 0; j < ny; j++)
            s->ay[j] = o->alpha + o->beta;
    } else {
        touch_slopes(s);
        if (grids ? (st = scheme_a(s, o, 0, err)) != TS_OK || (st = scheme_a(s, o, 1, err)) != TS_OK
                  : (st = scheme_a_nodes(s, o, err)) != TS_OK)
            goto fail;
        clamp_twists(s, tmp);
    }
    if ((st = repair(s, tmp, err)) != TS_OK)
        goto fail;
    s->ks = tmp + nx + ny; /* the last round's, of the final a */
    s->certified = o->shape != TS_SURFACE_NONE;
    *out = s;
    return TS_OK;
fail:
    release(s);
    return st;
}

void ts_surface_free(ts_surface *s)
{
    release(s);
}

size_t ts_surface_nx(const ts_surface *s) { return s->nx; }
size_t ts_surface_ny(const ts_surface *s) { return s->ny; }
const double *ts_surface_x(const ts_surface *s) { return s->x; }
const double *ts_surface_y(const ts_surface *s) { return s->y; }
const double *ts_surface_z(const ts_surface *s) { return s->z; }
const double *ts_surface_dzdx(const ts_surface *s) { return s->p; }
const double *ts_surface_dzdy(const ts_surface *s) { return s->q; }
const double *ts_surface_twist(const ts_surface *s) { return s->r; }
const double *ts_surface_ax(const ts_surface *s) { return s->ax; }
const double *ts_surface_ay(const ts_surface *s) { return s->ay; }
ts_form ts_surface_form(const ts_surface *s) { return s->form; }
ts_surface_shape ts_surface_shape_of(const ts_surface *s) { return s->shape; }
int ts_surface_certified(const ts_surface *s) { return s->certified; }

/* The patch's place, parameters and control values. */
static void report_head(const ts_surface *s, size_t i, size_t j, ts_patch_report *rep)
{
    rep->i = i;
    rep->j = j;
    rep->x0 = s->x[i];
    rep->x1 = s->x[i + 1];
    rep->y0 = s->y[j];
    rep->y1 = s->y[j + 1];
    rep->ax = s->ax[i];
    rep->ay = s->ay[j];
    ts__surf_patch(s, i, j, rep->B);
}

/* A patch against the planes lower, upper (NULL: none). */
static void report_patch(const ts_surface *s, size_t i, size_t j, const ts_plane *lower,
                         const ts_plane *upper, ts_patch_report *rep)
{
    report_head(s, i, j, rep);
    rep->has_lower = lower != NULL;
    rep->has_upper = upper != NULL;
    int ok = lower || upper;
    if (lower)
        ok &= ts__surf_certify_patch(s, i, j, lower, 1, &rep->proven_lower, &rep->sampled_lower,
                                     &rep->at_lower[0], &rep->at_lower[1]);
    if (upper)
        ok &= ts__surf_certify_patch(s, i, j, upper, -1, &rep->proven_upper,
                                     &rep->sampled_upper, &rep->at_upper[0], &rep->at_upper[1]);
    rep->certified = ok;
}

/* A patch of a surface between gridded fields against its own fields. */
static void report_fields(const ts_surface *s, size_t i, size_t j, ts_patch_report *rep)
{
    report_head(s, i, j, rep);
    rep->has_lower = s->has_lower;
    rep->has_upper = s->has_upper;
    int ok = 1;
    if (s->has_lower)
        ok &= ts__surf_certify_grid(s, i, j, &s->glo, 1, &rep->proven_lower, &rep->sampled_lower,
                                    &rep->at_lower[0], &rep->at_lower[1]);
    if (s->has_upper)
        ok &= ts__surf_certify_grid(s, i, j, &s->gup, -1, &rep->proven_upper,
                                    &rep->sampled_upper, &rep->at_upper[0], &rep->at_upper[1]);
    rep->certified = ok;
}

static void report_reset(ts_patch_report *rep)
{
    memset(rep, 0, sizeof *rep);
    rep->struct_size = sizeof *rep;
    rep->x0 = rep->x1 = rep->y0 = rep->y1 = rep->ax = rep->ay = (double)NAN;
    for (int k = 0; k < 16; k++)
        rep->B[k] = (double)NAN;
    rep->proven_lower = rep->sampled_lower = rep->at_lower[0] = rep->at_lower[1] = (double)NAN;
    rep->proven_upper = rep->sampled_upper = rep->at_upper[0] = rep->at_upper[1] = (double)NAN;
}

void ts_patch_report_init(ts_patch_report *reports, size_t n)
{
    for (size_t c = 0; reports && c < n; c++)
        report_reset(&reports[c]);
}

ts_status ts_surface_report(const ts_surface *s, size_t i, size_t j, ts_patch_report *rep)
{
    if (!rep)
        return TS_ERR_NULL;
    if (rep->struct_size != sizeof *rep)
        return TS_ERR_VERSION; /* a struct of another layout: not written */
    report_reset(rep);
    if (!s)
        return TS_ERR_NULL;
    if (i >= s->nx || j >= s->ny)
        return TS_ERR_INDEX;
    if (s->shape == TS_SURFACE_GRIDS) /* the fields: has_lower / has_upper say which */
        report_fields(s, i, j, rep);
    else
        report_patch(s, i, j, s->has_lower ? &s->lower : NULL, s->has_upper ? &s->upper : NULL,
                     rep);
    return TS_OK;
}

ts_status ts_surface_certify(const ts_surface *s, const ts_plane *lower, const ts_plane *upper,
                             ts_patch_report *reports, ts_error *err)
{
    ts__error_set(err, TS_OK, TS_NO_INDEX, TS_WHERE_NONE);
    if (reports && reports[0].struct_size != sizeof *reports)
        return ts__fail(err, TS_ERR_VERSION, TS_NO_INDEX, TS_WHERE_NONE);
    if (!s)
        return ts__fail(err, TS_ERR_NULL, TS_NO_INDEX, TS_WHERE_NONE);
    size_t np = s->nx * s->ny;
    if (reports)
        for (size_t c = 0; c < np; c++)
            report_reset(&reports[c]);
    if (!lower && !upper)
        return ts__fail(err, TS_ERR_NULL, TS_NO_INDEX, TS_WHERE_NONE);
    if ((lower && !finite_plane(lower)) || (upper && !finite_plane(upper)))
        return ts__fail(err, TS_ERR_NONFINITE, TS_NO_INDEX, TS_WHERE_NONE);
    ts_status st = TS_OK;
    for (size_t c = 0; c < np; c++) {
        ts_patch_report r;
        report_reset(&r); /* an absent side's numbers NaN, as the header says */
        report_patch(s, c % s->nx, c / s->nx, lower, upper, &r);
        if (reports)
            reports[c] = r;
        if (!r.certified && st == TS_OK)
            st = ts__fail(err, TS_ERR_VIOLATED, c, TS_WHERE_INTERVAL);
    }
    return st;
}
