/* semquad public API: the faces of a domain meshed on threads
 * (sq_api_faces_mesh; docs/domains.md "Threads").  Each face's field,
 * layout and mesh depend only on the face and on what the domain asks of
 * it (held edges, chord counts), so the faces run as the items of one
 * sq_parallel_for; each writes only its own mesh, log lines and status,
 * and these are taken in face order afterwards: the meshes, the report
 * and the log's order are those of a serial run for every thread count
 * (with one thread the lines are said as they come). */
#include "api_private.h"
#include "sq_parallel.h"

#include <stdlib.h>
#include <string.h>

/* One face's log lines, kept until the faces before it have said theirs
 * (faces meshed at once). */
typedef struct {
    sq_log_level level;
    char *text;
} kept_line;

typedef struct {
    int n, cap;
    kept_line *line;
    int lost; /* out of memory while keeping one: said when replayed */
} kept_log;

static void keep_line(void *data, sq_log_level level, const char *text)
{
    kept_log *l = data;
    if (l->n == l->cap) {
        int cap = l->cap ? 2 * l->cap : 16;
        kept_line *v = realloc(l->line, sizeof *v * (size_t)cap);
        if (!v) {
            l->lost++;
            return;
        }
        l->line = v, l->cap = cap;
    }
    char *t = strdup(text);
    if (!t) {
        l->lost++;
        return;
    }
    l->line[l->n++] = (kept_line){level, t};
}

static void replay(const sq_options *o, const kept_log *l)
{
    for (int k = 0; k < l->n; k++) sq_api_log(o, l->line[k].level, "%s", l->line[k].text);
    if (l->lost) sq_api_log(o, SQ_LOG_WARNING, "%d log lines lost (out of memory)", l->lost);
}

static void kept_log_free(kept_log *l)
{
    for (int k = 0; k < l->n; k++) free(l->line[k].text);
    free(l->line);
}

typedef struct {
    const sq_model *m;
    const int *faces;
    sq_options o; /* the caller's, the mesh stage's threads its share */
    int keep;     /* 1: the log lines kept (faces at once), 0: said as they come */
    int *const *held, *const *minc;
    sq_mesh **out;
    kept_log *log;
    sq_status *st;
} faces_work;

/* Faces [begin, end) in order, stopping at the first that fails (as a
 * serial run would: the faces after it are not meshed). */
static sq_status mesh_range(void *ctx, long begin, long end, sq_error *err)
{
    faces_work *w = ctx;
    for (long i = begin; i < end; i++) {
        sq_options o = w->o;
        if (w->keep && o.log) o.log = keep_line, o.log_data = &w->log[i];
        w->st[i] = sq_api_face_mesh(w->m, w->faces[i], &o, w->held ? w->held[i] : NULL,
                                    w->minc ? w->minc[i] : NULL, NULL, &w->out[i], err);
        if (w->st[i] != SQ_OK) return w->st[i];
    }
    return SQ_OK;
}

sq_status sq_api_faces_mesh(const sq_model *m, int n, const int *faces, const sq_options *o,
                            int *const *held, int *const *minc, sq_mesh **out, sq_error *err)
{
    if (n <= 0) return SQ_OK;
    int inner, outer = sq_threads_nested(o->threads, n, &inner);
    faces_work w = {m, faces, *o, outer > 1, held, minc, out, calloc((size_t)n, sizeof *w.log),
                    calloc((size_t)n, sizeof *w.st)};
    if (!w.log || !w.st) {
        free(w.log), free(w.st);
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    }
    /* the log lines and progress events of faces meshed at once would
     * interleave: lines kept, events sent only when one runs at a time */
    w.o.threads = inner;
    if (outer > 1) w.o.progress = NULL;
    sq_status st = sq_parallel_for(outer, n, 1, mesh_range, &w, err);
    /* the lines of the faces up to the first failure, as a serial run says them */
    for (int i = 0; i < n; i++) {
        replay(o, &w.log[i]);
        if (w.st[i] != SQ_OK) break;
    }
    for (int i = 0; i < n; i++) kept_log_free(&w.log[i]);
    if (st != SQ_OK)
        for (int i = 0; i < n; i++) sq_mesh_free(&out[i]);
    free(w.log), free(w.st);
    return st;
}
