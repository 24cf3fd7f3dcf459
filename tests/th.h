/* Minimal test harness: counts checks, prints "NAME: N passed, M failed". */
#ifndef TS_TH_H
#define TS_TH_H
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

static long th_pass_, th_fail_;

#define CHECK(cond)                                                            \
    do {                                                                       \
        if (cond) {                                                            \
            th_pass_++;                                                        \
        } else {                                                               \
            th_fail_++;                                                        \
            fprintf(stderr, "%s:%d: FAIL: %s\n", __FILE__, __LINE__, #cond);   \
        }                                                                      \
    } while (0)

/* CHECKF(cond, fmt, ...): with a message on failure. */
#define CHECKF(cond, ...)                                                      \
    do {                                                                       \
        if (cond) {                                                            \
            th_pass_++;                                                        \
        } else {                                                               \
            th_fail_++;                                                        \
            fprintf(stderr, "%s:%d: FAIL: %s: ", __FILE__, __LINE__, #cond);   \
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
    printf("%s: %ld passed, %ld failed\n", name, th_pass_, th_fail_);
    return th_fail_ ? 1 : 0;
}
#endif
