"""t643: a boundary layer that blends in (issue 24, docs/sizes.md "A
boundary layer that blends in"): the Schaefer-Turek 2D-2 channel
([0, 2.2] x [0, 0.41] minus a circle of diameter 0.1 at (0.2, 0.2), written
by step_face.py) meshed with a wake refinement (--refine-box) and a
boundary layer on the cylinder (edge 4): first height h0, ratio r over n
layers, then the gradation g up to the isotropic size.

- Valid and good: no inverted quad, the Bezier-bounded smallest scaled
  Jacobian and the worst eta at least 0.3 each (the issue's floor).
- Continuity: from every node on the cylinder, the grid line leaving it
  (the quads' sides, through interior nodes of valence 4) is followed
  outwards; every such line runs through all the layers (further from the
  wall at every step) and ends on a core node: a cell as large as the
  isotropic size, or an irregular node (the O-grid's corners, where the
  spokes end) beyond the layers' thickness.  The layers are the first
  cells of the blocks, not a strip whose lines stop.
- Heights along every line (docs/sizes.md states the bound): every grid
  line leaving the wall is re-graded along itself by the metric
  (src/mesh/quad_regrade.c), before the relaxation and again after it
  (from the wall to 4 cells past the core), so its first cells are the
  metric's to the midpoint rule's error (16 samples a cell: below 1e-4
  of a cell) and the straight segments' distance to the curved wall
  (h0^2 / 2R relative, 2e-5 here); the normal metric makes the height
  h0 also on a line that leaves the wall obliquely.  Stated band
  [0.97, 1.03] h0, measured 0.999-1.001.  Growth along a line: r inside
  the layers, the gradation g beyond, times the scaling that keeps the
  line's count, spread linearly over its cells past the layers: at most
  1 + |lambda - 1| / K a cell (K the cells past the layers, |lambda - 1|
  below 0.5 on these lines), so at most max(r, g) * 1.1; measured 1.397
  (the wake's lines, where the box refinement's sheets raise the count),
  1.301 without the wake box (was 1.99: the transfinite map's columns).
- The report's "boundary_layers" key (docs/sizes.md, "The report"): the
  asked values back, and the achieved ones within the same band: first
  heights and thickness within 3 % of h0 and T, every layer's growth
  within r (1.03 / 0.97)^{+-1}, all 4 layers inside T, one column per
  quad on the wall (as many as the lines above).
Usage: t643-bl-blend.py SEMQUAD"""
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

SEMQUAD = sys.argv[1]
XC, YC, R = 0.2, 0.2, 0.05
H0, RATIO, LAYERS, G = 0.002, 1.3, 4, 1.3
SIZE = 0.02
FIRST_TOL, RAMP = 0.03, 1.1
fails = []


def wall(p):
    return math.hypot(p[0] - XC, p[1] - YC) - R


def lines(pos, quads):
    """Every grid line leaving the cylinder: its nodes' distances from it."""
    nbr, quads_at = {}, {}
    for qi, q in enumerate(quads):
        for k in range(4):
            a, b = q[k], q[(k + 1) % 4]
            nbr.setdefault(a, set()).add(b)
            nbr.setdefault(b, set()).add(a)
            quads_at.setdefault(a, set()).add(qi)
    on = {v for v in pos if v in nbr and abs(wall(pos[v])) < 1e-9}
    out = []
    for w in sorted(on):
        up = [v for v in nbr[w] if v not in on]
        if len(up) != 1:
            fails.append("wall node %d: %d edges leave the wall" % (w, len(up)))
            continue
        prev, cur, dist = w, up[0], [0.0, wall(pos[up[0]])]
        # the next node: the neighbour of cur sharing no quad with prev
        while len(nbr[cur]) == 4 and len(quads_at[cur]) == 4:
            nxt = [v for v in nbr[cur] if v != prev and not (quads_at[v] & quads_at[prev])]
            if len(nxt) != 1:
                break
            prev, cur = cur, nxt[0]
            dist.append(wall(pos[cur]))
            if dist[-1] - dist[-2] >= SIZE:  # the core reached
                break
        irregular = len(nbr[cur]) != 4 or len(quads_at[cur]) != 4
        out.append((w, dist, irregular))
    return out


