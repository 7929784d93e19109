#!/usr/bin/python3
"""A planar face whose edge leaves the plane within the file's tolerance (issue 14).

Real parts (sheet metal after healing: AnalysisSitus' sheet_metal_54 faces 7, 13,
19, ...) have edges a little off their face's plane, within the file's tolerance;
semquad projects them onto the plane.  The face here (tests/step_face.py): the
rectangle [0, 1] x [0, 1.5] in z = 0, its top side a cubic B-spline whose two
inner poles are lifted by D = 1e-3 (height z = 3 D t (1 - t), at most 0.75 D: the
reader sets the edge's tolerance to that).  Its projection is the straight side,
so the face's area is 1.5.

- `info`: area 1.5 to 1e-12.  Green's integral of the projected curves in their
  own parameter (10-point Gauss per piece) is exact on lines and on the
  B-spline's quintic integrand: round-off only, ~1e-15.  The projected unit
  tangent against 3D arc length instead (the code before this test) adds the
  tilt's square: z' = 3 D (1 - 2 t), so the top side, 1.5 from the bottom one,
  sweeps 1.5 * int (z')^2 / 2 dt = 2.25 D^2 more of twice the area: 1.125e-6 of
  area (what it gave), 1e6 times the bound.
- `layout`: exit 0, one valid patch (its area, the same Green integral, matches
  the face's to the check's 1e-9 of it; it was "1 area mismatch", exit 6).
- `mesh`: exit 0 on the layout road, no interior irregular vertex (a
  rectangle), every scaled Jacobian > 0.
usage: t339-off-plane-edge.py SEMQUAD"""
import json
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from step_face import Step, info_face  # noqa: E402

sq = sys.argv[1]
D = 1e-3
fails = []
tmpdir = tempfile.TemporaryDirectory()  # removed at exit
tmp = tmpdir.name
step = os.path.join(tmp, "off_plane.step")
s = Step()
corners = [(0, 0), (1, 0), (1, 1.5), (0, 1.5)]
v = [s.vertex(p) for p in corners]
top = s.bspline(v[2], v[3], [(1, 1.5, 0), (2 / 3, 1.5, D), (1 / 3, 1.5, D), (0, 1.5, 0)], [0, 1],
                [4, 4])
s.write(step, [s.loop([s.line(v[0], v[1], corners[0], corners[1]),
                       s.line(v[1], v[2], corners[1], corners[2]), top,
                       s.line(v[3], v[0], corners[3], corners[0])])])


def run(*args):
    return subprocess.run([sq, *args], capture_output=True, text=True, timeout=120)


f, why = info_face(sq, step)
if f is None:
    fails.append(why)
elif abs(f["area"] - 1.5) > 1e-12:
    fails.append(f"info: area {f['area']!r}, not 1.5 (the projected rectangle)")

rep = os.path.join(tmp, "layout.json")
r = run("layout", step, "-q", "--report", rep)
if r.returncode != 0:
    fails.append(f"layout: exit {r.returncode}: {r.stderr.strip()}")
else:
    with open(rep) as f:
        lay = json.load(f)["layout"]
    if not lay["valid"] or lay["patches"] != 1:
        fails.append(f"layout: valid {lay['valid']}, {lay['patches']} patches, not 1 valid")

rep, msh = os.path.join(tmp, "mesh.json"), os.path.join(tmp, "mesh.msh")
r = run("mesh", step, "-q", "--report", rep, "-o", msh)
if r.returncode != 0:
    fails.append(f"mesh: exit {r.returncode}: {r.stderr.strip()}")
else:
    with open(rep) as f:
        d = json.load(f)
    q = d["mesh"]
    if d["road"] != "layout" or q["irregular_interior_vertices"] != 0 or \
            not q["min_scaled_jacobian"] > 0:
        fails.append(f"mesh: road {d['road']}, {q['irregular_interior_vertices']} interior "
                     f"irregular vertices, min scaled Jacobian {q['min_scaled_jacobian']}")

for line in fails:
    print("FAIL", line)
sys.exit(1 if fails else 0)
