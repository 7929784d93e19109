#!/usr/bin/python3
"""t642: periodic pairs of a domain of several faces, under a rotation
(`semquad mesh --periodic` on a file of several faces, docs/domains.md).

The domain (tests/domain_faces.py ring4): 1/8 of the ring 0.5 <= r <= 1,
cut by the arc r = 0.75 and the ray at 22.5 deg into four faces that share
four edges; each radial side is two edges of two faces, and the side at 0
deg is periodic with the side at 45 deg under the rotation by 45 deg about
the origin: each pair's two curves belong to different faces.  Its
boundary curves are named here with `--names` (points on them: inner,
outer, low, high).  Meshed with `--periodic auto` at order 6, then:

  - the report's pairs: two, (master, image) a low and a high curve, kind
    rotation, angle 45 deg and centre the origin to 1e-9 (the STEP file's
    points are written to 1e-13 or so; the transform comes from the
    curves' end points);
  - Gmsh's reader (getPeriodicNodes) returns, for each image curve, its
    master, the report's matrix and node pairs with |T(x_master) - x| <=
    1e-12 of the domain's size.  Why 1e-12: the image nodes are set to
    their masters' images by one affine map (a few roundings of 1e-16
    relative, then 17 digits written and read); nodes placed on their
    own curve would miss by the CAD's accuracy.  The pairs cover every
    node of the image curve's line elements, high-order ones included;
  - the same pairs with `--periodic A:B,C:D` named by the domain's curve
    numbers (tags), and a pair that does not match (an inner arc and a
    radial side) refused with exit 9, one line, no file;
  - no two nodes closer than 1e-9 of the size (interface and pair nodes
    are one node, not two close ones);
  - the area: the exact sector area pi/8 (1 - 1/4), within the
    interpolation bound of the arcs: an order-Q interpolant through
    points of an arc of radius R over an angle dtheta strays from it by at
    most R dtheta^(Q+1) / (Q+1)! (the (Q+1)-th derivative of R cos, R sin
    is at most R), so the area by at most the boundary's arc length times
    that, for the largest dtheta of the mesh's arc elements (measured here
    from Gmsh's line elements); plus 1e-13 for rounding of the quadrature
    (a sum of some thousand terms of 1e-16 relative);
  - `--road split` (the pairs exchanged as interfaces of the split road:
    the faces' triangulations redone until both curves of each pair carry
    the same vertices) linked to 1e-12 the same way, valid;
  - every quad valid (the report's Bezier bound: inverted 0, min scaled
    Jacobian > 0);
  - the identified domain (the ring sector glued along its radial sides:
    an annulus): chi 0 and Gauss-Bonnet's net index 0 (the four 90 deg
    corners merge in pairs into straight angles), so at least 0 irregular
    vertices; the four faces' one-patch layouts agree on the shared edges
    and the pairs at the default size (one chord count per side), so the
    mesh is the layout road's with 0 irregular vertices, the minimum;
  - the names as MSH physical names (Gmsh's reader); the Nektar++
    composites periodic_0_master and periodic_0_image, every image edge
    the image under T of one master edge (end vertices within 1e-12 of
    the size, as Nektar++ pairs them); the VTU's periodic_partner array
    marks every linked node.

A pair within one face of a domain (tests/domain_faces.py circle_square:
a disc inside the square [-1, 1]^2, two faces sharing the circle):
`--periodic auto` pairs the square's opposite sides (two pairs, by the
translations (0, 2) and (-2, 0)), all four curves of the outer face.  That
face's layout puts its corners on the sides at places of its own, so each
image side's vertices are slid onto its master's images and the face meshed again (docs/domains.md): both faces
by the layout road, as many irregular vertices as without the pair (the
slide moves vertices along the side only; the layout is the same), the
links to 1e-12 of the size as above.
usage: t642-periodic-domain.py SEMQUAD DOMAIN_FACES_PY"""
import json
import math
import os
import re
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

try:
    import gmsh
except ImportError:
    sys.exit(77)

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import nektar_xml  # noqa: E402  (tests/nektar_xml.py)

