/* Surface options and reports at their edges (include/trigspline.h):
 * a shape beyond the enum is TS_ERR_OPTION; the report of a surface
 * between gridded fields that has an upper field only says so (no lower
 * field, its numbers NaN) and is certified; ts_surface_certify checks a
 * surface between fields against planes given by the caller, not against
 * its fields, and leaves the numbers of the side it is not given NaN; an alpha so large that raising a (times 10, docs/method.md
 * §11.4) would pass 1e300 stops the repair with the status of the failing
 * patch (TS_ERR_UNPROVEN for fields) rather than overflowing.  Expected
 * values from the header's contract and closed forms: a field that peaks
 * at 2 in the middle of a cell whose four nodes are 1 is above the surface
 * there whatever a (the patch interpolates its nodes, and a surface of
 * nodes 1 cannot reach 2 when its a grows: its control values tend to the
 * nodes).
 *
 * A value of a surface between fields that evaluation puts within the
 * field's rounding bound e_F of it (docs/method.md §11.5, §11.7): a constant
 * surface z0 over a field that is the constant lev on the data's cell and 1
 * on a far node (so e_F = 32 eps), z0 just above lev + the certificate's
 * guard (found by sampling such pairs); at the point below it evaluates 7
 * ulps under z0, within e_F of lev, where the exact side decides.  The
 * value returned must be strictly above the field, which is lev on that
 * cell exactly, and near z0. */
#include "th.h"
#include "trigspline.h"

#include <float.h>
#include <math.h>

static const double X[2] = {0.0, 1.0}, Y[2] = {0.0, 1.0};

