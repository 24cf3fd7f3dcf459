/* tsu_io: numbers, table reader, safe output, row writer (see tsu_io.h).
 * Tool side only (trigspline_support), not part of libtrigspline. */
#define _POSIX_C_SOURCE 200809L

#include "tsu_io.h"

#include <errno.h>
#include <fcntl.h>
#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

#if defined(__GNUC__)
#define IO_PRINTF(a, b) __attribute__((format(printf, a, b)))
#else
#define IO_PRINTF(a, b)
#endif

/* ================================================================== */
/* Integer helpers                                                      */
/* ================================================================== */

#if defined(__SIZEOF_INT128__) && !defined(TSU_IO_NO_INT128)
__extension__ typedef unsigned __int128 io_u128;
static void mul64(uint64_t a, uint64_t b, uint64_t *hi, uint64_t *lo)
{
    io_u128 p = (io_u128)a * b;
    *hi = (uint64_t)(p >> 64);
    *lo = (uint64_t)p;
}
#else
static void mul64(uint64_t a, uint64_t b, uint64_t *hi, uint64_t *lo)
{
    uint64_t a0 = a & 0xffffffffu, a1 = a >> 32, b0 = b & 0xffffffffu, b1 = b >> 32;
    uint64_t p00 = a0 * b0, p01 = a0 * b1, p10 = a1 * b0, p11 = a1 * b1;
    uint64_t mid = (p00 >> 32) + (p01 & 0xffffffffu) + (p10 & 0xffffffffu);
    *lo = (mid << 32) | (p00 & 0xffffffffu);
    *hi = p11 + (p01 >> 32) + (p10 >> 32) + (mid >> 32);
}
#endif

static int clz64(uint64_t x) /* x != 0 */
{
#if defined(__GNUC__)
    return __builtin_clzll(x);
#else
    int n = 0;
    if (!(x >> 32)) { n += 32; x <<= 32; }
    if (!(x >> 48)) { n += 16; x <<= 16; }
    if (!(x >> 56)) { n += 8; x <<= 8; }
    if (!(x >> 60)) { n += 4; x <<= 4; }
    if (!(x >> 62)) { n += 2; x <<= 2; }
    if (!(x >> 63)) { n += 1; }
    return n;
#endif
}

static int floor_div(int a, int b) /* b > 0 */
{
    int q = a / b;
    return (a % b != 0 && a < 0) ? q - 1 : q;
}

static const uint64_t POW5[27] = {
    1u, 5u, 25u, 125u, 625u, 3125u, 15625u, 78125u, 390625u, 1953125u, 9765625u,
    48828125u, 244140625u, 1220703125u, 6103515625u, 30517578125u, 152587890625u,
    762939453125u, 3814697265625u, 19073486328125u, 95367431640625u, 476837158203125u,
    2384185791015625u, 11920928955078125u, 59604644775390625u, 298023223876953125u,
    1490116119384765625u};

static const uint64_t POW10U[20] = {
    1u, 10u, 100u, 1000u, 10000u, 100000u, 1000000u, 10000000u, 100000000u,
    1000000000u, 10000000000u, 100000000000u, 1000000000000u, 10000000000000u,
    100000000000000u, 1000000000000000u, 10000000000000000u, 100000000000000000u,
    1000000000000000000u, 10000000000000000000u};

/* ================================================================== */
/* Powers of ten: 10^k ≈ P·2^s, 2^127 <= P < 2^128                      */
/* ================================================================== */

/* 10^(27a) = T·2^s truncated, a = -13..12; printed by tools/support/tsu_io_gen_pow10.py
 * (exact rational arithmetic).  Checked exactly by tests/tools/test_io.c. */
static const struct p10e {
    uint64_t hi, lo;
    int s, exact;
} P10T[26] = {
    {0x8049a4ac0c5811aeu, 0x205b896d777d6278u, -1293, 0}, /* 10^-351 */
    {0xcf42894a5dce35eau, 0x52064cac828675b9u, -1204, 0}, /* 10^-324 */
    {0xa76c582338ed2621u, 0xaf2af2b80af6f24eu, -1114, 0}, /* 10^-297 */
    {0x873e4f75e2224e68u, 0x5a7744a6e804a291u, -1024, 0}, /* 10^-270 */
    {0xda7f5bf590966848u, 0xaf39a475506a899eu, -935, 0},  /* 10^-243 */
    {0xb080392cc4349decu, 0xbd8d794d96aacfb3u, -845, 0},  /* 10^-216 */
    {0x8e938662882af53eu, 0x547eb47b7282ee9cu, -755, 0},  /* 10^-189 */
    {0xe65829b3046b0afau, 0x0cb4a5a3112a5112u, -666, 0},  /* 10^-162 */
    {0xba121a4650e4ddebu, 0x92f34d62616ce413u, -576, 0},  /* 10^-135 */
    {0x964e858c91ba2655u, 0x3a6a07f8d510f86fu, -486, 0},  /* 10^-108 */
    {0xf2d56790ab41c2a2u, 0xfae27299423fb9c3u, -397, 0},  /* 10^-81 */
    {0xc428d05aa4751e4cu, 0xaa97e14c3c26b886u, -307, 0},  /* 10^-54 */
    {0x9e74d1b791e07e48u, 0x775ea264cf55347du, -217, 0},  /* 10^-27 */
    {0x8000000000000000u, 0x0000000000000000u, -127, 1},  /* 10^0 */
    {0xcecb8f27f4200f3au, 0x0000000000000000u, -38, 1},   /* 10^27 */
    {0xa70c3c40a64e6c51u, 0x999090b65f67d924u, 52, 1},    /* 10^54 */
    {0x86f0ac99b4e8dafdu, 0x69a028bb3ded71a3u, 142, 0},   /* 10^81 */
    {0xda01ee641a708de9u, 0xe80e6f4820cc9495u, 231, 0},   /* 10^108 */
    {0xb01ae745b101e9e4u, 0x5ec05dcff72e7f8fu, 321, 0},   /* 10^135 */
    {0x8e41ade9fbebc27du, 0x14588f13be847307u, 411, 0},   /* 10^162 */
    {0xe5d3ef282a242e81u, 0x8f1668c8a86da5fau, 500, 0},   /* 10^189 */
    {0xb9a74a0637ce2ee1u, 0x6d953e2bd7173692u, 590, 0},   /* 10^216 */
    {0x95f83d0a1fb69cd9u, 0x4abdaf101564f98eu, 680, 0},   /* 10^243 */
    {0xf24a01a73cf2dccfu, 0xbc633b39673c8cecu, 769, 0},   /* 10^270 */
    {0xc3b8358109e84f07u, 0x0a862f80ec4700c8u, 859, 0},   /* 10^297 */
    {0x9e19db92b4e31ba9u, 0x6c07a2c26a8346d1u, 949, 0},   /* 10^324 */
};

int tsu_io__pow10_entry(int a, unsigned long long *hi, unsigned long long *lo, int *s, int *exact)
{
    if (!(-13 <= a && a <= 12) || !hi || !lo || !s || !exact)
        return -1;
    *hi = P10T[a + 13].hi;
    *lo = P10T[a + 13].lo;
    *s = P10T[a + 13].s;
    *exact = P10T[a + 13].exact;
    return 0;
}

/* -351 <= k <= 350.  P <= 10^k·2^-s < P + 3 (P = T·5^b truncated, T < true T + 1,
 * the product shifted right by r >= bitlen(5^b) - 1 bits); *exact when equal. */
static void pow10_approx(int k, uint64_t *phi, uint64_t *plo, int *s, int *exact)
{
    int a = floor_div(k, 27), b = k - 27 * a, sh;
    const struct p10e *t = &P10T[a + 13];
    uint64_t f = POW5[b], h1, l1, h2, l2, r0, r1, r2;
    if (b == 0) {
        *phi = t->hi;
        *plo = t->lo;
        *s = t->s;
        *exact = t->exact;
        return;
    }
    mul64(t->lo, f, &h1, &l1);
    mul64(t->hi, f, &h2, &l2);
    r0 = l1;
    r1 = l2 + h1;
    r2 = h2 + (r1 < h1);
    sh = 64 - clz64(r2); /* 1..61: T·5^b < 2^189 */
    *phi = (r2 << (64 - sh)) | (r1 >> sh);
    *plo = (r1 << (64 - sh)) | (r0 >> sh);
    *s = t->s + b + sh;
    *exact = t->exact && (r0 & ((UINT64_C(1) << sh) - 1)) == 0;
}

/* ================================================================== */
/* Exact comparison  w·10^e10  vs  M·2^Q  (small big-integer)           */
/* ================================================================== */

#define BN_LIMBS 48 /* 1536 bits; |e10| <= 400 needs < 1000 */

typedef struct bignum {
    uint32_t d[BN_LIMBS];
    int n;
} bignum;

static void bn_set(bignum *a, uint64_t v)
{
    a->d[0] = (uint32_t)v;
    a->d[1] = (uint32_t)(v >> 32);
    a->n = (v >> 32) ? 2 : (v ? 1 : 0);
}

static void bn_mul32(bignum *a, uint32_t m)
{
    uint64_t carry = 0;
    int i;
    for (i = 0; i < a->n; i++) {
        uint64_t t = (uint64_t)a->d[i] * m + carry;
        a->d[i] = (uint32_t)t;
        carry = t >> 32;
    }
    if (carry && a->n < BN_LIMBS)
        a->d[a->n++] = (uint32_t)carry;
}

static void bn_mul_pow5(bignum *a, int k)
{
    for (; k >= 13; k -= 13)
        bn_mul32(a, 1220703125u);
    if (k > 0)
        bn_mul32(a, (uint32_t)POW5[k]);
}

static int bn_bitlen(const bignum *a)
{
    if (a->n == 0)
        return 0;
    return 32 * a->n - clz64((uint64_t)a->d[a->n - 1]) + 32;
}

static void bn_shl(bignum *a, int bits)
{
    int w = bits >> 5, b = bits & 31, i;
    if (a->n == 0 || a->n + w + 1 > BN_LIMBS)
        return; /* not reached: callers shift to at most ~1000 bits */
    if (b == 0) {
        for (i = a->n - 1; i >= 0; i--)
            a->d[i + w] = a->d[i];
    } else {
        a->d[a->n + w] = a->d[a->n - 1] >> (32 - b);
        for (i = a->n - 1; i > 0; i--)
            a->d[i + w] = (a->d[i] << b) | (a->d[i - 1] >> (32 - b));
        a->d[w] = a->d[0] << b;
    }
    for (i = 0; i < w; i++)
        a->d[i] = 0;
    a->n += w + (b != 0);
    while (a->n > 0 && a->d[a->n - 1] == 0)
        a->n--;
}

static int bn_cmp(const bignum *a, const bignum *b)
{
    int i;
    if (a->n != b->n)
        return a->n < b->n ? -1 : 1;
    for (i = a->n - 1; i >= 0; i--)
        if (a->d[i] != b->d[i])
            return a->d[i] < b->d[i] ? -1 : 1;
    return 0;
}

/* sign(w·10^e10 - M·2^Q), exactly.  Callers keep |e10| <= 400. */
static int cmp_dec_bin(uint64_t w, int e10, uint64_t M, int Q)
{
    bignum a, b;
    int a2 = e10, b2 = Q, la, lb;
    bn_set(&a, w);
    bn_set(&b, M);
    if (e10 >= 0)
        bn_mul_pow5(&a, e10 > 400 ? 400 : e10);
    else
        bn_mul_pow5(&b, e10 < -400 ? 400 : -e10);
    if (a.n == 0 || b.n == 0)
        return (a.n != 0) - (b.n != 0);
    la = bn_bitlen(&a) + a2;
    lb = bn_bitlen(&b) + b2;
    if (la != lb)
        return la < lb ? -1 : 1;
    if (a2 > b2)
        bn_shl(&a, a2 - b2);
    else if (b2 > a2)
        bn_shl(&b, b2 - a2);
    return bn_cmp(&a, &b);
}

/* ================================================================== */
/* Decimal -> double                                                    */
/* ================================================================== */

