/* The shortest decimal form of a double that reads back to it (messages;
 * docs/method.md is not involved).  The same text as the command's number
 * printer: the fewest significant digits that round-trip, written fixed when
 * the decimal exponent x of the first digit has -4 <= x < 17, else as
 * d.ddde±XX.  No allocation. */
#include "internal.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void ts__format_double(double v, char buf[TS__NUM_SIZE])
{
    if (isnan(v)) {
        snprintf(buf, TS__NUM_SIZE, "nan");
        return;
    }
    if (isinf(v)) {
        snprintf(buf, TS__NUM_SIZE, v > 0 ? "inf" : "-inf");
        return;
    }
    /* p significant digits: the first p whose %.(p-1)e reads back (17 always does) */
    int p = 1;
    for (; p < 17; p++) {
        snprintf(buf, TS__NUM_SIZE, "%.*e", p - 1, v);
        if (strtod(buf, NULL) == v)
            break;
    }
    snprintf(buf, TS__NUM_SIZE, "%.*e", p - 1, v);
    int x = atoi(strchr(buf, 'e') + 1); /* %e of a finite double always has its 'e' */
    if (-4 <= x && x < 17)
        snprintf(buf, TS__NUM_SIZE, "%.*f", p - 1 - x > 0 ? p - 1 - x : 0, v);
}
