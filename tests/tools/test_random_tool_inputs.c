/* Seeded robustness test of the tools' support code (tools/support): the
 * table reader, number conversion (tsu_io.h) and SVG plots (tsu_plot.h) with
 * random and hostile input.  The library's own entry points are fuzzed by
 * tests/api/test_random_inputs.c; this half was split off from it because it
 * needs the support headers, which are not part of the public API.
 *
 * What must hold, whatever the input:
 *  - no crash, no leak, no out-of-bounds access (run under ASan by make test);
 *  - the reader never accepts a non-finite value, agrees with the streaming
 *    reader, and repeats its error; tsu_parse_double agrees bit for bit with
 *    glibc strtod on the prefix it accepted; tsu_format_double round-trips;
 *  - SVG plots of hostile series render to a complete document that never
 *    contains "nan" or "inf"; ticks are increasing and inside their range.
 * Counts are reduced under ASan (__SANITIZE_ADDRESS__) to keep the run short.
 */
#define _POSIX_C_SOURCE 200809L
#include "th.h"
#include "common/th_rng.h"
#include "tsu_io.h"
#include "tsu_plot.h"

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#if TH_ASAN
#define TS_FUZZ_SLOW 1
#endif
#ifdef TS_FUZZ_SLOW
#define N_TABLE 6000
#define N_NUMBER 80000
#define N_PLOT 300
#else
#define N_TABLE 20000
#define N_NUMBER 400000
#define N_PLOT 1500
#endif

/* ---- random -------------------------------------------------------------- */

/* th_rng.h: the default generator (seeded in main); th_hostile() gives the
 * hostile doubles (NaN, infinities, extremes, subnormals, random bits). */

/* A garbage int for an enum field (out of range or valid). */
static int enum_val(int count)
{
    switch (th_below(12)) {
    case 0: return count;
    case 1: return -1;
    case 2: return 1000;
    default: return (int)th_below((size_t)count);
    }
}

/* ---- statistics, so that the test cannot pass by never succeeding -------- */

static long n_table_ok, n_table_err, n_num_ok;

/* ---- reader and numbers --------------------------------------------------- */

static const char alphabet[] = "0123456789012345.,,-+eE  \t\r\n\n#nanif\"xa\xef\xbb\xbf";

static size_t gen_bytes(char *b, size_t cap)
{
    size_t len = 0;
    if (th_chance(0.5)) { /* a valid table, then mutations */
        size_t rows = 1 + th_below(6), cols = 1 + th_below(3);
        int delim = (int)th_below(3);
        const char dc = delim == 0 ? ',' : delim == 1 ? '\t' : ' ';
        if (th_chance(0.3))
            len += (size_t)snprintf(b + len, cap - len, "x%cy%cz\n", dc, dc);
        for (size_t r = 0; r < rows && len + 80 < cap; r++) {
            for (size_t c = 0; c < cols; c++) {
                char nb[TSU_FMT_SIZE];
                size_t l = tsu_format_double(th_chance(0.9) ? th_unit() * 200 - 100 : th_hostile(), nb);
                memcpy(b + len, nb, l);
                len += l;
                b[len++] = c + 1 < cols ? dc : (th_chance(0.2) ? '\r' : '\n');
                if (b[len - 1] == '\r')
                    b[len++] = '\n';
            }
        }
        for (int k = (int)th_below(4); k > 0 && len; k--) {
            size_t i = th_below(len);
            switch (th_below(3)) {
            case 0: b[i] = alphabet[th_below(sizeof alphabet - 1)]; break;
            case 1: memmove(b + i, b + i + 1, len - i - 1), len--; break;
            default:
                if (len + 1 < cap) {
                    memmove(b + i + 1, b + i, len - i);
                    b[i] = (char)(th_chance(0.9) ? alphabet[th_below(sizeof alphabet - 1)] : (char)th_u64());
                    len++;
                }
            }
        }
    } else {
        len = th_below(cap < 300 ? cap : 300);
        for (size_t i = 0; i < len; i++)
            b[i] = th_chance(0.95) ? alphabet[th_below(sizeof alphabet - 1)] : (char)th_u64();
    }
    return len;
}

