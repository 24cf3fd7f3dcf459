/* The vocabulary (src/vocab.c): every value of every vocabulary round-trips
 * through its name, unknown names and out-of-range values are refused, NULL
 * arguments are refused.  Expected spellings are written out here from the
 * contract (include/trigspline.h), not read from the library. */
#include "internal.h"
#include "th.h"

#include <string.h>

static void check_list(ts_vocab v, const char *const *expect, int n, const char *what)
{
    TH_CASE(what);
    CHECKF(ts_vocab_count(v) == n, "%s: count %d, expected %d", what, ts_vocab_count(v), n);
    for (int i = 0; i < n; i++) {
        const char *s = ts_vocab_name(v, i);
        CHECKF(s && strcmp(s, expect[i]) == 0, "%s %d: \"%s\", expected \"%s\"", what, i,
               s ? s : "(null)", expect[i]);
        int back = -7;
        CHECKF(ts_vocab_value(v, expect[i], &back) == TS_OK && back == i,
               "%s \"%s\" -> %d, expected %d", what, expect[i], back, i);
    }
    CHECK(ts_vocab_name(v, n) == NULL);
    CHECK(ts_vocab_name(v, -1) == NULL);
    CHECK(ts_vocab_name(v, 1 << 30) == NULL);
    int back = 5;
    CHECK(ts_vocab_value(v, "no-such-name", &back) == TS_ERR_OPTION && back == -1);
    back = 5;
    CHECK(ts_vocab_value(v, "", &back) == TS_ERR_OPTION && back == -1);
    /* case matters: one spelling per value (every letter's case flipped) */
    char flipped[64];
    size_t len = strlen(expect[0]);
    CHECK(len < sizeof flipped);
    for (size_t k = 0; k <= len && k < sizeof flipped; k++) {
        char c = expect[0][k];
        flipped[k] = (c >= 'a' && c <= 'z') ? (char)(c - 'a' + 'A')
                     : (c >= 'A' && c <= 'Z') ? (char)(c - 'A' + 'a') : c;
    }
    CHECK(ts_vocab_value(v, flipped, &back) == TS_ERR_OPTION && back == -1);
}

