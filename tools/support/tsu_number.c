/* tsu_io numbers: correctly rounded decimal -> double and the shortest
 * round-trip double -> decimal (see tsu_io.h, 1. Numbers). */
#define _POSIX_C_SOURCE 200809L

#include "tsu_io_internal.h"

#include <errno.h>
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

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