def check_report(report, columns):
    """The report's boundary_layers key against the asked layers."""
    thick = H0 * (RATIO ** LAYERS - 1) / (RATIO - 1)
    bls = report.get("boundary_layers", [])
    if len(bls) != 1 or bls[0]["edge"] != 4:
        fails.append("report: boundary_layers %r, expects one entry for edge 4" % bls)
        return
    asked, got = bls[0]["requested"], bls[0]["achieved"]
    print("report: first %.5f..%.5f (median %.5f), ratio %.4f..%.4f, %d layers, thickness "
          "%.5f..%.5f" % (got["first_min"], got["first_max"], got["first_median"],
                          got["ratio_min"], got["ratio_max"], got["layers"],
                          got["thickness_min"], got["thickness_max"]))
    if (abs(asked["first"] - H0) > 1e-12 or abs(asked["ratio"] - RATIO) > 1e-12
            or asked["layers"] != LAYERS or abs(asked["thickness"] - thick) > 1e-12):
        fails.append("report: requested %r, expects %g, %g, %d, %g"
                     % (asked, H0, RATIO, LAYERS, thick))
    lo, hi = 1 - FIRST_TOL, 1 + FIRST_TOL
    if not (lo * H0 <= got["first_min"] <= got["first_median"] <= got["first_max"] <= hi * H0):
        fails.append("report: first heights %r outside [%g, %g] h0" % (got, lo, hi))
    if not (lo * thick <= got["thickness_min"] <= got["thickness_max"] <= hi * thick):
        fails.append("report: thickness outside [%g, %g] T" % (lo, hi))
    if not (RATIO * lo / hi <= got["ratio_min"] <= got["ratio_max"] <= RATIO * hi / lo):
        fails.append("report: layer growth %.4f..%.4f, outside r (%g/%g)^{+-1}"
                     % (got["ratio_min"], got["ratio_max"], hi, lo))
    if got["layers"] != LAYERS or got["columns"] != columns:
        fails.append("report: %d layers (expects %d), %d columns (expects %d)"
                     % (got["layers"], LAYERS, got["columns"], columns))


def main():
    with tempfile.TemporaryDirectory() as d:
        step, msh, rep = (os.path.join(d, n) for n in ("dfg.step", "dfg.msh", "dfg.json"))
        step_face(step, [[(0, 0), (2.2, 0), (2.2, 0.41), (0, 0.41)], ("circle", XC, YC, R)],
                  unit="m")
        r = subprocess.run([SEMQUAD, "mesh", step, "-q", "--order", "2", "--size", str(SIZE),
                            "--refine-box", "0.25,0.14,1.2,0.26,0.01",
                            "--bl", "4", "--bl-first", str(H0), "--bl-ratio", str(RATIO),
                            "--bl-layers", str(LAYERS), "-o", msh, "--report", rep],
                           capture_output=True, text=True, timeout=600)
        if r.returncode:
            print("FAIL mesh: exit %d: %s" % (r.returncode, r.stderr.strip()))
            return 1
        report = json.load(open(rep))
        m = report["mesh"]
        print("%d quads, worst eta %.3f, scaled Jacobian %.3f" %
              (m["quads"], m["quality"]["min"], m["min_scaled_jacobian"]))
        if m["inverted"] or not m["min_scaled_jacobian"] >= 0.3 or not m["quality"]["min"] >= 0.3:
            fails.append("inverted %d, scaled Jacobian %.3g, worst eta %.3g (floor 0.3)"
                         % (m["inverted"], m["min_scaled_jacobian"], m["quality"]["min"]))
        quads, _, pos = msh_quad_stats.read_elements(msh)
    found = lines(pos, quads.tolist())
    first, worst = [], 0.0
    thick = H0 * (RATIO ** LAYERS - 1) / (RATIO - 1)
    for w, dist, irregular in found:
        steps = [b - a for a, b in zip(dist, dist[1:])]
        if min(steps) <= 0.0:
            fails.append("wall node %d: its line turns back to the wall" % w)
            continue
        if len(steps) <= LAYERS or not (steps[-1] >= SIZE / G or irregular and dist[-1] > thick):
            fails.append("wall node %d: its line stops %.4g from the wall, after %d cells, "
                         "before the core" % (w, dist[-1], len(steps)))
        first.append(steps[0] / H0)
        worst = max(worst, max(b / a for a, b in zip(steps, steps[1:])))
    print("%d lines, first cell %.3f..%.3f h0, largest ratio of neighbours %.3f"
          % (len(found), min(first), max(first), worst))
    if not found:
        fails.append("no line leaves the cylinder")
    if first and not (1 - FIRST_TOL <= min(first) and max(first) <= 1 + FIRST_TOL):
        fails.append("first cells %.3f..%.3f h0, outside [%g, %g]"
                     % (min(first), max(first), 1 - FIRST_TOL, 1 + FIRST_TOL))
    if worst > max(RATIO, G) * RAMP:
        fails.append("neighbour cells along a line differ by %.3f, above %.3f"
                     % (worst, max(RATIO, G) * RAMP))
    check_report(report, len(found))
    for f in fails:
        print("FAIL", f)
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
