/* Names of the enum values as written on the command line, in messages and in
 * JSON, and of the commands.  The canonical names are the library's
 * vocabulary (ts_vocab_name / ts_vocab_value); until the library has them
 * these tables stand in for it: cli_vocab_name, cli_vocab_value and
 * cli_vocab_count are the only functions that read them, so that their
 * bodies become the library calls in one place. */
#include "cli.h"

#include <string.h>

/* Index = the enum value. */
static const char *const shape_names[] = {"none", "positive", "above", "below", "between",
                                          "monotone"};
static const char *const slopes_names[] = {"arithmetic", "geometric", "harmonic",
                                           "fritsch-carlson", "akima", "makima",
                                           "user", "periodic", "steffen"};
static const char *const form_names[] = {"paper", "c1", "geometric"};
static const char *const term_names[] = {"user", "margin", "lower-left", "lower-right",
                                         "upper-left", "upper-right", "monotone", "certify",
                                         "geometric"};
static const char *const param_names[] = {"centripetal", "chord", "uniform"};
static const char *const extrap_names[] = {"error", "clamp", "extend", "linear"};
static const char *const surface_shape_names[] = {"none", "positive", "bounds", "planes",
                                                  "range"};
static const char *const where_names[] = {"none", "point", "interval", "query"};

#define NELEM(a) (sizeof(a) / sizeof((a)[0]))

static const struct {
    const char *const *name;
    int n;
} vocab[CLI_VOCAB_COUNT_] = {
    [CLI_VOCAB_FORM] = {form_names, (int)NELEM(form_names)},
    [CLI_VOCAB_SLOPES] = {slopes_names, (int)NELEM(slopes_names)},
    [CLI_VOCAB_SHAPE] = {shape_names, (int)NELEM(shape_names)},
    [CLI_VOCAB_EXTRAP] = {extrap_names, (int)NELEM(extrap_names)},
    [CLI_VOCAB_PARAM] = {param_names, (int)NELEM(param_names)},
    [CLI_VOCAB_SURFACE_SHAPE] = {surface_shape_names, (int)NELEM(surface_shape_names)},
    [CLI_VOCAB_TERM] = {term_names, (int)NELEM(term_names)},
    [CLI_VOCAB_WHERE] = {where_names, (int)NELEM(where_names)},
};

/* ---- the shim: ts_vocab_name, ts_vocab_value, ts_vocab_count ------------ */

const char *cli_vocab_name(cli_vocab kind, int value)
{
    if (!((unsigned)kind < CLI_VOCAB_COUNT_) || !(0 <= value && value < vocab[kind].n))
        return NULL;
    return vocab[kind].name[value];
}

ts_status cli_vocab_value(cli_vocab kind, const char *name, int *value)
{
    if (!name || !value)
        return TS_ERR_NULL;
    if ((unsigned)kind < CLI_VOCAB_COUNT_)
        for (int i = 0; i < vocab[kind].n; i++)
            if (strcmp(name, vocab[kind].name[i]) == 0) {
                *value = i;
                return TS_OK;
            }
    return TS_ERR_OPTION;
}

int cli_vocab_count(cli_vocab kind)
{
    return (unsigned)kind < CLI_VOCAB_COUNT_ ? vocab[kind].n : 0;
}

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
    return or_unknown(cli_vocab_name(CLI_VOCAB_SHAPE, (int)s));
}
const char *cli_slopes_name(ts_slopes s)
{
    return or_unknown(cli_vocab_name(CLI_VOCAB_SLOPES, (int)s));
}
const char *cli_form_name(ts_form f)
{
    return or_unknown(cli_vocab_name(CLI_VOCAB_FORM, (int)f));
}
const char *cli_term_name(ts_term t)
{
    return or_unknown(cli_vocab_name(CLI_VOCAB_TERM, (int)t));
}
const char *cli_param_name(ts_param p)
{
    return or_unknown(cli_vocab_name(CLI_VOCAB_PARAM, (int)p));
}
const char *cli_extrap_name(ts_extrap e)
{
    return or_unknown(cli_vocab_name(CLI_VOCAB_EXTRAP, (int)e));
}
