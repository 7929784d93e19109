/* semquad — loops split across threads with output independent of their
 * number: items [0, n) cut into contiguous ranges, each range run by one
 * thread, every item writing only its own results.  A caller that needs a
 * sum or a minimum keeps one value per item and reduces them afterwards
 * in item order, so no result depends on the schedule (the files are
 * byte-identical for every thread count). */
#ifndef SQ_PARALLEL_H
#define SQ_PARALLEL_H

#include "sq_status.h"

/* Items [begin, end) of the loop; err is this range's own record. */
typedef sq_status (*sq_range_fn)(void *ctx, long begin, long end, sq_error *err);

/* Threads to use for a request of `threads`: itself when positive, else
 * the processors online (at least 1). */
int sq_threads_resolve(int threads);

/* A request of `threads` (resolved as above) shared by n items that run
 * at once and have parallel loops of their own (the faces of a domain):
 * the threads over the items (at most n, at least 1), and in *inner the
 * threads each item's own loops take, so that no more than the request
 * run in all. */
int sq_threads_nested(int threads, long n, int *inner);

/* fn over [0, n) on `threads` threads (resolved as above), in ranges of
 * at least `grain` items (fewer threads when n is small; one range runs
 * on the calling thread).  The status of the failing range with the
 * lowest items, its error in err. */
sq_status sq_parallel_for(int threads, long n, long grain, sq_range_fn fn, void *ctx,
                          sq_error *err);

#endif
