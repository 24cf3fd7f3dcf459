/*
 * Convergence study of the trigonometric spline (docs/accuracy.md).
 *
 *   accuracy [--quick] [--doc FILE.md] [--svg FILE.svg]
 *
 * Max error |f - S| on a fine grid (15 points inside every interval) for
 * four functions, n = 10 ... 10000 intervals, uniform and randomly perturbed
 * grids, the three forms, exact slopes and every slope method, a = alpha +
 * beta in {0.5, 1, 2, mixed}, plus GSL steffen and natural cspline on the
 * same data.  Prints tables; --doc replaces the text between the markers
 * <!-- BEGIN RESULTS --> and <!-- END RESULTS --> of FILE.md with the
 * tables, --svg writes a log-log plot of error against n.  Built and run by
 * `make accuracy` (needs libgsl-dev, which that target installs).
 * Deterministic: fixed seeds, no clocks in the output.
 */
#include <gsl/gsl_errno.h>
#include <gsl/gsl_interp.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "trigspline.h"

#define PI 3.14159265358979323846
#define NN 7
#define NA 4
#define NS 7
#define NF 4
#define NFORM 3
#define SUB 16 /* samples per interval: j/SUB, j = 1..SUB-1 */

static const size_t ns_all[NN] = {10, 32, 100, 316, 1000, 3162, 10000};
static size_t nn = NN;

/* ---- test functions -------------------------------------------------- */
typedef struct fun {
    const char *name, *tex;
    double lo, hi;
    double (*f)(double), (*fp)(double);
    double m1, m2, m3; /* max |f'|, |f''|, |f'''| on [lo, hi] (closed forms, see docs) */
} fun;

static double f_sin(double x) { return sin(x); }
static double fp_sin(double x) { return cos(x); }
static double f_exp(double x) { return exp(x); }
static double fp_exp(double x) { return exp(x); }
static double f_runge(double x) { return 1.0 / (1.0 + 25.0 * x * x); }
static double fp_runge(double x)
{
    double q = 1.0 + 25.0 * x * x;
    return -50.0 * x / (q * q);
}
static double f_pos(double x) { return (x - 0.3) * (x - 0.3) + 1e-3; }
static double fp_pos(double x) { return 2.0 * (x - 0.3); }

/* Maxima of |f'|, |f''| on the interval (the bound check uses them):
 * sin: 1, 1; exp on [-1, 1]: e, e; Runge: f' = -50x/q^2, q = 1 + 25x^2, largest
 * at 25x^2 = 1/3: 90/(16 sqrt 3); f'' = -50(1 - 75x^2)/q^3, largest at 0: 50;
 * (x-0.3)^2 + 1e-3: 1.4, 2.  m3 (max |f'''|) is used only for sin. */
static fun funs[NF] = {
    {"sin", "sin x on [0, 3]", 0.0, 3.0, f_sin, fp_sin, 1.0, 1.0, 1.0},
    {"exp", "exp x on [-1, 1]", -1.0, 1.0, f_exp, fp_exp, 2.718281828459046, 2.718281828459046,
     2.718281828459046},
    {"runge", "1/(1+25x^2) on [-1, 1]", -1.0, 1.0, f_runge, fp_runge, 3.2475952641916446, 50.0, 0.0},
    {"pos", "(x-0.3)^2 + 1e-3 on [0, 1]", 0.0, 1.0, f_pos, fp_pos, 1.4, 2.0, 0.0},
};

static const char *form_name[NFORM] = {"paper", "C1", "geometric"};
static const double a_val[NA] = {0.5, 1.0, 2.0, -1.0}; /* -1: mixed, a_i in [0.5, 2] */
static const char *a_name[NA] = {"0.5", "1", "2", "mixed"};
static const char *slope_name[NS] = {"exact", "arith", "geomean", "harmonic", "FC", "Akima", "mAkima"};
static const ts_slopes slope_method[NS] = {TS_SLOPES_USER,     TS_SLOPES_ARITHMETIC,
                                           TS_SLOPES_GEOMETRIC, TS_SLOPES_HARMONIC,
                                           TS_SLOPES_FRITSCH_CARLSON, TS_SLOPES_AKIMA,
                                           TS_SLOPES_MAKIMA};

