/* ts_curve_length when a coordinate is constant on a segment and far larger
 * than the moving one (docs/method.md §7, "Arc length"): the speed is
 * scaled by the moving coordinates alone, so a segment from (1e300, 0) to
 * (1e300, 1e-310) has the length of the one from (0, 0) to (0, 1e-310),
 * not 0 (the constant 1e300 used to set the scale and flush the speed).
 * Expected values: a two-point curve with one coordinate constant is the
 * straight segment between them, its length |Δy| (geometry); tolerance
 * 1e-12 relative (the length's default tol) plus, for 1e-310, the
 * subnormal spacing 2^-1074 times the 10-node sums (~1e-13 relative).
 * A constant coordinate changes no bit of the length (a power-of-two
 * scale commutes with rounding away from underflow): the same curve at
 * z = 0 and z = 1000 (3 dimensions), at x = 0 and x = 1e300. */
#include "th.h"
#include "trigspline.h"

#include <math.h>
#include <string.h>

static double length_of(const double *p, size_t m, size_t dim)
{
    ts_curve *c = NULL;
    double len = (double)NAN;
    CHECK(ts_curve_new(p, m, dim, NULL, &c, NULL) == TS_OK);
    if (c)
        CHECK(ts_curve_length(c, 0.0, &len) == TS_OK);
    ts_curve_free(c);
    return len;
}

int main(void)
{
    TH_CASE("a subnormal step next to a constant 1e300");
    const double tiny = 1e-310;
    double far[4] = {1e300, 0, 1e300, tiny}, near[4] = {0, 0, 0, tiny};
    double lf = length_of(far, 2, 2), ln = length_of(near, 2, 2);
    CHECKF(fabs(lf - tiny) <= 1e-12 * tiny, "length %.17g, want %.17g", lf, tiny);
    CHECKF(memcmp(&lf, &ln, sizeof lf) == 0, "%.17g vs %.17g", lf, ln);

    TH_CASE("a unit step next to a constant 1e300");
    double far1[4] = {1e300, 0, 1e300, 1}, near1[4] = {0, 0, 0, 1};
    lf = length_of(far1, 2, 2);
    ln = length_of(near1, 2, 2);
    CHECKF(fabs(lf - 1.0) <= 1e-12, "length %.17g", lf);
    CHECKF(memcmp(&lf, &ln, sizeof lf) == 0, "%.17g vs %.17g", lf, ln);

    TH_CASE("a planar curve at z = 0 and z = 1000");
    double z0[15] = {0, 0, 0, 1, 0.5, 0, 2, 2, 0, 1, 3, 0, 0, 2.5, 0}, z1[15];
    for (int k = 0; k < 15; k++)
        z1[k] = k % 3 == 2 ? 1000.0 : z0[k];
    double a = length_of(z0, 5, 3), b = length_of(z1, 5, 3);
    CHECKF(memcmp(&a, &b, sizeof a) == 0 && a > 0, "%.17g vs %.17g", a, b);
    return th_report("test_curve_length_scale");
}
