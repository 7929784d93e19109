#!/usr/bin/python3
"""t646: mesh families of domains of several faces (`semquad mesh FILE
--levels L --orders Q1,Q2`, docs/convergence-families.md "Domains of
several faces"): each face's mesh refined in its own frame, the faces'
meshes merged as the domain's first mesh was.

Domains built here (tests/domain_faces.py): circle_square (a disc inside a
square, sharing the circle), named by a --names file (the disc "disc", the
square's right side "outlet"), with --levels 3 --orders 2,4; ring4 (the
ring sector cut into four faces sharing two arcs and two segments) with
--levels 3 --orders 2.  Every file is read by Gmsh's reader
(tests/msh_quad_stats.py):

  - quads x4 from each level to the next; no triangle; no two nodes (the
    high-order ones too) closer than 1e-9 of the size (the nodes of a
    shared curve are one node, not one per face);
  - nested: every corner vertex of level k is a node of level k+1 within
    1e-12 of the size (the vertices are copied and mapped into the
    domain's frame by the same operations at every level: they agree to
    the bit, and 1e-12 leaves room for the 17 digits written and read);
  - the nodes used by two faces' elements are exactly the nodes on the
    shared curves (|r - 0.5| <= 1e-9 on the circle: the new nodes are
    placed on the CAD curve, to its evaluation's round-off), every one of
    them referenced by both faces;
  - det J > 0 at every Gauss point of every element, and the manifest's
    min_scaled_jacobian > 0 with no quad inverted;
  - the face groups (and the named boundary) in every file, one surface
    group per face: "disc", the square's "face_N", and "outlet" of
    circle_square; ring4's four "face_N";
  - area: the faces' areas, the integral of det J of the elements' own
    maps (Gauss, exact for these polynomials), against the exact ones
    (the disc pi/4; ring4's sum).  Estimate (docs/convergence-families.md,
    "What converges"): the boundary of an element of order Q interpolates
    its curve at GLL arc-length points, and the area error, the integral
    of the normal gap, is O(h^(2Q)) (Lobatto quadrature's exactness);
    a smooth curve (circles here) reaches that rate at once.  Asserted at
    Q=2, where the errors (1e-6 .. 1e-12) stay far above round-off: each
    level's error at most 2^-(2Q) of the last's, times 2^0.25 for the
    constant's change between levels (observed rates 4.00); at Q=4
    (errors at round-off) only |error| <= 1e-9 of the area.  New curve
    nodes on the parent's polynomial instead of the curve would stall the
    error at level 1's;
  - the manifest: its faces and face_area (the sum of the exact areas), one
    entry per file with the file's quads and nodes (dofs = nodes), h_area
    halving per level (to the area's own change, 1e-6), h_mean and h_max
    decreasing;
  - byte for byte the same files with --threads 2 as with --threads 1.
A single face's family keeps its named boundary too (examples/disc.step,
"0 wall": the name in level 2's file).
usage: t646-domain-family.py SEMQUAD DOMAIN_FACES_PY EXAMPLES_DIR"""
import filecmp
import json
import math
import os
import subprocess
import sys
import tempfile

try:
    import gmsh  # noqa: F401  (msh_quad_stats needs it)
    from scipy.spatial import cKDTree
except ImportError:
    sys.exit(77)

SQ, GEN, EXAMPLES = (os.path.abspath(a) for a in sys.argv[1:4])
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import msh_quad_stats  # noqa: E402

fails = []


def fail(msg):
    fails.append(msg)


def family(step, out, args):
    """Run the family; its manifest (None on failure)."""
    r = subprocess.run([SQ, "mesh", step, "-o", out, "-q"] + args, capture_output=True, text=True)
    if r.returncode != 0:
        fail("%s %s: exit %d: %s" % (os.path.basename(step), args, r.returncode, r.stderr.strip()))
        return None
    return json.load(open(out[:-4] + "_manifest.json"))


def physical_names(path):
    gmsh.initialize(["-v", "0"])
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.open(path)
    names = {gmsh.model.getPhysicalName(d, t) for d, t in gmsh.model.getPhysicalGroups()}
    nodes = len(gmsh.model.mesh.getNodes()[0])
    gmsh.finalize()
    return names, nodes


