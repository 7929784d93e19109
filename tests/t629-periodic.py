#!/usr/bin/python3
"""t629: periodic boundaries (`semquad mesh --periodic`, docs/domains.md).

Faces built here: the project's own T106-like cascade passage
(tests/cascade_aerofoil.py: periodic lines of four segments one pitch,
0.8, apart), 1/8 of the ring 0.5 <= r <= 1 (tests/domain_faces.py
sector: its radial sides periodic under the rotation by 45 deg about the
origin) and a channel with a round hole whose walls are periodic under
the translation by (0, 1) (domain_faces.py channel), and
examples/square.step, periodic both ways (a torus); with
$SEMQUAD_REAL_GEOMETRIES, NekMesh's real T106 file too (pitch 0.798; by
route 1b with Gauss-Bonnet's 4, since its folded patches are untangled).  Each meshed with `--periodic auto` at order 6, then:

  - the pairs found are the expected edges under the expected transform;
  - Gmsh's reader loads the MSH file with its $Periodic section and
    getPeriodicNodes gives (from the text file and from the --binary one
    alike), for every image curve, its master curve, the
    affine map of the report and node pairs with |T(x_master) - x| <= 1e-12
    of the face's size.  Why 1e-12: the image nodes are the master nodes
    mapped by one affine map (one multiply-add per coordinate, then the
    17-digit decimal written and read back): a few roundings of numbers of
    the face's size, 1e-16 relative each; 1e-12 leaves room but would catch
    nodes placed on the partner curve by its own arc length (the CAD
    curves match to the file's accuracy, 1e-13 to 1e-7);
  - both curves of a pair carry the same nodes count (the pairs are one to
    one and cover the image curve's line elements' nodes);
  - every quad valid (the report's Bezier bound: inverted 0, min scaled
    Jacobian > 0);
  - the identified domain: Euler characteristic (passage with a blade, its
    periodic lines glued: -1, the channel likewise; the sector glued: a
    ring, 0; the square: a torus, 0), the net index its interior vertices
    need by Gauss-Bonnet (-4, -4, 0 and 0: the corners merge in pairs to
    straight angles, the kinks
    and the square's four corners to full turns), and the mesh's
    irregular vertices there at least that many; the sector, whose single
    layout patch puts the same nodes on both radial sides, on the layout
    road with no irregular vertex at all, as the square; the channel on the
    layout road of its identified domain (field glued across the walls,
    separatrices re-entering, one chord count for a piece and its image)
    with exactly Gauss-Bonnet's 4 irregular vertices;
  - route 1b (domain_faces.py channel_offset, the channel with its hole
    off the centre line, and sector_hole, a quarter ring less a disc,
    periodic under the quarter turn): the face's own layout with one chord
    total per curve and the image's vertices slid onto the master's
    images, on the layout road with exactly Gauss-Bonnet's 4;
  - a mesh with more irregular vertices than Gauss-Bonnet's count (the
    cascade, on the split road) says in road_reason why route 1b and
    route 1 failed (docs/domains.md);
  - Nektar++ XML: one composite per periodic side, both with as many edges;
  - `--periodic 0:1` on the cascade (lengths 1.67 and 0.4) exits 9 with
    one line on stderr and writes nothing.
usage: t629-periodic.py SEMQUAD DOMAIN_FACES_PY CASCADE_STEP"""
import json
import math
import os
import re
import subprocess
import sys
import tempfile

try:
    import gmsh
except ImportError:
    sys.exit(77)

SQ, GEN, CASCADE = sys.argv[1], sys.argv[2], sys.argv[3]
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import msh_quad_stats  # noqa: E402
fails = []


def run_mesh(step, out, rep, extra=()):
    return subprocess.run([SQ, "mesh", step, "--periodic", "auto", "--order", "6", "-o", out,
                           "--report", rep, "-q"] + list(extra), capture_output=True, text=True)


