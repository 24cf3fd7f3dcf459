/* ts_error_message's sentences of the constraint scheme and of the
 * histogram rate, and their fall-backs: a sentence names values from the
 * context only when the context has them and they agree with the error
 * (include/trigspline.h, ts_error_message); otherwise the message is the
 * status's text with the index as the header gives it ("edge N: ",
 * "bin N: ", or the spline's point or interval).  Each case fails if a
 * sentence is written from a context that cannot support it (wrong text,
 * or a read through a NULL or short array, which the ASan build reports),
 * or if a supported one is not written. */
#include "th.h"
#include "trigspline.h"

#include <stdio.h>
#include <string.h>

static char buf[1024];

static const char *msg(ts_status st, size_t index, ts_where where, const ts_error_context *c)
{
    ts_error e = {st, index, where};
    size_t need = ts_error_message(&e, c, buf, sizeof buf);
    CHECK(need < sizeof buf && strlen(buf) == need);
    return buf;
}

#define HAS(s, sub) CHECKF(strstr((s), (sub)) != NULL, "\"%s\" lacks \"%s\"", (s), (sub))
#define LACKS(s, sub) CHECKF(strstr((s), (sub)) == NULL, "\"%s\" has \"%s\"", (s), (sub))
#define SAME(s, want) CHECKF(strcmp((s), (want)) == 0, "\n got  \"%s\"\n want \"%s\"", (s), (want))

/* a spline context with constraint records */
static ts_error_context sctx(const double *x, const double *f, size_t n, const ts_spline_options *o)
{
    ts_error_context c;
    ts_error_context_init(&c);
    c.x = x;
    c.f = f;
    c.n_points = n;
    c.spline_options = o;
    return c;
}

/* ts_spline_new's error on these data and options */
static ts_error fail_of(const double *x, const double *f, size_t n, const ts_spline_options *o)
{
    ts_error e;
    ts_spline *s = NULL;
    (void)ts_spline_new(x, f, n, o, &s, &e);
    ts_spline_free(s);
    return e;
}

