/* semquad converge FILE [--face N] [--solution NAME] [--method cg|dg|both]
 *   [--orders A-B] [--sizes h1,h2,...] [--geom-order G] [--csv out.csv]
 *   [--svg out.svg] [--quiet]: convergence study of the sem/ solvers
 *   (src/converge/converge.h) on a CAD face with an exact harmonic solution. */
#include "cli.h"

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

sq_status sq_cmd_converge(int argc, char **argv, sq_error *err)
{
    const char *csv = NULL, *val;
    double sizes[MAX_SIZES];
    sq_cli_args args;
    sq_cli_args_init(&args);
    sq_options *o = &args.opt;
    for (int i = 0; i < argc; i++) {
        const char *a = argv[i];
        int taken;
        SQ_TRY(sq_cli_take("converge", argc, argv, &i, &args, &taken, err));
        if (taken) continue;
        if (!strcmp(a, "--solution")) {
            SQ_TRY(sq_cli_value(argc, argv, &i, &o->study_solution, err));
        } else if (!strcmp(a, "--method")) {
            SQ_TRY(sq_cli_value(argc, argv, &i, &o->study_methods, err));
        } else if (!strcmp(a, "--orders")) {
            SQ_TRY(sq_cli_value(argc, argv, &i, &val, err));
            SQ_TRY(parse_orders(val, &o->study_pmin, &o->study_pmax, err));
        } else if (!strcmp(a, "--sizes")) {
            SQ_TRY(sq_cli_value(argc, argv, &i, &val, err));
            SQ_TRY(parse_sizes(val, sizes, &o->study_nsizes, err));
            o->study_sizes = sizes;
        } else if (!strcmp(a, "--geom-order")) {
            SQ_TRY(sq_cli_value(argc, argv, &i, &val, err));
            SQ_TRY(sq_cli_int(a, val, 1, 12, &o->study_geom_order, err));
        } else if (!strcmp(a, "--csv")) {
            SQ_TRY(sq_cli_value(argc, argv, &i, &csv, err));
        } else {
            return sq_cli_unknown("converge", a, err);
        }
    }
    if (args.output || args.report)
        return SQ_FAIL(err, SQ_ERR_USAGE, "converge: writes --csv and --svg only (no -o, --report)");
    const char *svg = args.svg;
    if (!args.input) return SQ_FAIL(err, SQ_ERR_USAGE, "converge: missing input file");
    sq_model *m = NULL;
    SQ_TRY(sq_cli_open(&args, &m, err));
    sq_study *s = NULL;
    sq_status st = sq_face_converge(m, args.face, o, &s, err);
    if (st == SQ_OK && csv) st = sq_study_write(s, csv, err);
    if (st == SQ_OK && svg) {
        st = sq_study_write(s, svg, err);
        if (st != SQ_OK && csv) remove(csv); /* all outputs or none */
    }
    char *text = NULL;
    if (st == SQ_OK && !args.quiet) st = sq_cli_print(sq_study_describe(s, &text, err), &text);
    sq_study_free(&s);
    sq_model_free(&m);
    return st;
}
