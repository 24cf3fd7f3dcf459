/* ts_error_message (src/errmsg.c) and the shortest-double formatter
 * (src/numfmt.c).  Each status is provoked through the library where the
 * data make it easy, and the expected sentence is written out by hand from
 * those data (the wording of include/trigspline.h, "Error messages").
 * Truncation and len = 0 behave as snprintf; the buffers are exactly the
 * size given (malloc), so ASan reports any write past them. */
#include "internal.h"
#include "th.h"

#include <float.h>
#include <stdlib.h>
#include <string.h>

static char text[1024];

static const char *message(const ts_error *e, const ts_error_context *c)
{
    size_t n = ts_error_message(e, c, text, sizeof text);
    if (n >= sizeof text)
        return "(too long)";
    return text;
}

#define EXPECT(e, c, want)                                                                 \
    do {                                                                                   \
        const char *got_ = message(e, c);                                                  \
        CHECKF(strcmp(got_, want) == 0, "\n   got  \"%s\"\n   want \"%s\"", got_, want); \
    } while (0)

static ts_error build(const double *x, const double *f, size_t n, const ts_spline_options *o)
{
    ts_error e;
    ts_spline *s = NULL;
    ts_status st = ts_spline_new(x, f, n, o, &s, &e);
    ts_spline_free(s);
    CHECK(st == e.status);
    return e;
}

static ts_error_context spline_ctx(const double *x, const double *f, size_t n, const ts_spline_options *o)
{
    ts_error_context c;
    ts_error_context_init(&c);
    c.x = x;
    c.f = f;
    c.n_points = n;
    c.spline_options = o;
    return c;
}

static int day_text(double x, char *buf, size_t len, void *user)
{
    return snprintf(buf, len, "%s %g", (const char *)user, x);
}

static void test_numbers(void)
{
    TH_CASE("shortest doubles");
    struct {
        double v;
        const char *s;
    } t[] = {{0.1, "0.1"},
             {1.0 / 3.0, "0.3333333333333333"},
             {2.5e-7, "2.5e-07"},
             {-0.0, "-0"},
             {0.0, "0"},
             {100, "100"},
             {123456789012345680.0, "1.2345678901234568e+17"},
             {DBL_MAX, "1.7976931348623157e+308"},
             {4.9406564584124654e-324, "5e-324"},
             {DBL_MIN, "2.2250738585072014e-308"},
             {0.30000000000000004, "0.30000000000000004"},
             {TH_NAN, "nan"},
             {TH_INF, "inf"},
             {-TH_INF, "-inf"}};
    for (size_t k = 0; k < sizeof t / sizeof t[0]; k++) {
        char b[TS__NUM_SIZE];
        ts__format_double(t[k].v, b);
        CHECKF(strcmp(b, t[k].s) == 0, "%s, expected %s", b, t[k].s);
    }
}

static void test_spline_points(void)
{
    double x[] = {0, 1, 2, 3};
    ts_spline_options o;

    TH_CASE("negative");
    double fneg[] = {1, -0.5, 2, -3};
    ts_spline_options_init(&o);
    o.shape = TS_SHAPE_POSITIVE;
    ts_error e = build(x, fneg, 4, &o);
    ts_error_context c = spline_ctx(x, fneg, 4, &o);
    CHECK(e.status == TS_ERR_NEGATIVE && e.index == 1);
    EXPECT(&e, &c, "point 1 (x = 1, f = -0.5) is negative; the positive shape needs f >= 0 "
                   "(negative at x = 1, 3)");
    /* dates through the callback, indices of a block of a longer series */
    c.format_x = day_text;
    c.format_x_user = "day";
    c.first_index = 100;
    EXPECT(&e, &c, "point 101 (x = day 1, f = -0.5) is negative; the positive shape needs "
                   "f >= 0 (negative at x = day 1, day 3)");

    TH_CASE("side, lower line");
    double fs[] = {2, 2, 6, 8};
    ts_spline_options_init(&o);
    o.shape = TS_SHAPE_ABOVE;
    o.lower.m = 2;
    o.lower.c = 1; /* y = 2x + 1: 1, 3, 5, 7 */
    e = build(x, fs, 4, &o);
    c = spline_ctx(x, fs, 4, &o);
    CHECK(e.status == TS_ERR_SIDE && e.index == 1);
    EXPECT(&e, &c, "point 1 (x = 1, f = 2) is not above the lower line y = 2x + 1; the data "
                   "are on or below it at x = 1");

    TH_CASE("side, upper line, many points");
    double xs[20], fb[20];
    for (int i = 0; i < 20; i++) {
        xs[i] = i;
        fb[i] = i < 5 ? 0 : 10; /* upper y = -x + 0.5 (0.5 at x = 0): above it from x = 1 on */
    }
    ts_spline_options_init(&o);
    o.shape = TS_SHAPE_BELOW;
    o.upper.m = -1;
    o.upper.c = 0.5;
    e = build(xs, fb, 20, &o);
    c = spline_ctx(xs, fb, 20, &o);
    CHECK(e.status == TS_ERR_SIDE && e.index == 1);
    EXPECT(&e, &c, "point 1 (x = 1, f = 0) is not below the upper line y = -x + 0.5; the data "
                   "are on or above it at x = 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, ...");

    TH_CASE("lines");
    double fl[] = {1, 1, 1, 1};
    ts_spline_options_init(&o);
    o.shape = TS_SHAPE_BETWEEN;
    o.lower.m = 1;
    o.lower.c = 0; /* y = x */
    o.upper.m = -1;
    o.upper.c = 2; /* y = -x + 2: equal at x = 1 */
    e = build(x, fl, 4, &o);
    c = spline_ctx(x, fl, 4, &o);
    CHECK(e.status == TS_ERR_LINES && e.index == 1);
    EXPECT(&e, &c, "at point 1 (x = 1) the lower line y = x (value 1) is not below the upper "
                   "line y = -x + 2 (value 1)");

    TH_CASE("unsorted");
    double xu[] = {0, 1, 1, 2}, fu[] = {1, 2, 3, 4};
    e = build(xu, fu, 4, NULL);
    c = spline_ctx(xu, fu, 4, NULL);
    CHECK(e.status == TS_ERR_UNSORTED && e.index == 2);
    EXPECT(&e, &c, "point 2 (x = 1) is not greater than the previous x = 1; x must be strictly "
                   "increasing");

    TH_CASE("nonmonotone");
    double fm[] = {0, 1, 0.5, 2};
    ts_spline_options_init(&o);
    o.shape = TS_SHAPE_MONOTONE;
    e = build(x, fm, 4, &o);
    c = spline_ctx(x, fm, 4, &o);
    CHECK(e.status == TS_ERR_NONMONOTONE && e.index == 2);
    EXPECT(&e, &c, "point 2 (x = 2, f = 0.5): the data change direction here; the monotone "
                   "shape needs monotone data");

    TH_CASE("zero slope");
    double fz[] = {1, 0, 1, 2}, d[] = {0, 0.5, 0, 0};
    ts_spline_options_init(&o);
    o.shape = TS_SHAPE_POSITIVE;
    o.slopes = TS_SLOPES_USER;
    o.user_slopes = d;
    o.n_user_slopes = 4;
    e = build(x, fz, 4, &o);
    c = spline_ctx(x, fz, 4, &o);
    CHECK(e.status == TS_ERR_ZERO_SLOPE && e.index == 1);
    EXPECT(&e, &c, "point 1 (x = 1, f = 0) touches the boundary and the user slope 0.5 there "
                   "points out of the region");

    TH_CASE("nonfinite user slope");
    double dn[] = {0, 0, TH_INF, 0};
    ts_spline_options_init(&o);
    o.slopes = TS_SLOPES_USER;
    o.user_slopes = dn;
    o.n_user_slopes = 4;
    e = build(x, fm, 4, &o);
    c = spline_ctx(x, fm, 4, &o);
    CHECK(e.status == TS_ERR_NONFINITE && e.index == 2);
    EXPECT(&e, &c, "point 2 (x = 2, f = 0.5): the user slope inf is not finite");
    double fnan[] = {0, TH_NAN, 1, 2};
    e = build(x, fnan, 4, NULL);
    c = spline_ctx(x, fnan, 4, NULL);
    CHECK(e.status == TS_ERR_NONFINITE && e.index == 1);
    EXPECT(&e, &c, "point 1 (x = 1, f = nan): x or f is NaN or infinite");

    TH_CASE("periodic");
    double fp[] = {1, 2, 3};
    ts_spline_options_init(&o);
    o.slopes = TS_SLOPES_PERIODIC;
    e = build(x, fp, 3, &o);
    c = spline_ctx(x, fp, 3, &o);
    CHECK(e.status == TS_ERR_PERIODIC);
    EXPECT(&e, &c, "periodic slopes need the last value equal to the first: f = 3 at point 2, "
                   "f = 1 at point 0");

    TH_CASE("too few");
    e = build(x, fp, 1, NULL);
    c = spline_ctx(x, fp, 1, NULL);
    CHECK(e.status == TS_ERR_TOO_FEW);
    EXPECT(&e, &c, "1 data point; at least 2 are needed");
}

