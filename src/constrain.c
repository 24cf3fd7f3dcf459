/* Constraint records (docs/method.md §13): validation, the data's necessary
 * conditions, slopes, the closed-form a_i of each constraint, the
 * certificates (exact signs of control-polygon quantities; polyline pieces:
 * the minimum with a guard), the repair, and the exact per-interval minima of
 * the report.  Geometric form only. */
#include "internal.h"

#include <float.h>
#include <math.h>
#include <string.h>

#define CON_EXACT TS_EXACT_TERMS /* terms of the exact sums below (ts__exact_sign) */
#define CON_DOUBLINGS TS_LIMIT(con_doublings)

/* a − b exactly as a two-term expansion (ts__exp_grow of a by −b, TwoSum):
 * r[1] the rounded difference, r[0] its rounding error. */
static void two_diff(double a, double b, double r[2])
{
    (void)ts__exp_grow(&a, 1, -b, r);
}

/* Product of term lists a[0..na) and b[0..nb) (exact, TwoProduct by fma)
 * appended to v at *k, times sg: the pairwise products, for ts__exact_sign
 * to sum.  Not ts__exp_product: piece_polygon's lists are not expansions
 * (nonoverlapping, increasing), which its Scale-Expansion needs, and where
 * a product underflows the two would sum different inexact terms. */
static void prod_terms(const double *a, int na, const double *b, int nb, double sg, double *v,
                       int *k)
{
    for (int i = 0; i < na; i++)
        for (int j = 0; j < nb; j++) {
            double p = a[i] * b[j];
            v[(*k)++] = sg * p;
            v[(*k)++] = sg * fma(a[i], b[j], -p);
        }
}

static size_t scope_end(const ts_constraint *c, size_t n)
{
    return c->count ? c->first + c->count : n;
}
static int in_scope(const ts_constraint *c, size_t i, size_t n)
{
    return c->first <= i && i < scope_end(c, n);
}

static ts_status con_fail(ts_error *err, ts_constraint_failure *fail, ts_status st, size_t k,
                          size_t index, ts_where where, ts_condition cond)
{
    if (fail) {
        fail->status = st;
        fail->constraint = k;
        fail->index = index;
        fail->where = where;
        fail->condition = cond;
    }
    return ts__fail(err, st, index, where);
}

ts_status ts__con_validate(const ts_spline_options *o, size_t n, ts_error *err,
                           ts_constraint_failure *fail)
{
    const ts_constraint *cs = o->constraints;
    if (!cs)
        return con_fail(err, fail, TS_ERR_NULL, TS_NO_INDEX, TS_NO_INDEX, TS_WHERE_NONE,
                        TS_CONDITION_NONE);
    if (o->form != TS_FORM_GEOMETRIC || o->shape != TS_SHAPE_NONE)
        return con_fail(err, fail, TS_ERR_OPTION, TS_NO_INDEX, TS_NO_INDEX, TS_WHERE_NONE,
                        TS_CONDITION_NONE);
    for (size_t k = 0; k < o->n_constraints; k++) {
        const ts_constraint *c = &cs[k];
        ts_status st = TS_OK;
        if (c->struct_size != sizeof *c)
            st = TS_ERR_VERSION;
        else if ((unsigned)c->kind >= (unsigned)TS_CONSTRAINT_COUNT_ ||
                 (unsigned)c->bound > (unsigned)TS_BOUND_SPLINE || c->first >= n ||
                 c->count > n - c->first)
            st = TS_ERR_OPTION;
        else if (!isfinite(c->value) ||
                 (c->kind == TS_CONSTRAINT_SLOPE_ABS && !(c->value >= 0.0)))
            st = isfinite(c->value) ? TS_ERR_OPTION : TS_ERR_NONFINITE;
        else if ((c->kind == TS_CONSTRAINT_LOWER || c->kind == TS_CONSTRAINT_UPPER) &&
                 c->bound == TS_BOUND_SPLINE && !c->spline)
            st = TS_ERR_NULL;
        else if ((c->kind == TS_CONSTRAINT_LOWER || c->kind == TS_CONSTRAINT_UPPER) &&
                 c->bound == TS_BOUND_POLYLINE) {
            if (!c->px || !c->py)
                st = TS_ERR_NULL;
            else if (c->n_poly < 2)
                st = TS_ERR_LENGTH;
            else
                for (size_t j = 0; j < c->n_poly && st == TS_OK; j++)
                    if (!isfinite(c->px[j]) || !isfinite(c->py[j]) ||
                        fabs(c->py[j]) > TS_VALUE_MAX)
                        st = TS_ERR_NONFINITE;
                    else if (j && !(c->px[j] > c->px[j - 1]))
                        st = TS_ERR_UNSORTED;
        }
        if (st != TS_OK)
            return con_fail(err, fail, st, k, TS_NO_INDEX, TS_WHERE_NONE, TS_CONDITION_NONE);
    }
    return TS_OK;
}

/* The slope interval [lo, hi] a record asks of S' on its intervals (slope
 * bounds and monotone); 0 when it asks none. */
static int slope_range(const ts_constraint *c, double *lo, double *hi)
{
    *lo = -HUGE_VAL;
    *hi = HUGE_VAL;
    switch (c->kind) {
    case TS_CONSTRAINT_INCREASING: *lo = 0.0; return 1;
    case TS_CONSTRAINT_DECREASING: *hi = 0.0; return 1;
    case TS_CONSTRAINT_SLOPE_MIN: *lo = c->value; return 1;
    case TS_CONSTRAINT_SLOPE_MAX: *hi = c->value; return 1;
    case TS_CONSTRAINT_SLOPE_ABS: *lo = -c->value; *hi = c->value; return 1;
    default: return 0;
    }
}
static double curv_sign(const ts_constraint *c)
{
    return c->kind == TS_CONSTRAINT_CONVEX ? 1.0 : c->kind == TS_CONSTRAINT_CONCAVE ? -1.0 : 0.0;
}
static double bound_sign(const ts_constraint *c)
{
    return c->kind == TS_CONSTRAINT_LOWER ? 1.0 : c->kind == TS_CONSTRAINT_UPPER ? -1.0 : 0.0;
}

/* The polyline's piece p as the line y = py_p + m (x − px_p). */
static double piece_slope(const ts_constraint *c, size_t p)
{
    return (c->py[p + 1] - c->py[p]) / (c->px[p + 1] - c->px[p]);
}

/* The exact sign (−1, 0, 1) of sg (f_j − bound(x_j)); 2 when x_j is outside
 * the polyline or the bound spline.  A bound spline's side is decided by an
 * enclosure (docs/method.md §13.7): 1 where proved, else −1 (touching data
 * are refused there, not certified). */
static int data_side(const ts_constraint *c, double xj, double fj)
{
    double sg = bound_sign(c), v[CON_EXACT];
    int k = 0;
    if (c->bound == TS_BOUND_CONSTANT) { /* the sign of a difference is exact */
        double g = sg * (fj - c->value);
        return (g > 0.0) - (g < 0.0);
    }
    if (c->bound == TS_BOUND_SPLINE) {
        int side = ts__bcurve_side(c->spline, sg, xj, fj);
        return side < 0 ? 2 : (side ? 1 : -1);
    }
    size_t m = c->n_poly;
    if (xj < c->px[0] || xj > c->px[m - 1])
        return 2;
    size_t p = 0;
    while (p + 2 < m && c->px[p + 1] <= xj)
        p++;
    /* (f − py_p)(px_{p+1} − px_p) − (py_{p+1} − py_p)(x − px_p) */
    double a[2], b[2], e[2], g[2];
    two_diff(fj, c->py[p], a);
    two_diff(c->px[p + 1], c->px[p], b);
    two_diff(c->py[p + 1], c->py[p], e);
    two_diff(xj, c->px[p], g);
    prod_terms(a, 2, b, 2, sg, v, &k);
    prod_terms(e, 2, g, 2, -sg, v, &k);
    return ts__exact_sign(v, k);
}

/* On the bound's side (or on it) at x_j?  1 yes, 0 no, −1 outside the
 * polyline (docs/method.md §13.1: a bound may be touched, §13.6). */
static int data_inside(const ts_constraint *c, double xj, double fj)
{
    int sd = data_side(c, xj, fj);
    return sd == 2 ? -1 : sd >= 0;
}

