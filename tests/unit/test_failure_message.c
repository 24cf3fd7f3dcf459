/* The sentence of a constraint failure record (src/errmsg.c,
 * failure_sentence through ts__failure_message): ts_error_message asks for
 * it only with the record the data checks found again, but the builder must
 * be safe for any record: one naming an end point for a convexity failure,
 * an interval past the last, a record or index outside the data, a
 * condition the checks never report, a touched breakpoint that is not an
 * inner one of a polyline, options that do not validate.  Those give 0 (no
 * sentence; ts_error_message then uses the generic one).  The sentences
 * that do apply are written out by hand from the data below (the wording of
 * src/errmsg.c; numbers in the shortest form: the secants are exact). */
#include "internal.h"
#include "th.h"

#include <stdio.h>
#include <string.h>

static char buf[512];

static size_t msg(const ts_constraint_failure *fl, const ts_error_context *c)
{
    return ts__failure_message(fl, c, buf, sizeof buf);
}

static ts_constraint_failure rec(size_t k, size_t i, ts_condition cond)
{
    ts_constraint_failure fl;
    ts_constraint_failure_init(&fl);
    fl.status = TS_ERR_CONDITION;
    fl.constraint = k;
    fl.index = i;
    fl.where = cond == TS_CONDITION_SECANT_SLOPE ? TS_WHERE_INTERVAL : TS_WHERE_POINT;
    fl.condition = cond;
    return fl;
}

#define NONE(fl, c)                                                                      \
    do {                                                                                 \
        ts_constraint_failure r_ = (fl);                                                 \
        size_t n_ = msg(&r_, (c));                                                       \
        CHECKF(n_ == 0 && buf[0] == '\0', "record %zu at %zu, condition %d: \"%s\"",     \
               r_.constraint, r_.index, (int)r_.condition, buf);                         \
    } while (0)

#define SAYS(fl, c, want)                                                                  \
    do {                                                                                   \
        ts_constraint_failure r_ = (fl);                                                   \
        size_t n_ = msg(&r_, (c));                                                         \
        CHECKF(n_ == strlen(want) && strcmp(buf, want) == 0, "\n   got  \"%s\"\n   want \"%s\"", \
               buf, want);                                                                 \
    } while (0)