static const double P10D[23] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

static double bits_to_double(uint64_t u)
{
    double d;
    memcpy(&d, &u, sizeof d);
    return d;
}

static uint64_t double_to_bits(double d)
{
    uint64_t u;
    memcpy(&u, &d, sizeof u);
    return u;
}

/* Is the 128-bit tail (th·2^64 + tl) at least 'lim' (< 2^64) below the
 * half (hh·2^64)?  Assumes tail < half. */
static int below_by(uint64_t th, uint64_t tl, uint64_t hh, uint64_t hl, uint64_t lim)
{
    uint64_t gh = hh - th - (hl < tl), gl = hl - tl;
    return gh != 0 || gl >= lim;
}

/* Nearest double to w·10^e10 (w > 0, -343 <= e10 <= 309).  0, or 1 if it
 * rounds to infinity. */
static int dec_to_double(uint64_t w, int e10, double *out)
{
    uint64_t phi, plo, W, h1, l1, h2, l2, z0, z1, z2, mant, th, tl, hh, bits;
    int s, exact, exactU, lz, L, E, b, dh, up;
#if defined(FLT_EVAL_METHOD) && FLT_EVAL_METHOD == 0
    /* Clinger: w and 10^|e10| exact doubles, one correctly rounded operation */
    if (w <= (UINT64_C(1) << 53)) {
        if (0 <= e10 && e10 <= 22) {
            *out = (double)w * P10D[e10];
            return 0;
        }
        if (-22 <= e10 && e10 < 0) {
            *out = (double)w / P10D[-e10];
            return 0;
        }
        if (22 < e10 && e10 <= 22 + 15 && w <= (UINT64_C(1) << 53) / POW10U[e10 - 22]) {
            *out = (double)(w * POW10U[e10 - 22]) * 1e22;
            return 0;
        }
    }
#endif
    pow10_approx(e10, &phi, &plo, &s, &exact);
    lz = clz64(w);
    W = w << lz;
    mul64(W, plo, &h1, &l1);
    mul64(W, phi, &h2, &l2);
    z0 = l1;
    z1 = l2 + h1;
    z2 = h2 + (z1 < h1);
    /* value = U·2^(64+s-lz), U = z2:z1, true U in [U, U + 4) (P error < 3W < 3·2^64,
     * plus the dropped z0); exact when P is and z0 == 0 */
    exactU = exact && z0 == 0;
    L = (z2 >> 63) ? 128 : 127;
    E = L - 1 + 64 - lz + s; /* 2^E <= value */
    if (E > 1023)
        return 1;
    b = E >= -1022 ? 53 : E + 1075; /* significant bits kept */
    if (b < 0) {
        if (b == -1) { /* value near 2^-1075, half the smallest subnormal */
            *out = cmp_dec_bin(w, e10, 1, -1075) > 0 ? bits_to_double(1) : 0.0;
            return 0;
        }
        *out = 0.0;
        return 0;
    }
    dh = L - b - 64; /* tail bits in z2: 10..64 */
    mant = dh == 64 ? 0 : z2 >> dh;
    th = dh == 64 ? z2 : z2 & ((UINT64_C(1) << dh) - 1);
    tl = z1;
    hh = UINT64_C(1) << (dh - 1);
    if (th > hh || (th == hh && tl != 0))
        up = 1;
    else if (th == hh)
        up = exactU ? (int)(mant & 1) : -1;
    else
        up = (exactU || below_by(th, tl, hh, 0, 4)) ? 0 : -1;
    if (up < 0) { /* the bound cannot decide: compare with the halfway point */
        int c = cmp_dec_bin(w, e10, 2 * mant + 1, E - b);
        up = c > 0 || (c == 0 && (mant & 1));
    }
    mant += (uint64_t)up;
    if (b == 53) { /* the hidden bit (and a carry to 2^53) adds to the exponent */
        if (E + 1022 + (int)(mant >> 53) >= 2046)
            return 1;
        bits = ((uint64_t)(E + 1022) << 52) + mant;
    } else {
        bits = mant; /* subnormal, or 2^52 = the smallest normal */
    }
    *out = bits_to_double(bits);
    return 0;
}

static size_t match_word(const char *p, const char *end, const char *w)
{
    size_t n = 0;
    while (w[n]) {
        if (p + n >= end || (p[n] | 0x20) != w[n])
            return 0;
        n++;
    }
    return n;
}

#define IS_DIGIT(c) ((unsigned)((unsigned char)(c) - '0') < 10u)

/* If p[0..7] are all decimal digits, *v = their value (8 at once: bytes of a
 * 64-bit word, pairs, quads, then the 8-digit number; no lane can carry). */
static int eight_digits(const char *p, uint64_t *v)
{
    uint64_t x = 0;
    int i;
    for (i = 7; i >= 0; i--) /* p[0] in the lowest byte, any byte order */
        x = (x << 8) | (unsigned char)p[i];
    if (((x & UINT64_C(0xF0F0F0F0F0F0F0F0)) |
         (((x + UINT64_C(0x0606060606060606)) & UINT64_C(0xF0F0F0F0F0F0F0F0)) >> 4)) !=
        UINT64_C(0x3333333333333333))
        return 0;
    x -= UINT64_C(0x3030303030303030);
    x = (x * 10 + (x >> 8)) & UINT64_C(0x00FF00FF00FF00FF);
    x = (x * 100 + (x >> 16)) & UINT64_C(0x0000FFFF0000FFFF);
    x = (x * 10000 + (x >> 32)) & UINT64_C(0xFFFFFFFF);
    *v = x;
    return 1;
}

/* Correct rounding through the C library for > 19 digits whose 19-digit
 * truncation t and t+1 round differently: digits and exponent are rewritten
 * as "DDDD...e±N" (no decimal point: locale free).  800 digits are kept, the
 * rest become one sticky digit: a halfway point has at most 768. */
static int strtod_fallback(const char *m, const char *mend, long expv, double *out)
{
    char buf[840];
    size_t k = 0;
    long frac = 0, dropped = 0;
    int seen_point = 0, sticky = 0;
    const char *p;
    for (p = m; p < mend; p++) {
        if (*p == '.') {
            seen_point = 1;
            continue;
        }
        if (seen_point)
            frac++;
        if (k == 0 && *p == '0')
            continue;
        if (k < 800)
            buf[k++] = *p;
        else {
            dropped++;
            sticky |= *p != '0';
        }
    }
    if (sticky) {
        buf[k++] = '1';
        dropped--;
    }
    snprintf(buf + k, sizeof buf - k, "e%ld", expv - frac + dropped);
    errno = 0;
    *out = strtod(buf, NULL);
    return isinf(*out) ? 1 : 0;
}

tsu_num_status tsu_parse_double(const char *s, const char *end, double *out, const char **stop)
{
    const char *p = s, *mstart;
    int neg = 0, any = 0, nd = 0, trunc = 0, r;
    uint64_t w = 0, w8;
    long e10 = 0, expv = 0, x10;
    double v = 0.0, dummy;
    if (!out)
        out = &dummy;
    *out = 0.0;
    if (!s) {
        if (stop)
            *stop = s;
        return TSU_NUM_SYNTAX;
    }
    if (!end)
        end = s + strlen(s);
    if (p < end && (*p == '-' || *p == '+')) {
        neg = *p == '-';
        p++;
    }
    if (p < end && ((*p | 0x20) == 'n' || (*p | 0x20) == 'i')) {
        size_t n = match_word(p, end, "infinity");
        if (!n)
            n = match_word(p, end, "inf");
        if (n) {
            *out = neg ? -HUGE_VAL : HUGE_VAL;
        } else if ((n = match_word(p, end, "nan")) != 0) {
            *out = neg ? -(double)NAN : (double)NAN;
        } else {
            if (stop)
                *stop = p;
            return TSU_NUM_SYNTAX;
        }
        if (stop)
            *stop = p + n;
        return TSU_NUM_NONFINITE;
    }
    mstart = p;
    while (p < end && *p == '0') {
        p++;
        any = 1;
    }
    while (nd <= 11 && end - p >= 8 && eight_digits(p, &w8)) {
        w = w * 100000000u + w8;
        nd += 8;
        p += 8;
        any = 1;
    }
    while (p < end && IS_DIGIT(*p)) {
        unsigned d = (unsigned)(*p - '0');
        if (nd < 19) {
            w = w * 10 + d;
            nd++;
        } else {
            e10++;
            trunc |= d != 0;
        }
        p++;
        any = 1;
    }
    if (p < end && *p == '.') {
        p++;
        if (nd == 0)
            while (p < end && *p == '0') {
                p++;
                e10--;
                any = 1;
            }
        while (nd <= 11 && end - p >= 8 && eight_digits(p, &w8)) {
            w = w * 100000000u + w8;
            nd += 8;
            e10 -= 8;
            p += 8;
            any = 1;
        }
        while (p < end && IS_DIGIT(*p)) {
            unsigned d = (unsigned)(*p - '0');
            if (nd < 19) {
                w = w * 10 + d;
                nd++;
                e10--;
            } else {
                trunc |= d != 0;
            }
            p++;
            any = 1;
        }
    }
    if (!any) {
        if (stop)
            *stop = p;
        return TSU_NUM_SYNTAX;
    }
    {
        const char *mend = p;
        if (p < end && (*p == 'e' || *p == 'E')) {
            const char *q = p + 1;
            int eneg = 0;
            if (q < end && (*q == '+' || *q == '-')) {
                eneg = *q == '-';
                q++;
            }
            if (q < end && IS_DIGIT(*q)) {
                while (q < end && IS_DIGIT(*q)) {
                    if (expv < 100000000L)
                        expv = expv * 10 + (*q - '0');
                    q++;
                }
                if (eneg)
                    expv = -expv;
                e10 += expv;
                p = q;
            }
        }
        if (stop)
            *stop = p;
        if (w == 0) {
            *out = neg ? -0.0 : 0.0;
            return TSU_NUM_OK;
        }
        x10 = e10 + nd - 1; /* 10^x10 <= value < 10^(x10+1) */
        if (x10 > 309) {
            *out = neg ? -HUGE_VAL : HUGE_VAL;
            return TSU_NUM_RANGE;
        }
        if (x10 < -325) { /* below 1e-325 < 2^-1075: rounds to zero */
            *out = neg ? -0.0 : 0.0;
            return TSU_NUM_OK;
        }
        r = dec_to_double(w, (int)e10, &v);
        if (trunc && r == 0) {
            double v2;
            int r2 = dec_to_double(w + 1, (int)e10, &v2);
            if (r2 != 0 || double_to_bits(v2) != double_to_bits(v))
                r = strtod_fallback(mstart, mend, expv, &v);
        }
    }
    if (r) {
        *out = neg ? -HUGE_VAL : HUGE_VAL;
        return TSU_NUM_RANGE;
    }
    *out = neg ? -v : v;
    return TSU_NUM_OK;
}

/* ================================================================== */
/* Double -> shortest decimal                                           */
/* ================================================================== */

/* (n·P) >> r as 128 bits (r in 1..127, result < 2^128); *lost = nonzero bits dropped. */
static void mulshift(uint64_t n, uint64_t phi, uint64_t plo, int r, uint64_t *hi, uint64_t *lo,
                     int *lost)
{
    uint64_t h1, l1, h2, l2, z0, z1, z2;
    mul64(n, plo, &h1, &l1);
    mul64(n, phi, &h2, &l2);
    z0 = l1;
    z1 = l2 + h1;
    z2 = h2 + (z1 < h1);
    if (r < 64) {
        *hi = (z2 << (64 - r)) | (z1 >> r);
        *lo = (z1 << (64 - r)) | (z0 >> r);
        *lost = (z0 << (64 - r)) != 0;
    } else if (r == 64) {
        *hi = z2;
        *lo = z1;
        *lost = z0 != 0;
    } else {
        *hi = z2 >> (r - 64);
        *lo = (z2 << (128 - r)) | (z1 >> (r - 64));
        *lost = (z0 | (z1 << (128 - r))) != 0;
    }
}

