#!/usr/bin/python3
"""t635: the MSH file's model entities as Gmsh classifies a mesh
(docs/formats.md, "Entities"): the corner nodes on point entities, the
nodes of a boundary curve or an interface between two faces on that curve's
entity, the rest on their face's surface; read back by Gmsh's own reader
(gmsh.open), from the text file and the --binary one alike.  Meshes: the
half disc (examples/half_disc.step, order 4), three rectangles in a row
(tests/domain_faces.py three_row: two straight interfaces, order 3), the
1/8 ring with its radial sides periodic (sector, --periodic auto, order 5)
and the disc in a square (circle_square: a closed interface, order 3).
For each:

  - every node on exactly one entity;
  - the point entities are the CAD vertices at the ends of the file's open
    curves (read from the STEP file by Gmsh's OCC kernel), one each, at the
    vertex within 1e-7 of the face's size.  Why 1e-7: the corner node is
    the CAD curve evaluated at its end, which meets the vertex within the
    file's vertex tolerance (OCCT's confusion, 1e-7); a node classified on
    the wrong point would be a whole element side away;
  - a boundary curve: getNodes(1, c, includeBoundary) is exactly the nodes
    of its line elements, Q * lines + 1 of them, and its bounding points
    are the nodes where its chain of lines begins and ends;
  - an interface (no line elements): its nodes lie on the shared CAD curve
    (a straight line: to 1e-9 of the size, as t625; the circle of radius R
    to the error of an order-Q interpolant of an arc of turning angle
    t, R t^(Q+1) / (4^(Q+1) (Q+1)!), t the longest side's (from the nodes'
    angles: a side may be longer than the size): the MSH file's nodes are the
    element maps' values at equispaced points, not projections; a node of
    the wrong curve or the inside would be an element side away), are used by
    quads of both faces, count Q * k + 1 for an open curve, Q * k for the
    closed circle (k its element sides), and it bounds both surfaces, with
    opposite signs;
  - a periodic pair: getPeriodicNodes of the image curve pairs exactly the
    image curve's nodes with exactly the master curve's (end points
    included);
  - meshio's reader (if installed) reads the same nodes and quads.
usage: t635-msh-entities.py SEMQUAD EXAMPLES_DIR DOMAIN_FACES_PY"""
import math
import os
import subprocess
import sys
import tempfile

try:
    import gmsh
except ImportError:
    sys.exit(77)

SQ, EXAMPLES, GEN = sys.argv[1:4]
fails = []


def cad_vertices(step):
    """The CAD vertices at the ends of the file's open curves."""
    gmsh.clear()
    gmsh.model.occ.importShapes(step)
    gmsh.model.occ.synchronize()
    ends = set()
    for _, c in gmsh.model.getEntities(1):
        b = [t for _, t in gmsh.model.getBoundary([(1, c)], oriented=False)]
        if len(set(b)) == 2:
            ends.update(b)
    # the faces of a file may each carry their own copy of a vertex: one
    # point per place (the copies coincide to the file's digits)
    places = []
    for v in sorted(ends):
        x = tuple(gmsh.model.getValue(0, v, [])[:2])
        if all(math.hypot(x[0] - p[0], x[1] - p[1]) > 1e-9 for p in places):
            places.append(x)
    return places


