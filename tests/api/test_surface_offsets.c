/* Surfaces at large offsets (docs/method.md §11): grids x = x0 + Σ hx,
 * y = y0 + Σ hy with x0, y0 in {0, 1e6, 1e9, 1e12, 1e15} and integer
 * spacings 1–100, every form (paper, C¹, geometric) and every scheme
 * (positive, bounds, range, constant planes, and sloped planes in the
 * geometric form; in the paper and C¹ forms sloped planes through
 * ts_surface_certify), random data near the bounds (fixed seed).
 *  - soundness: every certified patch is sampled on a grid of exactly
 *    representable positions (multiples of the grid's ulp from the patch's
 *    corner) and S − L is formed in long double in local coordinates,
 *    L = p (x − x0) + q (y − y0) + c0 with x − x0 exact: the plane's own
 *    rounding does not blur the check.  Tolerance: none for a surface
 *    built with a scheme (every value it returns is in its region,
 *    docs/method.md §11.5: on or inside a constant bound, strictly beyond a
 *    plane; the long double difference of a double and the exact local
 *    plane has the exact sign); 4 ulps of |S| for a surface without one
 *    certified afterwards by ts_surface_certify (its values are not moved
 *    into a region it does not have: the rounding of evaluation); the
 *    defect measured before plane sides were decided exactly is |p|
 *    times an ulp of x, 0.125·|p| at 1e15;
 *  - translation invariance: the same z on the grid shifted to 0 with the
 *    planes translated exactly (c0 = c + p x0 + q y0, checked exact): the
 *    surface is built (resp. a patch certified) iff the original is.
 * Formerly the plane was taken in global coordinates with a guard of
 * 16ε(|p x| + |q y| + |c|), 42 at 1e15 with slopes of 3: every sloped case
 * at 1e15 was refused (TS_ERR_INFEASIBLE) where the shifted copy certified. */
#include "th.h"
#include "common/th_rng.h"
#include "trigspline.h"

#include <float.h>
#include <math.h>
#include <string.h>

#define NPT 5            /* points per axis: 4 × 4 patches */
#define NN (NPT * NPT)
#define NPATCH ((NPT - 1) * (NPT - 1))
#define MS 8             /* samples per patch side */

static const double offsets[5] = {0.0, 1e6, 1e9, 1e12, 1e15};

/* a plane in local form: p (x − x0) + q (y − y0) + c0 */
typedef struct lplane {
    double p, q, c0;
} lplane;

typedef struct tally {
    long surfaces, built, refused, variant, patches, certified, samples, outside;
    double worst;
} tally;

static double ulp_of(double v)
{
    return nextafter(fabs(v), TH_INF) - fabs(v);
}

/* the global plane c = c0 − p x0 − q y0, checked exact (fma, TwoSum) */
static ts_plane global_plane(const lplane *L, double x0, double y0)
{
    double px = L->p * x0, qy = L->q * y0;
    CHECK(fma(L->p, x0, -px) == 0.0 && fma(L->q, y0, -qy) == 0.0);
    double s = L->c0 - px, z = s - L->c0, e1 = (L->c0 - (s - z)) + (-px - z);
    double c = s - qy, z2 = c - s, e2 = (s - (c - z2)) + (-qy - z2);
    CHECKF(e1 == 0.0 && e2 == 0.0, "plane at (%g, %g): c not exact", x0, y0);
    ts_plane pl = {L->p, L->q, c};
    return pl;
}

static long double plane_local(const lplane *L, double dx, double dy)
{
    return (long double)L->p * (long double)dx + (long double)L->q * (long double)dy +
           (long double)L->c0;
}

typedef struct scase {
    const char *name;
    ts_form form;
    ts_surface_shape shape;
    int has_lo, has_up;
    int sloped;       /* planes with slopes */
    int certify_only; /* NONE surface, ts_surface_certify against the planes */
} scase;

/* Sample the certified patches of s against the planes; dx, dy: offsets of
 * the grid from x0, y0 (exact). */