static FILE *open_bytes(const char *b, size_t len)
{
    if (len == 0)
        return tmpfile();
    return fmemopen((void *)(uintptr_t)b, len, "r");
}

static int msg_ok(const tsu_io_error *e)
{
    return memchr(e->msg, '\0', sizeof e->msg) != NULL && tsu_io_strerror(e->status) != NULL;
}

static void fuzz_tables(void)
{
    char b[1024];
    for (int it = 0; it < N_TABLE; it++) {
        size_t len = gen_bytes(b, sizeof b);
        tsu_read_options ro;
        tsu_read_options_init(&ro);
        ro.delim = (tsu_delim)(th_chance(0.9) ? (int)th_below(4) : enum_val(4));
        ro.header = (tsu_header)(th_chance(0.9) ? (int)th_below(3) : enum_val(3));
        ro.ncols = th_chance(0.7) ? 0 : th_below(5);
        ro.max_line = th_chance(0.5) ? TSU_IO_MAX_LINE : th_chance(0.9) ? 16 + th_below(100) : th_below(16);
        ro.buffer_size = th_chance(0.5) ? TSU_IO_BUFFER : th_chance(0.9) ? 16 + th_below(64) : th_below(16);
        ro.track_lines = (int)th_below(2);
        const tsu_read_options *op = th_chance(0.95) ? &ro : NULL;

        FILE *fp = open_bytes(b, len);
        if (!fp)
            continue;
        tsu_table t;
        tsu_io_error e;
        tsu_io_status st = tsu_read_table(fp, "fuzz", op, &t, &e);
        fclose(fp);
        CHECK((unsigned)st < (unsigned)TSU_IO_STATUS_COUNT_ && st != TSU_IO_END && e.status == st &&
              msg_ok(&e));
        if (st == TSU_IO_OK) {
            n_table_ok++;
            int ok = t.nrows > 0 && t.ncols > 0 && t.cols != NULL;
            for (size_t j = 0; ok && j < t.ncols; j++)
                for (size_t i = 0; ok && i < t.nrows; i++)
                    ok = isfinite(t.cols[j][i]);
            CHECK(ok);
            if (op && op->ncols)
                CHECK(t.ncols == op->ncols);
            int track = op ? op->track_lines : 1;
            CHECK((t.lines != NULL) == (track != 0));
            for (size_t i = 1; t.lines && i < t.nrows; i++)
                CHECK(t.lines[i] > t.lines[i - 1]);
        } else {
            n_table_err++;
            CHECK(t.nrows == 0 && t.cols == NULL && t.names == NULL && t.lines == NULL);
        }
        /* the streaming reader agrees */
        fp = open_bytes(b, len);
        if (fp) {
            tsu_reader *r = NULL;
            tsu_io_error e2;
            tsu_io_status so = tsu_reader_open(&r, fp, NULL, op, &e2);
            CHECK((unsigned)so < (unsigned)TSU_IO_STATUS_COUNT_ && msg_ok(&e2));
            if (so == TSU_IO_OK) {
                const double *row;
                size_t rows = 0;
                int same = 1;
                tsu_io_status sn;
                while ((sn = tsu_reader_next(r, &row, &e2)) == TSU_IO_OK && rows < 100000) {
                    CHECK(row != NULL);
                    size_t nc = tsu_reader_ncols(r);
                    if (st == TSU_IO_OK && rows < t.nrows && nc == t.ncols)
                        for (size_t j = 0; j < nc; j++)
                            same = same && memcmp(&row[j], &t.cols[j][rows], sizeof(double)) == 0;
                    rows++;
                }
                CHECK(msg_ok(&e2));
                if (st == TSU_IO_OK)
                    CHECKF(sn == TSU_IO_END && rows == t.nrows && same,
                           "reader: status %d rows %zu vs table %zu", (int)sn, rows, t.nrows);
                else
                    CHECKF(sn == st, "reader status %d vs table %d", (int)sn, (int)st);
                if (sn != TSU_IO_END) { /* the error repeats */
                    tsu_io_error e3;
                    CHECK(tsu_reader_next(r, &row, &e3) == sn && row == NULL &&
                          strcmp(e3.msg, e2.msg) == 0);
                }
            } else {
                CHECK(r == NULL);
            }
            tsu_reader_free(r);
            fclose(fp);
        }
        tsu_table_free(&t);
        CHECK(t.cols == NULL && t.nrows == 0);
    }
    tsu_table_free(NULL);
    tsu_reader_free(NULL);
}

