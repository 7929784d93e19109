#!/usr/bin/python3
"""semquad mesh --periodic against Gmsh 4.8.4's setPeriodic on one face
(issue 16's cascade benchmark; docs/benchmarks.md).

  semquad  `semquad mesh FILE --periodic auto --order 1 [--size H] -o s.msh
           --report s.json -q`: the pairs and their transforms from the report;
  Gmsh     Debian's python3-gmsh 4.8.4 in this process: gmsh.open(FILE), the
           same pairs set with gmsh.model.mesh.setPeriodic (curves found by
           their end points: Gmsh numbers curves its own way), Mesh.Algorithm
           6 (Frontal-Delaunay; 8, Frontal-Delaunay for quads, and 5 crash
           in generate with setPeriodic on real T106 in 4.8.4), Mesh.RecombineAll 1,
           Mesh.RecombinationAlgorithm 3 (Blossom full-quad),
           Mesh.MeshSizeMax = H, Mesh.MeshSizeFactor calibrated (a few untimed
           runs) until Gmsh's quads are within 15 % of semquad's.
Both MSH files are measured with tests/msh_quad_stats.py (quads, triangles,
interior irregular vertices, eta) and their periodic nodes read back with
gmsh.model.mesh.getPeriodicNodes (largest |T(master) - node|).  Times: the
median of --runs runs, in process (semquad: its report's timings_s.total;
Gmsh: open + setPeriodic + generate + write).

usage: /usr/bin/python3 bench/periodic_gmsh.py SEMQUAD FILE [--size H] [--runs 3]
Prints one Markdown table on stdout.  Not a test."""
import argparse
import json
import math
import os
import statistics
import subprocess
import tempfile
import time

import gmsh

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
QUADSTATS = os.path.join(ROOT, "tests", "msh_quad_stats.py")


def semquad(sq, step, size, out, runs):
    rep = out + ".json"
    cmd = [sq, "mesh", step, "--periodic", "auto", "--order", "1", "-o", out, "--report", rep, "-q"]
    if size:
        cmd += ["--size", repr(size)]
    times = []
    for _ in range(runs):
        subprocess.run(cmd, check=True)
        times.append(json.load(open(rep))["timings_s"]["total"])
    return json.load(open(rep)), statistics.median(times)


def curve_ends():
    """{gmsh curve tag: (start xy, end xy)} (a plane z = constant)"""
    ends = {}
    for _, c in gmsh.model.getEntities(1):
        b = gmsh.model.getBoundary([(1, c)], oriented=True)
        p = [gmsh.model.getValue(0, abs(t), []) for _, t in b]
        if len(p) == 2:
            ends[c] = (p[0][:2], p[1][:2])
    return ends


def gmsh_pairs(pairs):
    """The report's translation as Gmsh curves: (image, master, 4x4 affine).
    Gmsh's curves are numbered its own way and semquad's transform is in the
    face's frame: the pairs are found again in 3D, curves of equal length
    whose ends differ by one vector d with |d| the report's shift (its
    sense: the one most pairs share)."""
    a = pairs[0]["affine"]
    shift = math.hypot(a[2], a[5])
    ends = curve_ends()
    by_d = {}
    for m, (m0, m1) in ends.items():
        for s, (s0, s1) in ends.items():
            if s == m or abs(gmsh.model.occ.getMass(1, m) - gmsh.model.occ.getMass(1, s)) > 1e-6:
                continue
            for u, v in ((s0, s1), (s1, s0)):
                d = (u[0] - m0[0], u[1] - m0[1])
                if abs(math.hypot(*d) - shift) < 1e-6 and \
                        math.dist((m1[0] + d[0], m1[1] + d[1]), v) < 1e-6:
                    by_d.setdefault((round(d[0], 6), round(d[1], 6)), []).append((s, m))
    d, links = max(by_d.items(), key=lambda kv: (len(kv[1]), kv[0]))
    aff = [1, 0, 0, d[0], 0, 1, 0, d[1], 0, 0, 1, 0, 0, 0, 0, 1]
    return [(s, m, aff) for s, m in links]


