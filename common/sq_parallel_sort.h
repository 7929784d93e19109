/* semquad — an array sorted on threads with the same result for every
 * number of them: contiguous runs sorted each on its own thread, then
 * merged pairwise in rounds, a round's merges on the threads.  The order
 * must be total up to identical items (items that compare equal have the
 * same bytes): then the sorted array is unique, whatever the runs. */
#ifndef SQ_PARALLEL_SORT_H
#define SQ_PARALLEL_SORT_H

#include "sq_status.h"

#include <stddef.h>

typedef int (*sq_compare_fn)(const void *a, const void *b);

/* base[0, n), items of `size` bytes, sorted by cmp on `threads` threads
 * (sq_threads_resolve; one run on small arrays). */
sq_status sq_parallel_sort(int threads, void *base, size_t n, size_t size, sq_compare_fn cmp,
                           sq_error *err);

#endif
