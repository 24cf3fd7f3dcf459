/* Tests of tools/support (tsu_io.h): number conversion, table reader, safe output,
 * row writer.
 *
 * References, none of them the code under test:
 *  - glibc strtod (correctly rounded) and printf("%.*e") (exact digits);
 *  - CPython's float() and repr() via tests/tools/data/io_parse_ref.txt and
 *    io_format_ref.txt (tests/tools/data/io_gen_reference.py; David Gay's dtoa);
 *  - exact big-integer arithmetic written here for the power-of-ten table
 *    and for the exact decimal text of halfway points;
 *  - hand-written expected messages and values (from the format rules in
 *    tsu_io.h and IEEE 754 facts such as 2^53 + 1 rounding to 2^53).
 * Number conversions are exact, so every comparison is bit for bit (no
 * tolerance anywhere).  Speeds are printed for information only. */
#define _POSIX_C_SOURCE 200809L

#include "th.h"
#include "tsu_io.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <float.h>
#include <signal.h>
#include <stdint.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#if TH_ASAN
#define SAN 1
#endif
#ifndef SAN
#define SAN 0
#endif
/* Sanitized builds are ~10x slower, valgrind ~50x: fewer random cases there. */
static long scale_div = 1;
#define SCALE(n) ((n) / scale_div)

#ifndef TS_SOURCE_DIR
#define TS_SOURCE_DIR "."
#endif

/* ------------------------------------------------------------------ */
/* helpers                                                              */
/* ------------------------------------------------------------------ */

static uint64_t rng_state = 0x9E3779B97F4A7C15u;
static uint64_t rnd(void) /* xorshift64* */
{
    rng_state ^= rng_state >> 12;
    rng_state ^= rng_state << 25;
    rng_state ^= rng_state >> 27;
    return rng_state * 2685821657736338717u;
}
static unsigned rndn(unsigned n) { return (unsigned)(rnd() % n); }

static uint64_t bits_of(double d)
{
    uint64_t u;
    memcpy(&u, &d, sizeof u);
    return u;
}
static double of_bits(uint64_t u)
{
    double d;
    memcpy(&d, &u, sizeof d);
    return d;
}

static volatile double sink;

static double now(void)
{
    struct timespec ts;
    timespec_get(&ts, TIME_UTC);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

/* Canonical form of a decimal text: significant digits (no leading or
 * trailing zeros) and the exponent of the last digit.  "0" -> "", 0. */
static void canon(const char *s, char *dig, long *e)
{
    long frac = 0, ex = 0;
    int point = 0;
    size_t n = 0;
    const char *p = s;
    if (*p == '-' || *p == '+')
        p++;
    for (; *p && *p != 'e' && *p != 'E'; p++) {
        if (*p == '.') {
            point = 1;
            continue;
        }
        if (point)
            frac++;
        if (n == 0 && *p == '0')
            continue;
        dig[n++] = *p;
    }
    if (*p)
        ex = strtol(p + 1, NULL, 10);
    ex -= frac;
    while (n > 0 && dig[n - 1] == '0') {
        n--;
        ex++;
    }
    dig[n] = 0;
    *e = n ? ex : 0;
}

/* ------------------------------------------------------------------ */
/* a tiny exact big integer (base 2^32), separate from io.c's           */
/* ------------------------------------------------------------------ */

#define TB 80
typedef struct {
    uint32_t d[TB];
} tbig; /* fixed length, little-endian */

static void tb_set(tbig *a, uint64_t hi, uint64_t lo)
{
    memset(a, 0, sizeof *a);
    a->d[0] = (uint32_t)lo;
    a->d[1] = (uint32_t)(lo >> 32);
    a->d[2] = (uint32_t)hi;
    a->d[3] = (uint32_t)(hi >> 32);
}
static void tb_mul(tbig *a, uint32_t m)
{
    uint64_t c = 0;
    for (int i = 0; i < TB; i++) {
        uint64_t t = (uint64_t)a->d[i] * m + c;
        a->d[i] = (uint32_t)t;
        c = t >> 32;
    }
}
static void tb_pow10(tbig *a, int k)
{
    for (int i = 0; i < k; i++)
        tb_mul(a, 10);
}
static void tb_shl(tbig *a, int k)
{
    for (int i = 0; i < k; i++) {
        uint32_t c = 0;
        for (int j = 0; j < TB; j++) {
            uint32_t nc = a->d[j] >> 31;
            a->d[j] = (a->d[j] << 1) | c;
            c = nc;
        }
    }
}
static int tb_cmp(const tbig *a, const tbig *b)
{
    for (int i = TB - 1; i >= 0; i--)
        if (a->d[i] != b->d[i])
            return a->d[i] < b->d[i] ? -1 : 1;
    return 0;
}

/* Table entry a: T·2^s <= 10^(27a) < (T+1)·2^s, equality iff exact. */
static void test_pow10_table(void)
{
    for (int a = -13; a <= 12; a++) {
        unsigned long long hi, lo;
        int s, ex, k = 27 * a;
        tbig L, R, T1, X;
        CHECK(tsu_io__pow10_entry(a, &hi, &lo, &s, &ex) == 0);
        CHECK(hi >> 63 == 1); /* normalised: 2^127 <= T */
        /* compare T·2^s with 10^k, both sides made integers */
        tb_set(&L, hi, lo);
        tb_set(&T1, lo == UINT64_MAX ? hi + 1 : hi, lo + 1);
        memset(&X, 0, sizeof X);
        X.d[0] = 1;
        if (k >= 0)
            tb_pow10(&X, k);
        if (k < 0) { /* T·10^-k vs 2^-s */
            tb_pow10(&L, -k);
            tb_pow10(&T1, -k);
        }
        if (s >= 0) {
            tb_shl(&L, s);
            tb_shl(&T1, s);
        } else {
            tb_shl(&X, -s);
        }
        R = X;
        CHECKF(tb_cmp(&L, &R) <= 0 && tb_cmp(&R, &T1) < 0, "pow10 entry %d", a);
        CHECKF((tb_cmp(&L, &R) == 0) == (ex == 1), "pow10 entry %d exact flag", a);
    }
    CHECK(tsu_io__pow10_entry(13, NULL, NULL, NULL, NULL) == -1);
    CHECK(tsu_io__pow10_entry(-14, NULL, NULL, NULL, NULL) == -1);
}

/* ------------------------------------------------------------------ */
/* exact decimal text of M·2^Q (base 1e9 digits)                        */
/* ------------------------------------------------------------------ */

#define DB 160 /* 1440 decimal digits */
/* Writes the integer digits D with M·2^Q = D·10^*e10 into out. */
static void exact_decimal(uint64_t M, int Q, char *out, int *e10)
{
    uint32_t d[DB];
    int n = 0, i;
    memset(d, 0, sizeof d);
    while (M) {
        d[n++] = (uint32_t)(M % 1000000000u);
        M /= 1000000000u;
    }
    for (int r = Q >= 0 ? Q : -Q; r > 0;) { /* ·2^Q or ·5^-Q, up to 2^29 or 5^13 at a time */
        int step = Q >= 0 ? (r < 29 ? r : 29) : (r < 13 ? r : 13);
        uint64_t mul = 1, c = 0;
        for (int j = 0; j < step; j++)
            mul *= Q >= 0 ? 2u : 5u;
        for (i = 0; i < n; i++) {
            uint64_t t = (uint64_t)d[i] * mul + c; /* < 1e9 · 1.3e9 + 2e9 */
            d[i] = (uint32_t)(t % 1000000000u);
            c = t / 1000000000u;
        }
        while (c) {
            d[n++] = (uint32_t)(c % 1000000000u);
            c /= 1000000000u;
        }
        r -= step;
    }
    *e10 = Q >= 0 ? 0 : Q;
    i = sprintf(out, "%u", d[n - 1]);
    for (int j = n - 2; j >= 0; j--)
        i += sprintf(out + i, "%09u", d[j]);
}

/* ------------------------------------------------------------------ */
/* tsu_format_double                                                     */
/* ------------------------------------------------------------------ */

static void test_format_known(void)
{
    /* expected: the layout rules of tsu_io.h with the shortest digits
     * (which are those of Python's repr for these values) */
    static const struct {
        double v;
        const char *s;
    } T[] = {
        {0.1, "0.1"},
        {1e-300, "1e-300"},
        {-2.5, "-2.5"},
        {123456789.0, "123456789"},
        {100.0, "100"},
        {1e16, "10000000000000000"},
        {1e17, "1e+17"},
        {1.5e17, "1.5e+17"},
        {5e-324, "5e-324"},
        {DBL_MAX, "1.7976931348623157e+308"},
        {-DBL_MAX, "-1.7976931348623157e+308"},
        {DBL_MIN, "2.2250738585072014e-308"},
        {0.30000000000000004, "0.30000000000000004"},
        {1e-5, "1e-05"},
        {1e-4, "0.0001"},
        {0.000123, "0.000123"},
        {1.2345e-5, "1.2345e-05"},
        {1e23, "1e+23"},
        {1e22, "1e+22"},
        {9007199254740993.0, "9007199254740992"}, /* 2^53 + 1 rounds to 2^53 */
        {9223372036854775808.0, "9.223372036854776e+18"},
        {12345678901234567.0, "12345678901234568"},
        {123.456, "123.456"},
        {1.5e300, "1.5e+300"},
        {0.0, "0"},
        {-0.0, "-0"},
        {1.0, "1"},
        {-1.0, "-1"},
        {2.0, "2"},
        {0.5, "0.5"},
        {3.0e-310, "3e-310"},
        {2.2250738585072009e-308, "2.225073858507201e-308"}, /* largest subnormal */
        {4.9406564584124654e-323, "5e-323"},
        {1e100, "1e+100"},
        {5e-05, "5e-05"},
        {1234567890123456.7, "1234567890123456.8"},
        {0.1 + 0.7, "0.7999999999999999"},
        {1.0 / 3.0, "0.3333333333333333"},
        {2.0 / 3.0, "0.6666666666666666"},
        {100000.0, "100000"},
        {1e15, "1000000000000000"},
    };
    char buf[TSU_FMT_SIZE];
    for (size_t i = 0; i < sizeof T / sizeof *T; i++) {
        size_t n = tsu_format_double(T[i].v, buf);
        CHECKF(strcmp(buf, T[i].s) == 0 && n == strlen(T[i].s), "format %.17g: got %s, want %s",
               T[i].v, buf, T[i].s);
    }
    CHECK(tsu_format_double((double)NAN, buf) == 3 && strcmp(buf, "nan") == 0);
    CHECK(tsu_format_double(-(double)NAN, buf) == 3 && strcmp(buf, "nan") == 0);
    CHECK(tsu_format_double(HUGE_VAL, buf) == 3 && strcmp(buf, "inf") == 0);
    CHECK(tsu_format_double(-HUGE_VAL, buf) == 4 && strcmp(buf, "-inf") == 0);
}

/* Every line of io_format_ref.txt: same digits and exponent as Python's repr. */
static void test_format_python(void)
{
    FILE *f = fopen(TS_SOURCE_DIR "/tests/tools/data/io_format_ref.txt", "r");
    char line[200], want[64], buf[TSU_FMT_SIZE], d1[40], d2[40];
    long n = 0, bad = 0, e1, e2;
    CHECKF(f != NULL, "cannot open io_format_ref.txt");
    if (!f)
        return;
    while (fgets(line, sizeof line, f)) {
        unsigned long long u;
        if (sscanf(line, "%llx %63s", &u, want) != 2)
            continue;
        n++;
        tsu_format_double(of_bits((uint64_t)u), buf);
        canon(buf, d1, &e1);
        canon(want, d2, &e2);
        if (strcmp(d1, d2) != 0 || e1 != e2) {
            if (bad++ < 5)
                fprintf(stderr, "format %016llx: got %s, python %s\n", u, buf, want);
        }
    }
    fclose(f);
    CHECKF(n > 2000, "only %ld reference lines", n);
    CHECKF(bad == 0, "%ld of %ld differ from Python repr", bad, n);
}

/* A random finite double of one of several kinds. */
static double random_double(int kind)
{
    uint64_t u;
    double d;
    switch (kind) {
    case 0: /* any bit pattern */
        do
            u = rnd();
        while (((u >> 52) & 0x7ff) == 0x7ff);
        return of_bits(u);
    case 1: /* subnormal */
        return of_bits((rnd() & ((UINT64_C(1) << 52) - 1)) | (rnd() & (UINT64_C(1) << 63)));
    case 2: /* power of two or a neighbour */
        u = (uint64_t)(1 + rndn(2046)) << 52;
        u += (uint64_t)rndn(3);
        u -= (uint64_t)rndn(2) * 2;
        return of_bits(u);
    case 3: /* log-uniform in [1e-5, 1e10] */
        return pow(10.0, -5.0 + 15.0 * (double)(rnd() >> 11) * 0x1p-53);
    case 4: { /* a short decimal, as data often are */
        char s[40];
        snprintf(s, sizeof s, "%u.%0*ue%d", rndn(100000), (int)(1 + rndn(6)), rndn(1000000),
                 (int)rndn(41) - 20);
        return strtod(s, NULL);
    }
    case 5: /* integers */
        return (double)(rnd() >> rndn(64));
    default: /* near the extremes */
        d = rndn(2) ? DBL_MAX : DBL_MIN;
        u = bits_of(d) - rndn(1000);
        return of_bits(u);
    }
}

/* Round trip through glibc strtod and through tsu_parse_double, ~2e6 values. */
static void test_format_roundtrip(void)
{
    long n = SCALE(2000000), bad_c = 0, bad_p = 0, bad_len = 0;
    char buf[TSU_FMT_SIZE];
    double t0, tf = 0.0, tp = 0.0;
    static double vals[4096];
    static char strs[4096][TSU_FMT_SIZE];
    for (long i = 0; i < n; i += 4096) {
        int m = 4096;
        for (int j = 0; j < m; j++)
            vals[j] = random_double((int)(((unsigned long)i / 4096 + (unsigned)j) % 7));
        t0 = now();
        for (int j = 0; j < m; j++)
            tsu_format_double(vals[j], strs[j]);
        tf += now() - t0;
        t0 = now();
        for (int j = 0; j < m; j++) {
            double g;
            const char *stop;
            if (tsu_parse_double(strs[j], NULL, &g, &stop) != TSU_NUM_OK || *stop ||
                bits_of(g) != bits_of(vals[j])) {
                if (bad_p++ < 5)
                    fprintf(stderr, "parse back %s -> %a, want %a\n", strs[j], g, vals[j]);
            }
        }
        tp += now() - t0;
        for (int j = 0; j < m; j++) {
            double c = strtod(strs[j], NULL);
            if (bits_of(c) != bits_of(vals[j]) && bad_c++ < 5)
                fprintf(stderr, "strtod(%s) = %a, want %a\n", strs[j], c, vals[j]);
            if (strlen(strs[j]) > 24)
                bad_len++;
        }
    }
    CHECKF(bad_c == 0, "%ld of %ld formatted values do not round-trip through strtod", bad_c, n);
    CHECKF(bad_p == 0, "%ld of %ld do not round-trip through tsu_parse_double", bad_p, n);
    CHECK(bad_len == 0);
    printf("speed: tsu_format_double %.1f M/s, tsu_parse_double (its output) %.1f M/s\n",
           (double)n / tf * 1e-6, (double)n / tp * 1e-6);
    /* the same values with the library */
    t0 = now();
    for (int j = 0; j < 4096 * 25; j++)
        snprintf(buf, sizeof buf, "%.17g", vals[j % 4096]);
    tf = now() - t0;
    t0 = now();
    for (int j = 0; j < 4096 * 25; j++)
        sink = strtod(strs[j % 4096], NULL);
    tp = now() - t0;
    printf("speed: for comparison snprintf %%.17g %.1f M/s, strtod %.1f M/s\n",
           4096 * 25 / tf * 1e-6, 4096 * 25 / tp * 1e-6);
}

/* Shortest: no decimal with fewer digits round-trips (its nearest and both
 * neighbours at one digit less are checked with snprintf + strtod), and at
 * the length of the shortest %.Ne that round-trips the digits are the same. */
static void test_format_shortest(void)
{
    long n = SCALE(100000), bad_short = 0, bad_min = 0, bad_same = 0;
    char buf[TSU_FMT_SIZE], ref[40], d1[40], d2[40];
    for (long i = 0; i < n; i++) {
        double v = fabs(random_double((int)(i % 7)));
        long e1, e2;
        int nref = 17, nd;
        if (v == 0)
            continue;
        tsu_format_double(v, buf);
        canon(buf, d1, &e1);
        nd = (int)strlen(d1);
        for (int p = 1; p <= 17; p++) {
            snprintf(ref, sizeof ref, "%.*e", p - 1, v);
            if (strtod(ref, NULL) == v) {
                nref = p;
                break;
            }
        }
        snprintf(ref, sizeof ref, "%.*e", nref - 1, v);
        canon(ref, d2, &e2);
        if (nd > nref && bad_short++ < 5)
            fprintf(stderr, "%a: %s longer than %s\n", v, buf, ref);
        if (nd == nref && (strcmp(d1, d2) != 0 || e1 != e2) && bad_same++ < 5)
            fprintf(stderr, "%a: %s, printf %s\n", v, buf, ref);
        if (nd >= 2) { /* nothing with nd - 1 digits: nearest, and one unit either side */
            char c[40], *mant;
            long ex;
            snprintf(c, sizeof c, "%.*e", nd - 2, v);
            mant = c;
            ex = strtol(strchr(c, 'e') + 1, NULL, 10);
            {
                char digs[40];
                size_t k = 0;
                unsigned long long x;
                for (const char *p = mant; *p != 'e'; p++)
                    if (*p != '.')
                        digs[k++] = *p;
                digs[k] = 0;
                x = strtoull(digs, NULL, 10);
                for (int dlt = -1; dlt <= 2; dlt++) {
                    char t[60];
                    if (dlt < 2)
                        snprintf(t, sizeof t, "%llue%ld", x + (unsigned long long)(long long)dlt,
                                 ex - (long)(k - 1));
                    else if (digs[0] == '1' && strspn(digs + 1, "0") == k - 1) /* decade below */
                        snprintf(t, sizeof t, "%.*se%ld", (int)k, "99999999999999999", ex - (long)k);
                    else
                        continue;
                    if (strtod(t, NULL) == v && bad_min++ < 5)
                        fprintf(stderr, "%a: %s has %d digits but %s round-trips\n", v, buf, nd, t);
                }
            }
        }
    }
    CHECKF(bad_short == 0, "%ld longer than the shortest %%.Ne", bad_short);
    CHECKF(bad_same == 0, "%ld differ from the shortest %%.Ne of the same length", bad_same);
    CHECKF(bad_min == 0, "%ld not minimal", bad_min);
}

/* ------------------------------------------------------------------ */
/* tsu_parse_double                                                      */
/* ------------------------------------------------------------------ */

/* Compare tsu_parse_double with strtod on s (whole string must be consumed). */
static int parse_agrees(const char *s)
{
    double g, c = strtod(s, NULL);
    const char *stop;
    tsu_num_status st = tsu_parse_double(s, NULL, &g, &stop);
    if (isinf(c))
        return st == TSU_NUM_RANGE && *stop == 0 && g == c;
    return st == TSU_NUM_OK && *stop == 0 && bits_of(g) == bits_of(c);
}

static void random_decimal(char *s)
{
    static const int lens[] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 12, 14, 15, 16, 16, 17, 17, 17,
                               18, 18, 19, 19, 20, 20, 21, 22, 25, 30, 40, 60, 120};
    int nd = lens[rndn(sizeof lens / sizeof *lens)], k = 0, pt = -1, i, intd, x;
    unsigned r = rndn(100);
    if (r < 25)
        s[k++] = '-';
    else if (r < 30)
        s[k++] = '+';
    if (rndn(10) == 0)
        for (i = (int)rndn(3); i >= 0; i--)
            s[k++] = '0';
    if (rndn(10) < 6)
        pt = (int)rndn((unsigned)nd + 1);
    if (pt == 0 && rndn(2))
        s[k++] = '0';
    for (i = 0; i < nd; i++) {
        if (i == pt)
            s[k++] = '.';
        s[k++] = (char)('0' + (i == 0 ? 1 + rndn(9) : rndn(10)));
    }
    if (pt == nd)
        s[k++] = '.';
    intd = pt < 0 ? nd : pt;
    if (rndn(10) < 8) {
        x = (int)rndn(660) - 345; /* decimal exponent of the first digit */
        if (rndn(20) == 0)
            x = rndn(2) ? 308 + (int)rndn(3) : -324 - (int)rndn(3);
        k += sprintf(s + k, "%c%d", rndn(2) ? 'e' : 'E', x - (intd - 1));
    }
    s[k] = 0;
}

