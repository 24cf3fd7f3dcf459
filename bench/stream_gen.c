/* Rows for bench_stream.sh: "time","value" with every field quoted, ISO 8601
 * timestamps one second apart from 2000-01-01T00:00:00Z, positive values.
 * Usage: stream_gen N  (writes a header and N rows to standard output). */
#include <stdio.h>
#include <stdlib.h>

static int mdays(int y, int m)
{
    static const int d[12] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
    return m == 2 ? 28 + ((y % 4 == 0 && y % 100 != 0) || y % 400 == 0) : d[m - 1];
}

int main(int argc, char **argv)
{
    unsigned long long n = argc > 1 ? strtoull(argv[1], NULL, 10) : 1000;
    int Y = 2000, M = 1, D = 1, h = 0, mi = 0, s = 0;
    static char buf[1 << 16];
    setvbuf(stdout, buf, _IOFBF, sizeof buf);
    fputs("\"time\",\"value\"\n", stdout);
    for (unsigned long long i = 0; i < n; i++) {
        printf("\"%04d-%02d-%02dT%02d:%02d:%02dZ\",\"%llu.%02llu\"\n", Y, M, D, h, mi, s,
               1 + (i * 7919) % 97, (i * 104729) % 100);
        if (++s == 60) {
            s = 0;
            if (++mi == 60) {
                mi = 0;
                if (++h == 24) {
                    h = 0;
                    if (++D > mdays(Y, M)) {
                        D = 1;
                        if (++M == 13)
                            M = 1, Y++;
                    }
                }
            }
        }
    }
    return fflush(stdout) != 0;
}
