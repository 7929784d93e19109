"""A small reader of the Nektar++ XML geometry semquad writes, text or
compressed (docs/formats.md, "Compressed Nektar++ XML"), for the tests:
read(path) gives the same dictionary for both forms, so a test can compare
them entity by entity.

Compressed sections (Nektar++ SpatialDomains/MeshGraphIOXmlCompressed.cpp)
are base64 of zlib's compression of arrays of little-endian records of
8-byte ints and doubles (MeshEntities.hpp): MeshVertex "<qddd", MeshEdge
"<qqq", MeshQuad "<qqqqq", MeshCurvedInfo "<qqqqqq" (id, entityid,
npoints, ptid, ptoffset, ptype), DATAPOINTS' INDEX "<q" and POINTS
MeshVertex.  Decoded here with the standard library only (base64, zlib,
struct), independently of the writer."""
import base64
import struct
import xml.etree.ElementTree as ET
import zlib

B64Z = "B64Z-LittleEndian"
# LibUtilities::PointsType (Foundations/PointsType.h)
POINTS_TYPE = {4: "GaussLobattoLegendre", 17: "PolyEvenlySpaced"}


def decode(text, fmt):
    """The records of struct format fmt in a B64Z text.  The compressed
    bytes are padded with zero bytes to a multiple of 3 (no '='), as
    Nektar++ writes them: what follows zlib's stream must be those zeros."""
    raw = base64.b64decode(text.strip(), validate=True)
    z = zlib.decompressobj()
    data = z.decompress(raw)
    if not z.eof or z.unused_data.strip(b"\0") or len(z.unused_data) > 2:
        raise ValueError("not one zlib stream padded by < 3 zero bytes")
    size = struct.calcsize(fmt)
    if len(data) % size:
        raise ValueError("%d bytes: not a whole number of %d-byte records" % (len(data), size))
    return [struct.unpack_from(fmt, data, k) for k in range(0, len(data), size)]


def check_attrs(el):
    if el.get("COMPRESSED") != B64Z or el.get("BITSIZE") != "64":
        raise ValueError("<%s> attributes %r" % (el.tag, el.attrib))


def floats(text):
    v = [float(x) for x in text.split()]
    return [tuple(v[k:k + 3]) for k in range(0, len(v), 3)]


def read_text(geom, out):
    out["vertices"] = {int(v.get("ID")): floats(v.text)[0] for v in geom.find("VERTEX")}
    out["edges"] = {int(e.get("ID")): tuple(int(x) for x in e.text.split())
                    for e in geom.find("EDGE")}
    out["quads"] = {int(q.get("ID")): tuple(int(x) for x in q.text.split())
                    for q in geom.find("ELEMENT") if q.tag == "Q"}
    curved = geom.find("CURVED")
    for tag, key, name in (("E", "EDGEID", "curved_edges"), ("F", "FACEID", "curved_faces")):
        out[name] = {}
        for c in (curved if curved is not None else []):
            if c.tag != tag:
                continue
            pts = floats(c.text)
            if len(pts) != int(c.get("NUMPOINTS")):
                raise ValueError("<%s ID=%s>: NUMPOINTS %s, %d points"
                                 % (tag, c.get("ID"), c.get("NUMPOINTS"), len(pts)))
            out[name][int(c.get(key))] = (int(c.get("ID")), c.get("TYPE"), pts)


def read_compressed(geom, out):
    vertex, edge = geom.find("VERTEX"), geom.find("EDGE")
    check_attrs(vertex)
    check_attrs(edge)
    out["vertices"] = {r[0]: r[1:] for r in decode(vertex.text, "<qddd")}
    out["edges"] = {r[0]: r[1:] for r in decode(edge.text, "<qqq")}
    out["quads"] = {}
    for q in geom.find("ELEMENT"):
        check_attrs(q)
        if q.tag != "Q":
            raise ValueError("ELEMENT holds <%s>" % q.tag)
        out["quads"].update({r[0]: r[1:] for r in decode(q.text, "<qqqqq")})
    out["curved_edges"], out["curved_faces"] = {}, {}
    curved = geom.find("CURVED")
    if curved is None:
        return
    check_attrs(curved)
    pts = curved.find("DATAPOINTS")
    if pts.get("ID") != "0":
        raise ValueError("DATAPOINTS ID %r" % pts.get("ID"))
    index = [r[0] for r in decode(pts.find("INDEX").text, "<q")]
    points = {r[0]: r[1:] for r in decode(pts.find("POINTS").text, "<qddd")}
    for tag, name in (("E", "curved_edges"), ("F", "curved_faces")):
        el = curved.find(tag)
        for cid, entity, n, ptid, off, ptype in (decode(el.text, "<qqqqqq") if el is not None else []):
            if ptid != 0:
                raise ValueError("curve %d: ptid %d" % (cid, ptid))
            out[name][entity] = (cid, POINTS_TYPE.get(ptype, str(ptype)),
                                 [points[index[off + k]] for k in range(n)])


def read(path):
    """vertices {id: (x, y, z)}, edges {id: (v0, v1)}, quads {id: (e0..e3)},
    curved_edges / curved_faces {entity id: (curve id, point type, points)},
    composite and domain (their XML text), compressed (bool)."""
    root = ET.parse(path).getroot()
    geom = root.find("GEOMETRY")
    out = {"compressed": geom.find("VERTEX").get("COMPRESSED") is not None}
    (read_compressed if out["compressed"] else read_text)(geom, out)
    out["composite"] = ET.tostring(geom.find("COMPOSITE"))
    out["domain"] = ET.tostring(geom.find("DOMAIN"))
    return out
