/* semquad converge FILE [--face N] [--solution NAME] [--method cg|dg|both]
 *   [--orders A-B] [--sizes h1,h2,...] [--geom-order G] [--csv out.csv]
 *   [--svg out.svg] [--quiet]: convergence study of the sem/ solvers
 *   (src/converge.h) on a CAD face with an exact harmonic solution. */
#include "cli.h"
#include "converge.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_SIZES 64

/* "A-B" or "A", 1 <= A <= B <= 16 */
static sq_status parse_orders(const char *val, int *a, int *b, sq_error *err)
{
    char *end;
    errno = 0;
    long x = strtol(val, &end, 10), y = x;
    if (!errno && end != val && *end == '-') {
        const char *v2 = end + 1;
        y = strtol(v2, &end, 10);
        if (end == v2) end = (char *)val; /* "3-" is malformed */
    }
    if (errno || end == val || *end || x < 1 || y > 16 || x > y)
        return SQ_FAIL(err, SQ_ERR_USAGE,
                       "--orders expects A-B or A with 1 <= A <= B <= 16, got '%s'", val);
    *a = (int)x;
    *b = (int)y;
    return SQ_OK;
}

static sq_status parse_sizes(const char *val, double *h, int *n, sq_error *err)
{
    const char *p = val;
    *n = 0;
    for (;;) {
        char *end;
        errno = 0;
        double v = strtod(p, &end);
        if (errno || end == p || !isfinite(v) || v <= 0.0 || (*end && *end != ',') ||
            *n == MAX_SIZES)
            return SQ_FAIL(err, SQ_ERR_USAGE,
                           "--sizes expects up to %d positive numbers separated by commas, got "
                           "'%s'", MAX_SIZES, val);
        h[(*n)++] = v;
        if (!*end) return SQ_OK;
        p = end + 1;
    }
}

static void print_table(const char *path, int face, const char *solution,
                        const sq_converge_result *r)
{
    printf("%s face %d: u = %s, -lap u = 0, Dirichlet data u on the whole boundary\n", path, face,
           solution);
    printf("method  P         h  tris  geom     dofs     L2 error     H1 error  rate L2  rate H1"
           "   time s\n");
    for (int k = 0; k < r->nruns; k++) {
        const sq_converge_run *u = &r->runs[k];
        printf("%-6s %2d %9.4g %5d %5d %8ld %12.4e %12.4e", u->method == SEM_CG ? "CG" : "DG",
               u->P, u->h, u->ntris, u->geom_order, u->dofs, u->l2, u->h1);
        const sq_converge_run *v = k > 0 ? &r->runs[k - 1] : NULL;
        if (v && u->size_index > 0 && v->P == u->P && v->method == u->method &&
            u->dofs != v->dofs) {
            /* e ~ h_eff^rate with h_eff = dofs^(-1/2) */
            const double dl = 0.5 * log((double)u->dofs / (double)v->dofs);
            printf(" %8.2f %8.2f", log(v->l2 / u->l2) / dl, log(v->h1 / u->h1) / dl);
        } else {
            printf(" %8s %8s", "", "");
        }
        printf(" %8.3f\n", u->seconds);
    }
    if (r->nsizes > 1) {
        printf("observed h-rates (least squares over the sizes, h_eff = dofs^-1/2):\n");
        for (int k = 0; k < r->nruns; k += r->nsizes) {
            const sq_converge_run *u = &r->runs[k];
            double a, b;
            if (sq_converge_rate(r, u->method, u->P, 0, &a) ||
                sq_converge_rate(r, u->method, u->P, 1, &b))
                continue;
            printf("  %s P=%-2d L2 %.2f (P+1 = %d)  H1 %.2f (P = %d)\n",
                   u->method == SEM_CG ? "CG" : "DG", u->P, a, u->P + 1, b, u->P);
        }
    }
}