static void fuzz_numbers(void)
{
    static const char nchars[] = "0123456789012345678901234567890.-+eE.nNaAiIfFtTyY x";
    for (int it = 0; it < N_NUMBER; it++) {
        /* text: exact-size heap buffer, not NUL-terminated (ASan sees overreads) */
        size_t len = th_below(th_chance(0.9) ? 30 : 800);
        char *s = malloc(len ? len : 1);
        if (!s)
            continue;
        for (size_t i = 0; i < len; i++)
            s[i] = th_chance(0.97) ? nchars[th_below(sizeof nchars - 1)] : (char)th_u64();
        double v = 123.0;
        const char *stop = NULL;
        tsu_num_status st = tsu_parse_double(s, s + len, &v, &stop);
        CHECK((unsigned)st <= 3u && stop >= s && stop <= s + len);
        if (st == TSU_NUM_OK || st == TSU_NUM_RANGE) {
            char tmp[1024];
            size_t l = (size_t)(stop - s);
            memcpy(tmp, s, l);
            tmp[l] = '\0';
            char *e;
            double ref = strtod(tmp, &e);
            CHECKF(memcmp(&ref, &v, sizeof v) == 0 && e == tmp + l,
                   "\"%s\": %.17g vs strtod %.17g", tmp, v, ref);
            n_num_ok++;
        } else if (st == TSU_NUM_SYNTAX) {
            CHECK(v == 0.0);
        } else {
            CHECK(!isfinite(v));
        }
        free(s);

        /* shortest format round-trips */
        uint64_t bits = th_u64();
        double d;
        memcpy(&d, &bits, sizeof d);
        if (th_chance(0.2))
            d = th_hostile();
        char buf[TSU_FMT_SIZE];
        memset(buf, 'Z', sizeof buf);
        size_t fl = tsu_format_double(d, buf);
        CHECK(fl < TSU_FMT_SIZE && buf[fl] == '\0' && strlen(buf) == fl);
        double back;
        tsu_num_status sb = tsu_parse_double(buf, NULL, &back, &stop);
        if (isnan(d))
            CHECK(sb == TSU_NUM_NONFINITE && isnan(back));
        else
            CHECKF((sb == TSU_NUM_OK || (sb == TSU_NUM_NONFINITE && isinf(d))) &&
                       memcmp(&back, &d, sizeof d) == 0 && *stop == '\0',
                   "format %.17g -> \"%s\"", d, buf);
    }
}

/* ---- plots ---------------------------------------------------------------- */

#define PSET(s) (1u << (s))
static int plot_in(tsu_plot_status st, unsigned set)
{
    return (unsigned)st <= 5u && ((set >> st) & 1u) && tsu_plot_strerror(st) != NULL;
}

static long n_plot_ok;

