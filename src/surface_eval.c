/* docs/method.md §11: evaluating a surface (points, batches, grids), its
 * integral over a rectangle, its control nets.  No allocation. */
#include "internal.h"

#include <math.h>
#include <stdint.h>

static int inside(const double *t, size_t n, double v)
{
    return t[0] <= v && v <= t[n];
}

static void set_nan(double *v)
{
    if (v)
        *v = (double)NAN;
}

/* Is sg (v − plane(x, y)) > 0, exactly?  By the accurate plane value where
 * v is farther from it than twice its error bound, else by the exact sum
 * (p x = P + e, q y = Q + f by fma); -1 where undecidable (a term beyond
 * ts__exact_sign's range). */
static int strictly_beyond(const ts_plane *pl, double x, double y, double v, double sg)
{
    double err, L = ts__surf_plane_at(pl, x, y, &err), g = sg * (v - L), t[6];
    if (fabs(g) > 2.0 * err)
        return g > 0.0;
    if (!ts__exact_product(pl->p, x, -sg, t) || !ts__exact_product(pl->q, y, -sg, t + 2) ||
        !(fabs(pl->c) <= 0x1p1020) || !(fabs(v) <= 0x1p1020))
        return -1;
    t[4] = -sg * pl->c;
    t[5] = sg * v;
    return ts__exact_sign(t, 6) > 0;
}

/* v moved strictly beyond a plane (sg = +1: above the lower, −1: below the
 * upper) where rounding put it on or across it, or where its side cannot
 * be decided (a term beyond the exact sum's range): the nearest doubles
 * beyond the plane's rounded value, then that value moved by 4 of its error
 * bounds (docs/method.md §11.5, "Values inside the region"). */
static double beyond_plane(const ts_plane *pl, double x, double y, double v, double sg)
{
    if (strictly_beyond(pl, x, y, v, sg) == 1)
        return v;
    double err, r = ts__surf_plane_at(pl, x, y, &err);
    for (int k = 0; k < 4; k++) {
        if (strictly_beyond(pl, x, y, r, sg) == 1)
            return r;
        r = nextafter(r, sg * (double)INFINITY);
    }
    r = ts__surf_plane_at(pl, x, y, NULL) + sg * 4.0 * err;
    return strictly_beyond(pl, x, y, r, sg) == 1 ? r : v;
}

/* v strictly beyond a field (sg = +1: above the lower, −1: below the
 * upper), docs/method.md §11.7: kept where it is beyond the field's rounded
 * value by more than its error bound, or exactly beyond it (decided
 * exactly); else the rounded value moved by its error bound and one ulp. */
static double beyond_grid(const ts__gbound *g, double x, double y, double v, double sg)
{
    double b = ts__gb_value(g, x, y);
    double t = nextafter(b + sg * g->err, sg * (double)INFINITY); /* sg (t − field) > 0 */
    if (sg * (v - t) >= 0.0)
        return v;
    int side = ts__gb_side(g, x, y, v);
    return side != 2 && sg * side > 0.0 ? v : t;
}

/* A value of a certified surface in its region (docs/method.md §11.5):
 * the exact surface at the point evaluated is inside, so a value outside
 * is rounding and the side (constant bounds, closed) or the nearest double
 * beyond the plane (planes, open) is nearer the exact value than it. */
static double into_region(const ts_surface *s, double x, double y, double v)
{
    if (s->shape == TS_SURFACE_NONE)
        return v;
    if (s->shape == TS_SURFACE_GRIDS) {
        if (s->has_lower)
            v = beyond_grid(&s->glo, x, y, v, 1.0);
        if (s->has_upper)
            v = beyond_grid(&s->gup, x, y, v, -1.0);
        return v;
    }
    if (s->shape != TS_SURFACE_PLANES) {
        if (s->has_lower && v < s->lower.c)
            v = s->lower.c;
        if (s->has_upper && v > s->upper.c)
            v = s->upper.c;
        return v;
    }
    if (s->has_lower)
        v = beyond_plane(&s->lower, x, y, v, 1.0);
    if (s->has_upper)
        v = beyond_plane(&s->upper, x, y, v, -1.0);
    return v;
}

/* Knots from which the search prefetches: fewer stay in L1 between
 * queries (the prefetches cost time there). */
#define PREFETCH_KNOTS 512
/* Nodes from which a batch prefetches the patches' corners (z, p, q, r:
 * 2 MB at this size, beyond L2). */
