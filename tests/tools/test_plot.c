/* Tests of the SVG plot module (tools/support/tsu_plot.c, tsu_plot.h).
 *
 * Usage: test_plot [OUTDIR]   (default: <dir of this program>/plot_out)
 * Writes the SVG files that tests/tools/test_plot_xml.py parses and checks again
 * (structure, pixel mapping, simplification error, legend overlap).
 *
 * Expected ticks are derived by hand in the comments from the rule stated in
 * tsu_plot.h (4 % padding, 1-2-5 steps, 4..8 ticks closest to 6). */
#define _POSIX_C_SOURCE 200809L
#include "th.h"
#include "tsu_plot.h"

#include <ctype.h>
#include <errno.h>
#include <stdint.h>
#include <string.h>
#include <sys/stat.h>

static char outdir[4096];

/* ---------------------------------------------------------------- helpers */

static int label_is(const tsu_plot_ticks *t, size_t i, const char *s)
{
    return i < t->n && strcmp(t->label[i], s) == 0;
}

/* ticks equal to the given labels, exponent and step; values = label*10^exp */
static void check_ticks(const char *what, const tsu_plot_ticks *t, const char *const *labels,
                        size_t n, int exponent, double step)
{
    CHECKF(t->n == n, "%s: %zu ticks, expected %zu", what, t->n, n);
    CHECKF(t->exponent == exponent, "%s: exponent %d, expected %d", what, t->exponent, exponent);
    /* step: 1-2-5 times a power of ten, compared to ~1 ulp */
    CHECKF(fabs(t->step - step) <= 4e-16 * step, "%s: step %.17g", what, t->step);
    for (size_t i = 0; i < n && i < t->n; i++) {
        CHECKF(label_is(t, i, labels[i]), "%s: label %zu is '%s', expected '%s'", what, i,
               t->label[i], labels[i]);
        /* value from the expected label text: strtod + one scaling, so a few ulps */
        double v = strtod(labels[i], NULL) * pow(10.0, t->exponent);
        CHECKF(fabs(t->value[i] - v) <= 1e-12 * step, "%s: value %zu = %.17g, expected %.17g",
               what, i, t->value[i], v);
    }
}

static char *render(const tsu_plot *p)
{
    tsu_plot_buf b = TSU_PLOT_BUF_INIT;
    tsu_plot_status st = tsu_plot_render(p, &b);
    CHECKF(st == TSU_PLOT_OK, "render: %s", tsu_plot_strerror(st));
    if (st) {
        tsu_plot_buf_free(&b);
        return NULL;
    }
    return b.data;
}

static size_t count(const char *s, const char *needle)
{
    size_t n = 0, k = strlen(needle);
    for (const char *q = s; s && (q = strstr(q, needle)) != NULL; q += k)
        n++;
    return n;
}

/* no "nan"/"inf" anywhere (the test labels avoid those letters) */
static int has_nonfinite(const char *s)
{
    for (; s && *s; s++) {
        char a = (char)tolower((unsigned char)s[0]);
        if (a != 'n' && a != 'i')
            continue;
        char b2 = (char)tolower((unsigned char)s[1]);
        char c2 = b2 ? (char)tolower((unsigned char)s[2]) : 0;
        if ((a == 'n' && b2 == 'a' && c2 == 'n') || (a == 'i' && b2 == 'n' && c2 == 'f'))
            return 1;
    }
    return 0;
}

/* number of vertices of the k-th <polyline> (0-based), or 0 */
static size_t polyline_vertices(const char *s, size_t k)
{
    const char *q = s;
    for (size_t i = 0; i <= k; i++) {
        q = strstr(q, "<polyline points=\"");
        if (!q)
            return 0;
        q += 18;
    }
    size_t n = 0;
    for (; *q && *q != '"'; q++)
        n += *q == ',';
    return n;
}

static void save(const tsu_plot *p, const char *name)
{
    char path[4200];
    snprintf(path, sizeof path, "%s/%s", outdir, name);
    tsu_plot_status st = tsu_plot_save(p, path);
    CHECKF(st == TSU_PLOT_OK, "save %s: %s", path, tsu_plot_strerror(st));
    char *svg = render(p);
    CHECKF(svg && !has_nonfinite(svg), "%s contains nan/inf", name);
    free(svg);
}

/* ------------------------------------------------------------ tick tests */