static void test_spline_intervals(void)
{
    double x[] = {0, 1, 2, 3}, f[] = {1, 2, 1.5, 3};
    ts_spline_options o;

    TH_CASE("geometric bound");
    ts_spline_options_init(&o);
    o.form = TS_FORM_GEOMETRIC;
    o.alpha = 0.3;
    ts_error e = build(x, f, 4, &o);
    ts_error_context c = spline_ctx(x, f, 4, &o);
    CHECK(e.status == TS_ERR_GEOMETRIC && e.index == 0);
    EXPECT(&e, &c, "interval 0 [0, 1]: alpha + beta = 0.3 is below the geometric-form bound "
                   "0.3472; raise alpha or beta");

    TH_CASE("alpha");
    double al[] = {1, -2, 1};
    ts_spline_options_init(&o);
    o.alphas = al;
    o.n_alphas = 3;
    e = build(x, f, 4, &o);
    c = spline_ctx(x, f, 4, &o);
    CHECK(e.status == TS_ERR_ALPHA && e.index == 1);
    EXPECT(&e, &c, "interval 1 [1, 2]: alpha = -2 must be finite and > 0");

    TH_CASE("length");
    o.n_alphas = 2;
    e = build(x, f, 4, &o);
    c = spline_ctx(x, f, 4, &o);
    CHECK(e.status == TS_ERR_LENGTH);
    EXPECT(&e, &c, "alphas has 2 values, but the data have 3 intervals (one value per interval "
                   "is needed)");

    TH_CASE("infeasible, precision (error given)");
    c = spline_ctx(x, f, 4, NULL);
    ts_error inf = {TS_ERR_INFEASIBLE, 1, TS_WHERE_INTERVAL};
    EXPECT(&inf, &c, "interval 1 [1, 2]: no beta >= 0 keeps the spline inside the region on "
                     "this interval");
    ts_error prec = {TS_ERR_PRECISION, 2, TS_WHERE_INTERVAL};
    EXPECT(&prec, &c, "interval 2 [2, 3]: cannot be certified in double precision: gap below the "
                      "rounding bound");
    ts_error far = {TS_ERR_PRECISION, 3, TS_WHERE_INTERVAL}; /* beyond the data */
    EXPECT(&far, &c, "interval 3: cannot be certified in double precision: gap below the "
                     "rounding bound");

    TH_CASE("domain");
    ts_spline *s = NULL;
    CHECK(ts_spline_new(x, f, 4, NULL, &s, NULL) == TS_OK);
    double xq[] = {0.5, 7, TH_NAN}, yq[3];
    ts_error e2;
    CHECK(ts_spline_eval_batch(s, 0, xq, 3, yq, NULL, &e2) == TS_ERR_DOMAIN && e2.index == 1);
    ts_spline_free(s);
    c.queries = xq;
    c.n_queries = 3;
    EXPECT(&e2, &c, "query 1 (x = 7) lies outside [0, 3]");
    e2.index = 2;
    EXPECT(&e2, &c, "query 2 is NaN");
    c.queries = NULL;
    EXPECT(&e2, &c, "query 2: query is NaN or outside the data range");
}

