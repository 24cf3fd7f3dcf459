/* docs/method.md §5: shape schemes choose beta_i.
 *
 * Order of checks (each error names the first offender): margins
 * (TS_ERR_LENGTH, TS_ERR_MARGIN/interval), lines (TS_ERR_NONFINITE), data vs
 * scheme point by point (TS_ERR_NEGATIVE, TS_ERR_LINES before TS_ERR_SIDE at
 * the same point, TS_ERR_NONMONOTONE), slopes at zero knots
 * (TS_ERR_ZERO_SLOPE, user slopes only).
 *
 * Slope adjustments (docs/method.md §5.1, §5.5):
 *  - positive, f_i = 0: inner knot d_i = 0; d_0 >= 0, d_n <= 0 at the ends
 *    (periodic slopes: the ends are one inner knot, d_0 = d_n = 0).  Estimated
 *    slopes are set so; user slopes that break it are refused with
 *    TS_ERR_ZERO_SLOPE (the user asked for a curve that must cross zero).
 *  - monotone: slopes of the wrong sign are set to 0 (user slopes too, as
 *    docs/method.md §5.5 says), and both slopes of a flat interval (Δ_i = 0) are 0.
 * Data on a line are refused (TS_ERR_SIDE): unlike y = 0 for positive data,
 * touching a sloped line cannot be kept in the paper form.
 */
#include "internal.h"

#include <float.h>
#include <math.h>

/* beta is capped here; certify.c then checks (and repairs) the interval */
#define TS_BETA_CAP 1e300

static ts_status fail(ts_error *err, ts_status st, size_t index, ts_where where)
{
    ts__error_set(err, st, index, where);
    return st;
}

/* m x + c rounded once (docs/method.md §5.6: the line where the certificate
 * takes it; no rounding of m x on its own) */
static double line_at(const ts_line *l, double x)
{
    return fma(l->m, x, l->c);
}

/* sg times the terms of m x + c − Lh (Lh = line_at(l, x): its rounding
 * error) into v[0..3]: m x = p + e exactly (fma) where m x is 0 or far from
 * underflow, and every term within ts__exact_sign's range; else no terms
 * (undecided: taken as on the line). */
static int rounding_terms(const ts_line *l, double x, double Lh, double sg, double *v)
{
    if (!ts__exact_product(l->m, x, sg, v) || !(fabs(l->c) <= 0x1p1020 && fabs(Lh) <= 0x1p1020))
        return 0;
    v[2] = sg * l->c;
    v[3] = -sg * Lh;
    return 4;
}

/* Sign of v − (m x + c), exact (docs/method.md §5.8), Lh = line_at(l, x).
 * Rounding is monotone, so v > Lh gives v > m x + c and v < Lh gives
 * v < m x + c; at v = Lh the sign is that of Lh − (m x + c). */
static int side_of(double v, const ts_line *l, double x, double Lh)
{
    double t[4];
    if (v != Lh)
        return (v > Lh) - (v < Lh);
    return ts__exact_sign(t, rounding_terms(l, x, Lh, -1.0, t));
}

/* Sign of up(x) − lo(x), exact as side_of (Ll, Lu their line_at). */
static int order_of(const ts_line *lo, const ts_line *up, double x, double Ll, double Lu)
{
    double t[8];
    if (Ll != Lu)
        return (Lu > Ll) - (Lu < Ll);
    int n = rounding_terms(up, x, Lu, 1.0, t), k = rounding_terms(lo, x, Ll, -1.0, t + 4);
    return n && k ? ts__exact_sign(t, 8) : 0;
}

static int line_finite(const ts_line *l)
{
    return isfinite(l->m) && isfinite(l->c);
}

/* Direction of the data f[0..n]: sign of the first nonzero Δ_i (0: all flat). */
static int data_dir(const double *f, size_t n)
{
    int dir = 0;
    for (size_t i = 0; i < n && dir == 0; i++)
        dir = (f[i + 1] > f[i]) - (f[i + 1] < f[i]);
    return dir;
}