def entities(msh):
    """Per entity (dim, tag): its own node tags (sorted), its nodes with its
    boundary's, its signed boundary; node positions; quads per surface."""
    gmsh.clear()
    gmsh.open(msh)
    tags, xyz, _ = gmsh.model.mesh.getNodes()
    pos = {int(t): (xyz[3 * k], xyz[3 * k + 1]) for k, t in enumerate(tags)}
    ent = {}
    for dim, tag in gmsh.model.getEntities():
        own = sorted(int(t) for t in gmsh.model.mesh.getNodes(dim, tag)[0])
        full = sorted(int(t) for t in gmsh.model.mesh.getNodes(dim, tag, includeBoundary=True)[0])
        bnd = [t for _, t in gmsh.model.getBoundary([(dim, tag)], combined=False, oriented=True)] if dim else []
        elems = []
        for etype, _, en in zip(*gmsh.model.mesh.getElements(dim, tag)):
            nn = gmsh.model.mesh.getElementProperties(etype)[3]
            elems += [[int(x) for x in en[i:i + nn]] for i in range(0, len(en), nn)]
        ent[(dim, tag)] = (own, full, bnd, elems)
    periodic = {}
    for dim, tag in gmsh.model.getEntities(1):
        master, nodes, mnodes, _ = gmsh.model.mesh.getPeriodicNodes(dim, tag)
        if master != tag and len(nodes):
            periodic[tag] = (master, sorted(int(n) for n in nodes), sorted(int(n) for n in mnodes))
    return ent, pos, len(tags), periodic


def check_curve(name, c, own, full, bnd, elems, ent, Q, on_shared, tol, pos):
    if elems:  # a boundary curve: its line elements
        lines = {n for e in elems for n in e}
        if set(full) != lines:
            fails.append("%s: curve %d: %d nodes with its ends, its %d lines hold %d"
                         % (name, c, len(full), len(elems), len(lines)))
        ends = {}
        for e in elems:
            for n in e[:2]:
                ends[n] = ends.get(n, 0) + 1
        chain_ends = sorted(n for n, k in ends.items() if k == 1)
        point_nodes = sorted(ent[(0, abs(p))][0][0] for p in bnd)
        if chain_ends != point_nodes:
            fails.append("%s: curve %d: chain ends %s, bounding points' nodes %s"
                         % (name, c, chain_ends, point_nodes))
        want = Q * len(elems) + (1 if chain_ends else 0)
        if len(full) != want:
            fails.append("%s: curve %d: %d nodes, Q * lines (+1) = %d" % (name, c, len(full), want))
        return
    # an interface: its nodes on the shared CAD curve, used by both faces
    far = max(abs(on_shared(*pos[n])) for n in full)
    tol = tol([pos[n] for n in full])
    if far > tol:
        fails.append("%s: interface %d: a node %.3g off the shared curve" % (name, c, far))
    faces = [s for (d, s), v in ent.items() if d == 2 and c in [abs(b) for b in v[2]]]
    signs = sorted(b for (d, s), v in ent.items() if d == 2 for b in v[2] if abs(b) == c)
    if len(faces) != 2 or signs != [-c, c]:
        fails.append("%s: interface %d bounds surfaces %s with signs %s" % (name, c, faces, signs))
        return
    used = [{n for e in ent[(2, s)][3] for n in e} for s in faces]
    if not set(full) <= used[0] & used[1]:
        fails.append("%s: interface %d: nodes not used by both faces" % (name, c))
    k = (len(full) - (1 if bnd else 0)) / Q
    if k != int(k) or k < 1:
        fails.append("%s: interface %d: %d nodes, not Q * k (+1)" % (name, c, len(full)))