static void test_surface_and_curve(void)
{
    TH_CASE("surface node");
    double gx[] = {0, 1, 2}, gy[] = {0, 1}, gz[] = {1, 2, 3, 2, 1, -1};
    ts_surface_options so;
    ts_surface_options_init(&so);
    so.shape = TS_SURFACE_POSITIVE;
    ts_surface *sf = NULL;
    ts_error e;
    CHECK(ts_surface_new(gx, 3, gy, 2, gz, &so, &sf, &e) == TS_ERR_NEGATIVE && e.index == 5);
    ts_error_context c;
    ts_error_context_init(&c);
    c.x = gx;
    c.y = gy;
    c.f = gz;
    c.n_points = 3;
    c.ny_points = 2;
    c.surface_options = &so;
    EXPECT(&e, &c, "node (2, 1) (x = 2, y = 1, z = -1) is negative; the positive shape needs "
                   "z >= 0");
    ts_error ge = {TS_ERR_GEOMETRIC, TS_NO_INDEX, TS_WHERE_NONE};
    so.alpha = 0.25;
    so.beta = 0.0625;
    EXPECT(&ge, &c, "alpha + beta = 0.3125 is below the geometric-form bound 0.3472; raise alpha "
                    "or beta");
    so.struct_size = 0; /* options of another version: not read */
    EXPECT(&ge, &c, "alpha + beta below the geometric-form bound");
    so.struct_size = sizeof so;
    /* finite data, a non-finite slope or control value: the overflow is named,
     * not the input (a z that is itself not finite keeps the library text) */
    ts_error ne = {TS_ERR_NONFINITE, 1, TS_WHERE_POINT};
    EXPECT(&ne, &c, "node (1, 0) (x = 1, y = 0, z = 2): the slopes computed at this node "
                    "overflow a double (finite values this close to the largest double; "
                    "rescale z)");
    ts_error np = {TS_ERR_NONFINITE, 0, TS_WHERE_INTERVAL};
    EXPECT(&np, &c, "patch (0, 0) [0, 1] x [0, 1]: the control values of this patch overflow "
                    "a double (finite values this close to the largest double; rescale z)");
    gz[1] = HUGE_VAL;
    EXPECT(&ne, &c, "node (1, 0) (x = 1, y = 0, z = inf): NaN or infinite value in the input");
    gz[1] = 2;
    ts_error pe = {TS_ERR_INFEASIBLE, 1, TS_WHERE_INTERVAL};
    EXPECT(&pe, &c, "patch (1, 0) [1, 2] x [0, 1]: no beta keeps this interval inside the region");
    /* first_index shifts both grid indices of nodes and patches (1-based
     * front-ends such as R name node (2, 1) as z[2, 1]) */
    c.first_index = 1;
    EXPECT(&e, &c, "node (3, 2) (x = 2, y = 1, z = -1) is negative; the positive shape needs "
                   "z >= 0");
    EXPECT(&pe, &c, "patch (2, 1) [1, 2] x [0, 1]: no beta keeps this interval inside the region");
    ts_error off = {TS_ERR_INFEASIBLE, 7, TS_WHERE_INTERVAL}; /* beyond the grid: index only */
    EXPECT(&off, &c, "interval 8: no beta keeps this interval inside the region");
    c.first_index = 0;

    TH_CASE("curve point");
    double pts[] = {0, 0, 2, 0.5, 1, 1};
    ts_curve_options co;
    ts_curve_options_init(&co);
    co.has_hi[0] = 1;
    co.hi[0] = 1.5;
    ts_curve *cv = NULL;
    CHECK(ts_curve_new(pts, 3, 2, &co, &cv, &e) == TS_ERR_SIDE && e.index == 1);
    ts_error_context_init(&c);
    c.points = pts;
    c.n_points = 3;
    c.dim = 2;
    c.curve_options = &co;
    EXPECT(&e, &c, "point 1 (2, 0.5) is outside the box");
}

static int empty_text(double x, char *buf, size_t len, void *user)
{
    (void)x;
    (void)user;
    if (len)
        buf[0] = '\0';
    return 0;
}

static int failing_text(double x, char *buf, size_t len, void *user)
{
    (void)x;
    (void)buf;
    (void)len;
    return *(const int *)user; /* -1: an error; 500: longer than the library's buffer */
}

/* Every sentence's fallbacks: a status given without the data that name its
 * cause, indices beyond the data, options of each kind.  The expected
 * sentences follow the wording rules of include/trigspline.h: the cause
 * named from the data where they are given, else "WHERE INDEX: " and the
 * status's fixed text (ts_strerror). */
