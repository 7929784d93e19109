#include "nektar_b64z.h"

#include <stdlib.h>
#include <string.h>
#include <zlib.h>

unsigned char *sq_le64_int(unsigned char *p, long long v)
{
    unsigned long long u = (unsigned long long)v;
    for (int k = 0; k < 8; k++) p[k] = (unsigned char)(u >> 8 * k);
    return p + 8;
}

unsigned char *sq_le64_double(unsigned char *p, double v)
{
    long long bits;
    memcpy(&bits, &v, sizeof bits); /* IEEE 754 binary64, as NekDouble */
    return sq_le64_int(p, bits);
}

/* RFC 4648 base64 of b[0..n), n a multiple of 3 (zlib has no encoder). */
static void put_base64(FILE *fp, const unsigned char *b, size_t n)
{
    static const char abc[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    char quad[4];
    for (size_t i = 0; i < n; i += 3) {
        unsigned long w = (unsigned long)b[i] << 16 | (unsigned long)b[i + 1] << 8 | b[i + 2];
        for (int k = 0; k < 4; k++) quad[k] = abc[(w >> (18 - 6 * k)) & 63];
        fwrite(quad, 1, 4, fp);
    }
}

sq_status sq_write_b64z(FILE *fp, const unsigned char *raw, size_t n, sq_error *err)
{
    uLongf len = compressBound((uLong)n);
    unsigned char *z = calloc((size_t)len + 3, 1); /* zeroed: the padding */
    if (!z) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    int zs = compress2(z, &len, raw, (uLong)n, Z_DEFAULT_COMPRESSION);
    if (zs != Z_OK) {
        free(z);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "zlib compress2 failed (%d)", zs);
    }
    put_base64(fp, z, ((size_t)len + 2) / 3 * 3);
    free(z);
    return SQ_OK;
}
