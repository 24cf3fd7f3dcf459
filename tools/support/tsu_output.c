/* tsu_io output: files written through a temporary file renamed into place,
 * and the fast row writer (see tsu_io.h, 3. and 4.). */
#define _POSIX_C_SOURCE 200809L

#include "tsu_io_internal.h"

#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

/* ================================================================== */
/* Safe output files                                                    */
/* ================================================================== */

struct tsu_out {
    FILE *fp;
    char *path;
    char *tmp;
    unsigned flags;
    int is_std;
};

static void msg_set(char *buf, size_t len, const char *fmt, ...) IO_PRINTF(3, 4);

static void msg_set(char *buf, size_t len, const char *fmt, ...)
{
    va_list ap;
    if (!buf || !len)
        return;
    va_start(ap, fmt);
    vsnprintf(buf, len, fmt, ap);
    va_end(ap);
}

/* Temporary files open now, removed by the handler of SIGINT, SIGTERM,
 * SIGHUP and SIGQUIT (unlink is async-signal-safe), which then re-raises the
 * signal with its default action, so the exit status is still the signal's.
 * SIGXFSZ (a file size limit) is ignored instead, so that the write fails
 * with EFBIG and is reported like any other write error. */
#define OUT_SLOTS 16
#define OUT_NSIG 4
static char *volatile out_temps[OUT_SLOTS];
static volatile sig_atomic_t out_handlers_set;
static const int out_signals[OUT_NSIG] = {SIGINT, SIGTERM, SIGHUP, SIGQUIT};

static void out_on_signal(int sig)
{
    for (int k = 0; k < OUT_SLOTS; k++) {
        char *t = out_temps[k];
        if (t)
            (void)unlink(t);
    }
    (void)signal(sig, SIG_DFL);
    (void)raise(sig);
}

/* Standard output too: a redirected stdout has the same limit. */
static void out_ignore_xfsz(void)
{
    struct sigaction fsz;
    if (sigaction(SIGXFSZ, NULL, &fsz) == 0 && fsz.sa_handler == SIG_DFL) {
        fsz.sa_handler = SIG_IGN;
        (void)sigaction(SIGXFSZ, &fsz, NULL);
    }
}

static void out_register(char *tmp)
{
    if (!out_handlers_set) {
        out_handlers_set = 1;
        for (int k = 0; k < OUT_NSIG; k++) {
            struct sigaction old, sa;
            /* a signal the caller ignores stays ignored */
            if (sigaction(out_signals[k], NULL, &old) == 0 && old.sa_handler == SIG_IGN)
                continue;
            memset(&sa, 0, sizeof sa);
            sa.sa_handler = out_on_signal;
            sigemptyset(&sa.sa_mask);
            for (int j = 0; j < OUT_NSIG; j++)
                sigaddset(&sa.sa_mask, out_signals[j]);
            (void)sigaction(out_signals[k], &sa, NULL);
        }
    }
    for (int k = 0; k < OUT_SLOTS; k++)
        if (!out_temps[k]) {
            out_temps[k] = tmp;
            return;
        }
}

static void out_unregister(const char *tmp)
{
    for (int k = 0; tmp && k < OUT_SLOTS; k++)
        if (out_temps[k] == tmp)
            out_temps[k] = NULL;
}

static void out_free(tsu_out *o)
{
    out_unregister(o->tmp);
    free(o->path);
    free(o->tmp);
    free(o);
}