/* Knot j of scope [i0, i1] on the polyline of record c (docs/method.md
 * §13.6): the slope range [*lo, *hi] a C¹ curve on c's side needs there
 * (the pieces left and right of x_j, where the scope and the polyline
 * reach); *corner: x_j is an inner breakpoint whose turn (the exact sign of
 * the slope change, times the bound's sign) is negative, so that no slope
 * fits.  0 when x_j does not touch the polyline. */
static int touch_range(const ts_constraint *c, const double *x, const double *f, size_t j,
                       size_t i0, size_t i1, double *lo, double *hi, int *corner)
{
    *lo = -HUGE_VAL, *hi = HUGE_VAL, *corner = 0;
    if (c->bound != TS_BOUND_POLYLINE || bound_sign(c) == 0.0 || data_side(c, x[j], f[j]) != 0)
        return 0;
    size_t m = c->n_poly, pr = 0;
    while (pr + 2 < m && c->px[pr + 1] <= x[j])
        pr++;                                       /* px[pr] <= x_j < px[pr + 1] */
    size_t pl = pr > 0 && c->px[pr] == x[j] ? pr - 1 : pr; /* px[pl] < x_j <= px[pl + 1] */
    int left = j > i0 && x[j] > c->px[0], right = j < i1 && x[j] < c->px[m - 1];
    double ml = piece_slope(c, pl), mr = piece_slope(c, pr), bs = bound_sign(c);
    /* lower: S − L >= 0 on both sides of a zero: S' <= m_l, S' >= m_r */
    if (left)
        *(bs > 0.0 ? hi : lo) = ml;
    if (right)
        *(bs > 0.0 ? lo : hi) = mr;
    if (left && right && pl != pr) {
        /* bs [(y_{p+1} − y_p)(x_p − x_{p−1}) − (y_p − y_{p−1})(x_{p+1} − x_p)] < 0 */
        double a[2], b[2], e[2], g[2], v[CON_EXACT];
        int k = 0;
        two_diff(c->py[pr + 1], c->py[pr], a);
        two_diff(c->px[pr], c->px[pl], b);
        two_diff(c->py[pr], c->py[pl], e);
        two_diff(c->px[pr + 1], c->px[pr], g);
        prod_terms(a, 2, b, 2, -bs, v, &k);
        prod_terms(e, 2, g, 2, bs, v, &k);
        *corner = ts__exact_sign(v, k) < 0;
    }
    return 1;
}

/* The exact sign of f_{i+1} − f_i − L (x_{i+1} − x_i) (docs/method.md §13.1),
 * with x_{i+1} − x_i = h0 + h1 exactly (two_diff): L x_{i+1} may overflow
 * where L h does not.  Where L h0 is beyond the exact products' range
 * (|L h| > 2^1020), every term is scaled by 2^-k first, |L h| 2^-k near
 * 2^1010: |f| <= TS_VALUE_MAX = 2^1022, so an f term loses bits only far
 * below L h, whose sign then decides. */
static int secant_side(const double *x, const double *f, size_t i, double L)
{
    double v[8], p[2], hd[2], sc = 1.0;
    int m = 0, ke;
    two_diff(x[i + 1], x[i], hd);
    if (!isfinite(L * 0x1p-64 * hd[1])) {
        /* |L h| > 2^1087 > 2 TS_VALUE_MAX >= |f_{i+1} − f_i|: the sign is −L's */
        v[m++] = -L;
    } else {
        if (!(fabs(L * hd[1]) <= 0x1p1020)) {
            (void)frexp(L * 0x1p-64 * hd[1], &ke);
            sc = ldexp(1.0, -(ke + 64 - 1010));
        }
        v[m++] = sc * f[i + 1];
        v[m++] = -(sc * f[i]);
        for (int e = 0; e < 2; e++) {
            if (ts__exact_product(sc * L, hd[e], -1.0, p) != 2)
                p[0] = -(sc * L) * hd[e], p[1] = 0.0;
            v[m++] = p[0], v[m++] = p[1];
        }
    }
    return ts__exact_sign(v, m);
}

/* One side of the slope rule record c sets at knot j of its scope [i0, i1]
 * (docs/method.md §13.1, curvature-slope): none (0), the value *L (1), or
 * the slope of polyline piece *p (2).  side 0: the least slope, 1: the
 * greatest.  A slope bound or monotone record: its bound; a constant bound
 * the datum touches: 0 (inner knot both sides; at i0 only the side into
 * the region, at i1 the other); a polyline the datum touches: the pieces'
 * slopes as touch_range. */
static int knot_rule(const ts_constraint *c, const double *x, const double *f, size_t j,
                     size_t i0, size_t i1, int side, double *L, size_t *p)
{
    double lo, hi, bs = bound_sign(c);
    if (slope_range(c, &lo, &hi)) {
        *L = side ? hi : lo;
        return !isinf(*L);
    }
    if (bs == 0.0 || c->bound == TS_BOUND_SPLINE || data_side(c, x[j], f[j]) != 0)
        return 0; /* a datum touching a bound spline is refused (inside-bound) */
    /* lower: S − bound >= 0 on each side of a zero: S' <= m_l, S' >= m_r */
    int upper_side = (bs > 0.0) == (side == 1); /* the side m_l bounds */
    if (c->bound == TS_BOUND_CONSTANT) {
        *L = 0.0;
        return upper_side ? j > i0 : j < i1;
    }
    size_t m = c->n_poly, pr = 0;
    while (pr + 2 < m && c->px[pr + 1] <= x[j])
        pr++;
    size_t pl = pr > 0 && c->px[pr] == x[j] ? pr - 1 : pr;
    if (upper_side) {
        *p = pl;
        return j > i0 && x[j] > c->px[0] ? 2 : 0;
    }
    *p = pr;
    return j < i1 && x[j] < c->px[m - 1] ? 2 : 0;
}

/* A slope: the value L (type 1) or the secant of points p, p + 1 of (X, Y)
 * (type 2: a polyline piece, a data interval); k its record. */
typedef struct slope_of {
    int type;
    double L;
    const double *X, *Y;
    size_t p, k;
} slope_of;

/* The exact sign of a − b. */
static int slope_cmp(const slope_of *a, const slope_of *b)
{
    if (a->type == 1 && b->type == 1)
        return (a->L > b->L) - (a->L < b->L);
    if (b->type == 1)
        return secant_side(a->X, a->Y, a->p, b->L);
    if (a->type == 1)
        return -secant_side(b->X, b->Y, b->p, a->L);
    /* (Ya_{p+1} − Ya_p)(Xb_{q+1} − Xb_q) − (Yb_{q+1} − Yb_q)(Xa_{p+1} − Xa_p) */
    double u[2], w[2], e[2], g[2], v[CON_EXACT];
    int m = 0;
    two_diff(a->Y[a->p + 1], a->Y[a->p], u);
    two_diff(b->X[b->p + 1], b->X[b->p], w);
    two_diff(b->Y[b->p + 1], b->Y[b->p], e);
    two_diff(a->X[a->p + 1], a->X[a->p], g);
    prod_terms(u, 2, w, 2, 1.0, v, &m);
    prod_terms(e, 2, g, 2, -1.0, v, &m);
    return ts__exact_sign(v, m);
}

/* Record k's rule at knot j (side 0 least, 1 greatest) as a slope_of; 0
 * when it sets none there (knot j outside its scope too). */
static int rule_at(const ts_constraint *cs, size_t k, const double *x, const double *f, size_t n,
                   size_t j, int side, slope_of *r)
{
    const ts_constraint *c = &cs[k];
    size_t i0 = c->first, i1 = scope_end(c, n);
    if (!(i0 <= j && j <= i1))
        return 0;
    r->k = k;
    r->type = knot_rule(c, x, f, j, i0, i1, side, &r->L, &r->p);
    r->X = c->px, r->Y = c->py;
    return r->type != 0;
}

/* Does curvature record q's secant on its interval next to knot j
 * (left: j − 1) fall beyond the rule r (the greatest slope allowed for
 * convex left / concave right, else the least)?  *iv the interval. */