static void test_ticks_hand(void)
{
    tsu_plot_ticks t;
    /* [0, 30] -> padded [-1.2, 31.2]; step 5 gives 0..30 = 7 ticks (|7-6| = 1),
     * step 10 gives 4 (|4-6| = 2), step 2 gives 16: step 5. */
    CHECK(tsu_plot_ticks_compute(0, 30, TSU_PLOT_RANGE_AUTO, &t) == TSU_PLOT_OK);
    {
        static const char *const l[] = {"0", "5", "10", "15", "20", "25", "30"};
        check_ticks("[0,30]", &t, l, 7, 0, 5.0);
        CHECK_CLOSE(t.lo, -1.2, 1e-14); /* 4 % of 30, a few ulps */
        CHECK_CLOSE(t.hi, 31.2, 1e-14);
    }
    /* [1.53, 2.0] -> [1.5112, 2.0188]; step 0.1: 1.6..2.0 = 5 ticks (score 1),
     * 0.05: 10, 0.2: 3. */
    CHECK(tsu_plot_ticks_compute(1.53, 2.0, TSU_PLOT_RANGE_AUTO, &t) == TSU_PLOT_OK);
    {
        static const char *const l[] = {"1.6", "1.7", "1.8", "1.9", "2.0"};
        check_ticks("[1.53,2]", &t, l, 5, 0, 0.1);
    }
    /* [-1e-9, 3e-9] -> [-1.16e-9, 3.16e-9]; step 1e-9: -1..3 = 5 ticks; 5e-10: 9;
     * 2e-9: 2.  Largest |tick| 3e-9 < 1e-3: labels scaled by 10^-9. */
    CHECK(tsu_plot_ticks_compute(-1e-9, 3e-9, TSU_PLOT_RANGE_AUTO, &t) == TSU_PLOT_OK);
    {
        static const char *const l[] = {"-1", "0", "1", "2", "3"};
        check_ticks("[-1e-9,3e-9]", &t, l, 5, -9, 1e-9);
    }
    /* fixed [0, 1]: step 0.2 gives 6 ticks (score 0), 0.1 gives 11, 0.5 gives 3 */
    CHECK(tsu_plot_ticks_compute(0, 1, TSU_PLOT_RANGE_FIXED, &t) == TSU_PLOT_OK);
    {
        static const char *const l[] = {"0.0", "0.2", "0.4", "0.6", "0.8", "1.0"};
        check_ticks("fixed [0,1]", &t, l, 6, 0, 0.2);
        CHECK(t.lo == 0 && t.hi == 1);
    }
    /* fixed [0.1, 0.7]: step 0.1 gives 7 ticks; 0.3 must not print as 0.30000000000000004 */
    CHECK(tsu_plot_ticks_compute(0.1, 0.7, TSU_PLOT_RANGE_FIXED, &t) == TSU_PLOT_OK);
    {
        static const char *const l[] = {"0.1", "0.2", "0.3", "0.4", "0.5", "0.6", "0.7"};
        check_ticks("fixed [0.1,0.7]", &t, l, 7, 0, 0.1);
    }
    /* all equal 5 -> [4.5, 5.5]; step 0.2: 4.6..5.4 = 5 ticks; 0.1: 11; 0.5: 3 */
    CHECK(tsu_plot_ticks_compute(5, 5, TSU_PLOT_RANGE_AUTO, &t) == TSU_PLOT_OK);
    {
        static const char *const l[] = {"4.6", "4.8", "5.0", "5.2", "5.4"};
        check_ticks("[5,5]", &t, l, 5, 0, 0.2);
        CHECK_CLOSE(t.lo, 4.5, 1e-15);
        CHECK_CLOSE(t.hi, 5.5, 1e-15);
    }
    /* all zero -> [-1, 1]; step 0.5: 5 ticks; 0.2: 11; 1: 3 */
    CHECK(tsu_plot_ticks_compute(0, 0, TSU_PLOT_RANGE_AUTO, &t) == TSU_PLOT_OK);
    {
        static const char *const l[] = {"-1.0", "-0.5", "0.0", "0.5", "1.0"};
        check_ticks("[0,0]", &t, l, 5, 0, 0.5);
    }
    /* subnormal, all equal: treated as zero -> [-1, 1] */
    CHECK(tsu_plot_ticks_compute(1e-320, 1e-320, TSU_PLOT_RANGE_AUTO, &t) == TSU_PLOT_OK);
    CHECK(t.n == 5 && t.lo == -1 && t.hi == 1);
    /* [0, 3e12] -> [-1.2e11, 3.12e12]; step 5e11: 0..3e12 = 7 ticks (score 1);
     * 1e12: 4.  Largest 3e12 >= 1e5 and labels need 1 decimal: scaled by 10^12. */
    CHECK(tsu_plot_ticks_compute(0, 3e12, TSU_PLOT_RANGE_AUTO, &t) == TSU_PLOT_OK);
    {
        static const char *const l[] = {"0.0", "0.5", "1.0", "1.5", "2.0", "2.5", "3.0"};
        check_ticks("[0,3e12]", &t, l, 7, 12, 5e11);
    }
    /* [0, 2401] -> [-96.04, 2497.04]; step 500: 0..2000 = 5 ticks (score 1);
     * 200: 13; 1000: 3.  The zero tick is "0", not "000". */
    CHECK(tsu_plot_ticks_compute(0, 2401, TSU_PLOT_RANGE_AUTO, &t) == TSU_PLOT_OK);
    {
        static const char *const l[] = {"0", "500", "1000", "1500", "2000"};
        check_ticks("[0,2401]", &t, l, 5, 0, 500.0);
    }
    /* [-7, -2] -> [-7.2, -1.8]; step 1: 6 ticks (score 0) */
    CHECK(tsu_plot_ticks_compute(-7, -2, TSU_PLOT_RANGE_AUTO, &t) == TSU_PLOT_OK);
    {
        static const char *const l[] = {"-7", "-6", "-5", "-4", "-3", "-2"};
        check_ticks("[-7,-2]", &t, l, 6, 0, 1.0);
    }
    /* [1e6, 1e6+5] -> step 1, 6 ticks; scaled labels would need 6 decimals: plain */
    CHECK(tsu_plot_ticks_compute(1e6, 1e6 + 5, TSU_PLOT_RANGE_AUTO, &t) == TSU_PLOT_OK);
    {
        static const char *const l[] = {"1000000", "1000001", "1000002",
                                        "1000003", "1000004", "1000005"};
        check_ticks("[1e6,1e6+5]", &t, l, 6, 0, 1.0);
    }
    /* [0, 4e-5] -> [-1.6e-6, 4.16e-5]; step 1e-5: 0..4 = 5 ticks; 5e-6: 9 -> x10^-5 */
    CHECK(tsu_plot_ticks_compute(0, 4e-5, TSU_PLOT_RANGE_AUTO, &t) == TSU_PLOT_OK);
    {
        static const char *const l[] = {"0", "1", "2", "3", "4"};
        check_ticks("[0,4e-5]", &t, l, 5, -5, 1e-5);
    }
    /* [0.001, 0.0045] fixed: step 0.0005 -> 8 ticks (score 2), 0.001 -> 4 (score 2):
     * tie goes to the larger step; largest tick 0.004 >= 1e-3: plain labels */
    CHECK(tsu_plot_ticks_compute(0.001, 0.0045, TSU_PLOT_RANGE_FIXED, &t) == TSU_PLOT_OK);
    {
        static const char *const l[] = {"0.001", "0.002", "0.003", "0.004"};
        check_ticks("fixed [0.001,0.0045]", &t, l, 4, 0, 0.001);
    }
    /* huge magnitudes at the limit */
    CHECK(tsu_plot_ticks_compute(-1e300, 1e300, TSU_PLOT_RANGE_AUTO, &t) == TSU_PLOT_OK);
    CHECK(t.n >= 3 && t.exponent == 300 && isfinite(t.lo) && isfinite(t.hi));

    /* errors */
    CHECK(tsu_plot_ticks_compute(0, 1, TSU_PLOT_RANGE_AUTO, NULL) == TSU_PLOT_ERR_NULL);
    CHECK(tsu_plot_ticks_compute((double)NAN, 1, TSU_PLOT_RANGE_AUTO, &t) == TSU_PLOT_ERR_ARG);
    CHECK(tsu_plot_ticks_compute(0, (double)INFINITY, TSU_PLOT_RANGE_AUTO, &t) == TSU_PLOT_ERR_ARG);
    CHECK(tsu_plot_ticks_compute(0, 2e300, TSU_PLOT_RANGE_AUTO, &t) == TSU_PLOT_ERR_ARG);
    CHECK(tsu_plot_ticks_compute(2, 1, TSU_PLOT_RANGE_AUTO, &t) == TSU_PLOT_ERR_ARG);
    CHECK(tsu_plot_ticks_compute(1, 1, TSU_PLOT_RANGE_FIXED, &t) == TSU_PLOT_ERR_ARG);
    CHECK(tsu_plot_ticks_compute(1, 1 + 1e-13, TSU_PLOT_RANGE_FIXED, &t) == TSU_PLOT_ERR_ARG);
    CHECK(tsu_plot_ticks_compute(0, 1, (tsu_plot_range_mode)7, &t) == TSU_PLOT_ERR_ARG);
}

/* Properties over many ranges: checked against the labels' own text. */
static void test_ticks_sweep(void)
{
    unsigned long long s = 12345;
    long bad = 0, cases = 0;
    for (int i = 0; i < 20000; i++) {
        s = s * 6364136223846793005ULL + 1442695040888963407ULL;
        double u1 = (double)(s >> 11) / 9007199254740992.0;
        s = s * 6364136223846793005ULL + 1442695040888963407ULL;
        double u2 = (double)(s >> 11) / 9007199254740992.0;
        double mag = pow(10.0, -30 + 60 * u1);
        double lo = (u2 - 0.5) * 2 * mag * ((i % 3) ? 1.0 : 50.0);
        double hi = lo + mag * (0.001 + 10 * u1 * u2);
        tsu_plot_range_mode mode = (i & 1) ? TSU_PLOT_RANGE_AUTO : TSU_PLOT_RANGE_FIXED;
        tsu_plot_ticks t;
        if (tsu_plot_ticks_compute(lo, hi, mode, &t) != TSU_PLOT_OK)
            continue; /* a fixed range too narrow for its magnitude */
        cases++;
        int ok = t.n >= 3 && t.n <= 9 && t.lo <= t.hi;
        if (mode == TSU_PLOT_RANGE_AUTO)
            ok = ok && t.lo <= lo && hi <= t.hi;
        else
            ok = ok && t.lo == lo && t.hi == hi;
        double m = t.step / pow(10.0, floor(log10(t.step) + 1e-9));
        ok = ok && (fabs(m - 1) < 1e-9 || fabs(m - 2) < 1e-9 || fabs(m - 5) < 1e-9);
        for (size_t k = 0; k < t.n && ok; k++) {
            double v = strtod(t.label[k], NULL) * pow(10.0, t.exponent);
            ok = ok && strlen(t.label[k]) < 24 && t.value[k] >= t.lo && t.value[k] <= t.hi;
            /* canonical number: no leading zeros ("000", "-05"), no "-0" */
            const char *d = t.label[k] + (t.label[k][0] == '-');
            ok = ok && !(d[0] == '0' && isdigit((unsigned char)d[1]));
            ok = ok && !(t.label[k][0] == '-' && strspn(d, "0.") == strlen(d));
            ok = ok && fabs(v - t.value[k]) <= 1e-9 * t.step; /* label denotes the value */
            if (k) {
                ok = ok && fabs(t.value[k] - t.value[k - 1] - t.step) <= 1e-6 * t.step;
                ok = ok && strcmp(t.label[k], t.label[k - 1]) != 0;
            }
        }
        if (!ok && bad++ < 5)
            fprintf(stderr, "sweep: lo=%.17g hi=%.17g mode=%d n=%zu\n", lo, hi, (int)mode, t.n);
    }
    CHECKF(bad == 0, "%ld of %ld tick sets violate the rules", bad, cases);
    CHECK(cases > 15000);
}

