/* make bench: speed and memory of libtrigspline against GSL (issue 6).
 *
 * Every measurement runs in its own child process (fork), so its peak RSS
 * (wait4 rusage) belongs to that workload alone: inputs + structure + output.
 * Times are medians of several repetitions (CLOCK_MONOTONIC).  The table goes
 * to stdout and, with --out FILE, to a Markdown file with the machine, date
 * and compiler.  No assertion depends on a time.
 *
 * usage: bench [--out FILE] [--cli PATH] [--quick] [--no-eval] [--no-build] [--no-small]
 * (the --no-* options skip parts, for development)
 */
#define _DEFAULT_SOURCE
#include "trigspline.h"

#include <errno.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_interp.h>
#include <gsl/gsl_version.h>
#include <math.h>
#include <signal.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/time.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

/* internal entry of src/fast.c: run the batch with a chosen kernel
 * (0 portable C, 1 AVX2+FMA, 2 AVX-512F); 0 if not available here */
int ts__fast_batch_isa(const ts_spline *sp, int deriv, const double *xq, size_t m,
                       double *yq, ts_cursor *cur, int isa);

static int quick, skip_eval, skip_build, skip_small;

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

static double median(double *v, int k)
{
    qsort(v, (size_t)k, sizeof *v, cmp_double);
    return k % 2 ? v[k / 2] : 0.5 * (v[k / 2 - 1] + v[k / 2]);
}

/* ---- data ----------------------------------------------------------- */

static uint64_t rng = 0x9E3779B97F4A7C15u;
static double urand(void)
{
    rng ^= rng << 13;
    rng ^= rng >> 7;
    rng ^= rng << 17;
    return (double)(rng >> 11) * 0x1p-53;
}

typedef struct data {
    size_t np;           /* points */
    double *x, *f, *d;   /* d: slopes for the Hermite loop (our arithmetic mean) */
    size_t m;
    double *q, *y;
} data;

/* Non-uniform knots (steps in [0.5, 1.5)), positive values with structure
 * on two scales plus noise; queries sorted (evenly spaced) or random. */
static void make_data(data *D, size_t np, size_t m, int random_q)
{
    rng = 0x9E3779B97F4A7C15u;
    D->np = np;
    D->x = malloc(np * sizeof(double));
    D->f = malloc(np * sizeof(double));
    D->d = malloc(np * sizeof(double));
    D->m = m;
    D->q = m ? malloc(m * sizeof(double)) : NULL;
    D->y = m ? malloc(m * sizeof(double)) : NULL;
    if (!D->x || !D->f || !D->d || (m && (!D->q || !D->y))) {
        fprintf(stderr, "bench: out of memory\n");
        _exit(3);
    }
    D->x[0] = 0.0;
    for (size_t i = 1; i < np; i++)
        D->x[i] = D->x[i - 1] + 0.5 + urand();
    for (size_t i = 0; i < np; i++)
        D->f[i] = 1.5 + sin(0.001 * D->x[i]) + 0.3 * sin(0.37 * D->x[i]) + 0.2 * urand();
    if (ts_slopes_compute(TS_SLOPES_ARITHMETIC, D->x, D->f, np, D->d, NULL) != TS_OK) {
        fprintf(stderr, "bench: ts_slopes_compute failed\n");
        _exit(3);
    }
    double x0 = D->x[0], xn = D->x[np - 1];
    for (size_t j = 0; j < m; j++)
        D->q[j] = random_q ? x0 + (xn - x0) * urand() : x0 + (xn - x0) * ((double)j / (double)(m - 1));
    if (m)
        memset(D->y, 0, m * sizeof(double));
}

/* ---- implementations --------------------------------------------------- */