int main(void)
{
    /* 5 points; the upper polyline has breakpoints 0, 1, 2, 3, 4 */
    static const double x[5] = {0, 1, 2, 3, 4}, f[5] = {0, 2, 3, 5, 4};
    static const double px[5] = {0, 1, 2, 3, 4}, py[5] = {10, 11, 10, 11, 10};
    static const double ly[5] = {-10, -9, -10, -9, -10};
    ts_constraint cs[5];
    ts_constraint_init(&cs[0], TS_CONSTRAINT_CONVEX);
    ts_constraint_init(&cs[1], TS_CONSTRAINT_SLOPE_MAX);
    cs[1].value = 1.5;
    ts_constraint_init(&cs[2], TS_CONSTRAINT_UPPER);
    cs[2].bound = TS_BOUND_POLYLINE;
    cs[2].px = px;
    cs[2].py = py;
    cs[2].n_poly = 5;
    ts_constraint_init(&cs[3], TS_CONSTRAINT_LOWER); /* constant bound 0 */
    ts_constraint_init(&cs[4], TS_CONSTRAINT_LOWER);
    cs[4].bound = TS_BOUND_POLYLINE;
    cs[4].px = px;
    cs[4].py = ly;
    cs[4].n_poly = 5;
    ts_spline_options o;
    ts_spline_options_init(&o); /* the geometric form, no shape: records validate */
    o.constraints = cs;
    o.n_constraints = 5;
    ts_error_context c;
    ts_error_context_init(&c);
    c.x = x;
    c.f = f;
    c.n_points = 5;
    c.spline_options = &o;

    TH_CASE("sentences of the records the checks give");
    /* secants 2, 1, 2, -1: point 1 breaks convexity (2 then 1) */
    SAYS(rec(0, 1, TS_CONDITION_CONVEX_DATA), &c,
         "point 1 (x = 1, f = 2): the data are not convex here: the secant before it is 2, "
         "the secant after it 1 (constraint 0, convex)");
    SAYS(rec(1, 0, TS_CONDITION_SECANT_SLOPE), &c,
         "interval 0 [0, 1]: its secant 2 is beyond the slope-max bound 1.5 (the slope "
         "equals the secant somewhere in the interval) (constraint 1, slope-max)");
    /* point 1 (x = 1) on the breakpoint (1, 11): slopes 1, then -1 */
    SAYS(rec(2, 1, TS_CONDITION_TOUCH_CORNER), &c,
         "point 1 (x = 1, f = 2) lies on the upper bound at its breakpoint, where the "
         "polyline's slope goes from 1 to -1: no curve with a continuous slope stays below it "
         "through this point (constraint 2, upper)");
    /* point 1 on the lower polyline's breakpoint (1, -9): slopes 1, then -1 */
    SAYS(rec(4, 1, TS_CONDITION_TOUCH_CORNER), &c,
         "point 1 (x = 1, f = 2) lies on the lower bound at its breakpoint, where the "
         "polyline's slope goes from 1 to -1: no curve with a continuous slope stays above it "
         "through this point (constraint 4, lower)");

    TH_CASE("records naming nothing these data have: no sentence");
    NONE(rec(5, 2, TS_CONDITION_CONVEX_DATA), &c);  /* no record 5 */
    NONE(rec(0, 5, TS_CONDITION_CONVEX_DATA), &c);  /* no point 5 */
    NONE(rec(0, 0, TS_CONDITION_CONVEX_DATA), &c);  /* an end point: no secant before */
    NONE(rec(0, 4, TS_CONDITION_CONCAVE_DATA), &c); /* the last: no secant after */
    NONE(rec(1, 4, TS_CONDITION_SECANT_SLOPE), &c); /* interval 4 of 4 */
    NONE(rec(0, 2, TS_CONDITION_SLOPE_CONFLICT), &c);
    /* point 2: convex needs S' in [1, 2], slope-max allows up to 1.5: no conflict */
    NONE(rec(1, 2, TS_CONDITION_CURVATURE_SLOPE), &c);
    NONE(rec(0, 2, TS_CONDITION_UNPROVEN), &c);
    NONE(rec(0, 2, TS_CONDITION_NONE), &c);
    NONE(rec(3, 1, TS_CONDITION_TOUCH_CORNER), &c); /* a constant bound has no corner */
    NONE(rec(0, 1, TS_CONDITION_TOUCH_CORNER), &c); /* convex: a bound type is ignored */
    cs[0].bound = TS_BOUND_POLYLINE;                 /* ... also a polyline (px NULL) */
    NONE(rec(0, 1, TS_CONDITION_TOUCH_CORNER), &c);
    cs[0].bound = TS_BOUND_CONSTANT;
    NONE(rec(2, 0, TS_CONDITION_TOUCH_CORNER), &c); /* x = 0: the first breakpoint */
    NONE(rec(2, 4, TS_CONDITION_TOUCH_CORNER), &c); /* x = 4: the last */
    {
        static const double xs[5] = {0, 0.5, 2, 3, 4}; /* x = 0.5: no breakpoint */
        c.x = xs;
        NONE(rec(2, 1, TS_CONDITION_TOUCH_CORNER), &c);
        c.x = x;
    }
    o.form = TS_FORM_PAPER; /* records with the paper form: TS_ERR_OPTION */
    NONE(rec(0, 2, TS_CONDITION_CONVEX_DATA), &c);
    o.form = TS_FORM_GEOMETRIC;
    c.n_points = 1; /* one point: no interval for any record's scope */
    NONE(rec(0, 0, TS_CONDITION_MONOTONE_DATA), &c);
    c.n_points = 5;

    TH_CASE("the same records through ts_error_message: the checks' own record only");
    {
        /* the data checks find convexity broken at point 1 (record 0) first */
        ts_error e = {TS_ERR_CONDITION, 1, TS_WHERE_POINT};
        char all[512];
        CHECK(ts_error_message(&e, &c, all, sizeof all) > 0);
        ts_constraint_failure r = rec(0, 1, TS_CONDITION_CONVEX_DATA);
        CHECK(msg(&r, &c) > 0 && strcmp(all, buf) == 0);
        /* the error names point 3: not the checks' index, the generic sentence */
        e.index = 3;
        CHECK(ts_error_message(&e, &c, all, sizeof all) > 0);
        char want[512];
        snprintf(want, sizeof want, "point 3 (x = 3, f = 5): %s", ts_strerror(TS_ERR_CONDITION));
        CHECKF(strcmp(all, want) == 0, "\n   got  \"%s\"\n   want \"%s\"", all, want);
    }
    return th_report("test_failure_message");
}
