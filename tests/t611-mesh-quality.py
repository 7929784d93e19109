#!/usr/bin/python3
"""semquad mesh at --size 0.1 on every example: tests/msh_quad_stats.py (an
independent measure through Gmsh's own reader), run on the MSH output,
agrees with the JSON report (quads, interior irregular
vertices, eta mean / min / % above 0.9), and the quality reaches
eta_mean >= 0.9 and tau >= 80 %.

All eleven reach it since the compass search lifts the quads just below
eta = 0.9 (triangle 0.920 / 92 %, square_hole 0.907 / 83 %: the tightest).
usage: t611-mesh-quality.py SEMQUAD EXAMPLES MSH_QUAD_STATS"""
import json
import os
import subprocess
import sys
import tempfile

sq, ex, qs = sys.argv[1:4]
try:
    import gmsh  # noqa: F401 (msh_quad_stats.py reads the files with it)
except ImportError:
    print("python3-gmsh is missing (scripts/bootstrap.sh installs it)")
    sys.exit(77)
# (eta_mean >= 0.9 and tau >= 80 expected?)
cases = {"half_disc": True, "square": True, "two_holes": True, "nautilus": True,
         "naca0012": True, "lshape": True, "quarter_circle": True, "square_hole": True,
         "annulus": True, "triangle": True, "polygon": True}
fails = 0
with tempfile.TemporaryDirectory() as tmp:
    for name, good in cases.items():
        msh, rep = os.path.join(tmp, name + ".msh"), os.path.join(tmp, name + ".json")
        subprocess.run([sq, "mesh", os.path.join(ex, name + ".step"), "--size", "0.1", "-q",
                        "-o", msh, "--report", rep], check=True)
        m = json.load(open(rep))["mesh"]
        s = json.loads(subprocess.run([sys.executable, qs, msh], check=True,
                                      capture_output=True, text=True).stdout)
        # msh_quad_stats recomputes eta from the MSH's %.17g nodes with the same
        # angle formulas: a few U per quad, summed over ~1e2 quads for the
        # mean (1e-12, as t603); tau is a ratio of counts (1e-9 for its
        # rounding; only an eta within a few U of 0.9 could flip a count)
        pairs = [("quads", m["quads"], s["quads"], 0),
                 ("eta mean", m["quality"]["mean"], s["eta_mean"], 1e-12),
                 ("eta min", m["quality"]["min"], s["eta_min"], 1e-12),
                 ("tau", m["quality"]["above_0_9_percent"], s["eta_pct_gt_0.9"], 1e-9),
                 ("interior irregular", m["irregular_interior_vertices"], s["interior_irregular"],
                  0)]
        for what, ours, theirs, tol in pairs:
            if abs(ours - theirs) > tol:
                print(f"{name}: {what}: report {ours}, msh_quad_stats {theirs}")
                fails += 1
        reached = m["quality"]["mean"] >= 0.9 and m["quality"]["above_0_9_percent"] >= 80.0
        if reached != good:
            print(f"{name}: eta mean {m['quality']['mean']:.3f}, tau "
                  f"{m['quality']['above_0_9_percent']:.1f} %: expected "
                  f"{'' if good else 'not '}to reach 0.9 / 80 %")
            fails += 1
        if m["inverted"] != 0 or not m["min_scaled_jacobian"] > 0:
            print(f"{name}: inverted quads {m['inverted']}, min scaled Jacobian "
                  f"{m['min_scaled_jacobian']}")
            fails += 1
sys.exit(1 if fails else 0)
