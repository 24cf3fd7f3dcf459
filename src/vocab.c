/* The canonical names of the enum values and of the statuses: the one table
 * every front-end reads (bookkeeping; docs/method.md is not involved). */
#include "internal.h"

#include <string.h>

#define TS_NELEM(a) (sizeof(a) / sizeof((a)[0]))

static const char *const status_names[] = {
    [TS_OK] = "TS_OK",
    [TS_ERR_NULL] = "TS_ERR_NULL",
    [TS_ERR_NOMEM] = "TS_ERR_NOMEM",
    [TS_ERR_OVERFLOW] = "TS_ERR_OVERFLOW",
    [TS_ERR_TOO_FEW] = "TS_ERR_TOO_FEW",
    [TS_ERR_NONFINITE] = "TS_ERR_NONFINITE",
    [TS_ERR_UNSORTED] = "TS_ERR_UNSORTED",
    [TS_ERR_ALPHA] = "TS_ERR_ALPHA",
    [TS_ERR_BETA] = "TS_ERR_BETA",
    [TS_ERR_MARGIN] = "TS_ERR_MARGIN",
    [TS_ERR_LENGTH] = "TS_ERR_LENGTH",
    [TS_ERR_OPTION] = "TS_ERR_OPTION",
    [TS_ERR_PERIODIC] = "TS_ERR_PERIODIC",
    [TS_ERR_DOMAIN] = "TS_ERR_DOMAIN",
    [TS_ERR_NEGATIVE] = "TS_ERR_NEGATIVE",
    [TS_ERR_SIDE] = "TS_ERR_SIDE",
    [TS_ERR_LINES] = "TS_ERR_LINES",
    [TS_ERR_NONMONOTONE] = "TS_ERR_NONMONOTONE",
    [TS_ERR_INFEASIBLE] = "TS_ERR_INFEASIBLE",
    [TS_ERR_VIOLATED] = "TS_ERR_VIOLATED",
    [TS_ERR_GEOMETRIC] = "TS_ERR_GEOMETRIC",
    [TS_ERR_DIMENSION] = "TS_ERR_DIMENSION",
    [TS_ERR_INDEX] = "TS_ERR_INDEX",
    [TS_ERR_ZERO_SLOPE] = "TS_ERR_ZERO_SLOPE",
    [TS_ERR_SLOPE_OVERFLOW] = "TS_ERR_SLOPE_OVERFLOW",
    [TS_ERR_TOO_LARGE] = "TS_ERR_TOO_LARGE",
    [TS_ERR_CONTROL_OVERFLOW] = "TS_ERR_CONTROL_OVERFLOW",
    [TS_ERR_WIDTH] = "TS_ERR_WIDTH",
    [TS_ERR_PRECISION] = "TS_ERR_PRECISION",
    [TS_ERR_UNPROVEN] = "TS_ERR_UNPROVEN",
    [TS_ERR_VERSION] = "TS_ERR_VERSION",
    [TS_ERR_CONDITION] = "TS_ERR_CONDITION",
    [TS_ERR_BOUND_GRID] = "TS_ERR_BOUND_GRID",
};
static const char *const form_names[] = {
    [TS_FORM_PAPER] = "paper", [TS_FORM_C1] = "c1", [TS_FORM_GEOMETRIC] = "geometric"};
static const char *const slopes_names[] = {
    [TS_SLOPES_ARITHMETIC] = "arithmetic", [TS_SLOPES_GEOMETRIC] = "geometric",
    [TS_SLOPES_HARMONIC] = "harmonic",     [TS_SLOPES_FRITSCH_CARLSON] = "fritsch-carlson",
    [TS_SLOPES_AKIMA] = "akima",           [TS_SLOPES_MAKIMA] = "makima",
    [TS_SLOPES_USER] = "user",             [TS_SLOPES_PERIODIC] = "periodic",
    [TS_SLOPES_STEFFEN] = "steffen"};