SQ, GEN = sys.argv[1], sys.argv[2]
ORDER = 6
fails = []
# points on the boundary curves (the arcs' and the rays' middles)
NAMES = "".join("%.6f %.6f %s\n" % (r * math.cos(a), r * math.sin(a), name)
                for r, a, name in ((0.5, math.pi / 16, "inner"), (0.5, 3 * math.pi / 16, "inner"),
                                   (1, math.pi / 16, "outer"), (1, 3 * math.pi / 16, "outer"),
                                   (0.625, 0, "low"), (0.875, 0, "low"),
                                   (0.625, math.pi / 4, "high"), (0.875, math.pi / 4, "high")))


def mesh(step, out, extra=()):
    return subprocess.run([SQ, "mesh", step, "--order", str(ORDER), "-o", out, "-q"] + list(extra),
                          capture_output=True, text=True)


def read_gmsh(msh):
    """nodes {tag: (x, y)}, periodic links {image: (master, affine, pairs)},
    physical names of dim 1, arc element angles (largest, radius)"""
    gmsh.initialize(["-v", "0"])
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.open(msh)
    tags, xyz, _ = gmsh.model.mesh.getNodes()
    pos = dict(zip(tags, zip(xyz[0::3], xyz[1::3])))
    links = {}
    for dim, tag in gmsh.model.getEntities(1):
        master, nodes, mnodes, aff = gmsh.model.mesh.getPeriodicNodes(dim, tag)
        if master != tag and len(nodes):
            on_curve = set()
            for _, _, enodes in zip(*gmsh.model.mesh.getElements(1, tag)):
                on_curve.update(enodes)
            links[tag] = (master, list(aff), list(zip(nodes, mnodes)), on_curve)
    names = {}
    for dim, ptag in gmsh.model.getPhysicalGroups(1):
        names[gmsh.model.getPhysicalName(dim, ptag)] = gmsh.model.getEntitiesForPhysicalGroup(dim, ptag)
    dtheta = 0.0
    for name in ("inner", "outer"):
        for ent in names.get(name, []):
            for _, _, enodes in zip(*gmsh.model.mesh.getElements(1, ent)):
                npe = ORDER + 1
                for k in range(0, len(enodes), npe):
                    a, b = pos[enodes[k]], pos[enodes[k + 1]]  # the element's two end nodes
                    dtheta = max(dtheta, abs(math.atan2(a[0] * b[1] - a[1] * b[0],
                                                        a[0] * b[0] + a[1] * b[1])))
    gmsh.finalize()
    return pos, links, names, dtheta


def min_distance(pts):
    """smallest distance between two of pts (sorted sweep in x)"""
    p = sorted(pts)
    best = math.inf
    for i in range(len(p)):
        for j in range(i + 1, len(p)):
            if p[j][0] - p[i][0] >= best:
                break
            best = min(best, math.hypot(p[j][0] - p[i][0], p[j][1] - p[i][1]))
    return best


def check_pairs(rep, size):
    pairs = rep["periodic"]["pairs"]
    c, s = math.cos(math.pi / 4), math.sin(math.pi / 4)
    if len(pairs) != 2:
        fails.append("pairs: %s, expected two" % pairs)
    for p in pairs:
        a = p["affine"]
        angle = math.degrees(math.atan2(a[3], a[0]))
        # the centre: (I - R) x = t
        det = (1 - a[0]) ** 2 + a[3] ** 2
        cx = ((1 - a[0]) * a[2] - a[3] * a[5]) / det
        cy = (a[3] * a[2] + (1 - a[0]) * a[5]) / det
        print("pair %s: %s by %.12g deg about (%.3g, %.3g), %d nodes"
              % (p["edges"], p["kind"], angle, cx, cy, p["nodes"]))
        if p["kind"] != "rotation" or abs(angle - 45) > 1e-9 or math.hypot(cx, cy) > 1e-9 * size \
                or max(abs(a[0] - c), abs(a[1] + s), abs(a[3] - s), abs(a[4] - c)) > 1e-9:
            fails.append("pair %s: %s %s" % (p["edges"], p["kind"], a))
    return {tuple(p["edges"]) for p in pairs}


