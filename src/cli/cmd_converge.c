/* semquad converge FILE: convergence study of the sem/ solvers on a CAD
 * face with an exact harmonic solution (sq_face_converge). */
#include "cli.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

/* "A-B" or "A", 1 <= A <= B <= 16 */
static sq_status parse_orders(const char *opt, const char *val, sq_cli_args *a, sq_error *err)
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
        return SQ_FAIL(err, SQ_ERR_USAGE, "%s expects A-B or A with 1 <= A <= B <= 16, got '%s'",
                       opt, val);
    a->opt.study_pmin = (int)x;
    a->opt.study_pmax = (int)y;
    return SQ_OK;
}

static sq_status parse_sizes(const char *opt, const char *val, sq_cli_args *a, sq_error *err)
{
    const char *p = val;
    int *n = &a->opt.study_nsizes;
    *n = 0;
    a->opt.study_sizes = a->sizes;
    for (;;) {
        char *end;
        errno = 0;
        double v = strtod(p, &end);
        if (errno || end == p || !isfinite(v) || v <= 0.0 || (*end && *end != ',') ||
            *n == SQ_CLI_MAX_LIST)
            return SQ_FAIL(err, SQ_ERR_USAGE,
                           "%s expects up to %d positive numbers separated by commas, got '%s'",
                           opt, SQ_CLI_MAX_LIST, val);
        a->sizes[(*n)++] = v;
        if (!*end) return SQ_OK;
        p = end + 1;
    }
}

static sq_status run_converge(sq_cli_args *a, sq_error *err)
{
    sq_model *m = NULL;
    SQ_TRY(sq_cli_open(a, &m, err));
    sq_study *s = NULL;
    sq_status st = sq_face_converge(m, a->face, &a->opt, &s, err);
    if (st == SQ_OK && a->csv) st = sq_study_write(s, a->csv, err);
    if (st == SQ_OK && a->svg) {
        st = sq_study_write(s, a->svg, err);
        if (st != SQ_OK && a->csv && a->csv[0] != '-') remove(a->csv); /* all outputs or none */
    }
    char *text = NULL;
    if (st == SQ_OK && !a->quiet) st = sq_cli_print(sq_study_describe(s, &text, err), &text, a);
    sq_study_free(&s);
    sq_model_free(&m);
    return st;
}

static const sq_cli_opt converge_opts[] = {
    {.name = "solution", .kind = SQ_CLI_WORD, .value = "exp-sin|re-z5|poly|sin-sinh",
     .def = "exp-sin", .help = "the exact harmonic solution (exp-sin: e^x sin y; re-z5: Re z^5)",
     .target = SQ_CLI_AT(opt.study_solution)},
    {.name = "method", .kind = SQ_CLI_WORD, .value = "cg|dg|both", .def = "both",
     .help = "the solvers studied", .target = SQ_CLI_AT(opt.study_methods)},
    {.name = "orders", .kind = SQ_CLI_CUSTOM, .value = "A-B", .def = "1-12",
     .help = "every order P from A to B (1..16)", .parse = parse_orders},
    {.name = "sizes", .kind = SQ_CLI_CUSTOM, .value = "h1,h2,...", .def = "automatic",
     .unit = "file unit", .help = "longest triangle edge of each run (h-refinement)",
     .parse = parse_sizes},
    {.name = "geom-order", .kind = SQ_CLI_INT, .value = "G", .lo = 1, .hi = 12,
     .def = "max(P,8), at most 12", .help = "order of the curved triangles (1..12)",
     .target = SQ_CLI_AT(opt.study_geom_order)},
    {.name = "csv", .kind = SQ_CLI_OUTPUT, .value = "FILE", .def = "none",
     .help = "every run as CSV: method,P,h,dofs,L2,H1", .target = SQ_CLI_AT(csv)},
    SQ_CLI_OPT_SVG("log-log plot of the errors against the degrees of freedom"),
    SQ_CLI_OPTS_READING,
    {0}};

const sq_cli_command sq_cli_converge = {
    .name = "converge",
    .summary = "Convergence study of the CG/DG Poisson solvers: -lap u = 0 with u an exact "
               "harmonic solution on the whole boundary, every order on every size. Table on "
               "stdout; CSV of every run; SVG log-log plot of the errors against dofs "
               "(p-refinement, or h-refinement per P with several sizes).",
    .example = "semquad converge examples/square.step --orders 1-8 --csv square.csv",
    .opts = converge_opts,
    .run = run_converge};
