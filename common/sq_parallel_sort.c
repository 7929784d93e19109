/* semquad — runs sorted and merged on threads (sq_parallel_sort.h). */
#include "sq_parallel_sort.h"

#include "sq_parallel.h"

#include <stdlib.h>
#include <string.h>

/* items per run below which one qsort is quicker than threads */
#define SORT_GRAIN 4096

typedef struct {
    char *src, *dst;     /* the runs, and where a round merges them */
    const size_t *bound; /* run r is items [bound[r], bound[r + 1]) */
    long runs;
    size_t size;
    sq_compare_fn cmp;
} sort_job;

static sq_status sort_runs(void *ctx, long begin, long end, sq_error *err)
{
    (void)err;
    const sort_job *j = ctx;
    for (long r = begin; r < end; r++)
        qsort(j->src + j->bound[r] * j->size, j->bound[r + 1] - j->bound[r], j->size, j->cmp);
    return SQ_OK;
}

/* Runs 2p and 2p + 1 of src into dst at the same place (a last odd run
 * copied); the left run's item first on a tie, as a stable merge. */
static sq_status merge_pairs(void *ctx, long begin, long end, sq_error *err)
{
    (void)err;
    const sort_job *j = ctx;
    size_t sz = j->size;
    for (long p = begin; p < end; p++) {
        size_t a = j->bound[2 * p], mid = j->bound[2 * p + 1 < j->runs ? 2 * p + 1 : j->runs];
        size_t b = j->bound[2 * p + 2 < j->runs ? 2 * p + 2 : j->runs], i = a, k = mid, o = a;
        while (i < mid && k < b) {
            const char *x = j->src + i * sz, *y = j->src + k * sz;
            int left = j->cmp(x, y) <= 0;
            memcpy(j->dst + o++ * sz, left ? x : y, sz);
            i += left;
            k += !left;
        }
        memcpy(j->dst + o * sz, j->src + i * sz, (mid - i) * sz);
        o += mid - i;
        memcpy(j->dst + o * sz, j->src + k * sz, (b - k) * sz);
    }
    return SQ_OK;
}

sq_status sq_parallel_sort(int threads, void *base, size_t n, size_t size, sq_compare_fn cmp,
                           sq_error *err)
{
    long runs = sq_threads_resolve(threads);
    if ((size_t)runs > n / SORT_GRAIN) runs = (long)(n / SORT_GRAIN);
    if (runs <= 1) {
        qsort(base, n, size, cmp);
        return SQ_OK;
    }
    size_t *bound = malloc(((size_t)runs + 1) * sizeof *bound);
    char *tmp = malloc(n * size);
    if (!bound || !tmp) {
        free(bound), free(tmp);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    }
    for (long r = 0; r <= runs; r++) bound[r] = n * (size_t)r / (size_t)runs;
    sort_job j = {base, tmp, bound, runs, size, cmp};
    sq_status st = sq_parallel_for(threads, runs, 1, sort_runs, &j, err);
    while (st == SQ_OK && j.runs > 1) {
        long pairs = (j.runs + 1) / 2;
        st = sq_parallel_for(threads, pairs, 1, merge_pairs, &j, err);
        /* the merged runs' bounds: every other one */
        for (long p = 0; p <= pairs; p++) bound[p] = bound[2 * p < j.runs ? 2 * p : j.runs];
        j.runs = pairs;
        char *s = j.src;
        j.src = j.dst, j.dst = s;
    }
    if (st == SQ_OK && j.src != base) memcpy(base, j.src, n * size);
    free(bound), free(tmp);
    return st;
}
