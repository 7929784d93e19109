#!/usr/bin/python3
"""Quality and topology of a planar quad(-dominant) mesh in a Gmsh MSH file,
measured independently of semquad: the file is read by Gmsh's own reader
(Debian's python3-gmsh), only the corner nodes of each element (the first
four of a quad, three of a triangle) are used; the mesh must lie in a plane
z = constant.  semquad writes quads only; Gmsh's recombined meshes
(bench/compare_gmsh.py) may keep a few triangles.

Prints one JSON object:
  quads, triangles, vertices, boundary_vertices, euler_chi (V - E + F of the
      corner mesh),
  interior_irregular (interior vertices on other than 4 elements),
  boundary_irregular (boundary vertices on other than max(1, floor(theta/90° + 1/2))
      elements, theta the angle of the domain there summed over its elements),
  eta_mean, eta_min, eta_pct_gt_0.9 of the quads (Jezdimirović 2021, Table 1:
      eta = 1 - max_k |alpha_k - 90°| / 90° on the straight corner polygon,
      alpha_k signed w.r.t. the majority orientation of the elements, in
      [0°, 360°): a reflex or folded quad has eta <= 0, docs/conventions.md
      "Quality"),
  inverted_quads (corner polygons of the minority orientation or zero area),
  duplicate_nodes (pairs of element corners that are two nodes closer than
      1e-9 of the mesh's diameter: a mesh that does not conform where two
      faces meet has them).
usage: msh_quad_stats.py MESH.msh"""
import json
import math
import sys

import gmsh
import numpy as np
from scipy.spatial import cKDTree


