/* A bound given by another spline B (docs/method.md §13.7): its copy in the
 * fitted spline, the data's side of B, B's range over an x-range, the
 * certificate of S − B on an interval (subdivision; convex hull of rational
 * Bernstein coefficients in rigorous enclosures) and the report's minimum. */
#include "internal.h"

#include <float.h>
#include <math.h>
#include <string.h>

#define EPS DBL_EPSILON /* 2u: bounds the rounding of one operation, relative */
#define CELLS TS_LIMIT(bcurve_cells) /* cells of one certificate */
#define DEPTH TS_LIMIT(bcurve_depth) /* halvings of a cell in t */
#define TMARGIN 0x1p-40 /* t-widening of a paper / C¹ piece's range (§13.7) */
#define SCAN 32         /* the report's scan of S' − B' per piece */

/* A value and a bound on the absolute error of its computation (§13.7). */
typedef struct rv {
    double v, r;
} rv;

static rv rv_add(rv a, rv b)
{
    rv o;
    o.v = a.v + b.v;
    o.r = a.r + b.r + EPS * fabs(o.v);
    return o;
}
static rv rv_mul(rv a, rv b)
{
    rv o;
    o.v = a.v * b.v;
    o.r = fabs(a.v) * b.r + fabs(b.v) * a.r + a.r * b.r + EPS * fabs(o.v);
    return o;
}

/* q³ A_l in powers of t = tan(θ/2) (docs/method.md §2, roots of S − y) */
static const double QA[4][7] = {{1, -6, 15, -20, 15, -6, 1},
                                {0, 6, -16, 20, -16, 6, 0},
                                {0, 0, 4, 0, 4, 0, -8},
                                {0, 0, 0, 0, 0, 0, 8}};

/* Bernstein coefficients on [t0, t1] (0 <= t0 <= t1 <= 1) of Σ c_l q³A_l:
 * power form, Taylor shift by t0, scaling by t1 − t0, Bernstein weights
 * C(j, i)/C(6, i), every operation in rv (§13.7). */
static void bern(const rv c[4], double t0, double t1, rv b[7])
{
    static const double binom[7] = {1, 6, 15, 20, 15, 6, 1};
    rv a[7], T = {t0, 0.0}, w = {t1 - t0, EPS * fabs(t1 - t0)}, sc = {1.0, 0.0};
    for (int j = 0; j < 7; j++) {
        a[j].v = a[j].r = 0.0;
        for (int l = 0; l < 4; l++)
            if (QA[l][j] != 0.0) {
                rv q = {QA[l][j], 0.0};
                a[j] = rv_add(a[j], rv_mul(q, c[l]));
            }
    }
    for (int j = 0; j < 6; j++)
        for (int k = 5; k >= j; k--)
            a[k] = rv_add(a[k], rv_mul(T, a[k + 1]));
    for (int j = 0; j < 7; j++) {
        a[j] = rv_mul(a[j], sc);
        sc = rv_mul(sc, w);
    }
    for (int j = 0; j < 7; j++) {
        rv s = {0.0, 0.0};
        double cj = 1.0; /* C(j, i) */
        for (int i = 0; i <= j; i++) {
            double v = cj / binom[i];
            rv q = {v, EPS * v};
            s = rv_add(s, rv_mul(q, a[i]));
            cj = cj * (double)(j - i) / (double)(i + 1); /* integers: exact */
        }
        /* the error bounds' own rounding (< 2^-40 relative over these
         * few hundred operations) and underflow (< 2^-1000 absolute) */
        s.r = s.r * (1.0 + 0x1p-40) + 0x1p-1000;
        b[j] = s;
    }
}

/* A lower bound of b/w, each step rounded outwards; never NaN (−∞ for a
 * NaN numerator: control values near TS_VALUE_MAX overflow the sums).  w
 * is a Bernstein coefficient of q³ on [t0, t1] ⊂ [0, 1]: at least
 * q³(t0) >= 1 (every coefficient of q³(t0 + (t1 − t0) u) is >= 0), its
 * bound far below 1, so d >= 1/2. */