static const char *const shape_names[] = {
    [TS_SHAPE_NONE] = "none",   [TS_SHAPE_POSITIVE] = "positive", [TS_SHAPE_ABOVE] = "above",
    [TS_SHAPE_BELOW] = "below", [TS_SHAPE_BETWEEN] = "between",   [TS_SHAPE_MONOTONE] = "monotone"};
static const char *const extrap_names[] = {
    [TS_EXTRAP_ERROR] = "error", [TS_EXTRAP_CLAMP] = "clamp", [TS_EXTRAP_EXTEND] = "extend",
    [TS_EXTRAP_LINEAR] = "linear"};
static const char *const param_names[] = {
    [TS_PARAM_CENTRIPETAL] = "centripetal", [TS_PARAM_CHORD] = "chord",
    [TS_PARAM_UNIFORM] = "uniform"};
static const char *const surface_shape_names[] = {
    [TS_SURFACE_NONE] = "none",     [TS_SURFACE_POSITIVE] = "positive",
    [TS_SURFACE_BOUNDS] = "bounds", [TS_SURFACE_PLANES] = "planes",
    [TS_SURFACE_RANGE] = "range",   [TS_SURFACE_GRIDS] = "grids"};
static const char *const term_names[] = {
    [TS_TERM_USER] = "user",
    [TS_TERM_MARGIN] = "margin",
    [TS_TERM_LOWER_LEFT] = "lower-left",
    [TS_TERM_LOWER_RIGHT] = "lower-right",
    [TS_TERM_UPPER_LEFT] = "upper-left",
    [TS_TERM_UPPER_RIGHT] = "upper-right",
    [TS_TERM_MONOTONE] = "monotone",
    [TS_TERM_CERTIFY] = "certify",
    [TS_TERM_GEOMETRIC] = "geometric"};
static const char *const where_names[] = {
    [TS_WHERE_NONE] = "none", [TS_WHERE_POINT] = "point", [TS_WHERE_INTERVAL] = "interval",
    [TS_WHERE_QUERY] = "query"};

static const char *const constraint_names[] = {
    [TS_CONSTRAINT_CONVEX] = "convex",         [TS_CONSTRAINT_CONCAVE] = "concave",
    [TS_CONSTRAINT_INCREASING] = "increasing", [TS_CONSTRAINT_DECREASING] = "decreasing",
    [TS_CONSTRAINT_LOWER] = "lower",           [TS_CONSTRAINT_UPPER] = "upper",
    [TS_CONSTRAINT_SLOPE_MIN] = "slope-min",   [TS_CONSTRAINT_SLOPE_MAX] = "slope-max",
    [TS_CONSTRAINT_SLOPE_ABS] = "slope-abs"};
static const char *const bound_names[] = {[TS_BOUND_CONSTANT] = "constant",
                                          [TS_BOUND_POLYLINE] = "polyline",
                                          [TS_BOUND_SPLINE] = "spline"};
static const char *const condition_names[] = {
    [TS_CONDITION_NONE] = "none",
    [TS_CONDITION_CONVEX_DATA] = "convex-data",
    [TS_CONDITION_CONCAVE_DATA] = "concave-data",
    [TS_CONDITION_MONOTONE_DATA] = "monotone-data",
    [TS_CONDITION_INSIDE_BOUND] = "inside-bound",
    [TS_CONDITION_SECANT_SLOPE] = "secant-slope",
    [TS_CONDITION_SLOPE_CONFLICT] = "slope-conflict",
    [TS_CONDITION_UNPROVEN] = "unproven",
    [TS_CONDITION_TOUCH_CORNER] = "touch-corner",
    [TS_CONDITION_CURVATURE_SLOPE] = "curvature-slope"};

