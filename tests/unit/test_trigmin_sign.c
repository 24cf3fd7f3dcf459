/* The exact minimum of docs/method.md §5.6 with κ = 0 on C and on −C (the
 * minimum and the maximum of a piece, ts_histo_report, §12.5): the same
 * rounding guard bit for bit (the guard depends on |D_k|, max |C_l| and the
 * subdivision depth, which are the same for −C), and min(−C) = −max(C)
 * against dense sampling of the piece (within the guard plus the sampling
 * error: the curve's derivative times half the step, bounded by
 * 3 Σ|D_k| (π/2)/2 per unit of θ, §2). */
#include "th.h"
#include "internal.h"

#include <math.h>
#include <stdint.h>

static uint64_t rng = 0x2545f4914f6cdd1du;
static double urand(void)
{
    rng ^= rng << 13, rng ^= rng >> 7, rng ^= rng << 17;
    return (double)(rng >> 11) * 0x1p-53;
}

/* r at θ (the basis of §2: A_0 = (1 − sin)³, A_1 = sin (1 − sin)(3 − sin),
 * A_2 = cos (1 − cos)(3 − cos), A_3 = (1 − cos)³) */
static double piece(const double C[4], double th)
{
    double s = sin(th), c = cos(th), ms = 1.0 - s, mc = 1.0 - c;
    return ms * ms * ms * C[0] + s * ms * (3.0 - s) * C[1] + c * mc * (3.0 - c) * C[2] +
           mc * mc * mc * C[3];
}

int main(void)
{
    long both = 0, one = 0; /* minimum and maximum inside the piece; only one of them */
    long deeper = 0;        /* guards above the depth-0 guard: the isolation subdivided */
    for (int k = 0; k < 20000; k++) {
        double C[4], N[4];
        int kind = k % 4;
        for (int l = 0; l < 4; l++) {
            /* kind 0: any signs; 1: non-negative (histogram control values);
             * 2: small integers (ties, zeros); 3: values spread by 2^±40 */
            double u = urand();
            C[l] = kind == 0   ? 2.0 * u - 1.0
                   : kind == 1 ? u
                   : kind == 2 ? floor(5.0 * u) - 2.0
                               : ldexp(u, (int)(urand() * 80) - 40);
            N[l] = -C[l];
        }
        double th1, th2, t1, t2, g1, g2;
        double mn = ts__trig_min_core(C[0], C[1], C[2], C[3], 0.0, &th1, &t1, &g1);
        double mx = -ts__trig_min_core(N[0], N[1], N[2], N[3], 0.0, &th2, &t2, &g2);
        CHECKF(g1 == g2, "C = %a %a %a %a: guards %a, %a", C[0], C[1], C[2], C[3], g1, g2);
        double smin = HUGE_VAL, smax = -HUGE_VAL, slope = 0.0;
        for (int l = 0; l < 3; l++)
            slope += 3.0 * fabs(C[l + 1] - C[l]);
        for (int i = 0; i <= 512; i++) {
            double v = piece(C, TS_HALF_PI * i / 512.0);
            smin = fmin(smin, v), smax = fmax(smax, v);
        }
        double tol = g1 + slope * TS_HALF_PI / 1024.0 + 1e-15 * (fabs(smin) + fabs(smax));
        double rd = 1e-15 * (fabs(smin) + fabs(smax)); /* the sampling's own rounding */
        CHECKF(mn <= smin + g1 + rd && mn >= smin - tol, "C = %a %a %a %a: min %a, sampled %a", C[0],
               C[1], C[2], C[3], mn, smin);
        CHECKF(mx >= smax - g1 - rd && mx <= smax + tol, "C = %a %a %a %a: max %a, sampled %a", C[0],
               C[1], C[2], C[3], mx, smax);
        int in1 = th1 > 0.0 && th1 < TS_HALF_PI, in2 = th2 > 0.0 && th2 < TS_HALF_PI;
        both += in1 && in2;
        int e;
        double M = fmax(fmax(fabs(C[0]), fabs(C[1])), fmax(fabs(C[2]), fabs(C[3])));
        (void)frexp(M, &e);
        double c[4];
        for (int l = 0; l < 4; l++)
            c[l] = ldexp(C[l], -e);
        double babs = 3.0 * fabs(c[1] - c[0]) + 3.0 * fabs(c[2] - c[1]) + 24.0 * fabs(c[3] - c[2]);
        deeper += g1 > ldexp(ts__trig_min_guard(0, babs, ldexp(M, -e), 0.0), e);
        one += in1 != in2;
    }
    CHECKF(both > 500 && one > 2000 && deeper > 100, "both inside %ld, one inside %ld, deeper %ld", both, one,
           deeper);
    return th_report("test_trigmin_sign");
}
