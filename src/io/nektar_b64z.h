/* semquad — the "B64Z-LittleEndian" encoding of Nektar++'s compressed XML
 * geometry: an array of fixed records of 8-byte little-endian ints and
 * doubles (Nektar++ SpatialDomains/MeshEntities.hpp: MeshVertex {id, x, y,
 * z}, MeshEdge {id, v0, v1}, MeshQuad {id, e[4]}, MeshCurvedInfo {id,
 * entityid, npoints, ptid, ptoffset, ptype}, all NekInt64 / NekDouble, so
 * no padding), compressed by zlib at its default level and written as
 * base64 (LibUtilities/BasicUtils/CompressData.cpp). */
#ifndef SQ_NEKTAR_B64Z_H
#define SQ_NEKTAR_B64Z_H

#include "sq_status.h"

#include <stddef.h>
#include <stdio.h>

/* Store v (an int, or a double's bits) at p as 8 little-endian bytes;
 * returns p + 8. */
unsigned char *sq_le64_int(unsigned char *p, long long v);
unsigned char *sq_le64_double(unsigned char *p, double v);

/* Write base64 of zlib's compression of raw[0..n) to fp.  The compressed
 * bytes are padded with zero bytes to a multiple of 3 and no '=' is
 * written, as Nektar++ does: its decoder (Boost's binary_from_base64)
 * takes no '=', and zlib stops at the stream's end before the zeros.
 * SQ_ERR_INTERNAL if zlib fails or memory runs out. */
sq_status sq_write_b64z(FILE *fp, const unsigned char *raw, size_t n, sq_error *err);

#endif
