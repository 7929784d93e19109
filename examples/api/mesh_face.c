/* Mesh one face of a CAD file through libsemquad's public API.
 *
 *   cc mesh_face.c $(pkg-config --cflags --libs semquad) -o mesh_face
 *   ./mesh_face examples/half_disc.step [ORDER [OUT.msh]]
 *
 * prints the face, the road, the counts and the area, one per line; the
 * exit status is semquad's (0 ok, 3 bad file, ...). */
#include <semquad.h>

#include <stdio.h>
#include <stdlib.h>

static void log_line(void *data, sq_log_level level, const char *line)
{
    (void)data;
    if (level != SQ_LOG_INFO) fprintf(stderr, "mesh_face: %s\n", line);
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        fprintf(stderr, "usage: mesh_face FILE [ORDER [OUT.msh]]\n");
        return SQ_ERR_USAGE;
    }
    sq_options opt;
    sq_options_init(&opt);
    opt.order = argc > 2 ? atoi(argv[2]) : 4;
    opt.log = log_line;

    sq_error err;
    sq_model *model = NULL;
    sq_mesh *mesh = NULL;
    sq_status st = sq_model_open(argv[1], &opt, &model, &err);
    if (st == SQ_OK) st = sq_face_mesh(model, -1, &opt, &mesh, &err);
    if (st == SQ_OK && argc > 3) st = sq_mesh_write(mesh, argv[3], &err);
    if (st == SQ_OK) {
        /* the plain arrays: corner nodes of every quad are in the mesh */
        int Q = sq_mesh_order(mesh), nq = sq_mesh_num_quads(mesh), nn = sq_mesh_num_nodes(mesh);
        const int *quads = sq_mesh_quads(mesh);
        const double *sj = sq_mesh_scaled_jacobians(mesh);
        double min_sj = 1.0;
        for (int q = 0; q < nq; q++) {
            if (sj[q] < min_sj) min_sj = sj[q];
            if (quads[(Q + 1) * (Q + 1) * q] >= nn) st = SQ_ERR_INTERNAL;
        }
        printf("face %d\nroad %s\norder %d\nquads %d\nnodes %d\nboundary_sides %d\n",
               sq_mesh_face(mesh), sq_mesh_road(mesh), Q, nq, nn,
               sq_mesh_num_boundary_sides(mesh));
        printf("min_scaled_jacobian %.6f\narea %.15g\n", min_sj, sq_mesh_area(mesh));
    }
    if (st != SQ_OK) fprintf(stderr, "mesh_face: %s: %s\n", sq_status_name(st), err.msg);
    sq_mesh_free(&mesh);
    sq_model_free(&model);
    return (int)st;
}
