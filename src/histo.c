/* docs/method.md §12: a rate from bin totals.  Four cubic trigonometric
 * pieces per bin (knots at the edges and the quarter points), C¹
 * everywhere and C² where the bounds allow, each bin's integral its total,
 * lo <= r <= hi proved by the control values (§12.3–§12.5). */
#include "internal.h"

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* §12.2: a piece's mean is W0 (B0 + B3) + W1 (B1 + B2) */
#define HW1 0.33427249868113159128 /* 22/(3π) − 2 */
#define HW0 0.16572750131886840872 /* 5/2 − 22/(3π) */
/* §12.4: limits scaled by this keep every rounded control value inside */
#define HSHRINK (1.0 - 8.0 * DBL_EPSILON)
#define HMEAN_MAX TS__HISTO_MEAN_MAX /* §12.6: the largest |mean − lo| accepted */
#define HP 4          /* pieces per bin */
#define HB (4 * HP)   /* control values per bin */
#define HCHUNK 64     /* bins listed at a time (no branch on the data) */
#define HSUB 32       /* cells of ts_histo_subdivide's table */

struct ts_histo {
    size_t n;
    double lo, hi, H; /* H = hi − lo (+inf without an upper bound) */
    double hf;        /* hi, or 0.5 without one: a finite factor (clamp_w) */
    double *e;        /* n + 1 edges */
    double *B;        /* HB per bin: the HP pieces' control values minus lo */
    double *tot;      /* n: ∫ r over the bin from the pieces (lo included) */
};

static void options_defaults(ts_histo_options *opt)
{
    memset(opt, 0, sizeof *opt);
    opt->struct_size = sizeof *opt;
    opt->alpha = TS_DEFAULT_ALPHA;
    opt->lo = 0.0;
    opt->hi = HUGE_VAL;
}

static void release(ts_histo *h);

void ts_histo_options_init(ts_histo_options *opt)
{
    if (opt)
        options_defaults(opt);
}

/* The bin's mean minus lo; within 4 ulps of a bound it is taken on it
 * (totals formed as lo·w or hi·w, §12.6). */
TS_INLINE double rho_of(const double *e, const double *T, size_t j, double lo, double hi)
{
    double m = T[j] / (e[j + 1] - e[j]), r = m - lo, H = hi - lo;
    if (0.0 <= r && r <= H)
        return r;
    /* the larger magnitude of m and lo (hi): fmax, lo and hi being numbers */
    double am = fabs(m), al = fabs(lo), ah = fabs(hi);
    double tl = 4.0 * DBL_EPSILON * (am > al ? am : al);
    double th = 4.0 * DBL_EPSILON * (am > ah ? am : ah);
    r = (r < 0.0 && r >= -tl) ? 0.0 : r;
    return (r > H && r <= H + th) ? H : r;
}

/* The checks of analyse's first two loops at once (a vector loop), and
 * rho: 1 when every edge and bin passes them (then rho is analyse's). */
TS_VECTOR_LOOP static int scan_bins(const double *restrict e, const double *restrict T, size_t n,
                                    double lo, double hi, double *restrict rho)
{
    /* increasing between finite ends: every edge finite */
    int ok = (fabs(e[0]) <= DBL_MAX) & (fabs(e[n]) <= DBL_MAX);
    for (size_t i = 1; i <= n; i++) {
        double w = e[i] - e[i - 1];
        ok &= (e[i] > e[i - 1]) & (DBL_MIN <= w) & (w <= DBL_MAX);
    }
    double H = hi - lo;
    for (size_t j = 0; j < n; j++) {
        double r = rho_of(e, T, j, lo, hi);
        rho[j] = r;
        ok &= (fabs(T[j]) <= DBL_MAX) & (fabs(r) <= HMEAN_MAX) & (0.0 <= r) & (r <= H);
    }
    return ok;
}

/* §12.4: the value at an inner edge between bins of means (minus lo) p, q */
TS_INLINE double edge_y(double p, double q, double H)
{
    double mn = p < q ? p : q, mx = p < q ? q : p;
    double ub = 2.0 * mn, lb = 2.0 * mx - H;
    ub = ub < H ? ub : H;
    lb = lb > 0.0 ? lb : 0.0;
    /* harmonic mean; a vector loop forms the quotient in every lane, so a
       zero denominator (mn = mx = 0, result unused) is replaced by 1: no
       0/0 and no flag on valid input */
    double d = mn + mx > 0.0 ? mn + mx : 1.0;
    double y = mn > 0.0 ? 2.0 * mn * (mx / d) : 0.0;
    y = y < lb ? lb : y;
    return y > ub ? ub : y;
}

/* edge_y, and whether the bounds leave it no room (*bad) */
static double edge_value(double p, double q, double H, int *bad)
{
    double mn = p < q ? p : q, mx = p < q ? q : p;
    double ub = 2.0 * mn, lb = 2.0 * mx - H;
    ub = ub < H ? ub : H;
    lb = lb > 0.0 ? lb : 0.0;
    *bad = lb > ub;
    return edge_y(p, q, H);
}

/* edge_y at the inner edges 1 .. n − 1 (a vector loop: no branch on the data) */
TS_VECTOR_LOOP static void edge_values(const double *restrict rho, double *restrict y, size_t n,
                                       double H)
{
    for (size_t j = 1; j < n; j++)
        y[j] = edge_y(rho[j - 1], rho[j], H);
}

static void set_status(ts_status *st, size_t j, ts_status s)
{
    if (st && st[j] == TS_OK)
        st[j] = s;
}

