#!/usr/bin/python3
"""t704: the faces of a domain meshed on threads (`--threads N`,
docs/domains.md "Threads") give the serial run's output, byte for byte.

Domains built here with Gmsh's OCC kernel (tests/domain_faces.py): ring4
(four faces sharing four edges; with --periodic auto its radial sides are
pairs: the layout road with chord counts agreed in rounds, and the split
road with --road split), three_row (three rectangles: the layout road),
circle_square (a disc in a square) and grid_holes (four squares with a hole
each): the layout road's rounds fail on the last two, the split road meshes
them; ring4 again at size 0.004 (24 696 quads), where the libraries that
are not safe for concurrent callers (sem/lib_lock.h) are used hardest, with
--threads 2 three times.  Each is meshed with --threads 1, 2 and 3 at
order 4, and:

  - the MSH files are byte-identical;
  - the reports are identical but for their timings_s;
  - the log (stderr) has the same lines in the same order once the times
    in them, "(0.123 s)", are blanked: each face's lines are kept while
    the faces run and said in face order afterwards;
  - the mesh is a real one: Gmsh's reader (tests/msh_quad_stats.py) finds
    the report's quads, no triangle, none inverted, no two corners closer
    than 1e-9 of the mesh's diameter (conforming: a shared curve's nodes
    are one node, not two), and the report's interior irregular vertices
    (a shared curve's nodes are interior once it conforms).
usage: t704-domain-threads.py SEMQUAD DOMAIN_FACES_PY MSH_QUAD_STATS_PY"""
import json
import os
import re
import subprocess
import sys
import tempfile

try:
    import gmsh  # noqa: F401  (domain_faces.py and msh_quad_stats.py need it)
except ImportError:
    sys.exit(77)

SQ, GEN, QS = sys.argv[1:4]
sys.path.insert(0, os.path.dirname(os.path.abspath(QS)))
import msh_quad_stats  # noqa: E402

# case: (domain, options, thread counts after the serial run)
CASES = {
    "ring4_periodic": ("ring4", ["--periodic", "auto"], (2, 3)),
    "ring4_split": ("ring4", ["--periodic", "auto", "--road", "split"], (2, 3)),
    "three_row": ("three_row", ["--size", "0.2"], (2, 3)),
    "circle_square": ("circle_square", ["--size", "0.25"], (2, 3)),
    "grid_holes": ("grid_holes", [], (2, 3)),
    # 24 696 quads: the relaxation's Hessians are ordered by CHOLMOD's nested
    # dissection (METIS, one process-wide random generator) and factored by
    # OpenBLAS (one process-wide buffer table) while other faces do the
    # same; without sem/lib_lock.h about a third of the runs with two
    # threads differed in the last digits (METIS) or failed a factorization
    # (OpenBLAS), so it runs four times
    "ring4_fine": ("ring4", ["--size", "0.004"], (2, 2, 2, 3)),
}
TIME = re.compile(r"\d+\.\d+ s\b")
fails = []


def run(step, extra, threads, tmp, case):
    base = os.path.join(tmp, "%s_%d" % (case, threads))
    r = subprocess.run([SQ, "mesh", step, "--order", "4", "--threads", str(threads), "-o",
                        base + ".msh", "--report", base + ".json"] + extra,
                       capture_output=True, text=True)
    if r.returncode != 0:
        fails.append("%s --threads %d: exit %d: %s" % (case, threads, r.returncode,
                                                      r.stderr.strip()))
        return None
    report = json.load(open(base + ".json"))
    report.pop("timings_s")
    log = [TIME.sub("T s", line) for line in r.stderr.splitlines()]
    return open(base + ".msh", "rb").read(), report, log, base + ".msh"


def main():
    with tempfile.TemporaryDirectory() as tmp:
        steps = {}
        for case, (domain, extra, counts) in CASES.items():
            if domain not in steps:
                steps[domain] = os.path.join(tmp, domain + ".step")
                subprocess.run([sys.executable, GEN, domain, steps[domain]], check=True,
                               capture_output=True)
            first = run(steps[domain], extra, 1, tmp, case)
            if first is None:
                continue
            msh1, rep1, log1, path1 = first
            for t in counts:
                again = run(steps[domain], extra, t, tmp, case)
                if again is None:
                    continue
                msh, rep, log, _ = again
                if msh != msh1:
                    fails.append("%s: the MSH of --threads %d differs from --threads 1" % (case, t))
                if rep != rep1:
                    diff = [k for k in rep1 if rep.get(k) != rep1[k]]
                    fails.append("%s: the report of --threads %d differs in %s" % (case, t, diff))
                if log != log1:
                    first = next((a, b) for a, b in zip(log + [""], log1 + [""]) if a != b)
                    fails.append("%s: the log of --threads %d differs: %r, serial %r" %
                                 (case, t, first[0], first[1]))
            g, m = msh_quad_stats.stats(path1), rep1["mesh"]
            if (g["quads"], g["triangles"], g["inverted_quads"], g["interior_irregular"],
                    g["duplicate_nodes"]) != (m["quads"], 0, 0, m["irregular_interior_vertices"], 0):
                fails.append("%s: Gmsh's reader: %d quads, %d triangles, %d inverted, %d interior "
                             "irregular, %d duplicate nodes; the report: %d quads, %d irregular" % (
                                 case, g["quads"], g["triangles"], g["inverted_quads"],
                                 g["interior_irregular"], g["duplicate_nodes"], m["quads"],
                                 m["irregular_interior_vertices"]))
    for f in fails:
        print("FAIL", f)
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
