"""t628: sizes inside the blocks (docs/sizes.md, issue 24): the relaxation
keeps the grading of the user's sizes, the report's "sizes" key, and a
refinement inside a patch raises the chords through it.

1. The Schaefer-Turek 2D-2 channel ([0, 2.2] x [0, 0.41] minus a circle of
   diameter 0.1 at (0.2, 0.2), written by step_face.py), --size 0.04 and
   --grow 4:0.005:1.2 on the cylinder (edge 4): h = 0.005 + 0.2 d.
   - Valid and good: no inverted quad, the Bezier-bounded smallest scaled
     Jacobian and the worst eta at least 0.3 each (the floor the issue
     asks of this domain; measured 0.50 and 0.79).
   - The grading survives the relaxation: every quad on the cylinder is at
     most g h0 high (g = 1.2 the growth ratio: one gradation step above
     its target; measured 1.16 h0, the transfinite grid 1.19 h0; Winslow's
     energy without targets made them 2.4 h0).
   - The report's sizes: on the cylinder h = h0 up to the field's sampling
     of the circle (a 256-segment polyline: h off by at most
     0.2 R (1 - cos(pi / 256))).  Chord quantization: each patch side along
     the edge gets round(its integral of 1/h) segments, raised only by
     opposite sides, so over the k patch sides the edge's integral N and
     its segments n satisfy N <= n + k / 2: its mean achieved size L / n
     is at most a factor 1 + k / (2 n) above the mean target L / N (for
     one side, n + 1/2 over n; n / (n - 1/2) the other way).  The
     cylinder's counts are not raised (its patches' opposite sides lie
     where h is larger), so there also N >= n - k / 2.  The integral is the mesh's (trapezoid rule on the
     sides' nodes), the chords' the CAD curve's: they differ by far less
     than the half cell of slack.
2. A refinement inside the half disc, away from its sides (--size 0.1
   --refine 0,0.5,0.1,0.03): the sides' integrals of 1/h are those of the
   uniform size, so before this only the relaxation could move nodes; now
   the chords through the region count the integral across the patch's
   interior: more quads than without the refinement, and the quad at the
   refinement's centre no longer as coarse as the far size (its longest
   side at most 2 h: measured 1.6 h; 3.3 h with the sides' counts alone).
3. The split road honours the sizes too (--road split on the channel of
   1.): its triangles have longest edges at most 3 h(centroid)
   (SQ_SPLIT_TRI_SIZE), so one on the wall reaches at most L = 3 h(c)
   from it, its centroid L / 3, and h(c) <= h0 + a L / 3 = h0 + a h(c)
   gives h(c) <= h0 / (1 - a); its quads at the wall reach halfway up:
   at most 1.5 h0 / (1 - a) = 1.875 h0 high (measured 1.74 h0; 5.4 h0 when
   the split road ignored the sizes).  Every quad valid.
Usage: t628-sizes-blocks.py SEMQUAD EXAMPLES"""
import json
import math
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from step_face import step_face  # noqa: E402

try:
    import gmsh  # noqa: F401 (msh_quad_stats reads through it)
except ImportError:
    sys.exit(77)
import msh_quad_stats  # noqa: E402 (the tests' own reader, through Gmsh's)

SEMQUAD, EXAMPLES = sys.argv[1:3]
fails = []


def run(*args):
    return subprocess.run([SEMQUAD, *args], capture_output=True, text=True, timeout=600)


def quads(path):
    """Corner points of every quad of a MSH file."""
    corners, _, pos = msh_quad_stats.read_elements(path)
    return [[pos[t] for t in c] for c in corners.tolist()]


def mesh(d, name, step, *args):
    msh, rep = os.path.join(d, name + ".msh"), os.path.join(d, name + ".json")
    r = run("mesh", step, "-q", "-o", msh, "--report", rep, *args)
    if r.returncode:
        fails.append("%s: exit %d: %s" % (name, r.returncode, r.stderr.strip()))
        return None, None
    return msh, json.load(open(rep))


def wall_height(msh, xc, yc, R):
    """The largest distance from the circle of a quad with a side on it."""
    high = 0.0
    for c in quads(msh):
        r = [math.hypot(x - xc, y - yc) - R for x, y in c]
        if sum(abs(v) < 1e-9 for v in r) == 2:
            high = max(high, max(r))
    return high


