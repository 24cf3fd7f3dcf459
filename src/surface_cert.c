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
    double G[16], guard;
    ts__surf_gaps(s, i, j, pl, sign, G, &guard);
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
    for (int m = 0; m < 7; m++)
        for (int n = 0; n < 7; n++) {
            double v = 0.0;
            for (int k = 0; k < 4; k++)
                for (int l = 0; l < 4; l++)
                    v += bern[m][k] * bern[n][l] * G[4 * k + l];
            H[7 * m + n] = v;
        }
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
