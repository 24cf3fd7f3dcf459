/* Plot axes beyond the linear 1-2-5 ticks: dates on x, decades on a log y. */
#include "cli.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* Civil fields of t in the zone of form: "YYYY-MM-DD HH:MM:SS" (19 chars). */
static void civil_text(double t, const tsu_time_form *form, char out[20])
{
    tsu_time_form f = *form;
    char b[TSU_TIME_SIZE];
    f.date_only = 0;
    f.sep = ' ';
    f.seconds = 1;
    tsu_format_time(floor(t), &f, b);
    memcpy(out, b, 19);
    out[19] = 0;
}

/* t of YYYY-MM-01 00:00 (month m may run past 12) in the zone of form. */
static double month_start(long long y, long long m, const tsu_time_form *form)
{
    char b[64];
    double t = 0;
    y += (m - 1) / 12;
    m = (m - 1) % 12 + 1;
    if (form->zone == 2) {
        int o = form->offset_min < 0 ? -form->offset_min : form->offset_min;
        snprintf(b, sizeof b, "%04lld-%02lld-01T00:00:00%c%02d:%02d", y, m,
                 form->offset_min < 0 ? '-' : '+', o / 60, o % 60);
    } else {
        snprintf(b, sizeof b, "%04lld-%02lld-01T00:00:00Z", y, m);
    }
    (void)tsu_parse_time(b, NULL, &t, NULL, NULL);
    return t;
}

/* The label of tick v (civil text c) at step st seconds (0: calendar days
 * or more): the fields that changed since the previous tick's text prev
 * ("" for the first tick, which shows the date with its year). */
static void time_label(const char *c, const char *prev, double st, char *out)
{
    int first = !prev[0], new_year = !first && memcmp(c, prev, 4) != 0,
        new_day = !first && memcmp(c, prev, 10) != 0;
    char hm[16];
    snprintf(hm, sizeof hm, "%.*s", st < 60 ? 8 : 5, c + 11);
    if (st >= 86400 || st == 0) {
        if (first || new_year)
            snprintf(out, TSU_PLOT_LABEL_MAX, "%.10s", c);
        else
            snprintf(out, TSU_PLOT_LABEL_MAX, "%.5s", c + 5);
    } else if (first || new_year) {
        snprintf(out, TSU_PLOT_LABEL_MAX, "%.10s %s", c, hm);
    } else if (new_day) {
        snprintf(out, TSU_PLOT_LABEL_MAX, "%.5s %s", c + 5, hm);
    } else {
        snprintf(out, TSU_PLOT_LABEL_MAX, "%s", hm);
    }
}

void cli_time_ticks(void *ctx, tsu_plot_ticks *t)
{
    const tsu_time_form *form = ctx;
    /* round clock steps up to two days; beyond, days of the month and months */
    static const double steps[] = {1,    2,    5,    10,    15,    30,    60,    120,
                                   300,  600,  900,  1800,  3600,  7200,  10800, 21600,
                                   43200, 86400, 172800};
    static const int mdays[][6] = {
        {1, 6, 11, 16, 21, 26}, {1, 8, 15, 22, 0, 0}, {1, 15, 0, 0, 0, 0}};
    static const int months[] = {1, 2, 3, 6, 12, 24, 60, 120, 240, 600, 1200};
    double span = t->hi - t->lo, off = form->zone == 2 ? form->offset_min * 60.0 : 0.0;
    char c[20], prev[20] = "";
    t->n = 0;
    for (size_t k = 0; k < sizeof steps / sizeof steps[0]; k++) {
        double st = steps[k];
        if (span / st > 7)
            continue;
        /* multiples of st in local time */
        double first = ceil((t->lo + off) / st) * st - off;
        for (double v = first; v <= t->hi && t->n < TSU_PLOT_MAX_TICKS; v += st) {
            civil_text(v, form, c);
            t->value[t->n] = v;
            time_label(c, prev, st, t->label[t->n]);
            memcpy(prev, c, sizeof c);
            t->n++;
        }
        return;
    }
    civil_text(t->lo, form, c);
    long long y0 = 0, m0 = 0;
    if (sscanf(c, "%4lld-%2lld", &y0, &m0) != 2)
        return;
    /* days of the month: 5, 7 or 14 days apart */
    for (size_t k = 0; k < sizeof mdays / sizeof mdays[0]; k++) {
        double every = k == 0 ? 5 : k == 1 ? 7 : 14;
        if (span / (every * 86400) > 7)
            continue;
        for (long long idx = y0 * 12 + m0 - 1;; idx++) {
            double ms = month_start(idx / 12, idx % 12 + 1, form);
            if (ms > t->hi || t->n >= TSU_PLOT_MAX_TICKS)
                return;
            for (int q = 0; q < 6 && mdays[k][q] && t->n < TSU_PLOT_MAX_TICKS; q++) {
                double v = ms + (mdays[k][q] - 1) * 86400.0;
                if (v < t->lo || v > t->hi)
                    continue;
                civil_text(v, form, c);
                t->value[t->n] = v;
                time_label(c, prev, 0, t->label[t->n]);
                memcpy(prev, c, sizeof c);
                t->n++;
            }
        }
    }
    for (size_t k = 0; k < sizeof months / sizeof months[0]; k++) {
        int st = months[k];
        if (span / (st * 30.4 * 86400) > 7 && k + 1 < sizeof months / sizeof months[0])
            continue;
        long long idx = (y0 * 12 + m0 - 1) / st * st; /* months since year 0, aligned */
        for (;; idx += st) {
            double v = month_start(idx / 12, idx % 12 + 1, form);
            if (v > t->hi || t->n >= TSU_PLOT_MAX_TICKS)
                break;
            if (v < t->lo)
                continue;
            civil_text(v, form, c);
            t->value[t->n] = v;
            snprintf(t->label[t->n], TSU_PLOT_LABEL_MAX, st >= 12 ? "%.4s" : "%.7s", c);
            t->n++;
        }
        return;
    }
}