/* The checks of ts_histo_new in their order; st (may be NULL) per bin. */
static ts_status analyse(const double *e, const double *T, size_t n, const ts_histo_options *o,
                         ts_status *st, double *rho, ts_error *err)
{
    ts_status first = TS_OK;
    size_t fi = TS_NO_INDEX;
    ts_where fw = TS_WHERE_NONE;
#define HFAIL(S, I, W)                                                                   \
    do {                                                                                 \
        if (first == TS_OK) {                                                            \
            first = (S);                                                                 \
            fi = (I);                                                                    \
            fw = (W);                                                                    \
        }                                                                                \
    } while (0)
    if (st)
        for (size_t j = 0; j < n; j++)
            st[j] = TS_OK;
    int fast = rho && scan_bins(e, T, n, o->lo, o->hi, rho), edges_ok = 1;
    for (size_t i = 0; i <= n && !fast; i++) {
        ts_status s = TS_OK;
        if (!isfinite(e[i]))
            s = TS_ERR_NONFINITE;
        else if (i > 0 && isfinite(e[i - 1])) {
            double w = e[i] - e[i - 1];
            if (!(e[i] > e[i - 1]))
                s = TS_ERR_UNSORTED;
            else if (!(DBL_MIN <= w && w <= DBL_MAX))
                s = TS_ERR_WIDTH;
        }
        if (s != TS_OK) {
            edges_ok = 0;
            HFAIL(s, i, TS_WHERE_POINT);
            if (i > 0)
                set_status(st, i - 1, s);
            if (i < n)
                set_status(st, i, s);
        }
    }
    int plain = o->lo == 0.0 && o->hi == HUGE_VAL;
    double H = o->hi - o->lo;
    for (size_t j = 0; j < n && edges_ok && !fast; j++) {
        ts_status s = TS_OK;
        double r = isfinite(T[j]) ? rho_of(e, T, j, o->lo, o->hi) : (double)NAN;
        if (rho)
            rho[j] = r;
        if (!isfinite(T[j]))
            s = TS_ERR_NONFINITE;
        else if (!(fabs(r) <= HMEAN_MAX))
            s = TS_ERR_TOO_LARGE;
        else if (!(0.0 <= r && r <= H))
            s = plain ? TS_ERR_NEGATIVE : TS_ERR_INFEASIBLE;
        if (s != TS_OK) {
            HFAIL(s, j, TS_WHERE_INTERVAL);
            set_status(st, j, s);
        }
    }
    /* §12.4: neighbours the scheme cannot join (only with an upper bound) */
    for (size_t j = 1; j < n && edges_ok && first == TS_OK && H < HUGE_VAL; j++) {
        int bad;
        (void)edge_value(rho_of(e, T, j - 1, o->lo, o->hi), rho_of(e, T, j, o->lo, o->hi), H, &bad);
        if (bad) { /* the first failure: the loop runs while there is none */
            first = TS_ERR_INFEASIBLE;
            fi = j - 1;
            fw = TS_WHERE_INTERVAL;
            set_status(st, j - 1, TS_ERR_INFEASIBLE);
            set_status(st, j, TS_ERR_INFEASIBLE);
        }
    }
    /* later bins' infeasible edges for the per-bin status as well */
    for (size_t j = 1; j < n && edges_ok && st && first != TS_OK && H < HUGE_VAL; j++) {
        double p = rho_of(e, T, j - 1, o->lo, o->hi), q = rho_of(e, T, j, o->lo, o->hi);
        int bad;
        if (!(0.0 <= p && p <= H && 0.0 <= q && q <= H))
            continue;
        (void)edge_value(p, q, H, &bad);
        if (bad) {
            set_status(st, j - 1, TS_ERR_INFEASIBLE);
            set_status(st, j, TS_ERR_INFEASIBLE);
        }
    }
#undef HFAIL
    if (first != TS_OK)
        return ts__fail(err, first, fi, fw);
    return TS_OK;
}

/* Arguments and options, shared by ts_histo_new and ts_histo_check. */
static ts_status check_args(const double *edges, const double *totals, size_t n_bins,
                            const ts_histo_options *opt, ts_histo_options *o, ts_error *err)
{
    if (!edges || !totals)
        return ts__fail(err, TS_ERR_NULL, TS_NO_INDEX, TS_WHERE_NONE);
    if (opt && opt->struct_size != sizeof *opt)
        return ts__fail(err, TS_ERR_VERSION, TS_NO_INDEX, TS_WHERE_NONE);
    if (opt)
        *o = *opt;
    else
        options_defaults(o);
    if (n_bins == 0)
        return ts__fail(err, TS_ERR_TOO_FEW, TS_NO_INDEX, TS_WHERE_NONE);
    if (!ts__alpha_ok(o->alpha))
        return ts__fail(err, TS_ERR_ALPHA, TS_NO_INDEX, TS_WHERE_NONE);
    if (!(fabs(o->lo) <= HMEAN_MAX) || !(o->lo < o->hi) || !(o->hi - o->lo > 0.0))
        return ts__fail(err, TS_ERR_OPTION, TS_NO_INDEX, TS_WHERE_NONE);
    return TS_OK;
}

ts_status ts_histo_check(const double *edges, const double *totals, size_t n_bins,
                         const ts_histo_options *opt, ts_status *status, ts_error *err)
{
    ts__error_set(err, TS_OK, TS_NO_INDEX, TS_WHERE_NONE);
    ts_histo_options o;
    ts_status s = check_args(edges, totals, n_bins, opt, &o, err);
    if (s != TS_OK)
        return s;
    return analyse(edges, totals, n_bins, &o, status, NULL, err);
}

/* §12.3: the inverse of the matrix of (12.3) times 2400 (exact: its
 * determinant is −2400); rows Y1, Y2, Y3, E1, E2, E3, columns the
 * right-hand sides (integral, C² at the three inner knots, r'' at the
 * left and right edges). */
static const double HINV[6][6] = {
    {240, 280, -40, 40, 1100, -140},  {1920, -240, 0, 240, -960, -960},
    {240, -40, 40, -280, -140, 1100}, {240, 280, -40, 40, -100, -140},
    {0, -80, 320, -80, -160, 160},    {-240, 40, -40, 280, 140, 100}};

/* The power of 2 b is scaled by before HINV: 1 unless some |b_k| exceeds
 * 2^1008, where Σ |HINV_k| |b_k| <= 11520 · 2^1008 < 2^1022.5 would no
 * longer bound the sums of hrow below DBL_MAX (§12.6: means up to 2^1019);
 * then 2^-16.  A power of 2 commutes with every rounding of hrow and the
 * division by 2400 (no result near the subnormal range: the largest term
 * is above 2^992), so the scaled X is 2^16 times the X of b 2^-16 bit for
 * bit, and with scale 1 every value is as before. */
TS_INLINE double hscale(const double b[6])
{
    double m = fabs(b[0]);
    for (int k = 1; k < 6; k++)
        m = fabs(b[k]) > m ? fabs(b[k]) : m;
    return m > 0x1p1008 ? 0x1p-16 : 1.0;
}

/* Σ_k R[k] b[k] from 0, in order (one row of HINV times b) */
TS_INLINE double hrow(const double R[6], const double b[6])
{
    double s = 0.0;
    s += R[0] * b[0];
    s += R[1] * b[1];
    s += R[2] * b[2];
    s += R[3] * b[3];
    s += R[4] * b[4];
    s += R[5] * b[5];
    return s;
}

/* The control values of a bin from its knot values Y[0..4] and scaled
 * slopes E = K_q·slope (§12.3). */
static void controls(const double *Y, const double *E, double *B)
{
    for (int k = 0; k < HP; k++) {
        B[4 * k] = Y[k];
        B[4 * k + 1] = Y[k] + E[k];
        B[4 * k + 2] = Y[k + 1] - E[k + 1];
        B[4 * k + 3] = Y[k + 1];
    }
}

static int inside(const double *B, double H)
{
    int ok = 1;
    for (int l = 0; l < HB; l++)
        ok &= (0.0 <= B[l]) & (B[l] <= H);
    return ok;
}

/* §12.3: bin j from its edge values y, edge slopes sg (a bin whose C²
 * solution X wet_fast found outside [0, H]): X blended with the flat
 * solution Z by the largest λ in [0, 1] that keeps every control value in
 * [0, H], else Z itself, whose rounded control values are in [0, H]
 * (§12.6.1). */