def check(name, step, expect, tmp):
    """expect: pairs {(master, image)}, kind, transform check, chi, index,
    layout (1: layout road with exactly Gauss-Bonnet's irregular vertices)"""
    msh, rep, xml = (os.path.join(tmp, name + e) for e in (".msh", ".json", ".xml"))
    r = run_mesh(step, msh, rep)
    if r.returncode != 0:
        fails.append("%s: exit %d: %s" % (name, r.returncode, r.stderr.strip()))
        return
    report = json.load(open(rep))
    per, mesh = report["periodic"], report["mesh"]
    got = {tuple(p["edges"]) for p in per["pairs"]}
    if got != expect["pairs"]:
        fails.append("%s: pairs %s, expected %s" % (name, sorted(got), sorted(expect["pairs"])))
    for p in per["pairs"]:
        if p["kind"] != expect["kind"] or not expect["transform"](p["affine"]):
            fails.append("%s: pair %s: %s %s" % (name, p["edges"], p["kind"], p["affine"]))
    bb = [float(v) for v in re.findall(r"[-0-9.e]+", subprocess.run(
        [SQ, "info", step], capture_output=True, text=True).stdout.split("bbox")[1].split("\n")[0])]
    size = math.hypot(bb[1] - bb[0], bb[3] - bb[2])
    links = msh_quad_stats.periodic_pairs(msh, size)
    for p in per["pairs"]:
        master, image = p["edges"]
        if image not in links:
            fails.append("%s: Gmsh reads no periodic link for curve %d" % (name, image + 1))
            continue
        lm, aff, gap, npairs, ncurve = links[image]
        a = p["affine"]
        # the report prints 15 digits, the MSH file 17
        if lm != master or max(abs(u - v) for u, v in
                               zip((aff[0], aff[1], aff[3], aff[4], aff[5], aff[7]), a)) > 1e-13 * size:
            fails.append("%s: Gmsh's link of curve %d: master %d, affine %s" % (name, image, lm, aff))
        if gap > 1e-12:
            fails.append("%s: curve %d: nodes %.3g of the size from their master's images"
                         % (name, image, gap))
        if npairs != ncurve or npairs != p["nodes"]:
            fails.append("%s: curve %d: %d pairs, %d nodes on the curve, report %d"
                         % (name, image, npairs, ncurve, p["nodes"]))
    # the binary file (--binary) holds the same links, read by the same reader
    binmsh = os.path.join(tmp, name + "_bin.msh")
    rb = run_mesh(step, binmsh, os.path.join(tmp, name + "_bin.json"), ["--binary"])
    if rb.returncode != 0 or msh_quad_stats.periodic_pairs(binmsh, size) != links:
        fails.append("%s: --binary: exit %d, its periodic links differ from the text file's"
                     % (name, rb.returncode))
    if mesh["inverted"] != 0 or not mesh["min_scaled_jacobian"] > 0:
        fails.append("%s: %d quads not valid" % (name, mesh["inverted"]))
    if (per["identified_chi"], per["gauss_bonnet_index"]) != (expect["chi"], expect["index"]):
        fails.append("%s: identified chi %d, index %d; expected %d, %d" % (
            name, per["identified_chi"], per["gauss_bonnet_index"], expect["chi"], expect["index"]))
    if per["irregular_interior_vertices"] < abs(per["gauss_bonnet_index"]):
        fails.append("%s: %d irregular vertices, fewer than Gauss-Bonnet's %d" % (
            name, per["irregular_interior_vertices"], abs(per["gauss_bonnet_index"])))
    if expect["layout"] and (report["road"] != "layout" or per["irregular_interior_vertices"]
                             != abs(per["gauss_bonnet_index"])):
        fails.append("%s: road %s, %d irregular (Gauss-Bonnet: %d)" % (
            name, report["road"], per["irregular_interior_vertices"],
            abs(per["gauss_bonnet_index"])))
    # above Gauss-Bonnet's count the report says why the face's own layout
    # (route 1b) did not mesh it and why the identified domain's did not
    # (issue 14; docs/domains.md, route 1b)
    if per["irregular_interior_vertices"] > abs(per["gauss_bonnet_index"]) and not re.search(
            r"\(route 1b\): .+; the identified domain's layout \(route 1\): .+",
            report.get("road_reason", "")):
        fails.append("%s: %d irregular vertices over Gauss-Bonnet's %d, no reason: %s" % (
            name, per["irregular_interior_vertices"], abs(per["gauss_bonnet_index"]),
            report.get("road_reason", "")))
    if expect.get("route_1b") and "periodic route 1b" not in report.get("road_reason", ""):
        fails.append("%s: not by route 1b (the face's own layout, vertices slid): %s" % (
            name, report.get("road_reason", "")))
    r = subprocess.run([SQ, "mesh", step, "--periodic", "auto", "--order", "6", "-o", xml, "-q"],
                       capture_output=True, text=True)
    comp = dict(re.findall(r'NAME="(periodic_0_\w+)"> E\[([^\]]*)\]', open(xml).read())
                if r.returncode == 0 else [])

    def count(ranges):
        return sum(int(b) - int(a) + 1 if b else 1
                   for a, b in re.findall(r"(\d+)(?:-(\d+))?", ranges))

    if set(comp) != {"periodic_0_master", "periodic_0_image"} or \
            count(comp["periodic_0_master"]) != count(comp["periodic_0_image"]):
        fails.append("%s: Nektar++ periodic composites %s" % (name, comp))
    print("%s: %d pairs, %d quads, road %s, %d irregular (Gauss-Bonnet: %d), min sJ %.3f" % (
        name, len(got), mesh["quads"], report["road"], per["irregular_interior_vertices"],
        abs(per["gauss_bonnet_index"]), mesh["min_scaled_jacobian"]))


