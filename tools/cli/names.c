/* Names of the commands, and of the enum values as written on the command
 * line, in messages and in JSON: the library's vocabulary (ts_vocab_name). */
#include "cli.h"

#define NELEM(a) (sizeof(a) / sizeof((a)[0]))

/* ---- the command's own ------------------------------------------------- */

const char *cli_cmd_name(cli_cmd c)
{
    static const char *const cmds[] = {"fit", "certify", "curve", "surface"};
    return (size_t)c < NELEM(cmds) ? cmds[c] : "?";
}

static const char *or_unknown(const char *s)
{
    return s ? s : "?";
}
const char *cli_shape_name(ts_shape s)
{
    return or_unknown(ts_vocab_name(TS_VOCAB_SHAPE, (int)s));
}
const char *cli_slopes_name(ts_slopes s)
{
    return or_unknown(ts_vocab_name(TS_VOCAB_SLOPES, (int)s));
}
const char *cli_form_name(ts_form f)
{
    return or_unknown(ts_vocab_name(TS_VOCAB_FORM, (int)f));
}
const char *cli_term_name(ts_term t)
{
    return or_unknown(ts_vocab_name(TS_VOCAB_TERM, (int)t));
}
const char *cli_param_name(ts_param p)
{
    return or_unknown(ts_vocab_name(TS_VOCAB_PARAM, (int)p));
}
const char *cli_extrap_name(ts_extrap e)
{
    return or_unknown(ts_vocab_name(TS_VOCAB_EXTRAP, (int)e));
}