static void build_wet(ts_histo *h, size_t j, double rho, const double *y, const double *sg)
{
    double *B = h->B + HB * j;
    double w = h->e[j + 1] - h->e[j], Kq = w / (6.0 * TS_PI), H = h->H;
    double Y0 = y[j], Y4 = y[j + 1], E0 = Kq * sg[j], E4 = Kq * sg[j + 1];
    /* (12.3) with r'' = 0 at the edges */
    double b[6] = {4.0 * rho - 0.5 * (Y0 + Y4) - HW1 * (E0 - E4), -Y0 - E0, 0.0, Y4 - E4,
                   2.0 * Y0 + 8.0 * E0, 2.0 * Y4 - 8.0 * E4};
    double sc = hscale(b), bs[6], us = 1.0 / sc;
    for (int k = 0; k < 6; k++)
        bs[k] = sc * b[k];
    double YX[5] = {Y0, hrow(HINV[0], bs) / 2400.0 * us, hrow(HINV[1], bs) / 2400.0 * us,
                    hrow(HINV[2], bs) / 2400.0 * us, Y4};
    double EX[5] = {E0, hrow(HINV[3], bs) / 2400.0 * us, hrow(HINV[4], bs) / 2400.0 * us,
                    hrow(HINV[5], bs) / 2400.0 * us, E4};
    /* b0/3 > 0 for a wet bin (§12.6.1); the clamps keep Z inside regardless */
    double zv = b[0] / 3.0;
    zv = zv > 0.0 ? zv : 0.0;
    zv = zv < H ? zv : H;
    double YZ[5] = {Y0, zv, zv, zv, Y4}, EZ[5] = {E0, 0.0, 0.0, 0.0, E4};
    double BZ[HB], BX[HB];
    controls(YZ, EZ, BZ);
    controls(YX, EX, BX);
    double lam = 1.0;
    for (int l = 0; l < HB; l++) {
        double z = BZ[l], x = BX[l];
        if (!isfinite(x))
            lam = 0.0;
        else if (x < 0.0)
            lam = fmin(lam, z / (z - x));
        else if (x > H)
            lam = fmin(lam, (H - z) / (x - z));
    }
    /* the control values are linear in the knot data: blend them directly
     * (the edge ones are the same in X and Z, so they stay exact); λ
     * rounded to 1 keeps X, which may then be outside by rounding */
    if (lam == 1.0) {
        memcpy(B, BX, sizeof BX);
    } else {
        lam = lam > 0.0 ? lam * HSHRINK : 0.0;
        for (int l = 0; l < HB; l++)
            B[l] = BZ[l] + lam * (BX[l] - BZ[l]);
    }
    if (!inside(B, H))
        memcpy(B, BZ, sizeof BZ); /* inside: §12.6.1 */
}

/* *mn, *mx updated with v (the least and largest control value) */
TS_INLINE void min_max(double v, double *mn, double *mx)
{
    *mn = v < *mn ? v : *mn;
    *mx = v > *mx ? v : *mx;
}

/* The fast path of build_wet for m wet bins at once (a vector loop): from
 * each bin's mean r, edge values Y0, Y4, edge slopes s0, s4 and width w, X
 * of (12.3), its control values (Bt[l HCHUNK + i]), whether they are all
 * finite and in [0, H] (ok: then they are the bin's, as build_wet's) and
 * the bin's total (bin_total's sums; lo added). */
TS_VECTOR_LOOP static void wet_fast(size_t m, const double *restrict r, const double *restrict Y0a,
                                    const double *restrict Y4a, const double *restrict s0a,
                                    const double *restrict s4a, const double *restrict wa,
                                    double H, double lo, double *restrict Bt,
                                    double *restrict tt, int *restrict ok)
{
    for (size_t i = 0; i < m; i++) {
        double w = wa[i], Kq = w / (6.0 * TS_PI);
        double Y0 = Y0a[i], Y4 = Y4a[i], E0 = Kq * s0a[i], E4 = Kq * s4a[i];
        double b[6] = {4.0 * r[i] - 0.5 * (Y0 + Y4) - HW1 * (E0 - E4), -Y0 - E0, 0.0, Y4 - E4,
                       2.0 * Y0 + 8.0 * E0, 2.0 * Y4 - 8.0 * E4};
        double sc = hscale(b), us = 1.0 / sc;
        for (int k = 0; k < 6; k++)
            b[k] *= sc;
        double Y1 = hrow(HINV[0], b) / 2400.0 * us, Y2 = hrow(HINV[1], b) / 2400.0 * us,
               Y3 = hrow(HINV[2], b) / 2400.0 * us;
        double E1 = hrow(HINV[3], b) / 2400.0 * us, E2 = hrow(HINV[4], b) / 2400.0 * us,
               E3 = hrow(HINV[5], b) / 2400.0 * us;
        double sf = Y1 + Y2 + Y3 + E1 + E2 + E3;
        /* the control values (controls) piece by piece: Y_k, Y_k + E_k,
         * Y_{k+1} − E_{k+1}, Y_{k+1} */
        double P01 = Y0 + E0, P02 = Y1 - E1, P11 = Y1 + E1, P12 = Y2 - E2;
        double P21 = Y2 + E2, P22 = Y3 - E3, P31 = Y3 + E3, P32 = Y4 - E4;
        double mn = Y0 < Y1 ? Y0 : Y1, mx = Y0 > Y1 ? Y0 : Y1;
        min_max(Y2, &mn, &mx), min_max(Y3, &mn, &mx), min_max(Y4, &mn, &mx);
        min_max(P01, &mn, &mx), min_max(P02, &mn, &mx), min_max(P11, &mn, &mx);
        min_max(P12, &mn, &mx), min_max(P21, &mn, &mx), min_max(P22, &mn, &mx);
        min_max(P31, &mn, &mx), min_max(P32, &mn, &mx);
        ok[i] = (sf - sf == 0.0) & (0.0 <= mn) & (mx <= H) & (mx <= DBL_MAX);
        double *o = Bt + i;
        o[0] = Y0, o[HCHUNK] = P01, o[2 * HCHUNK] = P02, o[3 * HCHUNK] = Y1;
        o[4 * HCHUNK] = Y1, o[5 * HCHUNK] = P11, o[6 * HCHUNK] = P12, o[7 * HCHUNK] = Y2;
        o[8 * HCHUNK] = Y2, o[9 * HCHUNK] = P21, o[10 * HCHUNK] = P22, o[11 * HCHUNK] = Y3;
        o[12 * HCHUNK] = Y3, o[13 * HCHUNK] = P31, o[14 * HCHUNK] = P32, o[15 * HCHUNK] = Y4;
        /* bin_total's sums */
        double q = 0.25 * w, t = 0.0;
        t += q * (HW0 * (Y0 + Y1) + HW1 * (P01 + P02));
        t += q * (HW0 * (Y1 + Y2) + HW1 * (P11 + P12));
        t += q * (HW0 * (Y2 + Y3) + HW1 * (P21 + P22));
        t += q * (HW0 * (Y3 + Y4) + HW1 * (P31 + P32));
        tt[i] = t + lo * w;
    }
}

/* A dry bin (§12.4): X = Z = 0 */
static inline int dry(double rho, const double *y, const double *sg, size_t j)
{
    return (rho == 0.0) & (y[j] == 0.0) & (y[j + 1] == 0.0) & (sg[j] == 0.0) & (sg[j + 1] == 0.0);
}

