/* Outputs written only on success: temporary file + rename, or a device directly. */
#define _POSIX_C_SOURCE 200809L
#include "cli.h"

#include <sys/stat.h>
#include <sys/types.h>
#include <sys/wait.h>

#include <signal.h>
#include <stdlib.h>
#include <unistd.h>

#include <errno.h>
#include <stdio.h>
#include <string.h>

int cli_same_file(const char *a, const char *b)
{
    struct stat sa, sb;
    if (strcmp(a, b) == 0)
        return 1;
    return stat(a, &sa) == 0 && stat(b, &sb) == 0 && sa.st_dev == sb.st_dev &&
           sa.st_ino == sb.st_ino;
}

int cli_check_not_data(cli_cmd cmd, const char *data, const char *out, const char *svg)
{
    struct stat sd, so;
    if (!data || strcmp(data, "-") == 0 || stat(data, &sd) != 0 || !S_ISREG(sd.st_mode))
        return CLI_OK;
    const char *outs[2] = {out, svg}, *what[2] = {"-o", "the plot"};
    for (int k = 0; k < 2; k++)
        if (outs[k] && strcmp(outs[k], "-") != 0 && stat(outs[k], &so) == 0 &&
            so.st_dev == sd.st_dev && so.st_ino == sd.st_ino)
            return cli_usage(cmd, "%s names the input file \"%s\" (as \"%s\"): writing it would "
                                  "replace the data",
                             what[k], data, outs[k]);
    return CLI_OK;
}

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

/* Run the SVG converter: svg on its standard input, its output into fp.
 * 0, or -1 with the message printed. */
static int convert_svg(const tsu_plot_buf *svg, cli_plot_format fmt, FILE *fp, const char *path)
{
    const char *prog = getenv("TRIGSPLINE_SVG_CONVERTER");
    const char *fname = fmt == CLI_PLOT_PNG ? "png" : "pdf";
    int in[2], status = 0;
    if (!prog || !*prog)
        prog = "rsvg-convert";
    if (fflush(fp) != 0 || pipe(in) != 0) {
        cli_error("cannot write \"%s\": %s", path, strerror(errno));
        return -1;
    }
    pid_t pid = fork();
    if (pid < 0) {
        cli_error("cannot write \"%s\": %s", path, strerror(errno));
        close(in[0]);
        close(in[1]);
        return -1;
    }
    if (pid == 0) {
        char *argv[4];
        argv[0] = (char *)prog;
        argv[1] = (char *)"-f";
        argv[2] = (char *)fname;
        argv[3] = NULL;
        close(in[1]);
        if (dup2(in[0], 0) < 0 || dup2(fileno(fp), 1) < 0)
            _exit(126);
        close(in[0]);
        execvp(prog, argv);
        _exit(127);
    }
    close(in[0]);
    /* a converter that exits early must not kill us with SIGPIPE */
    struct sigaction sa, old;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = SIG_IGN;
    sigaction(SIGPIPE, &sa, &old);
    size_t off = 0;
    while (off < svg->len) {
        ssize_t w = write(in[1], svg->data + off, svg->len - off);
        if (w < 0 && errno == EINTR)
            continue;
        if (w <= 0)
            break;
        off += (size_t)w;
    }
    close(in[1]);
    sigaction(SIGPIPE, &old, NULL);
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR)
        ;
    if (WIFEXITED(status) && WEXITSTATUS(status) == 127) {
        cli_error("cannot write the %s plot \"%s\": the SVG converter \"%s\" was not found "
                  "(install the Debian package librsvg2-bin, or write --svg)", fname, path, prog);
        return -1;
    }
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || off < svg->len) {
        cli_error("cannot write the %s plot \"%s\": the SVG converter \"%s\" failed", fname,
                  path, prog);
        return -1;
    }
    /* the converter wrote through its own descriptor: move our stream to the end */
    if (fseek(fp, 0, SEEK_END) != 0 && errno != ESPIPE) {
        cli_error("cannot write \"%s\": %s", path, strerror(errno));
        return -1;
    }
    return 0;
}

int cli_write_outputs(const char *out_path, const tsu_plot_buf *text, cli_writer_fn fn,
                      void *fn_ctx, const char *svg_path, cli_plot_format fmt,
                      const tsu_plot_buf *svg)
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
        if (fmt != CLI_PLOT_SVG) {
            if (convert_svg(svg, fmt, cli_out_file(&os), svg_path) != 0) {
                cli_out_abort(&os);
                return CLI_IO;
            }
        } else if ((rc = put_all(cli_out_file(&os), svg, NULL, NULL)) != 0) {
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
        if (rc != ECANCELED)
            cli_error("cannot write %s%s%s: %s", out_path ? "\"" : "",
                      out_path ? out_path : "standard output", out_path ? "\"" : "",
                      strerror(rc));
        cli_out_abort(&oo);
        cli_out_abort(&os);
        return rc == ECANCELED ? CLI_DATA : CLI_IO;
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