/* A new enumerator without its name fails to compile here. */
_Static_assert(TS_NELEM(status_names) == TS_STATUS_COUNT_, "a status without a name");
_Static_assert(TS_NELEM(form_names) == TS_FORM_GEOMETRIC + 1, "a form without a name");
_Static_assert(TS_NELEM(slopes_names) == TS_SLOPES_COUNT_, "a slope method without a name");
_Static_assert(TS_NELEM(shape_names) == TS_SHAPE_MONOTONE + 1, "a shape without a name");
_Static_assert(TS_NELEM(extrap_names) == TS_EXTRAP_LINEAR + 1, "an extrapolation without a name");
_Static_assert(TS_NELEM(param_names) == TS_PARAM_UNIFORM + 1, "a parameterisation without a name");
_Static_assert(TS_NELEM(surface_shape_names) == TS_SURFACE_GRIDS + 1, "a surface shape without a name");
_Static_assert(TS_NELEM(term_names) == TS_TERM_GEOMETRIC + 1, "a term without a name");
_Static_assert(TS_NELEM(where_names) == TS_WHERE_QUERY + 1, "a where without a name");
_Static_assert(TS_NELEM(constraint_names) == TS_CONSTRAINT_COUNT_, "a constraint without a name");
_Static_assert(TS_NELEM(bound_names) == TS_BOUND_SPLINE + 1, "a bound without a name");
_Static_assert(TS_NELEM(condition_names) == TS_CONDITION_CURVATURE_SLOPE + 1, "a condition without a name");

typedef struct vocab_table {
    const char *const *name;
    int n;
} vocab_table;

static const vocab_table tables[TS_VOCAB_COUNT_] = {
    [TS_VOCAB_STATUS] = {status_names, (int)TS_NELEM(status_names)},
    [TS_VOCAB_FORM] = {form_names, (int)TS_NELEM(form_names)},
    [TS_VOCAB_SLOPES] = {slopes_names, (int)TS_NELEM(slopes_names)},
    [TS_VOCAB_SHAPE] = {shape_names, (int)TS_NELEM(shape_names)},
    [TS_VOCAB_EXTRAP] = {extrap_names, (int)TS_NELEM(extrap_names)},
    [TS_VOCAB_PARAM] = {param_names, (int)TS_NELEM(param_names)},
    [TS_VOCAB_SURFACE_SHAPE] = {surface_shape_names, (int)TS_NELEM(surface_shape_names)},
    [TS_VOCAB_TERM] = {term_names, (int)TS_NELEM(term_names)},
    [TS_VOCAB_WHERE] = {where_names, (int)TS_NELEM(where_names)},
    [TS_VOCAB_CONSTRAINT] = {constraint_names, (int)TS_NELEM(constraint_names)},
    [TS_VOCAB_BOUND] = {bound_names, (int)TS_NELEM(bound_names)},
    [TS_VOCAB_CONDITION] = {condition_names, (int)TS_NELEM(condition_names)},
};

const char *ts__vocab_name(ts_vocab vocab, int value)
{
    if (!((unsigned)vocab < (unsigned)TS_VOCAB_COUNT_))
        return NULL;
    const vocab_table *t = &tables[vocab];
    return (0 <= value && value < t->n) ? t->name[value] : NULL;
}

const char *ts_vocab_name(ts_vocab vocab, int value)
{
    return ts__vocab_name(vocab, value);
}

int ts_vocab_count(ts_vocab vocab)
{
    return (unsigned)vocab < (unsigned)TS_VOCAB_COUNT_ ? tables[vocab].n : 0;
}

ts_status ts_vocab_value(ts_vocab vocab, const char *name, int *value)
{
    if (value)
        *value = -1;
    if (!name || !value)
        return TS_ERR_NULL;
    if (!((unsigned)vocab < (unsigned)TS_VOCAB_COUNT_))
        return TS_ERR_OPTION;
    const vocab_table *t = &tables[vocab];
    for (int i = 0; i < t->n; i++)
        if (strcmp(name, t->name[i]) == 0) {
            *value = i;
            return TS_OK;
        }
    return TS_ERR_OPTION;
}

const char *ts__status_name(ts_status status)
{
    const char *s = ts__vocab_name(TS_VOCAB_STATUS, (int)status);
    return s ? s : "TS_STATUS_UNKNOWN";
}

const char *ts_status_name(ts_status status)
{
    return ts__status_name(status);
}
