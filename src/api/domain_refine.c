/* semquad public API: a family of a mesh of several faces
 * (docs/convergence-families.md "Domains of several faces").  Each face's
 * mesh (kept in its own frame by sq_model_mesh) is refined on its own CAD
 * face, as one face's family is, and the faces' refined meshes merged as
 * sq_model_mesh merged them (domain.h design 4).  Both faces of a shared
 * curve place a new node at the same arc-length fraction between the same
 * two vertices of the same curve, so the merge finds them one node; the
 * vertices are copied bit for bit and mapped into the domain's frame by
 * the same operations, so every level's vertices are the last's. */
#include "api_private.h"
#include "quad_refine.h"

#include <stdlib.h>
#include <string.h>

/* The faces, their domain, and their current meshes: m's own (borrowed)
 * before the first step, then the last step's (owned). */
typedef struct {
    const sq_api_domain *dom;
    sq_api_faces f;
    sq_domain d;
    sq_quad_mesh **q;
    int owned;
} domain_steps;

static void drop_meshes(domain_steps *s)
{
    for (int k = 0; s->owned && k < s->f.n; k++) sq_quad_mesh_free(&s->q[k]);
}

/* Every face's mesh refined in its frame, merged into *out. */
static sq_status domain_step(void *ctx, const sq_quad_mesh *from, int n, int order, int threads,
                             sq_quad_mesh **out, sq_error *err)
{
    (void)from; /* the merge of the faces' meshes, which are refined instead */
    domain_steps *s = ctx;
    sq_quad_mesh **next = calloc((size_t)s->f.n, sizeof *next);
    sq_status st = next ? SQ_OK : SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    for (int k = 0; k < s->f.n && st == SQ_OK; k++)
        st = sq_quad_mesh_refine(s->f.cad[k], s->q[k], n, order, threads, &next[k], err);
    if (st == SQ_OK) st = sq_domain_merge(&s->d, next, s->dom->face, s->dom->size, out, err);
    if (st == SQ_OK) {
        drop_meshes(s);
        memcpy(s->q, next, sizeof *next * (size_t)s->f.n);
        s->owned = 1;
    } else {
        for (int k = 0; next && k < s->f.n; k++) sq_quad_mesh_free(&next[k]);
    }
    free(next);
    return st;
}

/* h's domain record: m's, its per-quad faces h's, the faces' meshes s's
 * (taken). */
static sq_status refined_domain(const sq_api_domain *a, domain_steps *s, sq_mesh *h,
                                sq_error *err)
{
    int n = a->nfaces;
    SQ_TRY(sq_api_domain_new(h, n, a->ncurves, err));
    sq_api_domain *b = h->dom;
    b->ntags = a->ntags, b->rounds = a->rounds, b->size = a->size;
    memcpy(b->face, a->face, sizeof(int) * (size_t)n);
    memcpy(b->road, a->road, sizeof(char *) * (size_t)n);
    memcpy(b->area, a->area, sizeof(double) * (size_t)n);
    memcpy(b->curves, a->curves, sizeof *b->curves * (size_t)a->ncurves);
    for (int q = 0; q < h->q->nquads; q++) b->quad_face[q] = b->face[h->q->region[q]];
    for (int k = 0; k < n; k++) b->q[k] = s->owned ? s->q[k] : NULL;
    s->owned = 0;
    return SQ_OK;
}

sq_status sq_api_domain_refine(const sq_mesh *m, int levels, int order, const sq_options *o,
                               sq_mesh **out, sq_error *err)
{
    const sq_api_domain *a = m->dom;
    domain_steps s = {.dom = a, .q = calloc((size_t)a->nfaces, sizeof *s.q)};
    sq_quad_mesh *q = NULL;
    sq_status st = s.q ? sq_api_faces_load(m->face.model, a->face, a->nfaces, o, &s.f, err)
                       : SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    /* the same curves, tags and frames as the merge that made m */
    if (st == SQ_OK)
        st = sq_domain_build(a->nfaces, s.f.cad, s.f.info,
                             sq_api_domain_tolerance(m->face.model, a->size), &s.d, err);
    if (st == SQ_OK) {
        memcpy(s.q, a->q, sizeof *s.q * (size_t)a->nfaces);
        st = sq_api_refine_levels(m, levels, order, o, domain_step, &s, &q, err);
    }
    if (st == SQ_OK) st = sq_api_refined_handle(m, q, out, err);
    if (st == SQ_OK) st = refined_domain(a, &s, *out, err);
    if (st != SQ_OK) sq_mesh_free(out);
    drop_meshes(&s);
    free(s.q);
    sq_domain_free(&s.d);
    sq_api_faces_close(&s.f);
    return st;
}
