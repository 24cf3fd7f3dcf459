/* ts_error_message: the full sentence of a failure from the ts_error and
 * the caller's data and options (include/trigspline.h, "Error messages").
 * Bookkeeping only; the numbers are printed by numfmt.c. */
#include "internal.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#define MAX_LISTED 12 /* other failing points named, then ", ..." */

/* An snprintf-like writer: `need` counts the whole sentence, buf holds what fits. */
typedef struct out {
    char *buf;
    size_t len, need;
} out;

#if defined(__GNUC__)
__attribute__((format(printf, 2, 3)))
#endif
static void put(out *o, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    size_t room = o->need < o->len ? o->len - o->need : 0;
    int w = vsnprintf(room ? o->buf + o->need : NULL, room, fmt, ap);
    va_end(ap);
    if (w > 0)
        o->need += (size_t)w;
}

static void num(out *o, double v)
{
    char b[TS__NUM_SIZE];
    ts__format_double(v, b);
    put(o, "%s", b);
}

static void xval(out *o, const ts_error_context *c, double v)
{
    if (c->format_x) { /* c: never NULL (ts_error_message's `none`) */
        char b[128];
        int w = c->format_x(v, b, sizeof b, c->format_x_user);
        if (w >= 0 && (size_t)w < sizeof b) {
            put(o, "%s", b);
            return;
        }
    }
    num(o, v);
}

/* "y = 2x + 1", "y = -x", "y = 3" */
static void line_text(out *o, const ts_line *l)
{
    put(o, "y = ");
    if (l->m != 0.0) {
        if (l->m == -1.0)
            put(o, "-");
        else if (l->m != 1.0)
            num(o, l->m);
        put(o, "x");
        if (l->c > 0.0) {
            put(o, " + ");
            num(o, l->c);
        } else if (l->c < 0.0) {
            put(o, " - ");
            num(o, -l->c);
        } else if (l->c != 0.0) { /* NaN */
            put(o, " + ");
            num(o, l->c);
        }
    } else {
        num(o, l->c);
    }
}

static double line_at(const ts_line *l, double x)
{
    return l->m * x + l->c;
}

static const char *where_name(ts_where w)
{
    const char *s = ts__vocab_name(TS_VOCAB_WHERE, (int)w);
    return s ? s : "index";
}

/* ---- splines ------------------------------------------------------ */

typedef struct data {
    const ts_error_context *c;
    const ts_spline_options *opt; /* the options used, or the defaults */
    size_t n;              /* points with x and f (0: none given) */
    size_t base;
} data;

static void point_x(out *o, const data *d, size_t i)
{
    put(o, "point %zu (x = ", d->base + i);
    xval(o, d->c, d->c->x[i]);
    put(o, ")");
}

static void point_xf(out *o, const data *d, size_t i)
{
    put(o, "point %zu (x = ", d->base + i);
    xval(o, d->c, d->c->x[i]);
    put(o, ", f = ");
    num(o, d->c->f[i]);
    put(o, ")");
}

static void interval_text(out *o, const data *d, size_t i)
{
    put(o, "interval %zu [", d->base + i);
    xval(o, d->c, d->c->x[i]);
    put(o, ", ");
    xval(o, d->c, d->c->x[i + 1]);
    put(o, "]");
}

/* Does point (x, f) fail the scheme's condition? (kind: 0 negative, 1 not
 * above the lower line, 2 not below the upper; a constant line may be touched) */
static int fails(const ts_spline_options *opt, int kind, double x, double f)
{
    if (kind == 0)
        return !(f >= 0.0);
    const ts_line *l = kind == 1 ? &opt->lower : &opt->upper;
    double g = kind == 1 ? f - line_at(l, x) : line_at(l, x) - f;
    return l->m == 0.0 ? !(g >= 0.0) : !(g > 0.0);
}

/* " (... at x = X1, X2, ..., ...)" tail: every failing point's x, 12 at most */
static void list_failing(out *o, const data *d, int kind)
{
    size_t cnt = 0;
    for (size_t i = 0; i < d->n; i++) {
        if (!fails(d->opt, kind, d->c->x[i], d->c->f[i]))
            continue;
        if (cnt == MAX_LISTED) {
            put(o, ", ...");
            return;
        }
        if (cnt)
            put(o, ", ");
        xval(o, d->c, d->c->x[i]);
        cnt++;
    }
}

static double per_interval(const double *arr, size_t n_arr, double scalar, size_t i)
{
    return arr && i < n_arr ? arr[i] : scalar;
}

/* The sentence of the failure record fl of the data checks (docs/method.md
 * §13.1): which record and which necessary condition; 0 when fl names
 * nothing these data and records have (another condition, an index or a
 * record outside them, a touched breakpoint that is not an inner one). */