/* 10^v as a short label */
static void pow10_label(double v, char *buf)
{
    double r = nearbyint(v);
    if (fabs(v - r) < 1e-9 && r >= -3 && r <= 4) {
        char b[TSU_FMT_SIZE];
        snprintf(buf, TSU_PLOT_LABEL_MAX, "%s", cli_num(pow(10.0, r), b));
    } else if (fabs(v - r) < 1e-9) {
        snprintf(buf, TSU_PLOT_LABEL_MAX, "1e%d", (int)r);
    } else {
        snprintf(buf, TSU_PLOT_LABEL_MAX, "%.3g", pow(10.0, v));
    }
}

/* m * 10^k as the double nearest to it (one rounding) and its label. */
static double mant_value(int m, int k)
{
    double p = 1.0;
    for (int i = 0; i < (k < 0 ? -k : k); i++)
        p *= 10.0;
    return k < 0 ? m / p : m * p;
}

static void mant_label(int m, int k, char *buf)
{
    char b[TSU_FMT_SIZE];
    if (k >= -4 && k <= 5)
        snprintf(buf, TSU_PLOT_LABEL_MAX, "%s", cli_num(mant_value(m, k), b));
    else
        snprintf(buf, TSU_PLOT_LABEL_MAX, "%de%d", m, k);
}

/* Ticks at m * 10^k for m in ms[0..nm) inside [lo, hi] (log10 values); the count. */
static size_t mant_ticks(const int *ms, size_t nm, tsu_plot_ticks *t, int write)
{
    size_t n = 0;
    for (double k = floor(t->lo) - 1; k <= ceil(t->hi) + 1 && k < 400; k++)
        for (size_t i = 0; i < nm; i++) {
            double v = log10(mant_value(ms[i], (int)k));
            if (!(t->lo - 1e-9 <= v && v <= t->hi + 1e-9))
                continue;
            if (write && n < TSU_PLOT_MAX_TICKS) {
                t->value[n] = v;
                mant_label(ms[i], (int)k, t->label[n]);
            }
            n++;
        }
    return n;
}

void cli_log_ticks(void *ctx, tsu_plot_ticks *t)
{
    (void)ctx;
    double k0 = ceil(t->lo - 1e-9), k1 = floor(t->hi + 1e-9);
    if (k1 - k0 + 1 >= 4) {
        double every = ceil((k1 - k0 + 1) / 8);
        t->n = 0;
        for (double k = k0; k <= k1 && t->n < TSU_PLOT_MAX_TICKS; k += every) {
            t->value[t->n] = k;
            pow10_label(k, t->label[t->n]);
            t->n++;
        }
        return;
    }
    /* up to three decades: 1-2-5 in each, else 1-2-3-5, else every digit (as
     * matplotlib's LogLocator with subs) */
    static const int m125[] = {1, 2, 5}, m19[] = {1, 2, 3, 4, 5, 6, 7, 8, 9};
    size_t c125 = mant_ticks(m125, 3, t, 0);
    if (c125 >= 3 && c125 <= 10) {
        t->n = mant_ticks(m125, 3, t, 1);
        return;
    }
    static const int m1235[] = {1, 2, 3, 5};
    size_t c1235 = mant_ticks(m1235, 4, t, 0);
    if (c1235 >= 3 && c1235 <= 10) {
        t->n = mant_ticks(m1235, 4, t, 1);
        return;
    }
    size_t c19 = mant_ticks(m19, 9, t, 0);
    if (c19 >= 3 && c19 <= 10) {
        t->n = mant_ticks(m19, 9, t, 1);
        return;
    }
    /* a narrow range: the linear 1-2-5 ticks of y itself */
    tsu_plot_ticks lin;
    double ylo = pow(10.0, t->lo), yhi = pow(10.0, t->hi);
    if (!(ylo < yhi) || tsu_plot_ticks_compute(ylo, yhi, TSU_PLOT_RANGE_FIXED, &lin) != TSU_PLOT_OK)
        return;
    t->n = 0;
    for (size_t i = 0; i < lin.n; i++) {
        if (!(lin.value[i] > 0))
            continue;
        t->value[t->n] = log10(lin.value[i]);
        if (lin.exponent)
            snprintf(t->label[t->n], TSU_PLOT_LABEL_MAX, "%.16se%d", lin.label[i], lin.exponent);
        else
            snprintf(t->label[t->n], TSU_PLOT_LABEL_MAX, "%s", lin.label[i]);
        t->n++;
    }
}