#define PREFETCH_NODES 65536
/* Queries of a batch searched before their values are formed. */
#define BATCH_BLOCK 32

/* ts__search (the same interval and cursor), its binary search without
 * branches on the data: scattered queries mispredict none.  *hit (if not
 * NULL): try the cursor only if the previous query's interval was the
 * cursor's or the next, and say whether this one's was (the interval is
 * unique and the cursor ends on it either way). */
static size_t find(const double *t, size_t n, double v, ts_cursor *cur, int *hit)
{
    size_t was = cur ? cur->interval : n, i = !hit || *hit ? was : n;
    if (hit)
        *hit = 1;
    if (i < n && t[i] <= v) {
        if (v < t[i + 1] || i + 1 == n)
            return i;
        if (v < t[i + 2] || i + 2 == n) {
            cur->interval = i + 1;
            return i + 1;
        }
    }
    /* the largest i < n with t[i] <= v lies in [lo, lo + len) */
    size_t lo = 0, len = n;
    int far = n >= PREFETCH_KNOTS; /* the same for every step: predicted */
    while (len > 1) {
        size_t half = len / 2;
#if defined(__GNUC__)
        if (far) { /* both knots the next step may read: in flight together */
            __builtin_prefetch(t + lo + (len - half) / 2);
            __builtin_prefetch(t + lo + half + (len - half) / 2);
        }
#endif
        lo = t[lo + half] <= v ? lo + half : lo;
        len -= half;
    }
    if (cur)
        cur->interval = lo;
    if (hit)
        *hit = lo == was || lo == was + 1;
    return lo;
}

/* The bases in x and y at a point of patch (i, j) (and their derivatives
 * when want): A[0] Ax, A[1] Ay, A[2] dAx, A[3] dAy. */
static void bases(const ts_surface *s, double x, double y, size_t i, size_t j, int want,
                  double A[4][4])
{
    ts__surf_basis(s->x, s->ax, i, s->form, x, A[0], want ? A[2] : NULL);
    ts__surf_basis(s->y, s->ay, j, s->form, y, A[1], want ? A[3] : NULL);
}

/* Value (and partials when zx/zy) at a point of patch (i, j), its bases A. */
static void eval_in(const ts_surface *s, double x, double y, size_t i, size_t j,
                    double A[4][4], double *z, double *zx, double *zy)
{
    const double *Ax = A[0], *Ay = A[1], *dAx = A[2], *dAy = A[3];
    int want = zx || zy;
    double B[16];
    ts__surf_patch_k(s, i, j, s->ks + 2 * i, s->ks + 2 * (s->nx + j), B);
    double v = 0.0, vx = 0.0, vy = 0.0;
    for (int k = 0; k < 4; k++) {
        double c = 0.0, cy = 0.0;
        for (int l = 0; l < 4; l++) {
            c += Ay[l] * B[4 * k + l];
            if (want)
                cy += dAy[l] * B[4 * k + l];
        }
        v += Ax[k] * c;
        if (want) {
            vx += dAx[k] * c;
            vy += Ax[k] * cy;
        }
    }
    *z = into_region(s, x, y, v);
    if (zx)
        *zx = vx;
    if (zy)
        *zy = vy;
}

/* The same at a point known to be on the grid. */
static void eval_at(const ts_surface *s, double x, double y, ts_surface_cursor *cur, double *z,
                    double *zx, double *zy)
{
    size_t i = find(s->x, s->nx, x, cur ? &cur->x : NULL, NULL);
    size_t j = find(s->y, s->ny, y, cur ? &cur->y : NULL, NULL);
    double A[4][4];
    bases(s, x, y, i, j, zx || zy, A);
    eval_in(s, x, y, i, j, A, z, zx, zy);
}

ts_status ts_surface_eval(const ts_surface *s, double x, double y, ts_surface_cursor *cur,
                          double *z, double *zx, double *zy)
{
    set_nan(z);
    set_nan(zx);
    set_nan(zy);
    if (!s)
        return TS_ERR_NULL;
    if (!inside(s->x, s->nx, x) || !inside(s->y, s->ny, y))
        return TS_ERR_DOMAIN;
    double v;
    eval_at(s, x, y, cur, &v, zx, zy);
    if (z)
        *z = v;
    return TS_OK;
}