def check_file(name, e, size, groups_expected, on_shared):
    """One file of a family: quads, nodes, duplicates, groups, shared
    nodes, det J; its faces' areas."""
    path, tag = e["file"], "%s L%d Q%d" % (name, e["level"], e["order"])
    st = msh_quad_stats.stats(path)
    if st["quads"] != e["quads"] or st["triangles"] or st["inverted_quads"]:
        fail("%s: %d quads (manifest %d), %d triangles, %d inverted" % (
            tag, st["quads"], e["quads"], st["triangles"], st["inverted_quads"]))
    if st["duplicate_nodes"]:
        fail("%s: %d pairs of nodes closer than 1e-9 of the diameter" % (tag, st["duplicate_nodes"]))
    names, nnodes = physical_names(path)
    if nnodes != e["nodes"] or e["dofs"] != e["nodes"]:
        fail("%s: %d nodes in the file, manifest nodes %d dofs %d" % (tag, nnodes, e["nodes"],
                                                                      e["dofs"]))
    # V + (Q-1) E + (Q-1)^2 F nodes of a conforming mesh of order Q
    Q, V, F = e["order"], st["vertices"], st["quads"]
    E = V + F - st["euler_chi"]
    if nnodes != V + (Q - 1) * E + (Q - 1) ** 2 * F:
        fail("%s: %d nodes, a conforming mesh has %d" % (tag, nnodes,
                                                         V + (Q - 1) * E + (Q - 1) ** 2 * F))
    if not groups_expected <= names:
        fail("%s: groups %s, missing %s" % (tag, sorted(names), sorted(groups_expected - names)))
    if not e["min_scaled_jacobian"] > 0 or e["inverted"]:
        fail("%s: min scaled Jacobian %g, %d inverted" % (tag, e["min_scaled_jacobian"],
                                                          e["inverted"]))
    g = msh_quad_stats.face_groups(path)
    faces = [k for k in g if k not in ("outlet",) and not k.startswith("boundary_")]
    if len(faces) != len(e["faces"]):
        fail("%s: face groups %s for the faces %s" % (tag, faces, e["faces"]))
    for k in faces:
        if not g[k][1] > 0:
            fail("%s: face %s has det J %g at a Gauss point" % (tag, k, g[k][1]))
    _, _, pos = msh_quad_stats.read_elements(path)
    close = cKDTree(list(pos.values())).query_pairs(1e-9 * size)
    if close:
        fail("%s: %d pairs of nodes (high-order ones too) within 1e-9 of the size" % (tag,
                                                                                   len(close)))
    shared = set()
    for i, a in enumerate(faces):
        for b in faces[i + 1:]:
            shared |= g[a][2] & g[b][2]
    want = {n for n, p in pos.items() if on_shared(p)}
    if shared != want or not want:
        fail("%s: %d nodes in two faces' elements, %d on the shared curves (%d of them in one "
             "face only)" % (tag, len(shared), len(want), len(want - shared)))
    print("%s: %d quads, %d nodes, %d on shared curves, no duplicate, min det J %.3g" % (
        tag, e["quads"], nnodes, len(want), min(g[k][1] for k in faces)))
    return {k: g[k][0] for k in faces}


