#!/usr/bin/python3
"""Quality and topology of a planar quad mesh in a Gmsh MSH file, measured
independently of semquad: the file is read by Gmsh's own reader (Debian's
python3-gmsh), only the corner nodes of each quad (its first four) are used; the mesh must
lie in a plane z = constant.

Prints one JSON object:
  quads, vertices, boundary_vertices, euler_chi (V - E + F of the corner mesh),
  interior_irregular (interior vertices on other than 4 quads),
  boundary_irregular (boundary vertices on other than max(1, round(theta/90°))
      quads, theta the angle of the domain there summed over its quads),
  eta_mean, eta_min, eta_pct_gt_0.9 (Jezdimirović 2021, Table 1:
      eta = 1 - max_k |alpha_k - 90°| / 90° on the straight corner polygon,
      alpha_k signed w.r.t. the majority orientation, in [0°, 360°): a
      reflex or folded quad has eta <= 0, docs/conventions.md "Quality"),
  inverted_quads (corner polygons of the minority orientation or zero area).
usage: msh_quad_stats.py MESH.msh"""
import json
import math
import sys

import gmsh
import numpy as np


def read_quads(path):
    """Corner coordinates (n, 4, 2) and corner node tags (n, 4)."""
    gmsh.initialize(["-noenv"], readConfigFiles=False)
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.open(path)
    tags, xyz, _ = gmsh.model.mesh.getNodes()
    x, y, z = xyz[0::3], xyz[1::3], xyz[2::3]
    if np.ptp(z) > 1e-9 * max(np.ptp(x), np.ptp(y), 1e-300):
        sys.exit(f"{path}: the nodes do not lie in one plane z = constant")
    pos = {int(t): (x[i], y[i]) for i, t in enumerate(tags)}
    corners = []
    for etype, _, nodes in zip(*gmsh.model.mesh.getElements(dim=2)):
        name, _, _, nn, _, _ = gmsh.model.mesh.getElementProperties(etype)
        if not name.startswith("Quadrilateral"):
            sys.exit(f"{path}: element type {name} is not a quad")
        corners += [[int(t) for t in nodes[k * nn:k * nn + 4]] for k in range(len(nodes) // nn)]
    gmsh.finalize()
    c = np.array(corners, dtype=np.int64)
    return np.array([[pos[t] for t in q] for q in c]), c


def corner_angles(p, sign):
    """Signed interior angle at every corner, in [0, 2π)."""
    a = np.roll(p, -1, axis=1) - p  # to the next corner
    b = np.roll(p, 1, axis=1) - p  # to the previous corner
    cross = a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]
    dot = (a * b).sum(axis=2)
    return np.mod(np.arctan2(sign * cross, dot), 2 * math.pi)


def stats(path):
    p, c = read_quads(path)
    x, y = p[..., 0], p[..., 1]
    area = 0.5 * (x * np.roll(y, -1, axis=1) - np.roll(x, -1, axis=1) * y).sum(axis=1)
    sign = 1.0 if (area > 0).sum() >= (area < 0).sum() else -1.0
    alpha = corner_angles(p, sign)
    eta = 1 - np.abs(alpha - math.pi / 2).max(axis=1) / (math.pi / 2)
    edges = {}
    for q in c:
        for k in range(4):
            e = (min(q[k], q[(k + 1) % 4]), max(q[k], q[(k + 1) % 4]))
            edges[e] = edges.get(e, 0) + 1
    boundary = {v for e, n in edges.items() if n == 1 for v in e}
    valence, theta = {}, {}
    for q, al in zip(c, alpha):
        for v, a in zip(q, al):
            valence[v] = valence.get(v, 0) + 1
            theta[v] = theta.get(v, 0.0) + a
    interior_irr = sum(1 for v, n in valence.items() if v not in boundary and n != 4)
    # the expected valence rounds halves up, floor(x + 1/2), not to even
    boundary_irr = sum(1 for v in boundary
                       if valence[v] != max(1, math.floor(theta[v] / (math.pi / 2) + 0.5)))
    return {"quads": len(c), "vertices": len(valence), "boundary_vertices": len(boundary),
            "euler_chi": len(valence) - len(edges) + len(c),
            "interior_irregular": interior_irr, "boundary_irregular": boundary_irr,
            "eta_mean": float(eta.mean()), "eta_min": float(eta.min()),
            "eta_pct_gt_0.9": float(100.0 * (eta > 0.9).sum() / len(c)),
            "inverted_quads": int((sign * area <= 0).sum())}


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    print(json.dumps(stats(sys.argv[1]), indent=1))