int main(void)
{
    ts_surface_options o;
    ts_surface *s = NULL;
    ts_error e;
    double z[4] = {1.0, 1.0, 1.0, 1.0};

    TH_CASE("a shape beyond the enum");
    {
        ts_surface_options_init(&o);
        o.shape = (ts_surface_shape)(TS_SURFACE_GRIDS + 1);
        ts_status st = ts_surface_new(X, 2, Y, 2, z, &o, &s, &e);
        CHECKF(st == TS_ERR_OPTION && !s, "%s", ts_status_name(st));
    }

    /* an upper field 2 everywhere, on a grid of its own */
    double fx[3] = {-1.0, 0.5, 2.0}, fz2[9] = {2, 2, 2, 2, 2, 2, 2, 2, 2};
    TH_CASE("the report of a surface under an upper field only");
    {
        ts_surface_options_init(&o);
        o.shape = TS_SURFACE_GRIDS;
        o.has_upper = 1;
        o.upper_grid = (ts_grid_bound){fx, 3, fx, 3, fz2};
        ts_status st = ts_surface_new(X, 2, Y, 2, z, &o, &s, &e);
        CHECKF(st == TS_OK && s, "%s", ts_status_name(st));
        if (s) {
            ts_patch_report r;
            ts_patch_report_init(&r, 1);
            CHECK(ts_surface_report(s, 0, 0, &r) == TS_OK);
            CHECK(!r.has_lower && r.has_upper && r.certified);
            CHECK(isnan(r.proven_lower) && isnan(r.sampled_lower));
            /* a constant surface 1 under a field 2: the gap is 1 up to rounding */
            CHECKF(r.proven_upper > 0.0 && r.proven_upper <= 1.0, "%.17g", r.proven_upper);
            CHECKF(fabs(r.sampled_upper - 1.0) < 1e-12, "%.17g", r.sampled_upper);

            TH_CASE("ts_surface_certify of a surface between fields against planes");
            ts_plane below = {0.0, 0.0, 0.5}, above = {0.0, 0.0, 0.75};
            ts_patch_report_init(&r, 1);
            CHECK(ts_surface_certify(s, &below, NULL, &r, &e) == TS_OK);
            CHECK(r.has_lower && !r.has_upper && r.certified);
            /* the absent side's numbers NaN (the header), not left unset */
            CHECK(isnan(r.proven_upper) && isnan(r.sampled_upper) && isnan(r.at_upper[0]) &&
                  isnan(r.at_upper[1]));
            /* the constant plane 0.5 under the constant surface 1 */
            CHECKF(fabs(r.sampled_lower - 0.5) < 1e-12, "%.17g", r.sampled_lower);
            ts_patch_report_init(&r, 1);
            CHECK(ts_surface_certify(s, NULL, &above, &r, &e) == TS_ERR_VIOLATED && e.index == 0);
            CHECK(!r.certified);
            CHECK(isnan(r.proven_lower) && isnan(r.sampled_lower) && isnan(r.at_lower[0]) &&
                  isnan(r.at_lower[1]));
            ts_surface_free(s);
            s = NULL;
        }
    }

    TH_CASE("a repair that would raise a beyond 1e300");
    {
        double lz[9] = {0, 0, 0, 0, 2, 0, 0, 0, 0}; /* 2 at (0.5, 0.5) */
        for (int big = 0; big < 2; big++) {
            ts_surface_options_init(&o);
            o.shape = TS_SURFACE_GRIDS;
            o.has_lower = 1;
            o.lower_grid = (ts_grid_bound){fx, 3, fx, 3, lz};
            o.alpha = big ? 2e299 : 1.0;
            ts_status st = ts_surface_new(X, 2, Y, 2, z, &o, &s, &e);
            CHECKF(st == TS_ERR_UNPROVEN && e.index == 0 && e.where == TS_WHERE_INTERVAL && !s,
                   "alpha %g: %s at %zu", o.alpha, ts_status_name(st), e.index);
            ts_surface_free(s);
            s = NULL;
        }
    }
    TH_CASE("a node whose gap to the field equals the cell certificate's guard");
    {
        /* geometric form, a field 0 on one cell covering the data: the
         * guard is e_F + 2 eps max(|B| + |b|) = 8*2^-1074 + 2^-51, which
         * rounds to 2^-51 (the nodes 1 the largest control values); a node
         * 2^-51 above the field is above it (decided) but its gap is not
         * above the guard, so no a certifies the patch: TS_ERR_UNPROVEN */
        double fz[4] = {0, 0, 0, 0}, fg[2] = {-1.0, 2.0};
        for (int corner = 0; corner < 4; corner++) {
            double zc[4] = {1, 1, 1, 1};
            zc[corner] = 0x1p-51;
            ts_surface_options_init(&o);
            o.form = TS_FORM_GEOMETRIC;
            o.shape = TS_SURFACE_GRIDS;
            o.has_lower = 1;
            o.lower_grid = (ts_grid_bound){fg, 2, fg, 2, fz};
            ts_status st = ts_surface_new(X, 2, Y, 2, zc, &o, &s, &e);
            CHECKF(st == TS_ERR_UNPROVEN && e.index == 0 && !s, "corner %d: %s at %zu", corner,
                   ts_status_name(st), e.index);
            ts_surface_free(s);
            s = NULL;
        }
    }
    TH_CASE("values within the field's rounding bound of it");
    {
        const double lev = 0x1.9e63743024626p-17, z0 = 0x1.9e6374342462dp-17;
        const double p = 0x1.50325e429de58p-1;
        double gx[3] = {0, 1, 2}, gy[2] = {0, 1}, gz[6] = {lev, lev, 1, lev, lev, 1};
        double zz[4] = {z0, z0, z0, z0};
        ts_surface_options_init(&o);
        o.form = TS_FORM_GEOMETRIC;
        o.shape = TS_SURFACE_GRIDS;
        o.has_lower = 1;
        o.lower_grid = (ts_grid_bound){gx, 3, gy, 2, gz};
        ts_status st = ts_surface_new(X, 2, Y, 2, zz, &o, &s, &e);
        CHECKF(st == TS_OK && s, "%s", ts_status_name(st));
        if (s) {
            double v = 0.0, w = 0.0;
            CHECK(ts_surface_eval(s, p, p, NULL, &v, NULL, NULL) == TS_OK);
            CHECK(ts_surface_eval_grid(s, &p, 1, &p, 1, &w, &e) == TS_OK && w == v);
            /* strictly above the field, and within 40 ulps of the constant
             * surface (a few of evaluation, e_F = 32 eps of a move) */
            CHECKF(v > lev && fabs(v - z0) <= 40.0 * DBL_EPSILON, "%a", v);
        }
        ts_surface_free(s);
        s = NULL;
    }
    return th_report("test_surface_edges");
}
