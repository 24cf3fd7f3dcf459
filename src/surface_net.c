/* docs/method.md §11: the control net of a surface patch, the basis of one
 * direction at a query, and control gaps to a plane. */
#include "internal.h"

#include <float.h>
#include <math.h>

/* Gauss–Legendre, 12 points on [-1, 1] (positive half; published values). */
static const double gl_x[6] = {0.1252334085114689, 0.3678314989981802, 0.5873179542866175,
                               0.7699026741943047, 0.9041172563704748, 0.9815606342467192};
static const double gl_w[6] = {0.2491470458134027, 0.23349253653835464, 0.20316742672306565,
                               0.1600783285433461, 0.10693932599531888, 0.04717533638651202};

static double kappa_of(const double *a, size_t i, ts_form form)
{
    return ts__kappa(form == TS_FORM_GEOMETRIC ? a[i] : 1.0);
}

void ts__surf_xhat(const double *a, size_t i, ts_form form, double X[4])
{
    double kap = kappa_of(a, i, form);
    X[0] = 0.0;
    X[1] = kap;
    X[2] = 1.0 - kap;
    X[3] = 1.0;
}

/* X̂'(θ) of the geometric form (docs/method.md §4) from dA/dθ. */
static double xhat_d1(double kap, const double D[4])
{
    return kap * D[1] + (1.0 - kap) * D[2] + D[3];
}

void ts__surf_basis(const double *t, const double *a, size_t i, ts_form form, double v,
                    double A[4], double *dA)
{
    double h = t[i + 1] - t[i];
    double uw[2]; /* u, 1 − u from the nearer end: exact knots */
    ts__div2(v - t[i], h, t[i + 1] - v, h, uw);
    double u = uw[0], w = uw[1];
    int right = u > 0.5;
    double r = ts__pick(right, w, u), phi;
    if (form == TS_FORM_GEOMETRIC)
        phi = ts__geo_solve(ts__kappa(a[i]), r);
    else
        phi = TS_HALF_PI * r;
    double sp = sin(phi), cp = cos(phi);
    double s = ts__pick(right, cp, sp), c = ts__pick(right, sp, cp); /* right: θ = π/2 − φ */
    ts__basis(s, c, A);
    if (dA) {
        double D[4];
        ts__basis_d1(s, c, D);
        double dtheta = form == TS_FORM_GEOMETRIC
                            ? 1.0 / (h * xhat_d1(ts__kappa(a[i]), D))
                            : TS_HALF_PI / h;
        for (int k = 0; k < 4; k++)
            dA[k] = D[k] * dtheta;
    }
}

/* θ of a point of interval i (geometric: the solve; else linear). */
static double theta_at(const double *t, const double *a, size_t i, ts_form form, double v)
{
    double h = t[i + 1] - t[i];
    double u = (v - t[i]) / h;
    if (form != TS_FORM_GEOMETRIC)
        return TS_HALF_PI * u;
    double kap = ts__kappa(a[i]);
    return u <= 0.5 ? ts__geo_solve(kap, u) : TS_HALF_PI - ts__geo_solve(kap, (t[i + 1] - v) / h);
}

/* ∫ A_k(θ) X̂'(θ) dθ over [t0, t1] ⊂ [0, π/2] of length <= π/4: Gauss–Legendre,
 * exact to rounding for the degree-6 trigonometric integrand. */
static void geo_int_piece(double kap, double t0, double t1, double W[4])
{
    double mid = 0.5 * (t0 + t1), half = 0.5 * (t1 - t0);
    for (int m = 0; m < 12; m++) {
        double th = mid + (m < 6 ? -half * gl_x[m] : half * gl_x[m - 6]);
        double wt = half * gl_w[m < 6 ? m : m - 6];
        double A[4], D[4], s = sin(th), c = cos(th);
        ts__basis(s, c, A);
        ts__basis_d1(s, c, D);
        double xp = xhat_d1(kap, D) * wt;
        for (int k = 0; k < 4; k++)
            W[k] += A[k] * xp;
    }
}

void ts__surf_basis_int(const double *t, const double *a, size_t i, ts_form form, double ta,
                        double tb, double W[4])
{
    double h = t[i + 1] - t[i];
    double th0 = theta_at(t, a, i, form, ta), th1 = theta_at(t, a, i, form, tb);
    if (form != TS_FORM_GEOMETRIC) {
        double I0[4], I1[4];
        ts__basis_int(th0, sin(th0), cos(th0), I0);
        ts__basis_int(th1, sin(th1), cos(th1), I1);
        for (int k = 0; k < 4; k++)
            W[k] = (I1[k] - I0[k]) * h / TS_HALF_PI;
        return;
    }
    double kap = ts__kappa(a[i]), q = 0.25 * TS_PI;
    for (int k = 0; k < 4; k++)
        W[k] = 0.0;
    /* pieces of length <= π/4: split at π/4 */
    if (th0 < q && th1 > q) {
        geo_int_piece(kap, th0, q, W);
        geo_int_piece(kap, q, th1, W);
    } else {
        geo_int_piece(kap, th0, th1, W);
    }
    for (int k = 0; k < 4; k++)
        W[k] *= h;
}