static void test_parse_random(void)
{
    long n = SCALE(1000000), bad = 0;
    char s[300];
    for (long i = 0; i < n; i++) {
        random_decimal(s);
        if (!parse_agrees(s) && bad++ < 5) {
            double g;
            tsu_parse_double(s, NULL, &g, NULL);
            fprintf(stderr, "parse %s: %a, strtod %a\n", s, g, strtod(s, NULL));
        }
    }
    CHECKF(bad == 0, "%ld of %ld random decimals differ from strtod", bad, n);
}

/* Halfway points between neighbouring doubles, exactly, and just off. */
static void test_parse_halfway(void)
{
    long n = SCALE(20000), bad = 0, cnt = 0;
    static char D[1500], s[1600];
    for (long i = 0; i < n; i++) {
        uint64_t u = rndn(8) == 0 ? rnd() & ((UINT64_C(1) << 52) - 1) : rnd() & ~(UINT64_C(1) << 63);
        uint64_t m;
        int q, e10, len;
        if ((u >> 52) >= 0x7fe)
            u = (u & ((UINT64_C(1) << 52) - 1)) | ((uint64_t)rndn(0x7fe) << 52);
        if (i % 4 == 0) /* moderate exponents: shorter halfway texts */
            u = (u & ((UINT64_C(1) << 52) - 1)) | ((uint64_t)(1023 - 70 + rndn(140)) << 52);
        q = (int)(u >> 52) == 0 ? -1074 : (int)(u >> 52) - 1075;
        m = (u & ((UINT64_C(1) << 52) - 1)) | ((u >> 52) ? UINT64_C(1) << 52 : 0);
        exact_decimal(2 * m + 1, q - 1, D, &e10); /* (m + 1/2)·2^q */
        len = (int)strlen(D);
        sprintf(s, "%se%d", D, e10); /* exact: ties to even */
        cnt++;
        if (!parse_agrees(s) && bad++ < 5)
            fprintf(stderr, "halfway %.60s... (%d digits)\n", s, len);
        sprintf(s, "%s1e%d", D, e10 - 1); /* a hair above */
        cnt++;
        if (!parse_agrees(s) && bad++ < 5)
            fprintf(stderr, "above halfway %.60s...\n", s);
        if (len > 1) { /* below: the first 1..len-1 digits */
            int t = 1 + (int)rndn((unsigned)len - 1);
            if (rndn(2)) /* around the 19 digits kept exactly */
                t = 17 + (int)rndn(6);
            if (t > len - 1)
                t = len - 1;
            sprintf(s, "%.*se%d", t, D, e10 + (len - t));
            cnt++;
            if (!parse_agrees(s) && bad++ < 5)
                fprintf(stderr, "below halfway %.60s...\n", s);
            /* the same with a decimal point after the first digit */
            sprintf(s, "%c.%se%d", D[0], D + 1, e10 + len - 1);
            cnt++;
            if (!parse_agrees(s) && bad++ < 5)
                fprintf(stderr, "halfway (point) %.60s...\n", s);
        }
    }
    CHECKF(bad == 0, "%ld of %ld halfway texts differ from strtod", bad, cnt);
}