/* v = bits > 0 finite.  *digits·10^*e10 is the shortest decimal inside the
 * rounding interval of v, the nearest to v among those.
 *
 * With v = m·2^q, the interval is [(4m - dl)·2^(q-2), (4m + 2)·2^(q-2)], closed
 * iff m is even (round-half-even), dl = 1 at a power of two, else 2.  All
 * three points are scaled by 10^k so that v·10^k is in [1e16, 1e18) (then the
 * interval is wider than 1.1 and holds an integer), as 64.64 fixed point X
 * with the true value in [X, X + 2) units of 2^-64 (P error < 3·n/2^r < 3/8,
 * plus truncation), or exact.  A = least admissible integer, B = largest;
 * the answer is the multiple c·10^j in [A, B] with the largest j (fewest
 * digits), c nearest to v·10^k / 10^j.  Every decision the error bound
 * leaves open is settled by cmp_dec_bin. */
static void shortest(uint64_t bits, uint64_t *digits, int *e10)
{
    uint64_t f = bits & ((UINT64_C(1) << 52) - 1), m, dl, phi, plo;
    uint64_t il, fl, iv, fv, ih, fh, A, B, c, cmin, cmax, bq, aq, vr;
    int be = (int)(bits >> 52), q, closed, e2, k, s, exact, r, lostL, lostV, lostH;
    int exL, exV, exH, j = 0, up, lz0 = 1, lz9 = 1;
    unsigned ld = 0;
    if (be == 0) {
        m = f;
        q = -1074;
    } else {
        m = f | (UINT64_C(1) << 52);
        q = be - 1075;
    }
    closed = (m & 1) == 0;
    dl = (f == 0 && be > 1) ? 1 : 2;
    e2 = q + 63 - clz64(m);                  /* 2^e2 <= v < 2^(e2+1) */
    k = 16 - floor_div(e2 * 78913, 1 << 18); /* floor(e2·log10 2), exact for |e2| < 1700 */
    pow10_approx(k, &phi, &plo, &s, &exact);
    r = -(s + q + 62); /* 64.64 fixed point of N·2^(q-2)·10^k: 10 <= r <= 64 seen */
    mulshift(4 * m - dl, phi, plo, r, &il, &fl, &lostL);
    mulshift(4 * m, phi, plo, r, &iv, &fv, &lostV);
    mulshift(4 * m + 2, phi, plo, r, &ih, &fh, &lostH);
    exL = exact && !lostL;
    exV = exact && !lostV;
    exH = exact && !lostH;

    if (exL) {
        A = (fl == 0 && closed) ? il : il + 1;
    } else if (fl == 0 || fl >= UINT64_MAX - 1) { /* ceil(Lr) in {a, a + 1} */
        uint64_t a = il + (fl != 0);
        int cc = cmp_dec_bin(a, -k, 4 * m - dl, q - 2);
        A = (cc > 0 || (cc == 0 && closed)) ? a : a + 1;
    } else {
        A = il + 1;
    }
    if (exH) {
        B = (fh == 0 && !closed) ? ih - 1 : ih;
    } else if (fh == 0 || fh >= UINT64_MAX - 1) { /* floor(Hr) in {b - 1, b} */
        uint64_t bb = ih + (fh != 0);
        int cc = cmp_dec_bin(bb, -k, 4 * m + 2, q - 2);
        B = (cc < 0 || (cc == 0 && closed)) ? bb : bb - 1;
    } else {
        B = ih;
    }

    /* Largest j with a multiple of 10^j in [A, B]: floor(B/10^j) > floor((A-1)/10^j).
     * vr = floor(V/10^j); the removed digits of V are kept as the last one (ld)
     * and whether those below it are all 0 / all 9 (for the rounding). */
    bq = B;
    aq = A - 1;
    vr = iv;
    while (bq / 10 > aq / 10) {
        unsigned d = (unsigned)(vr % 10);
        if (j > 0) { /* the previous last digit joins those below */
            lz0 = lz0 && ld == 0;
            lz9 = lz9 && ld == 9;
        }
        ld = d;
        vr /= 10;
        bq /= 10;
        aq /= 10;
        j++;
    }
    c = vr; /* round V / 10^j to nearest, ties even */
    if (j == 0) {
        if (fv > (UINT64_C(1) << 63))
            up = 1;
        else if (fv == (UINT64_C(1) << 63))
            up = exV ? (int)(c & 1) : -1;
        else
            up = (exV || (UINT64_C(1) << 63) - fv >= 2) ? 0 : -1;
    } else if (ld > 5 || (ld == 5 && !(lz0 && fv == 0))) {
        up = 1;
    } else if (ld == 5) {
        up = exV ? (int)(c & 1) : -1;
    } else {
        up = (exV || !(ld == 4 && lz9 && fv >= UINT64_MAX - 1)) ? 0 : -1;
    }
    if (up < 0) { /* v against the decimal midpoint (c + 1/2)·10^(j-k) */
        int cc = cmp_dec_bin((2 * c + 1) * 5, j - 1 - k, m, q);
        up = cc < 0 || (cc == 0 && (c & 1));
    }
    c += (uint64_t)up;
    cmin = aq + 1;
    cmax = bq;
    if (c < cmin)
        c = cmin;
    else if (c > cmax)
        c = cmax;
    while (c % 10 == 0) { /* not expected (j is maximal); kept for safety */
        c /= 10;
        j++;
    }
    *digits = c;
    *e10 = j - k;
}

static const char DIGITS2[201] = "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
                                 "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
                                 "8081828384858687888990919293949596979899";

size_t tsu_format_double(double v, char buf[TSU_FMT_SIZE])
{
    uint64_t bits = double_to_bits(v), c;
    char dig[24], *o = buf;
    int n, e, x, i;
    if (((bits >> 52) & 0x7ff) == 0x7ff) {
        if (bits & ((UINT64_C(1) << 52) - 1)) {
            memcpy(buf, "nan", 4);
            return 3;
        }
        if (bits >> 63) {
            memcpy(buf, "-inf", 5);
            return 4;
        }
        memcpy(buf, "inf", 4);
        return 3;
    }
    if (bits >> 63)
        *o++ = '-';
    bits &= ~(UINT64_C(1) << 63);
    if (bits == 0) {
        *o++ = '0';
        *o = 0;
        return (size_t)(o - buf);
    }
    shortest(bits, &c, &e);
    n = 0; /* digits of c, most significant first, into dig[24 - n .. 23] */
    while (c >= 100000000u) { /* blocks of 8 (32-bit arithmetic, independent chains) */
        uint32_t lo = (uint32_t)(c % 100000000u);
        c /= 100000000u;
        for (i = 0; i < 4; i++) {
            uint32_t d = lo % 100u;
            lo /= 100u;
            dig[23 - n] = DIGITS2[2 * d + 1];
            dig[22 - n] = DIGITS2[2 * d];
            n += 2;
        }
    }
    {
        uint32_t c32 = (uint32_t)c; /* 1 <= c32 < 1e8 */
        while (c32 >= 100u) {
            uint32_t d = c32 % 100u;
            c32 /= 100u;
            dig[23 - n] = DIGITS2[2 * d + 1];
            dig[22 - n] = DIGITS2[2 * d];
            n += 2;
        }
        if (c32 >= 10u) {
            dig[23 - n] = DIGITS2[2 * c32 + 1];
            dig[22 - n] = DIGITS2[2 * c32];
            n += 2;
        } else {
            dig[23 - n] = (char)('0' + c32);
            n += 1;
        }
    }
    {
        const char *d0 = dig + 24 - n;
        x = e + n - 1; /* decimal exponent of the first digit */
        if (x < -4 || x >= 17) {
            unsigned ax = (unsigned)(x < 0 ? -x : x);
            *o++ = d0[0];
            if (n > 1) {
                *o++ = '.';
                memcpy(o, d0 + 1, (size_t)(n - 1));
                o += n - 1;
            }
            *o++ = 'e';
            *o++ = x < 0 ? '-' : '+';
            if (ax >= 100) {
                *o++ = (char)('0' + ax / 100);
                ax %= 100;
            }
            *o++ = DIGITS2[2 * ax];
            *o++ = DIGITS2[2 * ax + 1];
        } else if (x >= n - 1) {
            memcpy(o, d0, (size_t)n);
            o += n;
            for (i = n - 1; i < x; i++)
                *o++ = '0';
        } else if (x >= 0) {
            memcpy(o, d0, (size_t)(x + 1));
            o += x + 1;
            *o++ = '.';
            memcpy(o, d0 + x + 1, (size_t)(n - x - 1));
            o += n - x - 1;
        } else {
            *o++ = '0';
            *o++ = '.';
            for (i = -1; i > x; i--)
                *o++ = '0';
            memcpy(o, d0, (size_t)n);
            o += n;
        }
    }
    *o = 0;
    return (size_t)(o - buf);
}

/* ================================================================== */
/* Allocation (with the test hook)                                      */
/* ================================================================== */

static long io_fail_after = -1;

void tsu_io__fail_alloc_after(long n) { io_fail_after = n < 0 ? -1 : n; }

static int io_alloc_fails(void)
{
    if (io_fail_after < 0)
        return 0;
    return io_fail_after-- == 0;
}
static void *io_malloc(size_t n) { return io_alloc_fails() ? NULL : malloc(n); }
static void *io_calloc(size_t n, size_t sz) { return io_alloc_fails() ? NULL : calloc(n, sz); }
static void *io_realloc(void *p, size_t n) { return io_alloc_fails() ? NULL : realloc(p, n); }

/* ================================================================== */
/* Errors                                                               */
/* ================================================================== */

const char *tsu_io_strerror(tsu_io_status st)
{
    switch (st) {
    case TSU_IO_OK: return "success";
    case TSU_IO_END: return "end of input";
    case TSU_IO_ERR_NULL: return "null argument";
    case TSU_IO_ERR_NOMEM: return "out of memory";
    case TSU_IO_ERR_OVERFLOW: return "size overflow";
    case TSU_IO_ERR_OPTION: return "invalid option";
    case TSU_IO_ERR_OPEN: return "cannot open input";
    case TSU_IO_ERR_READ: return "read error";
    case TSU_IO_ERR_EMPTY: return "no data";
    case TSU_IO_ERR_NUMBER: return "not a number";
    case TSU_IO_ERR_NONFINITE: return "not a finite number";
    case TSU_IO_ERR_RANGE: return "number out of range";
    case TSU_IO_ERR_FIELDS: return "wrong number of fields";
    case TSU_IO_ERR_LINE: return "line too long";
    case TSU_IO_ERR_QUOTE: return "bad quoting";
    case TSU_IO_ERR_TIME: return "not a valid date or time";
    case TSU_IO_ERR_LAYOUT: return "ambiguous table layout";
    case TSU_IO_STATUS_COUNT_: break;
    }
    return "unknown status";
}

static void err_clear(tsu_io_error *e)
{
    if (e) {
        e->status = TSU_IO_OK;
        e->sys_errno = 0;
        e->line = 0;
        e->column = 0;
        e->field = 0;
        e->msg[0] = 0;
    }
}

static void err_set(tsu_io_error *e, tsu_io_status st, int sys, const char *name,
                    unsigned long long line, size_t col, size_t field, const char *fmt, ...)
    IO_PRINTF(8, 9);

static void err_set(tsu_io_error *e, tsu_io_status st, int sys, const char *name,
                    unsigned long long line, size_t col, size_t field, const char *fmt, ...)
{
    va_list ap;
    int n;
    if (!e)
        return;
    e->status = st;
    e->sys_errno = sys;
    e->line = line;
    e->column = col;
    e->field = field;
    if (!name)
        name = "<input>";
    if (line && col)
        n = snprintf(e->msg, sizeof e->msg, "%s:%llu:%zu: ", name, line, col);
    else if (line)
        n = snprintf(e->msg, sizeof e->msg, "%s:%llu: ", name, line);
    else
        n = snprintf(e->msg, sizeof e->msg, "%s: ", name);
    if (n < 0)
        n = 0;
    if ((size_t)n >= sizeof e->msg)
        return;
    va_start(ap, fmt);
    vsnprintf(e->msg + n, sizeof e->msg - (size_t)n, fmt, ap);
    va_end(ap);
}