static void constraint_sentences(void)
{
    TH_CASE("constraint conditions");
    const char *cond = ts_strerror(TS_ERR_CONDITION);
    double x[4] = {0, 1, 2, 3}, f[4] = {0, 2, 1, 3};
    ts_spline_options o;
    ts_constraint c[2];
    ts_spline_options_init(&o);
    ts_constraint_init(&c[0], TS_CONSTRAINT_INCREASING);
    o.constraints = c;
    o.n_constraints = 1;
    ts_error_context ctx = sctx(x, f, 4, &o);
    ts_error e = fail_of(x, f, 4, &o); /* up, then down at point 2 */
    CHECK(e.status == TS_ERR_CONDITION && e.where == TS_WHERE_POINT && e.index == 2);
    HAS(msg(e.status, e.index, e.where, &ctx), "the data change direction here; increasing needs monotone data");
    /* an index the data checks do not name: the status's text */
    LACKS(msg(e.status, 1, e.where, &ctx), "change direction");
    HAS(buf, cond);
    /* data that pass the checks: the same */
    double g[4] = {0, 1, 2, 3};
    ts_error_context ok = sctx(x, g, 4, &o);
    LACKS(msg(TS_ERR_CONDITION, 1, TS_WHERE_POINT, &ok), "change direction");
    HAS(buf, cond);
    /* contexts without the data or the records */
    ts_error_context nx = sctx(NULL, f, 4, &o), nf = sctx(x, NULL, 4, &o), n1 = sctx(x, f, 1, &o);
    HAS(msg(e.status, 1, e.where, &nx), cond);
    LACKS(buf, "change direction");
    HAS(msg(e.status, 1, e.where, &nf), cond);
    LACKS(buf, "change direction");
    HAS(msg(e.status, 0, e.where, &n1), cond);
    ts_spline_options plain;
    ts_spline_options_init(&plain);
    ts_error_context np = sctx(x, f, 4, &plain);
    HAS(msg(e.status, 1, e.where, &np), cond);
    LACKS(buf, "change direction");
    c[0].struct_size = 1; /* a record of another version: the checks fail first */
    HAS(msg(e.status, 2, e.where, &ctx), cond);
    LACKS(buf, "change direction");
    ts_constraint_init(&c[0], TS_CONSTRAINT_INCREASING);
    o.n_constraints = 0;
    HAS(msg(e.status, 1, e.where, &ctx), cond);
    LACKS(buf, "change direction");
    o.n_constraints = 1;

    /* a point above a constant upper bound */
    ts_constraint_init(&c[0], TS_CONSTRAINT_UPPER);
    c[0].value = 2.5;
    double h[4] = {0, 1, 3, 2};
    ctx = sctx(x, h, 4, &o);
    e = fail_of(x, h, 4, &o);
    CHECK(e.status == TS_ERR_CONDITION && e.index == 2);
    HAS(msg(e.status, e.index, e.where, &ctx), "is not below the upper bound");

    /* a point below a constant lower bound */
    ts_constraint_init(&c[0], TS_CONSTRAINT_LOWER);
    c[0].value = 0.5;
    double lw[4] = {1, 2, 0.25, 3};
    ctx = sctx(x, lw, 4, &o);
    e = fail_of(x, lw, 4, &o);
    CHECK(e.status == TS_ERR_CONDITION && e.index == 2);
    HAS(msg(e.status, e.index, e.where, &ctx), "is not above the lower bound");

    /* a secant beyond a slope bound, in the second record */
    ts_constraint_init(&c[0], TS_CONSTRAINT_INCREASING);
    ts_constraint_init(&c[1], TS_CONSTRAINT_SLOPE_MAX);
    c[1].value = 1.5;
    o.n_constraints = 2;
    double s[4] = {0, 1, 3, 4};
    ctx = sctx(x, s, 4, &o);
    e = fail_of(x, s, 4, &o);
    CHECK(e.status == TS_ERR_CONDITION && e.where == TS_WHERE_INTERVAL && e.index == 1);
    HAS(msg(e.status, e.index, e.where, &ctx), "is beyond the slope-max bound 1.5");

    TH_CASE("constraint searches");
    /* TS_ERR_UNPROVEN names an interval of a constrained spline only */
    HAS(msg(TS_ERR_UNPROVEN, 1, TS_WHERE_INTERVAL, &ctx), "no alpha + beta up to 2^60");
    LACKS(msg(TS_ERR_UNPROVEN, 1, TS_WHERE_POINT, &ctx), "2^60");
    HAS(buf, ts_strerror(TS_ERR_UNPROVEN));
    LACKS(msg(TS_ERR_UNPROVEN, 1, TS_WHERE_INTERVAL, &np), "2^60");
    /* TS_ERR_INFEASIBLE at a point: the constraints' sentence only with records */
    HAS(msg(TS_ERR_INFEASIBLE, 1, TS_WHERE_POINT, &ctx), "straight lines of different slopes");
    LACKS(msg(TS_ERR_INFEASIBLE, 1, TS_WHERE_POINT, &np), "straight lines");
}

