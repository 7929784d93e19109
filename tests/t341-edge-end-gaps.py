#!/usr/bin/python3
"""Edges whose curves miss their vertices within the file's tolerance (issue 14).

pythonocc-demos' Ventilator.stp face 13: the lines of its hexagonal hole end
up to 0.014 mm from the corners they share (tolerance 0.028 mm; healing is
declined there, t340), and the edge jumped from the curve's end to the
corner: the triangulation halved the chord towards the corner 16 times, never
came close, and the face went to the split road (120 irregular vertices
instead of 6).  An edge now runs continuously into its corners
(cad_face_edge_eval blends the end gaps in along it).

The face here: t340's rectangle (a short bottom edge and a lifted B-spline
top, so that healing is declined and the face is taken as read) with a
hexagonal hole whose six lines are shifted sideways by GAP from their
vertices.  The edges through the corners are then the hexagon of the
vertices, exactly: straight sides, whose area any order represents to
round-off.

- `mesh`: exit 0, the layout road, interior irregular vertices = the
  report's gauss_bonnet_min, no inverted quad, every scaled Jacobian > 0;
- the mesh's area = 1.5 - (3 sqrt(3) / 2) R^2 to 1e-12 relative: a sum of
  ~100 quads' areas at round-off each (~1e-16); a mesh on the shifted curves
  instead would be off by 6 R GAP = 1.8e-3 of it.
usage: t341-edge-end-gaps.py SEMQUAD"""
import json
import math
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from step_face import Step, as_read_outer  # noqa: E402

sq = sys.argv[1]
S, LIFT, GAP, R, C = 5e-4, 1e-3, 1e-3, 0.3, (0.5, 0.75)
fails = []
tmpdir = tempfile.TemporaryDirectory()  # removed at exit
tmp = tmpdir.name
step = os.path.join(tmp, "gaps.step")
s = Step()
outer = as_read_outer(s, S, LIFT, 0.0)
hv = [(C[0] + R * math.cos(math.pi / 3 * k + 0.1), C[1] + R * math.sin(math.pi / 3 * k + 0.1))
      for k in range(6)][::-1]  # clockwise: a hole
hvert = [s.vertex(p) for p in hv]
hole = []
for k in range(6):
    p, q = hv[k], hv[(k + 1) % 6]
    L = math.hypot(q[0] - p[0], q[1] - p[1])
    nx, ny = (q[1] - p[1]) / L * GAP, -(q[0] - p[0]) / L * GAP
    hole.append(s.line(hvert[k], hvert[(k + 1) % 6], (p[0] + nx, p[1] + ny), (q[0] + nx, q[1] + ny)))
s.write(step, [outer, s.loop(hole)])

msh, rep = os.path.join(tmp, "m.msh"), os.path.join(tmp, "m.json")
r = subprocess.run([sq, "mesh", step, "-o", msh, "--report", rep], capture_output=True, text=True,
                   timeout=120)
if r.returncode != 0:
    fails.append(f"mesh: exit {r.returncode}: {r.stderr.strip()}")
else:
    with open(rep) as fh:
        d = json.load(fh)
    q, gb = d["mesh"], d.get("layout", {}).get("gauss_bonnet_min")
    if d["road"] != "layout":
        fails.append(f"mesh: the {d['road']} road ({d.get('road_reason')}), not the layout road")
    if q["irregular_interior_vertices"] != gb:
        fails.append(f"mesh: {q['irregular_interior_vertices']} interior irregular vertices, "
                     f"gauss_bonnet_min {gb}")
    if q["inverted"] != 0 or not q["min_scaled_jacobian"] > 0:
        fails.append(f"mesh: {q['inverted']} inverted, min scaled Jacobian {q['min_scaled_jacobian']}")
    exact = 1.5 - 1.5 * math.sqrt(3) * R * R
    if abs(q["area"] - exact) > 1e-12 * exact:
        fails.append(f"mesh: area {q['area']!r}, the hexagon of the vertices gives {exact!r}")

for line in fails:
    print("FAIL", line)
sys.exit(1 if fails else 0)