def check_links(rep, pos, links, size):
    for p in rep["periodic"]["pairs"]:
        master, image = p["edges"]
        if image + 1 not in links:
            fails.append("Gmsh reads no periodic link for curve %d" % (image + 1))
            continue
        lm, aff, node_pairs, on_curve = links[image + 1]
        a = p["affine"]
        if lm != master + 1 or max(abs(u - v) for u, v in
                                   zip((aff[0], aff[1], aff[3], aff[4], aff[5], aff[7]), a)) > 1e-13:
            fails.append("Gmsh's link of curve %d: master %d, affine %s" % (image + 1, lm, aff))
        gap = 0.0
        for n, m in node_pairs:
            x, y = pos[m]
            tx, ty = aff[0] * x + aff[1] * y + aff[3], aff[4] * x + aff[5] * y + aff[7]
            gap = max(gap, math.hypot(tx - pos[n][0], ty - pos[n][1]))
        print("curve %d: %d node pairs (%d of them high-order), largest |T(x_master) - x| %.3g of "
              "the size" % (image + 1, len(node_pairs), len(node_pairs) - (len(node_pairs) - 1) //
                            ORDER - 1, gap / size))
        if gap > 1e-12 * size:
            fails.append("curve %d: nodes %.3g of the size from their masters' images"
                         % (image + 1, gap / size))
        if {n for n, _ in node_pairs} != on_curve or len(node_pairs) != p["nodes"]:
            fails.append("curve %d: %d pairs, %d nodes on the curve, report %d"
                         % (image + 1, len(node_pairs), len(on_curve), p["nodes"]))


def check_named(step, expect, tmp):
    spec = ",".join("%d:%d" % e for e in sorted(expect))
    out, rep = os.path.join(tmp, "named.msh"), os.path.join(tmp, "named.json")
    r = mesh(step, out, ["--periodic", spec, "--report", rep])
    got = {tuple(p["edges"]) for p in json.load(open(rep))["periodic"]["pairs"]} \
        if r.returncode == 0 else set()
    if got != expect:
        fails.append("--periodic %s: exit %d, pairs %s: %s" % (spec, r.returncode, got, r.stderr))
    inner = min(expect)[0]
    bad = os.path.join(tmp, "bad.msh")
    # an arc and a straight side of other lengths cannot match
    arcs = [t for t in range(8) if all(t not in e for e in expect)]
    r = mesh(step, bad, ["--periodic", "%d:%d" % (arcs[0], inner)])
    lines = r.stderr.strip().splitlines()
    if r.returncode != 9 or len(lines) != 1 or os.path.exists(bad):
        fails.append("--periodic %d:%d: exit %d, %d lines, output %s"
                     % (arcs[0], inner, r.returncode, len(lines), os.path.exists(bad)))


def check_split_road(step, tmp, size):
    """--road split: the pairs exchanged as interfaces are (the split road's
    triangulations agree on both curves of each pair), linked the same way"""
    msh, rep_path = os.path.join(tmp, "split.msh"), os.path.join(tmp, "split.json")
    r = mesh(step, msh, ["--periodic", "auto", "--road", "split", "--report", rep_path])
    if r.returncode != 0:
        fails.append("--road split: exit %d: %s" % (r.returncode, r.stderr.strip()))
        return
    rep = json.load(open(rep_path))
    pos, links, _, _ = read_gmsh(msh)
    check_links(rep, pos, links, size)
    m, per = rep["mesh"], rep["periodic"]
    print("--road split: %d quads, %d irregular (Gauss-Bonnet: %d), min scaled Jacobian %.3f"
          % (m["quads"], per["irregular_interior_vertices"], per["gauss_bonnet_min_irregular"],
             m["min_scaled_jacobian"]))
    if m["inverted"] or (per["identified_chi"], per["gauss_bonnet_index"]) != (0, 0) or \
            [f["road"] for f in rep["faces"]] != ["split"] * 4:
        fails.append("--road split: %d inverted, chi %d, index %d, roads %s" % (
            m["inverted"], per["identified_chi"], per["gauss_bonnet_index"], rep["faces"]))