sq_status sq_cmd_converge(int argc, char **argv, sq_error *err)
{
    const char *path = NULL, *csv = NULL, *svg = NULL, *val;
    int face = -1, quiet = 0;
    double sizes[MAX_SIZES];
    sq_converge_options opt;
    sq_converge_options_default(&opt);
    for (int i = 0; i < argc; i++) {
        const char *a = argv[i];
        if (!strcmp(a, "--face")) {
            SQ_TRY(sq_cli_value(argc, argv, &i, &val, err));
            SQ_TRY(sq_cli_int(a, val, 0, 1000000, &face, err));
        } else if (!strcmp(a, "--solution")) {
            sem_exact_fn fn;
            SQ_TRY(sq_cli_value(argc, argv, &i, &opt.solution, err));
            SQ_TRY(sq_converge_solution(opt.solution, &fn, err));
        } else if (!strcmp(a, "--method")) {
            SQ_TRY(sq_cli_value(argc, argv, &i, &val, err));
            if (!strcmp(val, "cg")) opt.methods = SQ_CONV_CG;
            else if (!strcmp(val, "dg")) opt.methods = SQ_CONV_DG;
            else if (!strcmp(val, "both")) opt.methods = SQ_CONV_CG | SQ_CONV_DG;
            else return SQ_FAIL(err, SQ_ERR_USAGE, "--method expects cg, dg or both, got '%s'", val);
        } else if (!strcmp(a, "--orders")) {
            SQ_TRY(sq_cli_value(argc, argv, &i, &val, err));
            SQ_TRY(parse_orders(val, &opt.pmin, &opt.pmax, err));
        } else if (!strcmp(a, "--sizes")) {
            SQ_TRY(sq_cli_value(argc, argv, &i, &val, err));
            SQ_TRY(parse_sizes(val, sizes, &opt.nsizes, err));
            opt.sizes = sizes;
        } else if (!strcmp(a, "--geom-order")) {
            SQ_TRY(sq_cli_value(argc, argv, &i, &val, err));
            SQ_TRY(sq_cli_int(a, val, 1, 12, &opt.geom_order, err));
        } else if (!strcmp(a, "--csv")) {
            SQ_TRY(sq_cli_value(argc, argv, &i, &csv, err));
        } else if (!strcmp(a, "--svg")) {
            SQ_TRY(sq_cli_value(argc, argv, &i, &svg, err));
        } else if (!strcmp(a, "--quiet") || !strcmp(a, "-q")) {
            quiet = 1;
        } else if (a[0] == '-' && a[1]) {
            return SQ_FAIL(err, SQ_ERR_USAGE, "converge: unknown option %s", a);
        } else if (!path) {
            path = a;
        } else {
            return SQ_FAIL(err, SQ_ERR_USAGE, "converge: one input file expected");
        }
    }
    if (!path) return SQ_FAIL(err, SQ_ERR_USAGE, "converge: missing input file");

    cad_model *m = NULL;
    cad_face *f = NULL;
    const char *note;
    SQ_TRY(sq_cli_open_face(path, face, NULL, &m, &f, &face, &note, err));
    if (note && !quiet) fprintf(stderr, "semquad: note: %s\n", note);
    sq_converge_result r;
    sq_status st = sq_converge_study(f, &opt, &r, err);
    if (st == SQ_OK && csv) st = sq_converge_write_csv(csv, &r, err);
    if (st == SQ_OK && svg) {
        const char *base = strrchr(path, '/');
        char title[256];
        snprintf(title, sizeof title, "%s, u = %s: %s-refinement", base ? base + 1 : path,
                 opt.solution, r.nsizes > 1 ? "h" : "p");
        st = sq_converge_write_svg(svg, &r, title, err);
        if (st != SQ_OK && csv) remove(csv); /* all outputs or none */
    }
    if (st == SQ_OK && !quiet) print_table(path, face, opt.solution, &r);
    sq_converge_result_free(&r);
    cad_face_free(&f);
    cad_model_free(&m);
    return st;
}
