/* semquad field FILE [--face N] [--order P] [--method auto|cg|dg] [--size H]
 *   [--report out.json] [--vtu out.vtu] [--svg out.svg] [--quiet] */
#include "cli.h"
#include "write_field.h"

#include <stdio.h>
#include <string.h>

sq_status sq_cmd_field(int argc, char **argv, sq_error *err)
{
    const char *path = NULL, *vtu = NULL, *svg = NULL, *report = NULL, *val;
    int face = -1, quiet = 0, tri_order = 0;
    sq_field_options opt;
    sq_field_options_default(&opt);
    for (int i = 0; i < argc; i++) {
        const char *a = argv[i];
        if (!strcmp(a, "--face")) {
            SQ_TRY(sq_cli_value(argc, argv, &i, &val, err));
            SQ_TRY(sq_cli_int(a, val, 0, 1000000, &face, err));
        } else if (!strcmp(a, "--order")) {
            SQ_TRY(sq_cli_value(argc, argv, &i, &val, err));
            SQ_TRY(sq_cli_int(a, val, 1, 16, &opt.order, err));
        } else if (!strcmp(a, "--geom-order")) {
            SQ_TRY(sq_cli_value(argc, argv, &i, &val, err));
            SQ_TRY(sq_cli_int(a, val, 1, 12, &tri_order, err));
        } else if (!strcmp(a, "--method")) {
            SQ_TRY(sq_cli_value(argc, argv, &i, &val, err));
            if (!strcmp(val, "auto")) opt.method = SQ_METHOD_AUTO;
            else if (!strcmp(val, "cg")) opt.method = SQ_METHOD_CG;
            else if (!strcmp(val, "dg")) opt.method = SQ_METHOD_DG;
            else return SQ_FAIL(err, SQ_ERR_USAGE, "--method expects auto, cg or dg, got '%s'", val);
        } else if (!strcmp(a, "--size")) {
            SQ_TRY(sq_cli_value(argc, argv, &i, &val, err));
            SQ_TRY(sq_cli_double(a, val, 1e-300, 1e300, &opt.tri.size, err));
        } else if (!strcmp(a, "--vtu") || !strcmp(a, "-o")) {
            SQ_TRY(sq_cli_value(argc, argv, &i, &vtu, err));
        } else if (!strcmp(a, "--svg")) {
            SQ_TRY(sq_cli_value(argc, argv, &i, &svg, err));
        } else if (!strcmp(a, "--report")) {
            SQ_TRY(sq_cli_value(argc, argv, &i, &report, err));
        } else if (!strcmp(a, "--quiet") || !strcmp(a, "-q")) {
            quiet = 1;
        } else if (a[0] == '-' && a[1]) {
            return SQ_FAIL(err, SQ_ERR_USAGE, "field: unknown option %s", a);
        } else if (!path) {
            path = a;
        } else {
            return SQ_FAIL(err, SQ_ERR_USAGE, "field: one input file expected");
        }
    }
    if (!path) return SQ_FAIL(err, SQ_ERR_USAGE, "field: missing input file");
    /* isoparametric unless told otherwise (the triangulation stops at 12) */
    opt.tri.order = tri_order ? tri_order : (opt.order < 12 ? opt.order : 12);

    double t0 = sq_now();
    cad_model *m = NULL;
    cad_face *f = NULL;
    const char *note;
    SQ_TRY(sq_cli_open_face(path, face, &m, &f, &face, &note, err));
    double t_read = sq_now() - t0;
    if (note && !quiet) fprintf(stderr, "semquad: note: %s\n", note);
    sq_field_analysis an;
    sq_status st = sq_field_analyse(f, &opt, &an, err);
    if (st == SQ_OK && vtu) st = sq_write_field_vtu(vtu, &an, err);
    if (st == SQ_OK && svg) st = sq_write_field_svg(svg, &an, err);
    if (st == SQ_OK && report) st = sq_write_field_report(report, path, face, &an, t_read, err);
    if (st == SQ_OK && !quiet) {
        printf("%s face %d: guiding field %s P=%d on %d triangles (%ld dofs per component)\n", path,
               face, an.field.method == SEM_CG ? "CG" : "DG", an.field.order, an.tri.mesh->ntris,
               an.field.ndofs);
        printf("  %d singular point%s\n", an.npoints, an.npoints == 1 ? "" : "s");
        for (int k = 0; k < an.npoints; k++)
            printf("    (%.9f, %.9f) valence %d%s\n", an.points[k].x, an.points[k].y,
                   an.points[k].valence, an.points[k].near_boundary ? " (on the boundary)" : "");
        printf("  corners:\n");
        for (int k = 0; k < an.info.nvertices; k++)
            if (!an.info.vertices[k].smooth)
                printf("    (%.6g, %.6g) %.2f deg: %d quad%s\n", an.info.vertices[k].x,
                       an.info.vertices[k].y, an.info.vertices[k].angle_deg,
                       an.corners[k].valence, an.corners[k].valence == 1 ? "" : "s");
        printf("  Poincare-Hopf: sum(4 - V) + sum(2 - n) = %d, 4 chi = %d: %s\n", an.ph_lhs,
               an.ph_rhs, an.ph_lhs == an.ph_rhs ? "holds" : "VIOLATED");
    }
    if (st == SQ_OK && an.ph_lhs != an.ph_rhs && !quiet)
        fprintf(stderr, "semquad: warning: Poincare-Hopf check fails (%d != %d): a singular point "
                        "was missed or misclassified\n", an.ph_lhs, an.ph_rhs);
    sq_field_analysis_free(&an);
    cad_face_free(&f);
    cad_model_free(&m);
    return st;
}