static void test_parse_python(void)
{
    FILE *f = fopen(TS_SOURCE_DIR "/tests/tools/data/io_parse_ref.txt", "r");
    static char line[4096];
    long n = 0, bad = 0;
    CHECKF(f != NULL, "cannot open io_parse_ref.txt");
    if (!f)
        return;
    while (fgets(line, sizeof line, f)) {
        char *sp = strchr(line, ' ');
        double g;
        const char *stop;
        tsu_num_status st;
        int ok;
        if (!sp)
            continue;
        *sp = 0;
        sp++;
        sp[strcspn(sp, "\n")] = 0;
        n++;
        st = tsu_parse_double(line, NULL, &g, &stop);
        if (strcmp(sp, "inf") == 0)
            ok = st == TSU_NUM_RANGE && g == HUGE_VAL;
        else if (strcmp(sp, "-inf") == 0)
            ok = st == TSU_NUM_RANGE && g == -HUGE_VAL;
        else
            ok = st == TSU_NUM_OK && *stop == 0 && bits_of(g) == strtoull(sp, NULL, 16);
        if (!ok && bad++ < 5)
            fprintf(stderr, "python ref %.60s: got %a (status %d), want %s\n", line, g, st, sp);
    }
    fclose(f);
    CHECKF(n > 1900, "only %ld reference lines", n);
    CHECKF(bad == 0, "%ld of %ld differ from Python float()", bad, n);
}

static void test_parse_cases(void)
{
    static const struct {
        const char *s;
        tsu_num_status st;
        int stop;
        double v;
    } T[] = {
        {"abc", TSU_NUM_SYNTAX, 0, 0},
        {"", TSU_NUM_SYNTAX, 0, 0},
        {"-", TSU_NUM_SYNTAX, 1, 0},
        {"+", TSU_NUM_SYNTAX, 1, 0},
        {".", TSU_NUM_SYNTAX, 1, 0},
        {"-.e5", TSU_NUM_SYNTAX, 2, 0},
        {"-x", TSU_NUM_SYNTAX, 1, 0},
        {" 1", TSU_NUM_SYNTAX, 0, 0},
        {"e5", TSU_NUM_SYNTAX, 0, 0},
        {"n", TSU_NUM_SYNTAX, 0, 0},
        {"in", TSU_NUM_SYNTAX, 0, 0},
        {"1e", TSU_NUM_OK, 1, 1.0},
        {"1e+", TSU_NUM_OK, 1, 1.0},
        {"1.5e-3x", TSU_NUM_OK, 6, 1.5e-3},
        {"0x1p3", TSU_NUM_OK, 1, 0.0},
        {"1_000", TSU_NUM_OK, 1, 1.0},
        {"1,5", TSU_NUM_OK, 1, 1.0},
        {".5", TSU_NUM_OK, 2, 0.5},
        {"5.", TSU_NUM_OK, 2, 5.0},
        {"+.5e1", TSU_NUM_OK, 5, 5.0},
        {"00012", TSU_NUM_OK, 5, 12.0},
        {"0.000", TSU_NUM_OK, 5, 0.0},
        {"1E+05", TSU_NUM_OK, 5, 1e5},
        {"1e0000000000000000000000000005", TSU_NUM_OK, 30, 1e5},
        {"1e99999999999999999999", TSU_NUM_RANGE, 22, HUGE_VAL},
        {"-1e99999999999999999999", TSU_NUM_RANGE, 23, -HUGE_VAL},
        {"1e-99999999999999", TSU_NUM_OK, 17, 0.0},
        {"0e999999", TSU_NUM_OK, 8, 0.0},
        {"1e400", TSU_NUM_RANGE, 5, HUGE_VAL},
        {"1.8e308", TSU_NUM_RANGE, 7, HUGE_VAL},
        {"1e-400", TSU_NUM_OK, 6, 0.0},
        {"nan", TSU_NUM_NONFINITE, 3, (double)NAN},
        {"-NaN", TSU_NUM_NONFINITE, 4, (double)NAN},
        {"nan(123)", TSU_NUM_NONFINITE, 3, (double)NAN},
        {"nano", TSU_NUM_NONFINITE, 3, (double)NAN},
        {"inf", TSU_NUM_NONFINITE, 3, HUGE_VAL},
        {"-Inf", TSU_NUM_NONFINITE, 4, -HUGE_VAL},
        {"INFINITY", TSU_NUM_NONFINITE, 8, HUGE_VAL},
        {"infinit", TSU_NUM_NONFINITE, 3, HUGE_VAL},
        {"9007199254740993", TSU_NUM_OK, 16, 9007199254740992.0},
        {"9007199254740995", TSU_NUM_OK, 16, 9007199254740996.0},
        {"0.1", TSU_NUM_OK, 3, 0.1},
        {"123456789012345678901234567890", TSU_NUM_OK, 30, 1.2345678901234568e29},
    };
    for (size_t i = 0; i < sizeof T / sizeof *T; i++) {
        double g = -7;
        const char *stop = NULL;
        tsu_num_status st = tsu_parse_double(T[i].s, NULL, &g, &stop);
        int vok = isnan(T[i].v) ? isnan(g) : bits_of(g) == bits_of(T[i].v);
        CHECKF(st == T[i].st && stop == T[i].s + T[i].stop && vok,
               "parse \"%s\": status %d stop %d value %a (want %d %d %a)", T[i].s, st,
               (int)(stop - T[i].s), g, T[i].st, T[i].stop, T[i].v);
    }
    {
        double g = 1;
        const char *stop = NULL;
        const char *s = "12345";
        CHECK(tsu_parse_double(s, s + 3, &g, &stop) == TSU_NUM_OK && g == 123.0 && stop == s + 3);
        CHECK(tsu_parse_double(s, s, &g, &stop) == TSU_NUM_SYNTAX && stop == s && g == 0.0);
        CHECK(tsu_parse_double("-0", NULL, &g, NULL) == TSU_NUM_OK && g == 0.0 && signbit(g));
        CHECK(tsu_parse_double("-0.0e-999", NULL, &g, NULL) == TSU_NUM_OK && g == 0.0 && signbit(g));
        CHECK(tsu_parse_double("-1e-400", NULL, &g, NULL) == TSU_NUM_OK && g == 0.0 && signbit(g));
        CHECK(tsu_parse_double(NULL, NULL, &g, &stop) == TSU_NUM_SYNTAX && stop == NULL);
        CHECK(tsu_parse_double("2.5", NULL, NULL, NULL) == TSU_NUM_OK);
        /* 1 + 2^-53 exactly (halfway: ties to 1), then with 900 zeros and a 1
         * (just above: 1 + 2^-52); > 19 digits whose truncations disagree go to
         * strtod through a copy of at most 800 digits plus one sticky digit */
        {
            static char h[1100];
            const char *half = "1.00000000000000011102230246251565404236316680908203125";
            strcpy(h, half);
            CHECK(tsu_parse_double(h, NULL, &g, NULL) == TSU_NUM_OK && g == 1.0 && parse_agrees(h));
            memset(h + strlen(half), '0', 900);
            h[strlen(half) + 900] = 0;
            CHECK(tsu_parse_double(h, NULL, &g, NULL) == TSU_NUM_OK && g == 1.0 && parse_agrees(h));
            strcat(h, "1");
            CHECK(tsu_parse_double(h, NULL, &g, NULL) == TSU_NUM_OK && g == 1.0 + 0x1p-52 &&
                  parse_agrees(h));
            strcat(h, "e-5"); /* with an exponent too */
            CHECK(parse_agrees(h));
            memmove(h + 1, h, strlen(h) + 1);
            h[0] = '-';
            CHECK(tsu_parse_double(h, NULL, &g, NULL) == TSU_NUM_OK && g < 0 && parse_agrees(h));
        }
        /* a digit string longer than the strtod fallback's 800-digit copy */
        {
            static char big[3000];
            memset(big, '0', sizeof big - 1);
            big[0] = '4';
            big[1] = '.';
            big[2999] = 0;
            big[2998] = '1';
            CHECK(parse_agrees(big));
            memcpy(big + 2990, "e-308", 6);
            CHECK(parse_agrees(big));
        }
    }
}

/* ------------------------------------------------------------------ */
/* reader                                                               */
/* ------------------------------------------------------------------ */

static FILE *mem_file(const char *text, size_t len)
{
    FILE *f = tmpfile();
    if (!f)
        return NULL;
    if (len)
        fwrite(text, 1, len, f);
    rewind(f);
    return f;
}

/* Read text as a table; returns the status, message in e. */
static tsu_io_status read_text(const char *text, size_t len, const tsu_read_options *opt,
                              tsu_table *t, tsu_io_error *e)
{
    FILE *f = mem_file(text, len);
    tsu_io_status st;
    if (!f)
        return TSU_IO_ERR_READ;
    st = tsu_read_table(f, "t.csv", opt, t, e);
    fclose(f);
    return st;
}

#define RT(text, opt, t, e) read_text(text, sizeof(text) - 1, opt, t, e)

static void expect_error(const char *text, size_t len, const tsu_read_options *opt,
                         tsu_io_status want, const char *msg, unsigned long long line, size_t col)
{
    tsu_table t;
    tsu_io_error e;
    tsu_io_status st = read_text(text, len, opt, &t, &e);
    CHECKF(st == want && e.status == want && strcmp(e.msg, msg) == 0 && e.line == line &&
               e.column == col && t.cols == NULL && t.nrows == 0,
           "input \"%.40s\": status %d, msg '%s' line %llu col %zu; want %d '%s' %llu %zu", text,
           st, e.msg, e.line, e.column, want, msg, line, col);
    /* the streaming reader gives the same error */
    {
        FILE *f = mem_file(text, len);
        tsu_reader *r;
        const double *row;
        tsu_io_error e2;
        tsu_io_status s2 = TSU_IO_OK;
        if (f && tsu_reader_open(&r, f, "t.csv", opt, &e2) == TSU_IO_OK) {
            while ((s2 = tsu_reader_next(r, &row, &e2)) == TSU_IO_OK)
                ;
            CHECKF(s2 == want && strcmp(e2.msg, msg) == 0, "streaming: %s", e2.msg);
            /* sticky */
            CHECK(tsu_reader_next(r, &row, &e2) == want && strcmp(e2.msg, msg) == 0 && row == NULL);
            tsu_reader_free(r);
        }
        if (f)
            fclose(f);
    }
}
#define EXPECT_ERR(text, opt, want, msg, line, col) \
    expect_error(text, sizeof(text) - 1, opt, want, msg, line, col)