/* 1 if no f[p0..p1) is negative (or NaN); *zero: and whether one is 0.
 * Flags, so that it vectorises. */
TS_VECTOR_LOOP static int all_nonnegative(const double *restrict f, size_t p0, size_t p1, int *zero)
{
    int ok = 1, z = 0;
    for (size_t i = p0; i < p1; i++) {
        ok &= f[i] >= 0.0;
        z |= f[i] == 0.0;
    }
    *zero = z;
    return ok;
}

/* 1 if every point of [p0, p1) is strictly inside the lines (lc: lower m,
 * c, upper m, c; hl, hu which there are) by its rounded line values, and
 * the lines are strictly ordered there: then check_data's exact tests
 * (side_of, order_of) pass each without their rounding terms.  A flag, so
 * that it vectorises. */
TS_VECTOR_LOOP static int all_inside(const double *restrict x, const double *restrict f, size_t p0,
                                     size_t p1, const double *restrict lc, int hl, int hu)
{
    int ok = 1;
    for (size_t i = p0; i < p1; i++) {
        double Ll = fma(lc[0], x[i], lc[1]), Lu = fma(lc[2], x[i], lc[3]);
        ok &= ((1 - hl) | (f[i] > Ll)) & ((1 - hu) | (f[i] < Lu)) & ((1 - (hl & hu)) | (Lu > Ll));
    }
    return ok;
}

/* Check points [p0, p1) against the scheme; first offending point.  dir:
 * data_dir (monotone only). */
static ts_status check_data(const ts_spline *sp, ts_shape shape, int dir, size_t p0, size_t p1,
                            ts_error *err)
{
    const double *x = sp->x, *f = sp->f;
    int zero;
    if (shape == TS_SHAPE_POSITIVE) {
        if (all_nonnegative(f, p0, p1, &zero))
            return TS_OK;
        size_t i = p0;
        while (f[i] >= 0.0) /* one of f[p0..p1) is not */
            i++;
        return fail(err, TS_ERR_NEGATIVE, i, TS_WHERE_POINT);
    }
    if (shape == TS_SHAPE_MONOTONE) {
        for (size_t i = p0 > 1 ? p0 : 1; i < p1; i++) {
            double df = f[i] - f[i - 1];
            int s = (df > 0.0) - (df < 0.0);
            if (s != 0 && s != dir) /* dir is the first nonzero s */
                return fail(err, TS_ERR_NONMONOTONE, i, TS_WHERE_POINT);
        }
        return TS_OK;
    }
    const double lc[4] = {sp->lower.m, sp->lower.c, sp->upper.m, sp->upper.c};
    if (all_inside(x, f, p0, p1, lc, sp->has_lower != 0, sp->has_upper != 0))
        return TS_OK;
    for (size_t i = p0; i < p1; i++) {
        const ts_line *lo = &sp->lower, *up = &sp->upper;
        double Ll = sp->has_lower ? line_at(lo, x[i]) : 0.0;
        double Lu = sp->has_upper ? line_at(up, x[i]) : 0.0;
        if (sp->has_lower && sp->has_upper && order_of(lo, up, x[i], Ll, Lu) <= 0)
            return fail(err, TS_ERR_LINES, i, TS_WHERE_POINT);
        /* a constant line may be touched (docs/method.md §5.8), a sloped one not */
        int sl = sp->has_lower ? side_of(f[i], lo, x[i], Ll) : 1;
        int su = sp->has_upper ? side_of(f[i], up, x[i], Lu) : -1;
        if (sl < 0 || (sl == 0 && lo->m != 0.0) || su > 0 || (su == 0 && up->m != 0.0))
            return fail(err, TS_ERR_SIDE, i, TS_WHERE_POINT);
    }
    return TS_OK;
}

/* docs/method.md §5.1, §5.8: knots of points [p0, p1) where the data touch
 * the constant level v (f = v; up = +1 for a lower bound, the curve leaving
 * upwards; −1 for an upper): an inner knot needs d = 0, the first up·d >= 0,
 * the last up·d <= 0 (periodic: both ends one inner knot).  Estimated
 * slopes are set so, user slopes that break it refused. */
