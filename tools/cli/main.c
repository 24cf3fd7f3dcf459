/* trigspline — command-line tool (interface: docs/cli.md,
 * manual: docs/trigspline.1). */
#include "cli.h"

#include <stdio.h>
#include <string.h>

int main(int argc, char **argv)
{
    if (argc < 2) {
        fprintf(stderr, "Usage: trigspline fit|certify|curve [DATA] [OPTIONS]\n"
                        "Try 'trigspline --help' for more information.\n");
        return CLI_USAGE;
    }
    const char *c = argv[1];
    if (strcmp(c, "--help") == 0 || strcmp(c, "-h") == 0 || strcmp(c, "help") == 0) {
        cli_print_main_help();
        return fflush(stdout) == 0 ? CLI_OK : CLI_IO;
    }
    if (strcmp(c, "--version") == 0) {
        printf("trigspline %s\n", ts_version());
        return fflush(stdout) == 0 ? CLI_OK : CLI_IO;
    }
    if (strcmp(c, "surface") == 0)
        return cli_surface(argc - 2, argv + 2);
    if (strcmp(c, "disaggregate") == 0)
        return cli_disaggregate(argc - 2, argv + 2);
    cli_cmd cmd;
    if (strcmp(c, "fit") == 0)
        cmd = CLI_FIT;
    else if (strcmp(c, "certify") == 0)
        cmd = CLI_CERTIFY;
    else if (strcmp(c, "curve") == 0)
        cmd = CLI_CURVE;
    else {
        fprintf(stderr, "trigspline: unknown command \"%s\" (expected fit, certify or curve)\n"
                        "Try 'trigspline --help' for more information.\n",
                c);
        return CLI_USAGE;
    }
    cli_opts o;
    int rc = cli_parse(cmd, argc - 2, argv + 2, &o);
    if (rc == CLI_HELP) {
        cli_opts_free(&o);
        cli_print_help(cmd);
        return fflush(stdout) == 0 ? CLI_OK : CLI_IO;
    }
    if (rc == CLI_OK) {
        if (cmd == CLI_FIT)
            rc = cli_fit(&o);
        else if (cmd == CLI_CERTIFY)
            rc = cli_certify(&o);
        else
            rc = cli_curve(&o);
    }
    cli_opts_free(&o);
    return rc;
}
