/* semquad sem/ — global numbering of the C0 modal space (cg_space.h). */
#include "cg_space.h"

#include "cg_basis.h"

#include <stdlib.h>

sq_status sem_cg_space_create(const sem_tri_mesh *mesh, int P, sem_cg_space **out, sq_error *err)
{
    if (!out) return SQ_FAIL(err, SQ_ERR_USAGE, "cg_space_create: NULL output");
    *out = NULL;
    if (!mesh || P < 1) return SQ_FAIL(err, SQ_ERR_USAGE, "cg_space_create: bad arguments");
    const int nt = mesh->ntris;
    sem_cg_space *s = calloc(1, sizeof *s);
    long *vdof = malloc(sizeof(long) * ((size_t)mesh->nverts + 1));
    if (!s || !vdof) goto oom;
    s->P = P;
    s->nb = 3 * P;
    s->ni = (P - 1) * (P - 2) / 2;
    s->bmap = malloc(sizeof(long) * ((size_t)nt * s->nb + 1));
    s->bsign = malloc((size_t)nt * s->nb + 1);
    s->edge = malloc(sizeof(long) * (3 * (size_t)nt + 1));
    if (!s->bmap || !s->bsign || !s->edge) goto oom;

    /* vertices used by some triangle, in order of first use */
    for (int v = 0; v < mesh->nverts; ++v) vdof[v] = -1;
    long nv = 0;
    for (size_t h = 0; h < 3 * (size_t)nt; ++h) {
        const int v = mesh->tri[h];
        if (v < 0 || v >= mesh->nverts) {
            free(vdof);
            sem_cg_space_free(&s);
            return SQ_FAIL(err, SQ_ERR_USAGE, "cg_space_create: triangle %zu has vertex %d", h / 3, v);
        }
        if (vdof[v] < 0) vdof[v] = nv++;
    }
    s->nvdofs = nv;

    /* edges: numbered by the lower-indexed element; the other side finds
     * its twin by the neighbour and the shared vertices */
    long ne = 0;
    for (int t = 0; t < nt; ++t)
        for (int k = 0; k < 3; ++k) {
            const int nb = mesh->neigh[3 * t + k];
            if (nb < 0 || nb > t) {
                s->edge[3 * t + k] = ne++;
                continue;
            }
            const int a = mesh->tri[3 * t + k], b = mesh->tri[3 * t + (k + 1) % 3];
            long found = -1;
            for (int j = 0; j < 3; ++j) {
                const int c = mesh->tri[3 * nb + j], d = mesh->tri[3 * nb + (j + 1) % 3];
                if (mesh->neigh[3 * nb + j] == t && ((c == a && d == b) || (c == b && d == a)))
                    found = s->edge[3 * nb + j];
            }
            if (found < 0) {
                free(vdof);
                sem_cg_space_free(&s);
                return SQ_FAIL(err, SQ_ERR_USAGE,
                               "cg_space_create: neighbours of triangles %d and %d disagree", t, nb);
            }
            s->edge[3 * t + k] = found;
        }
    s->nedges = ne;
    s->nbdofs = nv + ne * (P - 1);
    s->ndofs = s->nbdofs + (long)nt * s->ni;

    for (int t = 0; t < nt; ++t) {
        long *map = s->bmap + (size_t)t * s->nb;
        signed char *sg = s->bsign + (size_t)t * s->nb;
        for (int k = 0; k < 3; ++k) {
            map[k] = vdof[mesh->tri[3 * t + k]];
            sg[k] = 1;
        }
        for (int k = 0; k < 3; ++k) {
            const int forward = mesh->tri[3 * t + k] < mesh->tri[3 * t + (k + 1) % 3];
            for (int p = 1; p <= P - 1; ++p) {
                const int i = sem_cg_edge_mode(P, k, p);
                map[i] = nv + s->edge[3 * t + k] * (P - 1) + p - 1;
                sg[i] = (signed char)sem_cg_edge_sign(p, forward);
            }
        }
    }
    free(vdof);
    *out = s;
    return SQ_OK;
oom:
    free(vdof);
    sem_cg_space_free(&s);
    return SQ_FAIL(err, SQ_ERR_INTERNAL, "cg_space_create: out of memory (%d triangles)", nt);
}

void sem_cg_space_free(sem_cg_space **s)
{
    if (!s || !*s) return;
    free((*s)->bmap);
    free((*s)->bsign);
    free((*s)->edge);
    free(*s);
    *s = NULL;
}
