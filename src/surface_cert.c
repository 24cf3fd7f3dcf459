/* docs/method.md §11.4: the certificate of one surface patch.  With
 * t = tan(θ/2) each A_l is a degree-6 polynomial over (1 + t²)³, so a patch
 * is a tensor rational Bézier form of degree 6 × 6 with positive weights:
 * its value is a convex combination of the 49 ratios H/W (a lower bound),
 * and de Casteljau subdivision refines it.  Branch and bound. */
#include "internal.h"

#include <float.h>
#include <math.h>

/* Bernstein coefficients (degree 6, t in [0, 1]) of (1 + t²)³ A_l(θ(t)):
 * row m, column l (computed exactly from the factored basis of §2). */
static const double bern[7][4] = {
    {1.0, 0.0, 0.0, 0.0},
    {0.0, 1.0, 0.0, 0.0},
    {0.0, 14.0 / 15.0, 4.0 / 15.0, 0.0},
    {0.0, 0.8, 0.8, 0.0},
    {0.0, 8.0 / 15.0, 28.0 / 15.0, 0.0},
    {0.0, 0.0, 4.0, 0.0},
    {0.0, 0.0, 0.0, 8.0},
};
/* the row sums: Bernstein coefficients of (1 + t²)³ */
static const double wgt[7] = {1.0, 1.0, 1.2, 1.6, 2.4, 4.0, 8.0};

/* H: the degree-(6, 6) Bernstein coefficients of (1 + t²)³(1 + u²)³ times the
 * patch form with control values G (4 × 4), row-major 7 × 7 */
static void elevate(const double G[16], double H[49])
{
    for (int m = 0; m < 7; m++)
        for (int n = 0; n < 7; n++) {
            double v = 0.0;
            for (int k = 0; k < 4; k++)
                for (int l = 0; l < 4; l++)
                    v += bern[m][k] * bern[n][l] * G[4 * k + l];
            H[7 * m + n] = v;
        }
}


typedef struct bb_ctx {
    double kx, ky;          /* linear rest −kx θ − ky φ (paper, C¹ with a sloped plane) */
    double tol;
    double best, bt, bu;    /* least sampled gap and its (t, u) */
    double lower;           /* least bound over the leaves */
    int depth_max;
    long nodes;
} bb_ctx;

static double lin_max(double k, double t0, double t1)
{
    double a = k * 2.0 * atan(t0), b = k * 2.0 * atan(t1);
    return a > b ? a : b;
}

static void sample(bb_ctx *c, double h, double t, double u)
{
    double v = h - c->kx * 2.0 * atan(t) - c->ky * 2.0 * atan(u);
    if (v < c->best) {
        c->best = v;
        c->bt = t;
        c->bu = u;
    }
}

/* halves of a degree-6 Bernstein sequence with stride st (n = 7 values) */
static void split(const double *in, int st, double *lo, double *hi)
{
    double b[7];
    for (int m = 0; m < 7; m++)
        b[m] = in[m * st];
    for (int r = 0; r < 7; r++) {
        lo[r * st] = b[0];
        hi[(6 - r) * st] = b[6 - r];
        for (int m = 0; m < 6 - r; m++)
            b[m] = 0.5 * (b[m] + b[m + 1]);
    }
}

static void bb(bb_ctx *c, const double H[49], const double wx[7], const double wy[7], double t0,
               double t1, double u0, double u1, int depth)
{
    c->nodes++;
    if (depth > c->depth_max)
        c->depth_max = depth;
    double lo = (double)INFINITY;
    for (int m = 0; m < 7; m++)
        for (int n = 0; n < 7; n++) {
            double v = H[7 * m + n] / (wx[m] * wy[n]);
            lo = v < lo ? v : lo;
        }
    lo -= lin_max(c->kx, t0, t1) + lin_max(c->ky, u0, u1);
    /* corners: values of the surface */
    sample(c, H[0] / (wx[0] * wy[0]), t0, u0);
    sample(c, H[6] / (wx[0] * wy[6]), t0, u1);
    sample(c, H[42] / (wx[6] * wy[0]), t1, u0);
    sample(c, H[48] / (wx[6] * wy[6]), t1, u1);
    if (lo >= c->best - c->tol || depth >= TS_LIMIT(surface_cert_depth) ||
        c->nodes >= TS_LIMIT(surface_cert_nodes)) {
        c->lower = lo < c->lower ? lo : c->lower;
        return;
    }
    double A[49], Bh[49], wa[7], wb[7];
    if (depth % 2 == 0) { /* split in t */
        for (int n = 0; n < 7; n++)
            split(H + n, 7, A + n, Bh + n);
        split(wx, 1, wa, wb);
        double tm = 0.5 * (t0 + t1);
        bb(c, A, wa, wy, t0, tm, u0, u1, depth + 1);
        bb(c, Bh, wb, wy, tm, t1, u0, u1, depth + 1);
    } else { /* in u */
        for (int m = 0; m < 7; m++)
            split(H + 7 * m, 1, A + 7 * m, Bh + 7 * m);
        split(wy, 1, wa, wb);
        double um = 0.5 * (u0 + u1);
        bb(c, A, wx, wa, t0, t1, u0, um, depth + 1);
        bb(c, Bh, wx, wb, t0, t1, um, u1, depth + 1);
    }
}

