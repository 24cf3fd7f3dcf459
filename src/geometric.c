/* docs/method.md §4: the geometric form (X(θ), Y(θ)) with the same k_i in both
 * coordinates.  Derivations: docs/accuracy.md §1. */
#include "internal.h"

#include <float.h>
#include <math.h>

/* One side of an interval, seen from the end it starts at: with φ measured
 * from that end, X = x_end ± h X̂(φ), X̂ = s² + κ(A1 − A2), and
 * Y = F0 c² + F1 s² + k (D0 A1 − D1 A2).  From the right end the roles swap:
 * (F0, F1, D0, D1) = (f_{i+1}, f_i, −d_{i+1}, −d_i) (A0↔A3, A1↔A2 under
 * θ → π/2 − θ), so 1 − X̂(π/2 − φ) = X̂(φ). */
typedef struct geo_side {
    double F0, F1, D0, D1; /* values and slopes as above */
    double kappa, h, k;    /* κ = 2/(3π a), k = κ h */
} geo_side;

static void geo_side_init(const ts_spline *sp, size_t i, int right, geo_side *g)
{
    g->h = ts__h(sp, i);
    g->kappa = sp->kappa[i];
    g->k = g->kappa * g->h;
    if (!right) {
        g->F0 = sp->f[i];
        g->F1 = sp->f[i + 1];
        g->D0 = sp->d[i];
        g->D1 = sp->d[i + 1];
    } else {
        g->F0 = sp->f[i + 1];
        g->F1 = sp->f[i];
        g->D0 = -sp->d[i + 1];
        g->D1 = -sp->d[i];
    }
}

/* φ in [0, π/4] with X̂(φ) = u: ts__geo_root (internal.h) for u in (0, 1/2),
 * the ends exactly (u = 0, and u >= 1/2, which rounding of the nearer
 * end's distance can give). */
static double geo_solve(double kappa, double u)
{
    double sc[4];
    return u > 0.0 && u < 0.5 ? ts__geo_root(u, kappa, sc) : u > 0.0 ? 0.25 * TS_PI : 0.0;
}

/* The end φ = 0 of one side (s = 0, c = 1): the value (B0 exactly), and the
 * first and second derivatives in u = (x − x_i)/h (so h² never under- or
 * overflows).  sign = +1 from the left end, −1 from the right (x decreases
 * with φ there). */
static void geo_end(const geo_side *g, double sign, double out[3])
{
    const double s = 0.0, c = 1.0;
    out[0] = g->F0;
    double D1[4], dF = g->F1 - g->F0, sc2 = 2.0 * s * c;
    ts__basis_d1(s, c, D1);
    double Yp = dF * sc2 + g->k * (g->D0 * D1[1] - g->D1 * D1[2]);
    double Xp = sc2 + g->kappa * (D1[1] - D1[2]); /* X̂' (dx/dφ = ±h X̂') */
    out[1] = sign * (Yp / Xp);
    double D2[4], c2 = 2.0 * (c * c - s * s);
    ts__basis_d2(s, c, D2);
    double Ypp = dF * c2 + g->k * (g->D0 * D2[1] - g->D1 * D2[2]);
    double Xpp = c2 + g->kappa * (D2[1] - D2[2]);
    /* (Y''X' − Y'X'')/X'³ as ts__geo_y forms it (X'³ underflows for huge a);
     * the sign cancels (see docs/accuracy.md §1) */
    out[2] = (Ypp - (Yp / Xp) * Xpp) / Xp / Xp;
}

void ts__geo_eval(const ts_spline *sp, size_t i, double x, int want, double out[3])
{
    double x0 = sp->x[i], x1 = sp->x[i + 1];
    if (x0 <= x && x <= x1) {
        ts__geo_in(sp, i, x, want, out); /* the batch kernel's solve and expressions */
        return;
    }
    /* TS_EXTRAP_EXTEND: osculating parabola of the end (header) */
    int right = x > x1;
    double e[3];
    geo_side g;
    geo_side_init(sp, i, right, &g);
    double t = (x - (right ? x1 : x0)) / g.h;
    geo_end(&g, right ? -1.0 : 1.0, e);
    out[0] = e[0] + t * (e[1] + 0.5 * t * e[2]);
    if (want > 0)
        out[1] = (e[1] + t * e[2]) / g.h;
    if (want > 1)
        out[2] = e[2] / g.h / g.h;
}

/* 12-point Gauss–Legendre nodes and weights on [−1, 1] (positive half),
 * from tests/ref/accuracy_ref.py. */
static const double gl_node[6] = {
    0.9815606342467192506905, 0.9041172563704748566785, 0.7699026741943046870369,
    0.5873179542866174472967, 0.3678314989981801937527, 0.1252334085114689154724};
static const double gl_weight[6] = {
    0.04717533638651182719462, 0.1069393259953184309603, 0.1600783285433462263347,
    0.2031674267230659217491, 0.2334925365383548087608, 0.2491470458134027850006};

/* 2^-k h ∫_0^φ Y(t) X̂'(t) dt on one side, φ <= π/4: the integrand is a
 * trigonometric polynomial of degree 6, and the 12-point rule's error on
 * [0, π/4] is below 1e-17 of its coefficients (docs/accuracy.md §1).  The
 * half-length goes into the weights, so the sum stays below DBL_MAX for
 * |Y| <= TS_VALUE_MAX. */