/* ------------------------------------------------------ string buffer */

static void test_buf(void)
{
    tsu_plot_buf b = TSU_PLOT_BUF_INIT;
    CHECK(tsu_plot_buf_xml(&b, "a&b<c>\"'d") == TSU_PLOT_OK);
    CHECK(b.data && strcmp(b.data, "a&amp;b&lt;c&gt;&quot;&#39;d") == 0);
    tsu_plot_buf_free(&b);
    CHECK(b.data == NULL && b.len == 0);
    /* UTF-8: beta, emoji; invalid byte, overlong, surrogate, truncated, control */
    CHECK(tsu_plot_buf_xml(&b, "\xce\xb2\xf0\x9f\x98\x80|\xff|\xc0\xaf|\xed\xa0\x80|\x01\n|"
                              "\xe0\x80\xaf|\xf4\x90\x80\x80|\xef\xbf\xbe|\xe2\x82") == TSU_PLOT_OK);
    /* each byte of an invalid sequence becomes one U+FFFD: bad lead, overlong
     * 2- and 3-byte '/', surrogate D800, > U+10FFFF, U+FFFE, truncated */
    CHECKF(b.data && strcmp(b.data, "&#x3B2;&#x1F600;|&#xFFFD;|&#xFFFD;&#xFFFD;|"
                                    "&#xFFFD;&#xFFFD;&#xFFFD;|  |&#xFFFD;&#xFFFD;&#xFFFD;|"
                                    "&#xFFFD;&#xFFFD;&#xFFFD;&#xFFFD;|&#xFFFD;&#xFFFD;&#xFFFD;|"
                                    "&#xFFFD;&#xFFFD;") == 0,
           "got %s", b.data ? b.data : "(null)");
    tsu_plot_buf_free(&b);
    CHECK(tsu_plot_buf_printf(&b, "%d-%s", 42, "x") == TSU_PLOT_OK && strcmp(b.data, "42-x") == 0);
    CHECK(tsu_plot_buf_puts(&b, "yz") == TSU_PLOT_OK && b.len == 6 && strcmp(b.data, "42-xyz") == 0);
    /* growth over many appends */
    for (int i = 0; i < 10000; i++)
        tsu_plot_buf_append(&b, "0123456789", 10);
    CHECK(b.len == 6 + 100000 && b.data[b.len] == '\0' && b.len < b.cap);
    /* errors leave the buffer as it was */
    size_t len = b.len;
    CHECK(tsu_plot_buf_append(&b, "x", SIZE_MAX) == TSU_PLOT_ERR_OVERFLOW && b.len == len);
    CHECK(tsu_plot_buf_append(NULL, "x", 1) == TSU_PLOT_ERR_NULL);
    CHECK(tsu_plot_buf_append(&b, NULL, 1) == TSU_PLOT_ERR_NULL);
    CHECK(tsu_plot_buf_append(&b, NULL, 0) == TSU_PLOT_OK && b.len == len);
    CHECK(tsu_plot_buf_puts(&b, NULL) == TSU_PLOT_ERR_NULL);
    CHECK(tsu_plot_buf_xml(&b, NULL) == TSU_PLOT_ERR_NULL);
    CHECK(tsu_plot_buf_printf(NULL, "x") == TSU_PLOT_ERR_NULL);
    tsu_plot_buf_free(&b);
    /* an escape that runs out of memory half-way leaves the buffer as it was */
    CHECK(tsu_plot_buf_puts(&b, "ab") == TSU_PLOT_OK);
    char big[600];
    memset(big, '&', sizeof big - 1);
    big[sizeof big - 1] = '\0';
    tsu_plot_test_fail_alloc_after(0);
    CHECK(tsu_plot_buf_xml(&b, big) == TSU_PLOT_ERR_NOMEM);
    CHECK(tsu_plot_buf_printf(&b, "%s", big) == TSU_PLOT_ERR_NOMEM);
    tsu_plot_test_fail_alloc_after(-1);
    CHECK(b.len == 2 && strcmp(b.data, "ab") == 0);
    tsu_plot_buf_free(&b);
    tsu_plot_buf_free(NULL);
    tsu_plot_buf_init(NULL);
    /* strings for every status, and for an unknown one */
    for (int i = 0; i <= 6; i++) {
        const char *m = tsu_plot_strerror((tsu_plot_status)i);
        CHECK(m && *m);
    }
    CHECK(strcmp(tsu_plot_strerror(TSU_PLOT_OK), tsu_plot_strerror((tsu_plot_status)99)) != 0);
    CHECK(strcmp(tsu_plot_palette(0), "#0072B2") == 0 && strcmp(tsu_plot_palette(8), "#0072B2") == 0);
}

/* ----------------------------------------------------- argument errors */