static int failure_sentence(out *o, const data *d, const ts_constraint_failure *fl)
{
    const ts_spline_options *opt = d->opt;
    size_t i = fl->index, n = d->n;
    if (!(fl->constraint < opt->n_constraints && i < n) ||
        ts__con_validate(opt, n - 1, NULL, NULL) != TS_OK) /* then opt->constraints != NULL */
        return 0;
    const ts_constraint *c = &opt->constraints[fl->constraint];
    const char *kind = ts__vocab_name(TS_VOCAB_CONSTRAINT, (int)c->kind);
    switch (fl->condition) {
    case TS_CONDITION_CONVEX_DATA:
    case TS_CONDITION_CONCAVE_DATA:
        if (!(i > 0 && i + 1 < n))
            return 0;
        point_xf(o, d, i);
        put(o, ": the data are not %s here: the secant before it is ", kind);
        num(o, (d->c->f[i] - d->c->f[i - 1]) / (d->c->x[i] - d->c->x[i - 1]));
        put(o, ", the secant after it ");
        num(o, (d->c->f[i + 1] - d->c->f[i]) / (d->c->x[i + 1] - d->c->x[i]));
        break;
    case TS_CONDITION_MONOTONE_DATA:
        point_xf(o, d, i);
        put(o, ": the data change direction here; %s needs monotone data", kind);
        break;
    case TS_CONDITION_INSIDE_BOUND:
        point_xf(o, d, i);
        put(o, " is not %s the %s bound", c->kind == TS_CONSTRAINT_LOWER ? "above" : "below", kind);
        break;
    case TS_CONDITION_TOUCH_CORNER: {
        size_t p = 1;
        int bounded = c->kind == TS_CONSTRAINT_LOWER || c->kind == TS_CONSTRAINT_UPPER;
        if (!(bounded && c->bound == TS_BOUND_POLYLINE)) /* validated: px, py, n_poly >= 2 */
            return 0;
        while (p + 1 < c->n_poly && c->px[p] != d->c->x[i])
            p++;
        if (!(p + 1 < c->n_poly))
            return 0;
        point_xf(o, d, i);
        put(o, " lies on the %s bound at its breakpoint, where the polyline's slope goes from ",
            kind);
        num(o, (c->py[p] - c->py[p - 1]) / (c->px[p] - c->px[p - 1]));
        put(o, " to ");
        num(o, (c->py[p + 1] - c->py[p]) / (c->px[p + 1] - c->px[p]));
        put(o, ": no curve with a continuous slope stays %s it through this point",
            c->kind == TS_CONSTRAINT_LOWER ? "above" : "below");
        break;
    }
    case TS_CONDITION_CURVATURE_SLOPE: {
        size_t kc, iv;
        double sl;
        if (!ts__con_knot_conflict(d->c->x, d->c->f, n - 1, opt->constraints,
                                   opt->n_constraints, fl->constraint, i, &kc, &iv, &sl))
            return 0;
        const ts_constraint *cc = &opt->constraints[kc];
        int least = (cc->kind == TS_CONSTRAINT_CONVEX) == (iv + 1 == i);
        point_xf(o, d, i);
        put(o, ": constraint %zu (%s) needs a slope here of at %s the secant ", kc,
            ts__vocab_name(TS_VOCAB_CONSTRAINT, (int)cc->kind), least ? "least" : "most");
        num(o, (d->c->f[iv + 1] - d->c->f[iv]) / (d->c->x[iv + 1] - d->c->x[iv]));
        put(o, " of the interval %s it, but the %s constraint allows at %s ",
            iv + 1 == i ? "before" : "after", kind, least ? "most" : "least");
        num(o, sl);
        put(o, " there: no curve with a continuous slope meets both");
        break;
    }
    case TS_CONDITION_SECANT_SLOPE:
        if (!(i + 1 < n))
            return 0;
        interval_text(o, d, i);
        put(o, ": its secant ");
        num(o, (d->c->f[i + 1] - d->c->f[i]) / (d->c->x[i + 1] - d->c->x[i]));
        put(o, " is beyond the %s bound ", kind);
        num(o, c->value);
        put(o, " (the slope equals the secant somewhere in the interval)");
        break;
    default:
        return 0;
    }
    put(o, " (constraint %zu, %s)", fl->constraint, kind);
    return 1;
}

/* TS_ERR_CONDITION: the record and condition found again by the data
 * checks alone, when they name the same index as e. */
