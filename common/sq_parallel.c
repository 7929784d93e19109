/* semquad — contiguous ranges on POSIX threads (sq_parallel.h). */
#define _POSIX_C_SOURCE 200809L
#include "sq_parallel.h"

#include <omp.h>
#include <pthread.h>
#include <stdlib.h>
#include <unistd.h>

/* more threads than this are not asked for (a range's record each) */
#define PAR_MAX_THREADS 256

typedef struct {
    sq_range_fn fn;
    void *ctx;
    long begin, end;
    int omp_levels; /* the caller's omp_get_max_active_levels() */
    sq_status st;
    sq_error err;
} par_range;

static void *run_range(void *arg)
{
    par_range *r = arg;
    /* a POSIX thread starts with OpenMP's initial settings, not its
     * creator's (libgomp): the caller's limit on nested parallel regions
     * kept, so that CHOLMOD's supernodal loops, which the command runs on
     * the calling thread (src/cli/main.c), start no team of their own in
     * each of these threads */
    omp_set_max_active_levels(r->omp_levels);
    r->st = r->fn(r->ctx, r->begin, r->end, &r->err);
    return NULL;
}

int sq_threads_resolve(int threads)
{
    if (threads > 0) return threads < PAR_MAX_THREADS ? threads : PAR_MAX_THREADS;
    long n = sysconf(_SC_NPROCESSORS_ONLN);
    return n < 1 ? 1 : n < PAR_MAX_THREADS ? (int)n : PAR_MAX_THREADS;
}

int sq_threads_nested(int threads, long n, int *inner)
{
    int t = sq_threads_resolve(threads);
    int outer = n < 1 ? 1 : n < t ? (int)n : t;
    *inner = t / outer;
    return outer;
}

sq_status sq_parallel_for(int threads, long n, long grain, sq_range_fn fn, void *ctx,
                          sq_error *err)
{
    if (n <= 0) return SQ_OK;
    long t = sq_threads_resolve(threads);
    if (grain < 1) grain = 1;
    if (t > n / grain) t = n / grain;
    if (t <= 1) return fn(ctx, 0, n, err);
    par_range *r = calloc((size_t)t, sizeof *r);
    pthread_t *id = calloc((size_t)t, sizeof *id);
    char *started = calloc((size_t)t, 1);
    if (!r || !id || !started) {
        free(r), free(id), free(started);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    }
    int levels = omp_get_max_active_levels();
    for (long k = 0; k < t; k++)
        r[k] = (par_range){fn, ctx, n * k / t, n * (k + 1) / t, levels, SQ_OK, {0}};
    /* ranges 1.. on new threads, range 0 here; a range whose thread could
     * not start runs here too */
    for (long k = 1; k < t; k++) started[k] = pthread_create(&id[k], NULL, run_range, &r[k]) == 0;
    run_range(&r[0]);
    for (long k = 1; k < t; k++) {
        if (started[k]) pthread_join(id[k], NULL);
        else run_range(&r[k]);
    }
    sq_status st = SQ_OK;
    for (long k = 0; k < t && st == SQ_OK; k++)
        if (r[k].st != SQ_OK) {
            st = r[k].st;
            if (err) *err = r[k].err;
        }
    free(r), free(id), free(started);
    return st;
}