static void test_sentence_paths(void)
{
    double x[] = {0, 1, 2, 3}, f[] = {1, 0.5, 2, 3};
    ts_spline_options o;
    ts_error_context c;

    TH_CASE("x formatter: empty text, an error, a text too long");
    ts_spline_options_init(&o);
    o.shape = TS_SHAPE_POSITIVE;
    double fneg[] = {1, -2, 1, 1};
    c = spline_ctx(x, fneg, 4, &o);
    ts_error ng = {TS_ERR_NEGATIVE, 1, TS_WHERE_POINT};
    c.format_x = empty_text;
    EXPECT(&ng, &c, "point 1 (x = , f = -2) is negative; the positive shape needs f >= 0 "
                    "(negative at x = )");
    int fail = -1, big = 500;
    c.format_x = failing_text;
    c.format_x_user = &fail; /* the number instead */
    EXPECT(&ng, &c, "point 1 (x = 1, f = -2) is negative; the positive shape needs f >= 0 "
                    "(negative at x = 1)");
    c.format_x_user = &big;
    EXPECT(&ng, &c, "point 1 (x = 1, f = -2) is negative; the positive shape needs f >= 0 "
                    "(negative at x = 1)");
    ts_error ngi = {TS_ERR_NEGATIVE, 0, TS_WHERE_INTERVAL}; /* not a point: generic */
    c = spline_ctx(x, fneg, 4, &o);
    EXPECT(&ngi, &c, "interval 0 [0, 1]: negative data value for the positive scheme");

    TH_CASE("lines of each kind in the side sentence");
    ts_error sd = {TS_ERR_SIDE, 1, TS_WHERE_POINT};
    ts_spline_options_init(&o);
    o.shape = TS_SHAPE_ABOVE;
    o.lower.m = 0;
    o.lower.c = 1; /* y = 1: point 1 (f = 0.5) below it; a constant line may be touched */
    c = spline_ctx(x, f, 4, &o);
    EXPECT(&sd, &c, "point 1 (x = 1, f = 0.5) is not above the lower line y = 1; the data are on "
                    "or below it at x = 1");
    o.lower.m = 2;
    o.lower.c = -1; /* y = 2x - 1: 1 at x = 1, 3 at x = 2, 5 at x = 3 */
    EXPECT(&sd, &c, "point 1 (x = 1, f = 0.5) is not above the lower line y = 2x - 1; the data "
                    "are on or below it at x = 1, 2, 3");
    o.lower.m = 1;
    o.lower.c = TH_NAN; /* NaN: every point fails */
    EXPECT(&sd, &c, "point 1 (x = 1, f = 0.5) is not above the lower line y = x + nan; the data "
                    "are on or below it at x = 0, 1, 2, 3");
    o.lower.m = -1;
    o.lower.c = 0; /* y = -x */
    EXPECT(&sd, &c, "point 1 (x = 1, f = 0.5) is not above the lower line y = -x; the data are "
                    "on or below it at x = ");
    ts_spline_options_init(&o);
    o.shape = TS_SHAPE_BETWEEN;
    o.lower.c = 0.75; /* y = 0.75, y = 2.5: point 1 below, point 3 above */
    o.upper.c = 2.5;
    c = spline_ctx(x, f, 4, &o);
    EXPECT(&sd, &c, "point 1 (x = 1, f = 0.5) is not above the lower line y = 0.75; the data are "
                    "on or below it at x = 1");
    sd.index = 3;
    EXPECT(&sd, &c, "point 3 (x = 3, f = 3) is not below the upper line y = 2.5; the data are on "
                    "or above it at x = 3");
    o.shape = TS_SHAPE_POSITIVE; /* no line: generic */
    EXPECT(&sd, &c, "point 3 (x = 3, f = 3): a data point lies on or across a constraint line");

    TH_CASE("point statuses without a point");
    c = spline_ctx(x, f, 4, NULL);
    ts_status pst[] = {TS_ERR_UNSORTED, TS_ERR_NONFINITE, TS_ERR_WIDTH, TS_ERR_NEGATIVE,
                       TS_ERR_SIDE, TS_ERR_LINES, TS_ERR_NONMONOTONE, TS_ERR_ZERO_SLOPE};
    for (size_t k = 0; k < sizeof pst / sizeof pst[0]; k++) {
        ts_error none = {pst[k], TS_NO_INDEX, TS_WHERE_NONE};
        EXPECT(&none, &c, ts_strerror(pst[k]));
        ts_error beyond = {pst[k], 9, TS_WHERE_POINT}; /* beyond the 4 points */
        char want[200];
        snprintf(want, sizeof want, "point 9: %s", ts_strerror(pst[k]));
        EXPECT(&beyond, &c, want);
    }
    ts_error first = {TS_ERR_UNSORTED, 0, TS_WHERE_POINT}; /* no previous point */
    EXPECT(&first, &c, "point 0 (x = 0, f = 1): x values are not strictly increasing (unsorted "
                       "or duplicate)");
    ts_error wfirst = {TS_ERR_WIDTH, 0, TS_WHERE_POINT};
    EXPECT(&wfirst, &c, "point 0 (x = 0, f = 1): an interval width overflows, or underflows below "
                        "the smallest normal double");

    TH_CASE("too few, without the data or with none");
    ts_error tf = {TS_ERR_TOO_FEW, TS_NO_INDEX, TS_WHERE_NONE};
    EXPECT(&tf, NULL, "too few points: at least 2 are needed");
    ts_error_context_init(&c);
    c.n_points = 1; /* a count without the arrays */
    EXPECT(&tf, &c, "1 data point; at least 2 are needed");
    c = spline_ctx(x, f, 0, NULL);
    EXPECT(&tf, &c, "0 data points; at least 2 are needed");

    TH_CASE("width: underflow and overflow");
    double xw[] = {0, 1e-310, 1}, fw[] = {1, 1, 1};
    c = spline_ctx(xw, fw, 3, NULL);
    ts_error wu = {TS_ERR_WIDTH, 1, TS_WHERE_POINT};
    EXPECT(&wu, &c, "point 1 (x = 1e-310): the step 1e-310 from the previous x = 0 underflows: "
                    "steps below 2.2250738585072014e-308 (the smallest normal double) are "
                    "refused");
    ts_error wue = build(xw, fw, 3, NULL);
    CHECK(wue.status == TS_ERR_WIDTH && wue.index == 1 && wue.where == TS_WHERE_POINT);
    double xo[] = {-1e308, 1e308}, fo[] = {1, 1};
    c = spline_ctx(xo, fo, 2, NULL);
    EXPECT(&wu, &c, "point 1 (x = 1e+308): the step inf from the previous x = -1e+308 overflows "
                    "a double");
    ts_error woe = build(xo, fo, 2, NULL);
    CHECK(woe.status == TS_ERR_WIDTH && woe.index == 1);

    TH_CASE("nonfinite: x, slopes, and the step");
    double xi[] = {0, TH_INF, 2, 3};
    c = spline_ctx(xi, f, 4, NULL);
    ts_error nf = {TS_ERR_NONFINITE, 1, TS_WHERE_POINT};
    EXPECT(&nf, &c, "point 1 (x = inf, f = 0.5): x or f is NaN or infinite");
    ts_spline_options_init(&o);
    o.slopes = TS_SLOPES_USER; /* the slopes not given, or fewer, or finite: the step */
    c = spline_ctx(x, f, 4, &o);
    EXPECT(&nf, &c, "point 1 (x = 1, f = 0.5): the step from the previous point, or a slope "
                    "there, overflows a double");
    double us[] = {0, 1, 0, 0};
    o.user_slopes = us;
    o.n_user_slopes = 1;
    EXPECT(&nf, &c, "point 1 (x = 1, f = 0.5): the step from the previous point, or a slope "
                    "there, overflows a double");
    o.n_user_slopes = 4;
    EXPECT(&nf, &c, "point 1 (x = 1, f = 0.5): the step from the previous point, or a slope "
                    "there, overflows a double");
    ts_error nfn = {TS_ERR_NONFINITE, TS_NO_INDEX, TS_WHERE_NONE};
    EXPECT(&nfn, &c, "NaN or infinite value in the input");

    TH_CASE("periodic without data");
    ts_error pe = {TS_ERR_PERIODIC, TS_NO_INDEX, TS_WHERE_NONE};
    EXPECT(&pe, NULL, "periodic slopes need the first and last values equal");

    TH_CASE("zero slope without the slopes");
    ts_error zs = {TS_ERR_ZERO_SLOPE, 1, TS_WHERE_POINT};
    c = spline_ctx(x, f, 4, NULL);
    EXPECT(&zs, &c, "point 1 (x = 1, f = 0.5) touches the boundary and the user slope there "
                    "points out of the region");
    ts_spline_options_init(&o);
    o.slopes = TS_SLOPES_USER;
    o.user_slopes = us;
    o.n_user_slopes = 1; /* fewer than the index */
    c = spline_ctx(x, f, 4, &o);
    EXPECT(&zs, &c, "point 1 (x = 1, f = 0.5) touches the boundary and the user slope there "
                    "points out of the region");

    TH_CASE("alpha, beta, margin: per interval, beyond the arrays, without the data");
    ts_spline_options_init(&o);
    double al[] = {1, 2};
    o.alphas = al;
    o.n_alphas = 2; /* interval 2 is beyond: the scalar alpha */
    o.alpha = 0.5;
    o.beta = -1;
    o.margin = 0;
    c = spline_ctx(x, f, 4, &o);
    ts_error ea = {TS_ERR_ALPHA, 2, TS_WHERE_INTERVAL};
    EXPECT(&ea, &c, "interval 2 [2, 3]: alpha = 0.5 must be finite and > 0");
    ts_error eb = {TS_ERR_BETA, 1, TS_WHERE_INTERVAL};
    EXPECT(&eb, &c, "interval 1 [1, 2]: beta = -1 must be finite and >= 0, and alpha + beta = 1 "
                    "finite and > 0");
    ts_error em = {TS_ERR_MARGIN, 0, TS_WHERE_INTERVAL};
    EXPECT(&em, &c, "interval 0 [0, 1]: the margin t = 0 must be finite and > 0");
    ts_error_context_init(&c);
    c.spline_options = &o; /* no data: the index alone */
    EXPECT(&eb, &c, "interval 1: beta = -1 must be finite and >= 0, and alpha + beta = 1 finite "
                    "and > 0");
    ts_error en = {TS_ERR_MARGIN, TS_NO_INDEX, TS_WHERE_NONE};
    EXPECT(&en, &c, "the margin t = 0 must be finite and > 0");

    TH_CASE("length: each array, plurals, none wrong");
    double x2[] = {0, 1}, f2[] = {1, 1}, one[] = {1, 1, 1};
    ts_error le = {TS_ERR_LENGTH, TS_NO_INDEX, TS_WHERE_NONE};
    ts_spline_options_init(&o);
    o.slopes = TS_SLOPES_USER;
    o.user_slopes = one;
    o.n_user_slopes = 3;
    c = spline_ctx(x2, f2, 2, &o);
    EXPECT(&le, &c, "the user slopes have 3 values, but the data have 2 points (one slope per "
                    "point is needed)");
    o.n_user_slopes = 2;
    o.betas = one;
    o.n_betas = 3;
    EXPECT(&le, &c, "betas has 3 values, but the data have 1 interval (one value per interval is "
                    "needed)");
    o.n_betas = 1;
    o.margins = one;
    o.n_margins = 1; /* right */
    o.alphas = one;
    o.n_alphas = 1;
    EXPECT(&le, &c, "a per-interval or per-point array has the wrong length");
    o.n_margins = 2;
    EXPECT(&le, &c, "margins has 2 values, but the data have 1 interval (one value per interval "
                    "is needed)");
    c = spline_ctx(x, f, 4, &o);
    o.slopes = TS_SLOPES_GEOMETRIC;
    o.n_alphas = 1;
    EXPECT(&le, &c, "alphas has 1 value, but the data have 3 intervals (one value per interval is "
                    "needed)");
    EXPECT(&le, NULL, "a per-interval or per-point array has the wrong length");

    TH_CASE("geometric and control overflow; infeasible without an interval");
    ts_spline_options_init(&o);
    o.alpha = 0.25;
    c = spline_ctx(x, f, 4, &o);
    ts_error ge = {TS_ERR_GEOMETRIC, TS_NO_INDEX, TS_WHERE_NONE};
    EXPECT(&ge, &c, "alpha + beta = 0.25 is below the geometric-form bound 0.3472; raise alpha "
                    "or beta");
    ts_error co = {TS_ERR_CONTROL_OVERFLOW, 2, TS_WHERE_INTERVAL};
    EXPECT(&co, &c, "interval 2 [2, 3]: alpha + beta = 0.25 is too small for the slopes: the "
                    "control values overflow");
    ts_error inf = {TS_ERR_INFEASIBLE, TS_NO_INDEX, TS_WHERE_NONE};
    EXPECT(&inf, &c, "no beta keeps this interval inside the region");

    TH_CASE("spline options of another version are not read");
    ts_spline_options_init(&o);
    o.alpha = 7;
    o.struct_size = 4;
    c = spline_ctx(x, f, 4, &o);
    ts_error al0 = {TS_ERR_ALPHA, TS_NO_INDEX, TS_WHERE_NONE};
    char want[160];
    ts_spline_options def;
    ts_spline_options_init(&def);
    char a[TS__NUM_SIZE];
    ts__format_double(def.alpha, a);
    snprintf(want, sizeof want, "alpha = %s must be finite and > 0", a);
    EXPECT(&al0, &c, want);

    TH_CASE("data without f: the generic form");
    ts_error_context_init(&c);
    c.x = x;
    c.n_points = 4; /* f missing: no point is named */
    EXPECT(&ng, &c, "point 1: negative data value for the positive scheme");

    TH_CASE("queries: beyond, infinite, without a data range, on a surface");
    double q[] = {TH_INF, 5};
    c = spline_ctx(x, f, 4, NULL);
    c.queries = q;
    c.n_queries = 2;
    ts_error qd = {TS_ERR_DOMAIN, 0, TS_WHERE_QUERY};
    EXPECT(&qd, &c, "query 0 (x = inf) is infinite");
    qd.index = 5; /* beyond the queries */
    EXPECT(&qd, &c, "query 5: query is NaN or outside the data range");
    qd.index = 1;
    c = spline_ctx(x, f, 1, NULL);
    c.queries = q;
    c.n_queries = 2;
    EXPECT(&qd, &c, "query 1 (x = 5) lies outside the data");
    double gy[] = {0, 1};
    c.y = gy;
    c.n_points = 4;
    EXPECT(&qd, &c, "query 1 (x = 5) lies outside the data");
    ts_error qn = {TS_ERR_NONFINITE, 0, TS_WHERE_QUERY}; /* not a domain error */
    c = spline_ctx(x, f, 4, NULL);
    EXPECT(&qn, &c, "query 0: NaN or infinite value in the input");
}

