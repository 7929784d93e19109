#!/usr/bin/python3
"""The scaled Jacobians of semquad's Bézier bounds (src/mesh/jacobian_bezier.c)
against Gmsh's own analysis of the same meshes (issue 21).

Every planar example is meshed with the defaults (order 4); the VTU output
carries our per-quad scaled Jacobian (cell data "scaled_jacobian", %.10g),
the MSH output is read by Debian's python3-gmsh (4.8), whose
Plugin(AnalyseMeshQuality) with JacobianDeterminant and CreateView gives
minJ/maxJ per element (element tag = quad index + 1).  Both are lower bounds
of the same number, r* = min det J / max det J over the element (Johnen,
Remacle & Geuzaine 2013, the method of both):

  ours  r* - g_o <= r_o <= r*, g_o = 2 SQ_JAC_TOL / (1 - SQ_JAC_TOL), SQ_JAC_TOL = 1e-6
        (jacobian_bezier.h; no quad of the examples hits the caps: the
        report's jacobian_capped is checked to be 0);
  Gmsh  r* - g_g <= r_g <= r*: its subdivision stops when the least Bézier
        coefficient is within 1e-3 max(|minJ|, |maxJ|) of the least sampled
        value and likewise for the largest (qualityMeasuresJacobian.cpp,
        _coeffDataJac::boundsOk), so g_g <= 1e-3 (1 + r*) / (1 - 1e-3).

Hence |r_o - r_g| <= max(g_o, g_g) + e, e covering what differs in the input:
Gmsh reads the MSH's equispaced nodes (%.17g), resampled from our GLL nodes
(the same polynomial to 1e-12 of the coordinates, t602's round trip), and
our %.10g print (5e-11 relative): e = 1e-6, far above both and far below
g_g.  Gmsh's minJ/maxJ uses |det J|'s sign convention of the plane's normal;
for a mesh whose normal it finds as -z it reports maxJ/minJ, the same ratio.
Exit 77 if gmsh cannot be imported.
usage: t608-gmsh-jacobian.py SEMQUAD EXAMPLES"""
import glob
import json
import os
import re
import subprocess
import sys
import tempfile

try:
    import gmsh
except ImportError:
    sys.exit(77)

sq, ex = sys.argv[1:3]
TOL_OURS = 2e-6 / (1 - 1e-6)
E_INPUT = 1e-6
fails = 0


def vtu_cells(path, name):
    text = open(path).read()
    m = re.search(r'<DataArray[^>]*Name="%s"[^>]*>(.*?)</DataArray>' % name, text, re.S)
    return [float(v) for v in m.group(1).split()]


def gmsh_ratios(msh):
    gmsh.open(msh)
    gmsh.plugin.setNumber("AnalyseMeshQuality", "JacobianDeterminant", 1)
    gmsh.plugin.setNumber("AnalyseMeshQuality", "CreateView", 1)
    gmsh.plugin.setNumber("AnalyseMeshQuality", "Recompute", 1)
    gmsh.plugin.setNumber("AnalyseMeshQuality", "DimensionOfElements", 2)
    gmsh.plugin.run("AnalyseMeshQuality")
    tag = gmsh.view.getTags()[-1]
    _, tags, data, _, _ = gmsh.view.getModelData(tag, 0)
    out = {int(t): float(d[0]) for t, d in zip(tags, data)}
    gmsh.view.remove(tag)
    gmsh.clear()
    return out


gmsh.initialize()
gmsh.option.setNumber("General.Terminal", 0)
with tempfile.TemporaryDirectory() as tmp:
    for path in sorted(glob.glob(os.path.join(ex, "*.step"))):
        name = os.path.basename(path)[:-5]
        if name == "sphere":  # not planar
            continue
        base = os.path.join(tmp, name)
        for out in ("-o", base + ".msh", "--report", base + ".json"), ("-o", base + ".vtu"):
            subprocess.run([sq, "mesh", path, "-q", "--min-quality", "0"] + list(out), check=True)
        ours = vtu_cells(base + ".vtu", "scaled_jacobian")
        rep = json.load(open(base + ".json"))["mesh"]
        if rep["jacobian_capped"] != 0:
            print("%s: %d quads' bounds capped" % (name, rep["jacobian_capped"]))
            fails += 1
        theirs = gmsh_ratios(base + ".msh")
        if len(theirs) != len(ours):
            print("%s: Gmsh analysed %d elements, we have %d quads" % (name, len(theirs), len(ours)))
            fails += 1
            continue
        worst = 0.0
        for q, r_o in enumerate(ours):
            r_g = theirs[q + 1]
            tol = max(TOL_OURS, 1e-3 * (1 + max(r_o, r_g)) / (1 - 1e-3)) + E_INPUT
            worst = max(worst, abs(r_o - r_g) / tol)
            if abs(r_o - r_g) > tol:
                print("%s: quad %d: ours %.10g, Gmsh's minJ/maxJ %.10g (tolerance %.3g)"
                      % (name, q, r_o, r_g, tol))
                fails += 1
        lo_o, lo_g = min(ours), min(theirs.values())
        if abs(lo_o - lo_g) > 1e-3 * (1 + lo_o) / (1 - 1e-3) + TOL_OURS + E_INPUT:
            print("%s: worst ratio: ours %.6g, Gmsh %.6g" % (name, lo_o, lo_g))
            fails += 1
gmsh.finalize()
sys.exit(1 if fails else 0)