static void histo_sentences(void)
{
    TH_CASE("histogram sentences and fall-backs");
    double e[4] = {0, 1, 3, 4}, t[3] = {1, 8, 1};
    ts_histo_options ho;
    ts_histo_options_init(&ho);
    ho.hi = 2.0;
    ts_error_context c;
    ts_error_context_init(&c);
    c.x = e;
    c.f = t;
    c.n_points = 4;
    c.histo_options = &ho;
    char want[256];
    /* bin 1's mean 4 is outside [0, 2]: the single-bin sentence */
    HAS(msg(TS_ERR_INFEASIBLE, 1, TS_WHERE_INTERVAL, &c), "gives the mean 4, outside the rate bounds [0, 2]");
    /* bins 0 and 1 ... with means inside: the pair sentence; the last bin has no pair */
    t[1] = 3.0; /* mean 1.5 */
    HAS(msg(TS_ERR_INFEASIBLE, 0, TS_WHERE_INTERVAL, &c), "are too far apart");
    LACKS(msg(TS_ERR_INFEASIBLE, 2, TS_WHERE_INTERVAL, &c), "too far apart");
    HAS(buf, "outside the rate bounds");
    ho.lo = 1.2; /* bin 0's mean 1 below lo: single */
    LACKS(msg(TS_ERR_INFEASIBLE, 0, TS_WHERE_INTERVAL, &c), "too far apart");
    ho.lo = 0.0;
    /* no options: INFEASIBLE has no bounds to name */
    ts_histo_options other = ho;
    other.struct_size = 1; /* another version's: not read */
    c.histo_options = &other;
    snprintf(want, sizeof want, "bin 1: %s", ts_strerror(TS_ERR_INFEASIBLE));
    SAME(msg(TS_ERR_INFEASIBLE, 1, TS_WHERE_INTERVAL, &c), want);
    snprintf(want, sizeof want, "%s", ts_strerror(TS_ERR_OPTION));
    SAME(msg(TS_ERR_OPTION, TS_NO_INDEX, TS_WHERE_NONE, &c), want);
    snprintf(want, sizeof want, "%s", ts_strerror(TS_ERR_ALPHA));
    SAME(msg(TS_ERR_ALPHA, TS_NO_INDEX, TS_WHERE_NONE, &c), want);
    c.histo_options = &ho;
    /* the wrong kind of index, an index past the bins, no totals */
    snprintf(want, sizeof want, "edge 1: %s", ts_strerror(TS_ERR_NEGATIVE));
    SAME(msg(TS_ERR_NEGATIVE, 1, TS_WHERE_POINT, &c), want);
    snprintf(want, sizeof want, "bin 3: %s", ts_strerror(TS_ERR_TOO_LARGE));
    SAME(msg(TS_ERR_TOO_LARGE, 3, TS_WHERE_INTERVAL, &c), want);
    c.f = NULL;
    snprintf(want, sizeof want, "bin 0: %s", ts_strerror(TS_ERR_NEGATIVE));
    SAME(msg(TS_ERR_NEGATIVE, 0, TS_WHERE_INTERVAL, &c), want);
    snprintf(want, sizeof want, "bin 0: %s", ts_strerror(TS_ERR_NONFINITE));
    SAME(msg(TS_ERR_NONFINITE, 0, TS_WHERE_INTERVAL, &c), want);
    c.f = t;
    snprintf(want, sizeof want, "bin 3: %s", ts_strerror(TS_ERR_NONFINITE));
    SAME(msg(TS_ERR_NONFINITE, 3, TS_WHERE_INTERVAL, &c), want);
    snprintf(want, sizeof want, "edge 4: %s", ts_strerror(TS_ERR_NONFINITE));
    SAME(msg(TS_ERR_NONFINITE, 4, TS_WHERE_POINT, &c), want);
    /* edges: index 0 has no previous edge; intervals are not edges */
    snprintf(want, sizeof want, "edge 0: %s", ts_strerror(TS_ERR_UNSORTED));
    SAME(msg(TS_ERR_UNSORTED, 0, TS_WHERE_POINT, &c), want);
    snprintf(want, sizeof want, "bin 1: %s", ts_strerror(TS_ERR_UNSORTED));
    SAME(msg(TS_ERR_UNSORTED, 1, TS_WHERE_INTERVAL, &c), want);
    snprintf(want, sizeof want, "edge 9: %s", ts_strerror(TS_ERR_UNSORTED));
    SAME(msg(TS_ERR_UNSORTED, 9, TS_WHERE_POINT, &c), want);
    snprintf(want, sizeof want, "edge 0: %s", ts_strerror(TS_ERR_WIDTH));
    SAME(msg(TS_ERR_WIDTH, 0, TS_WHERE_POINT, &c), want);
    snprintf(want, sizeof want, "edge 9: %s", ts_strerror(TS_ERR_WIDTH));
    SAME(msg(TS_ERR_WIDTH, 9, TS_WHERE_POINT, &c), want);
    snprintf(want, sizeof want, "edge 4: %s", ts_strerror(TS_ERR_WIDTH));
    SAME(msg(TS_ERR_WIDTH, 4, TS_WHERE_POINT, &c), want);
    snprintf(want, sizeof want, "bin 1: %s", ts_strerror(TS_ERR_WIDTH));
    SAME(msg(TS_ERR_WIDTH, 1, TS_WHERE_INTERVAL, &c), want);
    /* a status without a histogram sentence, with and without an index */
    snprintf(want, sizeof want, "%s", ts_strerror(TS_ERR_NOMEM));
    SAME(msg(TS_ERR_NOMEM, TS_NO_INDEX, TS_WHERE_NONE, &c), want);
    snprintf(want, sizeof want, "bin 2: %s", ts_strerror(TS_ERR_NOMEM));
    SAME(msg(TS_ERR_NOMEM, 2, TS_WHERE_INTERVAL, &c), want);
}

int main(void)
{
    constraint_sentences();
    histo_sentences();
    return th_report("test_error_fallbacks");
}
