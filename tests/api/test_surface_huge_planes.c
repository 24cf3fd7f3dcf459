/* Planes whose terms leave the exact sign's range (|p x|, |q y|, |c| or
 * |z| above 2^1020, docs/method.md §11.3): where a node lies within the
 * plane value's rounding bound of such a plane, which side it is on cannot
 * be decided exactly, and ts_surface_new refuses it as on the plane
 * (include/trigspline.h: TS_ERR_SIDE "a node on or across a plane"; for two
 * planes not decidably ordered at a node, TS_ERR_LINES).  Expected values
 * from the header's contract: which node, which status.  Every node here
 * is exactly on the plane in real arithmetic (p x + c with powers of two),
 * so no answer but "on the plane" would be right, but one: a node one ulp
 * above the constant plane 2^1020, above it in real arithmetic, refused
 * by the same rule (|z| beyond 2^1020 within the rounding bound).
 *
 * Evaluation near such a plane (docs/method.md §11.5, "Values inside the
 * region"): a certified surface under the constant upper plane 2^1020 (and
 * 2^1021, the same data times 2), nodes 17 to 944 units of 2^967 below it
 * (z = c − m 2^(e−53)), evaluates by rounding to c + 1 ulp at some points of
 * a 300 x 300 grid, where the exact sign cannot be formed (|z| or |c| above
 * 2^1020).  Every value returned must still be strictly below the plane:
 * for a constant plane that is z < c, compared exactly in double. */
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
    TH_CASE("a constant plane in range, z beyond: one ulp above 2^1020");
    {
        /* 2^1020 + 2^968 is within the plane value's rounding bound
         * 2 * 2 eps 2^1020 = 2^970 of 2^1020 and beyond 2^1020: undecided,
         * refused as on the plane (the others, 2^1021, are decided above) */
        ts_plane lo = {0, 0, H};
        const double z[4] = {T, T, H + 0x1p968, T};
        CHECK(build(z, 1, lo, 0, none, &e) == TS_ERR_SIDE && e.index == 2);
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
    TH_CASE("values near a plane beyond the range stay inside the region");
    {
        static const int m[16] = {23, 328, 22, 517, 21, 274, 238, 944,
                                  128, 17, 17, 653, 881, 17, 17, 610};
        double x4[4] = {0, 1, 2, 3}, q[300];
        for (int k = 0; k < 300; k++)
            q[k] = 3.0 * k / 299.0;
        for (int e2 = 1020; e2 <= 1021; e2++) {
            double c = ldexp(1.0, e2), z[16];
            for (int k = 0; k < 16; k++)
                z[k] = c - m[k] * ldexp(1.0, e2 - 53);
            ts_surface_options o;
            ts_surface_options_init(&o);
            o.form = TS_FORM_GEOMETRIC;
            o.shape = TS_SURFACE_PLANES;
            o.has_upper = 1;
            o.upper = (ts_plane){0, 0, c};
            ts_surface *s = NULL;
            ts_status st = ts_surface_new(x4, 4, x4, 4, z, &o, &s, &e);
            CHECKF(st == TS_OK && s, "2^%d: %s", e2, ts_status_name(st));
            if (!s)
                continue;
            static double out[300 * 300];
            CHECK(ts_surface_eval_grid(s, q, 300, q, 300, out, &e) == TS_OK);
            size_t bad = 0;
            for (size_t k = 0; k < 300 * 300; k++)
                bad += !(out[k] < c);
            CHECKF(bad == 0, "2^%d: %zu values not below the plane", e2, bad);
            double v;
            CHECK(ts_surface_eval(s, q[168], q[242], NULL, &v, NULL, NULL) == TS_OK && v < c);
            ts_surface_free(s);
        }
    }
    return th_report("test_surface_huge_planes");
}
