#!/usr/bin/python3
"""Cusps blunted within the healing tolerance (issues 14 and 23).

The face: the rectangle [-1, 1] x [0, 1] cut by the unit disc centred at
(0, 1), built by Gmsh's OpenCASCADE kernel: two faces, each with two cusps
(the circle tangent to the rectangle's bottom side at the origin and to its
sides at (+-1, 1)), interior angle 0: no quad mesh of the exact face has
positive Jacobians.  The file's own tolerance (1e-7) is below 1e-5 of the
face's size, too small a segment to mesh (cad.h CAD_CUSP_MIN_SEGMENT); with
the stated uncertainty 1e-3 (--heal-tolerance) each cusp is cut where the
circle and the line part by 1e-3 and the cut joined by a 1e-3 segment:

- `mesh --heal-tolerance 1e-3`: exit 0, all scaled Jacobians > 0, two
  "cusp" fixes reported (JSON and the stderr line), segment 1e-3 to 1e-9
  (math_BracketedRoot's tolerance 1e-9 of the bracket on the parameter);
- the cut: where a line and a circle of radius R part by t, sqrt(2 R t)
  (= 0.0447) to O(t) (the circle's distance to its tangent, s^2/2R, is that
  to relative O(s/R) = 5 %, the bound used);
- the area removed: positive and at most the brief's bound, the segment
  (tol) times the cut, per cusp; close to the parabola's tol x cut / 3 (the
  sliver between a line and its osculating circle, to the same 5 %);
- `--no-heal` and the file's own tolerance: exit 6, one line naming the cusp
  and the option (--no-heal, --heal-tolerance), no output file.
usage: t336-cad-cusp.py SEMQUAD"""
import json
import math
import os
import subprocess
import sys
import tempfile

sq = sys.argv[1]
try:
    import gmsh
except ImportError:
    sys.exit(77)
fails = []
tmpdir = tempfile.TemporaryDirectory()  # removed at exit
tmp = tmpdir.name
step = os.path.join(tmp, "cusp.step")
gmsh.initialize()
gmsh.option.setNumber("General.Terminal", 0)
occ = gmsh.model.occ
occ.cut([(2, occ.addRectangle(-1, 0, 0, 2, 1))], [(2, occ.addDisk(0, 1, 0, 1, 1))])
occ.synchronize()
gmsh.write(step)
gmsh.finalize()

TOL, R = 1e-3, 1.0
ORIG = 1 - math.pi / 4  # each face: the half rectangle minus a quarter disc


def run(*args):
    return subprocess.run([sq, *args], capture_output=True, text=True, timeout=120)


def info(*args):
    r = run("info", step, "--json", "-q", *args)
    return json.loads(r.stdout)["faces"]


for f in info():
    if abs(f["area"] - ORIG) > 1e-12:  # Green's theorem on lines and arcs
        fails.append(f"face {f['index']}: area {f['area']}, not {ORIG}")
healed = info("--heal-tolerance", str(TOL))
for f in healed:
    fixes = f.get("healing", {}).get("fixes", [])
    cusps = [x for x in fixes if x["kind"] == "cusp"]
    if f["status"] != "healed" or len(cusps) != 2:
        fails.append(f"face {f['index']}: {f['status']}, {len(cusps)} cusps blunted: {fixes}")
        continue
    cut_est = math.sqrt(2 * R * TOL)
    bound = removed_est = 0.0
    for c in cusps:
        if abs(c["size"] - TOL) > 1e-9:
            fails.append(f"face {f['index']}: segment {c['size']}, not {TOL}")
        for cut in c["cut"]:
            if abs(cut - cut_est) > 0.05 * cut_est:
                fails.append(f"face {f['index']}: cut {cut}, not {cut_est} to 5 %")
        bound += TOL * max(c["cut"])
        removed_est += TOL * sum(c["cut"]) / 6
    removed = ORIG - f["area"]
    if not 0 < removed <= bound:
        fails.append(f"face {f['index']}: area removed {removed}, not in (0, {bound}]")
    if abs(removed - removed_est) > 0.05 * removed_est:
        fails.append(f"face {f['index']}: area removed {removed}, not {removed_est} to 5 %")

for face in ("0", "1"):
    msh, rep = os.path.join(tmp, f"c{face}.msh"), os.path.join(tmp, f"c{face}.json")
    r = run("mesh", step, "--face", face, "--heal-tolerance", str(TOL), "-o", msh, "--report", rep)
    if r.returncode != 0:
        fails.append(f"face {face}: mesh exit {r.returncode}: {r.stderr}")
        continue
    if "blunted a cusp" not in r.stderr:
        fails.append(f"face {face}: the heal not said on stderr: {r.stderr}")
    m = json.load(open(rep))
    if m["mesh"]["inverted"] != 0 or not m["mesh"]["min_scaled_jacobian"] > 0:
        fails.append(f"face {face}: not valid: {m['mesh']}")
    if [x["kind"] for x in m["healing"]["fixes"]] != ["cusp", "cusp"]:
        fails.append(f"face {face}: report's healing {m['healing']}")

for args, option in ((["--no-heal"], "--no-heal"), ([], "--heal-tolerance")):
    out = os.path.join(tmp, "refused.msh")
    r = run("mesh", step, "-q", "-o", out, *args)
    lines = r.stderr.strip().splitlines()
    if r.returncode != 6 or len(lines) != 1 or "is a cusp" not in r.stderr or option not in r.stderr:
        fails.append(f"{args}: exit {r.returncode}, not 6 with one line naming {option}: {r.stderr}")
    if os.path.exists(out):
        fails.append(f"{args}: output file left behind")

for f in fails:
    print(f)
sys.exit(1 if fails else 0)