def composite_edges(geometry, name):
    """the edge ids of the Nektar++ composite called name ("E[1-3,7]")"""
    for c in ET.fromstring(geometry["composite"]):
        if c.get("NAME") == name:
            ids = []
            for part in c.text.strip()[2:-1].split(","):
                first, _, last = part.partition("-")
                ids.extend(range(int(first), int(last or first) + 1))
            return ids
    return []


def check_writers(step, names_file, affine, size, tmp):
    """Nektar++: every edge of periodic_0_image is the image under T of an
    edge of periodic_0_master (end vertices within 1e-12 of the size, how
    Nektar++ pairs them), one to one; the VTU's periodic_partner marks"""
    xml, vtu = os.path.join(tmp, "ring4.xml"), os.path.join(tmp, "ring4.vtu")
    rx = mesh(step, xml, ["--periodic", "auto", "--names", names_file])
    g = nektar_xml.read(xml) if rx.returncode == 0 else None
    master = composite_edges(g, "periodic_0_master") if g else []
    image = composite_edges(g, "periodic_0_image") if g else []
    a = affine

    def ends(e, T):
        v = [g["vertices"][k] for k in g["edges"][e]]
        return [(a[0] * x + a[1] * y + a[2], a[3] * x + a[4] * y + a[5]) if T else (x, y)
                for x, y, _ in v]

    mapped = [ends(e, True) for e in master]
    matched = 0
    for e in image:
        p = ends(e, False)
        matched += sum(1 for q in mapped if max(math.dist(p[0], q[1]), math.dist(p[1], q[0])) <=
                       1e-12 * size or max(math.dist(p[0], q[0]), math.dist(p[1], q[1])) <= 1e-12 * size) == 1
    print("Nektar++: %d master edges, %d image edges, %d images of a master edge"
          % (len(master), len(image), matched))
    if not master or len(master) != len(image) or matched != len(image):
        fails.append("Nektar++ periodic composites: %d master, %d image edges, %d matched"
                     % (len(master), len(image), matched))
    rv = mesh(step, vtu, ["--periodic", "auto"])
    text = open(vtu).read() if rv.returncode == 0 else ""
    m = re.search(r'Name="periodic_partner"[^>]*>([^<]*)<', text)
    return [int(v) for v in m.group(1).split()] if m else []


def check_pair_within_face(tmp):
    step = os.path.join(tmp, "circle_square.step")
    subprocess.run([sys.executable, GEN, "circle_square", step], check=True, capture_output=True)
    size = 2 * math.sqrt(2)  # the square's diagonal
    plain, plain_rep = os.path.join(tmp, "cs.msh"), os.path.join(tmp, "cs.json")
    msh, rep_path = os.path.join(tmp, "csp.msh"), os.path.join(tmp, "csp.json")
    r0 = mesh(step, plain, ["--report", plain_rep])
    r = mesh(step, msh, ["--periodic", "auto", "--report", rep_path])
    if r0.returncode or r.returncode:
        fails.append("circle_square: exit %d, with --periodic auto %d: %s"
                     % (r0.returncode, r.returncode, r.stderr.strip()))
        return
    rep, n0 = json.load(open(rep_path)), json.load(open(plain_rep))["mesh"]["irregular_interior_vertices"]
    pos, links, _, _ = read_gmsh(msh)
    check_links(rep, pos, links, size)
    m, roads = rep["mesh"], [f["road"] for f in rep["faces"]]
    print("circle_square, --periodic auto: pairs %s, roads %s, %d quads, %d irregular (%d without "
          "the pair), min scaled Jacobian %.3f" % ([p["edges"] for p in rep["periodic"]["pairs"]], roads,
                                                    m["quads"], m["irregular_interior_vertices"], n0,
                                                    m["min_scaled_jacobian"]))
    if sorted(p["kind"] for p in rep["periodic"]["pairs"]) != ["translation"] * 2 or roads != ["layout"] * 2 or \
            m["irregular_interior_vertices"] != n0 or m["inverted"] or not m["min_scaled_jacobian"] > 0:
        fails.append("circle_square --periodic auto: pairs %s, roads %s, %d irregular (%d without), "
                     "%d inverted" % (rep["periodic"]["pairs"], roads, m["irregular_interior_vertices"],
                                      n0, m["inverted"]))


