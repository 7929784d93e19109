#!/usr/bin/python3
"""t625: whole 2D domains (docs/domains.md): `semquad mesh FILE` without
--face meshes every face as one conforming mesh.  Domains built here with
Gmsh's OCC kernel (tests/domain_faces.py): the circle-square (a disc in a
square sharing the circle: NekMesh's real_circle_square.step rebuilt), three
rectangles in a row sharing two straight edges, and a square whose elliptic
hole is filled by the ellipse.  With $SEMQUAD_REAL_GEOMETRIES, the real
circle-square file too.  Each at order Q = 8, read back with Gmsh's reader:

  - one face group per face ("face_N"), every quad in one of them;
  - no duplicate nodes: no two nodes closer than 1e-9 of the size;
  - the area of the mesh (the report's: Gauss quadrature of det J, exact for
    the element maps) equals the sum of the faces' exact areas to 1e-8
    relative.  Why 1e-8: the only error is the boundary's: an order-8
    interpolant of a circle or ellipse arc of turning angle t <= 1 rad
    (segments of at most the size 0.25 on radii of 0.35 and more) strays
    from the arc by at most R t^9 / (4^9 9!) < 1e-11 R, over a boundary of
    length < 10: below 1e-10 in area, with room for round-off (1e-14);
  - all quads valid: the report's Bézier lower bound of det J / max |det J|
    is positive for every quad (inverted 0);
  - every node on a shared curve is used by quads of both faces sharing it,
    and no quad side on it is a boundary line element;
  - every domain conforms on the layout road: the three rectangles as
    their layouts are (0 irregular vertices), the curved domains, whose
    faces' layouts put their corners at different places of the shared
    curve, with one face's vertices there slid onto the other's; each has
    exactly the sum of its faces' own Gauss-Bonnet minima: 0 for the
    rectangles, 4 + 4 for the disc (chi 1, no corner: four valence-3
    points) and the square around it (chi 0, four corners of one quad:
    four valence-5 points), the same for the ellipse (families of such
    domains: t646).
usage: t625-domain-mesh.py SEMQUAD DOMAIN_FACES_PY"""
import json
import math
import os
import subprocess
import sys
import tempfile

try:
    import gmsh
except ImportError:
    sys.exit(77)

SQ, GEN = sys.argv[1], sys.argv[2]
# name: (size, nfaces, predicate "on a shared curve" of a point)
DOMAINS = {
    "circle_square": (0.25, 2, lambda x, y: abs(math.hypot(x, y) - 0.5) < 1e-9),
    "three_row": (0.2, 3, lambda x, y: abs(x - 1) < 1e-9 or abs(x - 2.5) < 1e-9),
    "hole_filled": (0.1, 2,
                    lambda x, y: abs(((x - 1) / 0.6) ** 2 + ((y - 1) / 0.35) ** 2 - 1) < 1e-8),
}
fails = []


