/* Minimal test harness: counts checks, prints "NAME: N passed, M failed"
 * (tests/run_all.sh reads that last line).
 *
 *   CHECK(cond), CHECKF(cond, fmt, ...), CHECK_CLOSE(a, b, tol)
 *       one assertion each; a failure prints file:line, the current case and
 *       the condition (and the message / the values).
 *   TH_CASE("name")
 *       starts a named case: every later check belongs to it until the next
 *       TH_CASE.  Failures name it; th_report lists the cases that failed,
 *       and with TH_CASES=1 in the environment prints every case's counts.
 *   th_report(name)
 *       prints the totals; returns the exit status (0 if nothing failed).
 *   TH_PI, TH_HALF_PI, TH_NAN, TH_INF
 *       double constants (bare NAN / INFINITY are float: -Wdouble-promotion).
 *
 * Programs of tests/api/ are compiled with TH_PUBLIC_ONLY: there, the
 * library's internal header must not be reachable on the include path.
 */
#ifndef TS_TH_H
#define TS_TH_H
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#if defined(TH_PUBLIC_ONLY) && defined(__has_include)
#if __has_include("internal.h")
#error "a tests/api program sees src/internal.h: public header only (include/)"
#endif
#endif

#define TH_PI 3.14159265358979323846
#define TH_HALF_PI 1.57079632679489661923
#define TH_NAN ((double)NAN)
#define TH_INF ((double)INFINITY)

static long th_pass_, th_fail_;

/* 1 when long double arithmetic is wider than double at run time (x87:
 * 64-bit significand, 15-bit exponent); 0 where it is double, e.g. under
 * valgrind, which emulates x87 in 64-bit doubles.  Tests whose reference
 * needs the wider type take a reference that does not, or widen their
 * tolerance to the double reference's own rounding, when this is 0. */
static inline int th_long_double_wide(void)
{
    volatile long double one = 1.0L, tiny = 0x1p-60L, big = 0x1p1000L;
    return one + tiny != one && big * big > (long double)DBL_MAX;
}

/* ---- named cases --------------------------------------------------------- */
#define TH_MAX_CASES 64
typedef struct th_case_stat_ {
    const char *name;
    long pass, fail;
} th_case_stat_;
static th_case_stat_ th_cases_[TH_MAX_CASES];
static int th_ncases_;
static const char *th_case_; /* the current case (NULL before the first) */
static long th_case_pass0_, th_case_fail0_;

static inline void th_case_close_(void)
{
    if (th_case_ && th_ncases_ < TH_MAX_CASES) {
        th_cases_[th_ncases_].name = th_case_;
        th_cases_[th_ncases_].pass = th_pass_ - th_case_pass0_;
        th_cases_[th_ncases_].fail = th_fail_ - th_case_fail0_;
        th_ncases_++;
    }
    th_case_ = NULL;
}

static inline void th_case_begin_(const char *name)
{
    th_case_close_();
    th_case_ = name;
    th_case_pass0_ = th_pass_;
    th_case_fail0_ = th_fail_;
}
#define TH_CASE(name) th_case_begin_(name)

/* "file:line: FAIL [case]: " */
static inline void th_fail_at_(const char *file, int line)
{
    th_fail_++;
    if (th_case_)
        fprintf(stderr, "%s:%d: FAIL [%s]: ", file, line, th_case_);
    else
        fprintf(stderr, "%s:%d: FAIL: ", file, line);
}

/* ---- checks -------------------------------------------------------------- */
#define CHECK(cond)                                                            \
    do {                                                                       \
        if (cond) {                                                            \
            th_pass_++;                                                        \
        } else {                                                               \
            th_fail_at_(__FILE__, __LINE__);                                   \
            fprintf(stderr, "%s\n", #cond);                                    \
        }                                                                      \
    } while (0)

/* CHECKF(cond, fmt, ...): with a message on failure. */
#define CHECKF(cond, ...)                                                      \
    do {                                                                       \
        if (cond) {                                                            \
            th_pass_++;                                                        \
        } else {                                                               \
            th_fail_at_(__FILE__, __LINE__);                                   \
            fprintf(stderr, "%s: ", #cond);                                    \
            fprintf(stderr, __VA_ARGS__);                                      \
            fputc('\n', stderr);                                               \
        }                                                                      \
    } while (0)

/* |a - b| <= tol, NaN-safe (NaN fails). */
#define CHECK_CLOSE(a, b, tol)                                                 \
    do {                                                                       \
        double th_a_ = (a), th_b_ = (b), th_t_ = (tol);                        \
        CHECKF(fabs(th_a_ - th_b_) <= th_t_, "%s = %.17g, %s = %.17g, tol %.3g", \
               #a, th_a_, #b, th_b_, th_t_);                                   \
    } while (0)

static inline int th_report(const char *name)
{
    th_case_close_();
    const char *verbose = getenv("TH_CASES");
    int all = verbose && *verbose && *verbose != '0';
    for (int k = 0; k < th_ncases_; k++)
        if (all || th_cases_[k].fail)
            printf("  case %s: %ld passed, %ld failed\n", th_cases_[k].name, th_cases_[k].pass,
                   th_cases_[k].fail);
    printf("%s: %ld passed, %ld failed\n", name, th_pass_, th_fail_);
    return th_fail_ ? 1 : 0;
}
/* TH_ASAN: 1 in an AddressSanitizer build (gcc or clang), else 0, so the
 * slow random tests can run fewer cases there. */
#if defined(__SANITIZE_ADDRESS__)
#define TH_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define TH_ASAN 1
#endif
#endif
#ifndef TH_ASAN
#define TH_ASAN 0
#endif
#endif
