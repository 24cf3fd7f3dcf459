/* All x with S(x) = y: per interval the roots of q³(S − y), a polynomial of
 * degree 6 in t = tan(θ/2) (docs/method.md §2, with the substitution of
 * §5.6), isolated in Bernstein form (Descartes' rule of signs, de Casteljau
 * subdivision) and refined by bisection (docs/method.md §2, roots). */
#include "internal.h"

#include <math.h>

/* Bernstein coefficients (degree 6, t in [0, 1]) of q³A_l, q = 1 + t²:
 *   q³A0 = (1−t)⁶, q³A1 = 2t(1−t)²(3 − 2t + 3t²), q³A2 = 4t²(1−t²)(1 + 2t²), q³A3 = 8t⁶,
 * converted from the power basis: b_j = Σ_{i<=j} C(j,i)/C(6,i) a_i. */
static void poly_mul(const double *a, int na, const double *b, int nb, double *out)
{
    for (int i = 0; i < na + nb - 1; i++)
        out[i] = 0.0;
    for (int i = 0; i < na; i++)
        for (int j = 0; j < nb; j++)
            out[i + j] += a[i] * b[j];
}

static void bernstein_basis(double bern[4][7])
{
    double pw[4][7] = {{0}};
    double omt[2] = {1, -1}, t1[2] = {0, 1}, a[7] = {0}, b[7] = {0}, c[7] = {0};
    double acc[7] = {1};
    int len = 1;
    for (int k = 0; k < 6; k++) { /* (1 − t)⁶ */
        poly_mul(acc, len, omt, 2, a);
        len++;
        for (int j = 0; j < 7; j++)
            acc[j] = a[j];
    }
    for (int j = 0; j < 7; j++)
        pw[0][j] = acc[j];
    double sq[3] = {1, -2, 1}, k1[3] = {3, -2, 3};
    poly_mul(sq, 3, k1, 3, a); /* 2t(1 − t)²(3 − 2t + 3t²) */
    poly_mul(a, 5, t1, 2, b);
    for (int i = 0; i < 6; i++)
        pw[1][i] = 2.0 * b[i];
    double u1[3] = {1, 0, -1}, u2[3] = {1, 0, 2}, t2[3] = {0, 0, 1};
    poly_mul(u1, 3, u2, 3, a); /* 4t²(1 − t²)(1 + 2t²) */
    poly_mul(a, 5, t2, 3, c);
    for (int i = 0; i < 7; i++)
        pw[2][i] = 4.0 * c[i];
    pw[3][6] = 8.0;
    static const double C6[7] = {1, 6, 15, 20, 15, 6, 1};
    for (int l = 0; l < 4; l++)
        for (int j = 0; j < 7; j++) {
            double s = 0.0, cji = 1.0; /* C(j, i) */
            for (int i = 0; i <= j; i++) {
                s += cji / C6[i] * pw[l][i];
                cji = cji * (j - i) / (i + 1);
            }
            bern[l][j] = s;
        }
}

/* q³(S − y) at t from the factored forms (its sign). */
static double root_poly(const double C[4], double t)
{
    double omt = 1.0 - t, t2 = t * t;
    double o2 = omt * omt;
    return C[0] * (o2 * o2 * o2) + C[1] * 2.0 * t * o2 * (3.0 - 2.0 * t + 3.0 * t2) +
           C[2] * 4.0 * t2 * (1.0 - t) * (1.0 + t) * (1.0 + 2.0 * t2) + C[3] * 8.0 * (t2 * t2 * t2);
}

static int sgn(double v)
{
    return (v > 0.0) - (v < 0.0);
}

/* The roots found in one interval, in increasing t: at most 12 (at most 6
 * from the leaves, as subdivision never adds a sign change, and at most 6
 * subdivision points that are roots); counted past the end, not stored. */
#define TS_SOLVE_CAP TS_LIMIT_DEFAULT_solve_cap
typedef struct troots {
    double t[TS_SOLVE_CAP];
    size_t n;
} troots;

static void add_t(troots *L, double t)
{
    if (L->n < TS_LIMIT(solve_cap))
        L->t[L->n] = t;
    L->n++;
}

/* Roots of q³(S − y) in (lo, hi) from its Bernstein coefficients b there:
 * no sign change, none; one, exactly one, refined by bisection; more,
 * subdivide at the middle; depth 52: a multiple root (tangency), the
 * middle itself. */