static int bin_inside(const ts_histo *h, size_t j)
{
    return inside(h->B + HB * j, h->H);
}

/* §12.2: ∫ of a piece of width hh over its whole width */
TS_INLINE double piece_total(const double *P, double hh)
{
    return hh * (HW0 * (P[0] + P[3]) + HW1 * (P[1] + P[2]));
}

/* a / b for b > 0 (not NaN): ±∞ where it overflows, without raising
 * FE_OVERFLOW (§12.6).  |a| < 2^1022 b cannot overflow (2^1022 b is exact
 * for b < 1).  Otherwise |a| >= 2^-52, so |a| 2^-100 and b 2^1000 are
 * exact and their quotient is normal, in [2^-78, 2^998]: it is a / b
 * rounded, times 2^-1100 exactly, and a / b rounds to 2^1024 or above
 * (overflows) exactly where it is at least 2^-76. */
static double quot(double a, double b)
{
    if (b >= 1.0 || fabs(a) < 0x1p1022 * b)
        return a / b;
    return fabs(a) * 0x1p-100 / (b * 0x1p1000) >= 0x1p-76 ? copysign(HUGE_VAL, a) : a / b;
}

/* §12.4: the slope at inner edge j, limited by the room its value and
 * both bins leave (y[j] neither 0 nor H).  The limits and the central
 * difference may exceed DBL_MAX on narrow bins (means near the limit over
 * widths near DBL_MIN): quot gives the ∞ they rounded to, without
 * FE_OVERFLOW (an infinite limit does not bind; both infinite: slope 0). */
static double edge_slope(const double *edges, const double *rho, const double *y, double H,
                         double alpha, size_t j)
{
    double wl = edges[j] - edges[j - 1], wr = edges[j + 1] - edges[j];
    double Kl = wl / (3.0 * TS_PI), Kr = wr / (3.0 * TS_PI);
    double room = y[j] < H - y[j] ? y[j] : H - y[j];
    double L = quot(room, Kl > Kr ? Kl : Kr);
    for (int side = 0; side < 2; side++) {
        size_t b = j - 1 + (size_t)side;
        double m = 0.5 * (y[b] + y[b + 1]);
        double sl = 2.0 * rho[b] - m, sh = H - 2.0 * rho[b] + m;
        double slack = sl < sh ? sl : sh;
        double Lb = quot(slack, 4.0 * HW1 * (side ? Kr : Kl));
        L = Lb < L ? Lb : L;
    }
    L *= HSHRINK;
    /* the half sum of the widths: wl + wr overflows where both are near
     * DBL_MAX; halving first is exact there (both >= 2^-1021) or loses
     * only a width far below half an ulp of the other: the same double */
    double hw = wl < 0x1p1022 && wr < 0x1p1022 ? 0.5 * (wl + wr) : 0.5 * wl + 0.5 * wr;
    double d = quot(quot(rho[j] - rho[j - 1], hw), alpha);
    d = d < L ? d : L;
    d = d > -L ? d : -L;
    return isfinite(d) ? d : 0.0;
}

/* ∫ r over a bin of width w and control values B (lo included) */
static inline double bin_total(const double *B, double w, double lo)
{
    double q = 0.25 * w, t = 0.0;
    for (int k = 0; k < HP; k++)
        t += piece_total(B + 4 * k, q);
    return t + lo * w;
}

ts_status ts_histo_new(const double *edges, const double *totals, size_t n_bins,
                       const ts_histo_options *opt, ts_histo **out, ts_error *err)
{
    ts__error_set(err, TS_OK, TS_NO_INDEX, TS_WHERE_NONE);
    if (out)
        *out = NULL;
    if (!out)
        return ts__fail(err, TS_ERR_NULL, TS_NO_INDEX, TS_WHERE_NONE);
    ts_histo_options o;
    ts_status st = check_args(edges, totals, n_bins, opt, &o, err);
    if (st != TS_OK)
        return st;
    /* doubles: e (n+1), B (HB n), tot (n), y (n+1), sg (n+1), rho (n) */
    if (n_bins > (SIZE_MAX / sizeof(double) - 3) / (HB + 4))
        return ts__fail(err, TS_ERR_OVERFLOW, TS_NO_INDEX, TS_WHERE_NONE);
    size_t n = n_bins;
    ts_histo *h = ts__calloc(1, sizeof *h);
    double *work = ts__malloc((3 * n + 2) * sizeof(double));
    if (h)
        h->e = ts__calloc((HB + 2) * n + 1, sizeof(double)); /* B +0: the dry bins' */
    if (!h || !h->e || !work) {
        free(work);
        release(h);
        return ts__fail(err, TS_ERR_NOMEM, TS_NO_INDEX, TS_WHERE_NONE);
    }
    double *y = work, *sg = work + (n + 1), *rho = work + 2 * (n + 1);
    st = analyse(edges, totals, n_bins, &o, NULL, rho, err);
    if (st != TS_OK) {
        free(work);
        release(h);
        return st;
    }
    h->n = n;
    h->lo = o.lo;
    h->hi = o.hi;
    h->hf = o.hi < HUGE_VAL ? o.hi : 0.5;
    h->H = o.hi - o.lo;
    h->B = h->e + (n + 1);
    h->tot = h->B + HB * n;
    memcpy(h->e, edges, (n + 1) * sizeof(double));
    /* §12.4: edge values, then the room each bin leaves for its edge slopes */
    y[0] = rho[0];
    y[n] = rho[n - 1];
    edge_values(rho, y, n, h->H);
    /* slack of bin j: min(2ρ − (yl + yr)/2, H − 2ρ + (yl + yr)/2) >= 0 */
    sg[0] = sg[n] = 0.0;
    /* inner edges in chunks: those whose slope limit is not 0 listed first
     * (without a branch on the data), then their slopes (§12.4) */
    for (size_t j0 = 1; j0 < n; j0 += HCHUNK) {
        size_t j1 = n - j0 < HCHUNK ? n : j0 + HCHUNK, list[HCHUNK], m = 0;
        for (size_t j = j0; j < j1; j++) {
            sg[j] = 0.0;
            list[m] = j;
            m += (size_t)((y[j] != 0.0) & (y[j] != h->H));
        }
        for (size_t i = 0; i < m; i++)
            sg[list[i]] = edge_slope(edges, rho, y, h->H, o.alpha, list[i]);
    }
    /* bins in chunks: the wet ones listed (no branch on the data), every
     * total lo w (a dry bin's: bin_total of +0s; its control values are the
     * +0s of calloc), the wet ones built together (wet_fast) and written, the
     * scalar build where one of theirs falls outside (then inside: §12.6.1) */
    for (size_t j0 = 0; j0 < n; j0 += HCHUNK) {
        size_t j1 = n - j0 < HCHUNK ? n : j0 + HCHUNK, list[HCHUNK], m = 0;
        for (size_t j = j0; j < j1; j++) {
            h->tot[j] = 0.0 + o.lo * (edges[j + 1] - edges[j]); /* bin_total of +0s */
            list[m] = j;
            m += (size_t)!dry(rho[j], y, sg, j);
        }
        double r[HCHUNK], Y0[HCHUNK], Y4[HCHUNK], s0[HCHUNK], s4[HCHUNK], w[HCHUNK];
        double Bt[HB * HCHUNK], tt[HCHUNK];
        int ok[HCHUNK];
        for (size_t i = 0; i < m; i++) {
            size_t j = list[i];
            r[i] = rho[j];
            Y0[i] = y[j];
            Y4[i] = y[j + 1];
            s0[i] = sg[j];
            s4[i] = sg[j + 1];
            w[i] = h->e[j + 1] - h->e[j];
        }
        wet_fast(m, r, Y0, Y4, s0, s4, w, h->H, o.lo, Bt, tt, ok);
        for (size_t i = 0; i < m; i++) {
            size_t j = list[i];
            double *B = h->B + HB * j;
            if (ok[i]) {
                for (int l = 0; l < HB; l++)
                    B[l] = Bt[(size_t)l * HCHUNK + i];
                h->tot[j] = tt[i];
                continue;
            }
            build_wet(h, j, rho[j], y, sg);
            h->tot[j] = bin_total(B, edges[j + 1] - edges[j], o.lo);
        }
    }
    for (size_t j = 0; j < n; j++) {
        if (!isfinite(h->tot[j])) {
            free(work);
            release(h);
            return ts__fail(err, TS_ERR_TOO_LARGE, j, TS_WHERE_INTERVAL);
        }
    }
    free(work);
    *out = h;
    return TS_OK;
}