/* results */
static double err[NF][2][NFORM][NS][NA][NN];
static double bnd[NF][2][NFORM][NS][NA][NN];
static double gsl_err[NF][2][2][NN];
static long violations, bound_checks;

static unsigned long long rng_state;
static double urand(void)
{
    rng_state = rng_state * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(rng_state >> 11) / 9007199254740992.0;
}

static void make_grid(const fun *F, size_t n, int perturbed, double *x)
{
    double h = (F->hi - F->lo) / (double)n;
    rng_state = 12345u + n;
    for (size_t i = 0; i <= n; i++)
        x[i] = F->lo + h * (double)i;
    if (perturbed)
        for (size_t i = 1; i < n; i++)
            x[i] += 0.35 * h * (2.0 * urand() - 1.0);
    x[n] = F->hi;
}

/* max |f - S| at SUB-1 points inside every interval, from y at those points */
static double max_err(const fun *F, const double *xq, const double *yq, size_t m)
{
    double e = 0.0;
    for (size_t j = 0; j < m; j++) {
        double d = fabs(F->f(xq[j]) - yq[j]);
        if (!(d <= e))
            e = d; /* NaN propagates */
    }
    return e;
}

static double order_fit(const double *e, size_t k0, size_t k1)
{
    /* least-squares slope of -log e against log n over n index k0..k1 */
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    int m = 0;
    for (size_t k = k0; k <= k1; k++) {
        if (!(e[k] > 0))
            return NAN;
        double X = log((double)ns_all[k]), Y = -log(e[k]);
        sx += X, sy += Y, sxx += X * X, sxy += X * Y, m++;
    }
    return (m * sxy - sx * sy) / (m * sxx - sx * sx);
}

/* the paper's Theorem 1 constant C(a) = max_δ ∫_0^1 |K3(δ,τ)| dτ with
 * K3 = (δ-τ)_+^2 - s^2 (1-τ)^2 + 2κ A2 (1-τ) (docs/accuracy.md §4) */
static double k3_int(double a, double del)
{
    double th = 0.5 * PI * del, s = sin(th), c = cos(th), kap = 2.0 / (3.0 * PI * a);
    double A2 = c * (1 - c) * (3 - c), sum = 0.0;
    const int P = 2000; /* Simpson on [0, δ] and [δ, 1]; |K3| has kinks: error ~1e-9 */
    for (int part = 0; part < 2; part++) {
        double lo = part ? del : 0.0, hi = part ? 1.0 : del, hh = (hi - lo) / P;
        if (hi <= lo)
            continue;
        for (int j = 0; j <= P; j++) {
            double t = lo + hh * j, w = (j == 0 || j == P) ? 1 : (j % 2 ? 4 : 2);
            double dt = del - t > 0 ? del - t : 0;
            double K = dt * dt - s * s * (1 - t) * (1 - t) + 2 * kap * A2 * (1 - t);
            sum += w * fabs(K) * hh / 3;
        }
    }
    return sum;
}

static double theorem1_constant(double a)
{
    double best = 0, at = 0;
    for (int j = 0; j <= 200; j++) {
        double v = k3_int(a, j / 200.0);
        if (v > best)
            best = v, at = j / 200.0;
    }
    double lo = fmax(0, at - 0.005), hi = fmin(1, at + 0.005);
    for (int it = 0; it < 40; it++) {
        double p = lo + (hi - lo) * 0.382, q = lo + (hi - lo) * 0.618;
        if (k3_int(a, p) > k3_int(a, q))
            hi = q;
        else
            lo = p;
    }
    double v = k3_int(a, 0.5 * (lo + hi));
    return v > best ? v : best;
}