static double lo_ratio(rv b, rv w)
{
    double n = nextafter(b.v - b.r, -HUGE_VAL);
    double d = n >= 0.0 ? nextafter(w.v + w.r, HUGE_VAL) : nextafter(w.v - w.r, -HUGE_VAL);
    if (isnan(n))
        return -HUGE_VAL;
    return nextafter(n / d, -HUGE_VAL);
}

/* [lo, hi] containing Σ A_l(θ) c_l for every t = tan(θ/2) in [t0, t1]:
 * the convex hull of the rational Bernstein form, weights the coefficients
 * of q³ (all > 0), docs/method.md §13.7. */
static void hull(const rv c[4], double t0, double t1, double *lo, double *hi)
{
    static const rv one[4] = {{1.0, 0.0}, {1.0, 0.0}, {1.0, 0.0}, {1.0, 0.0}};
    rv b[7], w[7];
    bern(c, t0, t1, b);
    bern(one, t0, t1, w);
    *lo = HUGE_VAL;
    *hi = -HUGE_VAL;
    for (int k = 0; k < 7; k++) {
        rv nb = {-b[k].v, b[k].r};
        double l = lo_ratio(b[k], w[k]), u = -lo_ratio(nb, w[k]);
        *lo = l < *lo ? l : *lo;
        *hi = u > *hi ? u : *hi;
    }
}

/* Control values of interval i of any spline: Y and, geometric form, X̂ =
 * (0, κ, 1 − κ, 1) with 1 − κ's rounding in its bound (docs/method.md §4). */
static void y_ctl(const ts_spline *s, size_t i, rv Y[4])
{
    double B[4];
    ts__B(s, i, B);
    for (int l = 0; l < 4; l++)
        Y[l].v = B[l], Y[l].r = 0.0;
}
static void x_ctl(const ts_spline *s, size_t i, rv X[4])
{
    double k = s->kappa[i];
    X[0].v = 0.0, X[1].v = k, X[2].v = 1.0 - k, X[3].v = 1.0;
    X[0].r = X[1].r = X[3].r = 0.0;
    X[2].r = EPS * X[2].v;
}
static int geo(const ts_spline *s)
{
    return s->form == TS_FORM_GEOMETRIC;
}

/* x_i + h X̂ over t in [t0, t1] of a geometric interval: [*xa, *xb] contains it. */
static void x_range(const ts_spline *s, size_t i, double t0, double t1, double *xa, double *xb)
{
    rv X[4];
    double lo, hi, x0 = s->x[i], h = ts__h(s, i);
    x_ctl(s, i, X);
    hull(X, t0, t1, &lo, &hi);
    *xa = nextafter(x0 + nextafter(h * lo, -HUGE_VAL), -HUGE_VAL);
    *xb = nextafter(x0 + nextafter(h * hi, HUGE_VAL), HUGE_VAL);
}

/* X̂(t) of a geometric interval, rounded (the search of geo_t only). */
static double xhat_at(const ts_spline *s, size_t j, double t)
{
    double A[4], k = s->kappa[j];
    ts__basis_t(t, A);
    return A[1] * k + A[2] * (1.0 - k) + A[3];
}

/* A t of geometric interval j of b with X(t) <= x (dir < 0) or X(t) >= x
 * (dir > 0), proved by the enclosure of X at t; X increases (a_j > a*,
 * docs/method.md §4), so every t' with X(t') on the other side of x lies
 * beyond it.  0 or 1 when no closer t is proved. */
