#!/usr/bin/python3
"""A free face beside a solid (issue 23: `info` lists the faces Gmsh reads).

A BREP written by Gmsh holds a unit cube (a solid, 6 faces) and, outside it, a
free 2 x 1 rectangle at z = 2 (no shell, no solid), as in NIST CTC 02 (a solid
and a free annulus).  `semquad info` must list 7 faces, as Gmsh's importer does
when it reads every dimension (`gmsh.merge`, `importShapes(highestDimOnly=False)`;
the API's default `highestDimOnly=True` keeps only the solid's 6), and the free
face must mesh.
Area: OpenCASCADE's Gauss quadrature of a plane rectangle is exact up to
round-off (~1e-15 relative); 1e-9 leaves room for the plane's own tolerance
and is the bound t620 uses for straight-sided faces.
usage: t335-free-face.py SEMQUAD"""
import json
import os
import subprocess
import sys
import tempfile

sq = sys.argv[1]
try:
    import gmsh
except ImportError:
    sys.exit(77)

tmp = tempfile.mkdtemp(prefix="t335-")
path = os.path.join(tmp, "cube_and_face.brep")
gmsh.initialize()
gmsh.option.setNumber("General.Terminal", 0)
gmsh.model.occ.addBox(0, 0, 0, 1, 1, 1)
gmsh.model.occ.addRectangle(0, 0, 2, 2, 1)
gmsh.model.occ.synchronize()
gmsh.write(path)
counts = {}
for how in ("merge", "all dimensions"):
    gmsh.clear()
    if how == "merge":
        gmsh.merge(path)
    else:
        gmsh.model.occ.importShapes(path, highestDimOnly=False)
        gmsh.model.occ.synchronize()
    counts[how] = len(gmsh.model.getEntities(2))
gmsh.finalize()

fails = []
p = subprocess.run([sq, "info", path, "--json", "-q"], capture_output=True, timeout=120)
if p.returncode != 0:
    sys.exit("FAIL info exit %d: %s" % (p.returncode, p.stderr.decode()))
faces = json.loads(p.stdout)["faces"]
for how, n in counts.items():
    if len(faces) != n or n != 7:
        fails.append("info lists %d faces, Gmsh (%s) %d, expected 7" % (len(faces), how, n))
free = [f for f in faces if abs(f.get("area", 0) - 2.0) <= 1e-9 * 2.0]
if len(free) != 1 or free[0]["status"] != "ok":
    fails.append("the free 2 x 1 face is not listed once as ok: %s" % free)
else:
    out = os.path.join(tmp, "free.msh")
    m = subprocess.run([sq, "mesh", path, "--face", str(free[0]["index"]), "-q", "-o", out],
                       capture_output=True, timeout=300)
    if m.returncode != 0 or not os.path.getsize(out):
        fails.append("mesh --face %d: exit %d %s" % (free[0]["index"], m.returncode,
                                                    m.stderr.decode().strip()))
for f in fails:
    print("FAIL", f)
sys.exit(1 if fails else 0)
