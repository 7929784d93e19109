#!/usr/bin/python3
"""t704: a domain meshed with `--threads N` gives the serial run's output,
byte for byte (docs/domains.md "Threads": the faces run one after another,
the threads go to each face's refinement, quality pass and MSH text).

Domains built here with Gmsh's OCC kernel (tests/domain_faces.py): ring4
(four faces sharing four edges; with --periodic auto its radial sides are
pairs: the layout road with chord counts agreed in rounds, and the split
road with --road split), three_row (three rectangles: the layout road),
circle_square (a disc in a square: the layout road, the disc's vertices
slid onto the square's) and grid_holes (four squares with a hole each).  Each is meshed with --threads 1, 2 and 3 at order 4, and:

  - the MSH files are byte-identical;
  - the reports are identical but for their timings_s;
  - the log (stderr) has the same lines in the same order once the times
    in them, "(0.123 s)", are blanked;
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

# case: (domain, options)
CASES = {
    "ring4_periodic": ("ring4", ["--periodic", "auto"]),
    "ring4_split": ("ring4", ["--periodic", "auto", "--road", "split"]),
    "three_row": ("three_row", ["--size", "0.2"]),
    "circle_square": ("circle_square", ["--size", "0.25"]),
    "grid_holes": ("grid_holes", []),
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
        for case, (domain, extra) in CASES.items():
            if domain not in steps:
                steps[domain] = os.path.join(tmp, domain + ".step")
                subprocess.run([sys.executable, GEN, domain, steps[domain]], check=True,
                               capture_output=True)
            runs = {t: run(steps[domain], extra, t, tmp, case) for t in (1, 2, 3)}
            if any(v is None for v in runs.values()):
                continue
            msh1, rep1, log1, path1 = runs[1]
            for t in (2, 3):
                msh, rep, log, _ = runs[t]
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