enum impl {
    I_TS_BATCH,   /* ts_eval_batch, best kernel */
    I_TS_PORT,    /* ts_eval_batch path with the portable C kernel */
    I_TS_AVX2,    /* ... AVX2+FMA kernel */
    I_TS_D1,      /* ts_eval_batch, first derivative */
    I_TS_D2,      /* second derivative */
    I_TS_MT,      /* ts_eval_batch_mt, 2 threads */
    I_TS_EVAL,    /* ts_eval point by point with a cursor */
    I_GSL_STEFFEN,
    I_GSL_CSPLINE,
    I_HERMITE,    /* plain C cubic Hermite loop */
    I_COUNT
};

static const char *impl_name[I_COUNT] = {
    "trigspline ts_eval_batch",
    "  portable C kernel (no SIMD dispatch)",
    "  AVX2+FMA kernel",
    "trigspline ts_eval_batch, S'",
    "trigspline ts_eval_batch, S''",
    "trigspline ts_eval_batch_mt, 2 threads",
    "trigspline ts_eval, one call per point",
    "GSL steffen (gsl_interp_eval)",
    "GSL cspline (gsl_interp_eval)",
    "plain C cubic Hermite loop",
};

/* Hermite loop: the straightforward code a user would write. */
static void hermite(const data *D)
{
    const double *x = D->x, *f = D->f, *d = D->d;
    size_t n = D->np - 1, i = 0;
    for (size_t j = 0; j < D->m; j++) {
        double xx = D->q[j];
        if (!(x[i] <= xx && (xx < x[i + 1] || i + 1 == n))) {
            if (i + 1 < n && x[i + 1] <= xx && xx < x[i + 2]) {
                i++;
            } else { /* binary search */
                size_t lo = 0, hi = n;
                while (hi - lo > 1) {
                    size_t mid = (lo + hi) / 2;
                    if (x[mid] <= xx)
                        lo = mid;
                    else
                        hi = mid;
                }
                i = lo;
            }
        }
        double h = x[i + 1] - x[i], t = (xx - x[i]) / h, t2 = t * t, t3 = t2 * t;
        D->y[j] = (2 * t3 - 3 * t2 + 1) * f[i] + (t3 - 2 * t2 + t) * h * d[i] +
                  (3 * t2 - 2 * t3) * f[i + 1] + (t3 - t2) * h * d[i + 1];
    }
}

static ts_spline *build_ts(const data *D, int shape, int certify)
{
    ts_options o;
    ts_options_init(&o);
    if (shape) {
        o.shape = TS_SHAPE_POSITIVE;
        o.certify = certify;
    }
    ts_spline *s = NULL;
    ts_error e;
    ts_status st = ts_spline_new(D->x, D->f, D->np, &o, &s, &e);
    if (st != TS_OK) {
        fprintf(stderr, "bench: ts_spline_new: %s (index %zu)\n", ts_strerror(st), e.index);
        return NULL;
    }
    return s;
}

