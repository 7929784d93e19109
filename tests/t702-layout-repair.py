#!/usr/bin/python3
"""The layout road's repairs on stress-corpus faces it once gave way on
(issue 14, "Layout repair until valid"): each face must now be meshed by the
layout road itself, `semquad mesh --road layout` (no fallback to the split
road), into a valid all-quad mesh.

The faces are written by bench/stress_corpus.py, seed 1 (face i depends on the
seed and i only, so every clone meshes the same faces).  FACES names each with
the failure it had before and the stage that now mends it (docs/layout.md).

Checks, on each face (signs and integers: no tolerance, except the area):
- exit 0, the report's road "layout", its layout valid, no inverted quad, every
  scaled Jacobian > 0 (the report's min_scaled_jacobian, a Bezier bound);
- interior irregular vertices reported and at least the layout's
  gauss_bonnet_min (|4 chi - sum(2 - n_c)|: no all-quad mesh has fewer);
- read back from the MSH file by Gmsh's own reader (msh_quad_stats.py): the
  report's quads, none inverted, no triangle; V - E + F of the corner graph
  (Euler) equals the face's chi; the interior irregular vertices counted there
  equal the report's;
- area, on straight-sided faces only: the report's (Gauss quadrature of det J,
  exact for the bilinear-and-higher map of straight sides) against `semquad
  info`'s (OpenCASCADE's, exact to round-off): 1e-9 relative, round-off of
  sums of O(100) terms of the face's size.
usage: t702-layout-repair.py SEMQUAD STRESS_CORPUS_PY"""
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
Q = 4
# face id: what the layout road gave before (2026-11-26, docs/benchmarks.md)
# -> what mends it now
FACES = {
    35: "1 patch with 1 corners (137.7 and 155.5 deg corners given 2 quads, their "
        "separatrices along the boundary) -> bends of 2 quads start no separatrix",
    98: "repair line longer than its bound (a T-junction's stem) -> bends of 2 quads",
    219: "23 patches with 1 corners, 14 with 2, 39 with 3 (near-180 deg corners) -> "
         "bends of 2 quads start no separatrix",
    243: "2 patches with 1 corners, 33 with 2, 65 with 3 -> bends of 2 quads",
    291: "5 patches with 1 corners, 9 with 2, 40 with 3 -> bends of 2 quads",
}
# .ci/run's sanitized build runs several times slower
FACE_TIMEOUT = 120 * (4 if os.environ.get("ASAN_OPTIONS") else 1)


def check(path, tmp):
    msh, rep = path[:-5] + ".msh", path[:-5] + ".json"
    try:
        p = subprocess.run([sq, "mesh", path, "--road", "layout", "--order", str(Q), "-q",
                            "-o", msh, "--report", rep], capture_output=True, text=True,
                           timeout=FACE_TIMEOUT)
    except subprocess.TimeoutExpired:
        return "no answer after %d s" % FACE_TIMEOUT
    if p.returncode != 0:
        return "exit %d: %s" % (p.returncode, p.stderr.strip().splitlines()[-1:])
    d = json.load(open(rep))
    m, lay = d["mesh"], d.get("layout", {})
    if d["road"] != "layout" or not lay.get("valid"):
        return "road %s, layout valid %s" % (d["road"], lay.get("valid"))
    if m["inverted"] != 0 or not m["min_scaled_jacobian"] > 0:
        return "%d inverted, min scaled Jacobian %g" % (m["inverted"], m["min_scaled_jacobian"])
    irr = m.get("irregular_interior_vertices")
    if not isinstance(irr, int) or irr < lay["gauss_bonnet_min"]:
        return "interior irregular vertices %r, Gauss-Bonnet minimum %d" % (
            irr, lay["gauss_bonnet_min"])
    why = msh_quad_stats.against_report(msh, d)
    if why:
        return why
    out = subprocess.run([sq, "info", path], capture_output=True, text=True, check=True).stdout
    if not any(k in out for k in ("circle", "bspline", "ellipse", "bezier")):
        area = float(re.search(r"area ([-+0-9.e]+)", out).group(1))
        if abs(m["area"] - area) > 1e-9 * abs(area):
            return "area %.12g, OpenCASCADE %.12g" % (m["area"], area)
    return None


def main():
    fails = 0
    with tempfile.TemporaryDirectory() as tmp:
        for e in stress_corpus.generate(tmp, SEED, sorted(FACES)):
            why = check(os.path.join(tmp, e["file"]), tmp)
            if why:
                print("%s (%s): %s" % (e["file"], FACES[e["id"]], why))
                fails += 1
    if fails:
        print("%d of %d faces failed" % (fails, len(FACES)))
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