def translation(dx, dy):
    return lambda a: (a[0], a[1], a[3], a[4]) == (1, 0, 0, 1) and \
        abs(a[2] - dx) < 1e-9 and abs(a[5] - dy) < 1e-9


def rotation(deg):
    c, s = math.cos(math.radians(deg)), math.sin(math.radians(deg))
    # the centre, the origin, within the STEP file's 1e-13 accuracy
    return lambda a: max(abs(a[0] - c), abs(a[1] + s), abs(a[3] - s), abs(a[4] - c),
                         abs(a[2]), abs(a[5])) < 1e-9


def refusal(tmp):
    out = os.path.join(tmp, "refused.msh")
    r = subprocess.run([SQ, "mesh", CASCADE, "--periodic", "0:1", "-o", out, "-q"],
                       capture_output=True, text=True)
    lines = r.stderr.strip().splitlines()
    if r.returncode != 9 or len(lines) != 1 or os.path.exists(out):
        fails.append("--periodic 0:1: exit %d, %d lines, output %s" % (
            r.returncode, len(lines), os.path.exists(out)))


def main():
    with tempfile.TemporaryDirectory() as tmp:
        check("cascade", CASCADE, {"pairs": {(0, 8), (1, 7), (2, 6), (3, 5)}, "kind": "translation",
                                   "transform": translation(0, 0.8), "chi": -1, "index": -4,
                                   "layout": 0}, tmp)
        sector = os.path.join(tmp, "sector.step")
        subprocess.run([sys.executable, GEN, "sector", sector], check=True, capture_output=True)
        check("sector", sector, {"pairs": {(0, 2)}, "kind": "rotation", "transform": rotation(45),
                                 "chi": 0, "index": 0, "layout": 1}, tmp)
        channel = os.path.join(tmp, "channel.step")
        subprocess.run([sys.executable, GEN, "channel", channel], check=True, capture_output=True)
        check("channel", channel, {"pairs": {(0, 2)}, "kind": "translation",
                                   "transform": translation(0, 1), "chi": -1, "index": -4,
                                   "layout": 1}, tmp)
        # route 1b: the layout of the identified domain fails (the channel
        # with its hole off the centre line) or is not made (a rotation);
        # the face's own layout, one chord total per curve, the image's
        # vertices slid: exactly Gauss-Bonnet's 4 irregular vertices (a
        # glued pair of boundary nodes has 2 + 2 quads: regular)
        for face, kind, transform in (("channel_offset", "translation", translation(0, 1)),
                                      ("sector_hole", "rotation", rotation(90))):
            step = os.path.join(tmp, face + ".step")
            subprocess.run([sys.executable, GEN, face, step], check=True, capture_output=True)
            check(face, step, {"pairs": {(0, 2)}, "kind": kind, "transform": transform,
                               "chi": -1, "index": -4, "layout": 1, "route_1b": 1}, tmp)
        square = os.path.join(os.environ.get("SQ_EXAMPLES", "examples"), "square.step")
        check("square", square, {"pairs": {(0, 2), (1, 3)}, "kind": "translation",
                                 "transform": lambda a: translation(0, 1)(a) or
                                 translation(-1, 0)(a), "chi": 0, "index": 0, "layout": 1}, tmp)
        refusal(tmp)
        real = os.path.join(os.environ.get("SEMQUAD_REAL_GEOMETRIES", ""), "real_t106_cascade.step")
        if os.environ.get("SEMQUAD_REAL_GEOMETRIES") and os.path.exists(real):
            # route 1b's layout is valid (the outlet kinks bent); its patches
            # fold and are untangled (docs/domains.md): the layout road with
            # exactly Gauss-Bonnet's 4, not the split road
            check("real_t106", real, {"pairs": {(0, 2), (7, 5), (8, 4), (9, 3)},
                                      "kind": "translation", "transform": translation(0, -0.798),
                                      "chi": -1, "index": -4, "layout": 1, "route_1b": 1}, tmp)
        else:
            print("real_t106_cascade.step: not found (SEMQUAD_REAL_GEOMETRIES); skipped")
    for f in fails:
        print("FAIL", f)
    sys.exit(1 if fails else 0)


if __name__ == "__main__":
    main()
