/* semquad — Nektar++ XML geometry of a high-order quad mesh.
 *
 * <NEKTAR><GEOMETRY DIM="2" SPACE="2"> with VERTEX (the corner vertices),
 * EDGE (each element side once, its two vertices), ELEMENT (Q: the four
 * edges of a quad counter-clockwise, edge k = local side k), CURVED (when
 * Q >= 2: an E entry per edge with NUMPOINTS = Q+1 points from the edge's
 * first vertex to its second, and an F entry per quad, FACEID = quad ID,
 * NUMPOINTS = (Q+1)^2 points in the quad's lattice order, i along edge 0
 * fastest; TYPE "GaussLobattoLegendre" or "PolyEvenlySpaced" as the mesh's
 * nodes), COMPOSITE (C[0] = all quads, C[t+1] = the edges of boundary curve
 * t, for each curve that has edges) and DOMAIN C[0].  Nektar++ user guide,
 * "Geometry" section of the XML session file; reader: Nektar++
 * SpatialDomains/MeshGraphXml.cpp. */
#ifndef SQ_WRITE_NEKTAR_H
#define SQ_WRITE_NEKTAR_H

#include "quad_mesh.h"
#include "sq_progress.h"
#include "sq_status.h"

/* Atomic (outfile.h).  Reports "write" to progress (may be NULL): edges and
 * quads written of all (from Q = 2 each twice, in EDGE or ELEMENT and with
 * its points in CURVED), at most about 100 events. */
sq_status sq_write_nektar(const char *path, const sq_quad_mesh *m, const sq_progress *progress,
                          sq_error *err);

#endif