def main():
    with tempfile.TemporaryDirectory() as tmp:
        step = os.path.join(tmp, "ring4.step")
        gen = subprocess.run([sys.executable, GEN, "ring4", step], check=True, capture_output=True,
                             text=True)
        exact = sum(float(l.split()[1]) for l in gen.stdout.splitlines() if l.startswith("area"))
        names_file = os.path.join(tmp, "names.txt")
        with open(names_file, "w") as f:
            f.write(NAMES)
        msh, rep_path = os.path.join(tmp, "ring4.msh"), os.path.join(tmp, "ring4.json")
        r = mesh(step, msh, ["--periodic", "auto", "--names", names_file, "--report", rep_path])
        if r.returncode != 0:
            print("FAIL exit %d: %s" % (r.returncode, r.stderr.strip()))
            sys.exit(1)
        rep = json.load(open(rep_path))
        size = math.hypot(1 - 0.5 * math.cos(math.pi / 4), math.sin(math.pi / 4))  # the box's diagonal
        expect = check_pairs(rep, size)
        pos, links, names, dtheta = read_gmsh(msh)
        check_links(rep, pos, links, size)
        check_named(step, expect, tmp)
        nearest = min_distance(list(pos.values()))
        if nearest < 1e-9 * size:
            fails.append("two nodes %.3g apart (duplicates)" % nearest)
        mesh_rep, per = rep["mesh"], rep["periodic"]
        sector = math.pi / 8 * (1 - 0.25)
        bound = (math.pi / 4 * (0.5 + 1)) * dtheta ** (ORDER + 1) / math.factorial(ORDER + 1) + 1e-13
        err = abs(mesh_rep["area"] - sector)
        print("area %.15g, exact %.15g (faces %.15g): error %.2g, bound %.2g (largest arc element "
              "%.3g rad)" % (mesh_rep["area"], sector, exact, err, bound, dtheta))
        if err > bound or abs(exact - sector) > 1e-15:
            fails.append("area %.17g, exact %.17g, bound %.3g" % (mesh_rep["area"], sector, bound))
        if mesh_rep["inverted"] != 0 or not mesh_rep["min_scaled_jacobian"] > 0:
            fails.append("%d quads not valid (min scaled Jacobian %g)"
                         % (mesh_rep["inverted"], mesh_rep["min_scaled_jacobian"]))
        roads = [f["road"] for f in rep["faces"]]
        print("%d faces (roads %s), %d quads, %d nodes, min scaled Jacobian %.3f; identified chi "
              "%d, Gauss-Bonnet index %d (at least %d irregular), mesh %d irregular"
              % (len(rep["faces"]), roads, mesh_rep["quads"], mesh_rep["nodes"],
                 mesh_rep["min_scaled_jacobian"], per["identified_chi"], per["gauss_bonnet_index"],
                 per["gauss_bonnet_min_irregular"], per["irregular_interior_vertices"]))
        if (per["identified_chi"], per["gauss_bonnet_index"]) != (0, 0):
            fails.append("identified chi %d, index %d; expected 0, 0"
                         % (per["identified_chi"], per["gauss_bonnet_index"]))
        if roads != ["layout"] * 4 or per["irregular_interior_vertices"] != 0:
            fails.append("roads %s, %d irregular vertices (Gauss-Bonnet: 0)"
                         % (roads, per["irregular_interior_vertices"]))
        if sorted(names) != ["high", "inner", "low", "outer"] or \
                any(len(v) != 2 for v in names.values()):
            fails.append("physical names of curves %s" % names)
        check_split_road(step, tmp, size)
        partner = check_writers(step, names_file, rep["periodic"]["pairs"][0]["affine"], size, tmp)
        # the nodes of the links, masters and images (the chain's middle
        # vertex is in both links)
        linked = {n for _, _, pairs, _ in links.values() for pair in pairs for n in pair}
        if sum(v >= 0 for v in partner) != len(linked):
            fails.append("VTU periodic_partner marks %d nodes, expected %d"
                         % (sum(v >= 0 for v in partner), len(linked)))
        check_pair_within_face(tmp)
    for f in fails:
        print("FAIL", f)
    sys.exit(1 if fails else 0)


if __name__ == "__main__":
    main()