static double geo_t(const ts_spline *b, size_t j, double x, int dir)
{
    double u = (x - b->x[j]) / ts__h(b, j), lo = 0.0, hi = 1.0;
    for (int it = 0; it < 60; it++) {
        double mid = 0.5 * (lo + hi);
        if (xhat_at(b, j, mid) < u)
            lo = mid;
        else
            hi = mid;
    }
    static const double step[5] = {0x1p-44, 0x1p-36, 0x1p-28, 0x1p-20, 0x1p-10};
    for (int k = 0; k < 5; k++) {
        double t = dir < 0 ? lo - step[k] : hi + step[k], xa, xb;
        if (!(0.0 < t && t < 1.0))
            break;
        x_range(b, j, t, t, &xa, &xb);
        if (dir < 0 ? xb <= x : xa >= x)
            return t;
    }
    return dir < 0 ? 0.0 : 1.0;
}

/* tan(θ/2) for θ in [0, π/2], without cancellation (1 + cos θ >= 1). */
static double t_of(double th)
{
    return sin(th) / (1.0 + cos(th));
}

/* [*t0, *t1]: every parameter of interval j of b whose x lies in [xa, xb]
 * (xa <= xb, x_j <= xb: the callers' loops); 0 when the interval ends
 * before xa. */
static int b_trange(const ts_spline *b, size_t j, double xa, double xb, double *t0, double *t1)
{
    double xj = b->x[j], xk = b->x[j + 1];
    if (xa > xk)
        return 0;
    if (geo(b)) {
        *t0 = xa <= xj ? 0.0 : geo_t(b, j, xa, -1);
        *t1 = xb >= xk ? 1.0 : geo_t(b, j, xb, 1);
    } else {
        /* θ = (π/2)(x − x_j)/h_j, t = tan(θ/2) = sin θ/(1 + cos θ); their
         * rounding far below TMARGIN (docs/method.md §13.7) */
        double h = ts__h(b, j);
        *t0 = xa <= xj ? 0.0 : fmax(0.0, t_of(TS_HALF_PI * ((xa - xj) / h)) - TMARGIN);
        *t1 = xb >= xk ? 1.0 : fmin(1.0, t_of(TS_HALF_PI * ((xb - xj) / h)) + TMARGIN);
    }
    /* t0 <= t1 for xa <= xb: geo_t's bisections are monotone in x (lo
     * of xa <= hi of xb), and sin/(1 + cos) within 2 TMARGIN of monotone */
    return 1;
}

/* The interval of b with x_j <= x (0 below x_0), j < n. */
static size_t locate(const ts_spline *b, double x)
{
    size_t lo = 0, hi = b->n; /* x_lo <= x < x_hi, by bisection */
    if (!(x >= b->x[0]))
        return 0;
    while (hi - lo > 1) {
        size_t mid = lo + (hi - lo) / 2;
        if (b->x[mid] <= x)
            lo = mid;
        else
            hi = mid;
    }
    return lo;
}

int ts__bcurve_range(const ts_spline *b, double xa, double xb, double *lo, double *hi)
{
    int any = 0;
    *lo = HUGE_VAL;
    *hi = -HUGE_VAL;
    for (size_t j = locate(b, xa); j < b->n && b->x[j] <= xb; j++) {
        double t0, t1, l, u;
        rv Y[4];
        if (!b_trange(b, j, xa, xb, &t0, &t1))
            continue;
        y_ctl(b, j, Y);
        hull(Y, t0, t1, &l, &u);
        *lo = fmin(*lo, l);
        *hi = fmax(*hi, u);
        any = 1;
    }
    return any;
}

int ts__bcurve_side(const ts_spline *b, double sg, double x, double f)
{
    size_t m = b->n;
    if (!(b->x[0] <= x && x <= b->x[m]))
        return -1;
    size_t j = locate(b, x);
    if (x == b->x[j] || x == b->x[j + 1]) /* B interpolates its knots exactly */
        return sg * (f - b->f[x == b->x[j] ? j : j + 1]) > 0.0;
    double lo, hi;
    (void)ts__bcurve_range(b, x, x, &lo, &hi);
    return sg > 0.0 ? f > hi : f < lo;
}

static void b_eval(const ts_spline *b, size_t j, double x, int want, double o[3]);

