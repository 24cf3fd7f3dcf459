/* Messages, JSON building and safe output for the command-line tool. */
#define _POSIX_C_SOURCE 200809L
#include "cli.h"

#include <sys/stat.h>

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void cli_error(const char *fmt, ...)
{
    va_list ap;
    fputs("trigspline: ", stderr);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
}

int cli_usage(cli_cmd cmd, const char *fmt, ...)
{
    va_list ap;
    fprintf(stderr, "trigspline %s: ", cli_cmd_name(cmd));
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fprintf(stderr, "\nTry 'trigspline %s --help' for more information.\n", cli_cmd_name(cmd));
    return CLI_USAGE;
}

const char *cli_num(double v, char buf[TSU_FMT_SIZE])
{
    tsu_format_double(v, buf);
    return buf;
}

void cli_line_text(const ts_line *l, char *buf, size_t len)
{
    char m[TSU_FMT_SIZE + 1], c[TSU_FMT_SIZE];
    if (l->m == 1.0)
        snprintf(m, sizeof m, "x");
    else if (l->m == -1.0)
        snprintf(m, sizeof m, "-x");
    else {
        tsu_format_double(l->m, m);
        strcat(m, "x");
    }
    if (l->m == 0.0)
        snprintf(buf, len, "y = %s", cli_num(l->c, c));
    else if (l->c == 0.0)
        snprintf(buf, len, "y = %s", m);
    else if (l->c < 0.0)
        snprintf(buf, len, "y = %s - %s", m, cli_num(-l->c, c));
    else
        snprintf(buf, len, "y = %s + %s", m, cli_num(l->c, c));
}

int cli_nomem(void)
{
    cli_error("out of memory");
    return CLI_IO;
}

/* ---- JSON ------------------------------------------------------------- */

void cli_json_init(cli_json *j)
{
    tsu_plot_buf_init(&j->b);
    j->need_comma = 0;
    j->nl = 0;
    j->failed = 0;
}

void cli_json_nl(cli_json *j)
{
    j->nl = 1;
}

void cli_json_free(cli_json *j)
{
    tsu_plot_buf_free(&j->b);
}

void cli_json_raw(cli_json *j, const char *s)
{
    if (tsu_plot_buf_puts(&j->b, s) != TSU_PLOT_OK)
        j->failed = 1;
}

static void comma(cli_json *j)
{
    if (j->need_comma)
        cli_json_raw(j, j->nl ? ",\n" : ", ");
    else if (j->nl)
        cli_json_raw(j, "\n");
    j->nl = 0;
    j->need_comma = 1;
}

void cli_json_key(cli_json *j, const char *key)
{
    comma(j);
    cli_json_raw(j, "\"");
    cli_json_raw(j, key);
    cli_json_raw(j, "\": ");
    j->need_comma = 0;
}

void cli_json_begin(cli_json *j, char c)
{
    comma(j);
    cli_json_raw(j, c == '{' ? "{" : "[");
    j->need_comma = 0;
}

void cli_json_end(cli_json *j, char c)
{
    cli_json_raw(j, c == '}' ? "}" : "]");
    j->need_comma = 1;
}

void cli_json_num(cli_json *j, double v)
{
    char b[TSU_FMT_SIZE];
    comma(j);
    if (!isfinite(v)) {
        cli_json_raw(j, "null");
        return;
    }
    cli_json_raw(j, cli_num(v, b));
}

void cli_json_uint(cli_json *j, unsigned long long v)
{
    char b[32];
    comma(j);
    snprintf(b, sizeof b, "%llu", v);
    cli_json_raw(j, b);
}

void cli_json_bool(cli_json *j, int v)
{
    comma(j);
    cli_json_raw(j, v ? "true" : "false");
}

void cli_json_null(cli_json *j)
{
    comma(j);
    cli_json_raw(j, "null");
}

void cli_json_str(cli_json *j, const char *s)
{
    comma(j);
    cli_json_raw(j, "\"");
    char esc[8];
    const char *run = s;
    for (const char *p = s;; p++) {
        unsigned char ch = (unsigned char)*p;
        if (ch != '\0' && ch >= 0x20 && ch != '"' && ch != '\\')
            continue;
        if (p > run && tsu_plot_buf_append(&j->b, run, (size_t)(p - run)) != TSU_PLOT_OK)
            j->failed = 1;
        if (ch == '\0')
            break;
        if (ch == '"' || ch == '\\')
            snprintf(esc, sizeof esc, "\\%c", ch);
        else
            snprintf(esc, sizeof esc, "\\u%04x", ch);
        cli_json_raw(j, esc);
        run = p + 1;
    }
    cli_json_raw(j, "\"");
}

void cli_json_knum(cli_json *j, const char *k, double v)
{
    cli_json_key(j, k);
    cli_json_num(j, v);
}
void cli_json_kuint(cli_json *j, const char *k, unsigned long long v)
{
    cli_json_key(j, k);
    cli_json_uint(j, v);
}
void cli_json_kbool(cli_json *j, const char *k, int v)
{
    cli_json_key(j, k);
    cli_json_bool(j, v);
}
void cli_json_kstr(cli_json *j, const char *k, const char *s)
{
    cli_json_key(j, k);
    cli_json_str(j, s);
}
void cli_json_kline(cli_json *j, const char *k, const ts_line *l)
{
    cli_json_key(j, k);
    if (!l) {
        cli_json_null(j);
        return;
    }
    cli_json_begin(j, '{');
    cli_json_knum(j, "m", l->m);
    cli_json_knum(j, "c", l->c);
    cli_json_end(j, '}');
}