static void test_reader_valid(void)
{
    tsu_table t;
    tsu_io_error e;
    tsu_read_options o;

    /* CSV: comments, blank lines, CRLF, spaces, header, no final newline */
    CHECK(RT("# comment\r\n\r\nx, y\r\n1,2\r\n  3 , 4 # c\r\n   \r\n# x\n5,6e1", NULL, &t, &e) ==
          TSU_IO_OK);
    CHECK(t.nrows == 3 && t.ncols == 2 && t.names && strcmp(t.names[0], "x") == 0 &&
          strcmp(t.names[1], "y") == 0);
    if (t.nrows == 3) {
        CHECK(t.cols[0][0] == 1 && t.cols[1][0] == 2 && t.cols[0][1] == 3 && t.cols[1][1] == 4 &&
              t.cols[0][2] == 5 && t.cols[1][2] == 60);
        CHECK(t.lines && t.lines[0] == 4 && t.lines[1] == 5 && t.lines[2] == 8);
    }
    tsu_table_free(&t);
    CHECK(t.cols == NULL && t.names == NULL && t.nrows == 0);

    /* TSV with names containing spaces and parentheses */
    CHECK(RT("time s\tf(t)\n0\t1.5\n 1 \t-2\n", NULL, &t, &e) == TSU_IO_OK);
    CHECK(t.nrows == 2 && t.ncols == 2 && strcmp(t.names[0], "time s") == 0 &&
          strcmp(t.names[1], "f(t)") == 0 && t.cols[1][1] == -2);
    tsu_table_free(&t);

    /* white space, mixed spaces and tabs, three columns, no header */
    CHECK(RT("  1   2 3\n4\t5  \t6\n", NULL, &t, &e) == TSU_IO_OK);
    CHECK(t.nrows == 2 && t.ncols == 3 && t.names == NULL && t.cols[2][1] == 6 && t.cols[0][1] == 4);
    tsu_table_free(&t);

    /* byte-order mark, quoted header names, one column */
    CHECK(RT("\xef\xbb\xbf\"time, s\",\"val\"\"x\"\n1,2\n", NULL, &t, &e) == TSU_IO_OK);
    CHECK(t.ncols == 2 && strcmp(t.names[0], "time, s") == 0 && strcmp(t.names[1], "val\"x") == 0);
    tsu_table_free(&t);
    CHECK(RT("v\n1\n2\n3", NULL, &t, &e) == TSU_IO_OK && t.ncols == 1 && t.nrows == 3 &&
          t.cols[0][2] == 3);
    tsu_table_free(&t);

    /* TSU_HEADER_YES takes a numeric line as names; track_lines = 0 */
    tsu_read_options_init(&o);
    o.header = TSU_HEADER_YES;
    o.track_lines = 0;
    CHECK(RT("1,2\n3,4\n", &o, &t, &e) == TSU_IO_OK && t.nrows == 1 && strcmp(t.names[1], "2") == 0 &&
          t.lines == NULL);
    tsu_table_free(&t);

    /* explicit delimiter: tab given, commas would be errors; explicit ncols */
    tsu_read_options_init(&o);
    o.delim = TSU_DELIM_SPACE;
    o.ncols = 2;
    CHECK(RT("1\t2\n3 4\n", &o, &t, &e) == TSU_IO_OK && t.nrows == 2);
    tsu_table_free(&t);

    /* "nan,1" is data (nan counts as a number for the header rule); "x,nan" a header */
    CHECK(RT("nan,1\n1,2\n", NULL, &t, &e) == TSU_IO_ERR_NONFINITE);
    CHECK(strcmp(e.msg, "t.csv:1:1: not a finite number: \"nan\"") == 0);
    CHECK(RT("x,nan\n1,2\n", NULL, &t, &e) == TSU_IO_OK && strcmp(t.names[1], "nan") == 0);
    tsu_table_free(&t);

    /* the reader's accessors */
    {
        FILE *f = mem_file("a b\n1 2\n\n3 4\n", 13);
        tsu_reader *r;
        const double *row;
        CHECK(tsu_reader_open(&r, f, NULL, NULL, &e) == TSU_IO_OK);
        CHECK(tsu_reader_next(r, &row, &e) == TSU_IO_OK && row[0] == 1 && tsu_reader_line(r) == 2);
        CHECK(tsu_reader_ncols(r) == 2 && tsu_reader_nnames(r) == 2 &&
              strcmp(tsu_reader_name(r, 1), "b") == 0 && tsu_reader_name(r, 2) == NULL);
        CHECK(strcmp(tsu_reader_source(r), "<input>") == 0 && tsu_reader_delim(r) == TSU_DELIM_SPACE);
        CHECK(tsu_reader_next(r, &row, &e) == TSU_IO_OK && row[1] == 4 && tsu_reader_line(r) == 4);
        CHECK(tsu_reader_next(r, &row, &e) == TSU_IO_END && row == NULL && tsu_reader_rows(r) == 2);
        CHECK(tsu_reader_next(r, &row, &e) == TSU_IO_END);
        tsu_reader_free(r);
        fclose(f);
    }
    CHECK(tsu_reader_ncols(NULL) == 0 && tsu_reader_name(NULL, 0) == NULL && tsu_reader_line(NULL) == 0);

    /* header details: blanks around names, text after a closing quote */
    CHECK(RT("a ,\"b\" , c\n1,2,3\n", NULL, &t, &e) == TSU_IO_OK && t.ncols == 3 &&
          strcmp(t.names[0], "a") == 0 && strcmp(t.names[1], "b") == 0 && strcmp(t.names[2], "c") == 0);
    tsu_table_free(&t);
    CHECK(RT("\"a b\" \"c\"\n1 2\n", NULL, &t, &e) == TSU_IO_OK && t.ncols == 2 &&
          strcmp(t.names[0], "a b") == 0);
    tsu_table_free(&t);


    /* a file by path, and "-" for standard input */
    CHECK(tsu_read_table_path(TS_SOURCE_DIR "/tests/tools/data/io_sample.tsv", NULL, &t, &e) == TSU_IO_OK);
    CHECK(t.nrows == 3 && t.ncols == 2 && strcmp(t.names[0], "t (s)") == 0 &&
          strcmp(t.names[1], "y") == 0 && t.cols[1][1] == -2e-3 && t.cols[0][2] == 100 &&
          t.lines[2] == 6);
    tsu_table_free(&t);
    CHECK(tsu_read_table_path(TS_SOURCE_DIR "/tests/tools/data/io_bad.csv", NULL, &t, &e) ==
              TSU_IO_ERR_NUMBER &&
          strcmp(e.msg, TS_SOURCE_DIR "/tests/tools/data/io_bad.csv:3:3: expected a number, found \"abc\"") ==
              0);
    if (freopen(TS_SOURCE_DIR "/tests/tools/data/io_sample.tsv", "r", stdin)) {
        CHECK(tsu_read_table_path("-", NULL, &t, &e) == TSU_IO_OK && t.nrows == 3);
        tsu_table_free(&t);
    }
    if (freopen(TS_SOURCE_DIR "/tests/tools/data/io_bad.csv", "r", stdin)) {
        CHECK(tsu_read_table_path("-", NULL, &t, &e) == TSU_IO_ERR_NUMBER &&
              strcmp(e.msg, "<stdin>:3:3: expected a number, found \"abc\"") == 0);
    }
    tsu_reader_free(NULL);
    tsu_table_free(NULL);
}

static void test_reader_errors(void)
{
    tsu_read_options o;
    EXPECT_ERR("x,y\n1,2\n3,abc\n", NULL, TSU_IO_ERR_NUMBER,
               "t.csv:3:3: expected a number, found \"abc\"", 3, 3);
    EXPECT_ERR("1,2\n3,4,5\n", NULL, TSU_IO_ERR_FIELDS,
               "t.csv:2:5: wrong number of fields (3, expected 2)", 2, 5);
    EXPECT_ERR("1,2\n3\n", NULL, TSU_IO_ERR_FIELDS,
               "t.csv:2:2: wrong number of fields (1, expected 2)", 2, 2);
    EXPECT_ERR("1 2\n3 4 5 6 # c\n", NULL, TSU_IO_ERR_FIELDS,
               "t.csv:2:5: wrong number of fields (4, expected 2)", 2, 5);
    EXPECT_ERR("1,2\n3,nan\n", NULL, TSU_IO_ERR_NONFINITE, "t.csv:2:3: not a finite number: \"nan\"",
               2, 3);
    EXPECT_ERR("1,2\n3, -Infinity \n", NULL, TSU_IO_ERR_NONFINITE,
               "t.csv:2:4: not a finite number: \"-Infinity\"", 2, 4);
    EXPECT_ERR("1,2\n3,1e999\n", NULL, TSU_IO_ERR_RANGE, "t.csv:2:3: number out of range: \"1e999\"",
               2, 3);
    EXPECT_ERR("1,2\n3,,4\n", NULL, TSU_IO_ERR_NUMBER, "t.csv:2:3: empty field", 2, 3);
    EXPECT_ERR("1,2\n,4\n", NULL, TSU_IO_ERR_NUMBER, "t.csv:2:1: empty field", 2, 1);
    EXPECT_ERR("1,2\n3,\n", NULL, TSU_IO_ERR_NUMBER, "t.csv:2:3: empty field", 2, 3);
    EXPECT_ERR("1,\n", NULL, TSU_IO_ERR_NUMBER, "t.csv:1:3: empty field", 1, 3);
    EXPECT_ERR("", NULL, TSU_IO_ERR_EMPTY, "t.csv: no data (empty input)", 0, 0);
    EXPECT_ERR("# only a comment\n\n  \n", NULL, TSU_IO_ERR_EMPTY, "t.csv: no data (empty input)", 0,
               0);
    EXPECT_ERR("x,y\n# nothing\n", NULL, TSU_IO_ERR_EMPTY, "t.csv: no data rows", 0, 0);
    EXPECT_ERR("1 2\n3 4x\n", NULL, TSU_IO_ERR_NUMBER, "t.csv:2:3: expected a number, found \"4x\"",
               2, 3);
    EXPECT_ERR("1,2\n3,4 5\n", NULL, TSU_IO_ERR_NUMBER, "t.csv:2:3: expected a number, found \"4 5\"",
               2, 3);
    EXPECT_ERR("1,2\nabc ,4\n", NULL, TSU_IO_ERR_NUMBER, "t.csv:2:1: expected a number, found \"abc\"",
               2, 1);
    EXPECT_ERR("1,2\n0x10,2\n", NULL, TSU_IO_ERR_NUMBER,
               "t.csv:2:1: expected a number, found \"0x10\"", 2, 1);
    EXPECT_ERR("1,2\r\n3,x\r\n", NULL, TSU_IO_ERR_NUMBER, "t.csv:2:3: expected a number, found \"x\"",
               2, 3);
    EXPECT_ERR("1\t2\n3\tz\n", NULL, TSU_IO_ERR_NUMBER, "t.csv:2:3: expected a number, found \"z\"",
               2, 3);
    EXPECT_ERR("1\t2\n3\t\t4\n", NULL, TSU_IO_ERR_NUMBER, "t.csv:2:3: empty field", 2, 3);
    /* RFC 4180 quoting: errors */
    EXPECT_ERR("a,b\n\"open,x\n1,2\n", NULL, TSU_IO_ERR_QUOTE,
               "t.csv:2: quote not closed (the quoted field starting on this line runs to the "
               "end of the input)", 2, 0);
    EXPECT_ERR("a,b\n\"1\"x,2\n", NULL, TSU_IO_ERR_QUOTE,
               "t.csv:2:4: text after the closing quote", 2, 4);
    EXPECT_ERR("a,b\n\"1,000\",2\n", NULL, TSU_IO_ERR_NUMBER,
               "t.csv:2:1: expected a number, found \"1,000\" (digit grouping is not accepted; "
               "a decimal comma needs --decimal-comma)", 2, 1);
    EXPECT_ERR("1,2\n3,4\xc3\xa9\n", NULL, TSU_IO_ERR_NUMBER,
               "t.csv:2:3: expected a number, found \"4\\xc3\\xa9\"", 2, 3);
    expect_error("1,2\n3,\0\n", 7, NULL, TSU_IO_ERR_NUMBER,
                 "t.csv:2:3: expected a number, found \"\\x00\"", 2, 3);
    EXPECT_ERR("1,2\n3,aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa\n", NULL,
               TSU_IO_ERR_NUMBER,
               "t.csv:2:3: expected a number, found \"aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa\"...", 2,
               3);
    /* the byte-order mark is not counted in columns */
    tsu_read_options_init(&o);
    o.header = TSU_HEADER_NONE;
    EXPECT_ERR("\xef\xbb\xbf" "1,x\n", &o, TSU_IO_ERR_NUMBER, "t.csv:1:3: expected a number, found \"x\"",
               1, 3);
    EXPECT_ERR("x,y\n1,2\n", &o, TSU_IO_ERR_NUMBER, "t.csv:1:1: expected a number, found \"x\"", 1, 1);
    /* required number of columns */
    tsu_read_options_init(&o);
    o.ncols = 2;
    EXPECT_ERR("a,b,c\n1,2,3\n", &o, TSU_IO_ERR_FIELDS,
               "t.csv:1:5: wrong number of fields (3, expected 2)", 1, 5);
    EXPECT_ERR("a\n1\n", &o, TSU_IO_ERR_FIELDS, "t.csv:1:2: wrong number of fields (1, expected 2)",
               1, 2);
    EXPECT_ERR("1 2 3\n", &o, TSU_IO_ERR_FIELDS, "t.csv:1:5: wrong number of fields (3, expected 2)",
               1, 5);
    /* header fixes the count */
    EXPECT_ERR("a,b\n1,2,3\n", NULL, TSU_IO_ERR_FIELDS,
               "t.csv:2:5: wrong number of fields (3, expected 2)", 2, 5);
    /* long lines */
    tsu_read_options_init(&o);
    o.max_line = 16;
    o.buffer_size = 16;
    EXPECT_ERR("1,2\n123456789012345,1\n", &o, TSU_IO_ERR_LINE, "t.csv:2: line longer than 16 bytes",
               2, 0);
    EXPECT_ERR("1,2\n123456789012345,1", &o, TSU_IO_ERR_LINE, "t.csv:2: line longer than 16 bytes",
               2, 0);
    {
        tsu_table t;
        tsu_io_error e;
        /* exactly 16 bytes is fine, also at the end without newline */
        CHECK(RT("1,2\n1234567890123,1\n1234567890123,2", &o, &t, &e) == TSU_IO_OK && t.nrows == 3);
        tsu_table_free(&t);
    }
    /* options and arguments */
    {
        tsu_table t;
        tsu_io_error e;
        tsu_reader *r = (tsu_reader *)&e;
        FILE *f = tmpfile();
        tsu_read_options_init(&o);
        o.max_line = 5;
        CHECK(tsu_read_table(f, "t", &o, &t, &e) == TSU_IO_ERR_OPTION &&
              strcmp(e.msg, "t: invalid option") == 0);
        tsu_read_options_init(&o);
        o.delim = (tsu_delim)9;
        CHECK(tsu_reader_open(&r, f, "t", &o, &e) == TSU_IO_ERR_OPTION && r == NULL);
        tsu_read_options_init(&o);
        o.header = (tsu_header)-1;
        CHECK(tsu_reader_open(&r, f, "t", &o, &e) == TSU_IO_ERR_OPTION);
        tsu_read_options_init(&o);
        o.buffer_size = 3;
        CHECK(tsu_reader_open(&r, f, "t", &o, &e) == TSU_IO_ERR_OPTION);
        CHECK(tsu_reader_open(&r, NULL, "t", NULL, &e) == TSU_IO_ERR_NULL && r == NULL);
        CHECK(tsu_reader_open(NULL, f, "t", NULL, &e) == TSU_IO_ERR_NULL);
        CHECK(tsu_reader_next(NULL, NULL, &e) == TSU_IO_ERR_NULL);
        CHECK(tsu_read_table(f, "t", NULL, NULL, &e) == TSU_IO_ERR_NULL);
        CHECK(tsu_read_table_path(NULL, NULL, &t, &e) == TSU_IO_ERR_NULL);
        CHECK(tsu_read_table_path("/nonexistent-dir/x.csv", NULL, &t, &e) == TSU_IO_ERR_OPEN &&
              e.sys_errno == ENOENT &&
              strcmp(e.msg, "/nonexistent-dir/x.csv: cannot open: No such file or directory") == 0);
        tsu_read_options_init(NULL);
        fclose(f);
        /* a read error: reading a stream open for writing only */
        f = fopen("/dev/null", "w");
        if (f) {
            CHECK(tsu_read_table(f, "w.csv", NULL, &t, &e) == TSU_IO_ERR_READ && e.sys_errno != 0 &&
                  strncmp(e.msg, "w.csv: read error: ", 19) == 0);
            fclose(f);
        }
    }
    for (int s = 0; s <= TSU_IO_STATUS_COUNT_; s++)
        CHECK(tsu_io_strerror((tsu_io_status)s) != NULL);
    CHECK(strcmp(tsu_io_strerror((tsu_io_status)99), "unknown status") == 0);
}

