/* semquad tests — shared set-up for the tracing tests t50x: the guiding
 * field of an example, its singular points and corner valences, traced. */
#ifndef T50X_TRACE_H
#define T50X_TRACE_H

#include "field_analysis.h"
#include "test_util.h"
#include "trace.h"

#include <gsl/gsl_errno.h>

typedef struct {
    cad_model *model;
    cad_face *face;
    sq_field_analysis a;
    sq_singularity *sing;
    int *quads;
    sq_cross_field cf;
} t5_case;

static inline void t5_open(t5_case *c, const char *file, int order)
{
    char path[4096];
    sq_error err;
    memset(c, 0, sizeof *c);
    sq_test_path(path, sizeof path, 0, file);
    SQ_TEST_OK(cad_model_read(path, &c->model, &err), err);
    SQ_TEST_OK(cad_face_create(c->model, 0, &c->face, &err), err);
    sq_field_options fo;
    sq_field_options_default(&fo);
    fo.order = order;
    fo.tri.order = order;
    SQ_TEST_OK(sq_field_analyse(c->face, &fo, &c->a, &err), err);
    c->sing = calloc(c->a.npoints + 1, sizeof *c->sing);
    c->quads = calloc(c->a.info.nvertices + 1, sizeof *c->quads);
    for (int k = 0; k < c->a.npoints; k++) {
        c->sing[k].x = c->a.points[k].x;
        c->sing[k].y = c->a.points[k].y;
        c->sing[k].valence = c->a.points[k].valence;
        c->sing[k].origin = SQ_ORIGIN_CRITICAL;
    }
    for (int k = 0; k < c->a.info.nvertices; k++) c->quads[k] = c->a.corners[k].valence;
    c->cf = sq_guiding_cross_field(&c->a.field);
}

static inline void t5_close(t5_case *c)
{
    free(c->sing);
    free(c->quads);
    sq_field_analysis_free(&c->a);
    cad_face_free(&c->face);
    cad_model_free(&c->model);
}

/* Every separatrix ends on the boundary (exactly on its CAD edge, at
 * edge(s)), at a face vertex or at a singular point (exactly), and is
 * shorter than the length bound. */
static inline int t5_check_ends(const char *ctx, const t5_case *c, const sq_separatrix_set *set,
                                double max_length)
{
    int fails = 0;
    sq_error err;
    for (int k = 0; k < set->n; k++) {
        const sq_separatrix *s = &set->s[k];
        const double *p = &s->xy[2 * (s->npts - 1)];
        char what[128];
        snprintf(what, sizeof what, "separatrix %d ended (kind != open)", k);
        fails += sq_check_int(ctx, what, s->end.kind != SQ_END_OPEN, 1);
        snprintf(what, sizeof what, "separatrix %d length below the bound", k);
        fails += sq_check_int(ctx, what, sq_separatrix_length(s) < max_length, 1);
        if (s->end.kind == SQ_END_BOUNDARY) {
            double d, q[2];
            SQ_TEST_OK(cad_face_edge_project(c->face, s->end.id, p, NULL, NULL, &d, &err), err);
            SQ_TEST_OK(cad_face_edge_eval(c->face, s->end.id, s->end.s, q, NULL, NULL, &err), err);
            snprintf(what, sizeof what, "separatrix %d: distance of its end from CAD edge %d", k,
                     s->end.id);
            /* the end is the edge's point at s (snapped): a few U */
            fails += sq_check_abs(ctx, what, d, 0.0, 1e-12);
            snprintf(what, sizeof what, "separatrix %d: end - edge(s)", k);
            fails += sq_check_abs(ctx, what, hypot(q[0] - p[0], q[1] - p[1]), 0.0, 1e-12);
        } else if (s->end.kind == SQ_END_SINGULAR) {
            snprintf(what, sizeof what, "separatrix %d: end - its singular point", k);
            fails += sq_check_abs(ctx, what, hypot(p[0] - c->sing[s->end.id].x, p[1] - c->sing[s->end.id].y), 0.0, 0.0);
        } else if (s->end.kind == SQ_END_CORNER) {
            const sq_vertex *v = &c->a.info.vertices[s->end.id];
            snprintf(what, sizeof what, "separatrix %d: end - its vertex", k);
            fails += sq_check_abs(ctx, what, hypot(p[0] - v->x, p[1] - v->y), 0.0, 0.0);
        }
    }
    return fails;
}

#endif