static int curv_beyond(const ts_constraint *q, const double *x, const double *f, size_t n,
                       size_t j, int left, const slope_of *lo, const slope_of *hi, size_t *rk,
                       size_t *iv)
{
    double sg = curv_sign(q);
    size_t c0 = q->first, c1 = scope_end(q, n);
    if (sg == 0.0 || (left ? !(c0 < j && j <= c1) : !(c0 <= j && j < c1)))
        return 0;
    /* convex, left of x_j: S'(x_j) >= Δ_{j−1} (S' non-decreasing, mean
     * Δ_{j−1}), so the greatest allowed slope must not lie below it; right
     * of x_j: S'(x_j) <= Δ_j, the least not above it; concave mirrored */
    const slope_of *r = (sg > 0.0) == (left == 1) ? hi : lo;
    if (!r)
        return 0;
    slope_of D = {2, 0.0, x, f, left ? j - 1 : j, 0};
    int sd = slope_cmp(&D, r);
    if (left ? sg * sd > 0 : sg * sd < 0) {
        *rk = r->k, *iv = D.p;
        return 1;
    }
    return 0;
}

/* The first curvature record (in order, left of x_j before right) whose
 * secant next to knot j falls beyond the rules lo, hi (NULL: none on that
 * side): 1 with *q the record, *rk the rule's record, *iv the interval and
 * *r the rule it passes; 0 if none. */
static int curv_scan(const ts_constraint *cs, size_t nc, const double *x, const double *f,
                     size_t n, size_t j, const slope_of *lo, const slope_of *hi, size_t *q,
                     size_t *rk, size_t *iv, const slope_of **r)
{
    for (*q = 0; *q < nc; (*q)++)
        for (int left = 1; left >= 0; left--)
            if (curv_beyond(&cs[*q], x, f, n, j, left, lo, hi, rk, iv)) {
                *r = (curv_sign(&cs[*q]) > 0.0) == (left == 1) ? hi : lo;
                return 1;
            }
    return 0;
}

int ts__con_knot_conflict(const double *x, const double *f, size_t n, const ts_constraint *cs,
                          size_t nc, size_t k, size_t j, size_t *kc, size_t *iv, double *slope)
{
    slope_of lo, hi;
    const slope_of *r;
    size_t rk;
    int hl = rule_at(cs, k, x, f, n, j, 0, &lo), hh = rule_at(cs, k, x, f, n, j, 1, &hi);
    if (!curv_scan(cs, nc, x, f, n, j, hl ? &lo : NULL, hh ? &hi : NULL, kc, &rk, iv, &r))
        return 0;
    *slope = r->type == 1 ? r->L : piece_slope(&cs[k], r->p);
    return 1;
}

/* docs/method.md §13.1: the necessary conditions on the data. */
static ts_status data_checks(const double *x, const double *f, size_t n, const ts_constraint *cs,
                             size_t nc, ts_error *err, ts_constraint_failure *fail)
{
    for (size_t k = 0; k < nc; k++) {
        const ts_constraint *c = &cs[k];
        size_t i0 = c->first, i1 = scope_end(c, n);
        double sg = curv_sign(c), lo, hi;
        if (sg != 0.0) {
            for (size_t j = i0 + 1; j < i1; j++) {
                /* sg [(f_{j+1} − f_j)(x_j − x_{j−1}) − (f_j − f_{j−1})(x_{j+1} − x_j)] >= 0 */
                double a[2], b[2], e[2], g[2], v[CON_EXACT];
                int m = 0;
                two_diff(f[j + 1], f[j], a);
                two_diff(x[j], x[j - 1], b);
                two_diff(f[j], f[j - 1], e);
                two_diff(x[j + 1], x[j], g);
                prod_terms(a, 2, b, 2, sg, v, &m);
                prod_terms(e, 2, g, 2, -sg, v, &m);
                if (ts__exact_sign(v, m) < 0)
                    return con_fail(err, fail, TS_ERR_CONDITION, k, j, TS_WHERE_POINT,
                                    sg > 0 ? TS_CONDITION_CONVEX_DATA : TS_CONDITION_CONCAVE_DATA);
            }
        }
        if (slope_range(c, &lo, &hi)) {
            int mono = c->kind == TS_CONSTRAINT_INCREASING || c->kind == TS_CONSTRAINT_DECREASING;
            for (size_t i = i0; i < i1; i++)
                for (int side = 0; side < 2; side++) {
                    double L = side ? hi : lo, s = side ? -1.0 : 1.0;
                    if (isinf(L))
                        continue;
                    if (s * secant_side(x, f, i, L) < 0)
                        return mono ? con_fail(err, fail, TS_ERR_CONDITION, k, i + 1, TS_WHERE_POINT,
                                               TS_CONDITION_MONOTONE_DATA)
                                    : con_fail(err, fail, TS_ERR_CONDITION, k, i,
                                               TS_WHERE_INTERVAL, TS_CONDITION_SECANT_SLOPE);
                }
        }
        if (bound_sign(c) != 0.0)
            for (size_t j = i0; j <= i1; j++) {
                double tl, th;
                int corner;
                if (data_inside(c, x[j], f[j]) == 0)
                    return con_fail(err, fail, TS_ERR_CONDITION, k, j, TS_WHERE_POINT,
                                    TS_CONDITION_INSIDE_BOUND);
                if (touch_range(c, x, f, j, i0, i1, &tl, &th, &corner) && corner)
                    return con_fail(err, fail, TS_ERR_CONDITION, k, j, TS_WHERE_POINT,
                                    TS_CONDITION_TOUCH_CORNER);
            }
    }
    return TS_OK;
}

/* docs/method.md §13.1, curvature-slope: a knot whose slope rule and a
 * curvature record's secant exclude each other.  Checked after the slopes
 * (§13.2), whose slope-conflict proof keeps its precedence. */
static ts_status knot_checks(const double *x, const double *f, size_t n, const ts_constraint *cs,
                             size_t nc, ts_error *err, ts_constraint_failure *fail)
{
    for (size_t j = 0; j <= n; j++) {
        slope_of lo, hi, r;
        int hl = 0, hh = 0;
        for (size_t k = 0; k < nc; k++) {
            if (rule_at(cs, k, x, f, n, j, 0, &r) && (!hl || slope_cmp(&r, &lo) > 0))
                lo = r, hl = 1;
            if (rule_at(cs, k, x, f, n, j, 1, &r) && (!hh || slope_cmp(&r, &hi) < 0))
                hi = r, hh = 1;
        }
        /* two records' slope rules at one knot exclude each other */
        if (hl && hh && slope_cmp(&lo, &hi) > 0)
            return con_fail(err, fail, TS_ERR_INFEASIBLE, TS_NO_INDEX, j, TS_WHERE_POINT,
                            TS_CONDITION_SLOPE_CONFLICT);
        size_t q, rk, iv;
        const slope_of *rule;
        if (curv_scan(cs, nc, x, f, n, j, hl ? &lo : NULL, hh ? &hi : NULL, &q, &rk, &iv, &rule))
            return con_fail(err, fail, TS_ERR_CONDITION, rk, j, TS_WHERE_POINT,
                            TS_CONDITION_CURVATURE_SLOPE);
    }
    return TS_OK;
}

static double secant(const double *x, const double *f, size_t i)
{
    return (f[i + 1] - f[i]) / (x[i + 1] - x[i]);
}

/* Must interval i be a straight line (both slopes its secant)?  Convex:
 * unless d_i < Δ_i < d_{i+1}; a slope bound the secant reaches. */
static int must_be_line(const ts_constraint *cs, size_t nc, size_t n, const double *d, size_t i,
                        double D)
{
    for (size_t k = 0; k < nc; k++) {
        const ts_constraint *c = &cs[k];
        if (!in_scope(c, i, n))
            continue;
        double sg = curv_sign(c), lo, hi;
        if (sg != 0.0 && !(sg * d[i] < sg * D && sg * D < sg * d[i + 1]))
            return 1;
        if (slope_range(c, &lo, &hi) && (D <= lo || D >= hi))
            return 1;
    }
    return 0;
}

/* docs/method.md §13.2: slopes.  d holds the estimates; by[j] the record that
 * changed d_j last (−1: none). */
