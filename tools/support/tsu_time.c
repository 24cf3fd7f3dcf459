/* tsu_io dates and times: ISO 8601 text <-> seconds since 1970 (see
 * tsu_io.h, tsu_parse_time). */
#define _POSIX_C_SOURCE 200809L

#include "tsu_io_internal.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* ================================================================== */
/* Dates and times                                                      */
/* ================================================================== */

/* Days since 1970-01-01 of a proleptic Gregorian date (the era-based
 * day count: 400-year eras of 146097 days, years starting in March). */
static long long days_from_civil(long long y, int m, int d)
{
    y -= m <= 2;
    long long era = (y >= 0 ? y : y - 399) / 400;
    long long yoe = y - era * 400;
    long long doy = (153 * (m + (m > 2 ? -3 : 9)) + 2) / 5 + d - 1;
    long long doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
    return era * 146097 + doe - 719468;
}

static void civil_from_days(long long z, long long *y, int *m, int *d)
{
    z += 719468;
    long long era = (z >= 0 ? z : z - 146096) / 146097;
    long long doe = z - era * 146097;
    long long yoe = (doe - doe / 1460 + doe / 36524 - doe / 146096) / 365;
    long long doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    long long mp = (5 * doy + 2) / 153;
    *d = (int)(doy - (153 * mp + 2) / 5 + 1);
    *m = (int)(mp < 10 ? mp + 3 : mp - 9);
    *y = yoe + era * 400 + (*m <= 2);
}

static int month_days(long long y, int m)
{
    static const int md[12] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
    int leap = (y % 4 == 0 && y % 100 != 0) || y % 400 == 0;
    return m == 2 ? 28 + leap : md[m - 1];
}


/* n digits at p (p + n <= end) into *v; 0 if not all digits */
static int digits_at(const char *p, const char *end, int n, int *v)
{
    int acc = 0;
    if (end - p < n)
        return 0;
    for (int i = 0; i < n; i++) {
        if (!IS_DIGIT(p[i]))
            return 0;
        acc = acc * 10 + (p[i] - '0');
    }
    *v = acc;
    return 1;
}

int tsu_parse_time(const char *s, const char *end, double *t, tsu_time_form *form,
                   const char **stop)
{
    tsu_time_form f;
    const char *p = s;
    int Y, M, D, h = 0, mi = 0, sec = 0, oh, om;
    double frac = 0.0;
    memset(&f, 0, sizeof f);
    f.date_only = 1;
    f.sep = 'T';
    if (!end)
        end = s + strlen(s);
    if (stop)
        *stop = s;
    if (!digits_at(p, end, 4, &Y) || end - p < 5 || p[4] != '-')
        return 0;
    p += 5;
    if (!digits_at(p, end, 2, &M) || M < 1 || M > 12 || end - p < 3 || p[2] != '-') {
        if (stop)
            *stop = p;
        return 0;
    }
    p += 3;
    if (!digits_at(p, end, 2, &D) || D < 1 || D > month_days(Y, M)) {
        if (stop)
            *stop = p;
        return 0;
    }
    p += 2;
    if (p < end && (*p == 'T' || *p == 't' || *p == ' ') && end - p >= 4 && IS_DIGIT(p[1]) &&
        IS_DIGIT(p[2]) && p[3] == ':') {
        f.date_only = 0;
        f.sep = *p++;
        if (!digits_at(p, end, 2, &h) || h > 23 || !digits_at(p + 3, end, 2, &mi) || mi > 59) {
            if (stop)
                *stop = p;
            return 0;
        }
        p += 5;
        if (p < end && *p == ':') {
            if (!digits_at(p + 1, end, 2, &sec) || sec > 59) {
                if (stop)
                    *stop = p + 1;
                return 0;
            }
            f.seconds = 1;
            p += 3;
            if (p < end && *p == '.' && p + 1 < end && IS_DIGIT(p[1])) {
                const char *q;
                (void)tsu_parse_double(p, end, &frac, &q); /* ".ddd": exact rounding */
                p = q;
            }
        }
        if (p < end && (*p == 'Z' || *p == 'z')) {
            f.zone = 1;
            p++;
        } else if (p < end && (*p == '+' || *p == '-') && digits_at(p + 1, end, 2, &oh)) {
            int sign = *p == '-' ? -1 : 1;
            const char *q = p + 3;
            om = 0;
            if (q < end && *q == ':' && digits_at(q + 1, end, 2, &om)) {
                f.colon = 1;
                q += 3;
            } else if (digits_at(q, end, 2, &om)) {
                q += 2;
            }
            if (oh > 23 || om > 59) {
                if (stop)
                    *stop = p;
                return 0;
            }
            f.zone = 2;
            f.offset_min = sign * (oh * 60 + om);
            p = q;
        }
    }
    long long whole = days_from_civil(Y, M, D) * 86400 + h * 3600 + mi * 60 + sec -
                      (long long)f.offset_min * 60;
    if (t)
        *t = (double)whole + frac;
    if (form)
        *form = f;
    if (stop)
        *stop = p;
    return 1;
}