def check(name, step, size, nfaces, shared, areas, tmp):
    msh, rep = os.path.join(tmp, name + ".msh"), os.path.join(tmp, name + ".json")
    r = subprocess.run([SQ, "mesh", step, "--order", "8", "--size", str(size), "-o", msh,
                        "--report", rep, "-q"], capture_output=True, text=True)
    if r.returncode != 0:
        fails.append("%s: exit %d: %s" % (name, r.returncode, r.stderr.strip()))
        return
    report = json.load(open(rep))
    m = report["mesh"]
    if len(report["faces"]) != nfaces:
        fails.append("%s: %d faces meshed, expected %d" % (name, len(report["faces"]), nfaces))
    roads = [f["road"] for f in report["faces"]]
    # three rectangles: each face's layout is one patch with the same chord
    # counts on the shared edges, so the layout road conforms as it is:
    # block-structured, no irregular vertex; the others the faces' own
    # Gauss-Bonnet minima (the docstring)
    minimum = 0 if name == "three_row" else 8
    if roads != ["layout"] * nfaces or m["irregular_interior_vertices"] != minimum:
        fails.append("%s: roads %s, %d irregular vertices; expected the layout road, %d" %
                     (name, roads, m["irregular_interior_vertices"], minimum))
    exact = sum(areas) if areas else m["area_exact"]
    if abs(m["area"] - exact) > 1e-8 * exact:
        fails.append("%s: area %.17g, exact %.17g" % (name, m["area"], exact))
    if m["inverted"] != 0 or not m["min_scaled_jacobian"] > 0:
        fails.append("%s: %d invalid quads (min scaled Jacobian %g)" %
                     (name, m["inverted"], m["min_scaled_jacobian"]))
    gmsh.initialize(["-v", "0"])
    gmsh.open(msh)
    tags, xyz, _ = gmsh.model.mesh.getNodes()
    pos = {int(t): (xyz[3 * k], xyz[3 * k + 1]) for k, t in enumerate(tags)}
    # duplicates: sort by x, compare neighbours within the tolerance
    tol = 1e-9 * size
    order = sorted(pos.items(), key=lambda kv: kv[1][0])
    dup = 0
    for a in range(len(order)):
        b = a + 1
        while b < len(order) and order[b][1][0] - order[a][1][0] <= tol:
            if math.dist(order[a][1], order[b][1]) <= tol:
                dup += 1
            b += 1
    if dup:
        fails.append("%s: %d pairs of nodes closer than 1e-9 of the size" % (name, dup))
    groups = {gmsh.model.getPhysicalName(2, t): t for d, t in gmsh.model.getPhysicalGroups(2)}
    want = sorted("face_%d" % f["index"] for f in report["faces"])
    if sorted(groups) != want:
        fails.append("%s: surface groups %s, expected %s" % (name, sorted(groups), want))
    used = {}
    nquads = 0
    for gname, t in groups.items():
        for ent in gmsh.model.getEntitiesForPhysicalGroup(2, t):
            types, etags, enodes = gmsh.model.mesh.getElements(2, ent)
            for nodes in enodes:
                nquads += len(nodes) // 81
                for n in nodes:
                    used.setdefault(int(n), set()).add(gname)
    if nquads != m["quads"]:
        fails.append("%s: %d quads in the face groups, report %d" % (name, nquads, m["quads"]))
    on = [n for n, p in pos.items() if shared(*p)]
    both = [n for n in on if len(used.get(n, ())) >= 2]
    if not on or len(both) != len(on):
        fails.append("%s: %d of %d nodes on the shared curves used by both faces" %
                     (name, len(both), len(on)))
    _, _, lnodes = gmsh.model.mesh.getElements(1)
    for nodes in lnodes:
        for k in range(0, len(nodes), 9):
            if all(shared(*pos[int(n)]) for n in nodes[k:k + 9]):
                fails.append("%s: a boundary line element on a shared curve" % name)
                break
    gmsh.finalize()
    print("%s: %d faces, %d quads, %d nodes, %d on shared curves, area error %.2g, min scaled "
          "Jacobian %.3g" % (name, nfaces, m["quads"], m["nodes"], len(on),
                             abs(m["area"] - exact) / exact, m["min_scaled_jacobian"]))


with tempfile.TemporaryDirectory() as tmp:
    for name, (size, nfaces, shared) in DOMAINS.items():
        step = os.path.join(tmp, name + ".step")
        out = subprocess.run(["/usr/bin/python3", GEN, name, step], capture_output=True,
                             text=True, check=True).stdout
        areas = [float(l.split()[1]) for l in out.splitlines() if l.startswith("area ")]
        check(name, step, size, nfaces, shared, areas, tmp)
    real = os.environ.get("SEMQUAD_REAL_GEOMETRIES", "")
    cs = os.path.join(real, "real_circle_square.step")
    if real and os.path.isfile(cs):
        # NekMesh's file: a disc of radius 35 (mm) about the origin in a square
        # of side about 100; its exact areas from `semquad info` (Green's
        # theorem on the CAD curves)
        info = json.loads(subprocess.run([SQ, "info", cs, "--json"], capture_output=True,
                                         text=True, check=True).stdout)
        areas = [f["area"] for f in info["faces"]]
        check("real_circle_square", cs, 10.0, len(areas),
              lambda x, y: abs(math.hypot(x, y) - 35.0) < 35e-9, areas, tmp)
    else:
        print("real_circle_square.step: not found (SEMQUAD_REAL_GEOMETRIES); skipped")

for f in fails:
    print(f)
sys.exit(1 if fails else 0)