static void sample(const ts_surface *s, const scase *sc, const double *dx, const double *dy,
                   double x0, double y0, const lplane *lo, const lplane *up, const int *cert,
                   tally *t, const char *what)
{
    int strict = sc->shape == TS_SURFACE_PLANES && !sc->certify_only;
    double ux = ulp_of(x0 + dx[NPT - 1]), uy = ulp_of(y0 + dy[NPT - 1]);
    for (int j = 0; j < NPT - 1; j++)
        for (int i = 0; i < NPT - 1; i++) {
            if (!cert[j * (NPT - 1) + i])
                continue;
            for (int a = 0; a <= MS; a++)
                for (int b = 0; b <= MS; b++) {
                    /* multiples of the ulp, inside the patch (exact sums) */
                    double hx = dx[i + 1] - dx[i], hy = dy[j + 1] - dy[j];
                    double ex = ux * nearbyint(hx * a / MS / ux);
                    double ey = uy * nearbyint(hy * b / MS / uy);
                    double ddx = dx[i] + ex, ddy = dy[j] + ey, x = x0 + ddx, y = y0 + ddy;
                    CHECK(x - x0 == ddx && y - y0 == ddy);
                    double z;
                    if (ts_surface_eval(s, x, y, NULL, &z, NULL, NULL) != TS_OK) {
                        CHECKF(0, "%s: eval at (%.17g, %.17g)", what, x, y);
                        continue;
                    }
                    t->samples++;
                    double tol = sc->certify_only ? 4.0 * ulp_of(z) : 0.0;
                    long double g = HUGE_VALL;
                    if (lo) {
                        long double v = (long double)z - plane_local(lo, ddx, ddy);
                        g = v < g ? v : g;
                    }
                    if (up) {
                        long double v = plane_local(up, ddx, ddy) - (long double)z;
                        g = v < g ? v : g;
                    }
                    if (g < -(long double)tol || (strict && g <= 0.0L)) {
                        t->outside++;
                        if ((double)-g > t->worst)
                            t->worst = (double)-g;
                        if (t->outside <= 5)
                            CHECKF(0, "%s: patch (%d, %d) certified, S − L = %Lg at (%.17g, %.17g)",
                                   what, i, j, g, x, y);
                    }
                }
        }
}

/* (ts_surface_certify runs a branch and bound per patch, with a sloped
 * plane in the paper and C¹ forms of up to 2e5 pieces: to keep the test to
 * seconds those cases take x0 = y0 only, the paper and C¹ ones 1e15 only.) */
/* Build (and certify) one copy; cert[] receives each patch's certificate,
 * the return value the status of the construction (or the certify call). */
static ts_status run(const scase *sc, const double *dx, const double *dy, double x0, double y0,
                     const double *z, const lplane *lo, const lplane *up, int *cert, tally *t,
                     const char *what)
{
    double x[NPT], y[NPT];
    for (int k = 0; k < NPT; k++) {
        x[k] = x0 + dx[k];
        y[k] = y0 + dy[k];
        CHECK(x[k] - x0 == dx[k] && y[k] - y0 == dy[k]);
    }
    ts_surface_options o;
    ts_surface_options_init(&o);
    o.form = sc->form;
    o.shape = sc->certify_only ? TS_SURFACE_NONE : sc->shape;
    if (sc->form == TS_FORM_GEOMETRIC && o.shape == TS_SURFACE_NONE)
        o.alpha = 1.0;
    ts_plane gl = {0, 0, 0}, gu = {0, 0, 0};
    if (lo)
        gl = global_plane(lo, x0, y0);
    if (up)
        gu = global_plane(up, x0, y0);
    o.has_lower = sc->has_lo;
    o.has_upper = sc->has_up;
    o.lower = gl;
    o.upper = gu;
    ts_surface *s = NULL;
    ts_error e;
    ts_status st = ts_surface_new(x, NPT, y, NPT, z, &o, &s, &e);
    for (int c = 0; c < NPATCH; c++)
        cert[c] = 0;
    if (st != TS_OK)
        return st;
    if (sc->certify_only) {
        ts_patch_report rep[NPATCH];
        ts_patch_report_init(rep, sizeof rep / sizeof rep[0]);
        st = ts_surface_certify(s, lo ? &gl : NULL, up ? &gu : NULL, rep, &e);
        for (int c = 0; c < NPATCH; c++)
            cert[c] = rep[c].certified;
    } else {
        CHECK(ts_surface_certified(s));
        for (int c = 0; c < NPATCH; c++)
            cert[c] = 1;
    }
    sample(s, sc, dx, dy, x0, y0, lo, up, cert, t, what);
    ts_surface_free(s);
    return st;
}

