#!/usr/bin/python3
"""Untangling from a folded start (src/mesh/quad_relax.c, sq_quad_untangle;
docs/mesh.md, step 4): an eccentric annulus, a disc of radius 34 less a hole
of radius 6 centred 21 from its centre (mm; the shape of a real part's face
that took the split road).  Its layout is valid (the H/theta field of the
Gauss-Bonnet-minimal pattern: no singular point, four quad patches), but the
transfinite patches fold around the hole, where the patches' sides run
strongly bent and graded, and Laplace moves that keep every quad valid
cannot open them: before the untangler the layout road failed at every size
it tried ("... quads have a non-positive Jacobian") and the face took the
split road with 35 irregular vertices.

Checks (no tolerance: counts and signs):
- exit 0, the report's road "layout", 0 interior irregular vertices (an
  annulus has chi 0: the Gauss-Bonnet minimum), no inverted quad and a
  positive min scaled Jacobian;
- Gmsh's own analysis of the MSH file (Plugin(AnalyseMeshQuality),
  minJ/maxJ per element, Johnen 2013 bounds) finds every element positive:
  its lower bound r_g >= r* - 1e-3 (1 + r*) (t608), so r_g > 0 proves r* > 0
  independently of our Bezier bounds; and as many elements as the report's
  quads.
Exit 77 if gmsh cannot be imported.
usage: t710-untangle.py SEMQUAD STEP_FACE_DIR"""
import json
import os
import subprocess
import sys
import tempfile

try:
    import gmsh
except ImportError:
    sys.exit(77)

sq, helpers = sys.argv[1:3]
sys.dont_write_bytecode = True
sys.path.insert(0, helpers)
from step_face import Step  # noqa: E402


def eccentric_annulus(path):
    s = Step()
    # the outer circle, counter-clockwise (Step.circle writes a hole's)
    v = s.add("VERTEX_POINT('',%s)" % s.pt(34.0, 0.0))
    c = s.add("CIRCLE('',%s,%s)" % (s.axis(0.0, 0.0), s.real(34.0)))
    ec = s.add("EDGE_CURVE('',%s,%s,%s,.T.)" % (v, v, c))
    outer = s.add("EDGE_LOOP('',(%s))" % s.add("ORIENTED_EDGE('',*,*,%s,.T.)" % ec))
    s.write(path, [outer, s.circle(21.0, 0.0, 6.0)])


fails = 0
with tempfile.TemporaryDirectory() as tmp:
    step, msh, rep = (os.path.join(tmp, n) for n in ("ecc.step", "ecc.msh", "ecc.json"))
    eccentric_annulus(step)
    r = subprocess.run([sq, "mesh", step, "-o", msh, "--report", rep], capture_output=True,
                       text=True)
    if r.returncode != 0:
        sys.exit("FAIL: exit %d: %s" % (r.returncode, r.stderr.strip()))
    j = json.load(open(rep))
    m = j["mesh"]
    print("road %s, %d quads, %d interior irregular, min scaled Jacobian %.3f" %
          (j.get("road"), m["quads"], m["irregular_interior_vertices"], m["min_scaled_jacobian"]))
    if j.get("road") != "layout":
        print("FAIL: road %s (%s)" % (j.get("road"), j.get("road_reason")))
        fails += 1
    if m["irregular_interior_vertices"] != 0:
        print("FAIL: %d interior irregular vertices, the annulus needs 0"
              % m["irregular_interior_vertices"])
        fails += 1
    if m["inverted"] != 0 or not m["min_scaled_jacobian"] > 0.0:
        print("FAIL: %d inverted, min scaled Jacobian %g" % (m["inverted"], m["min_scaled_jacobian"]))
        fails += 1
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.open(msh)
    gmsh.plugin.setNumber("AnalyseMeshQuality", "JacobianDeterminant", 1)
    gmsh.plugin.setNumber("AnalyseMeshQuality", "CreateView", 1)
    gmsh.plugin.setNumber("AnalyseMeshQuality", "DimensionOfElements", 2)
    gmsh.plugin.run("AnalyseMeshQuality")
    _, tags, data, _, _ = gmsh.view.getModelData(gmsh.view.getTags()[-1], 0)
    gmsh.finalize()
    worst = min(float(d[0]) for d in data)
    print("gmsh: %d elements, least minJ/maxJ %.3f" % (len(tags), worst))
    if len(tags) != m["quads"] or not worst > 0.0:
        print("FAIL: gmsh finds %d elements, least minJ/maxJ %g" % (len(tags), worst))
        fails += 1
sys.exit(1 if fails else 0)