/* sg (S − B) at S's parameter t of interval i, both evaluated in floating
 * point (no proof: only to stop a certificate that cannot succeed). */
static double gap_t(const ts_spline *sp, size_t i, const ts_spline *b, double sg, double t)
{
    double A[4], B[4], k = sp->kappa[i], o[3];
    ts__basis_t(t, A);
    ts__B(sp, i, B);
    double x = sp->x[i] + ts__h(sp, i) * (A[1] * k + A[2] * (1.0 - k) + A[3]);
    double y = A[0] * B[0] + A[1] * B[1] + A[2] * B[2] + A[3] * B[3];
    if (!(b->x[0] <= x && x <= b->x[b->n]))
        return HUGE_VAL;
    b_eval(b, locate(b, x), x, 0, o);
    return sg * (y - o[0]);
}

int ts__bcurve_certify(const ts_spline *sp, size_t i, const ts_spline *b, double sg)
{
    double st0[TS_LIMIT_DEFAULT_bcurve_depth + 2], st1[TS_LIMIT_DEFAULT_bcurve_depth + 2];
    int sd[TS_LIMIT_DEFAULT_bcurve_depth + 2], top = 0, cells = 0;
    rv Y[4];
    y_ctl(sp, i, Y);
    st0[0] = 0.0, st1[0] = 1.0, sd[0] = 0, top = 1;
    while (top > 0) {
        top--;
        double t0 = st0[top], t1 = st1[top], ylo, yhi, xa, xb;
        int d = sd[top], ok = 1;
        if (++cells > CELLS)
            return 0;
        hull(Y, t0, t1, &ylo, &yhi);
        x_range(sp, i, t0, t1, &xa, &xb);
        for (size_t j = locate(b, xa); ok && j < b->n && b->x[j] <= xb; j++) {
            double u0, u1, lo, hi;
            rv Z[4];
            if (!b_trange(b, j, xa, xb, &u0, &u1))
                continue;
            y_ctl(b, j, Z);
            hull(Z, u0, u1, &lo, &hi);
            ok = sg > 0.0 ? ylo > hi : yhi < lo;
        }
        if (ok)
            continue;
        double tm = 0.5 * (t0 + t1);
        /* S on the wrong side of B at the cell's middle: no proof to find */
        if (d >= DEPTH || gap_t(sp, i, b, sg, tm) < 0.0)
            return 0;
        st0[top] = tm, st1[top] = t1, sd[top] = d + 1, top++;
        st0[top] = t0, st1[top] = tm, sd[top] = d + 1, top++;
    }
    return 1;
}

/* B and B' (want 1) at x in interval j of b. */
static void b_eval(const ts_spline *b, size_t j, double x, int want, double o[3])
{
    if (geo(b))
        ts__geo_eval(b, j, x, want, o);
    else
        ts__trig_eval_in(b, j, x, b->w[j], want, o);
}

/* sg (S − B) and its derivative at x in interval i of sp and j of b. */
static void gap_at(const ts_spline *sp, size_t i, const ts_spline *b, size_t j, double sg, double x,
                   double g[2])
{
    double s[3], o[3];
    ts__geo_eval(sp, i, x, 1, s);
    b_eval(b, j, x, 1, o);
    g[0] = sg * (s[0] - o[0]);
    g[1] = sg * (s[1] - o[1]);
}

/* The scan points of piece [u0, u1] (of interval i of sp and j of b): the
 * ends, and the x of SCAN + 1 parameters equally spaced in θ of each curve
 * (a geometric curve turns near its knots, within κh, where equal steps in
 * x would not see it), sorted; returns their number. */
