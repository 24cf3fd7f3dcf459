/* ts_curve_new with fuzzer-chosen points, options and box; on success the
 * box certificate, samples, length and evaluation.  Checks: a documented
 * status; a curve built with a box certifies against it, and its samples
 * stay inside the box (tolerance 8ε max|control| for the evaluation's
 * rounding); the length is never NaN. */
#include "fuzz.h"
#include "trigspline.h"

#include <float.h>
#include <math.h>

#define PMAX 16
#define SAMPLES 17

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_in in = {data, size};
    ts_curve_options o;
    ts_curve_options_init(&o);
    unsigned b0 = fuzz_byte(&in), b1 = fuzz_byte(&in);
    size_t dim = 2 + (b0 & 1);
    o.param = (ts_param)(b0 / 2 % 3);
    o.closed = (b0 / 6) & 1;
    o.slopes = (ts_slopes)(b0 / 12 % 8);
    size_t np = 2 + b1 % (PMAX - 1);
    double p[PMAX * 3];
    for (size_t i = 0; i < np * dim; i++)
        p[i] = fuzz_double(&in);
    o.alpha = (fuzz_byte(&in) + 1) / 64.0;
    o.beta = fuzz_byte(&in) / 64.0;
    unsigned box = fuzz_byte(&in);
    for (size_t k = 0; k < 3; k++) {
        o.has_lo[k] = (box >> (2 * k)) & 1;
        o.has_hi[k] = (box >> (2 * k + 1)) & 1;
        o.lo[k] = fuzz_double(&in);
        o.hi[k] = fuzz_double(&in);
    }
    if (box & 0x40)
        o.margin = (fuzz_byte(&in) + 1) / 256.0;
    ts_curve *c = NULL;
    ts_error e;
    ts_status st = ts_curve_new(p, np, dim, &o, &c, &e);
    FUZZ_CHECK(st == TS_OK || st == TS_ERR_OPTION || st == TS_ERR_TOO_FEW ||
                   st == TS_ERR_NONFINITE || st == TS_ERR_SLOPE_OVERFLOW || st == TS_ERR_ALPHA ||
                   st == TS_ERR_BETA || st == TS_ERR_MARGIN || st == TS_ERR_UNSORTED ||
                   st == TS_ERR_SIDE || st == TS_ERR_INFEASIBLE || st == TS_ERR_NOMEM,
               "status %d", (int)st);
    FUZZ_CHECK((st == TS_OK) == (c != NULL), "status %d", (int)st);
    if (!c)
        return 0;
    int boxed = 0;
    for (size_t k = 0; k < dim; k++)
        boxed |= o.has_lo[k] | o.has_hi[k];
    st = ts_curve_certify(c, NULL, &e);
    FUZZ_CHECK(!boxed || st == TS_OK, "boxed curve fails its certificate at %zu", e.index);
    size_t segs = ts_curve_segments(c), rows = 0;
    double cmax = 0.0, ctrl[12];
    for (size_t i = 0; i < segs; i++) {
        ts_curve_control(c, i, ctrl);
        for (size_t l = 0; l < 4 * dim; l++)
            cmax = fmax(cmax, fabs(ctrl[l]));
    }
    static double out[(PMAX + 1) * (SAMPLES - 1) * 4 + 8];
    st = ts_curve_sample(c, SAMPLES, out, sizeof out / sizeof *out, &rows);
    FUZZ_CHECK(st == TS_OK, "sample: %s", ts_strerror(st));
    double tol = 8 * DBL_EPSILON * cmax;
    for (size_t r = 0; boxed && r < rows; r++)
        for (size_t k = 0; k < dim; k++) {
            double v = out[r * (1 + dim) + 1 + k];
            FUZZ_CHECK(!o.has_lo[k] || v > o.lo[k] - tol, "row %zu coord %zu: %.17g < %.17g", r,
                       k, v, o.lo[k]);
            FUZZ_CHECK(!o.has_hi[k] || v < o.hi[k] + tol, "row %zu coord %zu: %.17g > %.17g", r,
                       k, v, o.hi[k]);
        }
    double len;
    FUZZ_CHECK(ts_curve_length(c, 1e-9, &len) == TS_OK && !isnan(len), "length %g", len);
    double pt[3];
    const double *t = ts_curve_knots(c);
    FUZZ_CHECK(ts_curve_eval(c, 0.5 * (t[0] + t[segs]), NULL, pt, NULL, NULL) == TS_OK, "eval");
    ts_curve_free(c);
    return 0;
}