def read_elements(path):
    """Corner node tags of the quads (n, 4) and triangles (m, 3), and the
    node positions {tag: (x, y)}."""
    gmsh.initialize(["-noenv"], readConfigFiles=False)
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.open(path)
    tags, xyz, _ = gmsh.model.mesh.getNodes()
    x, y, z = xyz[0::3], xyz[1::3], xyz[2::3]
    if np.ptp(z) > 1e-9 * max(np.ptp(x), np.ptp(y), 1e-300):
        sys.exit(f"{path}: the nodes do not lie in one plane z = constant")
    pos = {int(t): (x[i], y[i]) for i, t in enumerate(tags)}
    corners = {4: [], 3: []}
    for etype, _, nodes in zip(*gmsh.model.mesh.getElements(dim=2)):
        name, _, _, nn, _, _ = gmsh.model.mesh.getElementProperties(etype)
        k = 4 if name.startswith("Quadrilateral") else 3 if name.startswith("Triangle") else 0
        if not k:
            sys.exit(f"{path}: element type {name} is neither a quad nor a triangle")
        corners[k] += [[int(t) for t in nodes[i * nn:i * nn + k]] for i in range(len(nodes) // nn)]
    gmsh.finalize()
    return (np.array(corners[4], dtype=np.int64).reshape(-1, 4),
            np.array(corners[3], dtype=np.int64).reshape(-1, 3), pos)


def area_and_angles(c, pos, sign=None):
    """Signed areas of the corner polygons c (n, k), and, given the majority
    sign, their interior angles signed with it, in [0, 2π)."""
    p = np.array([[pos[t] for t in f] for f in c]).reshape(len(c), c.shape[1], 2)
    x, y = p[..., 0], p[..., 1]
    area = 0.5 * (x * np.roll(y, -1, axis=1) - np.roll(x, -1, axis=1) * y).sum(axis=1)
    if sign is None:
        return area
    a = np.roll(p, -1, axis=1) - p  # to the next corner
    b = np.roll(p, 1, axis=1) - p  # to the previous corner
    cross = a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]
    dot = (a * b).sum(axis=2)
    return area, np.mod(np.arctan2(sign * cross, dot), 2 * math.pi)


def face_groups(path, rule="Gauss20"):
    """Per physical surface group of the file (a domain's faces): {name:
    (area, least det J, set of the node tags of its elements, high-order
    nodes included)}, the area the integral of det J of the elements' own
    maps by Gmsh's Gauss rule `rule` (exact for a polynomial det J of that
    degree per variable), det J at the same points."""
    gmsh.initialize(["-v", "0"])
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.open(path)
    out = {}
    for dim, tag in gmsh.model.getPhysicalGroups(2):
        area, least, nodes = 0.0, math.inf, set()
        for ent in gmsh.model.getEntitiesForPhysicalGroup(dim, tag):
            for etype in gmsh.model.mesh.getElementTypes(2, ent):
                lc, w = gmsh.model.mesh.getIntegrationPoints(etype, rule)
                _, det, _ = gmsh.model.mesh.getJacobians(etype, lc, ent)
                det = np.array(det).reshape(-1, len(w))
                area += float((det * np.array(w)).sum())
                least = min(least, float(det.min()))
                _, enodes = gmsh.model.mesh.getElementsByType(etype, ent)
                nodes.update(int(t) for t in enodes)
        out[gmsh.model.getPhysicalName(dim, tag)] = (area, least, nodes)
    gmsh.finalize()
    return out


def periodic_pairs(msh, size):
    """The $Periodic section as Gmsh's reader gives it: {image curve (0-based):
    (master curve, affine 4x4 rows, largest |T(x_master) - x| / size, pairs,
    nodes on the curve)}, high-order nodes included."""
    gmsh.initialize(["-v", "0"])
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.open(msh)
    tags, xyz, _ = gmsh.model.mesh.getNodes()
    pos = {t: (xyz[3 * k], xyz[3 * k + 1]) for k, t in enumerate(tags)}
    out = {}
    for dim, tag in gmsh.model.getEntities(1):
        master, nodes, mnodes, aff = gmsh.model.mesh.getPeriodicNodes(dim, tag)
        if master == tag or len(nodes) == 0:
            continue
        gap = 0.0
        for n, m in zip(nodes, mnodes):
            x, y = pos[m]
            tx = aff[0] * x + aff[1] * y + aff[3]
            ty = aff[4] * x + aff[5] * y + aff[7]
            gap = max(gap, math.hypot(tx - pos[n][0], ty - pos[n][1]))
        on_curve = set()
        for _, _, enodes in zip(*gmsh.model.mesh.getElements(1, tag)):
            on_curve.update(enodes)
        out[tag - 1] = (master - 1, list(aff), gap / size, len(nodes), len(on_curve))
    gmsh.finalize()
    return out


def stats(path):
    quads, tris, pos = read_elements(path)
    areas = np.concatenate([area_and_angles(quads, pos), area_and_angles(tris, pos)])
    sign = 1.0 if (areas > 0).sum() >= (areas < 0).sum() else -1.0
    qarea, qalpha = area_and_angles(quads, pos, sign)
    _, talpha = area_and_angles(tris, pos, sign)
    eta = 1 - np.abs(qalpha - math.pi / 2).max(axis=1) / (math.pi / 2)
    edges, valence, theta = {}, {}, {}
    for c, alpha in ((quads, qalpha), (tris, talpha)):
        k = c.shape[1]
        for f, al in zip(c, alpha):
            for i in range(k):
                e = (min(f[i], f[(i + 1) % k]), max(f[i], f[(i + 1) % k]))
                edges[e] = edges.get(e, 0) + 1
                valence[f[i]] = valence.get(f[i], 0) + 1
                theta[f[i]] = theta.get(f[i], 0.0) + al[i]
    boundary = {v for e, n in edges.items() if n == 1 for v in e}
    interior_irr = sum(1 for v, n in valence.items() if v not in boundary and n != 4)
    # the expected valence rounds halves up, floor(x + 1/2), not to even
    boundary_irr = sum(1 for v in boundary
                       if valence[v] != max(1, math.floor(theta[v] / (math.pi / 2) + 0.5)))
    nq = len(quads)
    p = np.array([pos[v] for v in valence]).reshape(-1, 2)
    diameter = math.hypot(*np.ptp(p, axis=0)) if len(p) else 0.0
    duplicates = len(cKDTree(p).query_pairs(1e-9 * diameter)) if len(p) else 0
    return {"quads": nq, "triangles": len(tris), "vertices": len(valence),
            "boundary_vertices": len(boundary),
            "euler_chi": len(valence) - len(edges) + nq + len(tris),
            "interior_irregular": interior_irr, "boundary_irregular": boundary_irr,
            "eta_mean": float(eta.mean()) if nq else None, "eta_min": float(eta.min()) if nq else None,
            "eta_pct_gt_0.9": float(100.0 * (eta > 0.9).sum() / nq) if nq else None,
            "inverted_quads": int((sign * qarea <= 0).sum()), "duplicate_nodes": duplicates}


def against_report(msh, d):
    """Why the mesh file disagrees with semquad's report d of it (None: it
    agrees): the report's quads, none inverted, no triangle, V - E + F equal to
    the face's chi, the report's interior irregular vertices."""
    m, g = d["mesh"], stats(msh)
    if g["quads"] != m["quads"] or g["triangles"] != 0 or g["inverted_quads"] != 0:
        return "file: %d quads (report %d), %d triangles, %d inverted" % (
            g["quads"], m["quads"], g["triangles"], g["inverted_quads"])
    if g["euler_chi"] != d["chi"]:
        return "V - E + F = %d, chi %d" % (g["euler_chi"], d["chi"])
    if g["interior_irregular"] != m["irregular_interior_vertices"]:
        return "%d interior irregular vertices in the file, %d in the report" % (
            g["interior_irregular"], m["irregular_interior_vertices"])
    return None


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    print(json.dumps(stats(sys.argv[1]), indent=1))