static int condition_sentence(out *o, const data *d, const ts_error *e)
{
    const ts_spline_options *opt = d->opt;
    /* d->n is 0 unless x and f are given */
    if (!opt->constraints || !opt->n_constraints || d->n < 2)
        return 0;
    ts_constraint_failure fl;
    memset(&fl, 0, sizeof fl);
    if (ts__con_conditions(d->c->x, d->c->f, d->n - 1, opt, &fl) != TS_ERR_CONDITION ||
        fl.index != e->index)
        return 0;
    return failure_sentence(o, d, &fl);
}

/* The sentence of a spline failure; 0 when the generic form applies. */
static int spline_sentence(out *o, const data *d, const ts_error *e)
{
    const ts_spline_options *opt = d->opt;
    size_t i = e->index, n = d->n;
    int point = e->where == TS_WHERE_POINT && i < n;
    int interval = e->where == TS_WHERE_INTERVAL && n > 0 && i < n - 1;
    const double *x = d->c->x, *f = d->c->f;
    switch (e->status) {
    case TS_ERR_TOO_FEW:
        if (!d->c->x && !d->c->n_points)
            return 0;
        put(o, "%zu data point%s; at least 2 are needed", d->c->n_points,
            d->c->n_points == 1 ? "" : "s");
        return 1;
    case TS_ERR_UNSORTED:
        if (!(point && i > 0))
            return 0;
        point_x(o, d, i);
        put(o, " is not greater than the previous x = ");
        xval(o, d->c, x[i - 1]);
        put(o, "; x must be strictly increasing");
        return 1;
    case TS_ERR_NONFINITE:
        if (!point)
            return 0;
        point_xf(o, d, i);
        if (!isfinite(x[i]) || !isfinite(f[i])) {
            put(o, ": x or f is NaN or infinite");
        } else if (opt->slopes == TS_SLOPES_USER && opt->user_slopes && i < opt->n_user_slopes &&
                   !isfinite(opt->user_slopes[i])) {
            put(o, ": the user slope ");
            num(o, opt->user_slopes[i]);
            put(o, " is not finite");
        } else {
            put(o, ": the step from the previous point, or a slope there, overflows a double");
        }
        return 1;
    case TS_ERR_WIDTH:
        if (!(point && i > 0))
            return 0;
        {
            double h = x[i] - x[i - 1];
            point_x(o, d, i);
            put(o, ": the step ");
            num(o, h);
            put(o, " from the previous x = ");
            xval(o, d->c, x[i - 1]);
            if (h <= DBL_MAX) {
                put(o, " underflows: steps below ");
                num(o, DBL_MIN);
                put(o, " (the smallest normal double) are refused");
            } else {
                put(o, " overflows a double");
            }
        }
        return 1;
    case TS_ERR_PERIODIC:
        if (n < 2)
            return 0;
        put(o, "periodic slopes need the last value equal to the first: f = ");
        num(o, f[n - 1]);
        put(o, " at point %zu, f = ", d->base + n - 1);
        num(o, f[0]);
        put(o, " at point %zu", d->base);
        return 1;
    case TS_ERR_NEGATIVE:
        if (!point)
            return 0;
        point_xf(o, d, i);
        put(o, " is negative; the positive shape needs f >= 0 (negative at x = ");
        list_failing(o, d, 0);
        put(o, ")");
        return 1;
    case TS_ERR_SIDE: {
        if (!point)
            return 0;
        int low = opt->shape == TS_SHAPE_ABOVE ||
                  (opt->shape == TS_SHAPE_BETWEEN && fails(opt, 1, x[i], f[i]));
        if (!low && opt->shape != TS_SHAPE_BELOW && opt->shape != TS_SHAPE_BETWEEN)
            return 0;
        point_xf(o, d, i);
        put(o, " is not %s the %s line ", low ? "above" : "below", low ? "lower" : "upper");
        line_text(o, low ? &opt->lower : &opt->upper);
        put(o, "; the data are on or %s it at x = ", low ? "below" : "above");
        list_failing(o, d, low ? 1 : 2);
        return 1;
    }
    case TS_ERR_LINES:
        if (!point)
            return 0;
        put(o, "at ");
        point_x(o, d, i);
        put(o, " the lower line ");
        line_text(o, &opt->lower);
        put(o, " (value ");
        num(o, line_at(&opt->lower, x[i]));
        put(o, ") is not below the upper line ");
        line_text(o, &opt->upper);
        put(o, " (value ");
        num(o, line_at(&opt->upper, x[i]));
        put(o, ")");
        return 1;
    case TS_ERR_NONMONOTONE:
        if (!point)
            return 0;
        point_xf(o, d, i);
        put(o, ": the data change direction here; the monotone shape needs monotone data");
        return 1;
    case TS_ERR_ZERO_SLOPE:
        if (!point)
            return 0;
        point_xf(o, d, i);
        put(o, " touches the boundary and the user slope ");
        if (opt->user_slopes && i < opt->n_user_slopes) {
            num(o, opt->user_slopes[i]);
            put(o, " ");
        }
        put(o, "there points out of the region");
        return 1;
    case TS_ERR_ALPHA:
    case TS_ERR_BETA:
    case TS_ERR_MARGIN: {
        double al = per_interval(opt->alphas, opt->n_alphas, opt->alpha, i);
        double be = per_interval(opt->betas, opt->n_betas, opt->beta, i);
        double t = per_interval(opt->margins, opt->n_margins, opt->margin, i);
        if (interval) {
            interval_text(o, d, i);
            put(o, ": ");
        } else if (e->index != TS_NO_INDEX) {
            put(o, "interval %zu: ", d->base + i);
        }
        if (e->status == TS_ERR_ALPHA) {
            put(o, "alpha = ");
            num(o, al);
            put(o, " must be finite and > 0");
        } else if (e->status == TS_ERR_BETA) {
            put(o, "beta = ");
            num(o, be);
            put(o, " must be finite and >= 0, and alpha + beta = ");
            num(o, al + be);
            put(o, " finite and > 0");
        } else {
            put(o, "the margin t = ");
            num(o, t);
            put(o, " must be finite and > 0");
        }
        return 1;
    }
    case TS_ERR_LENGTH: {
        if (n < 2)
            return 0;
        const char *what = NULL;
        size_t have = 0, want = n - 1;
        if (opt->slopes == TS_SLOPES_USER && opt->n_user_slopes != n) {
            what = "the user slopes";
            have = opt->n_user_slopes;
            want = n;
        } else if (opt->alphas && opt->n_alphas != n - 1) {
            what = "alphas";
            have = opt->n_alphas;
        } else if (opt->betas && opt->n_betas != n - 1) {
            what = "betas";
            have = opt->n_betas;
        } else if (opt->margins && opt->n_margins != n - 1) {
            what = "margins";
            have = opt->n_margins;
        }
        if (!what)
            return 0;
        if (want == n)
            put(o, "%s have %zu values, but the data have %zu points (one slope per point is "
                   "needed)", what, have, n);
        else
            put(o, "%s has %zu value%s, but the data have %zu interval%s (one value per "
                   "interval is needed)", what, have, have == 1 ? "" : "s", want,
                want == 1 ? "" : "s");
        return 1;
    }
    case TS_ERR_GEOMETRIC:
    case TS_ERR_CONTROL_OVERFLOW: {
        double a = per_interval(opt->alphas, opt->n_alphas, opt->alpha, i) +
                   per_interval(opt->betas, opt->n_betas, opt->beta, i);
        if (interval) {
            interval_text(o, d, i);
            put(o, ": ");
        }
        put(o, "alpha + beta = ");
        num(o, a);
        if (e->status == TS_ERR_GEOMETRIC) {
            put(o, " is below the geometric-form bound ");
            num(o, TS_GEOMETRIC_A_MIN);
            put(o, "; raise alpha or beta");
        } else {
            put(o, " is too small for the slopes: the control values overflow");
        }
        return 1;
    }
    case TS_ERR_CONDITION:
        return condition_sentence(o, d, e);
    case TS_ERR_UNPROVEN:
        if (!interval || !opt->n_constraints)
            return 0;
        interval_text(o, d, i);
        put(o, ": no alpha + beta up to 2^60 times the first certifies the constraints here "
               "(the search gave up; infeasibility is not proven)");
        return 1;
    case TS_ERR_INFEASIBLE:
        if (point && opt->n_constraints) {
            point_x(o, d, i);
            put(o, ": the constraints make both neighbouring intervals straight lines of "
                   "different slopes; no curve with a continuous slope meets them");
            return 1;
        }
        if (!interval)
            return 0;
        interval_text(o, d, i);
        put(o, ": no beta >= 0 keeps the spline inside the region on this interval");
        return 1;
    default:
        return 0;
    }
}