static void test_errors(void)
{
    tsu_plot *p = (tsu_plot *)1;
    CHECK(tsu_plot_new(0, 0, NULL) == TSU_PLOT_ERR_NULL);
    CHECK(tsu_plot_new(100, 400, &p) == TSU_PLOT_ERR_ARG && p == NULL);
    CHECK(tsu_plot_new(400, 20000, &p) == TSU_PLOT_ERR_ARG && p == NULL);
    CHECK(tsu_plot_new(0, 0, &p) == TSU_PLOT_OK && p);
    if (!p)
        return;
    char *svg = render(p);
    CHECK(svg && strstr(svg, "width=\"720\" height=\"450\"")); /* defaults */
    free(svg);

    CHECK(tsu_plot_set_title(NULL, "x") == TSU_PLOT_ERR_NULL);
    CHECK(tsu_plot_set_labels(NULL, "x", "y") == TSU_PLOT_ERR_NULL);
    CHECK(tsu_plot_set_xrange(NULL, 0, 1) == TSU_PLOT_ERR_NULL);
    CHECK(tsu_plot_set_xrange(p, 1, 1) == TSU_PLOT_ERR_ARG);
    CHECK(tsu_plot_set_xrange(p, 2, 1) == TSU_PLOT_ERR_ARG);
    CHECK(tsu_plot_set_xrange(p, (double)NAN, 1) == TSU_PLOT_ERR_ARG);
    CHECK(tsu_plot_set_yrange(p, 0, (double)INFINITY) == TSU_PLOT_ERR_ARG);
    CHECK(tsu_plot_set_yrange(p, 1, 1 + 1e-13) == TSU_PLOT_ERR_ARG);
    CHECK(tsu_plot_set_yrange(p, 0, 1) == TSU_PLOT_OK);
    CHECK(tsu_plot_set_yrange(p, (double)NAN, (double)NAN) == TSU_PLOT_OK);
    CHECK(tsu_plot_set_equal_aspect(NULL, 1) == TSU_PLOT_ERR_NULL);
    CHECK(tsu_plot_set_legend(p, (tsu_plot_legend)99) == TSU_PLOT_ERR_ARG);
    CHECK(tsu_plot_set_legend(p, (tsu_plot_legend)-1) == TSU_PLOT_ERR_ARG);
    CHECK(tsu_plot_set_legend(NULL, TSU_PLOT_LEGEND_NONE) == TSU_PLOT_ERR_NULL);
    CHECK(tsu_plot_set_xml_declaration(NULL, 0) == TSU_PLOT_ERR_NULL);
    CHECK(tsu_plot_set_grid(NULL, 0) == TSU_PLOT_ERR_NULL);
    CHECK(tsu_plot_set_simplify(p, -1) == TSU_PLOT_ERR_ARG);
    CHECK(tsu_plot_set_simplify(p, (double)NAN) == TSU_PLOT_ERR_ARG);
    CHECK(tsu_plot_set_simplify(p, 11) == TSU_PLOT_ERR_ARG);
    CHECK(tsu_plot_set_simplify(NULL, 1) == TSU_PLOT_ERR_NULL);

    double x[2] = {0, 1}, y[2] = {0, 1};
    CHECK(tsu_plot_add_points(NULL, x, y, 2, NULL, NULL) == TSU_PLOT_ERR_NULL);
    CHECK(tsu_plot_add_points(p, NULL, y, 2, NULL, NULL) == TSU_PLOT_ERR_NULL);
    CHECK(tsu_plot_add_polyline(p, x, NULL, 2, NULL, NULL) == TSU_PLOT_ERR_NULL);
    CHECK(tsu_plot_add_polyline(p, NULL, NULL, 0, "empty", NULL) == TSU_PLOT_OK);
    CHECK(tsu_plot_add_points(p, x, y, SIZE_MAX / 8, NULL, NULL) == TSU_PLOT_ERR_OVERFLOW);
    tsu_plot_style st = {0};
    static const char *const bad_colors[] = {"red;", "#12", "#GGGGGG", "#1234567", "url(#a)",
                                             "averyveryverylongcolorname", "r d"};
    for (size_t i = 0; i < sizeof bad_colors / sizeof *bad_colors; i++) {
        st.color = bad_colors[i];
        CHECKF(tsu_plot_add_points(p, x, y, 2, NULL, &st) == TSU_PLOT_ERR_ARG, "%s", bad_colors[i]);
    }
    st.color = "#abc";
    CHECK(tsu_plot_add_points(p, x, y, 2, NULL, &st) == TSU_PLOT_OK);
    st.color = "DarkRed";
    CHECK(tsu_plot_add_points(p, x, y, 2, NULL, &st) == TSU_PLOT_OK);
    st.color = NULL;
    st.width = (double)NAN;
    CHECK(tsu_plot_add_polyline(p, x, y, 2, NULL, &st) == TSU_PLOT_ERR_ARG);
    st.width = 51;
    CHECK(tsu_plot_add_polyline(p, x, y, 2, NULL, &st) == TSU_PLOT_ERR_ARG);
    st.width = 0;
    st.marker_radius = -1;
    CHECK(tsu_plot_add_points(p, x, y, 2, NULL, &st) == TSU_PLOT_ERR_ARG);
    st.marker_radius = 0;
    st.dash = 3;
    CHECK(tsu_plot_add_polyline(p, x, y, 2, NULL, &st) == TSU_PLOT_ERR_ARG);
    st.dash = 0;
    st.fill_opacity = 1.5;
    CHECK(tsu_plot_add_floor(p, 0, NULL, &st) == TSU_PLOT_ERR_ARG);
    CHECK(tsu_plot_add_line(p, (double)NAN, 0, NULL, NULL) == TSU_PLOT_ERR_ARG);
    CHECK(tsu_plot_add_line(p, 0, (double)INFINITY, NULL, NULL) == TSU_PLOT_ERR_ARG);
    CHECK(tsu_plot_add_line(NULL, 0, 0, NULL, NULL) == TSU_PLOT_ERR_NULL);
    CHECK(tsu_plot_add_region(p, (tsu_plot_side)7, 0, 0, NULL, NULL) == TSU_PLOT_ERR_ARG);
    CHECK(tsu_plot_add_region(p, TSU_PLOT_FORBID_ABOVE, (double)NAN, 0, NULL, NULL) == TSU_PLOT_ERR_ARG);
    CHECK(tsu_plot_add_region(NULL, TSU_PLOT_FORBID_ABOVE, 0, 0, NULL, NULL) == TSU_PLOT_ERR_NULL);
    CHECK(tsu_plot_add_ceiling(p, (double)NAN, NULL, NULL) == TSU_PLOT_ERR_ARG);

    /* the two valid point series (#abc, DarkRed) and the empty polyline */
    svg = render(p);
    CHECK(svg && count(svg, "<g class=\"series points\"") == 2);
    CHECK(svg && count(svg, "<g class=\"series polyline\"") == 1);
    CHECK(svg && strstr(svg, "fill=\"#abc\"") && strstr(svg, "fill=\"DarkRed\""));
    free(svg);

    tsu_plot_ticks t;
    CHECK(tsu_plot_get_ticks(p, 2, &t) == TSU_PLOT_ERR_ARG);
    CHECK(tsu_plot_get_ticks(NULL, 0, &t) == TSU_PLOT_ERR_NULL);
    CHECK(tsu_plot_get_ticks(p, 0, NULL) == TSU_PLOT_ERR_NULL);
    tsu_plot_buf b = TSU_PLOT_BUF_INIT;
    CHECK(tsu_plot_render(NULL, &b) == TSU_PLOT_ERR_NULL);
    CHECK(tsu_plot_render(p, NULL) == TSU_PLOT_ERR_NULL);
    CHECK(tsu_plot_write(p, NULL) == TSU_PLOT_ERR_NULL);
    CHECK(tsu_plot_write(NULL, stdout) == TSU_PLOT_ERR_NULL);
    CHECK(tsu_plot_save(p, NULL) == TSU_PLOT_ERR_NULL);
    CHECK(tsu_plot_save(p, "/nonexistent-dir-ts-plot/x.svg") == TSU_PLOT_ERR_IO);
    FILE *full = fopen("/dev/full", "w");
    if (full) { /* every write fails there (Linux) */
        CHECK(tsu_plot_write(p, full) == TSU_PLOT_ERR_IO);
        fclose(full);
    }
    FILE *ro = fopen("/dev/null", "r");
    if (ro) { /* a stream not open for writing */
        CHECK(tsu_plot_write(p, ro) == TSU_PLOT_ERR_IO);
        fclose(ro);
    }
    /* render appends */
    CHECK(tsu_plot_buf_puts(&b, "<!--x-->") == TSU_PLOT_OK);
    CHECK(tsu_plot_render(p, &b) == TSU_PLOT_OK && strncmp(b.data, "<!--x--><?xml", 13) == 0);
    tsu_plot_buf_free(&b);
    tsu_plot_free(p);
    tsu_plot_free(NULL);
}

/* ------------------------------------------------- out-of-memory paths */

/* Build and render a plot with allocation number k failing; every failing
 * call must report TSU_PLOT_ERR_NOMEM and leave things consistent (ASan
 * checks leaks).  Returns 1 once nothing failed. */