/* "text" with non-printable bytes as \xNN, cut after 40 bytes with "..." */
static void quote_text(char *dst, size_t dsz, const char *s, const char *e)
{
    size_t k = 0, i, n = (size_t)(e - s);
    static const char hex[] = "0123456789abcdef";
    if (dsz < 60) { /* never leave dst unterminated */
        if (dsz)
            dst[0] = 0;
        return;
    }
    dst[k++] = '"';
    for (i = 0; i < n && i < 40; i++) {
        unsigned char ch = (unsigned char)s[i];
        if (ch >= 0x20 && ch < 0x7f) {
            dst[k++] = (char)ch;
        } else {
            dst[k++] = '\\';
            dst[k++] = 'x';
            dst[k++] = hex[ch >> 4];
            dst[k++] = hex[ch & 15];
        }
        if (k + 8 >= dsz)
            break;
    }
    dst[k++] = '"';
    if (i < n) {
        dst[k++] = '.';
        dst[k++] = '.';
        dst[k++] = '.';
    }
    dst[k] = 0;
}

#define IS_BLANK(c) ((c) == ' ' || (c) == '\t')

/* ================================================================== */
/* Dates and times                                                      */
/* ================================================================== */

/* Days since 1970-01-01 of a proleptic Gregorian date (the era-based
 * day count: 400-year eras of 146097 days, years starting in March). */
static long long days_from_civil(long long y, int m, int d)
{
    y -= m <= 2;
    long long era = (y >= 0 ? y : y - 399) / 400;
    long long yoe = y - era * 400;
    long long doy = (153 * (m + (m > 2 ? -3 : 9)) + 2) / 5 + d - 1;
    long long doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
    return era * 146097 + doe - 719468;
}

static void civil_from_days(long long z, long long *y, int *m, int *d)
{
    z += 719468;
    long long era = (z >= 0 ? z : z - 146096) / 146097;
    long long doe = z - era * 146097;
    long long yoe = (doe - doe / 1460 + doe / 36524 - doe / 146096) / 365;
    long long doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    long long mp = (5 * doy + 2) / 153;
    *d = (int)(doy - (153 * mp + 2) / 5 + 1);
    *m = (int)(mp < 10 ? mp + 3 : mp - 9);
    *y = yoe + era * 400 + (*m <= 2);
}

static int month_days(long long y, int m)
{
    static const int md[12] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
    int leap = (y % 4 == 0 && y % 100 != 0) || y % 400 == 0;
    return m == 2 ? 28 + leap : md[m - 1];
}


/* n digits at p (p + n <= end) into *v; 0 if not all digits */
static int digits_at(const char *p, const char *end, int n, int *v)
{
    int acc = 0;
    if (end - p < n)
        return 0;
    for (int i = 0; i < n; i++) {
        if (!IS_DIGIT(p[i]))
            return 0;
        acc = acc * 10 + (p[i] - '0');
    }
    *v = acc;
    return 1;
}

int tsu_parse_time(const char *s, const char *end, double *t, tsu_time_form *form,
                   const char **stop)
{
    tsu_time_form f;
    const char *p = s;
    int Y, M, D, h = 0, mi = 0, sec = 0, oh, om;
    double frac = 0.0;
    memset(&f, 0, sizeof f);
    f.date_only = 1;
    f.sep = 'T';
    if (!end)
        end = s + strlen(s);
    if (stop)
        *stop = s;
    if (!digits_at(p, end, 4, &Y) || end - p < 5 || p[4] != '-')
        return 0;
    p += 5;
    if (!digits_at(p, end, 2, &M) || M < 1 || M > 12 || end - p < 3 || p[2] != '-') {
        if (stop)
            *stop = p;
        return 0;
    }
    p += 3;
    if (!digits_at(p, end, 2, &D) || D < 1 || D > month_days(Y, M)) {
        if (stop)
            *stop = p;
        return 0;
    }
    p += 2;
    if (p < end && (*p == 'T' || *p == 't' || *p == ' ') && end - p >= 4 && IS_DIGIT(p[1]) &&
        IS_DIGIT(p[2]) && p[3] == ':') {
        f.date_only = 0;
        f.sep = *p++;
        if (!digits_at(p, end, 2, &h) || h > 23 || !digits_at(p + 3, end, 2, &mi) || mi > 59) {
            if (stop)
                *stop = p;
            return 0;
        }
        p += 5;
        if (p < end && *p == ':') {
            if (!digits_at(p + 1, end, 2, &sec) || sec > 59) {
                if (stop)
                    *stop = p + 1;
                return 0;
            }
            f.seconds = 1;
            p += 3;
            if (p < end && *p == '.' && p + 1 < end && IS_DIGIT(p[1])) {
                const char *q;
                (void)tsu_parse_double(p, end, &frac, &q); /* ".ddd": exact rounding */
                p = q;
            }
        }
        if (p < end && (*p == 'Z' || *p == 'z')) {
            f.zone = 1;
            p++;
        } else if (p < end && (*p == '+' || *p == '-') && digits_at(p + 1, end, 2, &oh)) {
            int sign = *p == '-' ? -1 : 1;
            const char *q = p + 3;
            om = 0;
            if (q < end && *q == ':' && digits_at(q + 1, end, 2, &om)) {
                f.colon = 1;
                q += 3;
            } else if (digits_at(q, end, 2, &om)) {
                q += 2;
            }
            if (oh > 23 || om > 59) {
                if (stop)
                    *stop = p;
                return 0;
            }
            f.zone = 2;
            f.offset_min = sign * (oh * 60 + om);
            p = q;
        }
    }
    long long whole = days_from_civil(Y, M, D) * 86400 + h * 3600 + mi * 60 + sec -
                      (long long)f.offset_min * 60;
    if (t)
        *t = (double)whole + frac;
    if (form)
        *form = f;
    if (stop)
        *stop = p;
    return 1;
}

size_t tsu_format_time(double t, const tsu_time_form *form, char buf[TSU_TIME_SIZE])
{
    tsu_time_form f;
    char fr[16] = "";
    long long y;
    int m, d;
    if (form)
        f = *form;
    else
        memset(&f, 0, sizeof f), f.sep = 'T', f.seconds = 1, f.zone = 1;
    if (!(fabs(t) < 2.5e14)) { /* beyond year 9999 both ways: a number */
        return tsu_format_double(t, buf);
    }
    double I = floor(t), frac = t - I;
    if (frac > 0.0) {
        /* the fewest digits that read back as t (as tsu_parse_time reads) */
        long long p10 = 1;
        for (int k = 1; k <= 9; k++) {
            p10 *= 10;
            double r = floor(frac * (double)p10 + 0.5);
            if (r >= (double)p10)
                continue;
            char tmp[16];
            snprintf(tmp, sizeof tmp, ".%0*lld", k, (long long)r);
            double back;
            (void)tsu_parse_double(tmp, NULL, &back, NULL);
            if (I + back == t || k == 9) {
                size_t L = strlen(tmp);
                while (L > 2 && tmp[L - 1] == '0')
                    tmp[--L] = 0;
                memcpy(fr, tmp, L + 1);
                break;
            }
        }
    }
    long long local = (long long)I + (f.zone == 2 ? (long long)f.offset_min * 60 : 0);
    long long days = local >= 0 ? local / 86400 : -((-local + 86399) / 86400);
    long long sod = local - days * 86400;
    int h = (int)(sod / 3600), mi = (int)(sod / 60 % 60), sec = (int)(sod % 60);
    civil_from_days(days, &y, &m, &d);
    int n;
    if (f.date_only && sod == 0 && !fr[0]) {
        n = snprintf(buf, TSU_TIME_SIZE, "%04lld-%02d-%02d", y, m, d);
    } else {
        char sep = f.date_only ? 'T' : f.sep;
        if (f.seconds || sec || fr[0])
            n = snprintf(buf, TSU_TIME_SIZE, "%04lld-%02d-%02d%c%02d:%02d:%02d%s", y, m, d, sep, h,
                         mi, sec, fr);
        else
            n = snprintf(buf, TSU_TIME_SIZE, "%04lld-%02d-%02d%c%02d:%02d", y, m, d, sep, h, mi);
        if (n > 0 && n < TSU_TIME_SIZE - 8) {
            if (f.zone == 1) {
                buf[n++] = 'Z';
                buf[n] = 0;
            } else if (f.zone == 2) {
                int o = f.offset_min < 0 ? -f.offset_min : f.offset_min;
                n += snprintf(buf + n, TSU_TIME_SIZE - (size_t)n, f.colon ? "%c%02d:%02d" : "%c%02d%02d",
                              f.offset_min < 0 ? '-' : '+', o / 60, o % 60);
            }
        }
    }
    return n < 0 ? 0 : (size_t)n;
}

/* ================================================================== */
/* Streaming reader                                                     */
/* ================================================================== */

struct tsu_reader {
    FILE *fp;
    char *name;
    char *buf;
    size_t cap, pos, len, cap_max;
    int eof;
    unsigned long long line;     /* physical lines consumed */
    unsigned long long rec_line; /* first line of the current record */
    unsigned long long row_line; /* line of the last row returned */
    unsigned long long rows;
    unsigned long long skip;
    unsigned long long header_line;
    tsu_delim delim;
    tsu_header header;
    int decimal_comma;
    int seen_content;
    size_t ncols;
    char **names;
    size_t nnames;
    double *row;
    size_t *fcol;  /* byte offset of each field of the row in its record */
    size_t rowcap;
    size_t missing;
    char **na;     /* missing-value words, NULL: none */
    size_t nna;
    int time_detect;
    size_t time_col; /* 1-based, 0 none */
    char *time_name;
    unsigned char *is_time; /* per column (ncols), once known */
    tsu_time_form *tform;
    char *tmp;      /* scratch: unquoted / decimal-comma field text */
    size_t tmpcap;
    const char *ls; /* start of the current record */
    unsigned char *use; /* per column (rowcap): 1 = parsed, when selected */
    int selected;       /* tsu_reader_use_columns was called */
    int pending;        /* tsu_reader_layout left a data record unparsed: */
    const char *pend_le; /* its content end (r->ls its start) */
    int rec_scanned;      /* its last line was quote-scanned: */
    const char *rec_hash; /* then its comment '#' (NULL: none) */
    int failed;
    tsu_io_error saved;
};

void tsu_read_options_init(tsu_read_options *opt)
{
    if (!opt)
        return;
    memset(opt, 0, sizeof *opt);
    opt->delim = TSU_DELIM_AUTO;
    opt->header = TSU_HEADER_AUTO;
    opt->ncols = 0;
    opt->max_line = TSU_IO_MAX_LINE;
    opt->buffer_size = TSU_IO_BUFFER;
    opt->track_lines = 1;
}

static char *dup_str(const char *s, size_t n)
{
    char *d = io_malloc(n + 1);
    if (d) {
        memcpy(d, s, n);
        d[n] = 0;
    }
    return d;
}

static void free_names(char **names, size_t n)
{
    size_t i;
    if (!names)
        return;
    for (i = 0; i < n; i++)
        free(names[i]);
    free(names);
}

/* Split the na list into words (trimmed); 0 or -1 (no memory). */
static int set_na(tsu_reader *r, const char *na)
{
    size_t n = 1, k = 0;
    for (const char *p = na; *p; p++)
        n += *p == ',';
    r->na = io_calloc(n, sizeof *r->na);
    if (!r->na)
        return -1;
    for (const char *p = na;;) {
        const char *e = strchr(p, ',');
        const char *we = e ? e : p + strlen(p);
        const char *ws = p;
        while (ws < we && IS_BLANK(*ws))
            ws++;
        while (we > ws && IS_BLANK(we[-1]))
            we--;
        if (we > ws) {
            if (!(r->na[k] = dup_str(ws, (size_t)(we - ws))))
                return -1;
            k++;
        }
        if (!e)
            break;
        p = e + 1;
    }
    r->nna = k;
    return 0;
}