static double geo_side_int(const geo_side *g, double phi, int k)
{
    double half = 0.5 * phi, sum = 0.0;
    for (int j = 0; j < 12; j++) {
        double xi = j < 6 ? -gl_node[j] : gl_node[11 - j];
        double w = j < 6 ? gl_weight[j] : gl_weight[11 - j];
        double t = half * (1.0 + xi), s = sin(t), c = cos(t), A[4], D[4];
        ts__basis(s, c, A);
        ts__basis_d1(s, c, D);
        double Y = g->F0 * c * c + g->F1 * s * s + g->k * (g->D0 * A[1] - g->D1 * A[2]);
        double Xp = 2.0 * s * c + g->kappa * (D[1] - D[2]);
        sum += (half * w) * Y * Xp;
    }
    return ldexp(g->h, -k) * sum;
}

/* 2^-k ∫ over the whole interval: h Σ Y_l P_l + k Σ Y_l Q_l with
 * P = (1/10, 2/5, 2/5, 1/10), Q = Q0 (1, −1, −1, 1), Q0 = 56/5 − 111π/32,
 * i.e. h(f_i + f_{i+1})/2 + k(d_i − d_{i+1})(2h/5 − Q0 k).  k d_i = B1 − f_i
 * is at most 2 TS_VALUE_MAX, so k d_i − k d_{i+1} cannot overflow; the
 * scale 2^-k goes on the factors of h. */
static double geo_whole(const ts_spline *sp, size_t i, int k)
{
    const double Q0 = 56.0 / 5.0 - 111.0 * TS_PI / 32.0;
    double h = ts__h(sp, i), kk = sp->kappa[i] * h;
    double hs = ldexp(h, -k), ks = ldexp(kk, -k);
    return 0.5 * hs * (sp->f[i] + sp->f[i + 1]) +
           (kk * sp->d[i] - kk * sp->d[i + 1]) * (0.4 * hs - Q0 * ks);
}

/* geo_whole at k = 0 (ldexp by 0 is the identity) for i in [i0, i1), into
 * wh[i − i0]: the same operations, in a loop that vectorises. */
TS_VECTOR_LOOP static void geo_wholes(const double *restrict kappa, const double *restrict x,
                                      const double *restrict f,
                                      const double *restrict d, double *restrict wh, size_t i0,
                                      size_t i1)
{
    const double Q0 = 56.0 / 5.0 - 111.0 * TS_PI / 32.0;
    for (size_t i = i0; i < i1; i++) {
        double h = x[i + 1] - x[i], kk = kappa[i] * h;
        wh[i - i0] = 0.5 * h * (f[i] + f[i + 1]) + (kk * d[i] - kk * d[i + 1]) * (0.4 * h - Q0 * kk);
    }
}

void ts__geo_wholes(const ts_spline *sp, size_t i0, size_t i1, double *wh)
{
    geo_wholes(sp->kappa, sp->x, sp->f, sp->d, wh, i0, i1);
}

double ts__geo_integral_scaled(const ts_spline *sp, size_t i, double x, int k)
{
    double x0 = sp->x[i], x1 = sp->x[i + 1];
    if (!(x > x0))
        return 0.0;
    if (x >= x1)
        return geo_whole(sp, i, k);
    double dl = x - x0, dr = x1 - x;
    int right = dr < dl;
    geo_side g;
    geo_side_init(sp, i, right, &g);
    double phi = geo_solve(g.kappa, (right ? dr : dl) / g.h);
    double part = geo_side_int(&g, phi, k);
    return right ? geo_whole(sp, i, k) - part : part;
}

/* Every alpha[i] + beta[i] >= amin, i in [i0, i1) (NaN fails). */
TS_VECTOR_LOOP static int all_at_least(const double *restrict alpha, const double *restrict beta,
                                       size_t i0, size_t i1, double amin)
{
    double low = 0.0; /* a double flag: this form vectorises */
    for (size_t i = i0; i < i1; i++)
        low = alpha[i] + beta[i] >= amin ? low : 1.0;
    return low == 0.0;
}

/* docs/method.md §4 bound; the policy is documented at TS_FORM_GEOMETRIC. */
ts_status ts__geo_check(ts_spline *sp, size_t i0, size_t i1, ts_error *err)
{
    double amin = sp->shape == TS_SHAPE_NONE ? TS_GEOMETRIC_A_MIN : TS_GEOMETRIC_A_RAISE;
    if (all_at_least(sp->alpha, sp->beta, i0, i1, amin))
        return TS_OK; /* the loop below would change nothing */
    for (size_t i = i0; i < i1; i++) {
        double al = sp->alpha[i], a = al + sp->beta[i];
        if (sp->shape == TS_SHAPE_NONE) {
            if (!(a >= TS_GEOMETRIC_A_MIN)) {
                ts__error_set(err, TS_ERR_GEOMETRIC, i, TS_WHERE_INTERVAL);
                return TS_ERR_GEOMETRIC;
            }
        } else if (!(a >= TS_GEOMETRIC_A_RAISE)) {
            double b = TS_GEOMETRIC_A_RAISE - al;
            while (al + b < TS_GEOMETRIC_A_RAISE)
                b = nextafter(b, (double)INFINITY);
            sp->beta[i] = b;
            sp->term[i] = (unsigned char)TS_TERM_GEOMETRIC;
        }
    }
    return TS_OK;
}

double ts__geo_solve(double kappa, double u)
{
    return geo_solve(kappa, u);
}
