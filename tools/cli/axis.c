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

void cli_time_ticks(void *ctx, tsu_plot_ticks *t)
{
    const tsu_time_form *form = ctx;
    static const double steps[] = {1, 2, 5, 10, 15, 30, 60, 120, 300, 600, 900, 1800, 3600, 7200,
                                   10800, 21600, 43200, 86400, 172800, 604800};
    static const int months[] = {1, 2, 3, 6, 12, 24, 60, 120, 240, 600, 1200};
    double span = t->hi - t->lo, off = form->zone == 2 ? form->offset_min * 60.0 : 0.0;
    char c[20];
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
            if (st < 60)
                snprintf(t->label[t->n], TSU_PLOT_LABEL_MAX, "%.8s", c + 11);
            else if (st < 86400)
                snprintf(t->label[t->n], TSU_PLOT_LABEL_MAX, "%.5s %.5s", c + 5, c + 11);
            else
                snprintf(t->label[t->n], TSU_PLOT_LABEL_MAX, "%.10s", c);
            t->n++;
        }
        return;
    }
    civil_text(t->lo, form, c);
    long long y0 = 0, m0 = 0;
    if (sscanf(c, "%4lld-%2lld", &y0, &m0) != 2)
        return;
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

void cli_log_ticks(void *ctx, tsu_plot_ticks *t)
{
    (void)ctx;
    double k0 = ceil(t->lo - 1e-9), k1 = floor(t->hi + 1e-9);
    if (k1 - k0 + 1 >= 2) {
        double every = ceil((k1 - k0 + 1) / 8);
        t->n = 0;
        for (double k = k0; k <= k1 && t->n < TSU_PLOT_MAX_TICKS; k += every) {
            t->value[t->n] = k;
            pow10_label(k, t->label[t->n]);
            t->n++;
        }
        return;
    }
    /* less than two decades: the linear ticks of log10 y, labelled with y */
    tsu_plot_ticks lin;
    if (tsu_plot_ticks_compute(t->lo, t->hi, TSU_PLOT_RANGE_FIXED, &lin) != TSU_PLOT_OK)
        return;
    t->n = lin.n;
    for (size_t i = 0; i < lin.n; i++) {
        t->value[i] = lin.value[i];
        pow10_label(lin.value[i], t->label[i]);
    }
}