void tsu_reader_free(tsu_reader *r)
{
    if (!r)
        return;
    free_names(r->names, r->nnames);
    free_names(r->na, r->nna);
    free(r->row);
    free(r->fcol);
    free(r->buf);
    free(r->name);
    free(r->time_name);
    free(r->is_time);
    free(r->tform);
    free(r->use);
    free(r->tmp);
    free(r);
}

tsu_io_status tsu_reader_open(tsu_reader **out, FILE *fp, const char *name,
                            const tsu_read_options *opt, tsu_io_error *err)
{
    tsu_read_options def;
    tsu_reader *r;
    err_clear(err);
    if (out)
        *out = NULL;
    if (!name)
        name = "<input>";
    if (!out || !fp) {
        err_set(err, TSU_IO_ERR_NULL, 0, name, 0, 0, 0, "null argument");
        return TSU_IO_ERR_NULL;
    }
    if (!opt) {
        tsu_read_options_init(&def);
        opt = &def;
    }
    if (!(opt->delim >= TSU_DELIM_AUTO && opt->delim <= TSU_DELIM_SEMICOLON) ||
        !(opt->header >= TSU_HEADER_AUTO && opt->header <= TSU_HEADER_YES) || opt->max_line < 16 ||
        opt->max_line >= SIZE_MAX / 4 || opt->buffer_size < 16 ||
        (opt->decimal_comma && opt->delim == TSU_DELIM_COMMA)) {
        err_set(err, TSU_IO_ERR_OPTION, 0, name, 0, 0, 0, "invalid option");
        return TSU_IO_ERR_OPTION;
    }
    r = io_calloc(1, sizeof *r);
    if (!r || !(r->name = dup_str(name, strlen(name)))) {
        free(r);
        err_set(err, TSU_IO_ERR_NOMEM, 0, name, 0, 0, 0, "out of memory");
        return TSU_IO_ERR_NOMEM;
    }
    r->fp = fp;
    r->cap_max = opt->max_line + 1; /* a line of max_line bytes plus its '\n' */
    r->cap = opt->buffer_size < r->cap_max ? opt->buffer_size : r->cap_max;
    r->buf = io_malloc(r->cap);
    if (!r->buf || (opt->na && set_na(r, opt->na) != 0) ||
        (opt->time_name && !(r->time_name = dup_str(opt->time_name, strlen(opt->time_name))))) {
        tsu_reader_free(r);
        err_set(err, TSU_IO_ERR_NOMEM, 0, name, 0, 0, 0, "out of memory");
        return TSU_IO_ERR_NOMEM;
    }
    r->delim = opt->delim;
    r->header = opt->header;
    r->ncols = opt->ncols;
    r->skip = opt->skip;
    r->decimal_comma = opt->decimal_comma;
    r->time_detect = opt->time_detect;
    r->time_col = opt->time_col;
    *out = r;
    return TSU_IO_OK;
}

size_t tsu_reader_ncols(const tsu_reader *r) { return r ? r->ncols : 0; }
unsigned long long tsu_reader_line(const tsu_reader *r) { return r ? r->row_line : 0; }
unsigned long long tsu_reader_rows(const tsu_reader *r) { return r ? r->rows : 0; }
size_t tsu_reader_nnames(const tsu_reader *r) { return r ? r->nnames : 0; }
const char *tsu_reader_source(const tsu_reader *r) { return r ? r->name : NULL; }
tsu_delim tsu_reader_delim(const tsu_reader *r) { return r ? r->delim : TSU_DELIM_AUTO; }
size_t tsu_reader_missing(const tsu_reader *r) { return r ? r->missing : 0; }
unsigned long long tsu_reader_header_line(const tsu_reader *r) { return r ? r->header_line : 0; }

const char *tsu_reader_name(const tsu_reader *r, size_t j)
{
    return (r && r->names && j < r->nnames) ? r->names[j] : NULL;
}

int tsu_reader_is_time(const tsu_reader *r, size_t j, tsu_time_form *form)
{
    if (!r || !r->is_time || j >= r->ncols || !r->is_time[j])
        return 0;
    if (form)
        *form = r->tform[j];
    return 1;
}

/* Set the reader's sticky error. */
#define RFAIL(r, st, sys, line, col, field, ...)                                    \
    (err_set(&(r)->saved, (st), (sys), (r)->name, (line), (col), (field), __VA_ARGS__), \
     (r)->failed = 1, (tsu_io_status)(st))

static char delim_char(tsu_delim d)
{
    return d == TSU_DELIM_COMMA ? ',' : d == TSU_DELIM_TAB ? '\t' : d == TSU_DELIM_SEMICOLON ? ';' : 0;
}

/* Could c end a field (for finding quoted fields before the delimiter is known)? */
/* After a value read by a fast path, ending at stop: the end of its field
 * (le, or the delimiter dc; with dc = 0 white space separates fields), past
 * trailing blanks (only spaces when the delimiter is a tab), or NULL if
 * something else follows the value there. */
static const char *fast_field_end(const char *stop, const char *le, char dc)
{
    const char *q = stop;
    if (dc == '\t')
        while (q < le && *q == ' ')
            q++;
    else
        while (q < le && IS_BLANK(*q))
            q++;
    return q == le || (dc ? *q == dc : q > stop) ? q : NULL;
}

static int field_sep(const tsu_reader *r, char c)
{
    char dc = delim_char(r->delim);
    if (r->delim == TSU_DELIM_AUTO)
        return c == ',' || c == ';' || c == '\t' || c == ' ';
    return dc ? c == dc : IS_BLANK(c);
}

/* Quote state over [p, e): *inq inside quotes, *fs at a field start, *cm in
 * a comment (*hash: where it starts). */
static void quote_scan(const tsu_reader *r, const char *p, const char *e, int *inq, int *fs, int *cm,
                       const char **hash)
{
    const char *seg = p;
    if (*cm)
        return;
    while (p < e) {
        if (*inq) {
            const char *q = memchr(p, '"', (size_t)(e - p));
            if (!q)
                return;
            if (q + 1 < e && q[1] == '"') {
                p = q + 2;
                continue;
            }
            *inq = 0;
            *fs = 0;
            p = q + 1;
            seg = p;
            continue;
        }
        /* outside quotes: the next '"' or '#' */
        const char *q = p;
        while (q < e && *q != '"' && *q != '#')
            q++;
        if (q == e) {
            /* the field-start state at the end, for a record continued by the caller */
            const char *b = e;
            while (b > seg && IS_BLANK(b[-1]) && !field_sep(r, b[-1]))
                b--;
            if (b > seg)
                *fs = field_sep(r, b[-1]);
            return;
        }
        if (*q == '#') {
            *cm = 1;
            *hash = q;
            return;
        }
        /* a '"' opens a quoted field at a field start: after blanks that follow a
         * separator, or the start of the scanned run with *fs set */
        {
            const char *b = q;
            int at_start;
            while (b > seg && IS_BLANK(b[-1]) && !field_sep(r, b[-1]))
                b--;
            at_start = b > seg ? field_sep(r, b[-1]) : *fs;
            if (at_start) {
                *inq = 1;
                *fs = 0;
            } else {
                *fs = 0;
                seg = q + 1;
            }
        }
        p = q + 1;
    }
}

/* Next record (without its final '\n') into [*ls, *ls + *ll): 1, 0 at the
 * end, or the negative of an error status. */
static int get_record(tsu_reader *r, char **ls, size_t *ll)
{
    size_t scan = 0; /* bytes of the record scanned so far, from r->pos */
    unsigned long long nls = 0;
    int inq = 0, fs = 1, cm = 0;
    for (;;) {
        char *base = r->buf + r->pos;
        size_t avail = r->len - r->pos;
        char *nl = scan < avail ? memchr(base + scan, '\n', avail - scan) : NULL;
        if (nl || (r->eof && scan < avail)) {
            char *segend = nl ? nl : base + avail;
            if (r->line + nls < r->skip) { /* a skipped line */
                r->pos += (size_t)(segend - base) + (nl ? 1 : 0);
                r->line++;
                continue;
            }
            r->rec_scanned = 0;
            r->rec_hash = NULL;
            if (inq || memchr(base + scan, '"', (size_t)(segend - (base + scan)))) {
                const char *from = base + scan;
                if (r->line + nls == 0 && scan == 0 && segend - from >= 3 &&
                    memcmp(from, "\xef\xbb\xbf", 3) == 0)
                    from += 3; /* the byte-order mark is not part of the first field */
                quote_scan(r, from, segend, &inq, &fs, &cm, &r->rec_hash);
                r->rec_scanned = 1;
            }
            nls++;
            cm = 0;
            if (inq && nl) { /* a line break inside quotes */
                scan = (size_t)(nl - base) + 1;
                fs = 0;
                continue;
            }
            if (inq)
                return -(int)RFAIL(r, TSU_IO_ERR_QUOTE, 0, r->line + 1, 0, 0,
                                   "quote not closed (the quoted field starting on this line "
                                   "runs to the end of the input)");
            *ls = base;
            *ll = (size_t)(segend - base);
            r->pos += *ll + (nl ? 1 : 0);
            r->rec_line = r->line + 1;
            r->line += nls;
            return 1;
        }
        if (r->eof) {
            if (scan > 0)
                return -(int)RFAIL(r, TSU_IO_ERR_QUOTE, 0, r->line + 1, 0, 0,
                                   "quote not closed (the quoted field starting on this line "
                                   "runs to the end of the input)");
            return 0;
        }
        if (r->pos > 0) {
            memmove(r->buf, r->buf + r->pos, r->len - r->pos);
            r->len -= r->pos;
            r->pos = 0;
        }
        if (r->len == r->cap) {
            size_t nc;
            char *nb;
            if (r->cap >= r->cap_max)
                return -(int)RFAIL(r, TSU_IO_ERR_LINE, 0, r->line + 1, 0, 0,
                                   "line longer than %zu bytes", r->cap_max - 1);
            nc = r->cap <= r->cap_max / 2 ? 2 * r->cap : r->cap_max;
            nb = io_realloc(r->buf, nc);
            if (!nb)
                return -(int)RFAIL(r, TSU_IO_ERR_NOMEM, 0, 0, 0, 0, "out of memory");
            r->buf = nb;
            r->cap = nc;
        }
        {
            size_t want = r->cap - r->len, got;
            errno = 0;
            got = fread(r->buf + r->len, 1, want, r->fp);
            r->len += got;
            if (got < want) { /* short read: end of file or error */
                if (ferror(r->fp)) {
                    int e = errno ? errno : EIO;
                    return -(int)RFAIL(r, TSU_IO_ERR_READ, e, 0, 0, 0, "read error: %s",
                                       strerror(e));
                }
                r->eof = 1;
            }
        }
    }
}

/* Line and column of p in the current record (records may span lines). */
static void pos_of(const tsu_reader *r, const char *p, unsigned long long *line, size_t *col)
{
    const char *ls = r->ls;
    unsigned long long ln = r->rec_line;
    for (const char *q = r->ls; q < p; q++)
        if (*q == '\n') {
            ln++;
            ls = q + 1;
        }
    *line = ln;
    *col = (size_t)(p - ls) + 1;
}

#define POS_FAIL(r, st, p, field, ...)                                                   \
    do {                                                                                 \
        unsigned long long ln_;                                                          \
        size_t col_;                                                                     \
        pos_of((r), (p), &ln_, &col_);                                                   \
        return RFAIL((r), (st), 0, ln_, col_, (field), __VA_ARGS__);                     \
    } while (0)

