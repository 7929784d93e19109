#!/usr/bin/python3
"""semquad against Gmsh 4.8.4 meshing the same whole file (issue 16's
benchmarks; docs/benchmarks.md): a periodic face (the cascade) and domains
of several faces sharing curves (the circle-square).

  semquad  `semquad mesh FILE [--periodic auto] --order 1 [--size H]
           --threads T -o s.msh --report s.json -q`, every face of the file
           (no --face): with --periodic auto for the positional FILEs, the
           pairs and their transforms from the report; without it for the
           --whole FILEs;
  Gmsh     Debian's python3-gmsh 4.8.4 in this process: gmsh.open(FILE)
           in the unit semquad reads it in (Geometry.OCCTargetUnit from
           `semquad info --json`; every face, and faces sharing an OCCT
           edge share its mesh), for a
           periodic FILE the same pairs set with gmsh.model.mesh.setPeriodic
           (curves found by their end points: Gmsh numbers curves its own
           way), Mesh.RecombineAll 1, Mesh.RecombinationAlgorithm 3 (Blossom
           full-quad), Mesh.CrossFieldClosestPoint 0, Mesh.MeshSizeMax = H,
           General.NumThreads 1,
           Mesh.MeshSizeFactor calibrated (a few untimed runs) until Gmsh's
           quads are within 15 % of semquad's; Mesh.Algorithm 6
           (Frontal-Delaunay; 8, Frontal-Delaunay for quads, and 5 crash in
           generate with setPeriodic on real T106 in 4.8.4), and for a
           --whole FILE also 8.
Both MSH files are measured with tests/msh_quad_stats.py (quads, triangles,
interior irregular vertices -- a conforming mesh's shared-curve nodes are
interior --, eta, duplicate nodes) and their periodic nodes read back with
gmsh.model.mesh.getPeriodicNodes (largest |T(master) - node|).  Times: the
median of --runs runs, in process (semquad: its report's timings_s.total;
Gmsh: open + setPeriodic + generate + write).

usage: /usr/bin/python3 bench/periodic_gmsh.py SEMQUAD [FILE ...] [--whole FILE ...]
           [--size H] [--runs 3] [--threads 1]
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


def semquad(sq, step, periodic, size, threads, out, runs):
    rep = out + ".json"
    cmd = [sq, "mesh", step, "--order", "1", "--threads", str(threads), "-o", out,
           "--report", rep, "-q"] + (["--periodic", "auto"] if periodic else [])
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


def file_unit(sq, step):
    """The unit semquad reads the file in (`semquad info --json`), as
    Gmsh's Geometry.OCCTargetUnit: both mesh in the same lengths."""
    info = json.loads(subprocess.run([sq, "info", step, "--json"], check=True,
                                     capture_output=True, text=True).stdout)
    return info["unit"].upper()


def gmsh_mesh(step, unit, pairs, algorithm, hmax, factor, out):
    gmsh.initialize(["gmsh", "-v", "0"])
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.option.setNumber("General.NumThreads", 1)
    gmsh.option.setString("Geometry.OCCTargetUnit", unit)
    t0 = time.perf_counter()
    gmsh.open(step)
    links = gmsh_pairs(pairs) if pairs else []
    for s, m, aff in links:
        gmsh.model.mesh.setPeriodic(1, [s], [m], aff)
    for k, v in (("Mesh.Algorithm", algorithm), ("Mesh.RecombineAll", 1),
                 ("Mesh.RecombinationAlgorithm", 3), ("Mesh.MeshSizeMax", hmax),
                 ("Mesh.MeshSizeFactor", factor), ("Mesh.ElementOrder", 1),
                 ("Mesh.MshFileVersion", 4.1), ("Mesh.CrossFieldClosestPoint", 0)):
        gmsh.option.setNumber(k, v)
    gmsh.model.mesh.generate(2)
    gmsh.write(out)
    t = time.perf_counter() - t0
    gmsh.finalize()
    return t, len(links)


def gmsh_row(step, unit, pairs, algorithm, hmax, quads, out, runs):
    """Gmsh's size factor calibrated (untimed) to semquad's quad count, then
    runs timed: (factor, its stats, median time, pairs linked)."""
    factor = 1.0
    for _ in range(8):
        gmsh_mesh(step, unit, pairs, algorithm, hmax, factor, out)
        ratio = stats(out)["quads"] / quads
        if abs(ratio - 1) < 0.15:
            break
        factor *= math.sqrt(ratio)
    times, nlinks = [], 0
    for _ in range(runs):
        t, nlinks = gmsh_mesh(step, unit, pairs, algorithm, hmax, factor, out)
        times.append(t)
    return factor, stats(out), statistics.median(times), nlinks


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


ALGORITHM = {6: "Frontal-Delaunay", 8: "Frontal-Delaunay for quads"}


def rows_of(a, step, periodic, tmp):
    """The table's rows for one file: semquad's, then Gmsh's."""
    s_msh, g_msh = os.path.join(tmp, "s.msh"), os.path.join(tmp, "g.msh")
    rep, t_sq = semquad(a.semquad, step, periodic, a.size, a.threads, s_msh, a.runs)
    sq = stats(s_msh)
    pairs = rep["periodic"]["pairs"] if periodic else []
    case = os.path.basename(step) + (" --periodic auto" if periodic else " (%d faces)" %
                                     len(rep.get("faces", [0])))
    roads = sorted({f["road"] for f in rep["faces"]}) if "faces" in rep else [rep["road"]]
    rows = [(case, "semquad --threads %d (%s road)" % (a.threads, ", ".join(roads)), sq, t_sq,
             periodic_gap(s_msh) if periodic else None, len(pairs))]
    hmax = a.size or math.sqrt(rep["mesh"]["area"] / rep["mesh"]["quads"])
    unit = file_unit(a.semquad, step)
    for alg in (6,) if periodic else (8, 6):
        factor, gm, t, nlinks = gmsh_row(step, unit, pairs, alg, hmax, sq["quads"], g_msh,
                                         a.runs)
        rows.append((case, "Gmsh 4.8.4 %s%s, f = %.2f" % (
            ALGORITHM[alg], " setPeriodic" if periodic else "", factor), gm, t,
            periodic_gap(g_msh) if periodic else None, nlinks))
    return rows


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("semquad")
    ap.add_argument("step", nargs="*", help="files meshed with --periodic auto")
    ap.add_argument("--whole", action="append", default=[],
                    help="a file meshed whole without --periodic (repeatable)")
    ap.add_argument("--size", type=float, default=0.0)
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--threads", type=int, default=1, help="semquad's (Gmsh runs on 1)")
    a = ap.parse_args()
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for step, periodic in [(f, True) for f in a.step] + [(f, False) for f in a.whole]:
            rows += rows_of(a, step, periodic, tmp)
    print("| file | mesher | pairs | quads | triangles | irregular interior | eta mean | "
          "eta worst | duplicate nodes | largest periodic gap | links read back | time (s) |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    for case, name, st, t, gap, npairs in rows:
        print("| %s | %s | %d | %d | %d | %d | %.3f | %.3f | %d | %s | %s | %.2f |" % (
            case, name, npairs, st["quads"], st["triangles"], st["interior_irregular"],
            st["eta_mean"], st["eta_min"], st["duplicate_nodes"],
            "%.1e" % gap[0] if gap else "—", "%d" % gap[1] if gap else "—", t))


if __name__ == "__main__":
    main()