ts_status ts_surface_eval_batch(const ts_surface *s, const double *xq, const double *yq,
                                size_t m, double *zq, double *zxq, double *zyq, ts_error *err)
{
    ts__error_set(err, TS_OK, TS_NO_INDEX, TS_WHERE_NONE);
    if (!s || (m > 0 && (!xq || !yq || !zq)))
        return ts__fail(err, TS_ERR_NULL, TS_NO_INDEX, TS_WHERE_NONE);
    ts_surface_cursor cur = TS_SURFACE_CURSOR_INIT;
    int hit[2] = {1, 1};
    ts_status st = TS_OK;
    /* blocks: the searches first, then the bases, then the values (each
     * pass's queries independent: in flight together) */
    int want = (zxq != NULL) | (zyq != NULL), far = (s->nx + 1) * (s->ny + 1) >= PREFETCH_NODES;
    for (size_t n0 = 0; n0 < m; n0 += BATCH_BLOCK) {
        size_t nb = m - n0 < BATCH_BLOCK ? m - n0 : BATCH_BLOCK, ij[BATCH_BLOCK][2];
        double A[BATCH_BLOCK][4][4];
        for (size_t b = 0; b < nb; b++) {
            double x = xq[n0 + b], y = yq[n0 + b];
            ij[b][0] = SIZE_MAX;
            if (inside(s->x, s->nx, x) && inside(s->y, s->ny, y)) {
                ij[b][0] = find(s->x, s->nx, x, &cur.x, hit);
                ij[b][1] = find(s->y, s->ny, y, &cur.y, hit + 1);
#if defined(__GNUC__)
                if (far) { /* the patch's corners: in flight with the other searches */
                    size_t c0 = ij[b][1] * (s->nx + 1) + ij[b][0], c1 = c0 + s->nx + 1;
                    __builtin_prefetch(s->z + c0);
                    __builtin_prefetch(s->z + c1);
                    __builtin_prefetch(s->p + c0);
                    __builtin_prefetch(s->p + c1);
                    __builtin_prefetch(s->q + c0);
                    __builtin_prefetch(s->q + c1);
                    __builtin_prefetch(s->r + c0);
                    __builtin_prefetch(s->r + c1);
                }
#endif
            }
        }
        for (size_t b = 0; b < nb; b++)
            if (ij[b][0] != SIZE_MAX)
                bases(s, xq[n0 + b], yq[n0 + b], ij[b][0], ij[b][1], want, A[b]);
        for (size_t b = 0, n = n0; b < nb; b++, n++) {
            double *px = zxq ? zxq + n : NULL, *py = zyq ? zyq + n : NULL;
            if (ij[b][0] != SIZE_MAX) {
                eval_in(s, xq[n], yq[n], ij[b][0], ij[b][1], A[b], zq + n, px, py);
                continue;
            }
            zq[n] = (double)NAN;
            set_nan(px);
            set_nan(py);
            if (st == TS_OK)
                st = ts__fail(err, TS_ERR_DOMAIN, n, TS_WHERE_QUERY);
        }
    }
    return st;
}

#define GRID_BLOCK 64