double ts__surf_k(const double *t, const double *a, size_t n, size_t i, size_t node,
                  ts_form form)
{
    double am = a[i];
    if (form == TS_FORM_C1) {
        if (node > 0 && a[node - 1] > am)
            am = a[node - 1];
        if (node < n && a[node] > am)
            am = a[node];
    }
    return ts__geo_k(t[i + 1] - t[i], am);
}

void ts__surf_ks(const ts_surface *s, int dir, size_t i, double u[2])
{
    const double *t = dir ? s->y : s->x, *a = dir ? s->ay : s->ax;
    size_t n = dir ? s->ny : s->nx;
    u[0] = ts__surf_k(t, a, n, i, i, s->form);
    /* the same at both ends but in the C¹ form (its neighbours' a) */
    u[1] = s->form == TS_FORM_C1 ? ts__surf_k(t, a, n, i, i + 1, s->form) : u[0];
}

void ts__surf_patch(const ts_surface *s, size_t i, size_t j, double B[16])
{
    double ux[2], uy[2];
    ts__surf_ks(s, 0, i, ux);
    ts__surf_ks(s, 1, j, uy);
    ts__surf_patch_k(s, i, j, ux, uy, B);
}

double ts__surf_plane_at(const ts_plane *pl, double x, double y, double *err)
{
    /* a constant plane (x, y finite: every caller passes a node, a patch
     * corner or a point inside the grid, whose knots are checked finite):
     * every term below but s2 is ±0 and their sum +0, so v = c + 0 (c, or
     * +0 for c = ±0) and the error bound 2ε|v| + 4·2^-1074: the same bits
     * without the products */
    if (pl->p == 0.0 && pl->q == 0.0) {
        double v = pl->c + 0.0;
        if (err)
            *err = 2.0 * DBL_EPSILON * fabs(v) + 4.0 * DBL_TRUE_MIN;
        return v;
    }
    /* docs/method.md §11.3: p x = P + e, q y = Q + f exactly (fma); P + Q =
     * s1 + e1, s1 + c = s2 + e2 exactly (TwoSum); the small terms summed */
    double P = pl->p * x, e = fma(pl->p, x, -P), Q = pl->q * y, f = fma(pl->q, y, -Q);
    double s1 = P + Q, z1 = s1 - P, e1 = (P - (s1 - z1)) + (Q - z1);
    double s2 = s1 + pl->c, z2 = s2 - s1, e2 = (s1 - (s2 - z2)) + (pl->c - z2);
    double v = s2 + (((e1 + e2) + e) + f);
    if (err)
        *err = 2.0 * DBL_EPSILON * (fabs(e1) + fabs(e2) + fabs(e) + fabs(f) + fabs(v)) +
               4.0 * DBL_TRUE_MIN;
    return v;
}

void ts__surf_gaps(const ts_surface *s, size_t i, size_t j, const double B[16], const ts_plane *pl,
                   int sign, double G[16], double *guard)
{
    double X[4] = {0.0, 0.0, 0.0, 0.0}, Y[4] = {0.0, 0.0, 0.0, 0.0};
    double hx = s->x[i + 1] - s->x[i], hy = s->y[j + 1] - s->y[j];
    int geo = s->form == TS_FORM_GEOMETRIC;
    if (geo) { /* the abscissae: the geometric form's rise only */
        ts__surf_xhat(s->ax, i, s->form, X);
        ts__surf_xhat(s->ay, j, s->form, Y);
    }
    /* docs/method.md §11.3, local coordinates: the plane at the patch's
     * corner (rounded about once) plus its rise p hx X̂_k + q hy Ŷ_l to the
     * control abscissae (geometric form; in the paper and C¹ forms the
     * linear rest is the certificate's, §11.4) */
    double eL, L0 = ts__surf_plane_at(pl, s->x[i], s->y[j], &eL);
    double bmax = 0.0, ph = pl->p * hx, qh = pl->q * hy;
    for (int k = 0; k < 4; k++) {
        for (int l = 0; l < 4; l++) {
            double L = L0 + (geo ? ph * X[k] + qh * Y[l] : 0.0);
            double b = fabs(B[4 * k + l]);
            bmax = b > bmax ? b : bmax;
            G[4 * k + l] = sign > 0 ? B[4 * k + l] - L : L - B[4 * k + l];
        }
    }
    /* 0 for a constant plane (L0 = c: the signs are exact); else the guard
     * of §11.3 in local quantities only */
    if (pl->p == 0.0 && pl->q == 0.0)
        *guard = 0.0;
    else
        *guard = eL + 16.0 * DBL_EPSILON * (bmax + fabs(L0) + fabs(ph) + fabs(qh)) +
                 (fabs(pl->p) * ts__width_error(s->x[i], s->x[i + 1], hx) +
                  fabs(pl->q) * ts__width_error(s->y[j], s->y[j + 1], hy)) *
                     (1.0 + 2.0 * DBL_EPSILON) +
                 4.0 * DBL_TRUE_MIN;
}

int ts__surf_gaps_inside(const double G[16], double guard)
{
    int ok = 1;
    for (int k = 0; k < 16; k++)
        ok &= G[k] >= guard;
    return ok;
}