/* One evaluation workload in the current process: fills t[0..reps). */
static int run_eval(int impl, size_t np, size_t m, int random_q, double *t, int reps)
{
    data D;
    make_data(&D, np, m, random_q);
    ts_spline *s = NULL;
    gsl_interp *gi = NULL;
    gsl_interp_accel *acc = NULL;
    if (impl == I_GSL_STEFFEN || impl == I_GSL_CSPLINE) {
        gi = gsl_interp_alloc(impl == I_GSL_STEFFEN ? gsl_interp_steffen : gsl_interp_cspline, np);
        acc = gsl_interp_accel_alloc();
        if (!gi || !acc || gsl_interp_init(gi, D.x, D.f, np))
            return -1;
    } else if (impl != I_HERMITE) {
        s = build_ts(&D, 0, 0);
        if (!s)
            return -1;
    }
    for (int r = 0; r < reps; r++) {
        double t0 = now();
        switch (impl) {
        case I_TS_BATCH:
        case I_TS_D1:
        case I_TS_D2: {
            int deriv = impl == I_TS_D1 ? 1 : impl == I_TS_D2 ? 2 : 0;
            if (ts_eval_batch(s, deriv, D.q, m, D.y, NULL, NULL) != TS_OK)
                return -1;
            break;
        }
        case I_TS_PORT:
        case I_TS_AVX2: {
            ts_cursor c = TS_CURSOR_INIT;
            if (!ts__fast_batch_isa(s, 0, D.q, m, D.y, &c, impl == I_TS_PORT ? 0 : 1))
                return 1; /* kernel not available on this machine */
            break;
        }
        case I_TS_MT:
            if (ts_eval_batch_mt(s, 0, D.q, m, D.y, 2, NULL) != TS_OK)
                return -1;
            break;
        case I_TS_EVAL: {
            ts_cursor c = TS_CURSOR_INIT;
            for (size_t j = 0; j < m; j++)
                ts_eval(s, D.q[j], &c, &D.y[j]);
            break;
        }
        case I_GSL_STEFFEN:
        case I_GSL_CSPLINE:
            for (size_t j = 0; j < m; j++)
                D.y[j] = gsl_interp_eval(gi, D.x, D.f, D.q[j], acc);
            break;
        case I_HERMITE:
            hermite(&D);
            break;
        }
        t[r] = (now() - t0) * 1e9 / (double)m;
    }
    /* keep the results alive */
    volatile double sink = D.y[m / 2];
    (void)sink;
    ts_spline_free(s);
    if (gi)
        gsl_interp_free(gi);
    if (acc)
        gsl_interp_accel_free(acc);
    return 0;
}

enum cimpl { C_TS_NONE, C_TS_POS, C_TS_POS_CERT, C_GSL_STEFFEN, C_GSL_STEFFEN_INIT, C_GSL_CSPLINE, C_COUNT };
static const char *cimpl_name[C_COUNT] = {
    "trigspline ts_spline_new, no shape",
    "trigspline ts_spline_new, positive, certify = 0",
    "trigspline ts_spline_new, positive, certify = 1",
    "GSL steffen alloc + init + free",
    "GSL steffen init only (state allocated once)",
    "GSL cspline alloc + init + free",
};

/* Construction: ns per knot, inner repetitions for small n. */
static int run_build(int impl, size_t np, double *t, int reps)
{
    data D;
    make_data(&D, np, 0, 0);
    size_t inner = np < 100000 ? 2000000 / np : 1;
    gsl_interp *keep = NULL;
    if (impl == C_GSL_STEFFEN_INIT) {
        keep = gsl_interp_alloc(gsl_interp_steffen, np);
        if (!keep || gsl_interp_init(keep, D.x, D.f, np))
            return -1;
    }
    for (int r = 0; r < reps; r++) {
        double t0 = now();
        for (size_t k = 0; k < inner; k++) {
            switch (impl) {
            case C_TS_NONE:
            case C_TS_POS:
            case C_TS_POS_CERT: {
                ts_spline *s = build_ts(&D, impl != C_TS_NONE, impl == C_TS_POS_CERT);
                if (!s)
                    return -1;
                ts_spline_free(s);
                break;
            }
            case C_GSL_STEFFEN:
            case C_GSL_CSPLINE: {
                gsl_interp *g =
                    gsl_interp_alloc(impl == C_GSL_STEFFEN ? gsl_interp_steffen : gsl_interp_cspline, np);
                if (!g || gsl_interp_init(g, D.x, D.f, np))
                    return -1;
                gsl_interp_free(g);
                break;
            }
            case C_GSL_STEFFEN_INIT:
                if (gsl_interp_init(keep, D.x, D.f, np))
                    return -1;
                break;
            }
        }
        t[r] = (now() - t0) * 1e9 / ((double)np * (double)inner);
    }
    if (keep)
        gsl_interp_free(keep);
    return 0;
}

/* ---- child processes ------------------------------------------------- */

typedef struct result {
    int status;          /* 0 ok, 1 not available, -1 failed */
    double med, min;     /* ns per point / knot */
    double rss_mib;      /* peak RSS of the child */
} result;

