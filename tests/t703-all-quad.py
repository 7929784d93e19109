#!/usr/bin/python3
"""The all-quad last resort (issue 14, "Layout repair until valid";
src/layout/layout_allquad.c): on stress-corpus faces whose layout the repairs
leave invalid, every patch that is not a quad is split (a two-corner patch cut
across, a triangle or polygon into n quads around a centre), and `semquad mesh`
keeps the layout road's mesh when it is above the quality floor with fewer
interior irregular vertices than the split road's.

The faces are written by bench/stress_corpus.py, seed 1 (face i depends on the
seed and i only).  FACES names each with the layout's defects before the last
resort, the splits it makes and the interior irregular vertices of its mesh
(measured 2026-11-26); the split road gives the face more, or as many in worse
quads (0121: 2 irregular either way, worst scaled Jacobian 0.748 against 0.333).

Checks, on each face (integers and signs: no tolerance, except the area):
- default road: exit 0, the report's road "layout", its road_reason naming the
  all-quad last resort, the layout's all_quad_splits as listed, no inverted
  quad, worst scaled Jacobian at or above the default floor 0.01 (the report's
  Bezier bound, the one the command compares);
- interior irregular vertices as listed, at least gauss_bonnet_min, and fewer
  than `--road split` gives the same face, or as many with a worst scaled
  Jacobian no worse (the rule the command keeps a road by);
- read back by Gmsh's own reader (msh_quad_stats.py): the report's quads, none
  inverted, no triangle, V - E + F of the corner graph equal to the face's chi
  (the T-junctions the splits leave are conforming vertices of the mesh), the
  interior irregular vertices the report's;
- area against `semquad info`'s (OpenCASCADE's; the faces are straight-sided,
  where Gauss quadrature of det J is exact): 1e-9 relative, round-off of sums
  of O(1000) terms of the face's size.
usage: t703-all-quad.py SEMQUAD STRESS_CORPUS_PY"""
import json
import os
import re
import subprocess
import sys
import tempfile

sq, gen = sys.argv[1:3]
try:
    import gmsh  # noqa: F401 (msh_quad_stats reads through it)
except ImportError:
    sys.exit(77)
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import msh_quad_stats  # noqa: E402 (the tests' own reader, through Gmsh's)
from stress_gen import load_stress_corpus  # noqa: E402 (the tests' own helper)

stress_corpus = load_stress_corpus(gen)

SEED = 1
MIN_QUALITY = 0.01  # the command's default floor, include/semquad.h SQ_MIN_QUALITY
# face id: (what the repairs leave, all-quad splits, interior irregular vertices)
FACES = {
    16: ("6 patches with 3 corners, 2 singular points and 3 face vertices with wrong "
         "corner counts (polygon)", 3, 8),
    121: ("1 patch with 2 corners: a sliver's lens between its acute ends, cut across, "
          "its two triangles split", 3, 2),
}
# .ci/run's sanitized build runs several times slower
FACE_TIMEOUT = 120 * (4 if os.environ.get("ASAN_OPTIONS") else 1)


def run(path, rep, msh, extra=()):
    return subprocess.run([sq, "mesh", path, "-q", "-o", msh, "--report", rep] + list(extra),
                          capture_output=True, text=True, timeout=FACE_TIMEOUT)


def check(path, fid):
    _, splits, irregular = FACES[fid]
    msh, rep = path[:-5] + ".msh", path[:-5] + ".json"
    p = run(path, rep, msh)
    if p.returncode != 0:
        return "exit %d: %s" % (p.returncode, p.stderr.strip().splitlines()[-1:])
    d = json.load(open(rep))
    m, lay = d["mesh"], d.get("layout", {})
    if d["road"] != "layout" or "all-quad last resort" not in d.get("road_reason", ""):
        return "road %s (%s), expected the layout road's all-quad last resort" % (
            d["road"], d.get("road_reason"))
    if lay.get("all_quad_splits") != splits:
        return "%r all-quad splits, expected %d" % (lay.get("all_quad_splits"), splits)
    if m["inverted"] != 0 or not m["min_scaled_jacobian"] >= MIN_QUALITY:
        return "%d inverted, min scaled Jacobian %g" % (m["inverted"], m["min_scaled_jacobian"])
    irr = m["irregular_interior_vertices"]
    if irr != irregular or irr < lay["gauss_bonnet_min"]:
        return "%d interior irregular vertices, expected %d (Gauss-Bonnet minimum %d)" % (
            irr, irregular, lay["gauss_bonnet_min"])
    why = msh_quad_stats.against_report(msh, d)
    if why:
        return why
    out = subprocess.run([sq, "info", path], capture_output=True, text=True, check=True).stdout
    area = float(re.search(r"area ([-+0-9.e]+)", out).group(1))
    if abs(m["area"] - area) > 1e-9 * abs(area):
        return "area %.12g, OpenCASCADE %.12g" % (m["area"], area)
    srep = path[:-5] + "_split.json"
    s = run(path, srep, path[:-5] + "_split.msh", ["--road", "split"])
    if s.returncode != 0:
        return "--road split: exit %d" % s.returncode
    sm = json.load(open(srep))["mesh"]
    sirr = sm["irregular_interior_vertices"]
    if not (irr < sirr or (irr == sirr and m["min_scaled_jacobian"] >= sm["min_scaled_jacobian"])):
        return "%d interior irregular vertices, worst scaled Jacobian %.3g; the split road's %d, " \
            "%.3g" % (irr, m["min_scaled_jacobian"], sirr, sm["min_scaled_jacobian"])
    return None


def main():
    fails = 0
    with tempfile.TemporaryDirectory() as tmp:
        for e in stress_corpus.generate(tmp, SEED, sorted(FACES)):
            try:
                why = check(os.path.join(tmp, e["file"]), e["id"])
            except subprocess.TimeoutExpired:
                why = "no answer after %d s" % FACE_TIMEOUT
            if why:
                print("%s (%s): %s" % (e["file"], FACES[e["id"]][0], why))
                fails += 1
    if fails:
        print("%d of %d faces failed" % (fails, len(FACES)))
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