static void test_surface_paths(void)
{
    double gx[] = {0, 1, 2}, gy[] = {0, 1}, gz[] = {1, 2, 3, 2, 1, 0};
    ts_error_context c;

    TH_CASE("surface places without coordinates or values");
    ts_error_context_init(&c);
    c.y = gy; /* a surface context: y given */
    c.n_points = 3;
    c.ny_points = 2;
    ts_error np = {TS_ERR_NEGATIVE, 4, TS_WHERE_POINT}; /* no z: the generic sentence */
    EXPECT(&np, &c, "node (1, 1): negative data value for the positive scheme");
    c.x = gx;
    EXPECT(&np, &c, "node (1, 1) (x = 1, y = 1): negative data value for the positive scheme");
    ts_error pt = {TS_ERR_INFEASIBLE, 1, TS_WHERE_INTERVAL};
    EXPECT(&pt, &c, "patch (1, 0) [1, 2] x [0, 1]: no beta keeps this interval inside the region");
    c.x = NULL;
    EXPECT(&pt, &c, "patch (1, 0): no beta keeps this interval inside the region");
    ts_error far = {TS_ERR_INFEASIBLE, 2, TS_WHERE_INTERVAL}; /* beyond the 2 patches */
    EXPECT(&far, &c, "interval 2: no beta keeps this interval inside the region");
    ts_error nfar = {TS_ERR_NEGATIVE, 6, TS_WHERE_POINT}; /* beyond the 6 nodes */
    EXPECT(&nfar, &c, "point 6: negative data value for the positive scheme");
    c.n_points = 0;
    EXPECT(&np, &c, "point 4: negative data value for the positive scheme");
    c.n_points = 1;
    c.ny_points = 1; /* one column: no patch */
    EXPECT(&pt, &c, "interval 1: no beta keeps this interval inside the region");
    ts_error none = {TS_ERR_NOMEM, TS_NO_INDEX, TS_WHERE_NONE};
    EXPECT(&none, &c, "out of memory");
    ts_error nidx = {TS_ERR_NOMEM, TS_NO_INDEX, TS_WHERE_POINT};
    EXPECT(&nidx, &c, "out of memory");

    TH_CASE("surface: negative at a patch, geometric without options, nonfinite cases");
    ts_error_context_init(&c);
    c.x = gx;
    c.y = gy;
    c.f = gz;
    c.n_points = 3;
    c.ny_points = 2;
    ts_error ni = {TS_ERR_NEGATIVE, 0, TS_WHERE_INTERVAL};
    EXPECT(&ni, &c, "patch (0, 0) [0, 1] x [0, 1]: negative data value for the positive scheme");
    ts_error ge = {TS_ERR_GEOMETRIC, TS_NO_INDEX, TS_WHERE_NONE};
    EXPECT(&ge, &c, "alpha + beta below the geometric-form bound");
    ts_error nn = {TS_ERR_NONFINITE, TS_NO_INDEX, TS_WHERE_NONE};
    EXPECT(&nn, &c, "NaN or infinite value in the input");
    ts_error nb = {TS_ERR_NONFINITE, 6, TS_WHERE_POINT}; /* beyond the nodes */
    EXPECT(&nb, &c, "point 6: NaN or infinite value in the input");
    c.y = NULL;
    ts_surface_options so;
    ts_surface_options_init(&so);
    c.surface_options = &so; /* options alone make it a surface context */
    ts_error n1 = {TS_ERR_NONFINITE, 1, TS_WHERE_POINT};
    EXPECT(&n1, &c, "node (1, 0): NaN or infinite value in the input");
    c.x = NULL;
    c.y = gy;
    EXPECT(&n1, &c, "node (1, 0): NaN or infinite value in the input");
    c.x = gx;
    c.f = NULL;
    EXPECT(&n1, &c, "node (1, 0) (x = 1, y = 0): NaN or infinite value in the input");

    TH_CASE("curve places");
    double p1[] = {0, 1, 2, 3}, p4[] = {0, 1, 2, 3, 4, 5, 6, 7};
    ts_error_context_init(&c);
    c.points = p4;
    c.n_points = 2;
    c.dim = 4; /* not 2 or 3: no coordinates */
    ts_error cp = {TS_ERR_NONFINITE, 1, TS_WHERE_POINT};
    EXPECT(&cp, &c, "point 1: NaN or infinite value in the input");
    c.dim = 1;
    c.points = p1;
    EXPECT(&cp, &c, "point 1: NaN or infinite value in the input");
    c.dim = 2;
    EXPECT(&cp, &c, "point 1 (2, 3): NaN or infinite value in the input");
    ts_error cu = {TS_ERR_UNSORTED, 1, TS_WHERE_POINT};
    EXPECT(&cu, &c, "point 1 (2, 3) repeats the previous point (or its parameter step is lost to "
                    "rounding)");
    ts_error cb = {TS_ERR_NONFINITE, 2, TS_WHERE_POINT}; /* beyond the points */
    EXPECT(&cb, &c, "point 2: NaN or infinite value in the input");
    ts_error cs = {TS_ERR_INFEASIBLE, 0, TS_WHERE_INTERVAL};
    c.first_index = 10;
    EXPECT(&cs, &c, "segment 10: no beta keeps this interval inside the region");
    ts_error cn = {TS_ERR_INFEASIBLE, TS_NO_INDEX, TS_WHERE_INTERVAL};
    EXPECT(&cn, &c, "no beta keeps this interval inside the region");
    ts_error cq = {TS_ERR_DOMAIN, 3, TS_WHERE_QUERY}; /* no queries given */
    EXPECT(&cq, &c, "query 13: query is NaN or outside the data range");
    ts_error cqn = {TS_ERR_DOMAIN, TS_NO_INDEX, TS_WHERE_QUERY};
    EXPECT(&cqn, &c, "query is NaN or outside the data range");
    ts_curve_options co;
    ts_curve_options_init(&co);
    ts_error_context_init(&c);
    c.curve_options = &co; /* options alone make it a curve context */
    ts_error cd = {TS_ERR_DIMENSION, TS_NO_INDEX, TS_WHERE_NONE};
    EXPECT(&cd, &c, "curve dimension must be 2 or 3");
}