/* TS_ERR_DOMAIN for query i (the range from the data when given) */
static int query_sentence(out *o, const ts_error_context *c, const ts_error *e, size_t base)
{
    size_t i = e->index;
    if (e->status != TS_ERR_DOMAIN || !c->queries || !(i < c->n_queries))
        return 0;
    double q = c->queries[i];
    put(o, "query %zu", base + i);
    if (isnan(q)) {
        put(o, " is NaN");
        return 1;
    }
    put(o, " (x = ");
    xval(o, c, q);
    put(o, ")");
    if (isinf(q)) {
        put(o, " is infinite");
    } else if (c->x && c->n_points >= 2 && !c->y) {
        put(o, " lies outside [");
        xval(o, c, c->x[0]);
        put(o, ", ");
        xval(o, c, c->x[c->n_points - 1]);
        put(o, "]");
    } else {
        put(o, " lies outside the data");
    }
    return 1;
}

/* ---- surfaces and curves --------------------------------------------- */

static void surface_where(out *o, const ts_error_context *c, const ts_error *e)
{
    size_t nx = c->n_points, ny = c->ny_points;
    if (e->where == TS_WHERE_POINT && nx && e->index / nx < ny) {
        size_t i = e->index % nx, j = e->index / nx;
        put(o, "node (%zu, %zu)", c->first_index + i, c->first_index + j);
        if (c->x && c->y) {
            put(o, " (x = ");
            xval(o, c, c->x[i]);
            put(o, ", y = ");
            num(o, c->y[j]);
            if (c->f) {
                put(o, ", z = ");
                num(o, c->f[e->index]);
            }
            put(o, ")");
        }
    } else if (e->where == TS_WHERE_INTERVAL && nx > 1 && ny > 1 &&
               e->index / (nx - 1) < ny - 1) {
        size_t i = e->index % (nx - 1), j = e->index / (nx - 1);
        put(o, "patch (%zu, %zu)", c->first_index + i, c->first_index + j);
        if (c->x && c->y) {
            put(o, " [");
            xval(o, c, c->x[i]);
            put(o, ", ");
            xval(o, c, c->x[i + 1]);
            put(o, "] x [");
            num(o, c->y[j]);
            put(o, ", ");
            num(o, c->y[j + 1]);
            put(o, "]");
        }
    } else {
        put(o, "%s %zu", where_name(e->where), c->first_index + e->index);
    }
}