static void one(const scase *sc, double x0, double y0, th_rng *r, tally *t)
{
    double dx[NPT], dy[NPT], z[NN];
    dx[0] = dy[0] = 0.0;
    for (int k = 1; k < NPT; k++) {
        dx[k] = dx[k - 1] + (double)(1 + th_rng_below(r, 100));
        dy[k] = dy[k - 1] + (double)(1 + th_rng_below(r, 100));
    }
    /* planes: slopes k/4 in [-3, 3] (p x0 exact), integer c0 */
    lplane lo = {0, 0, 0}, up = {0, 0, 0};
    if (sc->sloped) {
        lo.p = (double)((int)th_rng_below(r, 25) - 12) / 4.0;
        lo.q = (double)((int)th_rng_below(r, 25) - 12) / 4.0;
    }
    lo.c0 = sc->shape == TS_SURFACE_POSITIVE ? 0.0 : 1.0;
    up = lo;
    if (sc->sloped && sc->has_lo) {
        up.p += (double)th_rng_below(r, 2) / 4.0;
        up.q += (double)th_rng_below(r, 2) / 4.0;
    }
    up.c0 = lo.c0 + (double)(2 + th_rng_below(r, 5));
    for (int j = 0; j < NPT; j++)
        for (int i = 0; i < NPT; i++) {
            double L = (double)plane_local(&lo, dx[i], dy[j]);
            double U = (double)plane_local(&up, dx[i], dy[j]);
            double g = th_rng_chance(r, 0.5) ? th_rng_logu(r, 0.01, 0.1) : th_rng_logu(r, 0.1, 3.0);
            double v;
            if (sc->shape == TS_SURFACE_RANGE)
                v = th_rng_range(r, 0.0, 10.0);
            else if (sc->has_lo && sc->has_up)
                v = L + (U - L) * th_rng_range(r, 0.02, 0.98);
            else if (sc->has_up)
                v = U - g;
            else
                v = L + g;
            /* nodes on a constant bound (allowed by positive and bounds) */
            if (!sc->sloped && sc->shape != TS_SURFACE_PLANES && th_rng_chance(r, 0.1))
                v = sc->has_lo ? L : U;
            z[j * NPT + i] = v;
        }
    if (sc->shape == TS_SURFACE_RANGE) { /* the bounds are the data's range */
        lo.c0 = up.c0 = z[0];
        for (int n = 0; n < NN; n++) {
            lo.c0 = z[n] < lo.c0 ? z[n] : lo.c0;
            up.c0 = z[n] > up.c0 ? z[n] : up.c0;
        }
    }
    int ca[NPATCH], cb[NPATCH];
    char what[160];
    snprintf(what, sizeof what, "%s at (%g, %g)", sc->name, x0, y0);
    ts_status sa = run(sc, dx, dy, x0, y0, z, sc->has_lo ? &lo : NULL, sc->has_up ? &up : NULL,
                       ca, t, what);
    ts_status sb = run(sc, dx, dy, 0.0, 0.0, z, sc->has_lo ? &lo : NULL, sc->has_up ? &up : NULL,
                       cb, t, what);
    t->surfaces++;
    int built = sc->certify_only ? 1 : sa == TS_OK;
    t->built += built;
    t->refused += !built;
    int same = (sa == TS_OK) == (sb == TS_OK);
    for (int c = 0; c < NPATCH; c++) {
        same &= ca[c] == cb[c];
        t->patches++;
        t->certified += ca[c];
    }
    if (!same) {
        t->variant++;
        if (t->variant <= 5)
            CHECKF(0, "%s: not translation invariant (status %d vs %d shifted to 0)", what,
                   (int)sa, (int)sb);
    }
}