/* ---- the study ------------------------------------------------------- */
static void run(void)
{
    size_t nmax = ns_all[nn - 1];
    double *x = malloc((nmax + 1) * sizeof *x), *f = malloc((nmax + 1) * sizeof *f);
    double *d = malloc((nmax + 1) * sizeof *d), *al = malloc(nmax * sizeof *al);
    double *xq = malloc(nmax * SUB * sizeof *xq), *yq = malloc(nmax * SUB * sizeof *yq);
    if (!x || !f || !d || !al || !xq || !yq) {
        fprintf(stderr, "out of memory\n");
        exit(1);
    }
    gsl_set_error_handler_off();
    for (int fi = 0; fi < NF; fi++)
        for (int g = 0; g < 2; g++)
            for (size_t k = 0; k < nn; k++) {
                const fun *F = &funs[fi];
                size_t n = ns_all[k], m = 0;
                make_grid(F, n, g, x);
                for (size_t i = 0; i <= n; i++)
                    f[i] = F->f(x[i]);
                for (size_t i = 0; i < n; i++)
                    for (int j = 1; j < SUB; j++)
                        xq[m++] = x[i] + (x[i + 1] - x[i]) * j / (double)SUB;
                rng_state = 999u + n;
                for (size_t i = 0; i < n; i++)
                    al[i] = 0.5 * pow(4.0, urand()); /* mixed: log-uniform in [0.5, 2] */
                for (int sl = 0; sl < NS; sl++) {
                    if (sl == 0) {
                        for (size_t i = 0; i <= n; i++)
                            d[i] = F->fp(x[i]);
                    } else if (ts_slopes_compute(slope_method[sl], x, f, n + 1, d, NULL) != TS_OK) {
                        for (int fo = 0; fo < NFORM; fo++)
                            for (int ai = 0; ai < NA; ai++)
                                err[fi][g][fo][sl][ai][k] = bnd[fi][g][fo][sl][ai][k] = NAN;
                        continue;
                    }
                    for (int fo = 0; fo < NFORM; fo++)
                        for (int ai = 0; ai < NA; ai++) {
                            ts_spline_options o;
                            ts_spline_options_init(&o);
                            o.form = (ts_form)fo;
                            o.slopes = TS_SLOPES_USER;
                            o.user_slopes = d;
                            o.n_user_slopes = n + 1;
                            if (a_val[ai] > 0) {
                                o.alpha = a_val[ai];
                            } else {
                                o.alphas = al;
                                o.n_alphas = n;
                            }
                            ts_spline *s = NULL;
                            double e = NAN, b = NAN;
                            if (ts_spline_new(x, f, n + 1, &o, &s, NULL) == TS_OK &&
                                ts_spline_eval_batch(s, 0, xq, m, yq, NULL, NULL) == TS_OK) {
                                e = max_err(F, xq, yq, m);
                                /* the proven bound (exact slopes: the sharper two-term one too) */
                                if (ts_spline_error_bound(s, F->m1, F->m2, sl == 0, &b, NULL) == TS_OK) {
                                    bound_checks++;
                                    if (!(e <= b))
                                        violations++;
                                }
                            }
                            ts_spline_free(s);
                            err[fi][g][fo][sl][ai][k] = e;
                            bnd[fi][g][fo][sl][ai][k] = b;
                        }
                }
                for (int gi = 0; gi < 2; gi++) {
                    gsl_interp *ip = gsl_interp_alloc(gi ? gsl_interp_cspline : gsl_interp_steffen, n + 1);
                    double e = NAN;
                    if (ip && gsl_interp_init(ip, x, f, n + 1) == GSL_SUCCESS) {
                        gsl_interp_accel *acc = gsl_interp_accel_alloc();
                        for (size_t j = 0; j < m; j++)
                            yq[j] = gsl_interp_eval(ip, x, f, xq[j], acc);
                        gsl_interp_accel_free(acc);
                        e = max_err(F, xq, yq, m);
                    }
                    gsl_interp_free(ip);
                    gsl_err[fi][g][gi][k] = e;
                }
            }
    free(x), free(f), free(d), free(al), free(xq), free(yq);
}

/* ---- output ---------------------------------------------------------- */
typedef struct out {
    char *buf;
    size_t len, cap;
} out;

static void put(out *o, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    int k = vsnprintf(NULL, 0, fmt, ap);
    va_end(ap);
    if (k < 0)
        return;
    if (o->len + (size_t)k + 1 > o->cap) {
        size_t c = (o->cap ? o->cap * 2 : 65536) + (size_t)k;
        char *nb = realloc(o->buf, c);
        if (!nb)
            exit(1);
        o->buf = nb, o->cap = c;
    }
    va_start(ap, fmt);
    vsnprintf(o->buf + o->len, (size_t)k + 1, fmt, ap);
    va_end(ap);
    o->len += (size_t)k;
}

