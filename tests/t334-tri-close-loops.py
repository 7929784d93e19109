#!/usr/bin/python3
"""The triangulation stage on faces whose boundary chords would cross, and on
many near-straight corners (issue 14).  Faces written by step_face.py.

1. A circular hole near-tangent to the outline (gaps 1e-3 and 1e-6 of the
   face): the boundary polygon's chords of the hole cross the outline's where
   the curves do not, until they are halved there.  `triangulate` at order 1
   (the split road's) and order 4 must give a valid triangulation (min scaled
   Jacobian > 0) within 60 s, whose area matches 1 - pi r^2 within the
   boundary discretization's own error: chords turning by at most 30 degrees
   (the default --max-turn) lose at most pi r^2 (1 - sin(t)/t), t = pi/6, of
   the circle at order 1; at order 4 the arc's Lagrange interpolant at the
   5 Gauss-Lobatto points is within r t^5 / (2^5 5!) of the arc, so the area
   within 2 pi r^2 t^5 / (2^5 5!) (straight edges are exact either way).
2. The hole touching the outline (gap 0) is no face: exit 4, one line.
3. A 155-gon inscribed in a wobbly circle (every corner turns by 0.6 to 4
   degrees, bench/stress_corpus.py's many_sided class): the guiding field's
   triangulation grades no corner (they are near-straight: 2 quads, no
   separatrix), so it has the triangles of its boundary points and size,
   under 20 per corner (each graded corner added ~130: 21k triangles, 86 s).
usage: t334-tri-close-loops.py SEMQUAD"""
import math
import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from step_face import step_face  # noqa: E402 (the tests' own STEP writer)

sq = sys.argv[1]
fails = []
SQUARE = [(0, 0), (1, 0), (1, 1), (0, 1)]
T = math.pi / 6  # the default largest turn of a boundary chord


def run(args, timeout=60):
    try:
        return subprocess.run([sq] + args, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        fails.append("%s: no answer in %d s" % (" ".join(args), timeout))
        return None


with tempfile.TemporaryDirectory() as tmp:
    for gap in (1e-3, 1e-6):
        r = 0.3 - gap
        path = os.path.join(tmp, "gap%g.step" % gap)
        step_face(path, [SQUARE, ("circle", 0.7, 0.5, r)])
        exact = 1 - math.pi * r * r
        bound = {1: math.pi * r * r * (1 - math.sin(T) / T),
                 4: 2 * math.pi * r * r * T ** 5 / (2 ** 5 * math.factorial(5))}
        for order in (1, 4):
            p = run(["triangulate", path, "--order", str(order)])
            if p is None:
                continue
            m = re.search(r"(\d+) triangles of order \d+, min angle [-0-9.]+ deg, min scaled "
                          r"Jacobian ([-0-9.e+]+), area ([-0-9.e+]+)", p.stdout)
            if p.returncode != 0 or not m:
                fails.append("gap %g, order %d: exit %d: %s" % (gap, order, p.returncode,
                                                                p.stderr.strip()))
                continue
            jac, area = float(m.group(2)), float(m.group(3))
            if not jac > 0 or abs(area - exact) > bound[order]:
                fails.append("gap %g, order %d: min scaled Jacobian %g, area %.12g, expected > 0 "
                             "and %.12g within %.3g" % (gap, order, jac, area, exact, bound[order]))
    path = os.path.join(tmp, "tangent.step")
    step_face(path, [SQUARE, ("circle", 0.7, 0.5, 0.3)])
    p = run(["mesh", path, "-q", "-o", os.path.join(tmp, "o.msh")])
    if p is not None:
        err = [ln for ln in p.stderr.splitlines() if ln.strip()]
        if p.returncode != 4 or len(err) != 1 or os.path.exists(os.path.join(tmp, "o.msh")):
            fails.append("tangent hole: exit %d, stderr %r, expected 4 and one line" %
                         (p.returncode, err))
    n = 155
    wobbly = [(0.5 * (1 + 0.1 * math.sin(6 * math.pi * k / n)) * math.cos(2 * math.pi * k / n),
               0.5 * (1 + 0.1 * math.sin(6 * math.pi * k / n)) * math.sin(2 * math.pi * k / n))
              for k in range(n)]
    path = os.path.join(tmp, "wobbly.step")
    step_face(path, [wobbly])
    p = run(["field", path], timeout=120)
    if p is not None:
        m = re.search(r"on (\d+) triangles", p.stdout)
        if p.returncode != 0 or not m or int(m.group(1)) >= 20 * n:
            fails.append("wobbly %d-gon: exit %d, %s, expected under %d triangles" % (
                n, p.returncode, m.group(0) if m else p.stderr.strip(), 20 * n))

for msg in fails:
    print(msg)
sys.exit(1 if fails else 0)
