/* A JSON document built in memory: numbers shortest round-trip, NaN/Inf as null. */
#include "cli.h"

#include <math.h>
#include <stdio.h>

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

/* After a failed allocation nothing more is appended: the document is
 * already lost, and each retry would ask the allocator for the whole buffer
 * again. */
void cli_json_raw(cli_json *j, const char *s)
{
    if (!j->failed && tsu_plot_buf_puts(&j->b, s) != TSU_PLOT_OK)
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
        if (p > run && !j->failed &&
            tsu_plot_buf_append(&j->b, run, (size_t)(p - run)) != TSU_PLOT_OK)
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