static void fuzz_plots(void)
{
    const unsigned OK_ARG = PSET(TSU_PLOT_OK) | PSET(TSU_PLOT_ERR_ARG);
    const unsigned SERIES = PSET(TSU_PLOT_OK) | PSET(TSU_PLOT_ERR_NULL) | PSET(TSU_PLOT_ERR_ARG) |
                            PSET(TSU_PLOT_ERR_NOMEM) | PSET(TSU_PLOT_ERR_OVERFLOW);
    static const char *const colors[] = {"#123", "#a0b1c2", "black", "gray", "#12", "red!",
                                         "", "#GGGGGG", "abcdefghijklmnopqrstu"};
    static const char *const texts[] = {"T", "a < b & \"c\"", "\xff\xfe bad utf8 \x01",
                                        "\xc3\xa9t\xc3\xa9 \xe2\x88\x9a\x32", ""}; /* \x32: the digit 2 */
    double x[200], y[200];
    for (int it = 0; it < N_PLOT; it++) {
        /* ticks */
        tsu_plot_ticks tk;
        double lo = th_chance(0.6) ? (th_unit() - 0.5) * th_logu(1e-6, 1e12) : th_hostile();
        double hi = th_chance(0.8) ? lo + th_logu(1e-15, 1e6) * (fabs(lo) + 1) : th_hostile();
        tsu_plot_range_mode mode = (tsu_plot_range_mode)(th_chance(0.9) ? (int)th_below(2) : enum_val(2));
        tsu_plot_status st = tsu_plot_ticks_compute(lo, hi, mode, &tk);
        CHECK(plot_in(st, OK_ARG));
        if (st == TSU_PLOT_OK) {
            int ok = tk.n >= 1 && tk.n <= TSU_PLOT_MAX_TICKS && tk.lo < tk.hi;
            for (size_t i = 0; ok && i < tk.n; i++) {
                ok = tk.value[i] >= tk.lo - 1e-9 * (tk.hi - tk.lo) &&
                     tk.value[i] <= tk.hi + 1e-9 * (tk.hi - tk.lo) &&
                     (i == 0 || tk.value[i] > tk.value[i - 1]) &&
                     memchr(tk.label[i], '\0', TSU_PLOT_LABEL_MAX) != NULL;
            }
            CHECKF(ok, "ticks of [%.17g, %.17g] mode %d", lo, hi, (int)mode);
        }
        /* a plot */
        tsu_plot *p = NULL;
        unsigned w = th_chance(0.9) ? 0 : (unsigned)th_below(20000), h = th_chance(0.9) ? 0 : (unsigned)th_below(20000);
        st = tsu_plot_new(w, h, &p);
        CHECK(plot_in(st, OK_ARG) && (st == TSU_PLOT_OK) == (p != NULL));
        if (!p)
            continue;
        CHECK(plot_in(tsu_plot_set_title(p, th_chance(0.8) ? texts[th_below(5)] : NULL), PSET(TSU_PLOT_OK)));
        CHECK(plot_in(tsu_plot_set_labels(p, texts[th_below(5)], texts[th_below(5)]), PSET(TSU_PLOT_OK)));
        if (th_chance(0.3))
            CHECK(plot_in(tsu_plot_set_xrange(p, th_hostile(), th_hostile()), OK_ARG));
        if (th_chance(0.3))
            CHECK(plot_in(tsu_plot_set_yrange(p, th_unit(), th_unit() + th_unit()), OK_ARG));
        CHECK(tsu_plot_set_equal_aspect(p, (int)th_below(2)) == TSU_PLOT_OK);
        CHECK(plot_in(tsu_plot_set_legend(p, (tsu_plot_legend)enum_val(7)), OK_ARG));
        CHECK(tsu_plot_set_xml_declaration(p, (int)th_below(2)) == TSU_PLOT_OK);
        CHECK(tsu_plot_set_grid(p, (int)th_below(2)) == TSU_PLOT_OK);
        CHECK(plot_in(tsu_plot_set_simplify(p, th_chance(0.8) ? th_unit() : th_hostile()), OK_ARG));
        for (int k = (int)th_below(6); k > 0; k--) {
            size_t n = th_below(200);
            double sc = th_chance(0.8) ? th_logu(1e-3, 1e3) : th_logu(1e-300, 1e300);
            for (size_t i = 0; i < n; i++) {
                x[i] = th_chance(0.95) ? sc * (double)i : th_hostile();
                y[i] = th_chance(0.95) ? sc * sin((double)i) : th_hostile();
            }
            tsu_plot_style sty = {colors[th_below(9)], th_chance(0.9) ? th_unit() * 5 : th_hostile(), (int)th_below(4) - 1,
                                 th_chance(0.9) ? th_unit() * 5 : th_hostile(), (int)th_below(2), th_unit()};
            const tsu_plot_style *sp = th_chance(0.5) ? &sty : NULL;
            const char *lab = texts[th_below(5)];
            switch (th_below(7)) {
            case 0: st = tsu_plot_add_points(p, x, y, n, lab, sp); break;
            case 1: st = tsu_plot_add_polyline(p, x, y, n, lab, sp); break;
            case 2: st = tsu_plot_add_polygon(p, x, y, n, lab, sp); break;
            case 3: st = tsu_plot_add_line(p, th_hostile(), th_hostile(), lab, sp); break;
            case 4:
                st = tsu_plot_add_region(p, (tsu_plot_side)enum_val(2), th_unit() - 0.5,
                                        th_chance(0.9) ? th_unit() : th_hostile(), lab, sp);
                break;
            case 5: st = tsu_plot_add_floor(p, th_hostile(), lab, sp); break;
            default: st = tsu_plot_add_polyline(p, n ? x : NULL, y, n, lab, sp); break;
            }
            CHECK(plot_in(st, SERIES));
        }
        tsu_plot_buf b = TSU_PLOT_BUF_INIT;
        st = tsu_plot_render(p, &b);
        CHECK(plot_in(st, PSET(TSU_PLOT_OK) | PSET(TSU_PLOT_ERR_NOMEM) | PSET(TSU_PLOT_ERR_OVERFLOW)));
        if (st == TSU_PLOT_OK) {
            n_plot_ok++;
            int ok = b.data && strlen(b.data) == b.len && strstr(b.data, "<svg") &&
                     b.len > 7 && strcmp(b.data + b.len - 7, "</svg>\n") == 0;
            CHECK(ok);
            CHECKF(b.data && !strstr(b.data, "nan") && !strstr(b.data, "inf") &&
                       !strstr(b.data, "NaN") && !strstr(b.data, "Inf"),
                   "plot %d: nan/inf in the SVG", it);
        }
        for (int axis = -1; axis < 3; axis++) {
            tsu_plot_status sg = tsu_plot_get_ticks(p, axis, &tk);
            CHECK(plot_in(sg, OK_ARG) && ((axis == 0 || axis == 1) || sg == TSU_PLOT_ERR_ARG));
        }
        tsu_plot_buf_free(&b);
        tsu_plot_free(p);
    }
    tsu_plot_free(NULL);
    tsu_plot_buf_free(NULL);
}

int main(void)
{
    const char *seed = getenv("TS_FUZZ_SEED"); /* exploring other seeds by hand */
    th_seed(seed ? strtoull(seed, NULL, 10) : 0x5EED7001u);
    TH_CASE("fuzz_tables");
    fuzz_tables();
    TH_CASE("fuzz_numbers");
    fuzz_numbers();
    TH_CASE("fuzz_plots");
    fuzz_plots();
    /* the test exercised success paths, not only errors */
    CHECK(n_table_ok > N_TABLE / 20 && n_table_err > N_TABLE / 20);
    CHECK(n_num_ok > N_NUMBER / 10);
    CHECK(n_plot_ok > N_PLOT / 2);
    printf("tables ok %ld, failed %ld\n", n_table_ok, n_table_err);
    return th_report("test_random_tool_inputs");
}