/* Runs fn in a child; the child writes its times through a pipe. */
static result in_child(int kind, int impl, size_t np, size_t m, int random_q, int reps)
{
    result R = {-1, NAN, NAN, NAN};
    int fd[2];
    if (pipe(fd))
        return R;
    fflush(stdout);
    pid_t pid = fork();
    if (pid < 0)
        return R;
    if (pid == 0) {
        close(fd[0]);
        double t[16];
        int st = kind == 0 ? run_eval(impl, np, m, random_q, t, reps) : run_build(impl, np, t, reps);
        double msg[18];
        msg[0] = st;
        msg[1] = reps;
        for (int r = 0; r < reps; r++)
            msg[2 + r] = t[r];
        ssize_t w = write(fd[1], msg, sizeof msg);
        _exit(w == (ssize_t)sizeof msg ? 0 : 2);
    }
    close(fd[1]);
    double msg[18];
    size_t got = 0;
    while (got < sizeof msg) {
        ssize_t k = read(fd[0], (char *)msg + got, sizeof msg - got);
        if (k <= 0) {
            if (k < 0 && errno == EINTR)
                continue;
            break;
        }
        got += (size_t)k;
    }
    close(fd[0]);
    int wst;
    struct rusage ru;
    if (wait4(pid, &wst, 0, &ru) < 0 || got != sizeof msg || !WIFEXITED(wst) || WEXITSTATUS(wst))
        return R;
    R.status = (int)msg[0];
    R.rss_mib = (double)ru.ru_maxrss / 1024.0;
    if (R.status == 0) {
        int k = (int)msg[1];
        double v[16];
        double mn = INFINITY;
        for (int r = 0; r < k; r++) {
            v[r] = msg[2 + r];
            mn = v[r] < mn ? v[r] : mn;
        }
        R.min = mn;
        R.med = median(v, k);
    }
    return R;
}

/* ---- CLI streaming -------------------------------------------------- */

/* Writes rows "x,f\n" (x = 0, 1, 2, ..., f > 0) to fd; fast integer formatting. */
static void generate_rows(int fd, size_t rows)
{
    static char buf[1 << 16];
    size_t len = 0;
    for (size_t i = 0; i < rows; i++) {
        char tmp[32];
        int k = 0;
        size_t v = i;
        do {
            tmp[k++] = (char)('0' + v % 10);
            v /= 10;
        } while (v);
        if (len + 40 > sizeof buf) {
            if (write(fd, buf, len) != (ssize_t)len)
                _exit(1);
            len = 0;
        }
        while (k)
            buf[len++] = tmp[--k];
        unsigned frac = (unsigned)((i * 7919u) % 1000u);
        buf[len++] = ',';
        buf[len++] = '1';
        buf[len++] = '.';
        buf[len++] = (char)('0' + frac / 100);
        buf[len++] = (char)('0' + frac / 10 % 10);
        buf[len++] = (char)('0' + frac % 10);
        buf[len++] = '\n';
    }
    if (len && write(fd, buf, len) != (ssize_t)len)
        _exit(1);
}

typedef struct cli_result {
    int ok;
    double seconds, rows_per_s, rss_mib;
    int exit_code;
} cli_result;