static ts_status con_slopes(const double *x, const double *f, size_t n, const ts_constraint *cs,
                            size_t nc, double *d, int *by, ts_error *err,
                            ts_constraint_failure *fail)
{
    for (size_t j = 0; j <= n; j++)
        by[j] = -1;
    /* convex / concave: the three-point slope (one-sided at the scope's ends) */
    for (size_t k = 0; k < nc; k++) {
        const ts_constraint *c = &cs[k];
        if (curv_sign(c) == 0.0)
            continue;
        size_t i0 = c->first, i1 = scope_end(c, n);
        double sg = curv_sign(c);
        for (size_t j = i0; j <= i1; j++) {
            /* the estimate stays where it is admissible: strictly between the
             * neighbouring secants in scope (at a scope end: on the right
             * side of its one secant) */
            double dl = j > i0 ? sg * secant(x, f, j - 1) : -HUGE_VAL;
            double dr = j < i1 ? sg * secant(x, f, j) : HUGE_VAL;
            if ((dl < sg * d[j] && sg * d[j] < dr) || (dl == dr && sg * d[j] == dl))
                continue;
            double v;
            if (j > i0 && j < i1) {
                double hl = x[j] - x[j - 1], hr = x[j + 1] - x[j];
                double w = hr / (hl + hr);
                v = w * secant(x, f, j - 1) + (1.0 - w) * secant(x, f, j);
            } else if (i1 - i0 == 1) {
                v = secant(x, f, i0);
            } else if (j == i0) {
                double h0 = x[j + 1] - x[j], h1 = x[j + 2] - x[j + 1], D0 = secant(x, f, j);
                v = D0 + (D0 - secant(x, f, j + 1)) * (h0 / (h0 + h1));
            } else {
                double h0 = x[j] - x[j - 1], h1 = x[j - 1] - x[j - 2], D0 = secant(x, f, j - 1);
                v = D0 + (D0 - secant(x, f, j - 2)) * (h0 / (h0 + h1));
            }
            if (v != d[j])
                d[j] = v, by[j] = (int)k;
        }
    }
    /* slope bounds and monotone: clamp */
    for (size_t k = 0; k < nc; k++) {
        double lo, hi;
        if (!slope_range(&cs[k], &lo, &hi))
            continue;
        size_t i0 = cs[k].first, i1 = scope_end(&cs[k], n);
        for (size_t j = i0; j <= i1; j++) {
            double v = d[j] < lo ? lo : d[j] > hi ? hi : d[j];
            if (v != d[j])
                d[j] = v, by[j] = (int)k;
        }
    }
    /* a constant bound the data touch: the slope there 0 (pointing into the
     * region at the first and last knot of the scope), docs/method.md §5.1, §13.2 */
    for (size_t k = 0; k < nc; k++) {
        const ts_constraint *c = &cs[k];
        double bs = bound_sign(c);
        if (bs == 0.0 || c->bound != TS_BOUND_CONSTANT)
            continue;
        size_t i0 = c->first, i1 = scope_end(c, n);
        for (size_t j = i0; j <= i1; j++) {
            if (f[j] != c->value)
                continue;
            double v = (j > i0 && j < i1) ? 0.0
                       : j == i0 ? (bs * d[j] < 0.0 ? 0.0 : d[j])
                                 : (bs * d[j] > 0.0 ? 0.0 : d[j]);
            if (v != d[j])
                d[j] = v, by[j] = (int)k;
        }
    }
    /* a polyline the data touch: the slope there inside the range the pieces
     * on both sides allow (docs/method.md §13.6) */
    for (size_t k = 0; k < nc; k++) {
        size_t i0 = cs[k].first, i1 = scope_end(&cs[k], n);
        for (size_t j = i0; j <= i1; j++) {
            double lo, hi;
            int corner;
            if (!touch_range(&cs[k], x, f, j, i0, i1, &lo, &hi, &corner))
                continue;
            double v = d[j] < lo ? lo : d[j] > hi ? hi : d[j];
            if (v != d[j])
                d[j] = v, by[j] = (int)k;
        }
    }
    /* intervals that must be lines; a knot between two such with different
     * secants has no admissible slope (S' continuous).  The passes end: an
     * interval set to its line here stays a line that must be one (its
     * test holds with d = D; a neighbour would change its end only where
     * the conflict below returns first), and each pass that changes a
     * slope adds one, so at most n passes change something. */
    for (;;) {
        int changed = 0;
        for (size_t i = 0; i < n; i++) {
            double D = secant(x, f, i);
            if (!must_be_line(cs, nc, n, d, i, D) || (d[i] == D && d[i + 1] == D))
                continue;
            for (int e = 0; e < 2; e++) {
                size_t j = i + (size_t)e, nb = e ? i + 1 : i - 1; /* the other interval at j */
                int other = e ? i + 1 < n : i > 0;
                if (other && d[j] != D) {
                    double Dn = secant(x, f, nb);
                    if (Dn != D && must_be_line(cs, nc, n, d, nb, Dn) &&
                        (e ? d[j + 1] == Dn : d[j - 1] == Dn))
                        return con_fail(err, fail, TS_ERR_INFEASIBLE, TS_NO_INDEX, j,
                                        TS_WHERE_POINT, TS_CONDITION_SLOPE_CONFLICT);
                }
                if (d[j] != D)
                    d[j] = D, changed = 1;
            }
        }
        if (!changed)
            return TS_OK;
    }
}

/* docs/method.md §13.3: the smallest a the record needs on interval i
 * (closed form, a proof through the control polygon; 0 when none;
 * +Inf when no a does it with these slopes). */
static double a_needed(const ts_constraint *c, double h, double fi, double fj, double xi, double di,
                       double dj)
{
    const double K3 = 2.0 / (3.0 * TS_PI);
    double D = (fj - fi) / h, sg = curv_sign(c), lo, hi, a = 0.0;
    if (sg != 0.0) {
        double w = sg * (dj - di), m = fmin(sg * (D - di), sg * (dj - D));
        if (w <= 0.0)
            return 0.0;
        return m > 0.0 ? K3 * w / m : HUGE_VAL;
    }
    if (slope_range(c, &lo, &hi)) {
        for (int side = 0; side < 2; side++) {
            double L = side ? hi : lo, s = side ? -1.0 : 1.0;
            if (isinf(L))
                continue;
            double e = s * (di - L) + s * (dj - L), E = s * (D - L);
            if (e <= 0.0)
                continue;
            a = fmax(a, E > 0.0 ? K3 * e / E : HUGE_VAL);
        }
        return a;
    }
    double bs = bound_sign(c); /* lower or upper: every other kind returned above */
    double cv = c->value, blo, bhi;
    if (c->bound == TS_BOUND_SPLINE) {
        /* the constant rule against B's range over the interval (§13.7) */
        if (!ts__bcurve_range(c->spline, xi, xi + h, &blo, &bhi))
            return 0.0;
        cv = bs > 0.0 ? bhi : blo;
    }
    if (c->bound != TS_BOUND_POLYLINE) {
        double g0 = bs * (fi - cv), g1 = bs * (fj - cv);
        if (bs * di < 0.0 && g0 > 0.0)
            a = fmax(a, -K3 * h * bs * di / g0);
        if (bs * dj > 0.0 && g1 > 0.0)
            a = fmax(a, K3 * h * bs * dj / g1);
        return a;
    }
    /* polyline: every piece over the interval, its line extended over it */
    for (size_t p = 0; p + 1 < c->n_poly; p++) {
        if (c->px[p + 1] <= xi || c->px[p] >= xi + h)
            continue;
        double m = piece_slope(c, p);
        double g0 = bs * (fi - (c->py[p] + m * (xi - c->px[p])));
        double g1 = bs * (fj - (c->py[p] + m * (xi + h - c->px[p])));
        if (!(g0 >= 0.0 && g1 >= 0.0))
            continue; /* the search (§13.4) */
        /* a knot on the line (g = 0, §13.6): its slope rule, no a needed */
        if (bs * (di - m) < 0.0 && g0 > 0.0)
            a = fmax(a, -K3 * h * bs * (di - m) / g0);
        if (bs * (dj - m) > 0.0 && g1 > 0.0)
            a = fmax(a, K3 * h * bs * (dj - m) / g1);
    }
    return a;
}

/* docs/method.md §13.3: beta_i = t_i + max(0, a_need − alpha_i), a_i at
 * least 4/(3π) + t_i (§4); bind[i] the record with the largest need. */
void ts__con_betas(const double *x, const double *f, size_t n, const ts_spline_options *o,
                   const double *d, double *beta, int *bind)
{
    for (size_t i = 0; i < n; i++) {
        double al = o->alphas ? o->alphas[i] : o->alpha;
        double t = o->margins ? o->margins[i] : o->margin;
        double need = TS_GEOMETRIC_A_RAISE, h = x[i + 1] - x[i];
        bind[i] = -1;
        for (size_t k = 0; k < o->n_constraints; k++) {
            const ts_constraint *c = &o->constraints[k];
            if (!in_scope(c, i, n))
                continue;
            double a = a_needed(c, h, f[i], f[i + 1], x[i], d[i], d[i + 1]);
            if (a > need && a > al)
                need = a, bind[i] = (int)k;
        }
        if (!(need < 1e300))
            need = 1e300;
        beta[i] = t + (need > al ? need - al : 0.0);
    }
}