/* Content end of a record: before a '#' outside quotes, trailing blanks and '\r' removed. */
static const char *content_end(const tsu_reader *r, const char *ls, const char *le)
{
    const char *p;
    if (r->rec_scanned) {
        if (r->rec_hash)
            le = r->rec_hash;
    } else if (memchr(ls, '"', (size_t)(le - ls))) {
        int inq = 0, fs = 1;
        for (p = ls; p < le; p++) {
            char c = *p;
            if (inq) {
                if (c == '"') {
                    if (p + 1 < le && p[1] == '"')
                        p++;
                    else
                        inq = 0, fs = 0;
                }
                continue;
            }
            if (c == '#')
                break;
            if (c == '"' && fs)
                inq = 1, fs = 0;
            else if (field_sep(r, c))
                fs = 1;
            else if (!IS_BLANK(c))
                fs = 0;
        }
        le = p;
    } else if ((p = memchr(ls, '#', (size_t)(le - ls))) != NULL) {
        le = p;
    }
    while (le > ls && (le[-1] == ' ' || le[-1] == '\t' || le[-1] == '\r'))
        le--;
    return le;
}

/* A field of a record. */
typedef struct field {
    const char *at;   /* where it starts (after blanks; the quote if quoted) */
    const char *s, *e; /* its text: unquoted, trimmed ("" pairs still doubled) */
    int quoted, esc;  /* esc: contains "" */
} field;

/* Next field from *pp (first: at the record start).  1: a field, 0: end,
 * -1: quote error (reported). */
static int next_field(tsu_reader *r, const char **pp, const char *le, int first, field *f,
                      size_t fieldno)
{
    const char *p = *pp;
    char dc = delim_char(r->delim);
    if (!first) {
        if (p >= le)
            return 0;
        if (dc)
            p++; /* the delimiter */
    }
    if (dc == '\t')
        while (p < le && *p == ' ')
            p++;
    else
        while (p < le && IS_BLANK(*p))
            p++;
    if (!dc && p == le)
        return 0;
    f->at = p;
    f->quoted = f->esc = 0;
    if (p < le && *p == '"') {
        const char *q = p + 1;
        for (;;) {
            const char *c = memchr(q, '"', (size_t)(le - q));
            if (!c) {
                unsigned long long ln;
                size_t col;
                pos_of(r, p, &ln, &col);
                (void)RFAIL(r, TSU_IO_ERR_QUOTE, 0, ln, col, fieldno, "quote not closed");
                return -1;
            }
            if (c + 1 < le && c[1] == '"') {
                f->esc = 1;
                q = c + 2;
                continue;
            }
            q = c;
            break;
        }
        f->quoted = 1;
        f->s = p + 1;
        f->e = q;
        p = q + 1;
        if (dc)
            while (p < le && (dc == '\t' ? *p == ' ' : IS_BLANK(*p)))
                p++;
        if (!dc) {
            if (p < le && !IS_BLANK(*p)) {
                unsigned long long ln;
                size_t col;
                pos_of(r, p, &ln, &col);
                (void)RFAIL(r, TSU_IO_ERR_QUOTE, 0, ln, col, fieldno, "text after the closing quote");
                return -1;
            }
        } else if (p < le && *p != dc) {
            unsigned long long ln;
            size_t col;
            pos_of(r, p, &ln, &col);
            (void)RFAIL(r, TSU_IO_ERR_QUOTE, 0, ln, col, fieldno, "text after the closing quote");
            return -1;
        }
        while (f->s < f->e && IS_BLANK(*f->s))
            f->s++;
        while (f->e > f->s && IS_BLANK(f->e[-1]))
            f->e--;
        *pp = p;
        return 1;
    }
    f->s = p;
    while (p < le && (dc ? *p != dc : !IS_BLANK(*p)))
        p++;
    f->e = p;
    while (f->e > f->s && IS_BLANK(f->e[-1]))
        f->e--;
    *pp = p;
    return 1;
}

/* Scratch of at least n bytes; NULL: no memory (reported). */
static char *scratch(tsu_reader *r, size_t n)
{
    if (n > r->tmpcap) {
        size_t nc = n < 256 ? 256 : n;
        char *nb = io_realloc(r->tmp, nc);
        if (!nb) {
            (void)RFAIL(r, TSU_IO_ERR_NOMEM, 0, 0, 0, 0, "out of memory");
            return NULL;
        }
        r->tmp = nb;
        r->tmpcap = nc;
    }
    return r->tmp;
}

/* The text of f with "" undone (into scratch when needed); NULL: no memory. */
static const char *field_text(tsu_reader *r, const field *f, const char **e)
{
    if (!f->esc) {
        *e = f->e;
        return f->s;
    }
    char *d = scratch(r, (size_t)(f->e - f->s) + 1), *o;
    if (!d)
        return NULL;
    o = d;
    for (const char *q = f->s; q < f->e; q++) {
        *o++ = *q;
        if (*q == '"' && q + 1 < f->e && q[1] == '"')
            q++;
    }
    *e = o;
    return d;
}

static int is_na(const tsu_reader *r, const char *s, const char *e)
{
    size_t n = (size_t)(e - s);
    if (!r->na)
        return 0;
    if (n == 0)
        return 1;
    for (size_t k = 0; k < r->nna; k++) {
        const char *w = r->na[k];
        size_t i;
        if (strlen(w) != n)
            continue;
        for (i = 0; i < n; i++) {
            char a = s[i], b = w[i];
            if (a >= 'A' && a <= 'Z')
                a = (char)(a - 'A' + 'a');
            if (b >= 'A' && b <= 'Z')
                b = (char)(b - 'A' + 'a');
            if (a != b)
                break;
        }
        if (i == n)
            return 1;
    }
    return 0;
}

/* A whole-field number (decimal comma honoured): status, or -1 = no memory. */
static int num_field(tsu_reader *r, const char *s, const char *e, double *v)
{
    const char *stop;
    tsu_num_status ns;
    if (r->decimal_comma) {
        const char *c = memchr(s, ',', (size_t)(e - s));
        if (memchr(s, '.', (size_t)(e - s)))
            return TSU_NUM_SYNTAX;
        if (c) {
            char *d = scratch(r, (size_t)(e - s));
            if (!d)
                return -1;
            memcpy(d, s, (size_t)(e - s));
            d[c - s] = '.';
            e = d + (e - s);
            s = d;
        }
    }
    ns = tsu_parse_double(s, e, v, &stop);
    if (stop != e)
        return TSU_NUM_SYNTAX;
    return (int)ns;
}

#define IS_ALPHA(c) ((unsigned)(((unsigned char)(c) | 0x20) - 'a') < 26u)

/* A date or date-time followed by a time-zone name ("CET", " Europe/Paris",
 * "[Europe/Paris]": two letters or a '['), which is not accepted: 1 and
 * *name where the name starts, else 0. */
static int zone_name(const char *s, const char *e, const char **name)
{
    const char *stop, *p;
    if (!tsu_parse_time(s, e, NULL, NULL, &stop))
        return 0;
    for (p = stop; p < e && IS_BLANK(*p); p++)
        ;
    if (!(p < e && (*p == '[' || (p + 1 < e && IS_ALPHA(p[0]) && IS_ALPHA(p[1])))))
        return 0;
    *name = p;
    return 1;
}

/* The error for a field [s, e) at `at` that is a date with a zone name at `name`. */
#define ZONE_FAIL(r, at, fieldno, s, e, name)                                              \
    do {                                                                                   \
        char zq_[200], zn_[120];                                                           \
        quote_text(zq_, sizeof zq_, (s), (e));                                             \
        quote_text(zn_, sizeof zn_, (name), (e));                                          \
        POS_FAIL((r), TSU_IO_ERR_TIME, (at), (fieldno),                                    \
                 "time-zone name %s in %s: time-zone names are not accepted, write Z or a " \
                 "numeric UTC offset (+HH:MM, +HHMM or +HH)", zn_, zq_);                   \
    } while (0)

enum { FK_EMPTY, FK_NUMBER, FK_NA, FK_TIME, FK_TEXT, FK_NOMEM };

/* Is column j parsed (tsu_reader_use_columns)? */
static int col_used(const tsu_reader *r, size_t j)
{
    return !r->selected || (j < r->rowcap && r->use[j]);
}

static int classify(tsu_reader *r, const field *f)
{
    const char *e, *s = field_text(r, f, &e);
    double v;
    int ns;
    if (!s)
        return FK_NOMEM;
    if (s == e)
        return FK_EMPTY;
    if (is_na(r, s, e))
        return FK_NA;
    ns = num_field(r, s, e, &v);
    if (ns < 0)
        return FK_NOMEM;
    if (ns != TSU_NUM_SYNTAX)
        return FK_NUMBER;
    if (r->time_detect || r->time_col || r->time_name) {
        const char *stop;
        if (tsu_parse_time(s, e, NULL, NULL, &stop) && stop == e)
            return FK_TIME;
        if (zone_name(s, e, &stop))
            return FK_TIME; /* a date all the same: data, refused when parsed */
    }
    return FK_TEXT;
}

/* Is the record [ls, le) a header (a field that is text)? -1: error (reported). */
static int is_header(tsu_reader *r, const char *ls, const char *le, int *all_text)
{
    const char *p = ls;
    field f;
    int first = 1, k, hdr = 0, any_value = 0;
    size_t j = 0;
    while ((k = next_field(r, &p, le, first, &f, 0)) == 1) {
        first = 0;
        if (!col_used(r, j++))
            continue;
        int c = classify(r, &f);
        if (c == FK_NOMEM)
            return -1;
        if (c == FK_TEXT)
            hdr = 1;
        if (c == FK_NUMBER || c == FK_TIME)
            any_value = 1;
    }
    if (k < 0) {
        r->failed = 0; /* a quote error: let the data parser report it */
        return 0;
    }
    if (all_text)
        *all_text = hdr && !any_value;
    return hdr;
}

static int grow_row(tsu_reader *r, size_t need)
{
    if (need <= r->rowcap)
        return 0;
    size_t nc = r->rowcap ? 2 * r->rowcap : 8;
    while (nc < need)
        nc *= 2;
    if (nc > SIZE_MAX / sizeof(double) || nc > SIZE_MAX / sizeof(size_t))
        return RFAIL(r, TSU_IO_ERR_OVERFLOW, 0, r->rec_line, 0, 0, "size overflow");
    double *nr = io_realloc(r->row, nc * sizeof *nr);
    if (!nr)
        return RFAIL(r, TSU_IO_ERR_NOMEM, 0, 0, 0, 0, "out of memory");
    r->row = nr;
    size_t *nf = io_realloc(r->fcol, nc * sizeof *nf);
    if (!nf)
        return RFAIL(r, TSU_IO_ERR_NOMEM, 0, 0, 0, 0, "out of memory");
    r->fcol = nf;
    unsigned char *it = io_realloc(r->is_time, nc);
    if (!it)
        return RFAIL(r, TSU_IO_ERR_NOMEM, 0, 0, 0, 0, "out of memory");
    memset(it + r->rowcap, 0, nc - r->rowcap);
    r->is_time = it;
    tsu_time_form *tf = io_realloc(r->tform, nc * sizeof *tf);
    if (!tf)
        return RFAIL(r, TSU_IO_ERR_NOMEM, 0, 0, 0, 0, "out of memory");
    r->tform = tf;
    unsigned char *us = io_realloc(r->use, nc);
    if (!us)
        return RFAIL(r, TSU_IO_ERR_NOMEM, 0, 0, 0, 0, "out of memory");
    memset(us + r->rowcap, 0, nc - r->rowcap);
    r->use = us;
    r->rowcap = nc;
    return 0;
}

/* Per-column time flags once the number of columns is known. */
static tsu_io_status set_columns(tsu_reader *r, size_t n)
{
    r->ncols = n;
    if (grow_row(r, n ? n : 1))
        return r->saved.status;
    if (r->time_col && r->time_col <= n)
        r->is_time[r->time_col - 1] = 2; /* forced; form from the first value */
    if (r->time_name) {
        size_t j;
        for (j = 0; j < r->nnames && strcmp(r->names[j], r->time_name) != 0; j++)
            ;
        if (j < r->nnames)
            r->is_time[j] = 2;
    }
    return TSU_IO_OK;
}

