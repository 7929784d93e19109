/* semquad — VTK XML unstructured grid of curved high-order triangles
 * (VTK_LAGRANGE_TRIANGLE = 69), geometry and point data at the equispaced
 * lattice VTK expects, in the order of lattice_order.h. */
#ifndef SQ_WRITE_VTU_H
#define SQ_WRITE_VTU_H

#include "sq_status.h"
#include "tri_mesh.h"

/* Point data: out[ncomp] at reference point (r,s) of element e. */
typedef void (*sq_vtu_point_fn)(void *ctx, int e, double r, double s, double *out);

typedef struct {
    int npoint_arrays;
    const char *const *point_names; /* one scalar array per name */
    sq_vtu_point_fn point_data;     /* fills npoint_arrays values */
    void *ctx;
    int ncell_arrays;
    const char *const *cell_names;
    const double *const *cell_data; /* ncell_arrays arrays of ntris values */
} sq_vtu_data;

/* Write mesh at order `order` (its own geometry order if order <= 0) with
 * the optional data (may be NULL).  Atomic (outfile.h). */
sq_status sq_write_vtu(const char *path, const sem_tri_mesh *mesh, int order,
                       const sq_vtu_data *data, sq_error *err);

#endif