def check(name, step, args, Q, on_shared, size, tmp, shared_tol=0.0):
    verts = cad_vertices(step)
    got = []
    for binary in ([], ["--binary"]):
        msh = os.path.join(tmp, "%s%s.msh" % (name, "_bin" if binary else ""))
        r = subprocess.run([SQ, "mesh", step, "--order", str(Q), "-o", msh, "-q"] + args + binary,
                           capture_output=True, text=True)
        if r.returncode != 0:
            fails.append("%s: exit %d: %s" % (name, r.returncode, r.stderr.strip()))
            return
        got.append(entities(msh))
        check_meshio(name, msh, got[-1][2])
    if got[0] != got[1]:
        fails.append("%s: text and binary files differ as read" % name)
    ent, pos, nnodes, periodic = got[0]
    owned = [n for v in ent.values() for n in v[0]]
    if len(owned) != nnodes or len(set(owned)) != nnodes:
        fails.append("%s: %d nodes, %d on entities (%d distinct)" % (name, nnodes, len(owned), len(set(owned))))
    points = [pos[v[0][0]] for (d, _), v in ent.items() if d == 0 and len(v[0]) == 1]
    if len(points) != sum(d == 0 for d, _ in ent) or len(points) != len(verts):
        fails.append("%s: %d point entities, %d CAD vertices" % (name, len(points), len(verts)))
    for x, y in verts:
        gap = min((math.hypot(x - p[0], y - p[1]) for p in points), default=math.inf)
        if gap > 1e-7 * size:
            fails.append("%s: CAD vertex (%g, %g): nearest point entity %.3g away" % (name, x, y, gap))
    for (d, c), (own, full, bnd, elems) in ent.items():
        if d == 1:
            check_curve(name, c, own, full, bnd, elems, ent, Q, on_shared,
                        lambda pts: max(1e-9 * size, shared_tol(pts) if callable(shared_tol)
                                        else shared_tol), pos)
    for image, (master, nodes, mnodes) in periodic.items():
        if nodes != ent[(1, image)][1] or mnodes != ent[(1, master)][1]:
            fails.append("%s: periodic %d of %d: %d/%d pairs, curves hold %d/%d nodes"
                         % (name, image, master, len(nodes), len(mnodes), len(ent[(1, image)][1]),
                            len(ent[(1, master)][1])))
    if "--periodic" in args and not periodic:
        fails.append("%s: no periodic curve read" % name)
    print("%s: %d points, %d curves (%d interfaces), %d surfaces, %d nodes"
          % (name, len(points), sum(d == 1 for d, _ in ent),
             sum(d == 1 and not v[3] for (d, _), v in ent.items()), sum(d == 2 for d, _ in ent), nnodes))


def check_meshio(name, msh, nnodes):
    try:
        import meshio
    except ImportError:
        return
    m = meshio.read(msh, file_format="gmsh")
    quads = sum(len(c.data) for c in m.cells if c.type.startswith("quad"))
    if len(m.points) != nnodes or not quads:
        fails.append("%s: meshio reads %d nodes (Gmsh %d), %d quads" % (name, len(m.points), nnodes, quads))


def main():
    gmsh.initialize(["-v", "0"])
    gmsh.option.setNumber("General.Terminal", 0)
    tmp = tempfile.mkdtemp()
    check("half_disc", os.path.join(EXAMPLES, "half_disc.step"), ["--size", "0.25"], 4,
          None, 2.0, tmp)
    gen = {}
    for dom in ("three_row", "sector", "circle_square"):
        gen[dom] = os.path.join(tmp, dom + ".step")
        r = subprocess.run([sys.executable, GEN, dom, gen[dom]], capture_output=True, text=True)
        if r.returncode != 0:
            sys.exit("domain_faces.py %s: %s" % (dom, r.stderr))
    check("three_row", gen["three_row"], ["--size", "0.25"], 3,
          lambda x, y: min(abs(x - 1), abs(x - 2.5)), 3.0, tmp)
    check("sector", gen["sector"], ["--periodic", "auto"], 5, None, 1.0, tmp)
    R, h, Q = 0.5, 0.3, 3

    def arc_tol(pts):
        # the interpolation error of the longest element side on the circle:
        # its turning angle t is Q times the widest angular step between
        # consecutive nodes (Q + 1 equispaced nodes a side), +10 % for the
        # steps' unevenness; not the size h, which a side may exceed
        a = sorted(math.atan2(y, x) for x, y in pts)
        t = Q * max([b - c for b, c in zip(a[1:], a)] + [a[0] + 2 * math.pi - a[-1]]) * 1.1
        return R * t ** (Q + 1) / (4 ** (Q + 1) * math.factorial(Q + 1))

    check("circle_square", gen["circle_square"], ["--size", str(h)], Q,
          lambda x, y: math.hypot(x, y) - R, 2.0, tmp, arc_tol)
    gmsh.finalize()
    for f in fails:
        print("FAIL:", f)
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
