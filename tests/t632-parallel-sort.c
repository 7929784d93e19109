/* t632: sq_parallel_sort (common/sq_parallel_sort.h) gives qsort's array,
 * byte for byte, for every thread count: records (key, id) ordered by key
 * then id (a total order; keys from a small range, so most of them tie on
 * the key) and bare 64-bit keys with many repeats (equal items, identical
 * bytes), at sizes below one run, at run multiples and between them, on
 * 1..5 and 7 threads (odd numbers of runs leave a run over in a merge
 * round). */
#include "sq_parallel_sort.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    int key, id;
} record;

static uint64_t rng = 0x2545f4914f6cdd1du;
static uint64_t next(void)
{
    rng ^= rng << 13, rng ^= rng >> 7, rng ^= rng << 17;
    return rng;
}

static int cmp_record(const void *pa, const void *pb)
{
    const record *a = pa, *b = pb;
    if (a->key != b->key) return a->key < b->key ? -1 : 1;
    return (a->id > b->id) - (a->id < b->id);
}

static int cmp_u64(const void *pa, const void *pb)
{
    uint64_t a = *(const uint64_t *)pa, b = *(const uint64_t *)pb;
    return (a > b) - (a < b);
}

static int failed;

/* base[n] sorted on each thread count against qsort's copy. */
static void check(const void *base, size_t n, size_t size, sq_compare_fn cmp, const char *what)
{
    static const int threads[] = {1, 2, 3, 4, 5, 7};
    char *want = malloc(n * size + 1), *got = malloc(n * size + 1);
    if (!want || !got) exit(1);
    memcpy(want, base, n * size);
    qsort(want, n, size, cmp);
    for (size_t t = 0; t < sizeof threads / sizeof *threads; t++) {
        memcpy(got, base, n * size);
        sq_error err = {0};
        sq_status st = sq_parallel_sort(threads[t], got, n, size, cmp, &err);
        if (st != SQ_OK || memcmp(got, want, n * size)) {
            fprintf(stderr, "t632: %s, %zu items, %d threads: %s\n", what, n, threads[t],
                    st != SQ_OK ? err.msg : "not qsort's order");
            failed++;
        }
    }
    free(want), free(got);
}

int main(void)
{
    static const size_t sizes[] = {0, 1, 4095, 4096, 8192, 3 * 4096 + 5, 5 * 4096 - 1, 100003};
    for (size_t s = 0; s < sizeof sizes / sizeof *sizes; s++) {
        size_t n = sizes[s];
        record *r = malloc((n + 1) * sizeof *r);
        uint64_t *k = malloc((n + 1) * sizeof *k);
        if (!r || !k) return 1;
        for (size_t i = 0; i < n; i++) {
            r[i] = (record){(int)(next() % 97), (int)i};
            k[i] = next() % (n / 4 + 1); /* each value about 4 times */
        }
        check(r, n, sizeof *r, cmp_record, "records");
        check(k, n, sizeof *k, cmp_u64, "64-bit keys");
        free(r), free(k);
    }
    return failed ? 1 : 0;
}