int main(void)
{
    static const scase cases[] = {
        {"paper positive", TS_FORM_PAPER, TS_SURFACE_POSITIVE, 1, 0, 0, 0},
        {"paper bounds lower", TS_FORM_PAPER, TS_SURFACE_BOUNDS, 1, 0, 0, 0},
        {"paper bounds upper", TS_FORM_PAPER, TS_SURFACE_BOUNDS, 0, 1, 0, 0},
        {"paper bounds both", TS_FORM_PAPER, TS_SURFACE_BOUNDS, 1, 1, 0, 0},
        {"paper range", TS_FORM_PAPER, TS_SURFACE_RANGE, 1, 1, 0, 0},
        {"paper planes between", TS_FORM_PAPER, TS_SURFACE_PLANES, 1, 1, 0, 0},
        {"paper certify sloped lower", TS_FORM_PAPER, TS_SURFACE_PLANES, 1, 0, 1, 1},
        {"paper certify sloped between", TS_FORM_PAPER, TS_SURFACE_PLANES, 1, 1, 1, 1},
        {"C1 positive", TS_FORM_C1, TS_SURFACE_POSITIVE, 1, 0, 0, 0},
        {"C1 bounds both", TS_FORM_C1, TS_SURFACE_BOUNDS, 1, 1, 0, 0},
        {"C1 range", TS_FORM_C1, TS_SURFACE_RANGE, 1, 1, 0, 0},
        {"C1 planes lower", TS_FORM_C1, TS_SURFACE_PLANES, 1, 0, 0, 0},
        {"C1 planes upper", TS_FORM_C1, TS_SURFACE_PLANES, 0, 1, 0, 0},
        {"C1 certify sloped upper", TS_FORM_C1, TS_SURFACE_PLANES, 0, 1, 1, 1},
        {"geometric positive", TS_FORM_GEOMETRIC, TS_SURFACE_POSITIVE, 1, 0, 0, 0},
        {"geometric bounds both", TS_FORM_GEOMETRIC, TS_SURFACE_BOUNDS, 1, 1, 0, 0},
        {"geometric range", TS_FORM_GEOMETRIC, TS_SURFACE_RANGE, 1, 1, 0, 0},
        {"geometric planes between", TS_FORM_GEOMETRIC, TS_SURFACE_PLANES, 1, 1, 0, 0},
        {"geometric sloped lower", TS_FORM_GEOMETRIC, TS_SURFACE_PLANES, 1, 0, 1, 0},
        {"geometric sloped upper", TS_FORM_GEOMETRIC, TS_SURFACE_PLANES, 0, 1, 1, 0},
        {"geometric sloped between", TS_FORM_GEOMETRIC, TS_SURFACE_PLANES, 1, 1, 1, 0},
        {"geometric certify sloped lower", TS_FORM_GEOMETRIC, TS_SURFACE_PLANES, 1, 0, 1, 1},
    };
    th_rng r = TH_RNG_INIT(20261202);
    tally all;
    memset(&all, 0, sizeof all);
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        TH_CASE(cases[c].name);
        tally t;
        memset(&t, 0, sizeof t);
        int slow = cases[c].certify_only && cases[c].form != TS_FORM_GEOMETRIC;
        for (int ox = slow ? 4 : 0; ox < 5; ox++)
            for (int oy = 0; oy < (cases[c].certify_only ? 1 : 5); oy++)
                for (int rep = 0; rep < (cases[c].certify_only ? 1 : 2); rep++)
                    one(&cases[c], offsets[ox], offsets[(ox + oy) % 5], &r, &t);
        printf("  %-32s surfaces %3ld built %3ld refused %3ld variant %3ld patches %4ld "
               "certified %4ld samples %7ld outside %ld (worst %.3g)\n",
               cases[c].name, t.surfaces, t.built, t.refused, t.variant, t.patches, t.certified,
               t.samples, t.outside, t.worst);
        all.variant += t.variant;
        all.outside += t.outside;
        all.refused += t.refused;
        all.certified += t.certified;
        all.patches += t.patches;
    }
    printf("  total: certified %ld of %ld patches, %ld refusals, %ld translation-variant, "
           "%ld samples outside\n",
           all.certified, all.patches, all.refused, all.variant, all.outside);
    CHECK(all.variant == 0);
    CHECK(all.outside == 0);
    return th_report("test_surface_offsets");
}
