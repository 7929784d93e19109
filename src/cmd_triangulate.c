/* semquad triangulate FILE [--face N] [--order P] [--size H] [--min-angle A]
 *   [--max-turn T] [-o out.vtu] [--svg out.svg] [--report out.json] */
#include "cli.h"
#include "write_tri.h"

#include <stdio.h>
#include <string.h>

sq_status sq_cmd_triangulate(int argc, char **argv, sq_error *err)
{
    const char *path = NULL, *vtu = NULL, *svg = NULL, *report = NULL, *val;
    int face = -1, quiet = 0;
    sq_tri_options opt;
    sq_tri_options_default(&opt);
    for (int i = 0; i < argc; i++) {
        const char *a = argv[i];
        if (!strcmp(a, "--face")) {
            SQ_TRY(sq_cli_value(argc, argv, &i, &val, err));
            SQ_TRY(sq_cli_int(a, val, 0, 1000000, &face, err));
        } else if (!strcmp(a, "--order")) {
            SQ_TRY(sq_cli_value(argc, argv, &i, &val, err));
            SQ_TRY(sq_cli_int(a, val, 1, 12, &opt.order, err));
        } else if (!strcmp(a, "--size")) {
            SQ_TRY(sq_cli_value(argc, argv, &i, &val, err));
            SQ_TRY(sq_cli_double(a, val, 1e-300, 1e300, &opt.size, err));
        } else if (!strcmp(a, "--min-angle")) {
            SQ_TRY(sq_cli_value(argc, argv, &i, &val, err));
            SQ_TRY(sq_cli_double(a, val, 1.0, 30.0, &opt.min_angle_deg, err));
        } else if (!strcmp(a, "--max-turn")) {
            SQ_TRY(sq_cli_value(argc, argv, &i, &val, err));
            SQ_TRY(sq_cli_double(a, val, 1.0, 90.0, &opt.max_turn_deg, err));
        } else if (!strcmp(a, "-o") || !strcmp(a, "--output")) {
            SQ_TRY(sq_cli_value(argc, argv, &i, &vtu, err));
        } else if (!strcmp(a, "--svg")) {
            SQ_TRY(sq_cli_value(argc, argv, &i, &svg, err));
        } else if (!strcmp(a, "--report")) {
            SQ_TRY(sq_cli_value(argc, argv, &i, &report, err));
        } else if (!strcmp(a, "--quiet") || !strcmp(a, "-q")) {
            quiet = 1;
        } else if (a[0] == '-' && a[1]) {
            return SQ_FAIL(err, SQ_ERR_USAGE, "triangulate: unknown option %s", a);
        } else if (!path) {
            path = a;
        } else {
            return SQ_FAIL(err, SQ_ERR_USAGE, "triangulate: one input file expected");
        }
    }
    if (!path) return SQ_FAIL(err, SQ_ERR_USAGE, "triangulate: missing input file");

    cad_model *m = NULL;
    cad_face *f = NULL;
    const char *note;
    SQ_TRY(sq_cli_open_face(path, face, &m, &f, &face, &note, err));
    if (note && !quiet) fprintf(stderr, "semquad: note: %s\n", note);
    sq_triangulation t;
    sq_status st = sq_triangulate(f, &opt, &t, err);
    if (st == SQ_OK && vtu) st = sq_write_tri_vtu(vtu, &t, err);
    if (st == SQ_OK && svg) st = sq_write_tri_svg(svg, &t, err);
    if (st == SQ_OK && report) st = sq_write_tri_report(report, path, face, &t, err);
    if (st == SQ_OK && !quiet)
        printf("%s face %d: %d triangles of order %d, min angle %.2f deg, min scaled Jacobian "
               "%.4f, area %.12g\n",
               path, face, t.mesh->ntris, t.mesh->order, t.min_angle_deg, t.min_scaled_jacobian,
               t.area);
    sq_triangulation_free(&t);
    cad_face_free(&f);
    cad_model_free(&m);
    return st;
}