static void release(ts_histo *h)
{
    if (!h)
        return;
    free(h->e);
    free(h);
}

void ts_histo_free(ts_histo *h)
{
    release(h);
}

size_t ts_histo_bins(const ts_histo *h)
{
    return h ? h->n : 0;
}

/* The bin holding x (x in [e_0, e_n]); the last bin holds e_n. */
static size_t find_bin(const ts_histo *h, double x)
{
    return ts__search(h->e, h->n, x, NULL);
}

/* The piece of bin j holding x, its distance from the piece's nearer end
 * and whether that is its right end (§12.5). */
static const double *locate_piece(const ts_histo *h, size_t j, double x, double *dist, int *rev)
{
    double e0 = h->e[j], e1 = h->e[j + 1], q = 0.25 * (e1 - e0);
    double dl = x - e0, dre = e1 - x, dL, dR;
    int k;
    if (dl <= dre) {
        k = dl > q ? 1 : 0;
        dL = dl - k * q;
        dR = (k + 1) * q - dl;
    } else {
        int kr = dre > q ? 1 : 0;
        k = HP - 1 - kr;
        dR = dre - kr * q;
        dL = (kr + 1) * q - dre;
    }
    *rev = dL > dR;
    double d = *rev ? dR : dL;
    *dist = d > 0.0 ? d : 0.0;
    return h->B + HB * j + 4 * k;
}

/* §12.5: r − lo and dr/dx at x in bin j. */
static void eval_in(const ts_histo *h, size_t j, double x, double *r, double *dr)
{
    double q = 0.25 * (h->e[j + 1] - h->e[j]), dist;
    int rev;
    const double *P = locate_piece(h, j, x, &dist, &rev);
    double Q[4];
    for (int l = 0; l < 4; l++)
        Q[l] = rev ? P[3 - l] : P[l];
    double u = TS_HALF_PI * (dist / q), s, c, ms, mc;
    ts__sincos_q(u, &s, &c, &ms, &mc);
    /* every factor >= 0: the sum of non-negative terms is >= 0 exactly */
    double A0 = ms * ms * ms, A1 = s * ms * (3.0 - s), A2 = c * mc * (3.0 - c), A3 = mc * mc * mc;
    *r = A0 * Q[0] + A1 * Q[1] + A2 * Q[2] + A3 * Q[3];
    if (dr) {
        double d = 3.0 * ms * ms * c * (Q[1] - Q[0]) + 2.0 * s * c * (Q[2] - Q[1]) +
                   3.0 * mc * mc * s * (Q[3] - Q[2]);
        /* π/(2q) overflows for q below about 2^-1023.35 (widths near
         * DBL_MIN), and times a zero sum gave NaN: there divide last */
        d = q >= 0x1p-1023 ? d * (TS_HALF_PI / q) : d * TS_HALF_PI / q;
        *dr = rev ? -d : d;
    }
}

static double clamp_rate(const ts_histo *h, double rr)
{
    double v = h->lo + rr;
    return v < h->hi ? v : h->hi;
}

ts_status ts_histo_eval(const ts_histo *h, double x, double *r, double *dr)
{
    if (r)
        *r = (double)NAN;
    if (dr)
        *dr = (double)NAN;
    if (!h || !r)
        return TS_ERR_NULL;
    if (!(h->e[0] <= x && x <= h->e[h->n]))
        return TS_ERR_DOMAIN;
    double rr;
    eval_in(h, find_bin(h, x), x, &rr, dr);
    *r = clamp_rate(h, rr);
    return TS_OK;
}

ts_status ts_histo_eval_batch(const ts_histo *h, const double *x, size_t m, double *r, double *dr,
                              ts_error *err)
{
    ts__error_set(err, TS_OK, TS_NO_INDEX, TS_WHERE_NONE);
    for (size_t k = 0; r && k < m; k++) {
        r[k] = (double)NAN;
        if (dr)
            dr[k] = (double)NAN;
    }
    if (!h || (m > 0 && (!x || !r)))
        return ts__fail(err, TS_ERR_NULL, TS_NO_INDEX, TS_WHERE_NONE);
    ts_cursor cur = {0};
    for (size_t k = 0; k < m; k++) {
        if (!(h->e[0] <= x[k] && x[k] <= h->e[h->n]))
            return ts__fail(err, TS_ERR_DOMAIN, k, TS_WHERE_QUERY);
        double rr;
        eval_in(h, ts__search(h->e, h->n, x[k], &cur), x[k], &rr, dr ? dr + k : NULL);
        r[k] = clamp_rate(h, rr);
    }
    return TS_OK;
}

/* ∫_0^θ A_l for θ in [0, π/4] (ts__basis_int with the kernels' sine and
 * cosine, ts__sincos_q: 1 − cos without cancellation). */
TS_INLINE void basis_int_q(double th, double I[4])
{
    double s, c, ms, mc;
    ts__sincos_q(th, &s, &c, &ms, &mc);
    double sc = s * c, is2 = 0.5 * (th - sc), ic2 = 0.5 * (th + sc);
    double is3 = mc * (2.0 - c - c * c) / 3.0, ic3 = s - s * s * s / 3.0;
    I[0] = th - 3.0 * mc + 3.0 * is2 - is3;
    I[1] = 3.0 * mc - 4.0 * is2 + is3;
    I[2] = 3.0 * s - 4.0 * ic2 + ic3;
    I[3] = th - 3.0 * s + 3.0 * ic2 - ic3;
}