static void test_more_paths(void)
{
    double x[] = {0, 1, 2}, f[] = {1, 2, 3};
    ts_error_context c;
    ts_spline_options o;

    TH_CASE("nonfinite at a finite point without user slopes");
    c = spline_ctx(x, f, 3, NULL);
    ts_error nf = {TS_ERR_NONFINITE, 1, TS_WHERE_POINT};
    EXPECT(&nf, &c, "point 1 (x = 1, f = 2): the step from the previous point, or a slope "
                    "there, overflows a double");

    TH_CASE("length: betas or margins alone");
    double v[] = {1, 1, 1};
    ts_error le = {TS_ERR_LENGTH, TS_NO_INDEX, TS_WHERE_NONE};
    ts_spline_options_init(&o);
    o.margins = v;
    o.n_margins = 3;
    c = spline_ctx(x, f, 3, &o);
    EXPECT(&le, &c, "margins has 3 values, but the data have 2 intervals (one value per interval "
                    "is needed)");
    o.betas = v;
    o.n_betas = 2;
    o.n_margins = 2;
    EXPECT(&le, &c, "a per-interval or per-point array has the wrong length");
    c = spline_ctx(x, f, 3, NULL); /* no array at all: no length to name */
    EXPECT(&le, &c, "a per-interval or per-point array has the wrong length");

    TH_CASE("generic places of a spline without data");
    ts_error_context_init(&c);
    ts_error pr = {TS_ERR_PRECISION, 1, TS_WHERE_INTERVAL};
    EXPECT(&pr, &c, "interval 1: cannot be certified in double precision: gap below the "
                    "rounding bound");
    ts_error pn = {TS_ERR_PRECISION, TS_NO_INDEX, TS_WHERE_POINT};
    EXPECT(&pn, &c, "cannot be certified in double precision: gap below the rounding bound");

    TH_CASE("query without the data's x");
    double q[] = {5};
    c.queries = q;
    c.n_queries = 1;
    c.n_points = 3;
    ts_error qd = {TS_ERR_DOMAIN, 0, TS_WHERE_QUERY};
    EXPECT(&qd, &c, "query 0 (x = 5) lies outside the data");

    TH_CASE("surface patches: one row of nodes, x without y");
    ts_surface_options so;
    ts_surface_options_init(&so);
    ts_error_context_init(&c);
    c.surface_options = &so;
    c.x = x;
    c.n_points = 3;
    c.ny_points = 1; /* no patch */
    ts_error pt = {TS_ERR_INFEASIBLE, 0, TS_WHERE_INTERVAL};
    EXPECT(&pt, &c, "interval 0: no beta keeps this interval inside the region");
    c.ny_points = 2; /* a patch, y not given */
    EXPECT(&pt, &c, "patch (0, 0): no beta keeps this interval inside the region");

    TH_CASE("curve: a point without the points, a 3-D point");
    ts_curve_options co;
    ts_curve_options_init(&co);
    ts_error_context_init(&c);
    c.curve_options = &co;
    c.n_points = 2;
    c.dim = 3;
    ts_error cp = {TS_ERR_NONFINITE, 1, TS_WHERE_POINT};
    EXPECT(&cp, &c, "point 1: NaN or infinite value in the input");
    double p3[] = {0, 1, 2, 3, 4, 5};
    c.points = p3;
    EXPECT(&cp, &c, "point 1 (3, 4, 5): NaN or infinite value in the input");
}