static ts_status touch_slopes(ts_spline *sp, const ts_spline_options *opt, size_t p0, size_t p1, double v,
                              double up, ts_error *err)
{
    size_t n = sp->n;
    int user = opt->slopes == TS_SLOPES_USER;
    int periodic = opt->slopes == TS_SLOPES_PERIODIC;
    double *d = sp->d;
    for (size_t i = p0; i < p1; i++) {
        if (sp->f[i] != v)
            continue;
        if (!ts__touch_leaves(d[i], (i > 0 && i < n) || periodic, i == 0, up))
            continue;
        if (user)
            return fail(err, TS_ERR_ZERO_SLOPE, i, TS_WHERE_POINT);
        d[i] = 0.0;
    }
    if (periodic && p1 > n && sp->f[0] == v)
        d[0] = d[n] = 0.0;
    return TS_OK;
}

/* docs/method.md §5.1: zero knots of non-negative data (all checked >= 0). */
static ts_status zero_slopes(ts_spline *sp, const ts_spline_options *opt, size_t p0, size_t p1,
                             ts_error *err)
{
    int zero;
    (void)all_nonnegative(sp->f, p0, p1, &zero);
    if (!zero)
        return TS_OK; /* no zero knot here (periodic, f[0] = 0: f[n] = 0 is one) */
    return touch_slopes(sp, opt, p0, p1, 0.0, 1.0, err);
}

/* docs/method.md §5.8: knots on a constant line of a line scheme. */
static ts_status line_touch_slopes(ts_spline *sp, const ts_spline_options *opt, size_t p0, size_t p1,
                                   ts_error *err)
{
    ts_status st = TS_OK;
    if (sp->has_lower && sp->lower.m == 0.0)
        st = touch_slopes(sp, opt, p0, p1, sp->lower.c, 1.0, err);
    if (st == TS_OK && sp->has_upper && sp->upper.m == 0.0)
        st = touch_slopes(sp, opt, p0, p1, sp->upper.c, -1.0, err);
    return st;
}

/* docs/method.md §5.5: wrong-sign slopes to 0, both slopes of a flat interval 0;
 * points [p0, p1), dir = data_dir. */
static void monotone_slopes(ts_spline *sp, int dir, size_t p0, size_t p1)
{
    size_t n = sp->n;
    double *d = sp->d;
    const double *f = sp->f;
    for (size_t i = p0; i < p1; i++) {
        if (dir * d[i] < 0.0 || dir == 0)
            d[i] = 0.0;
        if ((i > 0 && f[i] == f[i - 1]) || (i < n && f[i + 1] == f[i]))
            d[i] = 0.0;
    }
}

/* margins t_i of docs/method.md §5, intervals [i0, i1) */
static ts_status check_margins(const ts_spline_options *opt, size_t i0, size_t i1, ts_error *err)
{
    double t0 = opt->margin;
    if (!opt->margins && ts__margin_ok(t0))
        return TS_OK; /* one margin for all */
    for (size_t i = i0; i < i1; i++)
        if (!ts__margin_ok(opt->margins ? opt->margins[i] : opt->margin))
            return fail(err, TS_ERR_MARGIN, i, TS_WHERE_INTERVAL);
    return TS_OK;
}

/* The margin array's length. */
static ts_status check_options(const ts_spline *sp, const ts_spline_options *opt, ts_error *err)
{
    if (opt->margins && opt->n_margins != sp->n)
        return fail(err, TS_ERR_LENGTH, TS_NO_INDEX, TS_WHERE_NONE);
    return TS_OK;
}

