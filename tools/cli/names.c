/* Names of the enum values as written on the command line, in messages and in
 * JSON (shape, slopes, form, term, param, extrapolate), and of the commands.
 * The library has no name functions (yet), so the tables live here. */
#include "cli.h"

#include <string.h>

/* Index = the enum value. */
static const char *const shape_names[] = {"none", "positive", "above", "below", "between",
                                          "monotone"};
static const char *const slopes_names[] = {"arithmetic", "geometric", "harmonic",
                                           "fritsch-carlson", "akima", "makima",
                                           "user", "periodic"};
static const char *const form_names[] = {"paper", "c1", "geometric"};
static const char *const term_names[] = {"user", "margin", "lower-left", "lower-right",
                                         "upper-left", "upper-right", "monotone", "certify",
                                         "geometric"};
static const char *const param_names[] = {"centripetal", "chord", "uniform"};
static const char *const extrap_names[] = {"error", "clamp", "extend", "linear"};

#define NELEM(a) (sizeof(a) / sizeof((a)[0]))

const cli_names cli_shape_names = {shape_names, NELEM(shape_names)};
const cli_names cli_slopes_names = {slopes_names, NELEM(slopes_names)};
const cli_names cli_form_names = {form_names, NELEM(form_names)};
const cli_names cli_param_names = {param_names, NELEM(param_names)};
const cli_names cli_extrap_names = {extrap_names, NELEM(extrap_names)};

const char *cli_cmd_name(cli_cmd c)
{
    return c == CLI_FIT ? "fit" : c == CLI_CERTIFY ? "certify" : "curve";
}
const char *cli_shape_name(ts_shape s)
{
    return (size_t)s < NELEM(shape_names) ? shape_names[s] : "?";
}
const char *cli_slopes_name(ts_slopes s)
{
    return (size_t)s < NELEM(slopes_names) ? slopes_names[s] : "?";
}
const char *cli_form_name(ts_form f)
{
    return (size_t)f < NELEM(form_names) ? form_names[f] : "?";
}
const char *cli_term_name(ts_term t)
{
    return (size_t)t < NELEM(term_names) ? term_names[t] : "?";
}
const char *cli_param_name(ts_param p)
{
    return (size_t)p < NELEM(param_names) ? param_names[p] : "?";
}
const char *cli_extrap_name(ts_extrap e)
{
    return (size_t)e < NELEM(extrap_names) ? extrap_names[e] : "?";
}

int cli_name_index(const cli_names *t, const char *s)
{
    for (size_t i = 0; i < t->n; i++)
        if (strcmp(s, t->name[i]) == 0)
            return (int)i;
    return -1;
}