static void test_buffers(void)
{
    TH_CASE("snprintf behaviour");
    ts_error e = {TS_ERR_SIDE, TS_NO_INDEX, TS_WHERE_NONE};
    const char *want = "a data point lies on or across a constraint line";
    size_t n = strlen(want);
    CHECK(ts_error_message(&e, NULL, NULL, 0) == n);
    char *b = malloc(n + 1);
    CHECK(b != NULL);
    if (b) {
        CHECK(ts_error_message(&e, NULL, b, n + 1) == n && strcmp(b, want) == 0);
        free(b);
    }
    for (size_t len = 1; len <= n; len++) {
        char *t = malloc(len); /* exactly len bytes: ASan sees any overrun */
        CHECK(t != NULL);
        if (!t)
            break;
        memset(t, 'Z', len);
        CHECKF(ts_error_message(&e, NULL, t, len) == n && strlen(t) == len - 1 &&
                   strncmp(t, want, len - 1) == 0,
               "len %zu", len);
        free(t);
    }
    char one = 'Z';
    CHECK(ts_error_message(&e, NULL, &one, 0) == n && one == 'Z'); /* len 0: nothing written */
    /* a long sentence truncated in the middle of a number */
    double x[] = {0, 1}, f[] = {-0.30000000000000004, 1};
    ts_spline_options o;
    ts_spline_options_init(&o);
    o.shape = TS_SHAPE_POSITIVE;
    ts_error_context c = spline_ctx(x, f, 2, &o);
    ts_error ne = {TS_ERR_NEGATIVE, 0, TS_WHERE_POINT};
    size_t full = ts_error_message(&ne, &c, NULL, 0);
    char small[24];
    CHECK(ts_error_message(&ne, &c, small, sizeof small) == full && full > sizeof small &&
          strcmp(small, "point 0 (x = 0, f = -0.") == 0);

    TH_CASE("NULL error, no context, foreign context");
    EXPECT(NULL, NULL, "a required pointer argument is NULL");
    ts_error pt = {TS_ERR_TOO_LARGE, 4, TS_WHERE_POINT};
    EXPECT(&pt, NULL, "point 4: a data or control value exceeds DBL_MAX/4: the spline could "
                      "overflow");
    ts_error ok = {TS_OK, TS_NO_INDEX, TS_WHERE_NONE};
    EXPECT(&ok, NULL, "success");
    ts_error_context_init(&c);
    c.struct_size = 8;
    c.x = x; /* not read */
    EXPECT(&pt, &c, "point 4: a data or control value exceeds DBL_MAX/4: the spline could "
                    "overflow (error context of another version ignored)");
    ts_error odd = {TS_ERR_INDEX, 7, (ts_where)9}; /* a where out of range */
    EXPECT(&odd, NULL, "index 7: index out of range");
    ts_error_context_init(NULL); /* no-op */
}

