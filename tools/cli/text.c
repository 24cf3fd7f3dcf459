/* Text built in memory (tsu_plot_buf) with a sticky failure: once an append
 * fails, the text is incomplete, later appends do nothing, and the caller
 * reports "out of memory" instead of writing it (cli.h). */
#include "cli.h"

#include <stdarg.h>

void cli_text_puts(cli_text *w, const char *s)
{
    if (!w->bad && tsu_plot_buf_puts(w->b, s) != TSU_PLOT_OK)
        w->bad = 1;
}

void cli_text_printf(cli_text *w, const char *fmt, ...)
{
    if (w->bad)
        return;
    va_list ap;
    va_start(ap, fmt);
    if (tsu_plot_buf_vprintf(w->b, fmt, ap) != TSU_PLOT_OK)
        w->bad = 1;
    va_end(ap);
}