static void e_cell(out *o, double e)
{
    if (isnan(e))
        put(o, " n/a |");
    else
        put(o, " %.2e |", e);
}

static void tables(out *o)
{
    size_t k0 = nn >= 5 ? nn - 4 : 0, k1 = nn - 1;
    put(o, "Max error over 15 points inside every interval; n = number of intervals; "
           "\"order\" = least-squares slope of -log(error) against log n for n >= %zu.\n\n",
        ns_all[k0]);
    for (int fi = 0; fi < NF; fi++)
        for (int g = 0; g < 2; g++) {
            put(o, "#### %s, %s grid, exact slopes d_i = f'(x_i)\n\n", funs[fi].tex,
                g ? "perturbed (±35% h)" : "uniform");
            put(o, "| form | a |");
            for (size_t k = 0; k < nn; k++)
                put(o, " n=%zu |", ns_all[k]);
            put(o, " order |\n|---|---|");
            for (size_t k = 0; k <= nn; k++)
                put(o, "---|");
            put(o, "\n");
            for (int fo = 0; fo < NFORM; fo++)
                for (int ai = 0; ai < NA; ai++) {
                    if (fo == 1 && ai < 3)
                        continue; /* C¹ = paper form when all a_i are equal */
                    put(o, "| %s | %s |", form_name[fo], a_name[ai]);
                    for (size_t k = 0; k < nn; k++)
                        e_cell(o, err[fi][g][fo][0][ai][k]);
                    put(o, " %.2f |\n", order_fit(err[fi][g][fo][0][ai], k0, k1));
                }
            for (int gi = 0; gi < 2; gi++) {
                put(o, "| GSL %s | - |", gi ? "cspline" : "steffen");
                for (size_t k = 0; k < nn; k++)
                    e_cell(o, gsl_err[fi][g][gi][k]);
                put(o, " %.2f |\n", order_fit(gsl_err[fi][g][gi], k0, k1));
            }
            put(o, "\n");
        }
    /* slope methods: error at n = 1000 (or the largest n) and order, a = 1 */
    size_t kk = nn > 4 ? 4 : nn - 1;
    put(o, "#### Estimated slopes (a = 1, uniform grid): error at n = %zu / order\n\n", ns_all[kk]);
    put(o, "| function | form |");
    for (int sl = 0; sl < NS; sl++)
        put(o, " %s |", slope_name[sl]);
    put(o, "\n|---|---|");
    for (int sl = 0; sl < NS; sl++)
        put(o, "---|");
    put(o, "\n");
    for (int fi = 0; fi < NF; fi++)
        for (int fo = 0; fo < NFORM; fo += 2) {
            put(o, "| %s | %s |", funs[fi].name, form_name[fo]);
            for (int sl = 0; sl < NS; sl++) {
                double e = err[fi][0][fo][sl][1][kk];
                if (isnan(e))
                    put(o, " n/a |");
                else
                    put(o, " %.1e / %.2f |", e, order_fit(err[fi][0][fo][sl][1], k0, k1));
            }
            put(o, "\n");
        }
    put(o, "\n#### Estimated slopes, perturbed grid, a = 1: order\n\n| function | form |");
    for (int sl = 0; sl < NS; sl++)
        put(o, " %s |", slope_name[sl]);
    put(o, "\n|---|---|");
    for (int sl = 0; sl < NS; sl++)
        put(o, "---|");
    put(o, "\n");
    for (int fi = 0; fi < NF; fi++)
        for (int fo = 0; fo < NFORM; fo += 2) {
            put(o, "| %s | %s |", funs[fi].name, form_name[fo]);
            for (int sl = 0; sl < NS; sl++)
                put(o, " %.2f |", order_fit(err[fi][1][fo][sl][1], k0, k1));
            put(o, "\n");
        }
    /* bound: worst ratio error/bound */
    double worst = 0, wexact = 0;
    for (int fi = 0; fi < NF; fi++)
        for (int g = 0; g < 2; g++)
            for (int fo = 0; fo < NFORM; fo++)
                for (int sl = 0; sl < NS; sl++)
                    for (int ai = 0; ai < NA; ai++)
                        for (size_t k = 0; k < nn; k++) {
                            double r = err[fi][g][fo][sl][ai][k] / bnd[fi][g][fo][sl][ai][k];
                            if (r > worst)
                                worst = r;
                            if (sl == 0 && r > wexact)
                                wexact = r;
                        }
    put(o, "\n#### The proven bound (ts_spline_error_bound)\n\n%ld spline fits checked, %ld violations; "
           "largest error/bound ratio %.3f (exact slopes, two-term bound: %.3f).\n\n",
        bound_checks, violations, worst, wexact);
    put(o, "| a | first (docs/method.md §8) | line | second | geometric first | geometric second | "
           "paper Theorem 1 C(a) |\n|---|---|---|---|---|---|---|\n");
    const double as[5] = {0.5, 1.0, 2.0, 5.0, TS_GEOMETRIC_A_RAISE};
    for (int j = 0; j < 5; j++) {
        ts_error_constants cp, cg;
        ts_error_constants_get(TS_FORM_PAPER, as[j], &cp);
        ts_error_constants_get(TS_FORM_GEOMETRIC, as[j], &cg);
        put(o, "| %.4g | %.6f | %.6f | %.6f | %.6f | %.6f | %.6f |\n", as[j], cp.first, cp.line,
            cp.second, cg.first, cg.second, theorem1_constant(as[j]));
    }
    /* the paper's claimed bound beside the measured error, sin, uniform, exact */
    put(o, "\n#### Theorem 1 against the measurement (sin on [0, 3], uniform, exact slopes, a = 1)\n\n"
           "| n | h | measured | claimed ½ C h³ ‖f'''‖ | proven bound |\n|---|---|---|---|---|\n");
    double C1 = theorem1_constant(1.0);
    for (size_t k = 0; k < nn; k++) {
        double h = 3.0 / (double)ns_all[k];
        put(o, "| %zu | %.3g | %.2e | %.2e | %.2e |\n", ns_all[k], h, err[0][0][0][0][1][k],
            0.5 * C1 * h * h * h, bnd[0][0][0][0][1][k]);
    }
}