static void isolate(const double C[4], const double b[7], double lo, double hi, int depth,
                    troots *L)
{
    int var = 0, last = 0;
    for (int j = 0; j < 7; j++) {
        int s = sgn(b[j]);
        if (s != 0 && last != 0 && s != last)
            var++;
        if (s != 0)
            last = s;
    }
    if (var == 0)
        return;
    double mid = 0.5 * (lo + hi);
    if (var == 1) {
        int slo = sgn(root_poly(C, lo));
        if (slo == 0)
            slo = sgn(b[0]) ? sgn(b[0]) : -sgn(b[6]);
        /* 0 <= lo < hi <= 1: while c − a > 4ε, the middle is a double strictly
         * between a and c (ulp <= ε/2 in [0, 1]), so this ends within 53 steps */
        double a = lo, c = hi;
        while (c - a > 4.0 * DBL_EPSILON) {
            double md = 0.5 * (a + c);
            int sm = sgn(root_poly(C, md));
            if (sm == 0) {
                a = c = md;
                break;
            }
            if (sm == slo)
                a = md;
            else
                c = md;
        }
        add_t(L, 0.5 * (a + c));
        return;
    }
    if (depth >= TS_LIMIT(solve_depth)) {
        add_t(L, mid);
        return;
    }
    /* de Casteljau at 1/2: l[k] = w_k[0], r[k] = w_{6−k}[k] */
    double w[7], l[7], r[7];
    for (int j = 0; j < 7; j++)
        w[j] = b[j];
    l[0] = w[0];
    r[6] = w[6];
    for (int k = 1; k < 7; k++) {
        for (int j = 0; j + k < 7; j++)
            w[j] = 0.5 * (w[j] + w[j + 1]);
        l[k] = w[0];
        r[6 - k] = w[6 - k];
    }
    isolate(C, l, lo, mid, depth + 1, L);
    if (l[6] == 0.0)
        add_t(L, mid);
    isolate(C, r, mid, hi, depth + 1, L);
}

/* x of t = tan(θ/2) in interval i: θ linear in x (paper, C¹), or X(θ) of the
 * geometric form (docs/method.md §4), kept strictly inside the interval. */
static double x_of_t(const ts_spline *sp, size_t i, double t)
{
    double x0 = sp->x[i], x1 = sp->x[i + 1], v;
    if (sp->form == TS_FORM_GEOMETRIC) {
        double k = ts__geo_k(ts__h(sp, i), sp->alpha[i] + sp->beta[i]);
        double X[4] = {x0, x0 + k, x1 - k, x1};
        double t2 = t * t, q = 1.0 + t2, q3 = q * q * q, omt = 1.0 - t;
        double A0 = omt * omt * omt * omt * omt * omt / q3;
        double A1 = 2.0 * t * omt * omt * (3.0 - 2.0 * t + 3.0 * t2) / q3;
        double A2 = 4.0 * t2 * (1.0 - t) * (1.0 + t) * (1.0 + 2.0 * t2) / q3;
        double A3 = 8.0 * t2 * t2 * t2 / q3;
        v = A0 * X[0] + A1 * X[1] + A2 * X[2] + A3 * X[3];
    } else {
        v = x0 + (x1 - x0) * (2.0 * atan(t) / TS_HALF_PI);
    }
    if (v <= x0)
        v = nextafter(x0, x1);
    if (v >= x1)
        v = nextafter(x1, x0);
    return v;
}

static void put(double *roots, size_t cap, size_t *count, double v)
{
    if (*count < cap)
        roots[*count] = v;
    (*count)++;
}

ts_status ts_spline_solve(const ts_spline *s, double y, double *roots, size_t cap, size_t *count)
{
    if (count)
        *count = 0;
    if (!s || !count || (!roots && cap > 0))
        return TS_ERR_NULL;
    /* |S| <= max |B_l| <= TS_VALUE_MAX (convex hull, docs/method.md §2):
     * no root beyond, nor for NaN */
    if (!(fabs(y) <= TS_VALUE_MAX))
        return TS_OK;
    double bern[4][7];
    bernstein_basis(bern);
    size_t n = s->n;
    for (size_t i = 0; i < n; i++) {
        double B[4], C[4], b[7];
        ts__B(s, i, B);
        for (int l = 0; l < 4; l++)
            C[l] = B[l] - y;
        if (C[0] == 0.0 && C[1] == 0.0 && C[2] == 0.0 && C[3] == 0.0) {
            put(roots, cap, count, s->x[i]); /* S == y on the interval */
            put(roots, cap, count, (double)NAN);
            continue;
        }
        if (C[0] == 0.0)
            put(roots, cap, count, s->x[i]);
        for (int j = 0; j < 7; j++)
            b[j] = C[0] * bern[0][j] + C[1] * bern[1][j] + C[2] * bern[2][j] + C[3] * bern[3][j];
        troots L;
        L.n = 0;
        isolate(C, b, 0.0, 1.0, 0, &L);
        /* every t is inside (0, 1): a bisection's middle of [a, c] with
         * c − a > 4ε in [0, 1], or an interval's middle; the knots are added
         * exactly, above and below */
        for (size_t k = 0; k < L.n && k < TS_LIMIT(solve_cap); k++)
            put(roots, cap, count, x_of_t(s, i, L.t[k]));
        if (i + 1 == n && C[3] == 0.0)
            put(roots, cap, count, s->x[n]);
    }
    return *count <= cap ? TS_OK : TS_ERR_LENGTH;
}