ts_status ts__con_conditions(const double *x, const double *f, size_t n,
                             const ts_spline_options *o, ts_constraint_failure *fail)
{
    ts_status st = ts__con_validate(o, n, NULL, fail);
    if (st == TS_OK)
        st = data_checks(x, f, n, o->constraints, o->n_constraints, NULL, fail);
    return st == TS_OK ? knot_checks(x, f, n, o->constraints, o->n_constraints, NULL, fail) : st;
}

ts_status ts__con_prepare(const double *x, const double *f, size_t n, const ts_spline_options *o,
                          double *d, int *by, ts_error *err, ts_constraint_failure *fail)
{
    ts_status st = data_checks(x, f, n, o->constraints, o->n_constraints, err, fail);
    if (st == TS_OK)
        st = con_slopes(x, f, n, o->constraints, o->n_constraints, d, by, err, fail);
    if (st == TS_OK)
        st = knot_checks(x, f, n, o->constraints, o->n_constraints, err, fail);
    return st;
}

/* ---- certificates (docs/method.md §13.4) -------------------------------- */

/* Local control polygon of interval i: Y = B, X̂ = (0, κ, 1 − κ, 1). */
typedef struct seg {
    double B[4], kap, h, xi;
    const ts_spline *sp;
    size_t i;
} seg;

static void seg_of(const ts_spline *sp, size_t i, seg *g)
{
    g->sp = sp;
    g->i = i;
    ts__B(sp, i, g->B);
    g->kap = sp->kappa[i];
    g->h = ts__h(sp, i);
    g->xi = sp->x[i];
}

/* sg · cross products D_a × D_b >= 0 for all a < b (convex polygon, X̂ in
 * units of h): exact. */
static int convex_polygon(const seg *g, double sg)
{
    double dB[3][2], dx[3][2];
    for (int l = 0; l < 3; l++)
        two_diff(g->B[l + 1], g->B[l], dB[l]);
    dx[0][0] = g->kap, dx[0][1] = 0.0;
    two_diff(1.0, 2.0 * g->kap, dx[1]);
    dx[2][0] = g->kap, dx[2][1] = 0.0;
    for (int a = 0; a < 3; a++)
        for (int b = a + 1; b < 3; b++) {
            double v[CON_EXACT];
            int k = 0;
            prod_terms(dx[a], 2, dB[b], 2, sg, v, &k);
            prod_terms(dB[a], 2, dx[b], 2, -sg, v, &k);
            if (ts__exact_sign(v, k) < 0)
                return 0;
        }
    return 1;
}

/* s (Z_{l+1} − Z_l) >= 0 for Z_l = B_l − L h X̂_l: S' >= L (s = 1) or
 * S' <= L (s = −1) through the polygon of Y − L X; exact. */
static int slope_polygon(const seg *g, double L, double s)
{
    double Lh[2], dx[3][2], sc = 1.0;
    /* |L h| beyond 2^1020: every term times 2^-k, |L h| 2^-k near 2^1010
     * (the inequalities are homogeneous); not proven if a B loses bits */
    if (fabs(L) > 0x1p1020 / g->h) {
        int k;
        (void)frexp(L * 0x1p-64 * g->h, &k);
        sc = ldexp(1.0, -(k + 64 - 1010));
        for (int l = 0; l < 4; l++)
            if ((sc * g->B[l]) / sc != g->B[l])
                return 0;
    }
    if (ts__exact_product(sc * L, g->h, 1.0, Lh) != 2) {
        if (!(fabs(L * g->h) < 0x1p-960))
            return 0;
        /* |L h| below 2^-960, where its product's error is not exact: then
         * |L h dX̂_l| < 2^-960 (0 <= dX̂_l <= 1), so the difference
         * B_{l+1} − B_l = d1 + d0 (two_diff, exact; |d0| <= ulp(d1)/2) with
         * s d1 >= 2^-958 decides each sign; a smaller one is not proven */
        for (int l = 0; l < 3; l++) {
            double d[2];
            two_diff(g->B[l + 1], g->B[l], d);
            if (!(s * d[1] >= 0x1p-958))
                return 0;
        }
        return 1;
    }
    dx[0][0] = g->kap, dx[0][1] = 0.0;
    two_diff(1.0, 2.0 * g->kap, dx[1]);
    dx[2][0] = g->kap, dx[2][1] = 0.0;
    for (int l = 0; l < 3; l++) {
        double v[CON_EXACT];
        int k = 0;
        v[k++] = s * (sc * g->B[l + 1]);
        v[k++] = -s * (sc * g->B[l]);
        prod_terms(Lh, 2, dx[l], 2, -s, v, &k);
        if (ts__exact_sign(v, k) < 0)
            return 0;
    }
    return 1;
}

/* bs (B_l − c) >= 0 for every l: S − c = Σ A_l (B_l − c) on the bound's
 * side over the whole interval (convex hull, (4.1); the data may touch it);
 * exact.  Not proven where h κ is not an exact product (|h κ| < 2^-960),
 * as when this test also took sloped lines (X̂_l h in its terms). */
static int const_polygon(const seg *g, double c, double bs)
{
    double hk[2];
    if (ts__exact_product(g->h, g->kap, 1.0, hk) != 2)
        return 0;
    for (int l = 0; l < 4; l++) {
        double v[2] = {bs * g->B[l], -bs * c};
        if (ts__exact_sign(v, 2) < 0)
            return 0;
    }
    return 1;
}

/* bs [(B_l − py_p)(px_{p+1} − px_p) − (py_{p+1} − py_p)(X_l − px_p)] >= 0 for
 * every l: the curve on the bound's side of piece p's line (through its
 * points, not a rounded slope) over the whole interval, touching allowed
 * (docs/method.md §13.6); exact. */
static int piece_polygon(const seg *g, const ts_constraint *c, size_t p, double bs)
{
    double off[2], hk[2], dx[2], dy[2];
    two_diff(g->xi, c->px[p], off);
    if (ts__exact_product(g->h, g->kap, 1.0, hk) != 2)
        return 0;
    two_diff(c->px[p + 1], c->px[p], dx);
    two_diff(c->py[p + 1], c->py[p], dy);
    /* X_l − px_p: X̂_1 h = hκ, X̂_2 h = h − hκ, X̂_3 h = h */
    double t0[2] = {off[0], off[1]}, t1[4] = {off[0], off[1], hk[0], hk[1]};
    double t2[5] = {off[0], off[1], g->h, -hk[0], -hk[1]}, t3[3] = {off[0], off[1], g->h};
    const double *tt[4] = {t0, t1, t2, t3};
    const int nt[4] = {2, 4, 5, 3};
    for (int l = 0; l < 4; l++) {
        double v[CON_EXACT], gb[2];
        int k = 0;
        two_diff(g->B[l], c->py[p], gb);
        prod_terms(gb, 2, dx, 2, bs, v, &k);
        prod_terms(dy, 2, tt[l], nt[l], -bs, v, &k);
        if (ts__exact_sign(v, k) < 0)
            return 0;
    }
    return 1;
}

/* ---- polynomials in t = tan(θ/2) (docs/method.md §13.5) ---------------- */

#define PMAX 25 /* degree <= 24 */
typedef struct poly {
    double c[PMAX];
    int deg;
} poly;

static void p_zero(poly *p, int deg)
{
    memset(p->c, 0, sizeof p->c);
    p->deg = deg;
}
static double p_eval(const poly *p, double t)
{
    double v = 0.0;
    for (int j = p->deg; j >= 0; j--)
        v = v * t + p->c[j];
    return v;
}
static void p_mul(const poly *a, const poly *b, poly *r)
{
    poly o;
    p_zero(&o, a->deg + b->deg);
    for (int i = 0; i <= a->deg; i++)
        for (int j = 0; j <= b->deg; j++)
            o.c[i + j] += a->c[i] * b->c[j];
    *r = o;
}
/* r += s a, a->deg <= r->deg: every sum below adds polynomials of one
 * degree (12, 23 or 6: p_combo and p_dtheta give degree 6) */