/* ---- SVG: log-log error against n ------------------------------------ */
static void svg(const char *path)
{
    FILE *fp = fopen(path, "w");
    if (!fp) {
        fprintf(stderr, "cannot write %s\n", path);
        return;
    }
    const double W = 720, H = 480, L = 80, R = 200, T = 40, B = 60;
    double lx0 = 1, lx1 = 4, ly0 = -11, ly1 = -1;
    struct ser {
        const char *label, *color;
        const double *e;
        int dash;
    } S[10] = {
        {"paper a=1", "#1f77b4", err[0][0][0][0][1], 0},
        {"paper a=0.5", "#1f77b4", err[0][0][0][0][0], 1},
        {"paper a=2", "#1f77b4", err[0][0][0][0][2], 2},
        {"geometric a=1", "#d62728", err[0][0][2][0][1], 0},
        {"geometric a=0.5", "#d62728", err[0][0][2][0][0], 1},
        {"geometric a=2", "#d62728", err[0][0][2][0][2], 2},
        {"bound, paper a=1", "#2ca02c", bnd[0][0][0][0][1], 1},
        {"bound, geometric a=1", "#ff7f0e", bnd[0][0][2][0][1], 1},
        {"GSL steffen", "#7f7f7f", gsl_err[0][0][0], 0},
        {"GSL cspline", "#000000", gsl_err[0][0][1], 0},
    };
    fprintf(fp, "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\" "
                "viewBox=\"0 0 %.0f %.0f\" font-family=\"sans-serif\" font-size=\"12\">\n",
            W, H, W, H);
    fprintf(fp, "<rect width=\"100%%\" height=\"100%%\" fill=\"white\"/>\n");
    fprintf(fp, "<text x=\"%.0f\" y=\"22\" text-anchor=\"middle\" font-size=\"14\">max |f - S| for "
                "sin x on [0, 3], uniform grid, exact slopes</text>\n",
            (L + W - R) / 2);
#define PX(v) (L + ((v) - lx0) / (lx1 - lx0) * (W - L - R))
#define PY(v) (T + (ly1 - (v)) / (ly1 - ly0) * (H - T - B))
    for (int e = (int)lx0; e <= (int)lx1; e++)
        fprintf(fp, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#ddd\"/>"
                    "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"middle\">1e%d</text>\n",
                PX(e), PY(ly0), PX(e), PY(ly1), PX(e), PY(ly0) + 18, e);
    for (int e = (int)ly0; e <= (int)ly1; e++)
        fprintf(fp, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#ddd\"/>"
                    "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"end\">1e%d</text>\n",
                PX(lx0), PY(e), PX(lx1), PY(e), PX(lx0) - 6, PY(e) + 4, e);
    fprintf(fp, "<rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\" fill=\"none\" "
                "stroke=\"black\"/>\n",
            PX(lx0), PY(ly1), PX(lx1) - PX(lx0), PY(ly0) - PY(ly1));
    fprintf(fp, "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"middle\">n (intervals)</text>\n",
            (PX(lx0) + PX(lx1)) / 2, H - 14);
    fprintf(fp, "<text transform=\"translate(20 %.1f) rotate(-90)\" text-anchor=\"middle\">max "
                "error</text>\n",
            (PY(ly0) + PY(ly1)) / 2);
    static const char *dash[3] = {"", " stroke-dasharray=\"6 3\"", " stroke-dasharray=\"2 3\""};
    for (int j = 0; j < 10; j++) {
        fprintf(fp, "<polyline fill=\"none\" stroke=\"%s\" stroke-width=\"1.8\"%s points=\"",
                S[j].color, dash[S[j].dash]);
        for (size_t k = 0; k < nn; k++) {
            double e = S[j].e[k];
            if (e > 0)
                fprintf(fp, "%.1f,%.1f ", PX(log10((double)ns_all[k])), PY(fmax(log10(e), ly0)));
        }
        fprintf(fp, "\"/>\n");
        double yl = T + 14 + 20 * j;
        fprintf(fp, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"%s\" "
                    "stroke-width=\"1.8\"%s/><text x=\"%.1f\" y=\"%.1f\">%s</text>\n",
                W - R + 12, yl, W - R + 40, yl, S[j].color, dash[S[j].dash], W - R + 46, yl + 4,
                S[j].label);
    }
    fprintf(fp, "</svg>\n");
    fclose(fp);
#undef PX
#undef PY
}

