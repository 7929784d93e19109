#!/usr/bin/python3
"""t604 helper: read an MSH file with Gmsh's own reader (Debian python3-gmsh,
which works with /usr/bin/python3 only) and check it against what the writer
meant.  Usage: t604-gmsh-check.py FILE NODES QUADS LINES QUADTYPE LINETYPE
PHYSICALS AREA.  Checks node and element counts and types, the physical
groups and their names, positive Jacobian determinants at Gauss points and
the area by Gmsh's own quadrature (which is only right if Gmsh reads the
nodes in the order they were meant).  Silent on success; exit 77 if gmsh
cannot be imported."""
import math
import sys

try:
    import gmsh
except ImportError:
    sys.exit(77)


def main(argv):
    path = argv[1]
    nodes, quads, lines, qtype, ltype, nphys = (int(a) for a in argv[2:8])
    area = float(argv[8])
    fails = []
    gmsh.initialize()
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.open(path)
        tags, _, _ = gmsh.model.mesh.getNodes()
        if len(tags) != nodes:
            fails.append("nodes %d, expected %d" % (len(tags), nodes))
        types, etags, _ = gmsh.model.mesh.getElements()
        count = {t: len(e) for t, e in zip(types, etags)}
        if count.get(qtype, 0) != quads:
            fails.append("quads of type %d: %d, expected %d" % (qtype, count.get(qtype, 0), quads))
        if count.get(ltype, 0) != lines:
            fails.append("lines of type %d: %d, expected %d" % (ltype, count.get(ltype, 0), lines))
        if sum(count.values()) != quads + lines:
            fails.append("elements %s" % count)
        groups = gmsh.model.getPhysicalGroups()
        if len(groups) != nphys:
            fails.append("physical groups %d, expected %d" % (len(groups), nphys))
        for dim, tag in groups:
            name = gmsh.model.getPhysicalName(dim, tag)
            want = "domain" if dim == 2 else "boundary_%d" % (tag - 1)
            if name != want:
                fails.append("physical (%d, %d) named %r, expected %r" % (dim, tag, name, want))
        order = gmsh.model.mesh.getElementProperties(qtype)[2]
        loc, w = gmsh.model.mesh.getIntegrationPoints(qtype, "Gauss%d" % (2 * order + 1))
        _, det, _ = gmsh.model.mesh.getJacobians(qtype, loc)
        npts = len(w)
        got = sum(w[k % npts] * det[k] for k in range(len(det)))
        if min(det) <= 0:
            fails.append("non-positive Jacobian determinant %g" % min(det))
        if abs(got - area) > 1e-10 * abs(area):
            fails.append("area by Gmsh %.15g, expected %.15g" % (got, area))
    finally:
        gmsh.finalize()
    for f in fails:
        print("%s: %s" % (path, f))
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