/* A caller's field as the library's view of it (docs/method.md §11.7);
 * 0 when it is malformed. */
static int field_view(const ts_grid_bound *g, ts__gbound *v)
{
    size_t at;
    double inf = (double)INFINITY;
    if (ts__gb_check(g, inf, -inf, inf, -inf, &at) != TS__GB_OK)
        return 0;
    v->nx = g->nx_points;
    v->ny = g->ny_points;
    v->x = g->x;
    v->y = g->y;
    v->z = g->z;
    double m = 0.0;
    for (size_t n = 0; n < v->nx * v->ny; n++)
        m = fabs(v->z[n]) > m ? fabs(v->z[n]) : m;
    v->err = 32.0 * DBL_EPSILON * m + 8.0 * DBL_TRUE_MIN;
    return 1;
}

/* The sentences of the gridded fields' statuses; 0 when not one. */
static int field_sentence(out *o, const ts_error_context *c, const ts_error *e)
{
    const ts_surface_options *so = c->surface_options;
    if (!so || so->struct_size != sizeof *so || so->shape != TS_SURFACE_GRIDS)
        return 0;
    int have_grid = c->x && c->y && c->n_points >= 2 && c->ny_points >= 2;
    double x0 = have_grid ? c->x[0] : (double)INFINITY, y0 = have_grid ? c->y[0] : (double)INFINITY;
    double x1 = have_grid ? c->x[c->n_points - 1] : -(double)INFINITY;
    double y1 = have_grid ? c->y[c->ny_points - 1] : -(double)INFINITY;
    if (e->status == TS_ERR_BOUND_GRID && (e->index == 0 || e->index == 1)) {
        const ts_grid_bound *g = e->index ? &so->upper_grid : &so->lower_grid;
        const char *side = e->index ? "upper" : "lower";
        size_t at;
        switch (ts__gb_check(g, x0, x1, y0, y1, &at)) {
        case TS__GB_NULL:
            put(o, "the %s field's x, y or z is NULL", side);
            return 1;
        case TS__GB_TOO_FEW:
            put(o, "the %s field has %zu x %zu nodes; at least 2 in each direction are needed",
                side, g->nx_points, g->ny_points);
            return 1;
        case TS__GB_AXIS: {
            int isy = at >= g->nx_points;
            size_t k = isy ? at - g->nx_points : at;
            put(o, "the %s field's %s[%zu] = ", side, isy ? "y" : "x", k);
            num(o, (isy ? g->y : g->x)[k]);
            put(o, " is not finite, or not greater than the previous one by a finite step");
            return 1;
        }
        case TS__GB_VALUE:
            put(o, "the %s field's value at its node (%zu, %zu) is ", side, at % g->nx_points,
                at / g->nx_points);
            num(o, g->z[at]);
            put(o, ", not finite or beyond 2^1022 in magnitude");
            return 1;
        case TS__GB_COVER:
            put(o, "the %s field's grid [", side);
            num(o, g->x[0]);
            put(o, ", ");
            num(o, g->x[g->nx_points - 1]);
            put(o, "] x [");
            num(o, g->y[0]);
            put(o, ", ");
            num(o, g->y[g->ny_points - 1]);
            put(o, "] does not cover the surface's grid [");
            num(o, x0);
            put(o, ", ");
            num(o, x1);
            put(o, "] x [");
            num(o, y0);
            put(o, ", ");
            num(o, y1);
            put(o, "]; a field is not extended beyond its grid");
            return 1;
        default:
            put(o, "the %s field: %s", side, ts__strerror(e->status));
            return 1;
        }
    }
    if (e->status == TS_ERR_UNPROVEN && e->where == TS_WHERE_INTERVAL) {
        surface_where(o, c, e);
        put(o, ": not proven strictly between the gridded fields, even with a^x and a^y "
               "raised tenfold 12 times (a field may bulge past the data between their nodes)");
        return 1;
    }
    ts__gbound lo, up;
    int hl = so->has_lower && field_view(&so->lower_grid, &lo);
    int hu = so->has_upper && field_view(&so->upper_grid, &up);
    if (e->status == TS_ERR_SIDE && e->where == TS_WHERE_POINT && have_grid && c->f &&
        e->index < c->n_points * c->ny_points) {
        double xv = c->x[e->index % c->n_points], yv = c->y[e->index / c->n_points];
        double z = c->f[e->index];
        int below = hl && ts__gb_side(&lo, xv, yv, z) != 1;
        if (!(below ? hl : hu))
            return 0;
        surface_where(o, c, e);
        put(o, below ? " is not above the lower field, whose value there is "
                     : " is not below the upper field, whose value there is ");
        num(o, ts__gb_value(below ? &lo : &up, xv, yv));
        put(o, "; every node must be strictly between the fields");
        return 1;
    }
    if (e->status == TS_ERR_LINES && hl && hu && have_grid) {
        double px = 0.0, py = 0.0;
        ts_error e2;
        if (ts__surf_grids_order(&lo, &up, x0, x1, y0, y1, &px, &py, &e2) == TS_ERR_LINES) {
            put(o, "at (x = ");
            xval(o, c, px);
            put(o, ", y = ");
            num(o, py);
            put(o, ") the upper field (value ");
            num(o, ts__gb_value(&up, px, py));
            put(o, ") is not above the lower field (value ");
            num(o, ts__gb_value(&lo, px, py));
            put(o, ") by more than their rounding bound ");
            num(o, 5.0 * (lo.err + up.err));
            return 1;
        }
    }
    return 0;
}