def gmsh_mesh(step, pairs, hmax, factor, out):
    gmsh.initialize(["gmsh", "-v", "0"])
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.option.setNumber("General.NumThreads", 1)
    gmsh.option.setString("Geometry.OCCTargetUnit", "M")  # as semquad: the file's metres
    t0 = time.perf_counter()
    gmsh.open(step)
    links = gmsh_pairs(pairs)
    for s, m, aff in links:
        gmsh.model.mesh.setPeriodic(1, [s], [m], aff)
    for k, v in (("Mesh.Algorithm", 6), ("Mesh.RecombineAll", 1),
                 ("Mesh.RecombinationAlgorithm", 3), ("Mesh.MeshSizeMax", hmax),
                 ("Mesh.MeshSizeFactor", factor), ("Mesh.ElementOrder", 1),
                 ("Mesh.MshFileVersion", 4.1)):
        gmsh.option.setNumber(k, v)
    gmsh.model.mesh.generate(2)
    gmsh.write(out)
    t = time.perf_counter() - t0
    gmsh.finalize()
    return t, len(links)


def periodic_gap(msh):
    """Largest |T(master) - node| over the file's periodic links, links."""
    gmsh.initialize(["gmsh", "-v", "0"])
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.open(msh)
    tags, xyz, _ = gmsh.model.mesh.getNodes()
    pos = {t: xyz[3 * k:3 * k + 2] for k, t in enumerate(tags)}
    gap, links = 0.0, 0
    for _, c in gmsh.model.getEntities(1):
        m, nodes, mn, a = gmsh.model.mesh.getPeriodicNodes(1, c)
        if m == c or not len(nodes):
            continue
        links += 1
        for n, k in zip(nodes, mn):
            x = pos[k]
            gap = max(gap, math.dist((a[0] * x[0] + a[1] * x[1] + a[3],
                                      a[4] * x[0] + a[5] * x[1] + a[7]), pos[n]))
    gmsh.finalize()
    return gap, links


def stats(msh):
    return json.loads(subprocess.run(["/usr/bin/python3", QUADSTATS, msh], check=True,
                                     capture_output=True, text=True).stdout)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("semquad")
    ap.add_argument("step")
    ap.add_argument("--size", type=float, default=0.0)
    ap.add_argument("--runs", type=int, default=3)
    a = ap.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        s_msh, g_msh = os.path.join(tmp, "s.msh"), os.path.join(tmp, "g.msh")
        rep, t_sq = semquad(a.semquad, a.step, a.size, s_msh, a.runs)
        sq = stats(s_msh)
        hmax = a.size or math.sqrt(rep["mesh"]["area"] / rep["mesh"]["quads"])
        factor = 1.0
        for _ in range(8):  # untimed calibration of the quad count
            gmsh_mesh(a.step, rep["periodic"]["pairs"], hmax, factor, g_msh)
            ratio = stats(g_msh)["quads"] / sq["quads"]
            if abs(ratio - 1) < 0.15:
                break
            factor *= math.sqrt(ratio)
        times, nlinks = [], 0
        for _ in range(a.runs):
            t, nlinks = gmsh_mesh(a.step, rep["periodic"]["pairs"], hmax, factor, g_msh)
            times.append(t)
        gm = stats(g_msh)
        rows = [("semquad (%s road)" % rep["road"], sq, t_sq, periodic_gap(s_msh),
                 len(rep["periodic"]["pairs"])),
                ("Gmsh 4.8.4 setPeriodic, f = %.2f" % factor, gm, statistics.median(times),
                 periodic_gap(g_msh), nlinks)]
        print("| mesher | pairs | quads | triangles | irregular interior | eta mean | eta worst "
              "| largest periodic gap | links read back | time (s) |")
        print("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |")
        for name, st, t, (gap, links), npairs in rows:
            print("| %s | %d | %d | %d | %d | %.3f | %.3f | %.1e | %d | %.2f |" % (
                name, npairs, st["quads"], st["triangles"], st["interior_irregular"],
                st["eta_mean"], st["eta_min"], gap, links, t))


if __name__ == "__main__":
    main()