int tsu_out_open(tsu_out **out, const char *path, unsigned flags, char *errbuf, size_t errlen)
{
    tsu_out *o;
    size_t n;
    int fd, e;
    struct stat st;
    mode_t mode;
    msg_set(errbuf, errlen, "%s", "");
    if (out)
        *out = NULL;
    if (!out || !path || !*path) {
        msg_set(errbuf, errlen, "no output path");
        return EINVAL;
    }
    if (flags & ~TSU_OUT_FSYNC) {
        msg_set(errbuf, errlen, "invalid output flags");
        return EINVAL;
    }
    n = strlen(path);
    o = tsu_io__calloc(1, sizeof *o);
    if (!o || !(o->path = tsu_io__dup_str(path, n))) {
        free(o);
        msg_set(errbuf, errlen, "out of memory");
        return ENOMEM;
    }
    o->flags = flags;
    out_ignore_xfsz();
    if (strcmp(path, "-") == 0) {
        o->fp = stdout;
        o->is_std = 1;
        *out = o;
        return 0;
    }
    if (n > SIZE_MAX - 16 || !(o->tmp = tsu_io__malloc(n + 16))) {
        out_free(o);
        msg_set(errbuf, errlen, "out of memory");
        return ENOMEM;
    }
    memcpy(o->tmp, path, n);
    memcpy(o->tmp + n, ".tmp.XXXXXX", 12);
    {
        /* none of out_signals between creating the file and registering it
         * for the handler (a signal there left the temporary file behind) */
        sigset_t block, prev;
        sigemptyset(&block);
        for (int k = 0; k < OUT_NSIG; k++)
            sigaddset(&block, out_signals[k]);
        int masked = sigprocmask(SIG_BLOCK, &block, &prev) == 0;
        fd = mkstemp(o->tmp);
        if (fd >= 0)
            out_register(o->tmp);
        if (masked)
            (void)sigprocmask(SIG_SETMASK, &prev, NULL);
    }
    if (fd < 0) {
        e = errno;
        msg_set(errbuf, errlen, "cannot create temporary file for \"%s\": %s", path, strerror(e));
        out_free(o);
        return e;
    }
    if (stat(path, &st) == 0 && S_ISREG(st.st_mode)) {
        mode = st.st_mode & 0777;
    } else {
        mode_t um = umask(022);
        umask(um);
        mode = 0666 & ~um;
    }
    (void)fchmod(fd, mode); /* mkstemp's 0600 stays if this fails */
    o->fp = fdopen(fd, "w");
    if (!o->fp) {
        e = errno;
        close(fd);
        unlink(o->tmp);
        msg_set(errbuf, errlen, "cannot open \"%s\": %s", o->tmp, strerror(e));
        out_free(o);
        return e;
    }
    *out = o;
    return 0;
}

FILE *tsu_out_file(const tsu_out *o) { return o ? o->fp : NULL; }
const char *tsu_out_path(const tsu_out *o) { return o ? o->path : NULL; }
const char *tsu_out_temp(const tsu_out *o) { return o ? o->tmp : NULL; }

static void fsync_dir_of(const char *path)
{
    const char *slash = strrchr(path, '/');
    char *dir;
    int fd;
    if (!slash)
        dir = tsu_io__dup_str(".", 1);
    else
        dir = tsu_io__dup_str(path, slash == path ? 1 : (size_t)(slash - path));
    if (!dir)
        return;
    fd = open(dir, O_RDONLY);
    if (fd >= 0) {
        (void)fsync(fd); /* not supported everywhere; the data are already renamed */
        close(fd);
    }
    free(dir);
}

int tsu_out_commit(tsu_out *o, char *errbuf, size_t errlen)
{
    int e = 0;
    msg_set(errbuf, errlen, "%s", "");
    if (!o) {
        msg_set(errbuf, errlen, "no output");
        return EINVAL;
    }
    if (o->is_std) {
        errno = 0;
        if (fflush(stdout) != 0 || ferror(stdout)) {
            e = errno ? errno : EIO;
            msg_set(errbuf, errlen, "error writing to standard output: %s", strerror(e));
        }
        out_free(o);
        return e;
    }
    errno = 0;
    if (fflush(o->fp) != 0) /* also retries what an earlier failed write left */
        e = errno ? errno : EIO;
    if (!e && ferror(o->fp))
        e = EIO; /* an earlier write failed, cause unknown */
    if (!e && (o->flags & TSU_OUT_FSYNC) && fsync(fileno(o->fp)) != 0)
        e = errno ? errno : EIO;
    errno = 0;
    if (fclose(o->fp) != 0 && !e)
        e = errno ? errno : EIO;
    o->fp = NULL;
    if (e) {
        unlink(o->tmp);
        msg_set(errbuf, errlen, "error writing \"%s\": %s", o->path, strerror(e));
        out_free(o);
        return e;
    }
    if (rename(o->tmp, o->path) != 0) {
        e = errno;
        unlink(o->tmp);
        msg_set(errbuf, errlen, "cannot replace \"%s\": %s", o->path, strerror(e));
        out_free(o);
        return e;
    }
    if (o->flags & TSU_OUT_FSYNC)
        fsync_dir_of(o->path);
    out_free(o);
    return 0;
}

