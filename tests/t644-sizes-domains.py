#!/usr/bin/python3
"""t644: the user's sizes on a domain of several faces and with --periodic
(issue 24; docs/sizes.md, "Domains and periodic faces").

- three_row (tests/domain_faces.py: three rectangles in a row, one frame):
  `--refine 1.2,0.5,0.1,0.02` acts on the domain: more quads than at the
  uniform size (300), and the quad nearest the point is refined: its
  longest side at most 2 h = 0.04 (the relaxation's targets shrink the
  quads at a refinement inside a patch to about 1.6 h, docs/sizes.md;
  unrefined it is 0.1).
- three_row with `--edge-size 3:0.02` or `--bl 3 ...`: an edge number
  names each face's own edge, not one curve of the domain: refused with
  exit 2, one line on stderr naming the option, no output file.
- channel (one face, its walls y = 0 and y = 1 periodic) with `--periodic
  auto --bl 4`: the report's boundary_layers (the hole's wall, edge 4):
  every first height within 3 % of h0 (the lines re-graded by the metric,
  t643's band), 3 layers, the thickness within 3 % of the asked one.
usage: t644-sizes-domains.py SEMQUAD DOMAIN_FACES_PY"""
import json
import math
import os
import subprocess
import sys
import tempfile

try:
    import gmsh  # noqa: F401 (msh_quad_stats and domain_faces read through it)
except ImportError:
    sys.exit(77)
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import msh_quad_stats  # noqa: E402

SQ, GEN = sys.argv[1], sys.argv[2]
fails = []


def mesh(step, out, *extra):
    return subprocess.run([SQ, "mesh", step, "-q", "-o", out] + list(extra),
                          capture_output=True, text=True, timeout=600)


def nearest_quad(msh, x, y):
    """Longest side of the quad whose centre is nearest (x, y); quads."""
    quads, _, pos = msh_quad_stats.read_elements(msh)
    best = None
    for q in quads.tolist():
        p = [pos[v] for v in q]
        c = (sum(a for a, _ in p) / 4, sum(b for _, b in p) / 4)
        d = math.hypot(c[0] - x, c[1] - y)
        side = max(math.hypot(p[k][0] - p[(k + 1) % 4][0], p[k][1] - p[(k + 1) % 4][1])
                   for k in range(4))
        if best is None or d < best[0]:
            best = (d, side)
    return best[1], len(quads)


def domain(d):
    step = os.path.join(d, "three_row.step")
    subprocess.run([sys.executable, GEN, "three_row", step], check=True, capture_output=True)
    out = os.path.join(d, "r.msh")
    r = mesh(step, out, "--size", "0.1", "--refine", "1.2,0.5,0.1,0.02")
    if r.returncode:
        fails.append("three_row --refine: exit %d: %s" % (r.returncode, r.stderr.strip()))
    else:
        side, n = nearest_quad(out, 1.2, 0.5)
        print("three_row --refine: %d quads, the quad at the point %.4f long" % (n, side))
        if not (n > 300 and side <= 0.04):
            fails.append("three_row --refine: %d quads (uniform 300), the quad at the point "
                         "%.4f long (expects <= 0.04)" % (n, side))
    for name, extra in (("--edge-size", ["--edge-size", "3:0.02"]),
                        ("--bl", ["--bl", "3", "--bl-first", "0.01", "--bl-layers", "3"])):
        out = os.path.join(d, "x.msh")
        r = mesh(step, out, "--size", "0.1", *extra)
        lines = r.stderr.strip().splitlines()
        print("three_row %s: exit %d: %s" % (name, r.returncode, r.stderr.strip()))
        if r.returncode != 2 or len(lines) != 1 or name not in lines[0] or os.path.exists(out):
            fails.append("three_row %s: exit %d, stderr %r, output %s (expects exit 2, one line "
                         "naming it, no file)" % (name, r.returncode, r.stderr,
                                                  os.path.exists(out)))


def periodic(d):
    step = os.path.join(d, "channel.step")
    subprocess.run([sys.executable, GEN, "channel", step], check=True, capture_output=True)
    out, rep = os.path.join(d, "c.msh"), os.path.join(d, "c.json")
    h0, ratio, layers = 0.005, 1.2, 3
    r = mesh(step, out, "--periodic", "auto", "--size", "0.1", "--bl", "4", "--bl-first",
             str(h0), "--bl-ratio", str(ratio), "--bl-layers", str(layers), "--report", rep)
    if r.returncode:
        fails.append("channel --periodic --bl: exit %d: %s" % (r.returncode, r.stderr.strip()))
        return
    report = json.load(open(rep))
    if "periodic" not in report or len(report.get("boundary_layers", [])) != 1:
        fails.append("channel --periodic --bl: report keys %s" % sorted(report))
        return
    got = report["boundary_layers"][0]["achieved"]
    thick = h0 * (ratio ** layers - 1) / (ratio - 1)
    print("channel --periodic --bl: first %.6f..%.6f, %d layers, thickness %.6f..%.6f"
          % (got["first_min"], got["first_max"], got["layers"], got["thickness_min"],
             got["thickness_max"]))
    if not (0.97 * h0 <= got["first_min"] and got["first_max"] <= 1.03 * h0
            and got["layers"] == layers and 0.97 * thick <= got["thickness_min"]
            and got["thickness_max"] <= 1.03 * thick):
        fails.append("channel --periodic --bl: achieved %r against h0 %g, %d layers, T %g"
                     % (got, h0, layers, thick))


def main():
    with tempfile.TemporaryDirectory() as d:
        domain(d)
        periodic(d)
    for f in fails:
        print("FAIL", f)
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
