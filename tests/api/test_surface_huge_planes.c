/* Planes whose terms leave the exact sign's range (|p x|, |q y|, |c| or
 * |z| above 2^1020, docs/method.md §11.3): where a node lies within the
 * plane value's rounding bound of such a plane, which side it is on cannot
 * be decided exactly, and ts_surface_new refuses it as on the plane
 * (include/trigspline.h: TS_ERR_SIDE "a node on or across a plane"; for two
 * planes not decidably ordered at a node, TS_ERR_LINES).  Expected values
 * from the header's contract: which node, which status.  Every node here
 * is exactly on the plane in real arithmetic (p x + c with powers of two),
 * so no answer but "on the plane" would be right. */
#include "th.h"
#include "trigspline.h"

#include <math.h>

static const double X[2] = {0.0, 1.0}, Y[2] = {0.0, 1.0};

static ts_status build(const double z[4], int has_lower, ts_plane lo, int has_upper, ts_plane up,
                       ts_error *e)
{
    ts_surface_options o;
    ts_surface_options_init(&o);
    o.form = TS_FORM_GEOMETRIC;
    o.shape = TS_SURFACE_PLANES;
    o.has_lower = has_lower;
    o.lower = lo;
    o.has_upper = has_upper;
    o.upper = up;
    ts_surface *s = NULL;
    ts_status st = ts_surface_new(X, 2, Y, 2, z, &o, &s, e);
    ts_surface_free(s);
    return st;
}

int main(void)
{
    const double T = 0x1p1021, H = 0x1p1020;
    const ts_plane none = {0, 0, 0};
    ts_error e;

    TH_CASE("p x beyond the range: the node at x = 1 is on the plane");
    {
        ts_plane lo = {T, 0, -1}; /* z = 2^1021 x - 1: -1 at x = 0, 2^1021 at x = 1 (rounded) */
        const double z[4] = {0, T, 0, T}; /* nodes in z order: (0,0), (1,0), (0,1), (1,1) */
        CHECK(build(z, 1, lo, 0, none, &e) == TS_ERR_SIDE && e.index == 1 &&
              e.where == TS_WHERE_POINT);
    }
    TH_CASE("q y beyond the range: the node at y = 1");
    {
        ts_plane lo = {0, T, -1};
        const double z[4] = {0, 0, T, T};
        CHECK(build(z, 1, lo, 0, none, &e) == TS_ERR_SIDE && e.index == 2);
    }
    TH_CASE("c beyond the range: a constant plane through every node");
    {
        ts_plane up = {0, 0, T};
        const double z[4] = {T, T, T, T};
        CHECK(build(z, 0, none, 1, up, &e) == TS_ERR_SIDE && e.index == 0);
    }
    TH_CASE("terms in range, z beyond: 2^1020 x + 2^1020 at x = 1");
    {
        ts_plane lo = {H, 0, H};
        const double z[4] = {T, T, T, T}; /* (0,0): 2^1021 above 2^1020, decided; (1,0) on it */
        CHECK(build(z, 1, lo, 0, none, &e) == TS_ERR_SIDE && e.index == 1);
    }
    TH_CASE("two planes equal at a node, the upper's terms beyond the range");
    {
        ts_plane lo = {H, 0, H}, up = {0, 0, T}; /* both 2^1021 at x = 1 */
        const double z[4] = {H + H / 2, T, H + H / 2, T};
        ts_status st = build(z, 1, lo, 1, up, &e);
        CHECKF(st == TS_ERR_LINES && e.index == 1 && e.where == TS_WHERE_POINT, "%s at %zu",
               ts_status_name(st), e.index);
    }
    TH_CASE("two planes equal at a node, the lower's terms beyond the range");
    {
        ts_plane lo = {T, 0, 0}, up = {H, 0, H};
        const double z[4] = {H / 2, T, H / 2, T};
        CHECK(build(z, 1, lo, 1, up, &e) == TS_ERR_LINES && e.index == 1);
    }
    return th_report("test_surface_huge_planes");
}