/* The abscissa of θ = 2 atan t in interval i of knots t. */
static double place(const double *knots, const double *a, size_t i, ts_form form, double t)
{
    double th = 2.0 * atan(t), h = knots[i + 1] - knots[i], u = th / TS_HALF_PI;
    if (form == TS_FORM_GEOMETRIC) {
        double X[4], A[4];
        ts__surf_xhat(a, i, form, X);
        ts__basis(sin(th), cos(th), A);
        u = A[1] * X[1] + A[2] * X[2] + A[3] * X[3];
    }
    double v = knots[i] + h * u; /* may round past the end */
    return v < knots[i + 1] ? v : knots[i + 1];
}

int ts__surf_certify_patch(const ts_surface *s, size_t i, size_t j, const ts_plane *pl,
                           int sign, double *proven, double *sampled, double *ax, double *ay)
{
    double B[16], G[16], guard;
    ts__surf_patch(s, i, j, B);
    ts__surf_gaps(s, i, j, B, pl, sign, G, &guard);
    int lin = s->form != TS_FORM_GEOMETRIC && (pl->p != 0.0 || pl->q != 0.0);
    bb_ctx c;
    c.kx = lin ? sign * pl->p * (s->x[i + 1] - s->x[i]) / TS_HALF_PI : 0.0;
    c.ky = lin ? sign * pl->q * (s->y[j + 1] - s->y[j]) / TS_HALF_PI : 0.0;
    double scale = fabs(c.kx) * TS_HALF_PI + fabs(c.ky) * TS_HALF_PI;
    for (int k = 0; k < 16; k++)
        scale = fabs(G[k]) > scale ? fabs(G[k]) : scale;
    /* the linear rest is bounded by its largest value on a piece, which
     * converges only linearly: there the tolerance adds 1e-4 of its range */
    c.tol = 1e-9 * scale + 1e-4 * (fabs(c.kx) + fabs(c.ky)) * TS_HALF_PI;
    c.best = (double)INFINITY;
    c.bt = c.bu = 0.0;
    c.lower = (double)INFINITY;
    c.depth_max = 0;
    c.nodes = 0;
    double H[49];
    elevate(G, H);
    bb(&c, H, wgt, wgt, 0.0, 1.0, 0.0, 1.0, 0);
    /* rounding of H (sums of non-negative multiples of G) and of each
     * subdivision level (averages), relative to the scale, plus the gaps' */
    double rg = (32.0 + 4.0 * c.depth_max) * DBL_EPSILON * scale + guard;
    double pv = c.lower - rg;
    int proof = !lin && ts__surf_gaps_inside(G, guard);
    if (proof && pv < 0.0)
        pv = 0.0;
    *proven = pv;
    *sampled = c.best;
    *ax = place(s->x, s->ax, i, s->form, c.bt);
    *ay = place(s->y, s->ay, j, s->form, c.bu);
    return proof || pv > 0.0;
}

/* ---- docs/method.md §11.7: against a gridded field ----------------------- */

#define GRID_NODES 20000

typedef struct gb_ctx {
    const ts_surface *s;
    const ts__gbound *g;
    size_t i, j;
    double sg, dx, dy, scale;
    double best, bt, bu; /* least sampled gap and its (t, u) */
    double lower;        /* least proven bound over the leaves */
    int depth_max, stop;
    long nodes;
} gb_ctx;