static int oom_round(long k, long *nomem_seen)
{
    double x[3] = {0, 1, 2}, y[3] = {1, 3, 2};
    tsu_plot *p = NULL;
    tsu_plot_buf b = TSU_PLOT_BUF_INIT;
    int added = 0, all_ok = 1;
    tsu_plot_test_fail_alloc_after(k);
    tsu_plot_status st = tsu_plot_new(0, 0, &p);
    if (st) {
        tsu_plot_test_fail_alloc_after(-1);
        CHECK(st == TSU_PLOT_ERR_NOMEM && p == NULL);
        (*nomem_seen)++;
        return 0;
    }
    tsu_plot_status r[12];
    size_t nr = 0;
    r[nr++] = tsu_plot_set_title(p, "title");
    r[nr++] = tsu_plot_set_labels(p, "x", "y");
    for (int i = 0; i < 9; i++) { /* the 9th add grows the series array */
        st = tsu_plot_add_polyline(p, x, y, 3, i % 2 ? "curve" : NULL, NULL);
        r[nr++] = st;
        if (st == TSU_PLOT_OK)
            added++;
    }
    r[11] = tsu_plot_render(p, &b);
    for (size_t i = 0; i < 12; i++) {
        if (r[i] != TSU_PLOT_OK) {
            all_ok = 0;
            CHECKF(r[i] == TSU_PLOT_ERR_NOMEM, "call %zu gave %d", i, (int)r[i]);
            (*nomem_seen)++;
        }
    }
    if (r[11] != TSU_PLOT_OK)
        CHECK(b.len == 0);
    tsu_plot_test_fail_alloc_after(-1);
    /* the plot still holds exactly the series whose add succeeded */
    tsu_plot_buf_free(&b);
    CHECK(tsu_plot_render(p, &b) == TSU_PLOT_OK);
    CHECKF(count(b.data, "<g class=\"series polyline\"") == (size_t)added, "k=%ld added=%d", k, added);
    tsu_plot_buf_free(&b);
    tsu_plot_free(p);
    return all_ok;
}

static void test_oom(void)
{
    long seen = 0, k;
    for (k = 0; k < 200; k++)
        if (oom_round(k, &seen))
            break;
    CHECKF(k > 5 && k < 200, "k = %ld", k);
    CHECK(seen >= k);
}

/* -------------------------------------------------------- simplification */

static void test_simplify(void)
{
    enum { N = 1000 };
    static double x[N], y[N];
    tsu_plot *p = NULL;
    CHECK(tsu_plot_new(0, 0, &p) == TSU_PLOT_OK);
    if (!p)
        return;
    tsu_plot_set_legend(p, TSU_PLOT_LEGEND_NONE);
    /* collinear points: only the two ends remain */
    for (int i = 0; i < N; i++)
        x[i] = i, y[i] = 0.5 * i;
    tsu_plot_add_polyline(p, x, y, N, NULL, NULL);
    char *svg = render(p);
    CHECKF(polyline_vertices(svg, 0) == 2, "%zu", polyline_vertices(svg, 0));
    free(svg);
    /* tolerance 0: every vertex that differs after rounding to 0.01 px; the
     * plot is ~650 px wide, so N points 0.65 px apart all differ */
    tsu_plot_set_simplify(p, 0);
    svg = render(p);
    CHECKF(polyline_vertices(svg, 0) == N, "%zu", polyline_vertices(svg, 0));
    free(svg);
    tsu_plot_free(p);

    /* going back along itself: the turning points stay.  0..10 then back to 5:
     * (0), (10), (5); and out and back to the start: (0), (10), (0) */
    CHECK(tsu_plot_new(0, 0, &p) == TSU_PLOT_OK);
    if (!p)
        return;
    for (int i = 0; i <= 10; i++)
        x[i] = i, y[i] = 1;
    for (int i = 11; i <= 15; i++)
        x[i] = 20 - i, y[i] = 1;
    tsu_plot_add_polyline(p, x, y, 16, NULL, NULL);
    double bx[3] = {0, 10, 0}, by[3] = {2, 2, 2};
    tsu_plot_add_polyline(p, bx, by, 3, NULL, NULL);
    svg = render(p);
    CHECKF(polyline_vertices(svg, 0) == 3, "%zu", polyline_vertices(svg, 0));
    CHECKF(polyline_vertices(svg, 1) == 3, "%zu", polyline_vertices(svg, 1));
    free(svg);
    tsu_plot_free(p);

    /* zig-zag of +-1 data unit over a ~400 px tall range of 40 units: ~10 px
     * deviations, every vertex must stay */
    CHECK(tsu_plot_new(0, 0, &p) == TSU_PLOT_OK);
    if (!p)
        return;
    for (int i = 0; i < 50; i++)
        x[i] = i, y[i] = (i % 2) ? 20.0 : -20.0;
    tsu_plot_add_polyline(p, x, y, 50, NULL, NULL);
    svg = render(p);
    CHECKF(polyline_vertices(svg, 0) == 50, "%zu", polyline_vertices(svg, 0));
    free(svg);
    tsu_plot_free(p);
}

/* ---------------------------------------------------------- the figures */

/* Table 1 of the paper with a smooth stand-in curve, its control polygon,
 * a floor, a ceiling and a constraint line. */
static void fig_full(void)
{
    static const double tx[9] = {0, 2, 3, 5, 15, 25, 27, 28, 30};
    static const double tf[9] = {2, 1.58, 1.55, 1.54, 1.8, 1.54, 1.55, 1.58, 2};
    enum { M = 601 };
    static double cx[M], cy[M];
    for (int i = 0; i < M; i++) {
        cx[i] = 30.0 * i / (M - 1);
        cy[i] = 1.77 + 0.23 * cos(cx[i] * 3.141592653589793 / 15.0);
    }
    tsu_plot *p = NULL;
    CHECK(tsu_plot_new(0, 0, &p) == TSU_PLOT_OK);
    if (!p)
        return;
    tsu_plot_set_title(p, "Table 1: positive data");
    tsu_plot_set_labels(p, "x", "f(x)");
    tsu_plot_style red = {0};
    red.color = "#D55E00";
    CHECK(tsu_plot_add_floor(p, 0.0, "forbidden: f < 0", &red) == TSU_PLOT_OK);
    CHECK(tsu_plot_add_ceiling(p, 2.2, "ceiling 2.2", NULL) == TSU_PLOT_OK);
    CHECK(tsu_plot_add_line(p, 0.01, 1.2, "y = 0.01x + 1.2", NULL) == TSU_PLOT_OK);
    CHECK(tsu_plot_add_polygon(p, tx, tf, 9, "control polygon", NULL) == TSU_PLOT_OK);
    CHECK(tsu_plot_add_polyline(p, cx, cy, M, "spline", NULL) == TSU_PLOT_OK);
    CHECK(tsu_plot_add_points(p, tx, tf, 9, "data", NULL) == TSU_PLOT_OK);
    /* y range: data [1.54, 2], floor 0, ceiling 2.2, line 1.2..1.5 -> [0, 2.2],
     * padded [-0.088, 2.288]: step 0.5 -> 0..2.0 = 5 ticks; 0.2 -> 12; 1 -> 3 */
    tsu_plot_ticks t;
    CHECK(tsu_plot_get_ticks(p, 1, &t) == TSU_PLOT_OK);
    {
        static const char *const l[] = {"0.0", "0.5", "1.0", "1.5", "2.0"};
        check_ticks("fig_full y", &t, l, 5, 0, 0.5);
    }
    CHECK(tsu_plot_get_ticks(p, 0, &t) == TSU_PLOT_OK);
    {
        static const char *const l[] = {"0", "5", "10", "15", "20", "25", "30"};
        check_ticks("fig_full x", &t, l, 7, 0, 5.0);
    }
    char *svg = render(p);
    if (svg) {
        CHECK(count(svg, "<polygon ") == 2);               /* floor and ceiling shading */
        CHECK(count(svg, "<g class=\"series points\"") == 1);
        CHECK(count(svg, "<polyline ") == 2);              /* control polygon, curve */
        CHECK(count(svg, "stroke-dasharray=\"6,4\"") == 2); /* polygon and its legend swatch */
        CHECK(count(svg, "<circle ") == 9 + 9 + 2);        /* markers, vertices, 2 legend swatches */
        CHECK(strstr(svg, "<title>Table 1: positive data</title>") != NULL);
        CHECK(strstr(svg, "&#8722;") == NULL);             /* no negative tick */
        /* default colours skip the explicit #D55E00: blue, green, purple, orange, sky */
        CHECK(count(svg, "#D55E00") == 2 + 2);             /* floor: shading, line; legend */
        CHECK(strstr(svg, "<g class=\"series line\" fill=\"none\" stroke=\"#009E73\""));
        /* draw order: regions, then lines/polylines, then points */
        const char *rg = strstr(svg, "series region"), *pl = strstr(svg, "series polyline");
        const char *pt = strstr(svg, "series points");
        CHECK(rg && pl && pt && rg < pl && pl < pt);
    }
    free(svg);
    save(p, "plot_full.svg");
    tsu_plot_free(p);
}