static int replace_block(const char *path, const char *text)
{
    const char *b = "<!-- BEGIN RESULTS -->", *e = "<!-- END RESULTS -->";
    FILE *fp = fopen(path, "rb");
    if (!fp)
        return -1;
    fseek(fp, 0, SEEK_END);
    long sz = ftell(fp);
    fseek(fp, 0, SEEK_SET);
    char *doc = malloc((size_t)sz + 1);
    if (!doc || fread(doc, 1, (size_t)sz, fp) != (size_t)sz) {
        fclose(fp);
        free(doc);
        return -1;
    }
    doc[sz] = 0;
    fclose(fp);
    char *p = strstr(doc, b), *q = p ? strstr(p, e) : NULL;
    if (!p || !q) {
        free(doc);
        return -2;
    }
    fp = fopen(path, "wb");
    if (!fp) {
        free(doc);
        return -1;
    }
    fwrite(doc, 1, (size_t)(p - doc) + strlen(b), fp);
    fprintf(fp, "\n%s\n", text);
    fputs(q, fp);
    fclose(fp);
    free(doc);
    return 0;
}

int main(int argc, char **argv)
{
    const char *doc = NULL, *svgp = NULL;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--quick"))
            nn = 4;
        else if (!strcmp(argv[i], "--doc") && i + 1 < argc)
            doc = argv[++i];
        else if (!strcmp(argv[i], "--svg") && i + 1 < argc)
            svgp = argv[++i];
        else {
            fprintf(stderr, "usage: %s [--quick] [--doc FILE.md] [--svg FILE.svg]\n", argv[0]);
            return 2;
        }
    }
    run();
    out o = {0};
    tables(&o);
    fputs(o.buf, stdout);
    if (doc) {
        int r = replace_block(doc, o.buf);
        if (r)
            fprintf(stderr, "%s: %s\n", doc, r == -2 ? "no RESULTS markers" : "cannot rewrite");
    }
    if (svgp)
        svg(svgp);
    free(o.buf);
    return violations ? 1 : 0;
}
