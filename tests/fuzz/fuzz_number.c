/* The CLI's number parser and printer (tools/support/tsu_io.h) against the
 * C library's strtod in the C locale: the parsed prefix gives the same bits
 * as strtod on that prefix, and every double printed by tsu_format_double
 * reads back (tsu and strtod) to the same bits, in at most 17 digits. */
#include "fuzz.h"
#include "tsu_io.h"

#include <math.h>

static int numeric_chars(const char *a, const char *b)
{
    for (; a < b; a++)
        if (!strchr("0123456789+-.eE", *a))
            return 0;
    return 1;
}

static int same_bits(double a, double b)
{
    return memcmp(&a, &b, sizeof a) == 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char s[256];
    size_t n = size < sizeof s - 1 ? size : sizeof s - 1;
    memcpy(s, data, n);
    s[n] = '\0';
    double v;
    const char *stop;
    tsu_num_status st = tsu_parse_double(s, NULL, &v, &stop);
    FUZZ_CHECK(stop >= s && stop <= s + n, "stop outside the input");
    if ((st == TSU_NUM_OK || st == TSU_NUM_RANGE) && numeric_chars(s, stop)) {
        char pre[256];
        memcpy(pre, s, (size_t)(stop - s));
        pre[stop - s] = '\0';
        char *end;
        double w = strtod(pre, &end);
        FUZZ_CHECK(*end == '\0', "strtod stops early in \"%s\"", pre);
        FUZZ_CHECK(same_bits(v, w), "\"%s\": tsu %.17g, strtod %.17g", pre, v, w);
        FUZZ_CHECK((st == TSU_NUM_RANGE) == (isinf(w) != 0), "\"%s\": range status", pre);
    }
    /* printer: the first 8 bytes as a double */
    if (size >= 8) {
        double d;
        memcpy(&d, data, sizeof d);
        char buf[TSU_FMT_SIZE];
        size_t len = tsu_format_double(d, buf);
        FUZZ_CHECK(len == strlen(buf) && len < TSU_FMT_SIZE, "length %zu", len);
        if (isfinite(d)) {
            double back, back2;
            FUZZ_CHECK(tsu_parse_double(buf, NULL, &back, &stop) == TSU_NUM_OK && *stop == '\0',
                       "\"%s\" does not parse", buf);
            back2 = strtod(buf, NULL);
            FUZZ_CHECK(same_bits(back, d) && same_bits(back2, d), "\"%s\" for %.17g", buf, d);
            int digits = 0, lead = 1;
            for (const char *c = buf; *c && *c != 'e' && *c != 'E'; c++)
                if (*c >= '0' && *c <= '9') {
                    lead = lead && *c == '0';
                    digits += !lead;
                }
            FUZZ_CHECK(digits <= 17, "\"%s\": %d digits", buf, digits);
        }
    }
    return 0;
}