/* §12.2: ∫ over [0, d] of the piece P of width hh, from the nearer end. */
static double piece_partial(const double *P, double hh, double d)
{
    double th = TS_HALF_PI * (d / hh), I[4];
    if (th <= 0.5 * TS_HALF_PI) {
        basis_int_q(th, I);
        return (hh / TS_HALF_PI) * (I[0] * P[0] + I[1] * P[1] + I[2] * P[2] + I[3] * P[3]);
    }
    double tm = TS_HALF_PI - th;
    tm = tm > 0.0 ? tm : 0.0;
    basis_int_q(tm, I);
    return piece_total(P, hh) -
           (hh / TS_HALF_PI) * (I[0] * P[3] + I[1] * P[2] + I[2] * P[1] + I[3] * P[0]);
}

/* ∫_{e_j}^x (r − lo) for x in bin j, from the nearer edge. */
static double bin_partial(const ts_histo *h, size_t j, double x)
{
    double e0 = h->e[j], e1 = h->e[j + 1], q = 0.25 * (e1 - e0);
    double dl = x - e0, dre = e1 - x, acc = 0.0;
    const double *B = h->B + HB * j;
    if (dl <= dre) {
        int k = dl > q ? 1 : 0;
        for (int i = 0; i < k; i++)
            acc += piece_total(B + 4 * i, q);
        return acc + piece_partial(B + 4 * k, q, dl - k * q);
    }
    int kr = dre > q ? 1 : 0;
    for (int i = 0; i < kr; i++)
        acc += piece_total(B + 4 * (HP - 1 - i), q);
    const double *P = B + 4 * (HP - 1 - kr);
    double Pr[4] = {P[3], P[2], P[1], P[0]};
    acc += piece_partial(Pr, q, dre - kr * q);
    return (h->tot[j] - h->lo * (e1 - e0)) - acc;
}

/* ∫_a^b r for e_0 <= a <= b <= e_n, bins ja, jb holding them. */
static double integral_ab(const ts_histo *h, double a, size_t ja, double b, size_t jb)
{
    if (ja == jb)
        return (bin_partial(h, ja, b) - bin_partial(h, ja, a)) + h->lo * (b - a);
    double s = h->tot[ja] - (bin_partial(h, ja, a) + h->lo * (a - h->e[ja]));
    for (size_t j = ja + 1; j < jb; j++)
        s += h->tot[j];
    return s + (bin_partial(h, jb, b) + h->lo * (b - h->e[jb]));
}

/* Within [lo, hi] times the width (rounding, §12.5). */
TS_INLINE double clamp_w(double lo, double hi, double hf, double v, double width)
{
    /* without an upper bound none; hi times the width formed as hf times
     * it, so that +inf times a zero width is never formed (no NaN, no
     * flag, also where a compiler evaluates both sides of a select) */
    double lw = lo * width, hw = hf * width;
    hw = hi < HUGE_VAL ? hw : HUGE_VAL;
    v = v > lw ? v : lw;
    return v < hw ? v : hw;
}

static double clamp_total(const ts_histo *h, double v, double width)
{
    return clamp_w(h->lo, h->hi, h->hf, v, width);
}

ts_status ts_histo_integral(const ts_histo *h, double a, double b, double *out)
{
    if (out)
        *out = (double)NAN;
    if (!h || !out)
        return TS_ERR_NULL;
    double e0 = h->e[0], en = h->e[h->n];
    if (!(e0 <= a && a <= en && e0 <= b && b <= en))
        return TS_ERR_DOMAIN;
    int neg = b < a;
    double p = neg ? b : a, q = neg ? a : b;
    double v = clamp_total(h, integral_ab(h, p, find_bin(h, p), q, find_bin(h, q)), q - p);
    *out = neg ? -v : v;
    return TS_OK;
}

/* Points staged at a time by ts_histo_totals */
#define HGRID 256

/* bin_partial's terms of the HGRID points of a block (struct-of-arrays) */
struct hstage {
    double d[HGRID], q[HGRID], acc[HGRID], base[HGRID], P[4][HGRID];
    int left[HGRID];
};

/* bin_partial up to its piece_partial, for point k at x in bin j: the
 * distance d into the partial piece from its nearer bin edge, that piece's
 * control values read from that edge, the whole pieces before it (acc) and
 * what the right edge's case subtracts from (base). */
TS_INLINE void stage_point(const ts_histo *h, size_t j, double x, struct hstage *st, size_t k)
{
    const double *Bj = h->B + HB * j;
    double e0 = h->e[j], e1 = h->e[j + 1], q = 0.25 * (e1 - e0);
    double dl = x - e0, dre = e1 - x;
    int left = dl <= dre;
    double dd = left ? dl : dre;
    int kk = dd > q ? 1 : 0;
    st->q[k] = q;
    st->left[k] = left;
    if (left) {
        const double *P = Bj + 4 * kk;
        st->acc[k] = kk ? 0.0 + piece_total(Bj, q) : 0.0;
        st->d[k] = dd - kk * q;
        st->base[k] = 0.0;
        st->P[0][k] = P[0];
        st->P[1][k] = P[1];
        st->P[2][k] = P[2];
        st->P[3][k] = P[3];
    } else {
        const double *P = Bj + 4 * (HP - 1 - kk);
        st->acc[k] = kk ? 0.0 + piece_total(Bj + 4 * (HP - 1), q) : 0.0;
        st->d[k] = dd - kk * q;
        st->base[k] = h->tot[j] - h->lo * (e1 - e0);
        st->P[0][k] = P[3];
        st->P[1][k] = P[2];
        st->P[2][k] = P[1];
        st->P[3][k] = P[0];
    }
}

/* The rest of bin_partial for m staged points (a vector loop: the same
 * operations in the same order, both cases of piece_partial in every lane
 * and the case selected; every lane's operands finite). */
TS_VECTOR_LOOP static void partials(const struct hstage *restrict st, size_t m, double *restrict G)
{
    for (size_t k = 0; k < m; k++) {
        double q = st->q[k], P0 = st->P[0][k], P1 = st->P[1][k], P2 = st->P[2][k], P3 = st->P[3][k];
        double th = TS_HALF_PI * (st->d[k] / q), tm = TS_HALF_PI - th;
        int near = th <= 0.5 * TS_HALF_PI;
        tm = tm > 0.0 ? tm : 0.0;
        double I[4];
        basis_int_q(near ? th : tm, I);
        double Q0 = near ? P0 : P3, Q1 = near ? P1 : P2, Q2 = near ? P2 : P1, Q3 = near ? P3 : P0;
        double S = (q / TS_HALF_PI) * (I[0] * Q0 + I[1] * Q1 + I[2] * Q2 + I[3] * Q3);
        double pt = q * (HW0 * (P0 + P3) + HW1 * (P1 + P2));
        double v = st->acc[k] + (near ? S : pt - S);
        G[k] = st->left[k] ? v : st->base[k] - v;
    }
}

/* The totals of the cells [x[i − 1], x[i]], i = 1 .. m − 1, as if both
 * ends were in one bin (integral_ab's first case, clamped), into out[i − 1]
 * (a vector loop; the caller redoes the cells that cross an edge). */
