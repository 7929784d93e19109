/* t607: sq_format_double and sq_format_long (src/io/format_number.h) against the C library on
 * 10^6 doubles (and sq_format_long on 10^5 longs against "%ld"): the same bytes as snprintf "%.17g", and strtod reads every
 * result back to the same double, bit for bit.  The doubles: random bit
 * patterns (every exponent, subnormals, infinities, NaNs), random values
 * of every magnitude the exact path takes (1e-12 .. 1e45, both signs),
 * mesh-like coordinates in [-10, 10], powers of ten and their neighbours,
 * exact ties at the 17th digit (odd multiples of 2^-(s+1) near 10^(16-s),
 * where v 10^s ends in .5 exactly: ties to even), 17-digit carries
 * (9.99..95 rounding to 10.0..), integers, ±0, the extremes. */
#include "format_number.h"

#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static uint64_t rng = 0x9e3779b97f4a7c15u;
static uint64_t next(void)
{
    rng ^= rng << 13, rng ^= rng >> 7, rng ^= rng << 17;
    return rng;
}
static double uniform(void) { return (double)(next() >> 11) / 9007199254740992.0; }

static long checked, failed;

static void check(double v)
{
    char ours[SQ_DOUBLE_CHARS], libc[64];
    int n = sq_format_double(ours, v);
    snprintf(libc, sizeof libc, "%.17g", v);
    double back = strtod(ours, NULL);
    int same = isnan(v) ? isnan(back) : memcmp(&back, &v, sizeof v) == 0;
    checked++;
    if (strcmp(ours, libc) || n != (int)strlen(ours) || !same) {
        if (failed++ < 10)
            fprintf(stderr, "t607: %a: ours '%s' (length %d), libc '%s'%s\n", v, ours, n, libc,
                    same ? "" : ", does not read back");
    }
}

int main(void)
{
    for (int i = 0; i < 300000; i++) {
        uint64_t b = next();
        double v;
        memcpy(&v, &b, sizeof v);
        check(v);
    }
    for (int i = 0; i < 300000; i++) {
        double v = pow(10.0, -12.0 + 57.0 * uniform());
        check(next() & 1 ? -v : v);
    }
    for (int i = 0; i < 200000; i++) check(20.0 * uniform() - 10.0);
    for (int k = -325; k <= 310; k++) {
        double p = pow(10.0, k);
        check(p), check(-p), check(nextafter(p, 0.0)), check(nextafter(p, INFINITY));
    }
    for (int s = 1; s <= 20; s++) {
        /* v = odd / 2^(s+1) in [10^(15-s), 10^(16-s)): v 10^s = N + 1/2 when
         * 5^s divides the odd numerator (v = (2N+1) / (2 10^s)) */
        double lo = pow(10.0, 15 - s), scale = ldexp(1.0, s + 1);
        if (lo * scale >= 9007199254740992.0) continue;
        uint64_t p5 = 1;
        for (int k = 0; k < s; k++) p5 *= 5;
        for (int i = 0; i < 5000; i++) {
            uint64_t odd = ((uint64_t)(lo * scale / (double)p5) + (next() % 1000000000u)) | 1;
            check((double)(odd * p5) / scale);
        }
    }
    for (int x = -11; x <= 40; x++)
        for (int i = 0; i < 200; i++) check(nextafter(pow(10.0, x) * (1.0 - 5e-18 * i), 0.0));
    for (int i = 0; i < 100000; i++) check((double)(int64_t)(next() >> (next() % 64)));
    double special[] = {0.0, -0.0, 1.0, -1.0, 0.1, 0.5, 1e-4, 9.9999999999999995e-5, 1e16, 1e17,
                        1.7976931348623157e308, 5e-324, 2.2250738585072014e-308, INFINITY, -INFINITY,
                        NAN};
    for (size_t i = 0; i < sizeof special / sizeof *special; i++) check(special[i]);
    for (int i = 0; i < 100000; i++) {
        long v = i < 4 ? (long[]){0, -1, LONG_MAX, LONG_MIN}[i] : (long)next() >> (next() % 64);
        char ours[24], libc[32];
        int n = sq_format_long(ours, v);
        snprintf(libc, sizeof libc, "%ld", v);
        if (n != (int)strlen(libc) || memcmp(ours, libc, (size_t)n)) {
            if (failed++ < 10) fprintf(stderr, "t607: %s: ours '%.*s'\n", libc, n, ours);
        }
        checked++;
    }
    printf("t607: %ld doubles and longs, %ld differ from printf or do not read back\n", checked, failed);
    return failed != 0;
}
