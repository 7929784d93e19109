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
 * SpatialDomains/MeshGraphXml.cpp.  The compressed form (Nektar++
 * SpatialDomains/MeshGraphIOXmlCompressed.cpp) holds the same entities, ids
 * and coordinates: VERTEX, EDGE, ELEMENT's one Q and CURVED (attributes
 * COMPRESSED="B64Z-LittleEndian" BITSIZE="64") with one base64 text each
 * (nektar_b64z.h); CURVED's E and F, DATAPOINTS ID="0" with INDEX and
 * POINTS; COMPOSITE and DOMAIN stay text. */
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
/* The same in Nektar++'s compressed XML (Nektar++ reads it by the
 * COMPRESSED attribute of VERTEX). */
sq_status sq_write_nektar_compressed(const char *path, const sq_quad_mesh *m,
                                     const sq_progress *progress, sq_error *err);

#endif