static void surface_sentence(out *o, const ts_error_context *c, const ts_error *e)
{
    if (field_sentence(o, c, e))
        return;
    if (e->status == TS_ERR_NEGATIVE && e->where == TS_WHERE_POINT && c->f) {
        surface_where(o, c, e);
        put(o, " is negative; the positive shape needs z >= 0");
        return;
    }
    if (e->status == TS_ERR_GEOMETRIC && c->surface_options &&
        c->surface_options->struct_size == sizeof *c->surface_options) {
        put(o, "alpha + beta = ");
        num(o, c->surface_options->alpha + c->surface_options->beta);
        put(o, " is below the geometric-form bound ");
        num(o, TS_GEOMETRIC_A_MIN);
        put(o, "; raise alpha or beta");
        return;
    }
    /* TS_ERR_NONFINITE at a node whose z is finite, or at a patch of finite
     * data: a slope or control value computed from finite data overflowed
     * (ts_surface_new), not the input */
    if (e->status == TS_ERR_NONFINITE && c->f && c->x && c->y &&
        ((e->where == TS_WHERE_POINT && e->index < c->n_points * c->ny_points &&
          isfinite(c->f[e->index])) ||
         e->where == TS_WHERE_INTERVAL)) {
        surface_where(o, c, e);
        put(o, e->where == TS_WHERE_POINT
                   ? ": the slopes computed at this node overflow a double (finite values "
                     "this close to the largest double; rescale z)"
                   : ": the control values of this patch overflow a double (finite values "
                     "this close to the largest double; rescale z)");
        return;
    }
    if (e->where != TS_WHERE_NONE && e->index != TS_NO_INDEX) {
        surface_where(o, c, e);
        put(o, ": ");
    }
    put(o, "%s", ts__strerror(e->status));
}

