/* semquad public API: convergence study of the sem/ solvers on a face
 * with an exact harmonic solution (`semquad converge`, converge.h). */
#include "api_private.h"
#include "converge.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

struct sq_study {
    sq_api_face face;
    char solution[32];
    sq_converge_result r;
};

static void print_table(FILE *fp, const char *path, int face, const char *solution,
                        const sq_converge_result *r)
{
    fprintf(fp, "%s face %d: u = %s, -lap u = 0, Dirichlet data u on the whole boundary\n", path, face,
           solution);
    fprintf(fp, "method  P         h  tris  geom     dofs     L2 error     H1 error  rate L2  rate H1"
           "   time s\n");
    for (int k = 0; k < r->nruns; k++) {
        const sq_converge_run *u = &r->runs[k];
        fprintf(fp, "%-6s %2d %9.4g %5d %5d %8ld %12.4e %12.4e", u->method == SEM_CG ? "CG" : "DG",
               u->P, u->h, u->ntris, u->geom_order, u->dofs, u->l2, u->h1);
        const sq_converge_run *v = k > 0 ? &r->runs[k - 1] : NULL;
        if (v && u->size_index > 0 && v->P == u->P && v->method == u->method &&
            u->dofs != v->dofs) {
            /* e ~ h_eff^rate with h_eff = dofs^(-1/2) */
            const double dl = 0.5 * log((double)u->dofs / (double)v->dofs);
            fprintf(fp, " %8.2f %8.2f", log(v->l2 / u->l2) / dl, log(v->h1 / u->h1) / dl);
        } else {
            fprintf(fp, " %8s %8s", "", "");
        }
        fprintf(fp, " %8.3f\n", u->seconds);
    }
    if (r->nsizes > 1) {
        fprintf(fp, "observed h-rates (least squares over the sizes, h_eff = dofs^-1/2):\n");
        for (int k = 0; k < r->nruns; k += r->nsizes) {
            const sq_converge_run *u = &r->runs[k];
            double a, b;
            if (sq_converge_rate(r, u->method, u->P, 0, &a) ||
                sq_converge_rate(r, u->method, u->P, 1, &b))
                continue;
            fprintf(fp, "  %s P=%-2d L2 %.2f (P+1 = %d)  H1 %.2f (P = %d)\n",
                   u->method == SEM_CG ? "CG" : "DG", u->P, a, u->P + 1, b, u->P);
        }
    }
}

sq_status sq_face_converge(const sq_model *m, int face, const sq_options *o, sq_study **out,
                           sq_error *err)
{
    *out = NULL;
    sq_options def;
    o = sq_api_options(o, &def);
    sq_converge_options co;
    sq_converge_options_default(&co);
    SQ_TRY(sq_api_study_methods(o, &co.methods, err));
    if (o->study_solution) co.solution = o->study_solution;
    if (o->study_pmin) co.pmin = o->study_pmin;
    if (o->study_pmax) co.pmax = o->study_pmax;
    co.nsizes = o->study_nsizes;
    co.sizes = o->study_sizes;
    co.geom_order = o->study_geom_order;
    sq_study *s = calloc(1, sizeof *s);
    if (!s) return SQ_FAIL(err, SQ_ERR_INTERNAL, "out of memory");
    snprintf(s->solution, sizeof s->solution, "%s", co.solution);
    sq_status st = sq_api_face_open(m, face, o, &s->face, err);
    if (st == SQ_OK) st = sq_converge_study(s->face.cad, &co, &s->r, err);
    if (st != SQ_OK) {
        sq_study_free(&s);
        return st;
    }
    *out = s;
    return SQ_OK;
}

void sq_study_free(sq_study **s)
{
    if (!s || !*s) return;
    sq_converge_result_free(&(*s)->r);
    sq_api_face_close(&(*s)->face);
    free(*s);
    *s = NULL;
}

sq_status sq_study_describe(const sq_study *s, char **text, sq_error *err)
{
    sq_api_text x;
    SQ_TRY(sq_api_text_open(&x, err));
    print_table(x.fp, s->face.model->path, s->face.index, s->solution, &s->r);
    return sq_api_text_close(&x, text, err);
}

sq_status sq_study_write(const sq_study *s, const char *path, sq_error *err)
{
    if (sq_api_ends_with(path, ".csv")) return sq_converge_write_csv(path, &s->r, err);
    if (!sq_api_ends_with(path, ".svg"))
        return SQ_FAIL(err, SQ_ERR_USAGE, "%s: unknown study format (use .csv or .svg)", path);
    const char *in = s->face.model->path, *base = strrchr(in, '/');
    char title[256];
    snprintf(title, sizeof title, "%s, u = %s: %s-refinement", base ? base + 1 : in, s->solution,
             s->r.nsizes > 1 ? "h" : "p");
    return sq_converge_write_svg(path, &s->r, title, err);
}
