/* t208: a CG solver made like another (sem_poisson_create_like) on a mesh
 * cut open along edges, as θ's solver is made from H's (Jezdimirović 2021
 * eq. 15):
 *  - it solves the same system as a solver made from scratch on the cut
 *    mesh: the same coefficients, bit for bit (tolerance 0: the element
 *    matrices are taken over, not recomputed, and the numbering, assembly and
 *    factorization are the same code on the same data, so nothing differs
 *    to round off, on any CPU);
 *  - the work it did, counted where it is done: no element matrix (the
 *    fresh solver computes one per triangle) and one factorization;
 *  - an evaluator of the cut mesh's field built on the uncut mesh's locator
 *    gives the values of one built on its own, bit for bit (the same modal
 *    geometry, from the same nodes);
 *  - the source is taken over (NULL after);
 *  - a mesh with other elements (the source kept), or a DG source, is
 *    refused (usage).
 * Mesh: the curved unit disc of t207 (geometry order 8), cut along the
 * interior edges of a path of elements; pure Neumann data du/dn for
 * u = e^x sin y on every boundary edge, the cut's two sides included. */
#include "field_eval.h"
#include "poisson.h"
#include "test_meshes.h"
#include "test_util.h"
#include "tri_mesh_cut.h"

#include <string.h>

static sem_bc_kind kind_neu(int tag, void *ctx) { (void)tag, (void)ctx; return SEM_BC_NEUMANN; }

/* du/dn of u = e^x sin y */
static double flux(const double x[2], const double n[2], int tag, void *ctx)
{
    (void)tag, (void)ctx;
    const double e = exp(x[0]);
    return e * sin(x[1]) * n[0] + e * cos(x[1]) * n[1];
}

static sem_field *solve(sem_poisson *s, const sem_tri_mesh *m, int P)
{
    sq_error err;
    sem_field *u = NULL;
    sem_poisson_data d = {NULL, NULL, flux, NULL, 0, NULL};
    if (sem_field_create(m, P, 1, &u, &err) != SQ_OK || sem_poisson_solve(s, &d, u, &err) != SQ_OK) {
        printf("t208: solve: %s\n", err.msg);
        sem_field_free(&u);
    }
    return u;
}

int main(void)
{
    const int P = 8;
    sq_error err;
    int fails = 0;
    sem_tri_mesh *disc = tm_disc(1.0, 2, 8), *other = tm_disc(1.0, 3, 8), *cut = NULL;
    if (!disc || !other) return printf("t208: mesh\n"), 1;
    /* cut: the interior edges of elements 0.. until two are cut */
    unsigned char *mark = calloc(3 * (size_t)disc->ntris, 1);
    int ncut = 0;
    for (int h = 0; h < 3 * disc->ntris && ncut < 2; h++)
        if (disc->neigh[h] >= 0) mark[h] = 1, ncut++;
    SQ_TEST_OK(sem_tri_mesh_cut(disc, mark, 7, &cut, NULL, &err), err);
    free(mark);
    fails += sq_check_int("cut", "more vertices than the disc", cut->nverts > disc->nverts, 1);

    sem_poisson *src = NULL, *fresh = NULL, *like = NULL;
    SQ_TEST_OK(sem_poisson_create(disc, P, SEM_CG, kind_neu, NULL, &src, &err), err);
    SQ_TEST_OK(sem_poisson_create(cut, P, SEM_CG, kind_neu, NULL, &fresh, &err), err);
    const sem_poisson_work ws = sem_poisson_work_done(src);
    /* refused: a mesh with other elements, src kept */
    sem_poisson *bad = NULL, *dg = NULL;
    fails += sq_check_int("other mesh", "status",
                          sem_poisson_create_like(&src, other, kind_neu, NULL, &bad, &err),
                          SQ_ERR_USAGE);
    fails += sq_check_int("other mesh", "source kept", src != NULL, 1);
    SQ_TEST_OK(sem_poisson_create_like(&src, cut, kind_neu, NULL, &like, &err), err);
    fails += sq_check_int("like", "source taken over", src == NULL, 1);
    const sem_poisson_work wf = sem_poisson_work_done(fresh), wl = sem_poisson_work_done(like);
    fails += sq_check_int("source", "element matrices", ws.element_matrices, disc->ntris);
    fails += sq_check_int("source", "factorizations", ws.factorizations, 1);
    fails += sq_check_int("fresh", "element matrices", wf.element_matrices, cut->ntris);
    fails += sq_check_int("fresh", "factorizations", wf.factorizations, 1);
    fails += sq_check_int("like", "element matrices", wl.element_matrices, 0);
    fails += sq_check_int("like", "factorizations", wl.factorizations, 1);
    fails += sq_check_int("like", "unknowns", sem_poisson_ndofs(like), sem_poisson_ndofs(fresh));

    sem_field *uf = solve(fresh, cut, P), *ul = solve(like, cut, P);
    if (!uf || !ul) return 1;
    const size_t nc = (size_t)cut->ntris * sem_tri_num_nodes(P);
    fails += sq_check_int("like", "coefficients identical to the fresh solver's",
                          !memcmp(uf->coef, ul->coef, sizeof(double) * nc), 1);

    /* the field on the cut mesh through the uncut mesh's locator */
    sem_locator *loc = NULL;
    sem_field_evaluator *eo = NULL, *es = NULL;
    SQ_TEST_OK(sem_locator_create(disc, &loc, &err), err);
    SQ_TEST_OK(sem_field_evaluator_create(ul, NULL, &eo, &err), err);
    SQ_TEST_OK(sem_field_evaluator_create(ul, loc, &es, &err), err);
    int differ = 0;
    for (int e = 0; e < cut->ntris; e++) {
        double v1, v2, g1[2], g2[2], x1[2], x2[2];
        sem_field_evaluator_eval_ref(eo, e, 0.2, 0.3, &v1, g1, x1);
        sem_field_evaluator_eval_ref(es, e, 0.2, 0.3, &v2, g2, x2);
        differ += v1 != v2 || g1[0] != g2[0] || g1[1] != g2[1] || x1[0] != x2[0] || x1[1] != x2[1];
    }
    fails += sq_check_int("evaluator", "values differing with the uncut mesh's locator", differ, 0);

    /* refused: a DG source */
    SQ_TEST_OK(sem_poisson_create(disc, 2, SEM_DG, kind_neu, NULL, &dg, &err), err);
    fails += sq_check_int("DG source", "status",
                          sem_poisson_create_like(&dg, cut, kind_neu, NULL, &bad, &err), SQ_ERR_USAGE);
    fails += sq_check_int("DG", "factorizations", sem_poisson_work_done(dg).factorizations, 1);
    fails += sq_check_int("DG", "element matrices", sem_poisson_work_done(dg).element_matrices,
                          disc->ntris);

    sem_field_evaluator_free(&eo);
    sem_field_evaluator_free(&es);
    sem_locator_free(&loc);
    sem_field_free(&uf);
    sem_field_free(&ul);
    sem_poisson_free(&src);
    sem_poisson_free(&fresh);
    sem_poisson_free(&like);
    sem_poisson_free(&dg);
    sem_tri_mesh_free(&disc);
    sem_tri_mesh_free(&other);
    sem_tri_mesh_free(&cut);
    if (fails) printf("t208: %d failure(s)\n", fails);
    return fails ? 1 : 0;
}