size_t tsu_format_time(double t, const tsu_time_form *form, char buf[TSU_TIME_SIZE])
{
    tsu_time_form f;
    char fr[16] = "";
    long long y;
    int m, d;
    if (form)
        f = *form;
    else
        memset(&f, 0, sizeof f), f.sep = 'T', f.seconds = 1, f.zone = 1;
    if (!(fabs(t) < 2.5e14)) { /* beyond year 9999 both ways: a number */
        return tsu_format_double(t, buf);
    }
    double I = floor(t), frac = t - I;
    if (frac > 0.0) {
        /* the fewest digits that read back as t (as tsu_parse_time reads) */
        long long p10 = 1;
        for (int k = 1; k <= 9; k++) {
            p10 *= 10;
            double r = floor(frac * (double)p10 + 0.5);
            if (r >= (double)p10)
                continue;
            char tmp[16];
            snprintf(tmp, sizeof tmp, ".%0*lld", k, (long long)r);
            double back;
            (void)tsu_parse_double(tmp, NULL, &back, NULL);
            if (I + back == t || k == 9) {
                size_t L = strlen(tmp);
                while (L > 2 && tmp[L - 1] == '0')
                    tmp[--L] = 0;
                memcpy(fr, tmp, L + 1);
                break;
            }
        }
    }
    long long local = (long long)I + (f.zone == 2 ? (long long)f.offset_min * 60 : 0);
    long long days = local >= 0 ? local / 86400 : -((-local + 86399) / 86400);
    long long sod = local - days * 86400;
    int h = (int)(sod / 3600), mi = (int)(sod / 60 % 60), sec = (int)(sod % 60);
    civil_from_days(days, &y, &m, &d);
    int n;
    if (f.date_only && sod == 0 && !fr[0]) {
        n = snprintf(buf, TSU_TIME_SIZE, "%04lld-%02d-%02d", y, m, d);
    } else {
        char sep = f.date_only ? 'T' : f.sep;
        if (f.seconds || sec || fr[0])
            n = snprintf(buf, TSU_TIME_SIZE, "%04lld-%02d-%02d%c%02d:%02d:%02d%s", y, m, d, sep, h,
                         mi, sec, fr);
        else
            n = snprintf(buf, TSU_TIME_SIZE, "%04lld-%02d-%02d%c%02d:%02d", y, m, d, sep, h, mi);
        if (n > 0 && n < TSU_TIME_SIZE - 8) {
            if (f.zone == 1) {
                buf[n++] = 'Z';
                buf[n] = 0;
            } else if (f.zone == 2) {
                int o = f.offset_min < 0 ? -f.offset_min : f.offset_min;
                n += snprintf(buf + n, TSU_TIME_SIZE - (size_t)n, f.colon ? "%c%02d:%02d" : "%c%02d%02d",
                              f.offset_min < 0 ? '-' : '+', o / 60, o % 60);
            }
        }
    }
    return n < 0 ? 0 : (size_t)n;
}