def cylinder(d):
    step = os.path.join(d, "dfg.step")
    xc, yc, R, h0, g = 0.2, 0.2, 0.05, 0.005, 1.2
    step_face(step, [[(0, 0), (2.2, 0), (2.2, 0.41), (0, 0.41)], ("circle", xc, yc, R)], unit="m")
    grow = ("--size", "0.04", "--grow", "4:%g:%g" % (h0, g))
    msh, rep = mesh(d, "dfg", step, *grow)
    if not msh:
        return
    m = rep["mesh"]
    if m["inverted"] or not m["min_scaled_jacobian"] >= 0.3 or not m["quality"]["min"] >= 0.3:
        fails.append("cylinder: inverted %d, scaled Jacobian %.3g, worst eta %.3g (floor 0.3)"
                     % (m["inverted"], m["min_scaled_jacobian"], m["quality"]["min"]))
    high = wall_height(msh, xc, yc, R)
    print("cylinder: wall quads at most %.3f h0 high" % (high / h0))
    if not 0.0 < high <= g * h0:
        fails.append("cylinder: a wall quad %.4g high, above g h0 = %.4g" % (high, g * h0))
    split, srep = mesh(d, "split", step, "--road", "split", *grow)
    if split:
        high, bound = wall_height(split, xc, yc, R), 1.5 * h0 / (2.0 - g)
        print("split road: wall quads at most %.3f h0 high" % (high / h0))
        if not 0.0 < high <= bound or srep["mesh"]["inverted"]:
            fails.append("split road: a wall quad %.4g high (bound %.4g), %d inverted"
                         % (high, bound, srep["mesh"]["inverted"]))
    edges = {e["edge"]: e for e in rep["sizes"]["edges"]}
    wall = edges[4]
    dev = (g - 1.0) * R * (1.0 - math.cos(math.pi / 256)) * (1.0 + 1e-9)
    if abs(wall["target_min"] - h0) > dev or abs(wall["target_max"] - h0) > dev:
        fails.append("cylinder: target sizes [%.9g, %.9g], expected %g" %
                     (wall["target_min"], wall["target_max"], h0))
    for e in edges.values():
        n, k, N = e["segments"], e["patch_sides"], e["cells"]
        low = n - k / 2.0 if e["edge"] == 4 else -math.inf
        print("edge %d: %d segments, %d patch sides, integral of 1/h %.3f, per side %.3f..%.3f"
              % (e["edge"], n, k, N, e["ratio_min"], e["ratio_max"]))
        if not low <= N <= n + k / 2.0:
            fails.append("edge %d: integral of 1/h %.4f outside [%g, %g]" % (e["edge"], N, low, n + k / 2.0))


def inside(d):
    hd = os.path.join(EXAMPLES, "half_disc.step")
    _, plain = mesh(d, "plain", hd, "--size", "0.1")
    msh, rep = mesh(d, "inside", hd, "--size", "0.1", "--refine", "0,0.5,0.1,0.03")
    if not msh or not plain:
        return
    if not rep["mesh"]["quads"] > plain["mesh"]["quads"]:
        fails.append("inside: %d quads, no more than the %d without the refinement"
                     % (rep["mesh"]["quads"], plain["mesh"]["quads"]))
    centre, h = (0.0, 0.5), 0.03
    side = max((max(math.dist(c[k], c[(k + 1) % 4]) for k in range(4)) for c in quads(msh)
                if contains(c, centre)), default=math.inf)
    print("inside: the quads at the centre have their longest side %.3f h" % (side / h))
    if side > 2 * h:
        fails.append("inside: a quad at the centre is %.4g long, above 2 h" % side)


def contains(c, p):
    """Does the counter-clockwise quad with corners c hold p (edges included)."""
    return all((c[(k + 1) % 4][0] - c[k][0]) * (p[1] - c[k][1]) -
               (c[(k + 1) % 4][1] - c[k][1]) * (p[0] - c[k][0]) >= 0 for k in range(4))


def main():
    with tempfile.TemporaryDirectory() as d:
        cylinder(d)
        inside(d)
    for f in fails:
        print("FAIL", f)
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
