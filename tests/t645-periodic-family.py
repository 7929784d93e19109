#!/usr/bin/python3
"""t645: mesh families of periodic faces (`semquad mesh --periodic auto
--levels L --orders Q1,Q2`, docs/convergence-families.md).

Faces built here: the project's own T106-like cascade passage
(tests/cascade_aerofoil.py, periodic lines one pitch apart: a translation;
the split road) and 1/8 of the ring 0.5 <= r <= 1 (tests/domain_faces.py
sector, its radial sides periodic under the rotation by 45 deg: the layout
road).  Each meshed with `--levels 2 --orders 3,5`, then for each of the
four files:

  - Gmsh's reader loads its $Periodic section: the same image curves as
    the family's first mesh, each pair covering every node of the image
    curve, |T(x_master) - x| <= 1e-12 of the face's size.  Why 1e-12: the
    image nodes are set to T(master) (one multiply-add per coordinate,
    then 17 digits written and read back), a few roundings of numbers of
    the face's size, 1e-16 relative each; a refined level whose new nodes
    were only placed on their own curve (at its arc-length midpoints)
    would be off by the curves' mismatch and the midpoints' round-off;
  - level 2 has 4 times level 1's quads, at each order;
  - nested: every vertex of level 1 is a node of level 2 to 1e-12 of the
    size (the family copies the parent's vertices; the links set the
    image vertices to the same T(master) on both levels);
  - the manifest lists the four files.
The same for a periodic domain of several faces: the ring cut into four
faces (tests/domain_faces.py ring4, its radial sides two curves each; the
faces' meshes refined, merged, and linked again on every level; the
manifest's face_area the sum of the faces').
usage: t645-periodic-family.py SEMQUAD DOMAIN_FACES_PY CASCADE_STEP"""
import json
import os
import subprocess
import sys
import tempfile

try:
    import gmsh  # noqa: F401  (msh_quad_stats needs it)
    from scipy.spatial import cKDTree
except ImportError:
    sys.exit(77)

SQ, GEN, CASCADE = sys.argv[1:4]
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import msh_quad_stats  # noqa: E402

fails = []


def family(name, step, tmp):
    out = os.path.join(tmp, name + ".msh")
    r = subprocess.run([SQ, "mesh", step, "--periodic", "auto", "--levels", "2", "--orders", "3,5",
                        "-o", out, "-q"], capture_output=True, text=True)
    if r.returncode != 0:
        fails.append("%s: exit %d: %s" % (name, r.returncode, r.stderr.strip()))
        return
    manifest = json.load(open(os.path.join(tmp, name + "_manifest.json")))
    files = {(e["level"], e["order"]): e for e in manifest["meshes"]}
    if sorted(files) != [(1, 3), (1, 5), (2, 3), (2, 5)]:
        fails.append("%s: the manifest lists %s" % (name, sorted(files)))
        return
    size = manifest["face_area"] ** 0.5  # the face's size
    curves = None
    for key, e in sorted(files.items()):
        links = msh_quad_stats.periodic_pairs(e["file"], size)
        gaps = {c: (l[2], l[3], l[4]) for c, l in links.items()}
        print("%s L%d Q%d: %d quads, image curves %s, largest gap %.2g of the size" % (
            name, key[0], key[1], e["quads"], sorted(links),
            max([g[0] for g in gaps.values()] or [0])))
        curves = curves if curves is not None else sorted(links)
        if not links or sorted(links) != curves:
            fails.append("%s L%d Q%d: image curves %s, expected %s" % (
                name, key[0], key[1], sorted(links), curves))
        for c, (gap, pairs, on_curve) in gaps.items():
            if gap > 1e-12 or pairs != on_curve:
                fails.append("%s L%d Q%d: curve %d gap %.3g, %d pairs for %d nodes" % (
                    name, key[0], key[1], c, gap, pairs, on_curve))
    for q in (3, 5):
        if files[(2, q)]["quads"] != 4 * files[(1, q)]["quads"]:
            fails.append("%s Q%d: %d quads at level 2, %d at level 1" % (
                name, q, files[(2, q)]["quads"], files[(1, q)]["quads"]))
        fine = msh_quad_stats.read_elements(files[(2, q)]["file"])
        coarse = msh_quad_stats.read_elements(files[(1, q)]["file"])
        tree = cKDTree(list(fine[2].values()))
        corners = {int(n) for quad in coarse[0] for n in quad}
        far = max(tree.query(coarse[2][n])[0] for n in corners)
        if far > 1e-12 * size:
            fails.append("%s Q%d: a level-1 vertex is %.3g from every level-2 node" % (name, q, far))


def main():
    with tempfile.TemporaryDirectory() as tmp:
        family("cascade", CASCADE, tmp)
        sector = os.path.join(tmp, "sector.step")
        subprocess.run([sys.executable, GEN, "sector", sector], check=True, capture_output=True)
        family("sector", sector, tmp)
        ring = os.path.join(tmp, "ring4.step")
        subprocess.run([sys.executable, GEN, "ring4", ring], check=True, capture_output=True)
        family("ring4", ring, tmp)
    for f in fails:
        print("FAIL", f)
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
