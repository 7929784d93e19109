/* semquad mesh FILE [--face N] [--order Q] [--size h] [--field-order P]
 *   [--method auto|cg|dg] [--merge-distance K] [--nodes gll|equispaced]
 *   [--bl E1,E2,... --bl-first d --bl-ratio r --bl-layers n] [--max-quads N]
 *   [--road auto|layout|split] [-o out.msh|.xml|.vtu] [--svg F] [--report F] [-q] */
#include "cli.h"

#include <stdio.h>
#include <string.h>

/* Options of mesh alone; SQ_ERR_USAGE for one no command takes. */
static sq_status mesh_option(int argc, char **argv, int *i, sq_options *o, int *bl, int maxbl,
                             sq_error *err)
{
    const char *a = argv[*i], *val;
    if (!strcmp(a, "--allow-misaligned")) {
        o->allow_misaligned = 1;
        return SQ_OK;
    }
    if (strcmp(a, "--order") && strcmp(a, "--size") && strcmp(a, "--field-order") &&
        strcmp(a, "--method") && strcmp(a, "--singularities") && strcmp(a, "--merge-distance") &&
        strcmp(a, "--bl") && strcmp(a, "--bl-first") && strcmp(a, "--bl-ratio") &&
        strcmp(a, "--bl-layers") && strcmp(a, "--max-quads") && strcmp(a, "--road") &&
        strcmp(a, "--nodes") && strcmp(a, "--min-quality"))
        return sq_cli_unknown("mesh", a, err);
    SQ_TRY(sq_cli_value(argc, argv, i, &val, err));
    if (!strcmp(a, "--order")) return sq_cli_int(a, val, 1, 10, &o->order, err);
    if (!strcmp(a, "--size")) return sq_cli_double(a, val, 1e-300, 1e300, &o->size, err);
    if (!strcmp(a, "--field-order")) return sq_cli_int(a, val, 1, 16, &o->field_order, err);
    if (!strcmp(a, "--merge-distance"))
        return sq_cli_double(a, val, 0.1, 1000.0, &o->merge_distance, err);
    if (!strcmp(a, "--bl")) {
        o->bl_edges = bl;
        return sq_cli_int_list(a, val, 0, 1000000, bl, maxbl, &o->nbl, err);
    }
    if (!strcmp(a, "--bl-first")) return sq_cli_double(a, val, 1e-300, 1e300, &o->bl_first, err);
    if (!strcmp(a, "--bl-ratio")) return sq_cli_double(a, val, 1.0, 10.0, &o->bl_ratio, err);
    if (!strcmp(a, "--bl-layers")) return sq_cli_int(a, val, 1, 1000, &o->bl_layers, err);
    if (!strcmp(a, "--max-quads")) return sq_cli_double(a, val, 1.0, 1e15, &o->max_quads, err);
    if (!strcmp(a, "--min-quality")) return sq_cli_double(a, val, 0.0, 1.0, &o->min_quality, err);
    if (!strcmp(a, "--method"))
        o->method = val;
    else if (!strcmp(a, "--singularities"))
        o->singularities = val;
    else if (!strcmp(a, "--road"))
        o->road = val;
    else
        o->nodes = val;
    return SQ_OK;
}

/* The outputs -o, --svg and --report, in that order (the report's
 * timings include the writes). */
static sq_status write_outputs(const sq_mesh *mesh, const sq_cli_args *args, sq_error *err)
{
    if (args->output) SQ_TRY(sq_mesh_write(mesh, args->output, err));
    if (args->svg) SQ_TRY(sq_mesh_write(mesh, args->svg, err));
    if (args->report) SQ_TRY(sq_mesh_write_report(mesh, args->report, err));
    return SQ_OK;
}

sq_status sq_cmd_mesh(int argc, char **argv, sq_error *err)
{
    int bl[64];
    sq_cli_args args;
    sq_cli_args_init(&args);
    for (int i = 0; i < argc; i++) {
        int taken;
        SQ_TRY(sq_cli_take("mesh", argc, argv, &i, &args, &taken, err));
        if (!taken)
            SQ_TRY(mesh_option(argc, argv, &i, &args.opt, bl, (int)(sizeof bl / sizeof *bl), err));
    }
    SQ_TRY(sq_cli_need_input("mesh", &args, err));
    if (args.output && !sq_mesh_format_known(args.output))
        return SQ_FAIL(err, SQ_ERR_USAGE, "%s: unknown mesh format (use .msh, .xml or .vtu)",
                       args.output);
    sq_model *m = NULL;
    SQ_TRY(sq_cli_open(&args, &m, err));
    sq_mesh *mesh = NULL;
    sq_status st = sq_face_mesh(m, args.face, &args.opt, &mesh, err);
    if (st == SQ_OK) st = write_outputs(mesh, &args, err);
    char *text = NULL;
    if (st == SQ_OK && !args.quiet) st = sq_cli_print(sq_mesh_describe(mesh, &text, err), &text);
    /* below the floor: written all the same, then the status */
    if (st == SQ_OK) st = sq_mesh_check_quality(mesh, &args.opt, err);
    sq_mesh_free(&mesh);
    sq_model_free(&m);
    return st;
}