def check_family(name, manifest, exact_area, size, groups, on_shared, measure):
    """The family's files, nesting, manifest entries, area rates; measure:
    the area compared, from a file's {face group: area}."""
    files = {(e["level"], e["order"]): e for e in manifest["meshes"]}
    if abs(manifest["face_area"] - exact_area[1]) > 1e-12 * exact_area[1]:
        fail("%s: manifest face_area %.17g, exact %.17g" % (name, manifest["face_area"],
                                                             exact_area[1]))
    err = {}
    for key, e in sorted(files.items()):
        e["faces"] = manifest["faces"]
        err[key] = measure(check_file(name, e, size, groups, on_shared)) - exact_area[0]
    levels = sorted({l for l, _ in files})
    for q in sorted({q for _, q in files}):
        for l in levels[1:]:
            fine, coarse = files[(l, q)], files[(l - 1, q)]
            if fine["quads"] != 4 * coarse["quads"]:
                fail("%s Q%d: %d quads at level %d, %d at %d" % (name, q, fine["quads"], l,
                                                                  coarse["quads"], l - 1))
            if (abs(coarse["h_area"] / fine["h_area"] - 2) > 1e-6 or
                    not fine["h_mean"] < coarse["h_mean"] or not fine["h_max"] < coarse["h_max"]):
                fail("%s Q%d L%d: h_area %g after %g, h_mean %g after %g" % (
                    name, q, l, fine["h_area"], coarse["h_area"], fine["h_mean"], coarse["h_mean"]))
            a = msh_quad_stats.read_elements(coarse["file"])
            b = msh_quad_stats.read_elements(fine["file"])
            tree = cKDTree(list(b[2].values()))
            far = max(tree.query(a[2][n])[0] for n in {int(v) for quad in a[0] for v in quad})
            if far > 1e-12 * size:
                fail("%s Q%d: a level-%d vertex is %.3g from every level-%d node" % (
                    name, q, l - 1, far, l))
            e0, e1 = abs(err[(l - 1, q)]), abs(err[(l, q)])
            if q == 2 and not e1 <= e0 * 2.0 ** (0.25 - 2 * q):
                fail("%s Q2: area error %.3g at level %d after %.3g (rate %.2f < %d)" % (
                    name, e1, l, e0, math.log2(e0 / e1) if e1 else 99, 2 * q))
        for l in levels:
            if q != 2 and abs(err[(l, q)]) > 1e-9 * exact_area[0]:
                fail("%s Q%d L%d: area error %.3g" % (name, q, l, err[(l, q)]))
        print("%s Q%d: area errors %s" % (name, q, " ".join("%.3g" % err[(l, q)] for l in levels)))


def step_of(name, tmp):
    step = os.path.join(tmp, name + ".step")
    out = subprocess.run(["/usr/bin/python3", GEN, name, step], capture_output=True, text=True,
                         check=True).stdout
    return step, [float(l.split()[1]) for l in out.splitlines() if l.startswith("area ")]


def circle_square(tmp):
    step, areas = step_of("circle_square", tmp)
    names = os.path.join(tmp, "names.txt")
    with open(names, "w") as f:
        f.write("face 0 0 disc\n1 0 outlet\n")  # the face about the origin; x = 1
    args = ["--levels", "3", "--orders", "2,4", "--names", names]
    out = os.path.join(tmp, "cs.msh")
    m = family(step, out, args + ["--threads", "1"])
    if m is None:
        return
    if m["faces"] != [0, 1] or len(m["meshes"]) != 6:
        fail("circle_square: manifest faces %s, %d files" % (m["faces"], len(m["meshes"])))
        return
    check_family("circle_square", m, (math.pi / 4, sum(areas)), 2.0,
                 {"disc", "outlet"}, lambda p: abs(math.hypot(*p) - 0.5) <= 1e-9,
                 lambda a: a["disc"])
    # the same files on two threads
    out2 = os.path.join(tmp, "t2", "cs.msh")
    os.mkdir(os.path.dirname(out2))
    if family(step, out2, args + ["--threads", "2"]) is not None:
        for e in m["meshes"]:
            twin = os.path.join(os.path.dirname(out2), os.path.basename(e["file"]))
            if not filecmp.cmp(e["file"], twin, shallow=False):
                fail("circle_square: %s differs with --threads 2" % os.path.basename(e["file"]))


def ring4(tmp):
    step, areas = step_of("ring4", tmp)
    m = family(step, os.path.join(tmp, "ring4.msh"), ["--levels", "3", "--orders", "2"])
    if m is None:
        return

    def on_shared(p):  # the arc r = 0.75 and the ray at 22.5 deg, inside the ring
        r, t = math.hypot(*p), math.atan2(p[1], p[0])
        return abs(r - 0.75) <= 1e-9 or (abs(t - math.pi / 8) * r <= 1e-9 and 0.5 <= r <= 1)

    check_family("ring4", m, (sum(areas), sum(areas)), 0.5, {"face_%d" % k for k in range(4)},
                 on_shared, lambda a: sum(a.values()))


def one_face(tmp):
    names = os.path.join(tmp, "wall.txt")
    with open(names, "w") as f:
        f.write("0 wall\n")
    m = family(os.path.join(EXAMPLES, "disc.step"), os.path.join(tmp, "disc.msh"),
               ["--levels", "2", "--names", names])
    if m is not None and "wall" not in physical_names(m["meshes"][1]["file"])[0]:
        fail("disc: level 2 lost the name 'wall'")


def main():
    with tempfile.TemporaryDirectory() as tmp:
        circle_square(tmp)
        ring4(tmp)
        one_face(tmp)
    for f in fails:
        print("FAIL", f)
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
