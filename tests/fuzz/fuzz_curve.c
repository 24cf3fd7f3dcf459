/* ts_curve_new with fuzzer-chosen points, options and box; on success the
 * box certificate, samples, length and evaluation.  Checks: a documented
 * status; a curve built with a box certifies against it; every point it
 * returns (ts_curve_sample, a closed curve's seam row included, and
 * ts_curve_eval at every knot and mid-segment) is in the box with ZERO
 * tolerance (lo <= v <= hi in doubles, compared exactly: the box is closed,
 * points may lie on a side); every knot returns its data point exactly
 * (evaluation from the nearer end); the length is never NaN. */
#include "fuzz.h"
#include "trigspline.h"

#include <float.h>
#include <math.h>

#define PMAX 16
#define SAMPLES 17

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_in in = {data, size};
    fuzz_stats_exec();
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
    fuzz_counts()[FUZZ_CERTIFIED] += boxed;
    double ctrl[12];
    static double out[(PMAX + 1) * (SAMPLES - 1) * 4 + 8];
    st = ts_curve_sample(c, SAMPLES, out, sizeof out / sizeof *out, &rows);
    FUZZ_CHECK(st == TS_OK, "sample: %s", ts_strerror(st));
    const double *t = ts_curve_knots(c);
    int closed = ts_curve_closed(c);
    fuzz_counts()[FUZZ_SAMPLES] += boxed ? (long)rows + 2 * (long)segs + 1 : 0;
    for (size_t r = 0; r < rows; r++) {
        /* a knot row: the data point of segment r / (m - 1), exactly */
        size_t i = r / (SAMPLES - 1), l = 0;
        if (r % (SAMPLES - 1) == 0) {
            if (i == segs) {
                i = segs - 1;
                l = 3;
            }
            ts_curve_control(c, i, ctrl);
        }
        for (size_t k = 0; k < dim; k++) {
            double v = out[r * (1 + dim) + 1 + k];
            FUZZ_CHECK(r % (SAMPLES - 1) != 0 || v == ctrl[l * dim + k],
                       "knot row %zu coord %zu: %.17g, data %.17g", r, k, v, ctrl[l * dim + k]);
            FUZZ_CHECK(!boxed || !o.has_lo[k] || v >= o.lo[k], "row %zu coord %zu: %.17g < %.17g",
                       r, k, v, o.lo[k]);
            FUZZ_CHECK(!boxed || !o.has_hi[k] || v <= o.hi[k], "row %zu coord %zu: %.17g > %.17g",
                       r, k, v, o.hi[k]);
        }
    }
    /* ts_curve_eval at every knot (open: t_n is the last point; closed:
     * t_n wraps to t_0) and at each segment's midpoint and 0.999 */
    for (size_t i = 0; i <= segs; i++)
        for (int w = 0; w < 3; w++) {
            if (i == segs && w > 0)
                continue;
            double tq = w == 0 ? t[i] : t[i] + (t[i + 1] - t[i]) * (w == 1 ? 0.5 : 0.999), pe[3];
            FUZZ_CHECK(ts_curve_eval(c, tq, NULL, pe, NULL, NULL) == TS_OK, "eval at %.17g", tq);
            if (w == 0) {
                size_t si = i < segs ? i : closed ? 0 : segs - 1, l = i < segs || closed ? 0 : 3;
                ts_curve_control(c, si, ctrl);
                for (size_t k = 0; k < dim; k++)
                    FUZZ_CHECK(pe[k] == ctrl[l * dim + k], "eval at knot %zu coord %zu: %.17g vs %.17g",
                               i, k, pe[k], ctrl[l * dim + k]);
            }
            for (size_t k = 0; boxed && k < dim; k++)
                FUZZ_CHECK((!o.has_lo[k] || pe[k] >= o.lo[k]) && (!o.has_hi[k] || pe[k] <= o.hi[k]),
                           "eval at %.17g coord %zu: %.17g outside the box", tq, k, pe[k]);
        }
    double len;
    FUZZ_CHECK(ts_curve_length(c, 1e-9, &len) == TS_OK && !isnan(len), "length %g", len);
    ts_curve_free(c);
    return 0;
}