static void p_axpy(double s, const poly *a, poly *r)
{
    for (int j = 0; j <= a->deg; j++)
        r->c[j] += s * a->c[j];
}
static void p_deriv(const poly *a, poly *r)
{
    poly o;
    p_zero(&o, a->deg > 0 ? a->deg - 1 : 0);
    for (int j = 1; j <= a->deg; j++)
        o.c[j - 1] = j * a->c[j];
    *r = o;
}
/* q³ d/dθ (p/q³) = (q p' − 6 t p)/2, q = 1 + t² (dθ/dt = 2/q) */
static void p_dtheta(const poly *a, poly *r)
{
    poly dp, o;
    p_deriv(a, &dp);
    p_zero(&o, a->deg + 1);
    for (int j = 0; j <= dp.deg; j++) {
        o.c[j] += 0.5 * dp.c[j];
        o.c[j + 2] += 0.5 * dp.c[j];
    }
    for (int j = 0; j <= a->deg; j++)
        o.c[j + 1] -= 3.0 * a->c[j];
    /* a trigonometric polynomial of degree 3 times q³ has degree <= 6: the
     * leading terms cancel exactly (rounding residue dropped; a has
     * degree 6, p_combo's or this function's) */
    o.deg = 6;
    *r = o;
}

/* q³ A_l (docs/method.md §2, roots): power coefficients */
static const double PA[4][7] = {
    {1, -6, 15, -20, 15, -6, 1},   /* (1 − t)^6 */
    {0, 6, -16, 20, -16, 6, 0},    /* 2t(1 − t)²(3 − 2t + 3t²) */
    {0, 0, 4, 0, 4, 0, -8},        /* 4t²(1 − t²)(1 + 2t²) */
    {0, 0, 0, 0, 0, 0, 8}};        /* 8t^6 */

static void p_combo(const double w[4], poly *r)
{
    p_zero(r, 6);
    for (int l = 0; l < 4; l++)
        for (int j = 0; j < 7; j++)
            r->c[j] += w[l] * PA[l][j];
}

/* Real roots of p in (lo, hi) by Bernstein subdivision; appended to t[*nt]
 * while *nt < cap; subdivision depth and bisection steps TS_LIMIT(con_root_*)
 * (the 62 places beyond the ends exceed the degree, at most 23). */
static void to_bernstein(const poly *p, double lo, double hi, double *b)
{
    /* p(lo + (hi − lo) u) in powers of u, then Bernstein on [0, 1] */
    int n = p->deg;
    double a[PMAX], w = hi - lo;
    for (int j = 0; j <= n; j++)
        a[j] = p->c[j];
    for (int j = 0; j <= n; j++) /* Taylor shift by lo */
        for (int k = n - 1; k >= j; k--)
            a[k] += lo * a[k + 1];
    double sc = 1.0;
    for (int j = 0; j <= n; j++, sc *= w)
        a[j] *= sc;
    for (int j = 0; j <= n; j++) {
        double s = 0.0, cj = 1.0; /* C(j, i)/C(n, i) */
        for (int i = 0; i <= j; i++) {
            s += cj * a[i];
            cj = cj * (double)(j - i) / (double)(n - i);
        }
        b[j] = s;
    }
}
static int sign_changes(const double *b, int n)
{
    int v = 0, s = 0;
    for (int j = 0; j <= n; j++) {
        int sj = (b[j] > 0.0) - (b[j] < 0.0);
        if (sj && s && sj != s)
            v++;
        if (sj)
            s = sj;
    }
    return v;
}
static void roots_in(const poly *p, double lo, double hi, int depth, double *t, int *nt, int cap)
{
    double b[PMAX];
    to_bernstein(p, lo, hi, b);
    int v = sign_changes(b, p->deg);
    if (v == 0 || *nt >= cap)
        return;
    if (v == 1 || depth >= TS_LIMIT(con_root_depth)) {
        double a = lo, c = hi, fa = p_eval(p, a);
        if (v == 1 && fa * p_eval(p, c) < 0.0) {
            for (int it = 0; it < TS_LIMIT(con_root_steps) && c - a > 4 * DBL_EPSILON; it++) {
                double mid = 0.5 * (a + c), fm = p_eval(p, mid);
                if ((fm < 0.0) == (fa < 0.0))
                    a = mid, fa = fm;
                else
                    c = mid;
            }
        }
        t[(*nt)++] = 0.5 * (a + c);
        return;
    }
    double mid = 0.5 * (lo + hi);
    roots_in(p, lo, mid, depth + 1, t, nt, cap);
    roots_in(p, mid, hi, depth + 1, t, nt, cap);
}

/* Polynomials of interval g: PX, PY and their θ-derivatives (q³ times). */
typedef struct seg_poly {
    poly X, Y, X1, Y1, X2, Y2;
} seg_poly;
static void seg_poly_of(const seg *g, seg_poly *s)
{
    double wx[4] = {0.0, g->kap, 1.0 - g->kap, 1.0};
    double wy[4] = {0.0, g->B[1] - g->B[0], g->B[2] - g->B[0], g->B[3] - g->B[0]};
    p_combo(wx, &s->X);
    p_combo(wy, &s->Y);
    p_dtheta(&s->X, &s->X1);
    p_dtheta(&s->Y, &s->Y1);
    p_dtheta(&s->X1, &s->X2);
    p_dtheta(&s->Y1, &s->Y2);
}
static double x_at(const seg *g, double t)
{
    double A[4];
    ts__basis_t(t, A);
    return g->xi + g->h * (A[1] * g->kap + A[2] * (1.0 - g->kap) + A[3]);
}
static double y_at(const seg *g, double t)
{
    double A[4];
    ts__basis_t(t, A);
    return g->B[0] + (A[1] * (g->B[1] - g->B[0]) + A[2] * (g->B[2] - g->B[0]) +
                      A[3] * (g->B[3] - g->B[0]));
}
/* S' and S'' at t as evaluation gives them (ts__geo_eval at x = X(t),
 * docs/method.md §4), not from the polynomials, which lose the digits of
 * the ratios where X' = 3κ is small (a large a); at the knots the slope is
 * the polygon's end leg (B1 − B0)/(κh), (B3 − B2)/(κh). */
static void derivs_at(const seg *g, double t, double *d1, double *d2)
{
    double out[3];
    double x = t == 0.0 ? g->xi : t == 1.0 ? g->sp->x[g->i + 1] : x_at(g, t);
    ts__geo_eval(g->sp, g->i, x, 2, out);
    *d1 = out[1];
    *d2 = out[2];
    if (t == 0.0)
        *d1 = (g->B[1] - g->B[0]) / (g->kap * g->h);
    if (t == 1.0)
        *d1 = (g->B[3] - g->B[2]) / (g->kap * g->h);
}
static double d1_at(const seg_poly *s, const seg *g, double t)
{
    (void)s;
    double a, b;
    derivs_at(g, t, &a, &b);
    return a;
}
static double d2_at(const seg_poly *s, const seg *g, double t)
{
    (void)s;
    double a, b;
    derivs_at(g, t, &a, &b);
    return b;
}

/* t in [0, 1] with x_at = x (X increasing), by bisection. */
static double t_of_x(const seg *g, double x)
{
    double lo = 0.0, hi = 1.0;
    for (int it = 0; it < 70; it++) {
        double mid = 0.5 * (lo + hi);
        if (x_at(g, mid) < x)
            lo = mid;
        else
            hi = mid;
    }
    return 0.5 * (lo + hi);
}

/* min over t in [lo, hi] of F (which: 0 S'' sg, 1 sg(S' − L), 2 bs (S − line))
 * from the ends and the roots of its derivative's numerator. */