static void fig_degenerate(void)
{
    double x[4] = {1, 2, 3, 4}, y[4] = {5, 5, 5, 5};
    tsu_plot *p = NULL;
    CHECK(tsu_plot_new(600, 400, &p) == TSU_PLOT_OK);
    if (!p)
        return;
    tsu_plot_set_title(p, "constant data");
    tsu_plot_add_polyline(p, x, y, 4, "line", NULL);
    tsu_plot_add_points(p, x, y, 4, "points", NULL);
    tsu_plot_ticks t;
    CHECK(tsu_plot_get_ticks(p, 1, &t) == TSU_PLOT_OK);
    {
        static const char *const l[] = {"4.6", "4.8", "5.0", "5.2", "5.4"};
        check_ticks("degenerate y", &t, l, 5, 0, 0.2);
    }
    save(p, "plot_degenerate.svg");
    tsu_plot_free(p);

    /* a single point, and nothing at all */
    CHECK(tsu_plot_new(0, 0, &p) == TSU_PLOT_OK);
    if (!p)
        return;
    tsu_plot_add_points(p, x, y, 1, NULL, NULL);
    CHECK(tsu_plot_get_ticks(p, 0, &t) == TSU_PLOT_OK && t.n == 5 && t.lo == 0.9 && t.hi == 1.1);
    save(p, "plot_single.svg");
    tsu_plot_free(p);
    CHECK(tsu_plot_new(0, 0, &p) == TSU_PLOT_OK);
    if (!p)
        return;
    tsu_plot_set_title(p, "empty");
    /* no data: [0, 1] padded to [-0.04, 1.04]; step 0.2 -> 6 ticks */
    CHECK(tsu_plot_get_ticks(p, 0, &t) == TSU_PLOT_OK && t.n == 6 && label_is(&t, 5, "1.0"));
    save(p, "plot_empty.svg");
    tsu_plot_free(p);
}

static void fig_nan(void)
{
    double x[12] = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11};
    double y[12] = {1, 2, (double)NAN, 3, 4, 2, (double)INFINITY, 1, 2, -(double)INFINITY, 5, 1e305};
    /* runs: {0,1}, {3,4,5}, {7,8}, {10} alone (no segment), 1e305 skipped */
    tsu_plot *p = NULL;
    CHECK(tsu_plot_new(0, 0, &p) == TSU_PLOT_OK);
    if (!p)
        return;
    tsu_plot_set_title(p, "gaps in the data");
    tsu_plot_add_polyline(p, x, y, 12, "curve with gaps", NULL);
    tsu_plot_add_points(p, x, y, 12, "finite points", NULL);
    tsu_plot_ticks t;
    /* y from the finite values only: [1, 5] -> [0.84, 5.16]; step 1: 1..5 = 5 ticks */
    CHECK(tsu_plot_get_ticks(p, 1, &t) == TSU_PLOT_OK && t.n == 5 && label_is(&t, 0, "1") &&
          label_is(&t, 4, "5"));
    char *svg = render(p);
    CHECK(svg && count(svg, "<polyline ") == 3);
    CHECK(svg && count(svg, "<circle ") == 8 + 1); /* 8 finite points + legend */
    free(svg);
    save(p, "plot_nan.svg");
    tsu_plot_free(p);
}

static void fig_huge(void)
{
    enum { N = 200 };
    static double x[N], y[N];
    for (int i = 0; i < N; i++) {
        x[i] = 3e12 * i / (N - 1);
        y[i] = -1e-9 + 4e-9 * (double)(i * i) / ((N - 1) * (N - 1));
    }
    tsu_plot *p = NULL;
    CHECK(tsu_plot_new(0, 0, &p) == TSU_PLOT_OK);
    if (!p)
        return;
    tsu_plot_set_title(p, "huge x, tiny y");
    tsu_plot_set_labels(p, "x", "y");
    tsu_plot_add_polyline(p, x, y, N, "y(x)", NULL);
    tsu_plot_ticks t;
    CHECK(tsu_plot_get_ticks(p, 0, &t) == TSU_PLOT_OK && t.exponent == 12);
    CHECK(tsu_plot_get_ticks(p, 1, &t) == TSU_PLOT_OK && t.exponent == -9);
    char *svg = render(p);
    CHECK(svg && strstr(svg, "class=\"xexp\"") && strstr(svg, "class=\"yexp\""));
    CHECK(svg && strstr(svg, ">&#8722;9</tspan>")); /* the y factor x10^-9 */
    CHECK(svg && strstr(svg, ">&#8722;1</text>"));  /* tick label -1 */
    free(svg);
    save(p, "plot_huge.svg");
    tsu_plot_free(p);

    /* extreme magnitudes: plotted or skipped, never nan/inf in the output */
    double ex[5] = {-1e300, -1e-300, 0, 1e-300, 1e300}, ey[5] = {1e300, -1e300, 5e-324, 1, -1};
    CHECK(tsu_plot_new(0, 0, &p) == TSU_PLOT_OK);
    if (!p)
        return;
    tsu_plot_add_polyline(p, ex, ey, 5, NULL, NULL);
    tsu_plot_add_points(p, ex, ey, 5, NULL, NULL);
    tsu_plot_add_line(p, 1e300, 1e300, NULL, NULL);
    tsu_plot_add_floor(p, -1e300, NULL, NULL);
    save(p, "plot_extreme.svg");
    tsu_plot_free(p);
}

static void fig_special(void)
{
    double x[3] = {0, 1, 2}, y[3] = {1, 0.5, 2};
    tsu_plot *p = NULL;
    CHECK(tsu_plot_new(0, 0, &p) == TSU_PLOT_OK);
    if (!p)
        return;
    /* & < > " ' , UTF-8 beta and em dash, an invalid byte, a control char */
    tsu_plot_set_title(p, "A & B <tag> \"q\" 'a' \xce\xb2 \xe2\x80\x94 \xff\x01");
    tsu_plot_set_labels(p, "x < 1 & y > 0", "\xce\xb1 + \xce\xb2");
    tsu_plot_add_polyline(p, x, y, 3, "</text><script>alert(1)</script>", NULL);
    tsu_plot_add_points(p, x, y, 3, "p & q", NULL);
    char *svg = render(p);
    CHECK(svg && strstr(svg, "<title>A &amp; B &lt;tag&gt; &quot;q&quot; &#39;a&#39; &#x3B2; "
                             "&#x2014; &#xFFFD; </title>"));
    CHECK(svg && !strstr(svg, "<script>"));
    CHECK(svg && strstr(svg, "&lt;/text&gt;&lt;script&gt;"));
    int ascii = 1;
    for (const char *c = svg; c && *c; c++)
        ascii &= (unsigned char)*c < 0x80;
    CHECK(ascii);
    free(svg);
    save(p, "plot_special.svg");
    tsu_plot_free(p);
}