/* A generated file read with several buffer sizes, read-all and streaming:
 * the values are those written, bit for bit, and the lines agree. */
/* Real-world layouts (docs/cli.md "Input"): quoting, delimiters, decimal
 * comma, missing values, skipped lines, dates, and the header rule. */
static void test_reader_realworld(void)
{
    tsu_table t;
    tsu_io_error e;
    tsu_read_options o;

    /* a quoted number is a number; quoted fields hold delimiters, "" and line breaks */
    CHECK(RT("\"0\",\"1\"\n1,2\n2,3\n", NULL, &t, &e) == TSU_IO_OK && t.nrows == 3 &&
          t.names == NULL && t.cols[0][0] == 0 && t.cols[1][0] == 1); /* issue: no silent loss */
    tsu_table_free(&t);
    CHECK(RT("\"a,\"\"x\"\"\",\"b\nc\"\n1,\" 2 \"\n", NULL, &t, &e) == TSU_IO_OK && t.nrows == 1 &&
          strcmp(t.names[0], "a,\"x\"") == 0 && strcmp(t.names[1], "b\nc") == 0 &&
          t.cols[1][0] == 2 && t.lines[0] == 3);
    tsu_table_free(&t);
    CHECK(RT("\"x # not a comment\",y # a comment\n1,2\n", NULL, &t, &e) == TSU_IO_OK &&
          strcmp(t.names[0], "x # not a comment") == 0 && t.nrows == 1);
    tsu_table_free(&t);
    /* names that start like nan / inf are names */
    CHECK(RT("nanoseconds,infections\n1,2\n", NULL, &t, &e) == TSU_IO_OK && t.nrows == 1 &&
          strcmp(t.names[0], "nanoseconds") == 0);
    tsu_table_free(&t);
    /* ';' files: "0;1" is data, not a header */
    CHECK(RT("0;1\n1;2\n", NULL, &t, &e) == TSU_IO_OK && t.nrows == 2 && t.names == NULL &&
          t.cols[1][1] == 2);
    tsu_table_free(&t);
    /* decimal comma */
    tsu_read_options_init(&o);
    o.decimal_comma = 1;
    CHECK(RT("t;v\n0,5;1,25\n1;-2,5e1\n", &o, &t, &e) == TSU_IO_OK && t.nrows == 2 &&
          t.cols[0][0] == 0.5 && t.cols[1][0] == 1.25 && t.cols[1][1] == -25);
    tsu_table_free(&t);
    EXPECT_ERR("t;v\n1.5;2\n", &o, TSU_IO_ERR_NUMBER,
               "t.csv:2:1: expected a number, found \"1.5\" ('.' is not accepted with a decimal "
               "comma)", 2, 1);
    o.delim = TSU_DELIM_COMMA; /* contradicts the decimal comma */
    EXPECT_ERR("1;2\n", &o, TSU_IO_ERR_OPTION, "t.csv: invalid option", 0, 0);
    /* missing values */
    tsu_read_options_init(&o);
    o.na = "NA, null";
    CHECK(RT("x,y\n1,NA\n2,\n3,na\n4,NaN\n", &o, &t, &e) == TSU_IO_ERR_NONFINITE);
    tsu_table_free(&t);
    o.na = "NA,NaN,null";
    CHECK(RT("x,y\n1,NA\n2,\n3,\"\"\n4,nan\n5,6\n", &o, &t, &e) == TSU_IO_OK && t.nrows == 5 &&
          isnan(t.cols[1][0]) && isnan(t.cols[1][1]) && isnan(t.cols[1][2]) &&
          isnan(t.cols[1][3]) && t.cols[1][4] == 6);
    tsu_table_free(&t);
    CHECK(RT("NA,1\n2,3\n", &o, &t, &e) == TSU_IO_OK && t.nrows == 2 && t.names == NULL);
    tsu_table_free(&t);
    /* skipped lines (metadata without '#') */
    tsu_read_options_init(&o);
    o.skip = 2;
    CHECK(RT("Station: Bern, CH\nUnits: s\nt,v\n1,2\n", &o, &t, &e) == TSU_IO_OK && t.nrows == 1 &&
          strcmp(t.names[1], "v") == 0 && t.lines[0] == 4);
    tsu_table_free(&t);
    EXPECT_ERR("Station_Bern\nt,v\n1,2\n", NULL, TSU_IO_ERR_NUMBER,
               "t.csv:2:1: expected a number, found \"t,v\" (the delimiter is white space; this "
               "line has ',': mixed delimiters? see --delimiter)", 2, 1);
    EXPECT_ERR("Station Bern\nt v w\n1 2 3\n", NULL, TSU_IO_ERR_LAYOUT,
               "t.csv:2:1: every field of this line is text: a second header line (units?) after "
               "the header on line 1? skip it with --units-row (lines before the header: "
               "--skip N)", 2, 1);
    /* a second header line */
    EXPECT_ERR("day,rain\nd,mm\n1,2\n", NULL, TSU_IO_ERR_LAYOUT,
               "t.csv:2:1: every field of this line is text: a second header line (units?) after "
               "the header on line 1? skip it with --units-row (lines before the header: "
               "--skip N)", 2, 1);
    /* mixed delimiters */
    EXPECT_ERR("a,b\n1;2\n", NULL, TSU_IO_ERR_NUMBER,
               "t.csv:2:1: expected a number, found \"1;2\" (the delimiter is ','; this line has "
               "';': mixed delimiters? see --delimiter)", 2, 1);
    /* dates */
    tsu_read_options_init(&o);
    o.time_detect = 1;
    {
        FILE *f = mem_file("when,v\n2024-03-01,1\n2024-03-01T12:30:15.25Z,2\n2024-03-02 01:00+02:00,3\n",
                           70);
        tsu_reader *r;
        const double *row;
        tsu_time_form tf;
        CHECK(f && tsu_reader_open(&r, f, "t.csv", &o, &e) == TSU_IO_OK);
        if (f && r) {
            CHECK(tsu_reader_next(r, &row, &e) == TSU_IO_OK && row[0] == 1709251200.0);
            CHECK(tsu_reader_is_time(r, 0, &tf) && tf.date_only && !tsu_reader_is_time(r, 1, NULL));
            CHECK(tsu_reader_next(r, &row, &e) == TSU_IO_OK && row[0] == 1709251200.0 + 45015.25);
            CHECK(tsu_reader_next(r, &row, &e) == TSU_IO_OK && row[0] == 1709251200.0 + 82800.0);
            tsu_reader_free(r);
        }
        if (f)
            fclose(f);
    }
    EXPECT_ERR("when,v\n2024-02-29,1\n2023-02-29,2\n", &o, TSU_IO_ERR_TIME,
               "t.csv:3:1: not a valid ISO 8601 date or date-time: \"2023-02-29\" "
               "(YYYY-MM-DD[THH:MM[:SS]][Z|+HH:MM])", 3, 1);
    /* white space as the delimiter ends a date at its blank (the man page: use
     * the T form there); a date-time with a space was read as one field by
     * the dates' fast path (found by fuzz_table) */
    EXPECT_ERR("2024-03-01 1\n2024-03-01 06:30 2\n", &o, TSU_IO_ERR_NUMBER,
               "t.csv:2:12: expected a number, found \"06:30\" (white space separates fields: write "
               "a date-time with T, YYYY-MM-DDTHH:MM)", 2, 12);
    /* a first line of dates is data */
    CHECK(RT("2024-01-01,1\n2024-01-02,2\n", &o, &t, &e) == TSU_IO_OK && t.nrows == 2 &&
          t.cols[0][1] - t.cols[0][0] == 86400);
    tsu_table_free(&t);
    /* time formatting: round trip of forms and fractions */
    {
        char b[TSU_TIME_SIZE];
        double v;
        tsu_time_form tf;
        const char *stop;
        static const char *const forms[] = {"2024-03-01", "2024-03-01T06:00", "2024-03-01 06:00:07",
                                            "2024-03-01T06:00:07.125Z", "1969-12-31T23:59:59-05:30",
                                            "2000-02-29T00:00:00+0100", "1970-01-01T00:00:00.3Z"};
        for (size_t i = 0; i < sizeof forms / sizeof forms[0]; i++) {
            CHECK(tsu_parse_time(forms[i], NULL, &v, &tf, &stop) && *stop == 0);
            tsu_format_time(v, &tf, b);
            CHECKF(strcmp(b, forms[i]) == 0, "%s -> %s", forms[i], b);
        }
        CHECK(tsu_parse_time("2024-03-01", NULL, &v, &tf, NULL));
        tsu_format_time(v + 21600.5, &tf, b);
        CHECK(strcmp(b, "2024-03-01T06:00:00.5") == 0);
        CHECK(!tsu_parse_time("2024-03-01T24:00", NULL, &v, &tf, NULL));
        CHECK(!tsu_parse_time("2024-03-01T23:59:60", NULL, &v, &tf, NULL)); /* no leap seconds */
    }
}

/* tsu_parse_time_format against the ISO reading of the same instants; the
 * reader's time_format, skip_after_header, header_corner and compressed input. */