/* ------------------------------------------------------------------ */
/* strptime-like formats                                                */
/* ------------------------------------------------------------------ */

/* 1 to max digits at *p into *v (greedy); 0 if none. */
static int digits_upto(const char **p, const char *end, int max, int *v)
{
    int acc = 0, n = 0;
    while (n < max && *p < end && IS_DIGIT(**p)) {
        acc = acc * 10 + (**p - '0');
        (*p)++;
        n++;
    }
    *v = acc;
    return n > 0;
}

static int lower_ascii(int c) { return c >= 'A' && c <= 'Z' ? c + 32 : c; }

/* An English month name (full or its first three letters, any case) at *p: 1-12, 0 if none. */
static int month_name(const char **p, const char *end)
{
    static const char *const names[12] = {"january", "february", "march",     "april",
                                          "may",     "june",     "july",      "august",
                                          "september", "october", "november", "december"};
    for (int m = 0; m < 12; m++) {
        size_t full = strlen(names[m]), k = 0;
        while (k < full && *p + k < end && lower_ascii((unsigned char)(*p)[k]) == names[m][k])
            k++;
        if (k == full || k == 3) {
            *p += k;
            return m + 1;
        }
    }
    return 0;
}

int tsu_parse_time_format(const char *fmt, const char *s, const char *end, double *t,
                          tsu_time_form *form, const char **stop)
{
    tsu_time_form f;
    const char *p = s, *q;
    int Y = 1970, M = 1, D = 1, yday = 0, h = 0, mi = 0, sec = 0, pm = -1, v;
    int have_date = 0;
    double frac = 0.0;
    memset(&f, 0, sizeof f);
    f.date_only = 1;
    f.sep = 'T';
    if (!end)
        end = s + strlen(s);
    if (stop)
        *stop = s;
    if (!fmt)
        return 0;
    for (const char *c = fmt; *c; c++) {
        if (*c == ' ' || *c == '\t') { /* any run of blanks, none included */
            while (p < end && IS_BLANK(*p))
                p++;
            continue;
        }
        if (*c != '%' || !c[1]) {
            if (p >= end || *p != *c)
                goto fail;
            p++;
            continue;
        }
        switch (*++c) {
        case 'Y':
            if (!digits_at(p, end, 4, &Y))
                goto fail;
            p += 4;
            have_date = 1;
            break;
        case 'y':
            if (!digits_at(p, end, 2, &v))
                goto fail;
            Y = v < 69 ? 2000 + v : 1900 + v; /* POSIX strptime */
            p += 2;
            have_date = 1;
            break;
        case 'm':
            if (!digits_upto(&p, end, 2, &M) || M < 1 || M > 12)
                goto fail;
            have_date = 1;
            break;
        case 'b':
        case 'B':
        case 'h':
            if (!(M = month_name(&p, end)))
                goto fail;
            have_date = 1;
            break;
        case 'd':
        case 'e':
            if (!digits_upto(&p, end, 2, &D) || D < 1 || D > 31)
                goto fail;
            have_date = 1;
            break;
        case 'j':
            if (!digits_upto(&p, end, 3, &yday) || yday < 1 || yday > 366)
                goto fail;
            have_date = 1;
            break;
        case 'H':
        case 'I':
            if (!digits_upto(&p, end, 2, &h) || (*c == 'H' ? h > 23 : h < 1 || h > 12))
                goto fail;
            if (*c == 'I' && pm < 0)
                pm = 2; /* 12-hour clock, %p not seen yet */
            f.date_only = 0;
            break;
        case 'M':
            if (!digits_upto(&p, end, 2, &mi) || mi > 59)
                goto fail;
            f.date_only = 0;
            break;
        case 'S':
            if (!digits_upto(&p, end, 2, &sec) || sec > 59)
                goto fail;
            f.date_only = 0;
            f.seconds = 1;
            break;
        case 'f': /* fraction digits of the second (Python's %f, any number) */
            if (p >= end || !IS_DIGIT(*p))
                goto fail;
            {
                char tmp[48];
                size_t n = 0;
                tmp[n++] = '.';
                for (q = p; q < end && IS_DIGIT(*q); q++)
                    if (n + 1 < sizeof tmp)
                        tmp[n++] = *q;
                tmp[n] = 0;
                (void)tsu_parse_double(tmp, NULL, &frac, NULL);
                p = q;
            }
            break;
        case 'p':
            if (end - p >= 2 && (lower_ascii((unsigned char)p[0]) == 'a' ||
                                 lower_ascii((unsigned char)p[0]) == 'p') &&
                lower_ascii((unsigned char)p[1]) == 'm') {
                int is_pm = lower_ascii((unsigned char)p[0]) == 'p';
                pm = pm == 2 || pm < 0 ? 10 + is_pm : pm;
                p += 2;
            } else {
                goto fail;
            }
            break;
        case 'z':
            if (p < end && (*p == 'Z' || *p == 'z')) {
                f.zone = 1;
                p++;
            } else if (p < end && (*p == '+' || *p == '-') && digits_at(p + 1, end, 2, &v)) {
                int sign = *p == '-' ? -1 : 1, om = 0;
                q = p + 3;
                if (q < end && *q == ':' && digits_at(q + 1, end, 2, &om)) {
                    f.colon = 1;
                    q += 3;
                } else if (digits_at(q, end, 2, &om)) {
                    q += 2;
                }
                if (v > 23 || om > 59)
                    goto fail;
                f.zone = 2;
                f.offset_min = sign * (v * 60 + om);
                p = q;
            } else {
                goto fail;
            }
            break;
        case 'T': /* %H:%M:%S */
            if (!digits_upto(&p, end, 2, &h) || h > 23 || p >= end || *p++ != ':' ||
                !digits_upto(&p, end, 2, &mi) || mi > 59 || p >= end || *p++ != ':' ||
                !digits_upto(&p, end, 2, &sec) || sec > 59)
                goto fail;
            f.date_only = 0;
            f.seconds = 1;
            break;
        case 'R': /* %H:%M */
            if (!digits_upto(&p, end, 2, &h) || h > 23 || p >= end || *p++ != ':' ||
                !digits_upto(&p, end, 2, &mi) || mi > 59)
                goto fail;
            f.date_only = 0;
            break;
        case 'F': /* %Y-%m-%d */
            if (!digits_at(p, end, 4, &Y) || end - p < 5 || p[4] != '-')
                goto fail;
            p += 5;
            if (!digits_upto(&p, end, 2, &M) || M < 1 || M > 12 || p >= end || *p++ != '-' ||
                !digits_upto(&p, end, 2, &D) || D < 1)
                goto fail;
            have_date = 1;
            break;
        case 'n':
        case 't':
            while (p < end && IS_BLANK(*p))
                p++;
            break;
        case '%':
            if (p >= end || *p != '%')
                goto fail;
            p++;
            break;
        default: /* a conversion not supported: never matches */
            goto fail;
        }
    }
    if (pm >= 10) { /* %I with %p */
        h = h % 12 + (pm == 11 ? 12 : 0);
    }
    if (yday) {
        int leap = (Y % 4 == 0 && Y % 100 != 0) || Y % 400 == 0;
        if (yday > 365 + leap)
            goto fail;
        M = 1;
        D = yday;
        while (D > month_days(Y, M)) {
            D -= month_days(Y, M);
            M++;
        }
    } else if (D > month_days(Y, M)) {
        goto fail;
    }
    if (!have_date && f.date_only)
        goto fail; /* neither a date nor a time */
    {
        long long whole = days_from_civil(Y, M, D) * 86400 + h * 3600 + mi * 60 + sec -
                          (long long)f.offset_min * 60;
        if (t)
            *t = (double)whole + frac;
    }
    if (form)
        *form = f;
    if (stop)
        *stop = p;
    return 1;
fail:
    if (stop)
        *stop = p;
    return 0;
}