static tsu_io_status read_header(tsu_reader *r, const char *ls, const char *le)
{
    const char *p = ls;
    field f;
    int first = 1, k;
    size_t n = 0, cap = 0;
    char **names = NULL;
    while ((k = next_field(r, &p, le, first, &f, n + 1)) == 1) {
        const char *e, *s;
        first = 0;
        if (n == cap) {
            size_t nc = cap ? 2 * cap : 8;
            char **nn;
            if (nc > SIZE_MAX / sizeof *names) {
                free_names(names, n);
                return RFAIL(r, TSU_IO_ERR_OVERFLOW, 0, r->rec_line, 0, 0, "size overflow");
            }
            nn = io_realloc(names, nc * sizeof *names);
            if (!nn) {
                free_names(names, n);
                return RFAIL(r, TSU_IO_ERR_NOMEM, 0, 0, 0, 0, "out of memory");
            }
            names = nn;
            cap = nc;
        }
        s = field_text(r, &f, &e);
        if (!s || !(names[n] = dup_str(s, (size_t)(e - s)))) {
            free_names(names, n);
            return RFAIL(r, TSU_IO_ERR_NOMEM, 0, 0, 0, 0, "out of memory");
        }
        n++;
    }
    if (k < 0) {
        free_names(names, n);
        return r->saved.status;
    }
    if (r->ncols && n != r->ncols) {
        size_t col = (size_t)(le - r->ls) + 1;
        unsigned long long ln = r->rec_line;
        if (n > r->ncols) {
            p = ls;
            first = 1;
            for (size_t i = 0; i <= r->ncols && next_field(r, &p, le, first, &f, 0) == 1; i++)
                first = 0;
            pos_of(r, f.at, &ln, &col);
        }
        free_names(names, n);
        return RFAIL(r, TSU_IO_ERR_FIELDS, 0, ln, col, 0,
                     "wrong number of fields (%zu, expected %zu)", n, r->ncols);
    }
    r->names = names;
    r->nnames = n;
    r->header_line = r->rec_line;
    return set_columns(r, n);
}

/* Number of fields of [ls, le) (for messages; quote errors count as the end). */
static size_t count_fields(tsu_reader *r, const char *ls, const char *le)
{
    const char *p = ls;
    field f;
    size_t n = 0;
    int failed = r->failed;
    while (next_field(r, &p, le, n == 0, &f, 0) == 1)
        n++;
    r->failed = failed;
    return n;
}

/* " (the delimiter is ','; this line also has ';')" for a likely mix-up */
static void delim_hint(const tsu_reader *r, const char *ls, const char *le, char *buf, size_t len)
{
    static const char cand[] = ",;\t";
    char dc = delim_char(r->delim);
    buf[0] = 0;
    for (const char *c = cand; *c; c++) {
        if (*c == dc || (*c == ',' && r->decimal_comma) || !memchr(ls, *c, (size_t)(le - ls)))
            continue;
        snprintf(buf, len, " (the delimiter is %s; this line has %s: mixed delimiters? "
                 "see --delimiter)",
                 dc == ',' ? "','" : dc == ';' ? "';'" : dc == '\t' ? "tab" : "white space",
                 *c == ',' ? "','" : *c == ';' ? "';'" : "a tab");
        return;
    }
}

static tsu_io_status fields_error(tsu_reader *r, const char *ls, const char *le, const char *at,
                                  size_t got)
{
    unsigned long long ln;
    size_t col;
    char hint[160];
    pos_of(r, at, &ln, &col);
    delim_hint(r, ls, le, hint, sizeof hint);
    if (!hint[0] && r->nnames == 1 && r->rows == 0)
        snprintf(hint, sizeof hint, " (the header, line %llu, has one field: metadata lines "
                 "before the header? skip them with --skip N)", r->header_line);
    return RFAIL(r, TSU_IO_ERR_FIELDS, 0, ln, col, 0, "wrong number of fields (%zu, expected %zu)%s",
                 got, r->ncols, hint);
}

/* "12,5": a number up to a ',' and a digit after it */
static int number_comma(const char *s, const char *e)
{
    const char *stop;
    double v;
    return tsu_parse_double(s, e, &v, &stop) == TSU_NUM_OK && stop + 1 < e && *stop == ',' &&
           IS_DIGIT(stop[1]);
}

static tsu_io_status value_error(tsu_reader *r, int ns, const field *f, const char *s,
                                 const char *e, size_t fieldno, const char *ls, const char *le)
{
    char q[200], hint[200] = "";
    int all_text = 0;
    const char *zn;
    quote_text(q, sizeof q, s, e);
    if (ns == TSU_NUM_SYNTAX && r->time_detect && r->rows == 0 && zone_name(s, e, &zn))
        ZONE_FAIL(r, f->at, fieldno, s, e, zn);
    if (ns == TSU_NUM_NONFINITE)
        POS_FAIL(r, TSU_IO_ERR_NONFINITE, f->at, fieldno, "not a finite number: %s", q);
    if (ns == TSU_NUM_RANGE)
        POS_FAIL(r, TSU_IO_ERR_RANGE, f->at, fieldno, "number out of range: %s", q);
    if (r->decimal_comma && memchr(s, '.', (size_t)(e - s)))
        snprintf(hint, sizeof hint, " ('.' is not accepted with a decimal comma)");
    else if (!r->decimal_comma && number_comma(s, e))
        snprintf(hint, sizeof hint, " (digit grouping is not accepted; a decimal comma needs "
                 "--decimal-comma)");
    else if (!delim_char(r->delim) && fieldno > 1 && fieldno - 2 < r->ncols &&
             r->is_time[fieldno - 2] && e - s >= 5 && IS_DIGIT(s[0]) && IS_DIGIT(s[1]) &&
             s[2] == ':')
        snprintf(hint, sizeof hint, " (white space separates fields: write a date-time with T, "
                 "YYYY-MM-DDTHH:MM)");
    else
        delim_hint(r, ls, le, hint, sizeof hint);
    if (!hint[0] && r->rows == 0 && r->header_line && is_header(r, ls, le, &all_text) > 0 &&
        all_text)
        POS_FAIL(r, TSU_IO_ERR_LAYOUT, f->at, fieldno,
                 "every field of this line is text: a second header line (units?) after the "
                 "header on line %llu? skip lines before the data with --skip N",
                 r->header_line);
    POS_FAIL(r, TSU_IO_ERR_NUMBER, f->at, fieldno, "expected a number, found %s%s", q, hint);
}

/* The fields of the data record [ls, le) (no comment, not blank) into r->row. */
static tsu_io_status parse_data(tsu_reader *r, const char *ls, const char *le)
{
    const char *p = ls;
    char dc = delim_char(r->delim);
    size_t nf = 0;
    r->missing = 0;
    for (;;) {
        field f;
        const char *s, *e;
        double v;
        int k;
        if (dc == '\t')
            while (p < le && *p == ' ')
                p++;
        else
            while (p < le && IS_BLANK(*p))
                p++;
        if (r->ncols && nf == r->ncols)
            return fields_error(r, ls, le, p, count_fields(r, ls, le));
        if (grow_row(r, nf + 1))
            return r->saved.status;
        r->fcol[nf] = (size_t)(p - ls);
        if (!col_used(r, nf)) { /* any text: split off, not read */
            const char *fp = p;
            if (next_field(r, &fp, le, 1, &f, nf + 1) < 0)
                return r->saved.status;
            p = fp;
            r->row[nf++] = (double)NAN;
            goto next;
        }
        /* fast path: an unquoted number in a number column */
        if (p < le && *p != '"' && r->is_time[nf] == 1) {
            const char *stop, *q, *fe = le;
            tsu_time_form tf;
            if (!dc) /* white space ends the field: "date HH:MM" is two fields */
                for (fe = p; fe < le && !IS_BLANK(*fe); fe++)
                    ;
            if (tsu_parse_time(p, fe, &v, &tf, &stop)) {
                if ((q = fast_field_end(stop, le, dc)) != NULL) {
                    r->row[nf++] = v;
                    if (q == le)
                        break;
                    p = dc ? q + 1 : q;
                    continue;
                }
            }
        }
        if (p < le && *p != '"' && !r->is_time[nf]) {
            const char *stop, *q;
            tsu_num_status ns = tsu_parse_double(p, le, &v, &stop);
            if (ns == TSU_NUM_OK && stop > p &&
                !(r->decimal_comma && memchr(p, '.', (size_t)(stop - p)))) {
                if ((q = fast_field_end(stop, le, dc)) != NULL) {
                    r->row[nf++] = v;
                    if (q == le)
                        break;
                    p = dc ? q + 1 : q;
                    continue;
                }
            }
        }
        /* fast path: a quoted field without "" in a number or time column */
        if (p < le && *p == '"') {
            const char *q = memchr(p + 1, '"', (size_t)(le - p - 1)), *stop, *t;
            if (q && !(q + 1 < le && q[1] == '"')) {
                const char *fs = p + 1, *fe = q;
                int good;
                while (fs < fe && IS_BLANK(*fs))
                    fs++;
                while (fe > fs && IS_BLANK(fe[-1]))
                    fe--;
                if (r->is_time[nf]) {
                    tsu_time_form tf;
                    good = fs < fe && r->is_time[nf] == 1 &&
                           tsu_parse_time(fs, fe, &v, &tf, &stop) && stop == fe;
                } else {
                    good = fs < fe && !r->decimal_comma &&
                           tsu_parse_double(fs, fe, &v, &stop) == TSU_NUM_OK && stop == fe;
                }
                t = q + 1;
                if (dc)
                    while (t < le && (dc == '\t' ? *t == ' ' : IS_BLANK(*t)))
                        t++;
                if (good && (t == le || (dc ? *t == dc : IS_BLANK(*t)))) {
                    r->row[nf++] = v;
                    if (t >= le)
                        break;
                    p = dc ? t + 1 : t;
                    continue;
                }
            }
        }
        /* general path */
        {
            const char *fp = p;
            k = next_field(r, &fp, le, 1, &f, nf + 1);
            if (k < 0)
                return r->saved.status;
            p = fp;
        }
        s = field_text(r, &f, &e);
        if (!s)
            return r->saved.status;
        if (s == e || is_na(r, s, e)) {
            if (!r->na) {
                if (s == e)
                    POS_FAIL(r, TSU_IO_ERR_NUMBER, f.at, nf + 1, "empty field");
            } else {
                r->row[nf++] = (double)NAN;
                r->missing++;
                goto next;
            }
        }
        if (r->is_time[nf]) {
            const char *stop;
            tsu_time_form tf;
            char q[200];
            if (!tsu_parse_time(s, e, &v, &tf, &stop) || stop != e) {
                const char *zn;
                if (zone_name(s, e, &zn))
                    ZONE_FAIL(r, f.at, nf + 1, s, e, zn);
                quote_text(q, sizeof q, s, e);
                POS_FAIL(r, TSU_IO_ERR_TIME, f.at, nf + 1,
                         "not a valid ISO 8601 date or date-time: %s (YYYY-MM-DD[THH:MM[:SS]]"
                         "[Z|+HH:MM])", q);
            }
            if (r->is_time[nf] == 2 || r->rows == 0) {
                r->tform[nf] = tf;
                r->is_time[nf] = 1;
            }
            r->row[nf++] = v;
            goto next;
        }
        k = num_field(r, s, e, &v);
        if (k < 0)
            return r->saved.status;
        if (k != TSU_NUM_OK) {
            const char *stop;
            tsu_time_form tf;
            if (k == TSU_NUM_SYNTAX && r->time_detect && r->rows == 0 &&
                tsu_parse_time(s, e, &v, &tf, &stop) && stop == e) {
                r->is_time[nf] = 1;
                r->tform[nf] = tf;
                r->row[nf++] = v;
                goto next;
            }
            return value_error(r, k, &f, s, e, nf + 1, ls, le);
        }
        r->row[nf++] = v;
    next:
        if (p >= le)
            break;
        if (dc)
            p++;
    }
    if (r->ncols && nf != r->ncols)
        return fields_error(r, ls, le, le, nf);
    if (!r->ncols)
        r->ncols = nf;
    return TSU_IO_OK;
}

/* The next data record (header and blank lines consumed) into r->ls and
 * *le: 1, 0 at the end, -1 on an error (r->saved). */