typedef struct target {
    int which;
    double sg, L, m, x0, y0;
} target;
static double f_at(const target *tg, const seg_poly *s, const seg *g, double t)
{
    switch (tg->which) {
    case 0: return tg->sg * d2_at(s, g, t);
    case 1: return tg->sg * (d1_at(s, g, t) - tg->L);
    default: return tg->sg * (y_at(g, t) - (tg->y0 + tg->m * (x_at(g, t) - tg->x0)));
    }
}
static double min_on(const target *tg, const seg_poly *s, const seg *g, double lo, double hi,
                     double *tmin)
{
    poly D;
    if (tg->which == 0) {
        /* d/dt [q³ N / X1³] ∝ (q³N)' X1 − 3 q³ N X1' */
        poly N, tmp, q3, q3N, dq3N, dX1, a, b;
        p_mul(&s->Y2, &s->X1, &N);
        p_mul(&s->Y1, &s->X2, &tmp);
        p_axpy(-1.0, &tmp, &N);
        p_zero(&q3, 6);
        q3.c[0] = 1, q3.c[2] = 3, q3.c[4] = 3, q3.c[6] = 1;
        p_mul(&q3, &N, &q3N);
        p_deriv(&q3N, &dq3N);
        p_deriv(&s->X1, &dX1);
        p_mul(&dq3N, &s->X1, &a);
        p_mul(&q3N, &dX1, &b);
        p_axpy(-3.0, &b, &a);
        D = a;
    } else if (tg->which == 1) {
        poly tmp;
        p_mul(&s->Y2, &s->X1, &D);
        p_mul(&s->Y1, &s->X2, &tmp);
        p_axpy(-1.0, &tmp, &D);
    } else {
        D = s->Y1;
        p_axpy(-tg->m * g->h, &s->X1, &D);
    }
    double ts[TS_LIMIT_DEFAULT_con_root_cap];
    int nt = 0;
    ts[nt++] = lo;
    ts[nt++] = hi;
    roots_in(&D, lo, hi, 0, ts, &nt, TS_LIMIT(con_root_cap));
    double best = f_at(tg, s, g, ts[0]);
    *tmin = ts[0];
    for (int j = 1; j < nt; j++) {
        double v = f_at(tg, s, g, ts[j]);
        if (v < best)
            best = v, *tmin = ts[j];
    }
    return best;
}

/* Exact minimum (to rounding) of record c's gap on interval i and where;
 * *proven: the certificate (docs/method.md §13.4). */
static double con_gap(const ts_spline *sp, const ts_constraint *c, size_t i, double *at,
                      int *proven, int want)
{
    if (c->bound == TS_BOUND_SPLINE && bound_sign(c) != 0.0) { /* §13.7 */
        *proven = ts__bcurve_certify(sp, i, c->spline, bound_sign(c));
        *at = (double)NAN;
        return want ? ts__bcurve_gap(sp, i, c->spline, bound_sign(c), at) : (double)NAN;
    }
    seg g;
    seg_poly s;
    seg_of(sp, i, &g);
    seg_poly_of(&g, &s);
    target tg = {0, 1.0, 0.0, 0.0, 0.0, 0.0};
    double tmin = 0.0, best = HUGE_VAL, lo, hi, sg = curv_sign(c), bs = bound_sign(c);
    *proven = 0;
    if (sg != 0.0) {
        tg.which = 0, tg.sg = sg;
        *proven = convex_polygon(&g, sg);
        best = want ? min_on(&tg, &s, &g, 0.0, 1.0, &tmin) : best;
    } else if (slope_range(c, &lo, &hi)) {
        int ok = 1;
        for (int side = 0; side < 2; side++) {
            double L = side ? hi : lo, sl = side ? -1.0 : 1.0, tm = 0.0;
            if (isinf(L))
                continue;
            ok &= slope_polygon(&g, L, sl);
            tg.which = 1, tg.sg = sl, tg.L = L;
            double v = want ? min_on(&tg, &s, &g, 0.0, 1.0, &tm) : best;
            if (v < best)
                best = v, tmin = tm;
        }
        *proven = ok;
    } else if (c->bound == TS_BOUND_CONSTANT) {
        tg.which = 2, tg.sg = bs, tg.m = 0.0, tg.x0 = g.xi, tg.y0 = c->value;
        *proven = const_polygon(&g, c->value, bs);
        best = want ? min_on(&tg, &s, &g, 0.0, 1.0, &tmin) : best;
    } else {
        /* covers() holds (the callers ask for no other interval): a piece
         * meets (x_i, x_{i+1}), since the pieces tile [px_0, px_m] */
        int ok = 1;
        double x1 = sp->x[i + 1];
        for (size_t p = 0; p + 1 < c->n_poly; p++) {
            double a = fmax(c->px[p], g.xi), b = fmin(c->px[p + 1], x1), tm = 0.0;
            if (!(a < b))
                continue;
            double m = piece_slope(c, p);
            tg.which = 2, tg.sg = bs, tg.m = m, tg.x0 = c->px[p], tg.y0 = c->py[p];
            double ta = a <= g.xi ? 0.0 : t_of_x(&g, a), tb = b >= x1 ? 1.0 : t_of_x(&g, b);
            double v = want ? min_on(&tg, &s, &g, ta, tb, &tm) : best;
            if (v < best)
                best = v, tmin = tm;
            if (!piece_polygon(&g, c, p, bs)) {
                /* the minimum over the piece, widened by 2^-40 in t, above a guard */
                double wa = fmax(0.0, ta - 0x1p-40), wb = fmin(1.0, tb + 0x1p-40), tw;
                double vw = min_on(&tg, &s, &g, wa, wb, &tw);
                double ly = fabs(c->py[p] + m * (g.xi - c->px[p]));
                double bmax = fmax(fmax(fabs(g.B[0]), fabs(g.B[1])), fmax(fabs(g.B[2]), fabs(g.B[3])));
                double guard = 64.0 * DBL_EPSILON * (bmax + ly + fabs(m) * g.h) + 0x1p-1060;
                ok &= vw > guard;
            }
        }
        *proven = ok;
    }
    *at = x_at(&g, tmin);
    return best;
}

/* Is the record binding-free on interval i (no piece of a polyline over it)? */
static int covers(const ts_constraint *c, const ts_spline *sp, size_t i)
{
    if (!in_scope(c, i, sp->n))
        return 0;
    if ((c->kind == TS_CONSTRAINT_LOWER || c->kind == TS_CONSTRAINT_UPPER) &&
        c->bound == TS_BOUND_POLYLINE)
        return c->px[0] < sp->x[i + 1] && c->px[c->n_poly - 1] > sp->x[i];
    if ((c->kind == TS_CONSTRAINT_LOWER || c->kind == TS_CONSTRAINT_UPPER) &&
        c->bound == TS_BOUND_SPLINE)
        return c->spline->x[0] < sp->x[i + 1] && c->spline->x[c->spline->n] > sp->x[i];
    return 1;
}

#define CON_C1_TOL 0x1p-20 /* docs/method.md §13.4 */
/* the largest a_k of a changed slope (beyond, the curve is a polyline to
 * rounding, §13.4); also the largest a whose rounding end_slope_ok accepts */
#define RESLOPE_A_MAX (0x1p14 * 4.0 / (3.0 * TS_PI))

/* docs/method.md §13.4: the slope of interval i's stored curve at one of
 * its ends, db/k (db = B1 − f_i or f_{i+1} − B2, fj the knot's value,
 * k = κ h), equals the knot's slope d within CON_C1_TOL of max(|d|,
 * |secant_i|), or within the rounding of a few ulps of fj at a0, the
 * closed-form a_i or RESLOPE_A_MAX, the smaller (2^-50 |fj| there, times
 * κ/κ0 = a0/a elsewhere: a constant in slope units, so raising a_i cannot
 * buy it);
 * compared times k, so nothing overflows.  db = 0 with d ≠ 0 fails
 * whatever the scale.  A large a_i leaves κ h d a few ulps of fj, or none:
 * the stored curve's tangent breaks at the knot. */
static int end_slope_ok(const ts_spline *sp, size_t i, double db, double d, double fj, double a0)
{
    double a = sp->alpha[i] + sp->beta[i], k = ts__geo_k(ts__h(sp, i), a);
    double m = fmax(k * fabs(d), sp->kappa[i] * fabs(sp->f[i + 1] - sp->f[i]));
    double tol = CON_C1_TOL * m + 0x1p-50 * fabs(fj) * (a0 / a);
    return (db != 0.0 || d == 0.0) && fabs(db - k * d) <= tol;
}

/* Every covering record's certificate on interval i, and the stored
 * curve's slope at an inner knot d_i (end_slope_ok; a0 the closed-form a_i,
 * at most RESLOPE_A_MAX): a tangent break there is seen by no record's
 * certificate, which holds for the stored values.  At the first and last
 * knot there is no other side: the end slope is the stored one.  *bad the
 * first failing (or covering) record. */
