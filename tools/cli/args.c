/* Command-line parsing: argv after the command into cli_opts or
 * cli_surface_opts with the one option table (options.c), then the checks of
 * options that depend on each other (docs/cli.md). */
#define _POSIX_C_SOURCE 200809L
#include "cli.h"

#include <stdlib.h>
#include <string.h>

void cli_opts_free(cli_opts *o)
{
    if (!o)
        return;
    free(o->alphas);
    free(o->betas);
    free(o->at_list);
    free(o->xcol);
    free(o->ycol);
    cli_constraints_free(o);
    o->alphas = o->betas = NULL;
    o->at_list = NULL;
    o->xcol = o->ycol = NULL;
}

/* argv into o (a cli_opts or a cli_surface_opts) and *data (DATA, NULL if
 * none): CLI_OK, CLI_USAGE or CLI_HELP. */
static int parse_argv(cli_cmd cmd, int argc, char **argv, void *o, const char **data)
{
    int only_args = 0;
    for (int i = 0; i < argc; i++) {
        const char *a = argv[i];
        if (only_args || a[0] != '-' || strcmp(a, "-") == 0) {
            if (*data)
                return cli_usage(cmd, "more than one data file (\"%s\" and \"%s\")", *data, a);
            *data = a;
            continue;
        }
        if (strcmp(a, "--") == 0) {
            only_args = 1;
            continue;
        }
        const char *eq = strncmp(a, "--", 2) == 0 ? strchr(a, '=') : NULL;
        size_t nlen = eq ? (size_t)(eq - a) : strlen(a);
        const char *name;
        const cli_optdef *d = cli_optdef_find(1u << cmd, a, nlen, &name);
        if (!d) {
            if (cli_optdef_find(~0u, a, nlen, &name))
                return cli_usage(cmd, "option %s is not available for \"%s\"", name,
                                 cli_cmd_name(cmd));
            return cli_usage(cmd, "unknown option \"%.*s\"", (int)nlen, a);
        }
        const char *val = NULL;
        if (d->kind == CLI_K_HELP)
            return CLI_HELP;
        if (d->meta || d->kind == CLI_K_ENUM) {
            if (eq)
                val = eq + 1;
            else if (i + 1 < argc)
                val = argv[++i];
            else
                return cli_usage(cmd, "option %s needs a value", name);
        } else if (eq) {
            return cli_usage(cmd, "option %s takes no value", name);
        }
        int rc = cli_optdef_apply(d, cmd, name, val, o);
        if (rc != CLI_OK)
            return rc;
    }
    return CLI_OK;
}

int cli_surface_parse(int argc, char **argv, cli_surface_opts *o)
{
    cli_opts_defaults(CLI_SURFACE, o);
    int rc = parse_argv(CLI_SURFACE, argc, argv, o, &o->data);
    if (rc != CLI_OK)
        return rc;
    if (!o->data)
        return cli_usage(CLI_SURFACE, "missing DATA");
    if (o->out && o->svg && strcmp(o->out, "-") != 0 && cli_same_file(o->out, o->svg))
        return cli_usage(CLI_SURFACE, "-o and the plot name the same file (\"%s\"): the plot "
                                      "would replace the samples", o->svg);
    return cli_check_not_data(CLI_SURFACE, o->data, o->out, o->svg);
}

int cli_parse(cli_cmd cmd, int argc, char **argv, cli_opts *o)
{
    cli_opts_defaults(cmd, o);
    int rc = parse_argv(cmd, argc, argv, o, &o->data);
    if (rc != CLI_OK)
        return rc;
    if (!o->data)
        o->data = "-";
    if (o->decimal_comma && o->delim == ',')
        return cli_usage(cmd, "--decimal-comma needs another delimiter than ',' (--delimiter ';')");
    if (o->xcol && o->ycol && strcmp(o->xcol, o->ycol) == 0)
        return cli_usage(cmd, "--columns / --x / --y: X and Y must be different columns (both "
                              "\"%s\")", o->xcol);
    if (o->out && o->svg && strcmp(o->out, "-") != 0 && cli_same_file(o->out, o->svg))
        return cli_usage(cmd, "-o and the plot name the same file (\"%s\"): the plot would replace "
                              "the samples", o->svg);
    if ((rc = cli_check_not_data(cmd, o->data, o->out, o->svg)) != CLI_OK)
        return rc;
    if (o->svg) {
        /* the format: --format, else the extension, which must agree with it */
        const char *dot = strrchr(o->svg, '.'), *slash = strrchr(o->svg, '/');
        int ext = -1;
        if (dot && (!slash || dot > slash)) {
            if (strcmp(dot, ".svg") == 0 || strcmp(dot, ".SVG") == 0)
                ext = CLI_PLOT_SVG;
            else if (strcmp(dot, ".png") == 0 || strcmp(dot, ".PNG") == 0)
                ext = CLI_PLOT_PNG;
            else if (strcmp(dot, ".pdf") == 0 || strcmp(dot, ".PDF") == 0)
                ext = CLI_PLOT_PDF;
        }
        static const char *const fname[3] = {"svg", "png", "pdf"};
        if (o->format_set) {
            if (ext >= 0 && ext != (int)o->plot_format)
                return cli_usage(cmd, "--format %s contradicts the extension of \"%s\"",
                                 fname[o->plot_format], o->svg);
        } else if (ext < 0) {
            return cli_usage(cmd, "cannot tell the plot format of \"%s\": use a .svg, .png or "
                                  ".pdf name, or --format svg|png|pdf", o->svg);
        } else if (ext != (int)o->plot_format) {
            return cli_usage(cmd, "--%s \"%s\": the extension says %s (use --%s, or --format)",
                             fname[o->plot_format], o->svg, fname[ext], fname[ext]);
        }
    } else if (o->format_set || o->xlabel || o->ylabel || o->logy || o->width) {
        return cli_usage(cmd, "%s only applies to a plot (--svg, --png or --pdf FILE)",
                         o->format_set ? "--format" : o->xlabel ? "--xlabel"
                         : o->ylabel ? "--ylabel" : o->logy ? "--logy" : "--size");
    }
    if (o->with_samples && !o->json)
        return cli_usage(cmd, "--with-samples only applies with --json");
    if (o->grid_set + (o->at != NULL) + (o->samples_total != 0) > 1 ||
        (o->samples_set && o->samples_total))
        return cli_usage(cmd, "give one of --samples, --samples-total, --grid and --at");
    if (o->step_set && (o->at || o->samples_total || o->samples_set))
        return cli_usage(cmd, "--step: give one of --samples, --samples-total, --step and --at");
    if (o->step_set && o->grid_set && o->grid_n)
        return cli_usage(cmd, "--grid A:B:N and --step %s: give the count N or the step, not "
                              "both (--grid A:B --step %s)", o->step_text, o->step_text);
    if (o->grid_set && !o->grid_n && !o->step_set)
        return cli_usage(cmd, "--grid A:B needs --step S (or the count of points: --grid A:B:N)");

    if (o->c1) {
        if (o->form_set && o->form != TS_FORM_C1)
            return cli_usage(cmd, "--c1 contradicts --form %s", cli_form_name(o->form));
        o->form = TS_FORM_C1;
        o->form_set = 1;
    }
    return CLI_OK;
}