/* Boundaries of the scheme into sp. */
static ts_status boundaries(ts_spline *sp, const ts_spline_options *opt, ts_error *err)
{
    ts_shape shape = opt->shape;
    sp->has_lower = shape == TS_SHAPE_POSITIVE || shape == TS_SHAPE_ABOVE ||
                    shape == TS_SHAPE_BETWEEN;
    sp->has_upper = shape == TS_SHAPE_BELOW || shape == TS_SHAPE_BETWEEN;
    sp->lower.m = sp->lower.c = 0.0;
    sp->upper.m = sp->upper.c = 0.0;
    if (shape == TS_SHAPE_ABOVE || shape == TS_SHAPE_BETWEEN) {
        if (!line_finite(&opt->lower))
            return fail(err, TS_ERR_NONFINITE, TS_NO_INDEX, TS_WHERE_NONE);
        sp->lower = opt->lower;
    }
    if (shape == TS_SHAPE_BELOW || shape == TS_SHAPE_BETWEEN) {
        if (!line_finite(&opt->upper))
            return fail(err, TS_ERR_NONFINITE, TS_NO_INDEX, TS_WHERE_NONE);
        sp->upper = opt->upper;
    }
    return TS_OK;
}

/* docs/method.md §5: beta_i = t_i + max{0, terms}; zero-gap knots drop their term.
 * Each term is considered in turn and taken when strictly larger: below, one
 * pass over a block per kind of term (lower line, upper line, monotone), then
 * t_i and the caps, each a plain loop that vectorises.  best[] is
 * beta[] before the last pass. */
/* The arrays of the passes (restrict parameters: through a struct GCC 12
 * does not see that they do not alias, and does not vectorise). */
#define TS_BETA_ARRAYS                                                         \
    const double *restrict x, const double *restrict f, const double *restrict d, \
        const double *restrict alpha, double *restrict best,                   \
        unsigned char *restrict term
#define TS_BETA_PASS(sp) (sp)->x, (sp)->f, (sp)->d, (sp)->alpha, (sp)->beta, (sp)->term

/* The divisor where the term is taken, else 1: a term is computed before
 * it is selected (so the loops vectorise), and 0/0 or x/0 there would raise
 * FE_INVALID or FE_DIVBYZERO on valid data (zero gaps, flat intervals). */
#define TS_SAFE(cond, v) ((cond) ? (v) : 1.0)
#define TS_CONSIDER(cond, val, code)                                           \
    do {                                                                       \
        double v_ = (val);                                                     \
        int take_ = (cond) && v_ > b;                                          \
        b = take_ ? v_ : b;                                                    \
        t = take_ ? (code) : t;                                                \
    } while (0)

/* docs/method.md §5 lower boundary m x + c: B1 - l > 0, B2 - l > 0; in the geometric
 * form (docs/method.md §4) the exact conditions Y_l - m X_l - c > 0 (ml = m, else 0). */
TS_VECTOR_LOOP static void consider_lower(TS_BETA_ARRAYS, size_t i0, size_t i1, double m, double c,
                                          double ml)
{
    for (size_t i = i0; i < i1; i++) {
        double g0 = f[i] - fma(m, x[i], c), g1 = f[i + 1] - fma(m, x[i + 1], c);
        double b = best[i];
        int t = term[i];
        ts__beta_line(alpha[i], ts__geo_K(x[i + 1] - x[i]), g0, g1, d[i] - ml, d[i + 1] - ml, 1.0,
                      TS_TERM_LOWER_LEFT, &b, &t);
        best[i] = b;
        term[i] = (unsigned char)t;
    }
}

/* docs/method.md §5 upper boundary, corrected signs (§5.3); mu as ml above. */
TS_VECTOR_LOOP static void consider_upper(TS_BETA_ARRAYS, size_t i0, size_t i1, double m, double c,
                                          double mu)
{
    for (size_t i = i0; i < i1; i++) {
        double G0 = fma(m, x[i], c) - f[i], G1 = fma(m, x[i + 1], c) - f[i + 1];
        double b = best[i];
        int t = term[i];
        ts__beta_line(alpha[i], ts__geo_K(x[i + 1] - x[i]), G0, G1, d[i] - mu, d[i + 1] - mu, -1.0,
                      TS_TERM_UPPER_LEFT, &b, &t);
        best[i] = b;
        term[i] = (unsigned char)t;
    }
}