/* [place(t0) − d, place(t1) + d] within the patch's interval i of knots */
static void image(const ts_surface *s, int dir, size_t i, double t0, double t1, double d,
                  double *lo, double *hi)
{
    const double *k = dir ? s->y : s->x, *a = dir ? s->ay : s->ax;
    double v0 = place(k, a, i, s->form, t0) - d, v1 = place(k, a, i, s->form, t1) + d;
    *lo = v0 > k[i] ? v0 : k[i];
    *hi = v1 < k[i + 1] ? v1 : k[i + 1];
}

static void gsample(gb_ctx *c, double h, double t, double u)
{
    double x = place(c->s->x, c->s->ax, c->i, c->s->form, t);
    double y = place(c->s->y, c->s->ay, c->j, c->s->form, u);
    double v = h - c->sg * ts__gb_value(c->g, x, y);
    if (v < c->best) {
        c->best = v;
        c->bt = t;
        c->bu = u;
    }
}

static void gbb(gb_ctx *c, const double H[49], const double wx[7], const double wy[7], double t0,
                double t1, double u0, double u1, int depth)
{
    if (c->stop)
        return;
    c->nodes++;
    if (depth > c->depth_max)
        c->depth_max = depth;
    double lo = (double)INFINITY, xa, xb, ya, yb;
    for (int m = 0; m < 7; m++)
        for (int n = 0; n < 7; n++) {
            double v = H[7 * m + n] / (wx[m] * wy[n]);
            lo = v < lo ? v : lo;
        }
    /* the rounding of H and of depth subdivisions; then the field's
     * largest value over the piece's image, widened by where evaluation
     * may place a point */
    lo -= (32.0 + 4.0 * depth) * DBL_EPSILON * c->scale;
    image(c->s, 0, c->i, t0, t1, c->dx, &xa, &xb);
    image(c->s, 1, c->j, u0, u1, c->dy, &ya, &yb);
    lo -= ts__gb_max(c->g, c->sg, xa, xb, ya, yb);
    gsample(c, H[0] / (wx[0] * wy[0]), t0, u0);
    gsample(c, H[6] / (wx[0] * wy[6]), t0, u1);
    gsample(c, H[42] / (wx[6] * wy[0]), t1, u0);
    gsample(c, H[48] / (wx[6] * wy[6]), t1, u1);
    if (!(c->best > 0.0))
        c->stop = 1; /* a sampled point on or across the field: not certified */
    if (c->stop || (lo > 0.0 && lo >= 0.5 * c->best) || depth >= TS_LIMIT(surface_cert_depth) ||
        c->nodes >= GRID_NODES) {
        c->lower = lo < c->lower ? lo : c->lower;
        return;
    }
    double A[49], Bh[49], wa[7], wb[7];
    if (depth % 2 == 0) {
        for (int n = 0; n < 7; n++)
            split(H + n, 7, A + n, Bh + n);
        split(wx, 1, wa, wb);
        double tm = 0.5 * (t0 + t1);
        gbb(c, A, wa, wy, t0, tm, u0, u1, depth + 1);
        gbb(c, Bh, wb, wy, tm, t1, u0, u1, depth + 1);
    } else {
        for (int m = 0; m < 7; m++)
            split(H + 7 * m, 1, A + 7 * m, Bh + 7 * m);
        split(wy, 1, wa, wb);
        double um = 0.5 * (u0 + u1);
        gbb(c, A, wx, wa, t0, t1, u0, um, depth + 1);
        gbb(c, Bh, wx, wb, t0, t1, um, u1, depth + 1);
    }
}

/* Geometric form, patch inside one cell of the field: the field is the
 * tensor form of its values at the control abscissae (docs/method.md §11.7),
 * so the gap has control values G and the certificate of §11.4 applies
 * (quadratic convergence; the control values alone prove it as a -> inf).
 * dx, dy: where a point may be placed; gx, gy: the field's slopes. */