static void fig_bigcurve(void)
{
    enum { N = 20000 };
    static double x[N], y[N];
    for (int i = 0; i < N; i++) {
        x[i] = 6.283185307179586 * i / (N - 1);
        y[i] = sin(x[i]);
    }
    tsu_plot *p = NULL;
    CHECK(tsu_plot_new(0, 0, &p) == TSU_PLOT_OK);
    if (!p)
        return;
    tsu_plot_set_title(p, "sin x, 20000 samples");
    tsu_plot_add_polyline(p, x, y, N, "sin", NULL);
    char *svg = render(p);
    size_t nv = polyline_vertices(svg, 0);
    /* a circle-like arc of curvature radius r px needs about L / sqrt(8 r tol)
     * vertices; for ~1000 px of length this is a few hundred at most */
    CHECKF(nv > 20 && nv < 1000, "vertices %zu", nv);
    CHECKF(svg && strlen(svg) < 30000, "size %zu", svg ? strlen(svg) : 0);
    free(svg);
    save(p, "plot_bigcurve.svg");
    tsu_plot_free(p);
}

/* closed curve with equal aspect (fig. 3 of the paper) */
static void fig_closed(void)
{
    double px[5] = {-1, 0, 1, 0, -1}, py[5] = {0, -1, 0, 1, 0};
    enum { N = 401 };
    static double cx[N], cy[N];
    for (int i = 0; i < N; i++) {
        double t = 6.283185307179586 * i / (N - 1);
        cx[i] = -cos(t) * (1 + 0.1 * cos(4 * t));
        cy[i] = -sin(t) * (1 + 0.1 * cos(4 * t));
    }
    tsu_plot *p = NULL;
    CHECK(tsu_plot_new(0, 0, &p) == TSU_PLOT_OK);
    if (!p)
        return;
    tsu_plot_set_title(p, "closed curve");
    tsu_plot_set_equal_aspect(p, 1);
    tsu_plot_add_polygon(p, px, py, 5, "control polygon", NULL);
    tsu_plot_add_polyline(p, cx, cy, N, "curve", NULL);
    tsu_plot_add_points(p, px, py, 4, "data", NULL);
    tsu_plot_ticks tx, ty;
    CHECK(tsu_plot_get_ticks(p, 0, &tx) == TSU_PLOT_OK && tsu_plot_get_ticks(p, 1, &ty) == TSU_PLOT_OK);
    /* the wide plot widens x: its range exceeds y's */
    CHECK(tx.hi - tx.lo > ty.hi - ty.lo);
    save(p, "plot_closed.svg");
    tsu_plot_free(p);
}

/* fixed ranges cut the curve; no declaration (for inlining into HTML) */
static void fig_fixed_inline(void)
{
    enum { N = 300 };
    static double x[N], y[N];
    for (int i = 0; i < N; i++) {
        x[i] = -2 + 4.0 * i / (N - 1);
        y[i] = x[i] * x[i] * x[i];
    }
    tsu_plot *p = NULL;
    CHECK(tsu_plot_new(480, 320, &p) == TSU_PLOT_OK);
    if (!p)
        return;
    tsu_plot_set_title(p, "fixed ranges");
    tsu_plot_set_xml_declaration(p, 0);
    CHECK(tsu_plot_set_xrange(p, -1, 1.5) == TSU_PLOT_OK);
    CHECK(tsu_plot_set_yrange(p, -0.5, 0.5) == TSU_PLOT_OK);
    tsu_plot_add_polyline(p, x, y, N, "x^3", NULL);
    tsu_plot_add_points(p, x, y, N, NULL, NULL);
    tsu_plot_add_line(p, -1, 0, "y = -x", NULL);
    tsu_plot_add_region(p, TSU_PLOT_FORBID_ABOVE, 0.5, 0.2, "y > x/2 + 0.2", NULL);
    tsu_plot_ticks t;
    CHECK(tsu_plot_get_ticks(p, 0, &t) == TSU_PLOT_OK && t.lo == -1 && t.hi == 1.5);
    char *svg = render(p);
    CHECK(svg && strncmp(svg, "<svg ", 5) == 0);
    free(svg);
    save(p, "plot_inline.svg");
    tsu_plot_free(p);
}

/* shading only where it has area */
static void test_regions(void)
{
    tsu_plot *p = NULL;
    CHECK(tsu_plot_new(0, 0, &p) == TSU_PLOT_OK);
    if (!p)
        return;
    tsu_plot_set_xrange(p, 0, 1);
    tsu_plot_set_yrange(p, 0, 1);
    tsu_plot_add_ceiling(p, 1, NULL, NULL); /* along the top edge: nothing to shade */
    tsu_plot_add_floor(p, 0, NULL, NULL);   /* along the bottom edge */
    tsu_plot_add_floor(p, -2, NULL, NULL);  /* below the plot */
    tsu_plot_add_ceiling(p, 3, NULL, NULL); /* above it */
    char *svg = render(p);
    CHECKF(count(svg, "<polygon ") == 0, "%zu", count(svg, "<polygon "));
    CHECK(count(svg, "<line x1") >= 2 && count(svg, "<g class=\"series region\">") == 4);
    free(svg);
    /* polylines that leave nothing visible: touching the corner (1, 1) from
     * outside, and a piece shorter than the 0.01 px resolution */
    double tx[2] = {0.5, 1.5}, ty[2] = {1.5, 0.5}, sx[2] = {0.5, 0.5 + 1e-9}, sy[2] = {0.5, 0.5};
    tsu_plot_add_polyline(p, tx, ty, 2, NULL, NULL);
    tsu_plot_add_polyline(p, sx, sy, 2, NULL, NULL);
    svg = render(p);
    CHECKF(count(svg, "<polyline") == 0, "%zu", count(svg, "<polyline"));
    CHECK(count(svg, "<g class=\"series polyline\"") == 2);
    free(svg);
    /* a zig-zag poking out over the top edge and back: two visible pieces */
    tsu_plot *q2 = NULL;
    CHECK(tsu_plot_new(0, 0, &q2) == TSU_PLOT_OK);
    if (q2) {
        double zx[3] = {0, 0.5, 1}, zy[3] = {0.2, 2, 0.2};
        tsu_plot_set_xrange(q2, 0, 1);
        tsu_plot_set_yrange(q2, 0, 1);
        tsu_plot_add_polyline(q2, zx, zy, 3, NULL, NULL);
        char *z = render(q2);
        CHECKF(count(z, "<polyline") == 2, "%zu", count(z, "<polyline"));
        CHECK(polyline_vertices(z, 0) == 2 && polyline_vertices(z, 1) == 2);
        free(z);
        tsu_plot_free(q2);
    }
    /* a diagonal floor through two corners shades a triangle, the whole
     * plot when entirely above it */
    tsu_plot_add_region(p, TSU_PLOT_FORBID_BELOW, 1, 0, NULL, NULL);
    tsu_plot_add_region(p, TSU_PLOT_FORBID_ABOVE, 0, 5, NULL, NULL);
    tsu_plot_add_region(p, TSU_PLOT_FORBID_BELOW, 0, 5, NULL, NULL);
    svg = render(p);
    CHECKF(count(svg, "<polygon ") == 2, "%zu", count(svg, "<polygon "));
    const char *q = svg ? strstr(svg, "<polygon points=\"") : NULL;
    size_t commas = 0;
    for (q = q ? q + 17 : NULL; q && *q && *q != '"'; q++)
        commas += *q == ',';
    CHECK(commas == 3); /* the triangle */
    free(svg);
    tsu_plot_free(p);
}