/* docs/method.md §5.5: a_i >= 2(d_i + d_{i+1}) / (3π Δ_i) */
TS_VECTOR_LOOP static void consider_monotone(TS_BETA_ARRAYS, size_t i0, size_t i1)
{
    (void)x;
    for (size_t i = i0; i < i1; i++) {
        double al = alpha[i], K = ts__geo_K(x[i + 1] - x[i]), df = f[i + 1] - f[i];
        double b = best[i];
        int t = term[i];
        TS_CONSIDER(df != 0.0, K * (d[i] + d[i + 1]) / TS_SAFE(df != 0.0, df) - al, TS_TERM_MONOTONE);
        best[i] = b;
        term[i] = (unsigned char)t;
    }
}
#undef TS_CONSIDER
#undef TS_SAFE

/* beta_i = t_i + best_i, capped (a_i finite for alpha near DBL_MAX) */
TS_VECTOR_LOOP static void add_margins(const double *restrict alpha, double *restrict beta,
                                       size_t i0, size_t i1, const double *restrict margins,
                                       double margin)
{
#define TS_BETA(t)                                                             \
    do {                                                                       \
        double b = (t) + beta[i], al = alpha[i];                               \
        b = b <= TS_BETA_CAP ? b : TS_BETA_CAP;                                \
        beta[i] = al + b <= DBL_MAX ? b : DBL_MAX - al;                        \
    } while (0)
    if (margins) {
        for (size_t i = i0; i < i1; i++)
            TS_BETA(margins[i]);
    } else {
        for (size_t i = i0; i < i1; i++)
            TS_BETA(margin);
    }
#undef TS_BETA
}

/* Intervals [i0, i1) (margins already checked). */
static void betas(ts_spline *sp, const ts_spline_options *opt, size_t i0, size_t i1)
{
    int geo = sp->form == TS_FORM_GEOMETRIC;
    double *restrict best = sp->beta;
    unsigned char *restrict term = sp->term;
    for (size_t i = i0; i < i1; i++) {
        best[i] = 0.0;
        term[i] = (unsigned char)TS_TERM_MARGIN;
    }
    if (sp->has_lower)
        consider_lower(TS_BETA_PASS(sp), i0, i1, sp->lower.m, sp->lower.c, geo ? sp->lower.m : 0.0);
    if (sp->has_upper)
        consider_upper(TS_BETA_PASS(sp), i0, i1, sp->upper.m, sp->upper.c, geo ? sp->upper.m : 0.0);
    if (opt->shape == TS_SHAPE_MONOTONE)
        consider_monotone(TS_BETA_PASS(sp), i0, i1);
    add_margins(sp->alpha, sp->beta, i0, i1, opt->margins, opt->margin);
}

/* Slope adjustments of points [p0, p1) (their data already checked). */
static ts_status adjust(ts_spline *sp, const ts_spline_options *opt, int dir, size_t p0, size_t p1,
                        ts_error *err)
{
    if (opt->shape == TS_SHAPE_POSITIVE)
        return zero_slopes(sp, opt, p0, p1, err);
    if (opt->shape == TS_SHAPE_MONOTONE) {
        monotone_slopes(sp, dir, p0, p1);
        return TS_OK;
    }
    return line_touch_slopes(sp, opt, p0, p1, err);
}

ts_status ts__shape_begin(ts_spline *sp, const ts_spline_options *opt, const double *f, int *dir,
                          ts_error *err)
{
    *dir = 0;
    ts_status st = check_options(sp, opt, err);
    if (st == TS_OK)
        st = boundaries(sp, opt, err);
    if (st == TS_OK && opt->shape == TS_SHAPE_MONOTONE)
        *dir = data_dir(f, sp->n);
    return st;
}

ts_status ts__shape_range(ts_spline *sp, const ts_spline_options *opt, int dir, size_t p0, size_t p1,
                          size_t i0, size_t i1, ts_error *err)
{
    ts_status st = check_margins(opt, i0, i1, err);
    if (st == TS_OK)
        st = check_data(sp, opt->shape, dir, p0, p1, err);
    if (st == TS_OK)
        st = adjust(sp, opt, dir, p0, p1, err);
    if (st == TS_OK)
        betas(sp, opt, i0, i1);
    return st;
}