ts_status ts_surface_eval_grid(const ts_surface *s, const double *xq, size_t mx,
                               const double *yq, size_t my, double *out, ts_error *err)
{
    ts__error_set(err, TS_OK, TS_NO_INDEX, TS_WHERE_NONE);
    if (!s || (mx > 0 && !xq) || (my > 0 && !yq) || (mx > 0 && my > 0 && !out))
        return ts__fail(err, TS_ERR_NULL, TS_NO_INDEX, TS_WHERE_NONE);
    ts_status st = TS_OK;
    for (size_t a = 0; a < mx && st == TS_OK; a++)
        if (!inside(s->x, s->nx, xq[a]))
            st = ts__fail(err, TS_ERR_DOMAIN, a, TS_WHERE_QUERY);
    for (size_t b = 0; b < my && st == TS_OK; b++)
        if (!inside(s->y, s->ny, yq[b]))
            st = ts__fail(err, TS_ERR_DOMAIN, mx + b, TS_WHERE_QUERY);
    ts_cursor cx = TS_CURSOR_INIT, cy = TS_CURSOR_INIT;
    for (size_t a0 = 0; a0 < mx; a0 += GRID_BLOCK) {
        size_t na = mx - a0 < GRID_BLOCK ? mx - a0 : GRID_BLOCK;
        double Ax[GRID_BLOCK][4], kx[GRID_BLOCK][2];
        size_t ia[GRID_BLOCK];
        for (size_t a = 0; a < na; a++) {
            double v = xq[a0 + a];
            ia[a] = SIZE_MAX;
            if (inside(s->x, s->nx, v)) {
                ia[a] = ts__search(s->x, s->nx, v, &cx);
                ts__surf_basis(s->x, s->ax, ia[a], s->form, v, Ax[a], NULL);
                if (a > 0 && ia[a] == ia[a - 1]) {
                    kx[a][0] = kx[a - 1][0];
                    kx[a][1] = kx[a - 1][1];
                } else {
                    ts__surf_ks(s, 0, ia[a], kx[a]);
                }
            }
        }
        for (size_t b = 0; b < my; b++) {
            double *row = out + b * mx + a0, v = yq[b];
            if (!inside(s->y, s->ny, v)) {
                for (size_t a = 0; a < na; a++)
                    row[a] = (double)NAN;
                continue;
            }
            size_t j = ts__search(s->y, s->ny, v, &cy), ic = SIZE_MAX;
            double Ay[4], C[4] = {0.0, 0.0, 0.0, 0.0}, B[16], ky[2];
            ts__surf_basis(s->y, s->ay, j, s->form, v, Ay, NULL);
            ts__surf_ks(s, 1, j, ky);
            for (size_t a = 0; a < na; a++) {
                if (ia[a] == SIZE_MAX) {
                    row[a] = (double)NAN;
                    continue;
                }
                if (ia[a] != ic) { /* the patch's four curves in x at this y */
                    ic = ia[a];
                    ts__surf_patch_k(s, ic, j, kx[a], ky, B);
                    for (int k = 0; k < 4; k++)
                        C[k] = Ay[0] * B[4 * k] + Ay[1] * B[4 * k + 1] + Ay[2] * B[4 * k + 2] +
                               Ay[3] * B[4 * k + 3];
                }
                row[a] = into_region(s, xq[a0 + a], v,
                                     Ax[a][0] * C[0] + Ax[a][1] * C[1] + Ax[a][2] * C[2] +
                                         Ax[a][3] * C[3]);
            }
        }
    }
    return st;
}

ts_status ts_surface_integral(const ts_surface *s, double xa, double xb, double ya, double yb,
                              double *out)
{
    set_nan(out);
    if (!s || !out)
        return TS_ERR_NULL;
    if (!inside(s->x, s->nx, xa) || !inside(s->x, s->nx, xb) || !inside(s->y, s->ny, ya) ||
        !inside(s->y, s->ny, yb))
        return TS_ERR_DOMAIN;
    double sign = 1.0;
    if (xa > xb) {
        double t = xa;
        xa = xb;
        xb = t;
        sign = -sign;
    }
    if (ya > yb) {
        double t = ya;
        ya = yb;
        yb = t;
        sign = -sign;
    }
    size_t i0 = ts__search(s->x, s->nx, xa, NULL), i1 = ts__search(s->x, s->nx, xb, NULL);
    size_t j0 = ts__search(s->y, s->ny, ya, NULL), j1 = ts__search(s->y, s->ny, yb, NULL);
    double sum = 0.0;
    for (size_t i = i0; i <= i1; i++) {
        double Wx[4];
        ts__surf_basis_int(s->x, s->ax, i, s->form, fmax(xa, s->x[i]), fmin(xb, s->x[i + 1]),
                           Wx);
        for (size_t j = j0; j <= j1; j++) {
            double Wy[4];
            ts__surf_basis_int(s->y, s->ay, j, s->form, fmax(ya, s->y[j]),
                               fmin(yb, s->y[j + 1]), Wy);
            double B[16];
            ts__surf_patch(s, i, j, B);
            for (int k = 0; k < 4; k++)
                for (int l = 0; l < 4; l++)
                    sum += Wx[k] * Wy[l] * B[4 * k + l];
        }
    }
    *out = sign * sum;
    return TS_OK;
}

ts_status ts_surface_control(const ts_surface *s, size_t i, size_t j, double B[16], double X[4],
                             double Y[4])
{
    if (!s || !B)
        return TS_ERR_NULL;
    if (i >= s->nx || j >= s->ny)
        return TS_ERR_INDEX;
    ts__surf_patch(s, i, j, B);
    double hx = s->x[i + 1] - s->x[i], hy = s->y[j + 1] - s->y[j];
    if (X) {
        ts__surf_xhat(s->ax, i, s->form, X);
        for (int k = 0; k < 4; k++)
            X[k] = s->x[i] + hx * X[k];
    }
    if (Y) {
        ts__surf_xhat(s->ay, j, s->form, Y);
        for (int l = 0; l < 4; l++)
            Y[l] = s->y[j] + hy * Y[l];
    }
    return TS_OK;
}