/* ts_histo_new's statuses, each provoked with small bins. */
static ts_error histo_build(const double *e, const double *t, size_t n, const ts_histo_options *o)
{
    ts_error err;
    ts_histo *h = NULL;
    ts_status st = ts_histo_new(e, t, n, o, &h, &err);
    ts_histo_free(h);
    CHECK(st == err.status && st != TS_OK && h == NULL);
    return err;
}

static void expect_histo(const double *e, const double *t, size_t n, const ts_histo_options *o,
                         const char *want)
{
    ts_histo_options dflt;
    ts_histo_options_init(&dflt);
    ts_error err = histo_build(e, t, n, o);
    ts_error_context c;
    ts_error_context_init(&c);
    c.x = e;
    c.f = t;
    c.n_points = n + 1;
    c.histo_options = o ? o : &dflt;
    EXPECT(&err, &c, want);
}

static void test_histo(void)
{
    TH_CASE("histogram bins and edges");
    ts_histo_options o;
    {
        const double e[] = {0, 1, 2, 3, 4}, t[] = {1, 2, -2, 1};
        expect_histo(e, t, 4, NULL, "bin 2 [2, 3]: total -2 is negative; totals must be >= 0");
    }
    {
        const double e[] = {0, 1, 2, 2, 3}, t[] = {1, 1, 1, 1};
        expect_histo(e, t, 4, NULL,
                     "edge 3 (x = 2) is not greater than the previous edge 2; edges must be "
                     "strictly increasing");
    }
    {
        const double e[] = {0, 1, (double)NAN, 3}, t[] = {1, 1, 1};
        expect_histo(e, t, 3, NULL, "edge 2 (x = nan) is NaN or infinite");
    }
    {
        const double e[] = {0, 1, 2}, t[] = {1, HUGE_VAL};
        expect_histo(e, t, 2, NULL, "bin 1 [1, 2]: total inf is NaN or infinite");
    }
    {
        const double e[] = {0, 1e-310}, t[] = {0};
        expect_histo(e, t, 1, NULL,
                     "bin 0 [0, 1e-310]: the width 1e-310 is below the smallest normal double");
    }
    {
        const double e[] = {-1e308, 1e308}, t[] = {0};
        expect_histo(e, t, 1, NULL, "bin 0 [-1e+308, 1e+308]: the width inf overflows a double");
    }
    {
        /* 1e308 over width 1: beyond the mean limit 2^1019 ~ 5.6e306 */
        const double e[] = {0, 1}, t[] = {1e308};
        expect_histo(e, t, 1, NULL,
                     "bin 0 [0, 1]: total 1e+308 gives the mean 1e+308, too large in magnitude");
    }
    {
        /* the mean 0 is fine; lo w = -1e600 is not (the header's second
         * case of TS_ERR_TOO_LARGE) */
        const double e[] = {0, 1, 1e300}, t[] = {0, 0};
        ts_histo_options_init(&o);
        o.lo = -1e300;
        expect_histo(e, t, 2, &o,
                     "bin 1 [1, 1e+300]: total 0 over the width 1e+300: the integral of the "
                     "rates (the lower bound -1e+300 times the width included) overflows a "
                     "double");
    }
    {
        const double e[] = {0, 1, 2}, t[] = {0.5, 4};
        ts_histo_options_init(&o);
        o.hi = 1;
        /* width 2: mean 2 */
        const double e2[] = {0, 1, 3};
        expect_histo(e2, t, 2, &o,
                     "bin 1 [1, 3]: total 4 gives the mean 2, outside the rate bounds [0, 1]");
        /* means 0 and 1 with H = 1: the edge value must be <= 2*0 and >= 2*1 - 1 (§12.4) */
        const double t2[] = {0, 1};
        expect_histo(e, t2, 2, &o,
                     "bin 0 [0, 1] and bin 1 [1, 2]: the means 0 and 1 are too far apart to "
                     "be joined inside the rate bounds [0, 1]");
    }
    {
        const double e[] = {0, 1}, t[] = {1};
        ts_histo_options_init(&o);
        o.alpha = -1;
        expect_histo(e, t, 1, &o, "alpha = -1 must be finite and > 0");
        ts_histo_options_init(&o);
        o.lo = 1;
        o.hi = 0;
        expect_histo(e, t, 1, &o, "the rate bounds lo = 1, hi = 0 need lo finite and lo < hi");
        expect_histo(e, t, 0, NULL, "0 bins; at least 1 is needed");
    }
    {
        /* first_index, and a status without a histogram sentence: the index only */
        const double e[] = {0, 1, 2, 3, 4}, t[] = {1, 2, -2, 1};
        ts_histo_options_init(&o);
        ts_error err = histo_build(e, t, 4, NULL);
        ts_error_context c;
        ts_error_context_init(&c);
        c.x = e;
        c.f = t;
        c.n_points = 5;
        c.histo_options = &o;
        c.first_index = 10;
        EXPECT(&err, &c, "bin 12 [2, 3]: total -2 is negative; totals must be >= 0");
        c.x = NULL;
        EXPECT(&err, &c, "bin 12: negative data value for the positive scheme");
        ts_error nomem = {TS_ERR_NOMEM, TS_NO_INDEX, TS_WHERE_NONE};
        c.x = e;
        EXPECT(&nomem, &c, "out of memory");
        o.struct_size = 1; /* options of another version: their values are not read */
        ts_error alpha = {TS_ERR_ALPHA, TS_NO_INDEX, TS_WHERE_NONE};
        char want[256];
        snprintf(want, sizeof want, "%s", ts_strerror(TS_ERR_ALPHA));
        EXPECT(&alpha, &c, want);
    }
}

int main(void)
{
    test_histo();
    test_numbers();
    test_spline_points();
    test_spline_intervals();
    test_surface_and_curve();
    test_sentence_paths();
    test_surface_paths();
    test_more_paths();
    test_buffers();
    return th_report("error_message");
}
