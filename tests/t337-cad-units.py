#!/usr/bin/python3
"""Lengths in the file's unit, read as Gmsh reads them (issue 23: `info` lists
the faces Gmsh's importer lists).

OpenCASCADE's STEP reader heals each face as it reads it, and whether it splits
a sub-tolerance sliver off a face hinges on the round-off of the coordinates,
that is on the unit it converts to (a public part in inch listed one face fewer
than Gmsh when read in inch).  semquad reads STEP in millimetres, as Gmsh does,
and scales the shape to the file's unit.  Checked here, on faces the test writes:

1. a half disc of radius 5/25.4 in an inch STEP file (a rational cubic B-spline
   and a line): unit inch, corners and box at the file's numbers, area pi r^2/2;
2. an inch bowtie, which the reader splits into 2 faces: both still listed
   broken with the reader's reason (found through the scaling);
3. arc length on a curve under a location that a scaling transformed (the
   shape of an assembly read in mm and scaled: its curves are transformed
   under the instance's placement): a BREP made by Gmsh, the half disc of
   radius 5 moved by (1000, 700) (a location) then scaled by 1/25.4 about the
   origin.  Its speeds carry ~1e-14 relative round-off (coordinates near 40
   from a placement of 1000), above the 1e-15 of a piece the arc-length table
   used to require alone: that halved to depth 24 (info took 58 s).  Now info
   answers within the 20 s given here (0.1 s expected).

Tolerances: the inch numbers go through * 25.4 and / 25.4, a few roundings of
1.1e-16 each: 1e-14 of the face's size.  The half disc is exactly a rational
Bezier circle, its area from the arc-length pieces is exact to round-off
(1e-15): 1e-12 relative.  On the located curve (3) Green's theorem sums
x dy with x near 40 along a loop of length 1 for an area of 0.06: a
cancellation of 40 / 0.06 ~ 700 of terms that carry the curve's 1e-14
round-off, ~7e-12 relative: 1e-10.
usage: t337-cad-units.py SEMQUAD"""
import json
import math
import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from step_face import Step, step_face  # noqa: E402 (the tests' own STEP writer)

sq = sys.argv[1]
fails = []
R = 5 / 25.4  # the half disc's radius, inch
HALF = math.pi * R * R / 2


def half_disc(s, c, r):
    """The half disc above y = c[1] of centre c and radius r, as a rational
    cubic Bezier (a circle exactly) and a line."""
    x0, x1, y0 = c[0] - r, c[0] + r, c[1]
    return s.bspline_loop([(x0, y0), (x0, y0 + 2 * r), (x1, y0 + 2 * r), (x1, y0)],
                          weights=[1, 1 / 3, 1 / 3, 1], knots=[0, 30])


def info(path):
    p = subprocess.run([sq, "info", path, "--json", "-q"], capture_output=True, text=True,
                       timeout=20)
    if p.returncode != 0:
        fails.append("%s: info exit %d: %s" % (path, p.returncode, p.stderr.strip()))
        return None
    return json.loads(p.stdout)


def close(name, got, want, tol):
    if not abs(got - want) <= tol:
        fails.append("%s: %.17g, expected %.17g (tolerance %.3g)" % (name, got, want, tol))


with tempfile.TemporaryDirectory() as tmp:
    # 1. the inch half disc
    path = os.path.join(tmp, "half_disc_inch.step")
    s = Step("inch")
    s.write(path, [half_disc(s, (10 / 25.4, 7.5 / 25.4), R)])
    d = info(path)
    if d:
        f = d["faces"][0]
        if d["unit"] != "inch" or len(d["faces"]) != 1 or f["status"] != "ok":
            fails.append("half disc: unit %s, %d faces, status %s" % (d["unit"], len(d["faces"]),
                                                                     f["status"]))
        close("half disc area", f["area"], HALF, 1e-12 * HALF)
        want = [5 / 25.4, 7.5 / 25.4, 15 / 25.4, 7.5 / 25.4 + R]
        for k in range(4):
            close("half disc bbox[%d]" % k, f["bbox"][k], want[k], 1e-14 * 2 * R)
        for c, x in zip(f["corners"], (5 / 25.4, 15 / 25.4)):
            close("half disc corner", c["x"], x, 1e-14 * 2 * R)
    # 2. the inch bowtie: two faces, both broken with the reader's reason
    path = os.path.join(tmp, "bowtie_inch.step")
    step_face(path, [[(0, 0), (1, 1), (1, 0), (0, 1)]], unit="inch")
    d = info(path)
    if d:
        why = [f.get("reason", "") for f in d["faces"] if f["status"] == "broken"]
        if len(d["faces"]) != 2 or len(why) != 2 or not all(
                re.search("the file's face #[0-9]+ has loops that cross", w) for w in why):
            fails.append("bowtie (inch): %d faces, reasons %r" % (len(d["faces"]), why))
    # 3. a located curve, scaled
    try:
        import gmsh
    except ImportError:
        gmsh = None
    if gmsh:
        path = os.path.join(tmp, "located.brep")
        gmsh.initialize()
        gmsh.option.setNumber("General.Terminal", 0)
        occ = gmsh.model.occ
        p = [occ.addPoint(x, y, 0) for x, y in ((5, 7.5), (5, 17.5), (15, 17.5), (15, 7.5))]
        b = occ.addBSpline(p, 3, weights=[1, 1 / 3, 1 / 3, 1], knots=[0, 30],
                           multiplicities=[4, 4])
        srf = occ.addPlaneSurface([occ.addCurveLoop([b, occ.addLine(p[3], p[0])])])
        occ.translate([(2, srf)], 1000, 700, 0)
        occ.dilate([(2, srf)], 0, 0, 0, 1 / 25.4, 1 / 25.4, 1 / 25.4)
        occ.synchronize()
        gmsh.write(path)
        gmsh.finalize()
        try:
            d = info(path)
        except subprocess.TimeoutExpired:
            d = None
            fails.append("located curve: info took more than 20 s")
        if d:
            close("located curve area", d["faces"][0]["area"], HALF, 1e-10 * HALF)

for msg in fails:
    print(msg)
sys.exit(1 if fails else 0)