static void curve_sentence(out *o, const ts_error_context *c, const ts_error *e)
{
    size_t i = e->index;
    if (e->where == TS_WHERE_POINT && c->points && i < c->n_points &&
        (c->dim == 2 || c->dim == 3)) {
        put(o, "point %zu (", c->first_index + i);
        for (size_t k = 0; k < c->dim; k++) {
            if (k)
                put(o, ", ");
            num(o, c->points[i * c->dim + k]);
        }
        put(o, ")");
        if (e->status == TS_ERR_SIDE) {
            put(o, " is outside the box");
            return;
        }
        if (e->status == TS_ERR_UNSORTED) {
            put(o, " repeats the previous point (or its parameter step is lost to rounding)");
            return;
        }
        put(o, ": ");
    } else if (e->where == TS_WHERE_INTERVAL && i != TS_NO_INDEX) {
        put(o, "segment %zu: ", c->first_index + i);
    } else if (e->where != TS_WHERE_NONE && i != TS_NO_INDEX) {
        put(o, "%s %zu: ", where_name(e->where), c->first_index + i);
    }
    put(o, "%s", ts__strerror(e->status));
}

/* ---- histograms (docs/method.md §12) ------------------------------------ */

static void bin_text(out *o, const ts_error_context *c, size_t j)
{
    put(o, "bin %zu [", c->first_index + j);
    xval(o, c, c->x[j]);
    put(o, ", ");
    xval(o, c, c->x[j + 1]);
    put(o, "]");
}

static void bounds_text(out *o, double lo, double hi)
{
    put(o, "the rate bounds [");
    num(o, lo);
    put(o, ", ");
    num(o, hi);
    put(o, "]");
}

/* 1 when a sentence was written. */
static int histo_sentence(out *o, const ts_error_context *c, const ts_error *e)
{
    /* options of another version: not read (their sentences name no values) */
    const ts_histo_options *opt =
        c->histo_options->struct_size == sizeof *opt ? c->histo_options : NULL;
    size_t ne = c->x ? c->n_points : 0, nb = ne > 0 ? ne - 1 : 0, i = e->index;
    int have_t = c->f != NULL;
    switch (e->status) {
    case TS_ERR_TOO_FEW:
        put(o, "0 bins; at least 1 is needed");
        return 1;
    case TS_ERR_ALPHA:
        if (!opt)
            return 0;
        put(o, "alpha = ");
        num(o, opt->alpha);
        put(o, " must be finite and > 0");
        return 1;
    case TS_ERR_OPTION:
        if (!opt)
            return 0;
        put(o, "the rate bounds lo = ");
        num(o, opt->lo);
        put(o, ", hi = ");
        num(o, opt->hi);
        put(o, " need lo finite and lo < hi");
        return 1;
    case TS_ERR_NONFINITE:
        if (e->where == TS_WHERE_POINT && i < ne) {
            put(o, "edge %zu (x = ", c->first_index + i);
            xval(o, c, c->x[i]);
            put(o, ") is NaN or infinite");
            return 1;
        }
        if (e->where == TS_WHERE_INTERVAL && i < nb && have_t) {
            bin_text(o, c, i);
            put(o, ": total ");
            num(o, c->f[i]);
            put(o, " is NaN or infinite");
            return 1;
        }
        return 0;
    case TS_ERR_UNSORTED:
        if (e->where != TS_WHERE_POINT || !(0 < i && i < ne))
            return 0;
        put(o, "edge %zu (x = ", c->first_index + i);
        xval(o, c, c->x[i]);
        put(o, ") is not greater than the previous edge ");
        xval(o, c, c->x[i - 1]);
        put(o, "; edges must be strictly increasing");
        return 1;
    case TS_ERR_WIDTH: {
        if (e->where != TS_WHERE_POINT || !(0 < i && i < ne))
            return 0;
        double w = c->x[i] - c->x[i - 1];
        bin_text(o, c, i - 1);
        put(o, ": the width ");
        num(o, w);
        put(o, w > 1.0 ? " overflows a double" : " is below the smallest normal double");
        return 1;
    }
    case TS_ERR_TOO_LARGE:
    case TS_ERR_NEGATIVE:
    case TS_ERR_INFEASIBLE: {
        if (e->where != TS_WHERE_INTERVAL || i >= nb || !have_t ||
            (e->status == TS_ERR_INFEASIBLE && !opt))
            return 0;
        double m = c->f[i] / (c->x[i + 1] - c->x[i]);
        /* TS_ERR_INFEASIBLE: opt != NULL (returned above otherwise) */
        int pair = e->status == TS_ERR_INFEASIBLE && opt->lo <= m && m <= opt->hi && i + 1 < nb;
        bin_text(o, c, i);
        if (!pair) {
            put(o, ": total ");
            num(o, c->f[i]);
        }
        if (e->status == TS_ERR_NEGATIVE) {
            put(o, " is negative; totals must be >= 0");
            return 1;
        }
        if (e->status == TS_ERR_TOO_LARGE) {
            double lo = opt ? opt->lo : 0.0;
            if (!(fabs(m - lo) <= TS__HISTO_MEAN_MAX)) {
                put(o, " gives the mean ");
                num(o, m);
                put(o, ", too large in magnitude");
                return 1;
            }
            /* the mean is within the limit: the bin's integral overflowed */
            put(o, " over the width ");
            num(o, c->x[i + 1] - c->x[i]);
            put(o, ": the integral of the rates");
            if (lo != 0.0) {
                put(o, " (the lower bound ");
                num(o, lo);
                put(o, " times the width included)");
            }
            put(o, " overflows a double");
            return 1;
        }
        if (!pair) {
            put(o, " gives the mean ");
            num(o, m);
            put(o, ", outside ");
            bounds_text(o, opt->lo, opt->hi);
            return 1;
        }
        put(o, " and ");
        bin_text(o, c, i + 1);
        put(o, ": the means ");
        num(o, m);
        put(o, " and ");
        num(o, c->f[i + 1] / (c->x[i + 2] - c->x[i + 1]));
        put(o, " are too far apart to be joined inside ");
        bounds_text(o, opt->lo, opt->hi);
        return 1;
    }
    default:
        return 0;
    }
}