static int scan_points(const ts_spline *sp, size_t i, const ts_spline *b, size_t j, double u0,
                       double u1, double *xs)
{
    int m = 0;
    xs[m++] = u0;
    xs[m++] = u1;
    for (int k = 1; k < SCAN; k++) {
        double t = t_of(TS_HALF_PI * k / SCAN);
        double c[2] = {sp->x[i] + ts__h(sp, i) * xhat_at(sp, i, t),
                       geo(b) ? b->x[j] + ts__h(b, j) * xhat_at(b, j, t)
                              : b->x[j] + ts__h(b, j) * k / SCAN};
        for (int l = 0; l < 2; l++)
            if (u0 < c[l] && c[l] < u1)
                xs[m++] = c[l];
    }
    for (int k = 2; k < m; k++) /* insertion sort; xs[0] = u0 is the least */
        for (int l = k; l > 1 && xs[l - 1] > xs[l]; l--) {
            double v = xs[l];
            xs[l] = xs[l - 1];
            xs[l - 1] = v;
        }
    return m;
}

double ts__bcurve_gap(const ts_spline *sp, size_t i, const ts_spline *b, double sg, double *at)
{
    /* a < e: the report asks for intervals that B overlaps (covers()) */
    double a = fmax(sp->x[i], b->x[0]), e = fmin(sp->x[i + 1], b->x[b->n]);
    double best = (double)NAN;
    *at = (double)NAN;
    for (size_t j = locate(b, a); j < b->n && b->x[j] < e; j++) {
        double u0 = fmax(a, b->x[j]), u1 = fmin(e, b->x[j + 1]);
        double xs[2 * SCAN + 2], gs[2 * SCAN + 2][2];
        int m = scan_points(sp, i, b, j, u0, u1, xs);
        for (int k = 0; k < m; k++) {
            gap_at(sp, i, b, j, sg, xs[k], gs[k]);
            if (!(gs[k][0] >= best)) /* best NaN at first */
                best = gs[k][0], *at = xs[k];
        }
        /* the minima inside: S' − B' from − to + between two scan points */
        for (int k = 0; k + 1 < m; k++) {
            if (!(gs[k][1] < 0.0 && gs[k + 1][1] >= 0.0))
                continue;
            double lo = xs[k], hi = xs[k + 1], g[2];
            /* lo < hi: equal scan points have equal derivatives */
            for (int it = 0; it < TS_LIMIT(bcurve_gap_steps); it++) {
                double mid = 0.5 * (lo + hi);
                if (mid <= lo || mid >= hi)
                    break;
                gap_at(sp, i, b, j, sg, mid, g);
                if (g[1] < 0.0)
                    lo = mid;
                else
                    hi = mid;
            }
            gap_at(sp, i, b, j, sg, lo, g);
            if (g[0] < best)
                best = g[0], *at = lo;
        }
    }
    return best;
}

size_t ts__bcurve_doubles(const ts_spline *b)
{
    return 3 * (b->n + 1) + 3 * b->n;
}

void ts__bcurve_copy(const ts_spline *b, ts_spline *dst, double *q)
{
    size_t m = b->n, p = (m + 1) * sizeof *q, s = m * sizeof *q;
    memset(dst, 0, sizeof *dst);
    dst->n = m;
    dst->form = b->form;
    dst->shape = TS_SHAPE_NONE;
    dst->extrap = b->extrap;
    dst->x = q, memcpy(q, b->x, p), q += m + 1;
    dst->f = q, memcpy(q, b->f, p), q += m + 1;
    dst->d = q, memcpy(q, b->d, p), q += m + 1;
    /* the inner control values stored (a geometric B derives them from its
       a_i, which are not copied); the widths are derived from x (ts__h),
       dθ/dx copied (the paper and C¹ forms' w, in κ's place) */
    dst->b1 = q, q += m;
    dst->b2 = q, q += m;
    for (size_t i = 0; i < m; i++) {
        double B[4];
        ts__B(b, i, B);
        dst->b1[i] = B[1], dst->b2[i] = B[2];
    }
    if (b->kappa)
        dst->kappa = q, memcpy(q, b->kappa, s);
    else
        dst->w = q, memcpy(q, b->w, s);
}