static void test_time_format(void)
{
    static const struct {
        const char *fmt, *text, *iso;
    } ok[] = {{"%d/%m/%Y %H:%M", "05/01/2024 10:30", "2024-01-05T10:30Z"},
              {"%d/%m/%Y %H:%M", "5/1/2024  9:05", "2024-01-05T09:05Z"},
              {"%Y%m%d%H%M", "202401051030", "2024-01-05T10:30Z"},
              {"%y-%m-%d", "69-07-20", "1969-07-20"},
              {"%y-%m-%d", "68-07-20", "2068-07-20"},
              {"%Y-%j", "2024-060", "2024-02-29"},
              {"%Y-%j", "2023-365", "2023-12-31"},
              {"%d %B %Y", "29 February 2024", "2024-02-29"},
              {"%b %e %Y %I:%M:%S %p", "Mar  1 2024 12:00:05 AM", "2024-03-01T00:00:05Z"},
              {"%b %e %Y %I:%M %p", "mar 1 2024 12:30 pm", "2024-03-01T12:30Z"},
              {"%FT%T.%f%z", "2024-03-01T06:00:07.125+05:30", "2024-03-01T06:00:07.125+05:30"},
              {"%F %R %z", "2024-03-01 06:00 -0230", "2024-03-01T06:00-02:30"},
              {"%d.%m.%Y %H:%M:%S %z", "01.03.2024 06:00:00 Z", "2024-03-01T06:00:00Z"},
              {"%H:%M %%%d/%m/%Y", "10:00 %5/1/2024", "2024-01-05T10:00Z"}};
    for (size_t i = 0; i < sizeof ok / sizeof ok[0]; i++) {
        double a = 0, b = -1;
        tsu_time_form f;
        const char *stop;
        int got = tsu_parse_time_format(ok[i].fmt, ok[i].text, NULL, &a, &f, &stop);
        CHECK(tsu_parse_time(ok[i].iso, NULL, &b, NULL, NULL));
        CHECKF(got && *stop == 0 && a == b, "%s on \"%s\": %d %.17g %.17g", ok[i].fmt,
               ok[i].text, got, a, b);
    }
    static const struct {
        const char *fmt, *text;
    } bad[] = {{"%d/%m/%Y", "31/02/2024"}, {"%d/%m/%Y", "00/01/2024"}, {"%m/%d/%Y", "13/01/2024"},
               {"%Y-%j", "2023-366"},      {"%H:%M", "24:00"},          {"%H:%M:%S", "10:00:60"},
               {"%d/%m/%Y", "05-01-2024"}, {"%Y", "24"},                {"%d %b %Y", "5 Foo 2024"},
               {"%Y-%m-%d %z", "2024-01-05 +25"}, {"%Q", "1"},          {"%H:%M", ""}};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        double a;
        CHECKF(!tsu_parse_time_format(bad[i].fmt, bad[i].text, NULL, &a, NULL, NULL),
               "%s on \"%s\" accepted", bad[i].fmt, bad[i].text);
    }
    CHECK(!tsu_parse_time_format(NULL, "2024", NULL, NULL, NULL, NULL));
    {
        tsu_time_form f;
        double v;
        char b[TSU_TIME_SIZE];
        CHECK(tsu_parse_time_format("%d/%m/%Y", "05/01/2024", NULL, &v, &f, NULL) && f.date_only);
        tsu_format_time(v, &f, b);
        CHECK(strcmp(b, "2024-01-05") == 0);
        CHECK(tsu_parse_time_format("%d/%m/%Y %H:%M", "05/01/2024 10:00", NULL, &v, &f, NULL) &&
              !f.date_only && !f.seconds && f.zone == 0);
        tsu_format_time(v, &f, b);
        CHECK(strcmp(b, "2024-01-05T10:00") == 0);
    }
    tsu_table t;
    tsu_io_error e;
    tsu_read_options o;
    tsu_read_options_init(&o);
    o.time_detect = 1;
    o.time_format = "%d/%m/%Y %H:%M";
    CHECK(RT("t;q\n05/01/2024 10:00;1\n05/01/2024 11:00;2\n", &o, &t, &e) == TSU_IO_OK &&
          t.nrows == 2 && t.cols[0][1] - t.cols[0][0] == 3600 && t.names);
    tsu_table_free(&t);
    /* the first data line in the format is data, not a header */
    CHECK(RT("05/01/2024 10:00;1\n05/01/2024 11:00;2\n", &o, &t, &e) == TSU_IO_OK &&
          t.nrows == 2 && !t.names);
    tsu_table_free(&t);
    EXPECT_ERR("t;q\n05/01/2024 10:00;1\n2024-01-05T11:00;2\n", &o, TSU_IO_ERR_TIME,
               "t.csv:3:1: not a date of the format \"%d/%m/%Y %H:%M\": \"2024-01-05T11:00\"", 3,
               1);
    /* units row */
    tsu_read_options_init(&o);
    o.skip_after_header = 1;
    CHECK(RT("# c\nday,rain\n\n# c\nd,mm\n1,2\n3,4\n", &o, &t, &e) == TSU_IO_OK &&
          t.nrows == 2 && t.lines[0] == 6 && strcmp(t.names[1], "rain") == 0);
    tsu_table_free(&t);
    CHECK(RT("1,2\n3,4\n", &o, &t, &e) == TSU_IO_OK && t.nrows == 2); /* no header: none */
    tsu_table_free(&t);
    /* the corner cell of a matrix */
    tsu_read_options_init(&o);
    o.header_corner = 1;
    CHECK(RT(",1,2\n10,3,4\n", &o, &t, &e) == TSU_IO_OK && t.nrows == 1 && t.names &&
          strcmp(t.names[0], "") == 0 && strcmp(t.names[2], "2") == 0);
    tsu_table_free(&t);
    CHECK(RT("0,1,2\n10,3,4\n", &o, &t, &e) == TSU_IO_OK && t.nrows == 2 && !t.names);
    tsu_table_free(&t);
    EXPECT_ERR(",1,2\n10,3,4\n", NULL, TSU_IO_ERR_NUMBER, "t.csv:1:1: empty field", 1, 1);
    /* a column forced to dates: after the layout, before the first row */
    {
        FILE *f = mem_file("d,q\n20240105,1\n20240106,2\n", 27);
        tsu_reader *r;
        const double *row;
        tsu_read_options_init(&o);
        o.time_format = "%Y%m%d";
        CHECK(tsu_reader_open(&r, f, "t.csv", &o, &e) == TSU_IO_OK);
        CHECK(tsu_reader_set_time_column(r, 0) == -1); /* columns not known yet */
        CHECK(tsu_reader_layout(r, &e) == TSU_IO_OK);
        CHECK(tsu_reader_set_time_column(r, 2) == -1); /* not a column */
        CHECK(tsu_reader_set_time_column(r, 0) == 0);
        CHECK(tsu_reader_next(r, &row, &e) == TSU_IO_OK && row[0] == 19727.0 * 86400 &&
              tsu_reader_is_time(r, 0, NULL) && !tsu_reader_is_time(r, 1, NULL));
        CHECK(tsu_reader_set_time_column(r, 1) == -1); /* too late */
        CHECK(tsu_reader_set_time_column(NULL, 0) == -1);
        tsu_reader_free(r);
        fclose(f);
    }
    /* compressed input */
    EXPECT_ERR("\x1f\x8b\x08\x00\x00\x00\x00\x00", NULL, TSU_IO_ERR_ENCODING,
               "t.csv: gzip-compressed input: decompress it first (zcat t.csv | trigspline ...)",
               0, 0);
    EXPECT_ERR("PK\x03\x04\x14\x00", NULL, TSU_IO_ERR_ENCODING,
               "t.csv: a zip archive (or a spreadsheet: .xlsx, .ods): extract the table or save "
               "it as CSV first", 0, 0);
    /* one byte of gzip's magic is text */
    CHECK(RT("\x1f", NULL, &t, &e) != TSU_IO_ERR_ENCODING);
    tsu_table_free(&t);
}

/* tsu_reader_layout and tsu_reader_use_columns: the columns not chosen hold any text. */
static void test_reader_columns(void)
{
    static const char text[] = "name,t,v,note\nAlpha, 1 ,0.5,\"a, b\"\n\"Beta \"\"x\"\"\",2,NA,"
                               "-\nGamma,4,7,\n";
    static const char nohdr[] = "Alpha,1,0.5\nBeta,2,2.25\n";
    tsu_read_options o;
    tsu_io_error e;
    tsu_reader *r = NULL;
    const double *row;
    size_t use[2] = {1, 2};
    tsu_read_options_init(&o);
    o.na = "NA";
    FILE *f = mem_file(text, sizeof text - 1);
    CHECK(f && tsu_reader_open(&r, f, "c.csv", &o, &e) == TSU_IO_OK);
    if (f && r) {
        CHECK(tsu_reader_layout(r, &e) == TSU_IO_OK && tsu_reader_ncols(r) == 4 &&
              tsu_reader_nnames(r) == 4 && strcmp(tsu_reader_name(r, 3), "note") == 0 &&
              tsu_reader_line(r) == 2 && tsu_reader_rows(r) == 0);
        CHECK(tsu_reader_layout(r, &e) == TSU_IO_OK && tsu_reader_line(r) == 2); /* idempotent */
        CHECK(tsu_reader_use_columns(r, use, 2, &e) == TSU_IO_OK);
        CHECK(tsu_reader_next(r, &row, &e) == TSU_IO_OK && row[1] == 1 && row[2] == 0.5 &&
              isnan(row[0]) && isnan(row[3]) && tsu_reader_missing(r) == 0 &&
              tsu_reader_line(r) == 2);
        CHECK(tsu_reader_next(r, &row, &e) == TSU_IO_OK && row[1] == 2 && isnan(row[2]) &&
              tsu_reader_missing(r) == 1);
        CHECK(tsu_reader_next(r, &row, &e) == TSU_IO_OK && row[1] == 4 && row[2] == 7);
        CHECK(tsu_reader_next(r, &row, &e) == TSU_IO_END);
        tsu_reader_free(r);
        r = NULL;
    }
    if (f)
        fclose(f);
    /* every column parsed (no choice): the text is an error naming line and column */
    f = mem_file(text, sizeof text - 1);
    CHECK(f && tsu_reader_open(&r, f, "c.csv", &o, &e) == TSU_IO_OK);
    if (f && r) {
        CHECK(tsu_reader_next(r, &row, &e) == TSU_IO_ERR_NUMBER &&
              strcmp(e.msg, "c.csv:2:1: expected a number, found \"Alpha\"") == 0);
        tsu_reader_free(r);
        r = NULL;
    }
    if (f)
        fclose(f);
    /* chosen before the header test: line 1 is data, not a header */
    f = mem_file(nohdr, sizeof nohdr - 1);
    CHECK(f && tsu_reader_open(&r, f, "n.csv", &o, &e) == TSU_IO_OK);
    if (f && r) {
        size_t u2[2] = {1, 2};
        CHECK(tsu_reader_use_columns(r, u2, 2, &e) == TSU_IO_OK);
        CHECK(tsu_reader_layout(r, &e) == TSU_IO_OK && tsu_reader_nnames(r) == 0 &&
              tsu_reader_ncols(r) == 3 && tsu_reader_line(r) == 1);
        CHECK(tsu_reader_next(r, &row, &e) == TSU_IO_OK && row[1] == 1 && row[2] == 0.5);
        tsu_reader_free(r);
        r = NULL;
    }
    if (f)
        fclose(f);
    /* a chosen column still checked; a quote error in another one is still an error */
    f = mem_file("a,b\nu,2\n3,x\n", 12);
    CHECK(f && tsu_reader_open(&r, f, "q.csv", &o, &e) == TSU_IO_OK);
    if (f && r) {
        size_t u1[1] = {1};
        CHECK(tsu_reader_use_columns(r, u1, 1, &e) == TSU_IO_OK);
        CHECK(tsu_reader_next(r, &row, &e) == TSU_IO_OK && row[1] == 2);
        CHECK(tsu_reader_next(r, &row, &e) == TSU_IO_ERR_NUMBER &&
              strcmp(e.msg, "q.csv:3:3: expected a number, found \"x\"") == 0);
        tsu_reader_free(r);
        r = NULL;
    }
    if (f)
        fclose(f);
    f = mem_file("a,b\n\"x\"y,1\n", 11);
    CHECK(f && tsu_reader_open(&r, f, "q.csv", &o, &e) == TSU_IO_OK);
    if (f && r) {
        size_t u1[1] = {1};
        CHECK(tsu_reader_use_columns(r, u1, 1, &e) == TSU_IO_OK);
        CHECK(tsu_reader_layout(r, &e) == TSU_IO_OK);
        CHECK(tsu_reader_next(r, &row, &e) == TSU_IO_ERR_QUOTE && e.line == 2 && e.column == 4);
        tsu_reader_free(r);
        r = NULL;
    }
    if (f)
        fclose(f);
    /* a quote error in the first row is reported by the layout itself */
    f = mem_file("\"x\"y,1\n", 7);
    CHECK(f && tsu_reader_open(&r, f, "q.csv", &o, &e) == TSU_IO_OK);
    if (f && r) {
        CHECK(tsu_reader_layout(r, &e) == TSU_IO_ERR_QUOTE && e.line == 1 && e.column == 4);
        tsu_reader_free(r);
    }
    if (f)
        fclose(f);
    CHECK(tsu_reader_layout(NULL, &e) == TSU_IO_ERR_NULL);
    CHECK(tsu_reader_use_columns(NULL, use, 2, &e) == TSU_IO_ERR_NULL);
    /* empty input */
    f = mem_file("", 0);
    CHECK(f && tsu_reader_open(&r, f, "e.csv", &o, &e) == TSU_IO_OK);
    if (f && r) {
        CHECK(tsu_reader_layout(r, &e) == TSU_IO_ERR_EMPTY);
        tsu_reader_free(r);
    }
    if (f)
        fclose(f);
}

