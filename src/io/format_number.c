#include "format_number.h"

#include <stdint.h>
#include <stdio.h>
#include <string.h>

#define DIGITS 17
#define MAX_SCALE 27 /* 5^27 < 2^63: the scale factors fit one word */

typedef unsigned __int128 u128;

static uint64_t pow5(int k)
{
    uint64_t p = 1;
    while (k-- > 0) p *= 5;
    return p;
}

/* The DIGITS-digit integer part of v 10^s (*trunc) and its value rounded
 * to nearest, ties to even (*round), v = m 2^e exactly; 0 when that leaves
 * 128-bit integers (|s| > MAX_SCALE or shifts too long). */
static int scaled(uint64_t m, int e, int s, uint64_t *trunc, uint64_t *round)
{
    if (s > MAX_SCALE || s < -MAX_SCALE) return 0;
    u128 num = m, den = 1;
    int k = e + s; /* v 10^s = m 5^s 2^k, or m 2^k / 5^-s */
    if (s >= 0) num *= pow5(s);
    else den = pow5(-s);
    if (k >= 0) {
        if (k > 60 || num >> (127 - k)) return 0;
        num <<= k;
    } else {
        if (-k > 62) return 0;
        den <<= -k;
    }
    u128 q = num / den, r = num % den;
    if (q >> 64) return 0;
    *trunc = (uint64_t)q;
    *round = *trunc + (2 * r > den || (2 * r == den && (q & 1)));
    return 1;
}

/* digits d[0..DIGITS) with decimal exponent x, as %g: fixed for
 * -4 <= x < DIGITS, else d.ddde±XX; trailing zeros dropped. */
static int layout(char *out, const char *d, int x)
{
    int nd = DIGITS, n = 0;
    while (nd > 1 && d[nd - 1] == '0') nd--;
    if (x >= -4 && x < DIGITS) {
        if (x < 0) {
            out[n++] = '0', out[n++] = '.';
            for (int z = 0; z < -x - 1; z++) out[n++] = '0';
            memcpy(out + n, d, (size_t)nd), n += nd;
        } else {
            int ni = x + 1;
            memcpy(out + n, d, (size_t)ni), n += ni;
            if (nd > ni) {
                out[n++] = '.';
                memcpy(out + n, d + ni, (size_t)(nd - ni)), n += nd - ni;
            }
        }
    } else {
        out[n++] = d[0];
        if (nd > 1) {
            out[n++] = '.';
            memcpy(out + n, d + 1, (size_t)(nd - 1)), n += nd - 1;
        }
        out[n++] = 'e', out[n++] = x < 0 ? '-' : '+';
        int a = x < 0 ? -x : x;
        if (a >= 100) out[n++] = (char)('0' + a / 100);
        out[n++] = (char)('0' + a / 10 % 10), out[n++] = (char)('0' + a % 10);
    }
    out[n] = '\0';
    return n;
}

int sq_format_double(char *buf, double v)
{
    uint64_t bits;
    memcpy(&bits, &v, sizeof bits);
    int neg = (int)(bits >> 63), be = (int)(bits >> 52 & 0x7ff);
    uint64_t frac = bits & ((UINT64_C(1) << 52) - 1);
    if (be == 0 && frac == 0) {
        strcpy(buf, neg ? "-0" : "0");
        return 1 + neg;
    }
    if (be == 0 || be == 0x7ff) return snprintf(buf, SQ_DOUBLE_CHARS, "%.17g", v);
    uint64_t m = frac | UINT64_C(1) << 52, lo = UINT64_C(10000000000000000), t, r;
    int e = be - 1075;
    /* x = floor(log10 |v|), log10 2 (e + 52) <= log10 |v| < log10 2 (e + 53):
     * this estimate is off by at most one, which the loop corrects */
    int x = (int)((e + 52) * 30103L / 100000 - ((e + 52) < 0));
    for (int tries = 0; tries < 3; tries++) {
        if (!scaled(m, e, DIGITS - 1 - x, &t, &r)) break;
        if (t < lo || t >= 10 * lo) {
            x += t < lo ? -1 : 1;
            continue;
        }
        if (r == 10 * lo) r = lo, x++; /* 9.99..95 rounds up to 10.00.. */
        char d[DIGITS];
        for (int k = DIGITS - 1; k >= 0; k--) d[k] = (char)('0' + r % 10), r /= 10;
        buf[0] = '-';
        return neg + layout(buf + neg, d, x);
    }
    return snprintf(buf, SQ_DOUBLE_CHARS, "%.17g", v);
}

int sq_format_long(char *buf, long v)
{
    char d[24];
    unsigned long u = v < 0 ? 0ul - (unsigned long)v : (unsigned long)v;
    int n = 0, k = 0;
    do d[k++] = (char)('0' + u % 10), u /= 10;
    while (u);
    if (v < 0) buf[n++] = '-';
    while (k) buf[n++] = d[--k];
    return n;
}

int sq_format_xy0(char *buf, double x, double y)
{
    int n = sq_format_double(buf, x);
    buf[n++] = ' ';
    n += sq_format_double(buf + n, y);
    memcpy(buf + n, " 0", 2);
    return n + 2;
}
