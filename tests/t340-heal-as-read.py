#!/usr/bin/python3
"""A face that healing would spoil is kept as read (issue 14).

pythonocc-demos' Ventilator.stp face 13: its gaps are within the file's
tolerance, but closing them grows the edges' tolerances past a 0.0144 mm edge,
which is then "small" and left by the fix; the face was refused ("healing left
a small edge", exit 4) although it meshes as read.  The face here
(tests/step_face.py) has the same three ingredients: the rectangle
[0, 1] x [0, 1.5], its bottom side in three lines with a short middle one of
S = 5e-4, its top side a cubic B-spline whose inner poles leave the plane by
1e-3 (the reader gives that edge a tolerance of 7.5e-4, the face's healing
tolerance) and whose first pole misses its vertex by a 1e-6 gap (found and
closed by healing; closing it grows the edges' tolerances to 7.5e-4 > S).

- `info --json`: status ok (the face is untouched), one record kind "as read", defect "small
  edge", edge 1 of wire 0, size S to 1e-15 (0.5 + S - 0.5 in doubles: a few
  ulps of 0.5, ~1e-16);
- `mesh`: exit 0, every scaled Jacobian > 0, the stderr line says the face was
  kept as read and names the edge;
- `--no-heal`: the same mesh (the face as read, bytes equal).
usage: t340-heal-as-read.py SEMQUAD"""
import json
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from step_face import Step, as_read_outer, info_face  # noqa: E402

sq = sys.argv[1]
S, LIFT, GAP = 5e-4, 1e-3, 1e-6
fails = []
tmpdir = tempfile.TemporaryDirectory()  # removed at exit
tmp = tmpdir.name
step = os.path.join(tmp, "as_read.step")
s = Step()
s.write(step, [as_read_outer(s, S, LIFT, GAP)])


def run(*args):
    return subprocess.run([sq, *args], capture_output=True, text=True, timeout=120)


f, why = info_face(sq, step)
if f is None:
    fails.append(why)
else:
    fixes = f.get("healing", {}).get("fixes", [])
    if f["status"] != "ok" or len(fixes) != 1:
        fails.append(f"info: status {f['status']} ({f.get('reason', '')}), fixes {fixes}")
    else:
        x = fixes[0]
        if (x["kind"], x.get("defect"), x["wire"], x["edges"]) != ("as read", "small edge", 0, [1]) \
                or abs(x["size"] - S) > 1e-15:
            fails.append(f"info: record {x}, not 'as read' of the small edge 1 of wire 0, {S}")

meshes = {}
for opt in ([], ["--no-heal"]):
    msh, rep = os.path.join(tmp, "m%d.msh" % len(opt)), os.path.join(tmp, "m%d.json" % len(opt))
    r = run("mesh", step, "-o", msh, "--report", rep, *opt)
    if r.returncode != 0:
        fails.append(f"mesh {opt}: exit {r.returncode}: {r.stderr.strip()}")
        continue
    with open(rep) as fh:
        q = json.load(fh)["mesh"]
    if not q["min_scaled_jacobian"] > 0:
        fails.append(f"mesh {opt}: min scaled Jacobian {q['min_scaled_jacobian']}")
    if not opt and "kept the face as read: healing would leave a small edge 1 of wire 0" \
            not in r.stderr:
        fails.append(f"mesh: stderr does not say the face was kept as read: {r.stderr.strip()}")
    with open(msh, "rb") as fh:
        meshes[len(opt)] = fh.read()
if len(meshes) == 2 and meshes[0] != meshes[1]:
    fails.append("mesh: the face kept as read meshes otherwise than with --no-heal")

for line in fails:
    print("FAIL", line)
sys.exit(1 if fails else 0)