/* Line ends CR LF, LF and a lone CR (old Mac OS) read alike, with the same
 * line numbers, for every buffer size (a CR last in the buffer); UTF-16 text
 * is named as such. */
static void test_reader_line_ends(void)
{
    static const char *const texts[] = {
        "x,y\n# c\n0,1\n\n1,2\n2,1.5\n3,4\n",           /* the reference: LF */
        "x,y\r# c\r0,1\r\r1,2\r2,1.5\r3,4\r",           /* CR */
        "x,y\r# c\r0,1\r\r1,2\r2,1.5\r3,4",             /* CR, none at the end */
        "x,y\r\n# c\r\n0,1\r\n\r\n1,2\r\n2,1.5\r\n3,4\r\n", /* CR LF */
        "x,y\r# c\n0,1\r\n\r1,2\n2,1.5\r3,4\r\n",       /* mixed */
    };
    static const double want[4][2] = {{0, 1}, {1, 2}, {2, 1.5}, {3, 4}};
    static const unsigned long long want_line[4] = {3, 5, 6, 7};
    static const size_t bufs[] = {16, 17, 18, 19, 4096};
    for (size_t k = 0; k < sizeof texts / sizeof *texts; k++)
        for (size_t b = 0; b < sizeof bufs / sizeof *bufs; b++) {
            tsu_read_options o;
            tsu_table t;
            tsu_io_error e;
            tsu_read_options_init(&o);
            o.buffer_size = bufs[b];
            int ok = read_text(texts[k], strlen(texts[k]), &o, &t, &e) == TSU_IO_OK &&
                     t.nrows == 4 && t.ncols == 2 && strcmp(t.names[1], "y") == 0;
            for (size_t i = 0; ok && i < 4; i++)
                ok = t.cols[0][i] == want[i][0] && t.cols[1][i] == want[i][1] &&
                     t.lines[i] == want_line[i];
            CHECKF(ok, "line ends %zu, buffer %zu: %s", k, bufs[b], e.msg);
            tsu_table_free(&t);
        }
    /* line numbers in a message after lone CRs */
    EXPECT_ERR("x,y\r0,1\r\rz,2\r", NULL, TSU_IO_ERR_NUMBER,
               "t.csv:4:1: expected a number, found \"z\"", 4, 1);
    /* UTF-16: with a byte-order mark (LE, BE), or without one (NUL bytes) */
    EXPECT_ERR("\xff\xfex\0,\0y\0\n\0" "0\0,\0" "1\0\n\0", NULL, TSU_IO_ERR_ENCODING,
               "t.csv:1: the file is UTF-16 text (a UTF-16 byte-order mark): convert it to UTF-8 "
               "(for example iconv -f UTF-16 -t UTF-8)", 1, 0);
    EXPECT_ERR("\xfe\xff\0x\0,\0y\0\n\0" "0\0,\0" "1\0\n", NULL, TSU_IO_ERR_ENCODING,
               "t.csv:1: the file is UTF-16 text (a UTF-16 byte-order mark): convert it to UTF-8 "
               "(for example iconv -f UTF-16 -t UTF-8)", 1, 0);
    EXPECT_ERR("\0x\0,\0y\0\r\0\n\0" "0\0,\0" "1\0\r\0\n", NULL, TSU_IO_ERR_ENCODING,
               "t.csv:1: the file is UTF-16 text (NUL bytes in its first line): convert it to "
               "UTF-8 (for example iconv -f UTF-16 -t UTF-8)", 1, 0);
    CHECK(strcmp(tsu_io_strerror(TSU_IO_ERR_ENCODING), "not UTF-8 text") == 0);
}

static void test_reader_stream(void)
{
    long nrows = SCALE(200000), i;
    FILE *f = tmpfile();
    static const size_t bufs[] = {16, 100, 4096, 0};
    double *xv = malloc((size_t)nrows * sizeof *xv), *yv = malloc((size_t)nrows * sizeof *yv);
    unsigned long long *lines = malloc((size_t)nrows * sizeof *lines), line = 0;
    char a[TSU_FMT_SIZE];
    if (!f || !xv || !yv || !lines) {
        CHECK(0);
        return;
    }
    fputs("# generated\nx,y\n", f);
    line = 2;
    for (i = 0; i < nrows; i++) {
        xv[i] = random_double((int)(i % 7));
        yv[i] = random_double((int)((i + 3) % 7));
        if (i % 1000 == 7) {
            fputs("\r\n# comment, with, commas\n", f);
            line += 2;
        }
        if (i % 2) {
            tsu_format_double(xv[i], a);
            fprintf(f, "%s, %.17g\n", a, yv[i]);
        } else {
            fprintf(f, "%.20e,%s\r\n", xv[i], (tsu_format_double(yv[i], a), a));
        }
        lines[i] = ++line;
    }
    for (size_t b = 0; b < sizeof bufs / sizeof *bufs; b++) {
        tsu_read_options o;
        tsu_table t;
        tsu_io_error e;
        tsu_reader *r;
        const double *row;
        long bad = 0, k = 0;
        tsu_read_options_init(&o);
        if (bufs[b])
            o.buffer_size = bufs[b];
        rewind(f);
        CHECK(tsu_read_table(f, "g.csv", &o, &t, &e) == TSU_IO_OK);
        CHECK(t.nrows == (size_t)nrows && t.ncols == 2);
        for (i = 0; i < nrows && t.nrows == (size_t)nrows; i++)
            if (bits_of(t.cols[0][i]) != bits_of(xv[i]) || bits_of(t.cols[1][i]) != bits_of(yv[i]) ||
                t.lines[i] != lines[i])
                bad++;
        CHECKF(bad == 0, "buffer %zu: %ld rows differ", bufs[b], bad);
        rewind(f);
        bad = 0;
        CHECK(tsu_reader_open(&r, f, "g.csv", &o, &e) == TSU_IO_OK);
        while (tsu_reader_next(r, &row, &e) == TSU_IO_OK) {
            if (k >= nrows || bits_of(row[0]) != bits_of(t.cols[0][k]) ||
                bits_of(row[1]) != bits_of(t.cols[1][k]) || tsu_reader_line(r) != t.lines[k])
                bad++;
            k++;
        }
        CHECKF(bad == 0 && k == nrows && e.status == TSU_IO_OK, "streaming, buffer %zu", bufs[b]);
        tsu_reader_free(r);
        tsu_table_free(&t);
    }
    fclose(f);
    free(xv);
    free(yv);
    free(lines);
}

/* ------------------------------------------------------------------ */
/* output                                                               */
/* ------------------------------------------------------------------ */

static int dir_entries(const char *dir, char names[][64], int max)
{
    DIR *d = opendir(dir);
    struct dirent *de;
    int n = 0;
    if (!d)
        return -1;
    while ((de = readdir(d)) != NULL) {
        if (strcmp(de->d_name, ".") == 0 || strcmp(de->d_name, "..") == 0)
            continue;
        if (n < max)
            snprintf(names[n], 64, "%.63s", de->d_name);
        n++;
    }
    closedir(d);
    return n;
}

static int file_is(const char *path, const char *content)
{
    char buf[256];
    size_t n;
    FILE *f = fopen(path, "rb");
    if (!f)
        return 0;
    n = fread(buf, 1, sizeof buf - 1, f);
    fclose(f);
    buf[n] = 0;
    return strcmp(buf, content) == 0;
}

static void test_out(void)
{
    char tmpl[] = "/tmp/ts_io_test.XXXXXX", path[300], sub[300], msg[TSU_IO_MSG_SIZE], names[8][64];
    char *dir = mkdtemp(tmpl);
    tsu_out *o;
    struct stat st;
    mode_t old = umask(022);
    CHECK(dir != NULL);
    if (!dir)
        return;
    snprintf(path, sizeof path, "%s/out.csv", dir);

    /* aborted: nothing left */
    CHECK(tsu_out_open(&o, path, 0, msg, sizeof msg) == 0 && o && msg[0] == 0);
    CHECK(strncmp(tsu_out_temp(o), path, strlen(path)) == 0 &&
          strncmp(tsu_out_temp(o) + strlen(path), ".tmp.", 5) == 0);
    CHECK(strcmp(tsu_out_path(o), path) == 0);
    fputs("half written", tsu_out_file(o));
    CHECK(dir_entries(dir, names, 8) == 1); /* the temp file exists meanwhile */
    tsu_out_abort(o);
    CHECK(dir_entries(dir, names, 8) == 0);

    /* committed: the file, nothing else, mode 0666 & ~umask */
    CHECK(tsu_out_open(&o, path, TSU_OUT_FSYNC, msg, sizeof msg) == 0);
    fputs("a,b\n", tsu_out_file(o));
    CHECK(tsu_out_commit(o, msg, sizeof msg) == 0 && msg[0] == 0);
    CHECK(file_is(path, "a,b\n"));
    CHECK(dir_entries(dir, names, 8) == 1 && strcmp(names[0], "out.csv") == 0);
    CHECK(stat(path, &st) == 0 && (st.st_mode & 0777) == 0644);

    /* replacing keeps the permissions of the old file */
    chmod(path, 0640);
    CHECK(tsu_out_open(&o, path, 0, msg, sizeof msg) == 0);
    fputs("new\n", tsu_out_file(o));
    CHECK(file_is(path, "a,b\n")); /* untouched until commit */
    CHECK(tsu_out_commit(o, msg, sizeof msg) == 0);
    CHECK(file_is(path, "new\n") && stat(path, &st) == 0 && (st.st_mode & 0777) == 0640);
    /* aborting a replacement leaves the old file */
    CHECK(tsu_out_open(&o, path, 0, msg, sizeof msg) == 0);
    fputs("newer\n", tsu_out_file(o));
    tsu_out_abort(o);
    CHECK(file_is(path, "new\n") && dir_entries(dir, names, 8) == 1);

    /* directory missing */
    snprintf(sub, sizeof sub, "%s/nope/x.csv", dir);
    o = (tsu_out *)msg;
    CHECK(tsu_out_open(&o, sub, 0, msg, sizeof msg) == ENOENT && o == NULL);
    {
        char want[400];
        snprintf(want, sizeof want,
                 "cannot create temporary file for \"%s\": No such file or directory", sub);
        CHECKF(strcmp(msg, want) == 0, "%s", msg);
    }

    /* rename fails (target is a non-empty directory): temp removed, error */
    snprintf(sub, sizeof sub, "%s/sub", dir);
    mkdir(sub, 0755);
    {
        char inner[320];
        snprintf(inner, sizeof inner, "%s/keep", sub);
        FILE *f = fopen(inner, "w");
        if (f)
            fclose(f);
        CHECK(tsu_out_open(&o, sub, 0, msg, sizeof msg) == 0);
        fputs("x", tsu_out_file(o));
        {
            int rc = tsu_out_commit(o, msg, sizeof msg);
            char want[400];
            snprintf(want, sizeof want, "cannot replace \"%s\": %s", sub, strerror(rc));
            CHECKF((rc == EISDIR || rc == ENOTEMPTY || rc == EEXIST) && strcmp(msg, want) == 0,
                   "rc %d: %s", rc, msg);
        }
        CHECK(dir_entries(dir, names, 8) == 2); /* out.csv and sub only */
        remove(inner);
        rmdir(sub);
    }

    /* a write error (file size limit -> EFBIG) removes the temp file */
    {
        struct rlimit rl, lim;
        if (getrlimit(RLIMIT_FSIZE, &rl) == 0) {
            void (*oldh)(int) = signal(SIGXFSZ, SIG_IGN);
            snprintf(sub, sizeof sub, "%s/big.csv", dir);
            CHECK(tsu_out_open(&o, sub, 0, msg, sizeof msg) == 0);
            lim = rl;
            lim.rlim_cur = 1000;
            if (setrlimit(RLIMIT_FSIZE, &lim) == 0) {
                int rc;
                for (int i = 0; i < 500; i++)
                    fputs("0123456789\n", tsu_out_file(o));
                rc = tsu_out_commit(o, msg, sizeof msg);
                setrlimit(RLIMIT_FSIZE, &rl);
                CHECKF(rc == EFBIG && strstr(msg, "error writing \"") == msg, "rc %d: %s", rc, msg);
                CHECK(dir_entries(dir, names, 8) == 1);
            } else {
                tsu_out_abort(o);
            }
            signal(SIGXFSZ, oldh);
        }
    }

    /* a relative path (directory ".", fsync'ed) */
    {
        char cwd[1024];
        if (getcwd(cwd, sizeof cwd) && chdir(dir) == 0) {
            CHECK(tsu_out_open(&o, "rel.csv", TSU_OUT_FSYNC, msg, sizeof msg) == 0);
            fputs("r\n", tsu_out_file(o));
            CHECK(tsu_out_commit(o, msg, sizeof msg) == 0 && file_is("rel.csv", "r\n"));
            remove("rel.csv");
            CHECK(chdir(cwd) == 0);
        }
    }

    /* standard output */
    CHECK(tsu_out_open(&o, "-", 0, msg, sizeof msg) == 0 && tsu_out_file(o) == stdout &&
          tsu_out_temp(o) == NULL);
    CHECK(tsu_out_commit(o, msg, sizeof msg) == 0);
    { /* standard output that fails (/dev/full on fd 1 for a moment) */
        int save, full;
        fflush(stdout);
        save = dup(1);
        full = open("/dev/full", O_WRONLY);
        if (save >= 0 && full >= 0 && dup2(full, 1) >= 0) {
            int rc;
            CHECK(tsu_out_open(&o, "-", 0, msg, sizeof msg) == 0);
            fputs("\n", tsu_out_file(o));
            rc = tsu_out_commit(o, msg, sizeof msg);
            dup2(save, 1);
            clearerr(stdout);
            CHECKF(rc == ENOSPC && strcmp(msg, "error writing to standard output: No space left on "
                                               "device") == 0,
                   "rc %d %s", rc, msg);
        }
        if (full >= 0)
            close(full);
        if (save >= 0)
            close(save);
    }
    CHECK(tsu_out_open(&o, "-", 0, NULL, 0) == 0);
    tsu_out_abort(o);

    /* arguments */
    CHECK(tsu_out_open(&o, NULL, 0, msg, sizeof msg) == EINVAL && strcmp(msg, "no output path") == 0);
    CHECK(tsu_out_open(&o, "", 0, msg, sizeof msg) == EINVAL);
    CHECK(tsu_out_open(NULL, path, 0, msg, sizeof msg) == EINVAL);
    CHECK(tsu_out_open(&o, path, 0x100, msg, sizeof msg) == EINVAL && o == NULL);
    CHECK(tsu_out_commit(NULL, msg, sizeof msg) == EINVAL);
    tsu_out_abort(NULL);
    CHECK(tsu_out_file(NULL) == NULL && tsu_out_path(NULL) == NULL);

    remove(path);
    CHECK(dir_entries(dir, names, 8) == 0);
    rmdir(dir);
    umask(old);
}