static int next_record(tsu_reader *r, const char **lep)
{
    while (!r->failed) {
        char *ls, *h;
        const char *le, *p;
        size_t ll;
        int g = get_record(r, &ls, &ll);
        if (g == 0) {
            if (r->rows == 0) {
                (void)RFAIL(r, TSU_IO_ERR_EMPTY, 0, 0, 0, 0,
                            r->seen_content ? "no data rows" : "no data (empty input)");
                break;
            }
            return 0;
        }
        if (g < 0)
            break;
        if (r->rec_line == 1 && ll >= 3 && memcmp(ls, "\xef\xbb\xbf", 3) == 0) {
            ls += 3; /* UTF-8 byte-order mark */
            ll -= 3;
        }
        r->ls = ls;
        le = content_end(r, ls, ls + ll);
        p = ls;
        while (p < le && IS_BLANK(*p))
            p++;
        if (p == le)
            continue;
        if (r->delim == TSU_DELIM_AUTO) {
            /* the first candidate outside quotes */
            int inq = 0, semi = 0, comma = 0, tab = 0;
            for (h = ls; h < le; h++) {
                if (*h == '"')
                    inq = !inq;
                else if (!inq)
                    semi |= *h == ';', comma |= *h == ',', tab |= *h == '\t';
            }
            r->delim = semi                        ? TSU_DELIM_SEMICOLON
                       : comma && !r->decimal_comma ? TSU_DELIM_COMMA
                       : tab                        ? TSU_DELIM_TAB
                                                    : TSU_DELIM_SPACE;
        }
        if (!r->seen_content) {
            int hd;
            r->seen_content = 1;
            hd = r->header == TSU_HEADER_YES ||
                 (r->header == TSU_HEADER_AUTO && is_header(r, ls, le, NULL) != 0);
            if (r->failed)
                break;
            if (hd) {
                if (read_header(r, ls, le) != TSU_IO_OK)
                    break;
                continue;
            }
            if (r->ncols && set_columns(r, r->ncols) != TSU_IO_OK)
                break;
        }
        *lep = le;
        return 1;
    }
    return -1;
}

tsu_io_status tsu_reader_layout(tsu_reader *r, tsu_io_error *err)
{
    const char *le;
    int g;
    err_clear(err);
    if (!r) {
        err_set(err, TSU_IO_ERR_NULL, 0, NULL, 0, 0, 0, "null argument");
        return TSU_IO_ERR_NULL;
    }
    if (r->failed || r->pending || r->rows)
        goto out;
    g = next_record(r, &le);
    if (g <= 0)
        goto out; /* g == 0 cannot happen before a row: TSU_IO_ERR_EMPTY */
    if (!r->ncols) {
        const char *p = r->ls;
        field f;
        size_t n = 0;
        int k;
        while ((k = next_field(r, &p, le, n == 0, &f, n + 1)) == 1)
            n++;
        if (k < 0 || set_columns(r, n) != TSU_IO_OK)
            goto out; /* a quote error in the first row: reported as such */
    }
    r->pending = 1;
    r->pend_le = le;
    r->row_line = r->rec_line;
out:
    if (r->failed && err)
        *err = r->saved;
    return r->failed ? r->saved.status : TSU_IO_OK;
}

tsu_io_status tsu_reader_use_columns(tsu_reader *r, const size_t *cols, size_t n,
                                     tsu_io_error *err)
{
    size_t need = 1;
    err_clear(err);
    if (!r || (n && !cols)) {
        err_set(err, TSU_IO_ERR_NULL, 0, r ? r->name : NULL, 0, 0, 0, "null argument");
        return TSU_IO_ERR_NULL;
    }
    for (size_t k = 0; k < n; k++)
        if (cols[k] >= need)
            need = cols[k] + 1;
    if (!r->failed && grow_row(r, need) == 0) {
        memset(r->use, 0, r->rowcap);
        for (size_t k = 0; k < n; k++)
            r->use[cols[k]] = 1;
        r->selected = 1;
        return TSU_IO_OK;
    }
    if (err)
        *err = r->saved;
    return r->saved.status;
}

tsu_io_status tsu_reader_next(tsu_reader *r, const double **row, tsu_io_error *err)
{
    err_clear(err);
    if (row)
        *row = NULL;
    if (!r) {
        err_set(err, TSU_IO_ERR_NULL, 0, NULL, 0, 0, 0, "null argument");
        return TSU_IO_ERR_NULL;
    }
    if (!r->failed) {
        const char *le;
        int g = 1;
        if (r->pending) {
            r->pending = 0;
            le = r->pend_le;
        } else {
            g = next_record(r, &le);
        }
        if (g == 0)
            return TSU_IO_END;
        if (g > 0 && parse_data(r, r->ls, le) == TSU_IO_OK) {
            r->rows++;
            r->row_line = r->rec_line;
            if (row)
                *row = r->row;
            return TSU_IO_OK;
        }
    }
    if (err)
        *err = r->saved;
    return r->saved.status;
}

void tsu_reader_field_pos(const tsu_reader *r, size_t j, unsigned long long *line, size_t *col)
{
    *line = r ? r->row_line : 0;
    *col = 0;
    if (r && j < r->ncols && r->fcol && r->rows)
        *col = r->fcol[j] + 1; /* within the record's first line in the usual case */
}

/* ================================================================== */
/* Whole table                                                          */
/* ================================================================== */

void tsu_table_free(tsu_table *t)
{
    size_t j;
    if (!t)
        return;
    if (t->cols)
        for (j = 0; j < t->ncols; j++)
            free(t->cols[j]);
    free(t->cols);
    free_names(t->names, t->names ? t->ncols : 0);
    free(t->lines);
    t->cols = NULL;
    t->names = NULL;
    t->lines = NULL;
    t->nrows = t->ncols = 0;
}

/* Grow every column (and lines) to cap rows. */
static int table_grow(tsu_table *t, size_t cap, int track)
{
    size_t j;
    if (cap > SIZE_MAX / sizeof(double) || cap > SIZE_MAX / sizeof(unsigned long long))
        return TSU_IO_ERR_OVERFLOW;
    for (j = 0; j < t->ncols; j++) {
        double *nc = io_realloc(t->cols[j], cap * sizeof(double));
        if (!nc)
            return TSU_IO_ERR_NOMEM;
        t->cols[j] = nc;
    }
    if (track) {
        unsigned long long *nl = io_realloc(t->lines, cap * sizeof(unsigned long long));
        if (!nl)
            return TSU_IO_ERR_NOMEM;
        t->lines = nl;
    }
    return TSU_IO_OK;
}

tsu_io_status tsu_read_table(FILE *fp, const char *name, const tsu_read_options *opt,
                           tsu_table *out, tsu_io_error *err)
{
    tsu_reader *r;
    tsu_io_status st;
    const double *row;
    size_t cap = 0, n = 0, j;
    int track = opt ? opt->track_lines : 1;
    err_clear(err);
    if (!out) {
        err_set(err, TSU_IO_ERR_NULL, 0, name, 0, 0, 0, "null argument");
        return TSU_IO_ERR_NULL;
    }
    memset(out, 0, sizeof *out);
    st = tsu_reader_open(&r, fp, name, opt, err);
    if (st != TSU_IO_OK)
        return st;
    while ((st = tsu_reader_next(r, &row, err)) == TSU_IO_OK) {
        if (!out->cols) {
            out->ncols = tsu_reader_ncols(r);
            out->cols = io_calloc(out->ncols, sizeof *out->cols);
            if (!out->cols) {
                st = TSU_IO_ERR_NOMEM;
                break;
            }
        }
        if (n == cap) {
            size_t nc = cap ? cap * 2 : 4096;
            if (nc < cap) {
                st = TSU_IO_ERR_OVERFLOW;
                break;
            }
            st = (tsu_io_status)table_grow(out, nc, track);
            if (st != TSU_IO_OK)
                break;
            cap = nc;
        }
        for (j = 0; j < out->ncols; j++)
            out->cols[j][n] = row[j];
        if (track)
            out->lines[n] = tsu_reader_line(r);
        n++;
        out->nrows = n;
    }
    if (st == TSU_IO_END) {
        out->names = r->names; /* taken over */
        r->names = NULL;
        r->nnames = 0;
        if (n < cap) { /* give back the spare capacity; failure is harmless */
            for (j = 0; j < out->ncols; j++) {
                double *nc = io_realloc(out->cols[j], n * sizeof(double));
                if (nc)
                    out->cols[j] = nc;
            }
            if (track) {
                unsigned long long *nl = io_realloc(out->lines, n * sizeof(unsigned long long));
                if (nl)
                    out->lines = nl;
            }
        }
        tsu_reader_free(r);
        return TSU_IO_OK;
    }
    if (st == TSU_IO_ERR_NOMEM || st == TSU_IO_ERR_OVERFLOW) {
        if (err && err->status == TSU_IO_OK)
            err_set(err, st, 0, r->name, 0, 0, 0, "%s",
                    st == TSU_IO_ERR_NOMEM ? "out of memory" : "size overflow");
    }
    tsu_reader_free(r);
    tsu_table_free(out);
    return st;
}

tsu_io_status tsu_read_table_path(const char *path, const tsu_read_options *opt, tsu_table *out,
                                tsu_io_error *err)
{
    FILE *fp;
    tsu_io_status st;
    err_clear(err);
    if (out)
        memset(out, 0, sizeof *out);
    if (!path || !out) {
        err_set(err, TSU_IO_ERR_NULL, 0, path, 0, 0, 0, "null argument");
        return TSU_IO_ERR_NULL;
    }
    if (strcmp(path, "-") == 0)
        return tsu_read_table(stdin, "<stdin>", opt, out, err);
    fp = fopen(path, "rb");
    if (!fp) {
        int e = errno;
        err_set(err, TSU_IO_ERR_OPEN, e, path, 0, 0, 0, "cannot open: %s", strerror(e));
        return TSU_IO_ERR_OPEN;
    }
    st = tsu_read_table(fp, path, opt, out, err);
    fclose(fp);
    return st;
}

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

/* Temporary files open now, removed by the handler of SIGINT, SIGTERM and
 * SIGHUP (unlink is async-signal-safe), which then re-raises the signal with
 * its default action, so the exit status is still the signal's. */
#define OUT_SLOTS 16
static char *volatile out_temps[OUT_SLOTS];
static volatile sig_atomic_t out_handlers_set;
static const int out_signals[3] = {SIGINT, SIGTERM, SIGHUP};

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

static void out_register(char *tmp)
{
    if (!out_handlers_set) {
        out_handlers_set = 1;
        for (int k = 0; k < 3; k++) {
            struct sigaction old, sa;
            /* a signal the caller ignores stays ignored */
            if (sigaction(out_signals[k], NULL, &old) == 0 && old.sa_handler == SIG_IGN)
                continue;
            memset(&sa, 0, sizeof sa);
            sa.sa_handler = out_on_signal;
            sigemptyset(&sa.sa_mask);
            for (int j = 0; j < 3; j++)
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
    o = io_calloc(1, sizeof *o);
    if (!o || !(o->path = dup_str(path, n))) {
        free(o);
        msg_set(errbuf, errlen, "out of memory");
        return ENOMEM;
    }
    o->flags = flags;
    if (strcmp(path, "-") == 0) {
        o->fp = stdout;
        o->is_std = 1;
        *out = o;
        return 0;
    }
    if (n > SIZE_MAX - 16 || !(o->tmp = io_malloc(n + 16))) {
        out_free(o);
        msg_set(errbuf, errlen, "out of memory");
        return ENOMEM;
    }
    memcpy(o->tmp, path, n);
    memcpy(o->tmp + n, ".tmp.XXXXXX", 12);
    {
        /* no SIGINT/SIGTERM/SIGHUP between creating the file and registering
         * it for the handler (a signal there left the temporary file behind) */
        sigset_t block, prev;
        sigemptyset(&block);
        for (int k = 0; k < 3; k++)
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
        dir = dup_str(".", 1);
    else
        dir = dup_str(path, slash == path ? 1 : (size_t)(slash - path));
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
    w = io_malloc(sizeof *w);
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