static cli_result run_cli(const char *cli, size_t rows)
{
    cli_result R = {0, NAN, NAN, NAN, -1};
    int fd[2];
    if (pipe(fd))
        return R;
    fflush(stdout);
    double t0 = now();
    pid_t gen = fork();
    if (gen == 0) {
        close(fd[0]);
        signal(SIGPIPE, SIG_DFL);
        generate_rows(fd[1], rows);
        _exit(0);
    }
    pid_t pid = fork();
    if (pid == 0) {
        close(fd[1]);
        dup2(fd[0], 0);
        close(fd[0]);
        FILE *dn = fopen("/dev/null", "w");
        if (dn)
            dup2(fileno(dn), 1);
        execl(cli, cli, "fit", "--shape", "positive", "--samples", "2", (char *)NULL);
        _exit(127);
    }
    close(fd[0]);
    close(fd[1]);
    int wst;
    struct rusage ru;
    if (pid < 0 || wait4(pid, &wst, 0, &ru) < 0) {
        if (gen > 0)
            waitpid(gen, NULL, 0);
        return R;
    }
    double t1 = now();
    if (gen > 0)
        waitpid(gen, NULL, 0);
    R.exit_code = WIFEXITED(wst) ? WEXITSTATUS(wst) : -1;
    R.ok = R.exit_code == 0;
    R.seconds = t1 - t0;
    R.rows_per_s = (double)rows / R.seconds;
    R.rss_mib = (double)ru.ru_maxrss / 1024.0;
    return R;
}

/* ---- output --------------------------------------------------------- */

static FILE *md;

static void out(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vprintf(fmt, ap);
    va_end(ap);
    if (md) {
        va_start(ap, fmt);
        vfprintf(md, fmt, ap);
        va_end(ap);
    }
    fflush(stdout);
}

static void cpu_model(char *buf, size_t len)
{
    snprintf(buf, len, "unknown");
    FILE *f = fopen("/proc/cpuinfo", "r");
    if (!f)
        return;
    char line[512];
    while (fgets(line, sizeof line, f)) {
        if (!strncmp(line, "model name", 10)) {
            char *c = strchr(line, ':');
            if (c) {
                c++;
                while (*c == ' ')
                    c++;
                c[strcspn(c, "\n")] = 0;
                snprintf(buf, len, "%s", c);
            }
            break;
        }
    }
    fclose(f);
}

static const char *fmt_ratio(char *buf, double a, double b)
{
    if (!(a > 0) || !(b > 0))
        return "–";
    snprintf(buf, 16, "%.2f", a / b);
    return buf;
}

typedef struct goal {
    const char *what;
    double value, limit;
} goal;
static goal goals[16];
static int ngoals;

static void add_goal(const char *what, double value, double limit)
{
    if (ngoals < 16)
        goals[ngoals++] = (goal){what, value, limit};
}