/* data at every candidate spot (corners, edge middles, centre): the legend
 * goes outside on the right */
static void fig_legend(void)
{
    double x[9] = {0, 5, 10, 0, 5, 10, 0, 5, 10}, y[9] = {0, 0, 0, 5, 5, 5, 10, 10, 10};
    tsu_plot *p = NULL;
    CHECK(tsu_plot_new(0, 0, &p) == TSU_PLOT_OK);
    if (!p)
        return;
    tsu_plot_set_title(p, "legend outside");
    tsu_plot_add_points(p, x, y, 9, "grid", NULL);
    tsu_plot_add_points(p, x + 4, y + 4, 1, "centre again", NULL);
    char *svg = render(p);
    CHECK(svg && count(svg, "<circle") == 9 + 1 + 2);
    free(svg);
    save(p, "plot_legend_outside.svg");
    tsu_plot_free(p);

    /* an increasing curve leaves the upper-left corner free */
    double cx[50], cy[50];
    for (int i = 0; i < 50; i++)
        cx[i] = i, cy[i] = i * i;
    CHECK(tsu_plot_new(0, 0, &p) == TSU_PLOT_OK);
    if (!p)
        return;
    tsu_plot_set_title(p, "legend upper left");
    tsu_plot_add_polyline(p, cx, cy, 50, "x squared", NULL);
    tsu_plot_add_points(p, cx, cy, 50, "samples", NULL);
    svg = render(p);
    /* the legend box starts 8 px inside the frame's left edge */
    const char *lg = svg ? strstr(svg, "<g class=\"legend\"><rect x=\"") : NULL;
    const char *fr = svg ? strstr(svg, "<g class=\"axes\"") : NULL;
    fr = fr ? strstr(fr, "<rect x=\"") : NULL;
    CHECK(lg && fr);
    if (lg && fr) {
        double lx = strtod(lg + 27, NULL), fx = strtod(fr + 9, NULL);
        CHECKF(fabs(lx - (fx + 8)) < 0.01, "legend x %g, frame x %g", lx, fx);
    }
    free(svg);
    save(p, "plot_legend_ul.svg");
    tsu_plot_free(p);
}

/* Random plots: odd sizes, values (NaN, +-Inf, huge, tiny), fixed ranges,
 * equal aspect, legend modes.  Every render must succeed, give sane ticks
 * and no nan/inf; every 40th is saved as fuzz_*.svg for the script. */
static unsigned long long fz = 99;
static double frand(void)
{
    fz = fz * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(fz >> 11) / 9007199254740992.0;
}

static double fvalue(double scale)
{
    double r = frand();
    if (r < 0.02)
        return (double)NAN;
    if (r < 0.03)
        return r < 0.025 ? (double)INFINITY : -(double)INFINITY;
    if (r < 0.035)
        return 1e301;
    return scale * (2 * frand() - 1);
}

static void test_fuzz(void)
{
    static double x[300], y[300];
    long bad = 0;
    for (int it = 0; it < 400; it++) {
        tsu_plot *p = NULL;
        unsigned w = 160 + (unsigned)(frand() * 1000), h = 160 + (unsigned)(frand() * 700);
        if (tsu_plot_new(w, h, &p) != TSU_PLOT_OK) {
            bad++;
            continue;
        }
        double sx = pow(10.0, -12 + 24 * frand()), sy = pow(10.0, -12 + 24 * frand());
        if (frand() < 0.3)
            tsu_plot_set_title(p, frand() < 0.5 ? "a rather long title for a small plot, really" : "t");
        if (frand() < 0.3)
            tsu_plot_set_labels(p, "x label", frand() < 0.5 ? "y" : NULL);
        if (frand() < 0.2)
            tsu_plot_set_xrange(p, -sx * frand(), sx * frand() + sx * 0.01);
        if (frand() < 0.2)
            tsu_plot_set_yrange(p, -sy * frand(), sy * frand() + sy * 0.01);
        tsu_plot_set_equal_aspect(p, frand() < 0.2);
        tsu_plot_set_legend(p, (tsu_plot_legend)(int)(frand() * 7));
        int ns = (int)(frand() * 6);
        for (int k = 0; k < ns; k++) {
            size_t n = (size_t)(frand() * 300);
            int mono = frand() < 0.5;
            for (size_t i = 0; i < n; i++) {
                x[i] = mono ? sx * (double)i / 300 : fvalue(sx);
                y[i] = fvalue(sy);
            }
            const char *lab = frand() < 0.7 ? "series with a label" : NULL;
            double r = frand();
            if (r < 0.3)
                tsu_plot_add_points(p, x, y, n, lab, NULL);
            else if (r < 0.6)
                tsu_plot_add_polyline(p, x, y, n, lab, NULL);
            else if (r < 0.7)
                tsu_plot_add_polygon(p, x, y, n, lab, NULL);
            else if (r < 0.85)
                tsu_plot_add_line(p, (2 * frand() - 1) * sy / sx, (2 * frand() - 1) * sy, lab, NULL);
            else
                tsu_plot_add_region(p, frand() < 0.5 ? TSU_PLOT_FORBID_BELOW : TSU_PLOT_FORBID_ABOVE,
                                   (2 * frand() - 1) * sy / sx, (2 * frand() - 1) * sy, lab, NULL);
        }
        tsu_plot_ticks tx, ty;
        tsu_plot_get_ticks(p, 0, &tx);
        tsu_plot_get_ticks(p, 1, &ty);
        char *svg = render(p);
        int ok = svg && !has_nonfinite(svg) && tx.n >= 3 && tx.n <= 9 && ty.n >= 3 && ty.n <= 9;
        if (!ok && bad++ < 3)
            fprintf(stderr, "fuzz %d: ticks %zu %zu\n", it, tx.n, ty.n);
        free(svg);
        if (it % 40 == 0) {
            char name[40];
            snprintf(name, sizeof name, "fuzz_%03d.svg", it);
            save(p, name);
        }
        tsu_plot_free(p);
    }
    CHECKF(bad == 0, "%ld fuzz plots failed", bad);
}

int main(int argc, char **argv)
{
    if (argc > 1) {
        snprintf(outdir, sizeof outdir, "%s", argv[1]);
    } else {
        const char *slash = strrchr(argv[0], '/');
        int n = slash ? (int)(slash - argv[0]) : 1;
        snprintf(outdir, sizeof outdir, "%.*s/plot_out", n, slash ? argv[0] : ".");
    }
    if (mkdir(outdir, 0777) != 0 && errno != EEXIST) {
        fprintf(stderr, "cannot create %s\n", outdir);
        CHECK(0);
    }
    test_ticks_hand();
    test_ticks_sweep();
    test_buf();
    test_errors();
    test_oom();
    test_simplify();
    test_regions();
    fig_full();
    fig_degenerate();
    fig_nan();
    fig_huge();
    fig_special();
    fig_bigcurve();
    fig_closed();
    fig_fixed_inline();
    fig_legend();
    test_fuzz();
    return th_report("test_plot");
}
