/* semquad tests — shared checks: silent on success, print what, value,
 * expected and tolerance on failure and return 1 (so failures add up). */
#ifndef SQ_TEST_UTIL_H
#define SQ_TEST_UTIL_H

#include "sq_status.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static inline int sq_check_abs(const char *ctx, const char *what, double got, double want,
                               double tol)
{
    if (fabs(got - want) <= tol) return 0;
    printf("%s: %s = %.17g, expected %.17g (tolerance %g, off by %.3g)\n", ctx, what, got, want,
           tol, got - want);
    return 1;
}

static inline int sq_check_rel(const char *ctx, const char *what, double got, double want,
                               double rtol)
{
    if (fabs(got - want) <= rtol * fabs(want)) return 0;
    printf("%s: %s = %.17g, expected %.17g (relative tolerance %g, off by %.3g relative)\n", ctx,
           what, got, want, rtol, (got - want) / want);
    return 1;
}

static inline int sq_check_int(const char *ctx, const char *what, long got, long want)
{
    if (got == want) return 0;
    printf("%s: %s = %ld, expected %ld\n", ctx, what, got, want);
    return 1;
}

static inline int sq_check_str(const char *ctx, const char *what, const char *got,
                               const char *want)
{
    if (got && !strcmp(got, want)) return 0;
    printf("%s: %s = '%s', expected '%s'\n", ctx, what, got ? got : "(null)", want);
    return 1;
}

/* Abort the test on a failing status, printing the error. */
#define SQ_TEST_OK(expr, err)                                                                      \
    do {                                                                                           \
        if ((expr) != SQ_OK) {                                                                     \
            printf("%s:%d: %s failed: %s\n", __FILE__, __LINE__, #expr, (err).msg);                \
            exit(1);                                                                               \
        }                                                                                          \
    } while (0)

/* The line a test prints when an optional CAD file written by others is
 * absent (tests/README.md, "Optional real geometries"). */
static inline void sq_test_real_missing(const char *path)
{
    printf("%s: not found; to run the checks on the optional real geometries, configure "
           "with -Dreal_geometries=DIR or set SEMQUAD_REAL_GEOMETRIES=DIR (tests/README.md)\n",
           path);
}

/* Path of an example (real = 0: $SQ_EXAMPLES) or of an optional real CAD
 * file (real = 1: $SEMQUAD_REAL_GEOMETRIES).  Returns 0, after printing
 * sq_test_real_missing's line, if that real file is not readable (skip). */
static inline int sq_test_path(char *buf, size_t n, int real, const char *file)
{
    const char *dir = getenv(real ? "SEMQUAD_REAL_GEOMETRIES" : "SQ_EXAMPLES");
    if (!dir) dir = real ? "(SEMQUAD_REAL_GEOMETRIES unset)" : "examples";
    snprintf(buf, n, "%s/%s", dir, file);
    if (!real) return 1;
    FILE *fp = fopen(buf, "rb");
    if (!fp) {
        sq_test_real_missing(buf);
        return 0;
    }
    fclose(fp);
    return 1;
}

#endif