void tsu_out_abort(tsu_out *o)
{
    if (!o)
        return;
    if (o->is_std) {
        fflush(stdout);
    } else {
        if (o->fp)
            fclose(o->fp);
        unlink(o->tmp);
    }
    out_free(o);
}

/* ================================================================== */
/* Row writer                                                           */
/* ================================================================== */

#define WR_BUF 65536

struct tsu_writer {
    FILE *fp;
    int err;
    char delim;
    size_t len;
    char buf[WR_BUF];
};

tsu_writer *tsu_writer_new(FILE *fp, char delim)
{
    tsu_writer *w;
    if (!fp || !(delim == ',' || delim == '\t' || delim == ' ' || delim == ';'))
        return NULL;
    w = tsu_io__malloc(sizeof *w);
    if (!w)
        return NULL;
    w->fp = fp;
    w->err = 0;
    w->delim = delim;
    w->len = 0;
    return w;
}

static int wr_drain(tsu_writer *w)
{
    if (w->len && !w->err) {
        errno = 0;
        if (fwrite(w->buf, 1, w->len, w->fp) != w->len)
            w->err = errno ? errno : EIO;
    }
    w->len = 0;
    return w->err;
}

int tsu_writer_row(tsu_writer *w, const double *v, size_t n)
{
    size_t i;
    if (!w)
        return EINVAL;
    if (!v && n)
        return w->err ? w->err : (w->err = EINVAL);
    if (w->err)
        return w->err;
    for (i = 0; i < n; i++) {
        if (WR_BUF - w->len < TSU_FMT_SIZE + 2 && wr_drain(w))
            return w->err;
        if (i)
            w->buf[w->len++] = w->delim;
        w->len += tsu_format_double(v[i], w->buf + w->len);
    }
    if (w->len == WR_BUF && wr_drain(w))
        return w->err;
    w->buf[w->len++] = '\n';
    return w->err;
}

int tsu_writer_xy(tsu_writer *w, double x, double y)
{
    if (!w)
        return EINVAL;
    if (w->err)
        return w->err;
    if (WR_BUF - w->len < 2 * TSU_FMT_SIZE + 2 && wr_drain(w))
        return w->err;
    w->len += tsu_format_double(x, w->buf + w->len);
    w->buf[w->len++] = w->delim;
    w->len += tsu_format_double(y, w->buf + w->len);
    w->buf[w->len++] = '\n';
    return w->err;
}

int tsu_writer_text(tsu_writer *w, const char *s, size_t len)
{
    if (!w)
        return EINVAL;
    if (!s && len)
        return w->err ? w->err : (w->err = EINVAL);
    while (len > 0 && !w->err) {
        size_t k = WR_BUF - w->len < len ? WR_BUF - w->len : len;
        memcpy(w->buf + w->len, s, k);
        w->len += k;
        s += k;
        len -= k;
        if (w->len == WR_BUF)
            wr_drain(w);
    }
    return w->err;
}

int tsu_writer_flush(tsu_writer *w)
{
    if (!w)
        return EINVAL;
    if (wr_drain(w))
        return w->err;
    errno = 0;
    if (fflush(w->fp) != 0)
        w->err = errno ? errno : EIO;
    return w->err;
}

int tsu_writer_free(tsu_writer *w)
{
    int e;
    if (!w)
        return 0;
    e = tsu_writer_flush(w);
    free(w);
    return e;
}
