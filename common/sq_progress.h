/* semquad — progress of the stages that loop (tracing, patch meshing,
 * relaxation, writing), reported to the library caller's callback
 * (sq_options.progress, include/semquad.h): `done` of `total` units of the
 * named stage.  A stage reports when done changes; one that ends early
 * (a relaxation that converged) may stop short of total. */
#ifndef SQ_PROGRESS_H
#define SQ_PROGRESS_H

typedef struct {
    void (*fn)(void *data, const char *stage, long done, long total); /* NULL: silent */
    void *data;
} sq_progress;

static inline void sq_progress_report(const sq_progress *p, const char *stage, long done,
                                      long total)
{
    if (p && p->fn) p->fn(p->data, stage, done, total);
}

/* For a loop over many items (a writer's nodes and elements): reports
 * `done` of `total` when done is 0, a multiple of a hundredth of total
 * (rounded up) or total, so at most 102 events whatever total is, at the
 * same counts on every run. */
static inline void sq_progress_every(const sq_progress *p, const char *stage, long done, long total)
{
    long step = total > 100 ? (total + 99) / 100 : 1;
    if (done % step == 0 || done == total) sq_progress_report(p, stage, done, total);
}

#endif
