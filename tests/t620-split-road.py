#!/usr/bin/python3
"""The split road (src/mesh/quad_split.c) on every planar example: `semquad mesh
--road split` must give an all-quad mesh, valid and conforming, byte for byte
the same on a second run.

Checks, on each example:
- exit 0, the report's road "split", no inverted quad, min scaled Jacobian > 0
  (signs: no tolerance);
- Euler: V - E + F of the quads' corner graph (read back from the MSH file with
  Gmsh's own reader) equals the face's chi, and every interior edge has two
  quads (conforming), every boundary edge one;
- area: the report's (Gauss quadrature of det J, exact for the polynomial map)
  against `semquad info`'s (OpenCASCADE's, exact to ~1e-9).  The difference is
  the order-Q interpolation of the curved boundary: each boundary quad side
  covers at most half a triangle edge, which turns by at most 30 degrees (the
  triangulation's bound), so phi <= pi/12; interpolating a circle of radius R
  over an arc phi at Q+1 nodes moves it by at most R phi^(Q+1) / (Q+1)!
  (Lagrange remainder of x(t) with |x^(Q+1)| <= R), over a perimeter P: the
  bound below, with R the largest radius of the example's arcs (the bounding
  box's half diagonal) and a factor 2 for the triangulation's own chords'
  round-off-free placement.  Straight-sided faces must agree to 1e-9 relative
  (OpenCASCADE's area and the sum of exact quadratures).
usage: t620-split-road.py SEMQUAD EXAMPLES_DIR"""
import filecmp
import json
import math
import os
import re
import subprocess
import sys
import tempfile

sq, ex = sys.argv[1:3]
try:
    import gmsh
except ImportError:
    sys.exit(77)

Q = 4
EXAMPLES = ["annulus", "disc", "half_disc", "lshape", "naca0012", "nautilus", "obtuse_quad",
            "polygon", "quarter_circle", "square", "square_hole", "triangle", "two_holes"]


def info(step):
    out = subprocess.run([sq, "info", step], capture_output=True, text=True, check=True).stdout
    area = float(re.search(r"area ([-+0-9.e]+)", out).group(1))
    b = [float(x) for x in re.search(r"bbox \[(\S+), (\S+)\] x \[(\S+), (\S+)\]", out).groups()]
    curved = any(k in out for k in ("circle", "bspline", "ellipse", "bezier"))
    length = sum(float(x) for x in re.findall(r"length ([-+0-9.e]+)", out))
    return area, curved, 0.5 * math.hypot(b[1] - b[0], b[3] - b[2]), length


def corner_graph(msh):
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.open(msh)
    types, _, nodes = gmsh.model.mesh.getElements(2)
    gmsh.finalize()
    npe = (Q + 1) ** 2
    conn = nodes[0]
    quads = [conn[i * npe:i * npe + 4] for i in range(len(conn) // npe)]
    edges = {}
    for c in quads:
        for k in range(4):
            a, b = int(c[k]), int(c[(k + 1) % 4])
            key = (min(a, b), max(a, b))
            edges[key] = edges.get(key, 0) + 1
    verts = {int(v) for c in quads for v in c}
    return len(verts), edges, len(quads)


def check(name, tmp):
    step = os.path.join(ex, name + ".step")
    outs = []
    for run in range(2):
        msh, rep = os.path.join(tmp, "%s%d.msh" % (name, run)), os.path.join(tmp, "%s%d.json" % (name, run))
        p = subprocess.run([sq, "mesh", step, "--road", "split", "--order", str(Q), "-q", "-o", msh,
                            "--report", rep], capture_output=True, text=True)
        if p.returncode != 0:
            return "exit %d: %s" % (p.returncode, p.stderr.strip())
        outs.append((msh, rep))
    if not filecmp.cmp(outs[0][0], outs[1][0], shallow=False):
        return "two runs wrote different meshes"
    d = json.load(open(outs[0][1]))
    m = d["mesh"]
    if d["road"] != "split" or m["inverted"] != 0 or not m["min_scaled_jacobian"] > 0:
        return "road %s, %d inverted, min scaled Jacobian %g" % (d["road"], m["inverted"],
                                                                 m["min_scaled_jacobian"])
    V, edges, F = corner_graph(outs[0][0])
    if F != m["quads"]:
        return "%d quads in the file, %d in the report" % (F, m["quads"])
    if any(n > 2 for n in edges.values()):
        return "an edge shared by more than two quads (not conforming)"
    if V - len(edges) + F != d["chi"]:
        return "V - E + F = %d, chi %d" % (V - len(edges) + F, d["chi"])
    area, curved, R, P = info(step)
    phi = math.pi / 12
    tol = 2.0 * P * R * phi ** (Q + 1) / math.factorial(Q + 1) if curved else 1e-9 * area
    if abs(m["area"] - area) > tol:
        return "area %.12g, OpenCASCADE %.12g, difference %.3g > %.3g" % (m["area"], area,
                                                                         abs(m["area"] - area), tol)
    return None


def main():
    fails = 0
    with tempfile.TemporaryDirectory() as tmp:
        for name in EXAMPLES:
            why = check(name, tmp)
            if why:
                print("%s: %s" % (name, why))
                fails += 1
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
