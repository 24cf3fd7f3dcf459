/* A 0.1 program: the old names (include/trigspline.h, "Deprecated names").
 * tests/test_deprecated_names.py compiles it, expects one deprecation warning
 * per old name, and runs it: the old names give the new names' results bit
 * for bit.  Prints "deprecated_use: N passed, M failed". */
#include <stdio.h>
#include <string.h>

#include "trigspline.h"

int main(void)
{
    const double x[] = {0, 2, 3, 5, 15, 25, 27, 28, 30};
    const double f[] = {2, 1.58, 1.55, 1.54, 1.8, 1.54, 1.55, 1.58, 2};
    int passed = 0, failed = 0;
#define CHECK(c) ((c) ? (void)passed++ : (void)(failed++, printf("FAIL: %s\n", #c)))
    ts_options o; /* the old type name */
    ts_spline_options n;
    ts_options_init(&o);
    ts_spline_options_init(&n);
    CHECK(memcmp(&o, &n, sizeof o) == 0);
    o.shape = TS_SHAPE_POSITIVE;
    ts_spline *s = NULL;
    CHECK(ts_spline_new(x, f, 9, &o, &s, NULL) == TS_OK);
    double y0, y1, d0[3], d1[3], b0[4], b1[4], i0, i1, e0, e1;
    const double q[] = {0.5, 4.2, 16, 29.5};
    CHECK(ts_eval(s, 4.2, NULL, &y0) == TS_OK && ts_spline_eval(s, 4.2, NULL, &y1) == TS_OK &&
          memcmp(&y0, &y1, sizeof y0) == 0);
    CHECK(ts_eval_deriv(s, 4.2, NULL, &d0[0], &d0[1], &d0[2]) == TS_OK &&
          ts_spline_eval_deriv(s, 4.2, NULL, &d1[0], &d1[1], &d1[2]) == TS_OK &&
          memcmp(d0, d1, sizeof d0) == 0);
    CHECK(ts_eval_batch(s, 0, q, 4, b0, NULL, NULL) == TS_OK &&
          ts_spline_eval_batch(s, 0, q, 4, b1, NULL, NULL) == TS_OK &&
          memcmp(b0, b1, sizeof b0) == 0);
    CHECK(ts_eval_batch_mt(s, 1, q, 4, b0, 1, NULL) == TS_OK &&
          ts_spline_eval_batch_mt(s, 1, q, 4, b1, 1, NULL) == TS_OK &&
          memcmp(b0, b1, sizeof b0) == 0);
    CHECK(ts_integral(s, 1, 29, &i0) == TS_OK && ts_spline_integral(s, 1, 29, &i1) == TS_OK &&
          memcmp(&i0, &i1, sizeof i0) == 0);
    ts_line zero = {0, 0};
    CHECK(ts_certify(s, &zero, NULL, NULL, NULL) == ts_spline_certify(s, &zero, NULL, NULL, NULL));
    CHECK(ts_error_bound(s, 1, 1, 0, &e0, NULL) == ts_spline_error_bound(s, 1, 1, 0, &e1, NULL) &&
          memcmp(&e0, &e1, sizeof e0) == 0);
    ts_spline_free(s);
    printf("deprecated_use: %d passed, %d failed\n", passed, failed);
    return failed != 0;
}