int main(void)
{
    static const char *const status[] = {
        "TS_OK", "TS_ERR_NULL", "TS_ERR_NOMEM", "TS_ERR_OVERFLOW", "TS_ERR_TOO_FEW",
        "TS_ERR_NONFINITE", "TS_ERR_UNSORTED", "TS_ERR_ALPHA", "TS_ERR_BETA", "TS_ERR_MARGIN",
        "TS_ERR_LENGTH", "TS_ERR_OPTION", "TS_ERR_PERIODIC", "TS_ERR_DOMAIN", "TS_ERR_NEGATIVE",
        "TS_ERR_SIDE", "TS_ERR_LINES", "TS_ERR_NONMONOTONE", "TS_ERR_INFEASIBLE",
        "TS_ERR_VIOLATED", "TS_ERR_GEOMETRIC", "TS_ERR_DIMENSION", "TS_ERR_INDEX",
        "TS_ERR_ZERO_SLOPE", "TS_ERR_SLOPE_OVERFLOW", "TS_ERR_TOO_LARGE",
        "TS_ERR_CONTROL_OVERFLOW", "TS_ERR_WIDTH", "TS_ERR_PRECISION", "TS_ERR_UNPROVEN",
        "TS_ERR_VERSION", "TS_ERR_CONDITION", "TS_ERR_BOUND_GRID"};
    static const char *const form[] = {"paper", "c1", "geometric"};
    static const char *const slopes[] = {"arithmetic", "geometric", "harmonic", "fritsch-carlson",
                                         "akima", "makima", "user", "periodic", "steffen"};
    static const char *const shape[] = {"none", "positive", "above", "below", "between",
                                        "monotone"};
    static const char *const extrap[] = {"error", "clamp", "extend", "linear"};
    static const char *const param[] = {"centripetal", "chord", "uniform"};
    static const char *const sshape[] = {"none", "positive", "bounds", "planes", "range", "grids"};
    static const char *const term[] = {"user", "margin", "lower-left", "lower-right",
                                       "upper-left", "upper-right", "monotone", "certify",
                                       "geometric"};
    static const char *const where[] = {"none", "point", "interval", "query"};
    static const char *const constraint[] = {"convex", "concave", "increasing", "decreasing",
                                             "lower", "upper", "slope-min", "slope-max",
                                             "slope-abs"};
    static const char *const bound[] = {"constant", "polyline", "spline"};
    static const char *const condition[] = {"none", "convex-data", "concave-data",
                                            "monotone-data", "inside-bound", "secant-slope",
                                            "slope-conflict", "unproven", "touch-corner",
                                            "curvature-slope"};
#define LIST(v, a) check_list(v, a, (int)(sizeof(a) / sizeof((a)[0])), #v)
    LIST(TS_VOCAB_STATUS, status);
    LIST(TS_VOCAB_FORM, form);
    LIST(TS_VOCAB_SLOPES, slopes);
    LIST(TS_VOCAB_SHAPE, shape);
    LIST(TS_VOCAB_EXTRAP, extrap);
    LIST(TS_VOCAB_PARAM, param);
    LIST(TS_VOCAB_SURFACE_SHAPE, sshape);
    LIST(TS_VOCAB_TERM, term);
    LIST(TS_VOCAB_WHERE, where);
    LIST(TS_VOCAB_CONSTRAINT, constraint);
    LIST(TS_VOCAB_BOUND, bound);
    LIST(TS_VOCAB_CONDITION, condition);

    TH_CASE("enum values are the indices");
    int v = -1;
    CHECK(ts_vocab_value(TS_VOCAB_SLOPES, "fritsch-carlson", &v) == TS_OK &&
          v == (int)TS_SLOPES_FRITSCH_CARLSON);
    CHECK(ts_vocab_value(TS_VOCAB_TERM, "upper-right", &v) == TS_OK && v == (int)TS_TERM_UPPER_RIGHT);
    CHECK(ts_vocab_value(TS_VOCAB_SURFACE_SHAPE, "range", &v) == TS_OK && v == (int)TS_SURFACE_RANGE);
    CHECK(ts_vocab_value(TS_VOCAB_STATUS, "TS_ERR_SIDE", &v) == TS_OK && v == (int)TS_ERR_SIDE);
    /* underscores are not an alternative spelling */
    CHECK(ts_vocab_value(TS_VOCAB_SLOPES, "fritsch_carlson", &v) == TS_ERR_OPTION && v == -1);

    TH_CASE("vocabulary out of range");
    CHECK(ts_vocab_count(TS_VOCAB_COUNT_) == 0);
    CHECK(ts_vocab_count((ts_vocab)-1) == 0);
    CHECK(ts_vocab_name(TS_VOCAB_COUNT_, 0) == NULL);
    CHECK(ts_vocab_name((ts_vocab)-1, 0) == NULL);
    v = 3;
    CHECK(ts_vocab_value(TS_VOCAB_COUNT_, "paper", &v) == TS_ERR_OPTION && v == -1);

    TH_CASE("NULL arguments");
    v = 3;
    CHECK(ts_vocab_value(TS_VOCAB_FORM, NULL, &v) == TS_ERR_NULL && v == -1);
    CHECK(ts_vocab_value(TS_VOCAB_FORM, "paper", NULL) == TS_ERR_NULL);
    CHECK(ts_vocab_value(TS_VOCAB_FORM, NULL, NULL) == TS_ERR_NULL);

    TH_CASE("ts_status_name");
    for (int s = 0; s < TS_STATUS_COUNT_; s++)
        CHECKF(strcmp(ts_status_name((ts_status)s), status[s]) == 0, "status %d", s);
    CHECK(strcmp(ts_status_name(TS_STATUS_COUNT_), "TS_STATUS_UNKNOWN") == 0);
    CHECK(strcmp(ts_status_name((ts_status)-1), "TS_STATUS_UNKNOWN") == 0);
    CHECK(strcmp(ts_status_name((ts_status)1000), "TS_STATUS_UNKNOWN") == 0);
    CHECK(ts__status_name(TS_ERR_NULL) == ts_status_name(TS_ERR_NULL));
    CHECK(ts__vocab_name(TS_VOCAB_FORM, 2) == ts_vocab_name(TS_VOCAB_FORM, 2));
    return th_report("vocab");
}