/* ---- growable pairs ------------------------------------------------------ */

void cli_xy_push(cli_xy *a, double x, double y)
{
    if (a->failed)
        return;
    if (a->n == a->cap) {
        size_t cap = a->cap ? a->cap * 2 : 256;
        if (cap < a->cap || cap > SIZE_MAX / sizeof(double)) {
            a->failed = 1;
            return;
        }
        double *nx = realloc(a->x, cap * sizeof *nx);
        if (!nx) {
            a->failed = 1;
            return;
        }
        a->x = nx;
        double *ny = realloc(a->y, cap * sizeof *ny);
        if (!ny) {
            a->failed = 1;
            return;
        }
        a->y = ny;
        a->cap = cap;
    }
    a->x[a->n] = x;
    a->y[a->n] = y;
    a->n++;
}

void cli_xy_free(cli_xy *a)
{
    free(a->x);
    free(a->y);
    memset(a, 0, sizeof *a);
}

/* ---- outputs --------------------------------------------------------------- */

int cli_out_open(cli_out *c, const char *path, char *msg, size_t len)
{
    struct stat st;
    c->o = NULL;
    c->direct = NULL;
    if (strcmp(path, "-") != 0 && stat(path, &st) == 0 && !S_ISREG(st.st_mode)) {
        if (S_ISDIR(st.st_mode)) {
            snprintf(msg, len, "cannot write \"%s\": Is a directory", path);
            return EISDIR;
        }
        c->direct = fopen(path, "w");
        if (!c->direct) {
            int e = errno;
            snprintf(msg, len, "cannot open \"%s\": %s", path, strerror(e));
            return e ? e : EIO;
        }
        return 0;
    }
    return tsu_out_open(&c->o, path, 0, msg, len);
}

FILE *cli_out_file(const cli_out *c)
{
    return c->direct ? c->direct : tsu_out_file(c->o);
}

int cli_out_commit(cli_out *c, char *msg, size_t len)
{
    if (c->direct) {
        FILE *fp = c->direct;
        c->direct = NULL;
        errno = 0;
        int bad = fflush(fp) != 0 || ferror(fp);
        int e = errno ? errno : EIO;
        if (fclose(fp) != 0 && !bad) {
            bad = 1;
            e = errno ? errno : EIO;
        }
        if (bad) {
            snprintf(msg, len, "write error: %s", strerror(e));
            return e;
        }
        return 0;
    }
    tsu_out *o = c->o;
    c->o = NULL;
    return o ? tsu_out_commit(o, msg, len) : 0;
}

void cli_out_abort(cli_out *c)
{
    if (c->direct)
        fclose(c->direct);
    tsu_out_abort(c->o);
    c->direct = NULL;
    c->o = NULL;
}

/* Write, then flush and check the stream: 0 or an errno. */
static int put_all(FILE *fp, const tsu_plot_buf *text, cli_writer_fn fn, void *ctx)
{
    int rc = 0;
    errno = 0;
    if (text && text->len && fwrite(text->data, 1, text->len, fp) != text->len)
        rc = errno ? errno : EIO;
    if (!rc && fn)
        rc = fn(ctx, fp);
    errno = 0;
    if (!rc && fflush(fp) != 0)
        rc = errno ? errno : EIO;
    if (!rc && ferror(fp))
        rc = EIO;
    return rc;
}

int cli_write_outputs(const char *out_path, const tsu_plot_buf *text, cli_writer_fn fn,
                      void *fn_ctx, const char *svg_path, const tsu_plot_buf *svg)
{
    char msg[TSU_IO_MSG_SIZE];
    cli_out os = {NULL, NULL}, oo = {NULL, NULL};
    const char *opath = out_path ? out_path : "-";
    int rc;

    /* 1. the plot into its temporary file */
    if (svg_path) {
        rc = cli_out_open(&os, svg_path, msg, sizeof msg);
        if (rc) {
            cli_error("%s", msg);
            return CLI_IO;
        }
        rc = put_all(cli_out_file(&os), svg, NULL, NULL);
        if (rc) {
            cli_error("cannot write \"%s\": %s", svg_path, strerror(rc));
            cli_out_abort(&os);
            return CLI_IO;
        }
    }
    /* 2. the main output (standard output is written directly) */
    rc = cli_out_open(&oo, opath, msg, sizeof msg);
    if (rc) {
        cli_error("%s", msg);
        cli_out_abort(&os);
        return CLI_IO;
    }
    rc = put_all(cli_out_file(&oo), text, fn, fn_ctx);
    if (rc) {
        cli_error("cannot write %s%s%s: %s", out_path ? "\"" : "",
                  out_path ? out_path : "standard output", out_path ? "\"" : "", strerror(rc));
        cli_out_abort(&oo);
        cli_out_abort(&os);
        return CLI_IO;
    }
    /* 3. both complete and flushed: rename into place */
    rc = cli_out_commit(&oo, msg, sizeof msg);
    if (rc) {
        cli_error("%s", msg);
        cli_out_abort(&os);
        return CLI_IO;
    }
    rc = cli_out_commit(&os, msg, sizeof msg);
    if (rc) {
        cli_error("%s", msg);
        return CLI_IO;
    }
    return CLI_OK;
}