int main(int argc, char **argv)
{
    const char *outpath = NULL, *cli = NULL;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--out") && i + 1 < argc)
            outpath = argv[++i];
        else if (!strcmp(argv[i], "--cli") && i + 1 < argc)
            cli = argv[++i];
        else if (!strcmp(argv[i], "--quick"))
            quick = 1;
        else if (!strcmp(argv[i], "--no-eval"))
            skip_eval = 1;
        else if (!strcmp(argv[i], "--no-build"))
            skip_build = 1;
        else if (!strcmp(argv[i], "--no-small"))
            skip_small = 1;
        else {
            fprintf(stderr, "usage: bench [--out FILE] [--cli PATH] [--quick] [--no-eval] [--no-build] "
                            "[--no-small]\n");
            return 1;
        }
    }
    gsl_set_error_handler_off();
    if (outpath) {
        md = fopen(outpath, "w");
        if (!md) {
            fprintf(stderr, "bench: cannot write %s\n", outpath);
            return 5;
        }
    }
    double wall0 = now();
    char cpu[256], date[64];
    cpu_model(cpu, sizeof cpu);
    time_t tt = time(NULL);
    strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", gmtime(&tt));
    long ncpu = sysconf(_SC_NPROCESSORS_ONLN);
    out("# trigspline benchmark (make bench)\n\n");
    out("- CPU: %s, %ld online cores\n- date: %s\n- compiler: gcc %s (library: CMake Release, "
        "src/fast.c -O3 -ffp-contract=fast; bench.c -O2)\n",
        cpu, ncpu, date, __VERSION__);
    out("- GSL: %s\n", GSL_VERSION);
    out("- times: median of the repetitions (min in brackets), each workload in its own process; "
        "RSS = peak resident memory of that process (inputs + structure + output)\n\n");

    const size_t sizes[2] = {1001, 1000001};
    const size_t M = quick ? 1000000 : 10000000;

    /* ---- evaluation ---- */
    out("## Evaluation, paper form (no shape), %zu queries\n\n", M);
    out("| knots | queries | implementation | ns/point | peak RSS MiB | × GSL steffen | × GSL cspline | × Hermite loop |\n");
    out("|---:|---|---|---:|---:|---:|---:|---:|\n");
    double steffen_sorted_1e6 = NAN, steffen_random_1e6 = NAN, herm_sorted_1e6 = NAN;
    double ts_sorted_1e6 = NAN, ts_random_1e6 = NAN, mt_sorted = NAN, mt_random = NAN;
    double one_sorted = NAN, one_random = NAN;
    for (int si = skip_small; si < 2 && !skip_eval; si++) {
        for (int rq = 0; rq < 2; rq++) {
            result R[I_COUNT];
            for (int im = 0; im < I_COUNT; im++) {
                int slow = rq && si == 1 &&
                           (im == I_GSL_STEFFEN || im == I_GSL_CSPLINE || im == I_TS_EVAL || im == I_HERMITE);
                int reps = quick ? 3 : slow ? 3 : 7;
                R[im] = in_child(0, im, sizes[si], M, rq, reps);
            }
            for (int im = 0; im < I_COUNT; im++) {
                char a[16], b[16], c[16];
                if (R[im].status == 1)
                    continue; /* kernel not on this CPU */
                if (R[im].status != 0) {
                    out("| %zu | %s | %s | failed | | | | |\n", sizes[si] - 1, rq ? "random" : "sorted",
                        impl_name[im]);
                    continue;
                }
                out("| %zu | %s | %s | %.2f (%.2f) | %.0f | %s | %s | %s |\n", sizes[si] - 1,
                    rq ? "random" : "sorted", impl_name[im], R[im].med, R[im].min, R[im].rss_mib,
                    fmt_ratio(a, R[im].med, R[I_GSL_STEFFEN].med), fmt_ratio(b, R[im].med, R[I_GSL_CSPLINE].med),
                    fmt_ratio(c, R[im].med, R[I_HERMITE].med));
            }
            if (si == 1) {
                if (!rq) {
                    steffen_sorted_1e6 = R[I_GSL_STEFFEN].med;
                    herm_sorted_1e6 = R[I_HERMITE].med;
                    ts_sorted_1e6 = R[I_TS_BATCH].med;
                    mt_sorted = R[I_TS_MT].med;
                    one_sorted = R[I_TS_BATCH].med;
                } else {
                    steffen_random_1e6 = R[I_GSL_STEFFEN].med;
                    ts_random_1e6 = R[I_TS_BATCH].med;
                    mt_random = R[I_TS_MT].med;
                    one_random = R[I_TS_BATCH].med;
                }
            }
        }
    }
    add_goal("sorted queries, n = 1e6: ts_eval_batch / GSL steffen <= 0.5", ts_sorted_1e6 / steffen_sorted_1e6, 0.5);
    add_goal("sorted queries, n = 1e6: ts_eval_batch / Hermite loop <= 1.5", ts_sorted_1e6 / herm_sorted_1e6, 1.5);
    add_goal("random queries, n = 1e6: ts_eval_batch / GSL steffen <= 0.5", ts_random_1e6 / steffen_random_1e6, 0.5);
    out("\nts_eval_batch_mt on 2 threads, n = 1e6: speed-up %.2f× (sorted), %.2f× (random) over one thread.\n\n",
        one_sorted / mt_sorted, one_random / mt_random);

    /* ---- construction ---- */
    out("## Construction\n\n");
    out("| knots | implementation | ns/knot | peak RSS MiB | × GSL steffen alloc+init | × GSL steffen init only |\n");
    out("|---:|---|---:|---:|---:|---:|\n");
    double c_pos = NAN, c_cert = NAN, c_st = NAN, c_sti = NAN;
    for (int si = skip_small; si < 2 && !skip_build; si++) {
        result R[C_COUNT];
        for (int im = 0; im < C_COUNT; im++)
            R[im] = in_child(1, im, sizes[si], 0, 0, quick ? 3 : 7);
        for (int im = 0; im < C_COUNT; im++) {
            char a[16], b[16];
            if (R[im].status != 0) {
                out("| %zu | %s | failed (see stderr) | | | |\n", sizes[si] - 1, cimpl_name[im]);
                continue;
            }
            out("| %zu | %s | %.2f (%.2f) | %.0f | %s | %s |\n", sizes[si] - 1, cimpl_name[im], R[im].med,
                R[im].min, R[im].rss_mib, fmt_ratio(a, R[im].med, R[C_GSL_STEFFEN].med),
                fmt_ratio(b, R[im].med, R[C_GSL_STEFFEN_INIT].med));
        }
        if (si == 1) {
            c_pos = R[C_TS_POS].status == 0 ? R[C_TS_POS].med : NAN;
            c_cert = R[C_TS_POS_CERT].status == 0 ? R[C_TS_POS_CERT].med : NAN;
            c_st = R[C_GSL_STEFFEN].med;
            c_sti = R[C_GSL_STEFFEN_INIT].med;
        }
    }
    add_goal("construct positive, n = 1e6: / GSL steffen alloc+init <= 1.0", c_pos / c_st, 1.0);
    add_goal("construct positive + certificates, n = 1e6: / GSL steffen alloc+init <= 3.0", c_cert / c_st, 3.0);
    add_goal("(stricter) construct positive, n = 1e6: / GSL steffen init only <= 1.0", c_pos / c_sti, 1.0);
    add_goal("(stricter) construct positive + certificates: / GSL steffen init only <= 3.0", c_cert / c_sti, 3.0);

    /* ---- CLI ---- */
    out("\n## CLI streaming: generated rows piped through `trigspline fit --shape positive --samples 2` > /dev/null\n\n");
    if (!cli || access(cli, X_OK)) {
        out("skipped: no CLI at %s (not built yet)\n", cli ? cli : "(none given)");
    } else {
        size_t rows = quick ? 1000000 : 10000000;
        cli_result C = run_cli(cli, rows);
        if (C.ok && !quick && C.seconds < 12.0) {
            cli_result C8 = run_cli(cli, 100000000);
            if (C8.ok) {
                out("| rows | seconds | rows/s | peak RSS MiB |\n|---:|---:|---:|---:|\n");
                out("| %zu | %.2f | %.3g | %.1f |\n", rows, C.seconds, C.rows_per_s, C.rss_mib);
                rows = 100000000;
                C = C8;
            }
        } else {
            out("| rows | seconds | rows/s | peak RSS MiB |\n|---:|---:|---:|---:|\n");
        }
        if (C.ok) {
            out("| %zu | %.2f | %.3g | %.1f |\n", rows, C.seconds, C.rows_per_s, C.rss_mib);
            add_goal("CLI streaming peak RSS MiB <= 16", C.rss_mib, 16.0);
        } else {
            out("CLI failed (exit status %d) on `%s fit --shape positive --samples 2`\n", C.exit_code, cli);
        }
    }

    out("\n## Goals of issue 6\n\n| goal | measured | holds |\n|---|---:|---|\n");
    for (int g = 0; g < ngoals; g++)
        out("| %s | %.2f | %s |\n", goals[g].what, goals[g].value,
            isnan(goals[g].value) ? "not measured" : goals[g].value <= goals[g].limit ? "yes" : "**no**");
    out("\nwhole run: %.0f s\n", now() - wall0);
    if (md)
        fclose(md);
    return 0;
}