static int certify_cell(const ts_surface *s, size_t i, size_t j, const ts__gbound *g, int sign,
                        double dx, double dy, double gx, double gy, double *proven,
                        double *sampled, double *ax, double *ay)
{
    double B[16];
    ts__surf_patch(s, i, j, B);
    double X[4], Y[4], G[16], hx = s->x[i + 1] - s->x[i], hy = s->y[j + 1] - s->y[j];
    ts__surf_xhat(s->ax, i, s->form, X);
    ts__surf_xhat(s->ay, j, s->form, Y);
    double big = 0.0;
    for (int k = 0; k < 4; k++) {
        double xv = fmin(s->x[i] + hx * X[k], s->x[i + 1]);
        for (int l = 0; l < 4; l++) {
            double yv = fmin(s->y[j] + hy * Y[l], s->y[j + 1]);
            double b = ts__gb_value(g, xv, yv);
            G[4 * k + l] = sign * (B[4 * k + l] - b);
            big = fmax(big, fabs(B[4 * k + l]) + fabs(b));
        }
    }
    /* the field's rounding, its change over the rounding of the control
     * abscissae and over where evaluation places a point, the subtraction */
    double guard = g->err + 2.0 * (gx * dx + gy * dy) + 2.0 * DBL_EPSILON * big;
    bb_ctx c;
    c.kx = c.ky = 0.0;
    double scale = 0.0;
    for (int k = 0; k < 16; k++)
        scale = fabs(G[k]) > scale ? fabs(G[k]) : scale;
    c.tol = 1e-9 * scale;
    c.best = c.lower = (double)INFINITY;
    c.bt = c.bu = 0.0;
    c.depth_max = 0;
    c.nodes = 0;
    double H[49];
    elevate(G, H);
    bb(&c, H, wgt, wgt, 0.0, 1.0, 0.0, 1.0, 0);
    double pv = c.lower - (32.0 + 4.0 * c.depth_max) * DBL_EPSILON * scale - guard;
    int proof = ts__surf_gaps_inside(G, guard) && G[0] > guard && G[3] > guard &&
                G[12] > guard && G[15] > guard;
    if (proof) { /* the control values: every one above the guard */
        double m = (double)INFINITY;
        for (int k = 0; k < 16; k++)
            m = fmin(m, G[k] - guard);
        pv = fmax(pv, m);
    }
    *proven = pv;
    *sampled = c.best;
    *ax = place(s->x, s->ax, i, s->form, c.bt);
    *ay = place(s->y, s->ay, j, s->form, c.bu);
    return pv > 0.0;
}

int ts__surf_certify_grid(const ts_surface *s, size_t i, size_t j, const ts__gbound *g,
                          int sign, double *proven, double *sampled, double *ax, double *ay)
{
    double B[16];
    ts__surf_patch(s, i, j, B);
    gb_ctx c;
    c.s = s;
    c.g = g;
    c.i = i;
    c.j = j;
    c.sg = sign;
    /* where evaluation places a point and the rounding of a piece's image:
     * a few ε of the width (local coordinates), one rounding of the
     * coordinate, and the rounding of the width when measured from the far
     * end (§11.3 item 3) */
    double hx = s->x[i + 1] - s->x[i], hy = s->y[j + 1] - s->y[j];
    c.dx = 64.0 * DBL_EPSILON * hx + 2.0 * DBL_EPSILON * (fabs(s->x[i]) + fabs(s->x[i + 1])) +
           ts__width_error(s->x[i], s->x[i + 1], hx) + 4.0 * DBL_TRUE_MIN;
    c.dy = 64.0 * DBL_EPSILON * hy + 2.0 * DBL_EPSILON * (fabs(s->y[j]) + fabs(s->y[j + 1])) +
           ts__width_error(s->y[j], s->y[j + 1], hy) + 4.0 * DBL_TRUE_MIN;
    double gx, gy;
    if (s->form == TS_FORM_GEOMETRIC &&
        ts__gb_cell(g, s->x[i], s->x[i + 1], s->y[j], s->y[j + 1], &gx, &gy))
        return certify_cell(s, i, j, g, sign, c.dx, c.dy, gx, gy, proven, sampled, ax, ay);
    c.scale = 0.0;
    for (int k = 0; k < 16; k++)
        c.scale = fabs(B[k]) > c.scale ? fabs(B[k]) : c.scale;
    c.best = c.lower = (double)INFINITY;
    c.bt = c.bu = 0.0;
    c.depth_max = c.stop = 0;
    c.nodes = 0;
    double H[49], SB[16];
    for (int k = 0; k < 16; k++)
        SB[k] = sign * B[k]; /* exact: sign is ±1 */
    elevate(SB, H);
    gbb(&c, H, wgt, wgt, 0.0, 1.0, 0.0, 1.0, 0);
    *proven = c.lower;
    *sampled = c.best;
    *ax = place(s->x, s->ax, i, s->form, c.bt);
    *ay = place(s->y, s->ay, j, s->form, c.bu);
    return !c.stop && c.lower > 0.0;
}
