/* Messages on standard error and the number and line texts they use. */
#include "cli.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

static FILE *msg_stream; /* NULL: stderr */

void cli_set_messages(FILE *fp)
{
    msg_stream = fp;
}

FILE *cli_messages(void)
{
    return msg_stream ? msg_stream : stderr;
}

void cli_error(const char *fmt, ...)
{
    FILE *fp = cli_messages();
    va_list ap;
    fputs("trigspline: ", fp);
    va_start(ap, fmt);
    vfprintf(fp, fmt, ap);
    va_end(ap);
    fputc('\n', fp);
}

int cli_usage(cli_cmd cmd, const char *fmt, ...)
{
    FILE *fp = cli_messages();
    va_list ap;
    fprintf(fp, "trigspline %s: ", cli_cmd_name(cmd));
    va_start(ap, fmt);
    vfprintf(fp, fmt, ap);
    va_end(ap);
    fprintf(fp, "\nTry 'trigspline %s --help' for more information.\n", cli_cmd_name(cmd));
    return CLI_USAGE;
}

const char *cli_num_sig(double v, int sig, char buf[TSU_FMT_SIZE])
{
    if (!isfinite(v) || v == 0.0)
        return cli_num(v, buf);
    snprintf(buf, TSU_FMT_SIZE, "%.*g", sig < 1 ? 1 : sig > 17 ? 17 : sig, v);
    return buf;
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

int cli_report_io(const tsu_io_error *e)
{
    cli_error("%s", e->msg);
    switch (e->status) {
    case TSU_IO_ERR_OPEN:
    case TSU_IO_ERR_READ:
    case TSU_IO_ERR_NOMEM:
    case TSU_IO_ERR_OVERFLOW:
    case TSU_IO_ERR_NULL:
    case TSU_IO_ERR_OPTION:
        return CLI_IO;
    default:
        return CLI_DATA;
    }
}