static void test_writer(void)
{
    FILE *f = tmpfile();
    tsu_writer *w;
    char buf[512];
    size_t n;
    double row[3] = {1.0, -0.1, 3e-300};
    CHECK(tsu_writer_new(NULL, ',') == NULL && tsu_writer_new(f, 'x') == NULL);
    w = tsu_writer_new(f, ',');
    CHECK(w != NULL);
    CHECK(tsu_writer_text(w, "x,y\n", 4) == 0);
    CHECK(tsu_writer_xy(w, 0.5, 100.0) == 0);
    CHECK(tsu_writer_row(w, row, 3) == 0);
    CHECK(tsu_writer_row(w, row, 0) == 0);
    CHECK(tsu_writer_xy(w, -0.0, 1e21) == 0);
    CHECK(tsu_writer_free(w) == 0);
    rewind(f);
    n = fread(buf, 1, sizeof buf - 1, f);
    buf[n] = 0;
    CHECKF(strcmp(buf, "x,y\n0.5,100\n1,-0.1,3e-300\n\n-0,1e+21\n") == 0, "%s", buf);
    fclose(f);

    w = tsu_writer_new(stdout, '\t');
    CHECK(tsu_writer_row(w, NULL, 2) == EINVAL && tsu_writer_xy(w, 1, 2) == EINVAL); /* sticky */
    CHECK(tsu_writer_free(w) == EINVAL);
    CHECK(tsu_writer_row(NULL, row, 1) == EINVAL && tsu_writer_flush(NULL) == EINVAL &&
          tsu_writer_free(NULL) == 0 && tsu_writer_text(NULL, "", 0) == EINVAL);

    /* write errors: /dev/full */
    f = fopen("/dev/full", "w");
    if (f) {
        long i;
        int rc = 0;
        w = tsu_writer_new(f, ',');
        for (i = 0; i < 100000 && rc == 0; i++)
            rc = tsu_writer_xy(w, (double)i, 0.25);
        if (rc == 0)
            rc = tsu_writer_flush(w);
        CHECKF(rc == ENOSPC, "rc %d", rc);
        CHECK(tsu_writer_xy(w, 1, 2) == ENOSPC && tsu_writer_text(w, "a", 1) == ENOSPC);
        CHECK(tsu_writer_row(w, row, 3) == ENOSPC);
        CHECK(tsu_writer_free(w) == ENOSPC);
        fclose(f);
    }
    f = fopen("/dev/full", "w");
    if (f) { /* rows, a small write that fails only at fflush, long text */
        static double many[5000];
        static char txt[100000];
        int rc = 0;
        w = tsu_writer_new(f, ';');
        for (int i = 0; i < 100 && rc == 0; i++)
            rc = tsu_writer_row(w, many, 5000);
        CHECK(rc == ENOSPC && tsu_writer_free(w) == ENOSPC);
        clearerr(f);
        w = tsu_writer_new(f, ' ');
        CHECK(tsu_writer_xy(w, 1, 2) == 0 && tsu_writer_flush(w) == ENOSPC && tsu_writer_free(w) == ENOSPC);
        clearerr(f);
        memset(txt, 'a', sizeof txt);
        w = tsu_writer_new(f, ',');
        CHECK(tsu_writer_text(w, txt, sizeof txt) == ENOSPC && tsu_writer_free(w) == ENOSPC);
        fclose(f);
    }
    w = tsu_writer_new(stdout, ',');
    CHECK(tsu_writer_text(w, NULL, 3) == EINVAL && tsu_writer_free(w) == EINVAL);
    CHECK(tsu_writer_xy(NULL, 1, 2) == EINVAL);

    /* speed: rows of (x, y) into a temporary file; then reading them back */
    {
        long rows = SCALE(1000000), i;
        double t0, tw, tr, ts;
        tsu_table t;
        tsu_io_error e;
        tsu_reader *r;
        const double *rw;
        f = tmpfile();
        w = tsu_writer_new(f, ',');
        t0 = now();
        for (i = 0; i < rows; i++)
            tsu_writer_xy(w, (double)i * 0.001, sin((double)i * 0.001) * 12.5);
        CHECK(tsu_writer_free(w) == 0);
        tw = now() - t0;
        rewind(f);
        t0 = now();
        CHECK(tsu_read_table(f, "w.csv", NULL, &t, &e) == TSU_IO_OK && t.nrows == (size_t)rows);
        tr = now() - t0;
        CHECK(t.nrows == (size_t)rows && t.cols[0][rows - 1] == (double)(rows - 1) * 0.001 &&
              t.cols[1][rows / 2] == sin((double)(rows / 2) * 0.001) * 12.5);
        tsu_table_free(&t);
        rewind(f);
        t0 = now();
        CHECK(tsu_reader_open(&r, f, "w.csv", NULL, &e) == TSU_IO_OK);
        i = 0;
        while (tsu_reader_next(r, &rw, &e) == TSU_IO_OK)
            i++;
        ts = now() - t0;
        CHECK(i == rows);
        tsu_reader_free(r);
        fclose(f);
        printf("speed: writer %.2f M rows/s, read_table %.2f M rows/s, streaming %.2f M rows/s "
               "(%ld rows of x,y)\n",
               (double)rows / tw * 1e-6, (double)rows / tr * 1e-6, (double)rows / ts * 1e-6, rows);
    }
}

/* Every allocation failing in turn: NOMEM (or success once the operation
 * needs fewer allocations), with nothing leaked (LeakSanitizer in the ASan
 * build) and the outputs reset. */
static void test_nomem(void)
{
    static const char text[] = "alpha_long_name,b\n1,2\n3,4\n5,6\n";
    int ok_seen = 0, nomem_seen = 0, bad = 0;
    for (long n = 0; n < 40; n++) {
        tsu_table t;
        tsu_io_error e;
        tsu_read_options o;
        FILE *f = mem_file(text, sizeof text - 1);
        tsu_io_status st;
        tsu_read_options_init(&o);
        o.buffer_size = 16; /* the buffer grows too */
        tsu_io__fail_alloc_after(n);
        st = tsu_read_table(f, "t.csv", &o, &t, &e);
        tsu_io__fail_alloc_after(-1);
        if (st == TSU_IO_OK) {
            ok_seen++;
            if (t.nrows != 3 || t.cols[1][2] != 6)
                bad++;
        } else if (st == TSU_IO_ERR_NOMEM && strcmp(e.msg, "t.csv: out of memory") == 0 &&
                   t.cols == NULL && t.names == NULL) {
            nomem_seen++;
        } else {
            bad++;
            fprintf(stderr, "nomem %ld: status %d %s\n", n, st, e.msg);
        }
        tsu_table_free(&t);
        fclose(f);
    }
    CHECKF(bad == 0 && ok_seen > 0 && nomem_seen >= 10, "bad %d ok %d nomem %d", bad, ok_seen,
           nomem_seen);
    {
        tsu_reader *r;
        tsu_io_error e;
        tsu_out *o;
        char msg[200];
        FILE *f = tmpfile();
        for (long n = 0; n < 3; n++) {
            tsu_io__fail_alloc_after(n);
            CHECK(tsu_reader_open(&r, f, "t", NULL, &e) == TSU_IO_ERR_NOMEM && r == NULL &&
                  strcmp(e.msg, "t: out of memory") == 0);
            tsu_io__fail_alloc_after(-1);
        }
        for (long n = 0; n < 3; n++) {
            tsu_io__fail_alloc_after(n);
            CHECK(tsu_out_open(&o, "/tmp/x.csv", 0, msg, sizeof msg) == ENOMEM && o == NULL &&
                  strcmp(msg, "out of memory") == 0);
            tsu_io__fail_alloc_after(-1);
        }
        tsu_io__fail_alloc_after(0);
        CHECK(tsu_writer_new(f, ',') == NULL);
        tsu_io__fail_alloc_after(-1);
        fclose(f);
    }
}

int main(void)
{
    double t0 = now();
    const char *pre = getenv("LD_PRELOAD");
    scale_div = (pre && strstr(pre, "vgpreload")) ? 40 : SAN ? 4 : 1;
    test_pow10_table();
    test_format_known();
    test_format_python();
    test_format_roundtrip();
    test_format_shortest();
    test_parse_cases();
    test_parse_python();
    test_parse_random();
    test_parse_halfway();
    test_reader_valid();
    test_reader_errors();
    test_reader_realworld();
    test_reader_columns();
    test_time_format();
    test_reader_stream();
    test_reader_line_ends();
    test_out();
    test_writer();
    test_nomem();
    printf("test_io: %.1f s (1/%ld of the random cases)\n", now() - t0, scale_div);
    return th_report("test_io");
}