TS_VECTOR_LOOP static void same_bin(const double *restrict x, const double *restrict G, size_t m,
                                    double lo, double hi, double hf, double *restrict out)
{
    for (size_t i = 1; i < m; i++) {
        double w = x[i] - x[i - 1];
        out[i - 1] = clamp_w(lo, hi, hf, (G[i] - G[i - 1]) + lo * w, w);
    }
}

/* Whether every point is in [e0, en] and none below the one before (a
 * vector loop; then ts_histo_totals' checks all pass). */
TS_VECTOR_LOOP static int grid_ok(const double *restrict g, size_t m, double e0, double en)
{
    int ok = 1;
    for (size_t k = 0; k < m; k++)
        ok &= (e0 <= g[k]) & (g[k] <= en);
    for (size_t k = 1; k < m; k++)
        ok &= g[k] >= g[k - 1];
    return ok;
}

ts_status ts_histo_totals(const ts_histo *h, const double *grid, size_t m, double *out,
                          ts_error *err)
{
    ts__error_set(err, TS_OK, TS_NO_INDEX, TS_WHERE_NONE);
    for (size_t k = 0; out && k + 1 < m; k++)
        out[k] = (double)NAN;
    if (!h || (m >= 2 && (!grid || !out)))
        return ts__fail(err, TS_ERR_NULL, TS_NO_INDEX, TS_WHERE_NONE);
    if (m < 2)
        return TS_OK;
    double e0 = h->e[0], en = h->e[h->n];
    /* grid_ok's tests point by point: the first point failing one (k < m
     * when ok is 0: a point outside fails the first test here, and where
     * the first failure is the order, both points are inside, so not NaN,
     * and !(g_k >= g_k-1) is g_k < g_k-1) returns */
    int ok = grid_ok(grid, m, e0, en);
    for (size_t k = 0; !ok; k++) {
        if (!(e0 <= grid[k] && grid[k] <= en))
            return ts__fail(err, TS_ERR_DOMAIN, k, TS_WHERE_QUERY);
        if (k > 0 && grid[k] < grid[k - 1])
            return ts__fail(err, TS_ERR_UNSORTED, k, TS_WHERE_QUERY);
    }
    /* integral_ab's expressions, each point's partial integral formed once
     * (bin_partial, HGRID points at a time) */
    ts_cursor cur = {0};
    struct hstage st;
    size_t jb[HGRID], ja = 0;
    double G[HGRID + 1], Ga = 0.0;
    for (size_t k0 = 0; k0 < m; k0 += HGRID) {
        size_t nk = m - k0 < HGRID ? m - k0 : HGRID;
        for (size_t i = 0; i < nk; i++) {
            /* the cursor's bin when it holds the point, as ts__search (the
             * cursor is 0 or the bin of an earlier point: c < n and
             * e_c <= x, the points being sorted) */
            size_t c = cur.interval;
            double x = grid[k0 + i];
            jb[i] = x < h->e[c + 1] || c + 1 == h->n ? c : ts__search(h->e, h->n, x, &cur);
            stage_point(h, jb[i], x, &st, i);
        }
        /* G[0] the point before the block (G[1] the first of the block) */
        partials(&st, nk, G + 1);
        size_t i0 = k0 == 0 ? 1 : 0;
        G[0] = Ga;
        same_bin(grid + k0 - (1 - i0), G + i0, nk + 1 - i0, h->lo, h->hi, h->hf,
                 out + k0 - (1 - i0));
        for (size_t i = i0; i < nk; i++) { /* k >= 1 (i0 = 1 in the first block) */
            size_t k = k0 + i;
            size_t jprev = i > 0 ? jb[i - 1] : ja;
            if (jprev != jb[i]) {
                double a = grid[k - 1], b = grid[k], Gb = G[i + 1], v;
                v = h->tot[jprev] - (G[i] + h->lo * (a - h->e[jprev]));
                for (size_t j = jprev + 1; j < jb[i]; j++)
                    v += h->tot[j];
                v += Gb + h->lo * (b - h->e[jb[i]]);
                out[k - 1] = clamp_total(h, v, b - a);
            }
        }
        ja = jb[nk - 1];
        Ga = G[nk];
    }
    return TS_OK;
}

/* §12.5: ∫_0^θ A_l dθ for θ in [0, π/2] from the nearer end (the far half
 * as the whole integral minus the mirrored rest). */
static void basis_int_near(double th, double I[4])
{
    static const double full[4] = {1.25 * TS_PI - 11.0 / 3.0, 11.0 / 3.0 - TS_PI,
                                   11.0 / 3.0 - TS_PI, 1.25 * TS_PI - 11.0 / 3.0};
    if (th <= 0.5 * TS_HALF_PI) {
        ts__basis_int(th, sin(th), cos(th), I);
        return;
    }
    double tm = TS_HALF_PI - th, J[4];
    tm = tm > 0.0 ? tm : 0.0;
    ts__basis_int(tm, sin(tm), cos(tm), J);
    for (int l = 0; l < 4; l++)
        I[l] = full[l] - J[3 - l];
}

/* §12.5: ts_histo_subdivide's cells k0 .. k0 + nk − 1 of bins j0 .. j1 − 1
 * (out: their first cell) from the table (c: weight l of term t of cell k
 * at [(4 t + l) HSUB + k]; pk: the piece of each term; one: a cell inside
 * one piece; run: where the runs of cells inside the same piece start).
 * Every cell is first filled with lo's total (in order: the writes stream),
 * the bins not at lo (dry: r ≡ lo) listed without a branch on the data and
 * their runs evaluated with the piece's control values held. */
TS_VECTOR_LOOP static void cells_chunk(const double *restrict B, const double *restrict e,
                                       const double *restrict tot, size_t j0, size_t j1,
                                       size_t sub, size_t nk, const size_t *restrict run,
                                       int nrun, const int *restrict one,
                                       const int *restrict pk0, const int *restrict pk1,
                                       const double *restrict c, double lo, double hi,
                                       double *restrict out)
{
    size_t list[HCHUNK], m = 0;
    for (size_t j = j0; j < j1; j++) {
        double w = e[j + 1] - e[j], lc = lo * (w / (double)sub);
        int at_lo = tot[j] == lo * w;
        double *o = out + j * sub;
        for (size_t k = 0; k < nk; k++)
            o[k] = lc;
        list[m] = j;
        m += (size_t)!at_lo;
    }
    for (size_t i = 0; i < m; i++) {
        size_t j = list[i];
        const double *Bj = B + HB * j;
        double w = e[j + 1] - e[j], cw = w / (double)sub;
        double lc = lo * cw, hc = hi * cw; /* within [lo, hi] times the width */
        double *o = out + j * sub;
        for (int r = 0; r < nrun; r++) {
            size_t ka = run[r], kb = run[r + 1];
            const double *P = Bj + 4 * pk0[ka];
            if (one[ka]) {
                double P0 = P[0], P1 = P[1], P2 = P[2], P3 = P[3];
                for (size_t k = ka; k < kb; k++) {
                    double v = c[k] * P0 + c[HSUB + k] * P1 + c[2 * HSUB + k] * P2 +
                               c[3 * HSUB + k] * P3;
                    double x = w * v + lc;
                    x = x > lc ? x : lc;
                    o[k] = x < hc ? x : hc;
                }
                continue;
            }
            const double *Q = Bj + 4 * pk1[ka], *d = c + 4 * HSUB;
            double v = (c[ka] * P[0] + c[HSUB + ka] * P[1] + c[2 * HSUB + ka] * P[2] +
                        c[3 * HSUB + ka] * P[3]) +
                       (d[ka] * Q[0] + d[HSUB + ka] * Q[1] + d[2 * HSUB + ka] * Q[2] +
                        d[3 * HSUB + ka] * Q[3]);
            double x = w * v + lc;
            x = x > lc ? x : lc;
            o[ka] = x < hc ? x : hc;
        }
    }
}