/* ---- the entry point ------------------------------------------------- */

static void context_init(ts_error_context *ctx)
{
    memset(ctx, 0, sizeof *ctx);
    ctx->struct_size = sizeof *ctx;
}

void ts_error_context_init(ts_error_context *ctx)
{
    if (ctx)
        context_init(ctx);
}

static void generic(out *o, const data *d, const ts_error *e)
{
    size_t i = e->index, n = d->n;
    if (e->where == TS_WHERE_POINT && i < n) {
        point_xf(o, d, i);
        put(o, ": ");
    } else if (e->where == TS_WHERE_INTERVAL && n > 0 && i < n - 1) {
        interval_text(o, d, i);
        put(o, ": ");
    } else if (e->where != TS_WHERE_NONE && i != TS_NO_INDEX) {
        put(o, "%s %zu: ", where_name(e->where), d->base + i);
    }
    put(o, "%s", ts__strerror(e->status));
}

size_t ts_error_message(const ts_error *err, const ts_error_context *ctx, char *buf, size_t len)
{
    out o = {buf, buf ? len : 0, 0};
    if (o.len)
        buf[0] = '\0';
    ts_error null_err = {TS_ERR_NULL, TS_NO_INDEX, TS_WHERE_NONE};
    const ts_error *e = err ? err : &null_err;
    ts_error_context none;
    context_init(&none);
    int foreign = ctx && ctx->struct_size != sizeof *ctx;
    const ts_error_context *c = ctx && !foreign ? ctx : &none;

    ts_spline_options defaults;
    ts__options_defaults(&defaults);
    data d = {c, c->spline_options ? c->spline_options : &defaults,
              c->x && c->f ? c->n_points : 0, c->first_index};
    if (d.opt->struct_size != sizeof *d.opt) /* options of another version: not read */
        d.opt = &defaults;

    if (e->where == TS_WHERE_QUERY && query_sentence(&o, c, e, c->first_index)) {
        /* done */
    } else if (c->histo_options) {
        if (!histo_sentence(&o, c, e)) { /* index only: x, f are not points */
            if (e->where == TS_WHERE_POINT || e->where == TS_WHERE_INTERVAL)
                put(&o, "%s %zu: ", e->where == TS_WHERE_POINT ? "edge" : "bin",
                    c->first_index + e->index);
            put(&o, "%s", ts__strerror(e->status));
        }
    } else if (c->surface_options || c->y) {
        surface_sentence(&o, c, e);
    } else if (c->curve_options || c->points) {
        curve_sentence(&o, c, e);
    } else if (!spline_sentence(&o, &d, e)) {
        generic(&o, &d, e);
    }
    if (foreign)
        put(&o, " (error context of another version ignored)");
    return o.need;
}

#ifdef TS_TEST_HOOKS
/* internal.h: the sentence of a failure record, for records the data
 * checks do not produce (tests/unit/test_error_message.c). */
size_t ts__failure_message(const ts_constraint_failure *fl, const ts_error_context *ctx, char *buf,
                           size_t len)
{
    out o = {buf, len, 0};
    buf[0] = '\0';
    data d = {ctx, ctx->spline_options, ctx->n_points, ctx->first_index};
    return failure_sentence(&o, &d, fl) ? o.need : 0;
}
#endif
