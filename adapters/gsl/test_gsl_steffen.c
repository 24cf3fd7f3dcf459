/* TS_SLOPES_STEFFEN against GSL's own steffen interpolation: the derivative
 * of gsl_interp_steffen at the knots (gsl_interp_eval_deriv) is GSL's slope
 * there.  Inner knots use the same rule (Steffen 1990, eq. 11) and must
 * agree; the end rules differ: GSL takes d_0 = Δ_0, d_n = Δ_{n-1} (Steffen's
 * "simplest possibility"), the library Steffen's eq. 26 (the three-point end
 * value, limited to [0, 2Δ]); both are checked. */
#include "common/th_rng.h"
#include "th.h"
#include "trigspline.h"

#include <float.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_interp.h>
#include <math.h>

int main(void)
{
    gsl_set_error_handler_off();
    th_seed(1990);
    long inner = 0;
    for (int rep = 0; rep < 2000; rep++) {
        double x[30], f[30], d[30];
        size_t np = 3 + th_below(27), n;
        x[0] = th_range(-5, 5);
        f[0] = th_range(-5, 5);
        for (size_t i = 1; i < np; i++) {
            x[i] = x[i - 1] + (th_chance(0.5) ? th_range(0.1, 2) : th_logu(1e-2, 1e2));
            f[i] = th_chance(0.1) ? f[i - 1] : f[i - 1] + th_range(-3, 3);
        }
        n = np - 1;
        CHECK(ts_slopes_compute(TS_SLOPES_STEFFEN, x, f, np, d, NULL) == TS_OK);
        gsl_interp *g = gsl_interp_alloc(gsl_interp_steffen, np);
        gsl_interp_accel *acc = gsl_interp_accel_alloc();
        CHECK(g && acc && gsl_interp_init(g, x, f, np) == GSL_SUCCESS);
        double M = 0.0; /* largest secant */
        for (size_t i = 0; i < n; i++)
            M = fmax(M, fabs((f[i + 1] - f[i]) / (x[i + 1] - x[i])));
        /* GSL forms p_i as (Δ_{i-1} h_i + Δ_i h_{i-1})/(h_{i-1} + h_i), the
         * library as the same weights divided first: a few roundings of
         * terms <= 2 max|Δ| apart; 16 eps max|Δ| covers them with a factor 2 */
        double tol = 16 * DBL_EPSILON * M;
        for (size_t i = 1; i < n; i++) {
            double gd = gsl_interp_eval_deriv(g, x, f, x[i], acc);
            CHECKF(fabs(gd - d[i]) <= tol, "rep %d knot %zu: gsl %.17g lib %.17g", rep, i, gd,
                   d[i]);
            inner++;
        }
        /* GSL's ends: the end secants (its cubic at x_0 has slope y'_0 exactly) */
        double g0 = gsl_interp_eval_deriv(g, x, f, x[0], acc);
        CHECK(fabs(g0 - (f[1] - f[0]) / (x[1] - x[0])) <= tol);
        /* the library's ends: Steffen's eq. 26, re-derived here */
        for (int side = 0; side < 2; side++) {
            size_t a = side ? n : 0, b = side ? n - 1 : 1, c = side ? n - 2 : 2;
            double h0 = fabs(x[a] - x[b]), h1 = fabs(x[b] - x[c]);
            double D0 = (f[a] - f[b]) / (x[a] - x[b]), D1 = (f[b] - f[c]) / (x[b] - x[c]);
            double e = D0 + (D0 - D1) * h0 / (h0 + h1);
            double want = e * D0 <= 0 ? 0.0 : fabs(e) > 2 * fabs(D0) ? 2 * D0 : e;
            CHECKF(fabs(d[a] - want) <= tol, "rep %d end %d: %.17g want %.17g", rep, side, d[a],
                   want);
        }
        gsl_interp_accel_free(acc);
        gsl_interp_free(g);
    }
    CHECK(inner > 10000);
    return th_report("test_gsl_steffen");
}