ts_status ts_histo_subdivide(const ts_histo *h, size_t sub, double *out, ts_error *err)
{
    ts__error_set(err, TS_OK, TS_NO_INDEX, TS_WHERE_NONE);
    if (!h || !out)
        return ts__fail(err, TS_ERR_NULL, TS_NO_INDEX, TS_WHERE_NONE);
    if (sub == 0)
        return ts__fail(err, TS_ERR_OPTION, TS_NO_INDEX, TS_WHERE_NONE);
    if (h->n > SIZE_MAX / sub)
        return ts__fail(err, TS_ERR_OVERFLOW, TS_NO_INDEX, TS_WHERE_NONE);
    size_t n = h->n;
    if (sub == 1) { /* the cell is the bin: its total (a cell below meets at most two pieces) */
        for (size_t j = 0; j < n; j++)
            out[j] = clamp_total(h, h->tot[j], h->e[j + 1] - h->e[j]);
        return TS_OK;
    }
    /* cell k of every bin: the same weights on the control values (§12.5),
     * c[p][l] = (1/(2π)) (I_l(θ_b) − I_l(θ_a)) over its overlap with piece p,
     * times the width; a table of HSUB cells at a time (no allocation).  A
     * cell inside one piece has no second term (its weights are +0: adding
     * that ±0 changes no value once clamped to [lo, hi] times the width). */
    double c[2 * 4 * HSUB]; /* [term][l][cell] */
    int pk0[HSUB], pk1[HSUB], one[HSUB];
    double tprev = -1.0, Iprev[4] = {0.0, 0.0, 0.0, 0.0};
    for (size_t k0 = 0; k0 < sub; k0 += HSUB) {
        size_t k1 = sub - k0 < HSUB ? sub : k0 + HSUB;
        for (size_t k = k0; k < k1; k++) {
            double a = (double)k / (double)sub, b = (double)(k + 1) / (double)sub;
            int p0 = (int)(4.0 * a);
            p0 = p0 < HP - 1 ? p0 : HP - 1;
            one[k - k0] = 1;
            for (int t = 0; t < 2; t++) {
                int p = p0 + t < HP ? p0 + t : HP - 1;
                double q0 = 0.25 * p, q1 = 0.25 * (p + 1);
                double lo = a > q0 ? a : q0, hi = b < q1 ? b : q1;
                (t ? pk1 : pk0)[k - k0] = p;
                for (int l = 0; l < 4; l++)
                    c[(size_t)(4 * t + l) * HSUB + (k - k0)] = 0.0;
                if (!(lo < hi) || (t == 1 && p == p0))
                    continue;
                one[k - k0] = t == 0;
                double Ia[4], Ib[4], ta = TS_HALF_PI * 4.0 * (lo - q0);
                if (ta == tprev) /* the previous cell's right end */
                    memcpy(Ia, Iprev, sizeof Ia);
                else
                    basis_int_near(ta, Ia);
                tprev = TS_HALF_PI * 4.0 * (hi - q0);
                basis_int_near(tprev, Ib);
                memcpy(Iprev, Ib, sizeof Ib);
                for (int l = 0; l < 4; l++)
                    c[(size_t)(4 * t + l) * HSUB + (k - k0)] = (Ib[l] - Ia[l]) / (2.0 * TS_PI);
            }
        }
        /* runs of cells in the same single piece */
        size_t run[HSUB + 1];
        int nrun = 0;
        for (size_t k = k0; k < k1; k++)
            if (k == k0 || !one[k - k0] || !one[k - 1 - k0] || pk0[k - k0] != pk0[k - 1 - k0])
                run[nrun++] = k - k0;
        run[nrun] = k1 - k0;
        for (size_t j0 = 0; j0 < n; j0 += HCHUNK)
            cells_chunk(h->B, h->e, h->tot, j0, n - j0 < HCHUNK ? n : j0 + HCHUNK, sub, k1 - k0,
                        run, nrun, one, pk0, pk1, c, h->lo, h->hi, out + k0);
    }
    return TS_OK;
}

static void report_reset(ts_bin_report *rep)
{
    rep->struct_size = sizeof *rep;
    rep->e0 = rep->e1 = rep->total = rep->mean = (double)NAN;
    rep->r_min = rep->at_min = rep->r_max = rep->at_max = rep->guard = (double)NAN;
    for (int l = 0; l < 16; l++)
        rep->B[l] = (double)NAN;
    rep->certified = 0;
}

void ts_bin_report_init(ts_bin_report *rep)
{
    if (rep)
        report_reset(rep);
}

ts_status ts_histo_report(const ts_histo *h, size_t bin, ts_bin_report *rep)
{
    if (!rep)
        return TS_ERR_NULL;
    if (rep->struct_size != sizeof *rep)
        return TS_ERR_VERSION;
    report_reset(rep);
    if (!h)
        return TS_ERR_NULL;
    if (bin >= h->n)
        return TS_ERR_INDEX;
    double e0 = h->e[bin], e1 = h->e[bin + 1], q = 0.25 * (e1 - e0);
    rep->e0 = e0;
    rep->e1 = e1;
    rep->total = h->tot[bin];
    rep->mean = h->tot[bin] / (e1 - e0);
    memcpy(rep->B, h->B + HB * bin, sizeof rep->B);
    rep->certified = bin_inside(h, bin);
    double mn = HUGE_VAL, mx = -HUGE_VAL, g = 0.0;
    for (int p = 0; p < HP; p++) {
        const double *P = h->B + HB * bin + 4 * p;
        double x0 = e0 + p * q, th, tb, eb;
        double v = ts__trig_min_core(P[0], P[1], P[2], P[3], 0.0, &th, &tb, &eb);
        g = eb > g ? eb : g;
        if (v < mn) {
            mn = v;
            rep->at_min = x0 + (q / TS_HALF_PI) * th;
        }
        /* its guard is the minimum's (§12.5): g stays */
        v = -ts__trig_min_core(-P[0], -P[1], -P[2], -P[3], 0.0, &th, &tb, &eb);
        if (v > mx) {
            mx = v;
            rep->at_max = x0 + (q / TS_HALF_PI) * th;
        }
    }
    rep->r_min = h->lo + mn;
    rep->r_max = h->lo + mx;
    rep->guard = g;
    return TS_OK;
}