static int interval_ok(const ts_spline *sp, const ts_constraint *cs, size_t nc, size_t i,
                       double a0, size_t *bad)
{
    int any = 0;
    for (size_t k = 0; k < nc; k++) {
        if (!covers(&cs[k], sp, i))
            continue;
        double at;
        int proven;
        (void)con_gap(sp, &cs[k], i, &at, &proven, 0); /* the proof alone */
        if (!proven || !any)
            *bad = k, any = 1;
        if (!proven)
            return 0;
    }
    const double *f = sp->f;
    return !any ||
           ((i == 0 || end_slope_ok(sp, i, sp->b1[i] - f[i], sp->d[i], f[i], a0)) &&
            (i + 1 == sp->n || end_slope_ok(sp, i, f[i + 1] - sp->b2[i], sp->d[i + 1], f[i + 1], a0)));
}

static int nudge(ts_spline *sp, const ts_constraint *cs, size_t nc, size_t i, double a0,
                 size_t *bad)
{
    double b1 = sp->b1[i], b2 = sp->b2[i];
    for (int u = -2; u <= 2; u++)
        for (int v = -2; v <= 2; v++) {
            double c1 = b1, c2 = b2;
            for (int k = 0; k < (u < 0 ? -u : u); k++)
                c1 = nextafter(c1, u < 0 ? -HUGE_VAL : HUGE_VAL);
            for (int k = 0; k < (v < 0 ? -v : v); k++)
                c2 = nextafter(c2, v < 0 ? -HUGE_VAL : HUGE_VAL);
            sp->b1[i] = c1;
            sp->b2[i] = c2;
            if (interval_ok(sp, cs, nc, i, a0, bad))
                return 1;
        }
    sp->b1[i] = b1;
    sp->b2[i] = b2;
    return 0;
}

/* docs/method.md §13.4: certify interval i; double a_i where a certificate
 * fails (every closed-form condition of §13.3 survives a larger a); 0 after
 * CON_DOUBLINGS doublings and the downward values, *bad the record.  a_ref
 * the closed-form a_i (end_slope_ok accepts the rounding there, or at
 * RESLOPE_A_MAX if that is smaller). */
static int certify_interval(ts_spline *sp, const ts_constraint *cs, size_t nc, size_t i,
                            double a_ref, size_t *bad)
{
    int tries = 0;
    double a0 = sp->alpha[i] + sp->beta[i], lo = TS_GEOMETRIC_A_RAISE;
    double ar = fmin(a_ref, RESLOPE_A_MAX);
    while (!interval_ok(sp, cs, nc, i, ar, bad)) {
        /* first the inner control values moved by up to 2 ulps: a slope
         * set exactly to a bound, or a forced line, is met in exact
         * arithmetic only if B1, B2 round the right way (docs/method.md
         * §13.4); evaluation reads the stored values */
        if (tries == 0 && nudge(sp, cs, nc, i, ar, bad))
            return 1;
        /* a0 doubled CON_DOUBLINGS times, then (a polyline piece's gap
         * is not monotone in a) 16 values from 4/(3π) up to a0 */
        double a;
        if (tries < CON_DOUBLINGS && 2.0 * (sp->alpha[i] + sp->beta[i]) < 1e300)
            a = 2.0 * (sp->alpha[i] + sp->beta[i]);
        else if (tries < CON_DOUBLINGS + 16 && a0 > lo)
            a = lo * pow(a0 / lo, (tries - CON_DOUBLINGS) / 16.0) * (1.0 + 0x1p-40);
        else
            return 0;
        if (tries < CON_DOUBLINGS && !(2.0 * (sp->alpha[i] + sp->beta[i]) < 1e300))
            tries = CON_DOUBLINGS;
        tries++;
        sp->beta[i] = a > sp->alpha[i] ? a - sp->alpha[i] : 0.0;
        sp->term[i] = (unsigned char)TS_TERM_CERTIFY;
        ts__controls_geo(sp, i, i + 1);
    }
    return 1;
}

/* Is interval k's a_k, raised first to the closed-form need of the records
 * with the current slopes (§13.3), at most RESLOPE_A_MAX after the search? */
static int resloped_ok(ts_spline *sp, const ts_constraint *cs, size_t nc, size_t k)
{
    double need = 0.0;
    for (size_t r = 0; r < nc; r++)
        if (in_scope(&cs[r], k, sp->n))
            need = fmax(need, a_needed(&cs[r], ts__h(sp, k), sp->f[k], sp->f[k + 1], sp->x[k],
                                       sp->d[k], sp->d[k + 1]));
    if (!(need <= RESLOPE_A_MAX))
        return 0;
    if (need > sp->alpha[k] + sp->beta[k]) {
        sp->beta[k] = need - sp->alpha[k];
        ts__controls_geo(sp, k, k + 1);
    }
    size_t bad;
    return certify_interval(sp, cs, nc, k, fmax(need, sp->alpha[k]), &bad) &&
           sp->alpha[k] + sp->beta[k] <= RESLOPE_A_MAX;
}

/* docs/method.md §13.4: interval i has no certified a_i with its slopes;
 * try the slopes of its knots scaled (both, then each alone) by the factors
 * below (those of the brute-force comparison in the tests), each with a
 * fresh search on the intervals they touch (i − 1, i, i + 1), each a_k
 * kept at most RESLOPE_A_MAX (beyond, evaluation loses S'' to
 * rounding near the knots).  Sound whatever the slopes: only certificates
 * accept.  1 when one is certified, else everything as it was. */
static int reslope(ts_spline *sp, const ts_constraint *cs, size_t nc, size_t i)
{
    static const double scale[] = {0.5, 0.25, 0.0, 1.5};
    size_t i0 = i > 0 ? i - 1 : i, i1 = i + 2 <= sp->n ? i + 2 : sp->n; /* intervals [i0, i1) */
    double d0[2] = {sp->d[i], sp->d[i + 1]}, be[3], b1[3], b2[3], ka[3];
    unsigned char te[3];
    for (size_t k = i0; k < i1; k++)
        be[k - i0] = sp->beta[k], b1[k - i0] = sp->b1[k], b2[k - i0] = sp->b2[k],
        ka[k - i0] = sp->kappa[k], te[k - i0] = sp->term[k];
    for (int which = 0; which < 3; which++)       /* both knots, the left, the right */
        for (int m = 0; m < 4; m++) {
            if (which != 2)
                sp->d[i] = scale[m] * d0[0];
            if (which != 1)
                sp->d[i + 1] = scale[m] * d0[1];
            ts__controls_geo(sp, i0, i1);
            if ((i0 == i || resloped_ok(sp, cs, nc, i0)) && resloped_ok(sp, cs, nc, i) &&
                (i + 1 == i1 || resloped_ok(sp, cs, nc, i + 1)))
                return 1;
            sp->d[i] = d0[0], sp->d[i + 1] = d0[1];
            for (size_t k = i0; k < i1; k++)
                sp->beta[k] = be[k - i0], sp->b1[k] = b1[k - i0], sp->b2[k] = b2[k - i0],
                sp->kappa[k] = ka[k - i0], sp->term[k] = te[k - i0];
        }
    return 0;
}

/* docs/method.md §13.4: certify every interval (certify_interval, then
 * reslope); TS_ERR_UNPROVEN when neither finds a certificate. */
ts_status ts__con_certify(ts_spline *sp, const ts_constraint *cs, size_t nc, ts_error *err,
                          ts_constraint_failure *fail)
{
    for (size_t i = 0; i < sp->n; i++) {
        size_t bad = 0;
        if (!certify_interval(sp, cs, nc, i, sp->alpha[i] + sp->beta[i], &bad) &&
            !reslope(sp, cs, nc, i))
            return con_fail(err, fail, TS_ERR_UNPROVEN, bad, i, TS_WHERE_INTERVAL,
                            TS_CONDITION_UNPROVEN);
    }
    sp->certified = 1;
    return TS_OK;
}

void ts__con_report(const ts_spline *sp, size_t k, size_t i, ts_constraint_report *rep)
{
    const ts_constraint *c = &sp->con[k];
    rep->in_scope = covers(c, sp, i);
    rep->active = 0;
    rep->gap = rep->at = (double)NAN;
    rep->certified = 0;
    if (!rep->in_scope)
        return;
    rep->active = sp->con_bind[i] == (int)k || sp->con_by[i] == (int)k ||
                  sp->con_by[i + 1] == (int)k;
    rep->gap = con_gap(sp, c, i, &rep->at, &rep->certified, 1);
}
