/* semquad — periodic links of a quad mesh (quad_mesh.h; docs/domains.md):
 * the nodes of one curve are the images of another's under one rigid
 * motion, kept so through copies and resampling. */
#include "identified_edges.h"
#include "quad_mesh.h"

#include <stdlib.h>
#include <string.h>

void sq_quad_mesh_apply_periodic(sq_quad_mesh *m)
{
    for (int l = 0; l < m->nperiodic; l++) {
        const sq_quad_periodic *p = &m->periodic[l];
        for (int k = 0; k < p->nnodes; k++)
            sq_affine_map(p->affine, &m->xy[2 * (size_t)p->master_node[k]],
                          &m->xy[2 * (size_t)p->node[k]]);
    }
}

sq_status sq_quad_mesh_add_periodic(sq_quad_mesh *m, const sq_quad_periodic *link, sq_error *err)
{
    sq_quad_periodic *p = realloc(m->periodic, sizeof *p * (size_t)(m->nperiodic + 1));
    if (!p) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    m->periodic = p;
    m->periodic[m->nperiodic++] = *link;
    return SQ_OK;
}

sq_status sq_quad_mesh_copy_periodic(sq_quad_mesh *dst, const sq_quad_mesh *src, sq_error *err)
{
    dst->periodic_chi = src->periodic_chi;
    dst->periodic_index = src->periodic_index;
    dst->periodic_irregular = src->periodic_irregular;
    dst->periodic_mesh_index = src->periodic_mesh_index;
    for (int l = 0; l < src->nperiodic; l++) {
        sq_quad_periodic c = src->periodic[l];
        size_t n = (size_t)c.nnodes + 1;
        c.node = malloc(sizeof(int) * n);
        c.master_node = malloc(sizeof(int) * n);
        sq_status st = c.node && c.master_node ? SQ_OK : SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
        if (st == SQ_OK) {
            memcpy(c.node, src->periodic[l].node, sizeof(int) * (size_t)c.nnodes);
            memcpy(c.master_node, src->periodic[l].master_node, sizeof(int) * (size_t)c.nnodes);
            st = sq_quad_mesh_add_periodic(dst, &c, err);
        }
        if (st != SQ_OK) {
            free(c.node), free(c.master_node);
            return st;
        }
    }
    return SQ_OK;
}

void sq_quad_mesh_free_periodic(sq_quad_mesh *m)
{
    for (int l = 0; l < m->nperiodic; l++) free(m->periodic[l].node), free(m->periodic[l].master_node);
    free(m->periodic);
    m->periodic = NULL;
    m->nperiodic = 0;
}
