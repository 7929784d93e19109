#!/usr/bin/python3
"""Test helper: multi-face 2D domains as STEP files, built with Gmsh's OCC
kernel (python3-gmsh) and fragmented so that faces share their edges:

  circle_square  a disc of radius 0.5 inside the square [-1, 1]^2 (the
                 geometry of NekMesh's real_circle_square.step): two faces
                 sharing the circle;
  three_row      three rectangles [0,1]x[0,1], [1,2.5]x[0,1], [2.5,3]x[0,1]
                 in a row, sharing two straight edges;
  hole_filled    the square [0,2]^2 with an elliptic hole (centre (1,1),
                 semi-axes 0.6, 0.35) filled by the ellipse as a second face;
  sector         one face: 1/8 of the ring 0.5 <= r <= 1 about the origin,
                 0 <= angle <= 45 deg (its radial sides periodic under the
                 rotation by 45 deg, docs/domains.md);
  channel        one face: the channel [0,3]x[0,1] with a round hole (centre
                 (1.2, 0.5), radius 0.25), its walls y = 0 and y = 1
                 periodic under the translation by (0, 1);
  channel_offset the channel with its hole off the centre line (centre
                 (1.2, 0.3), radius 0.2): the layout of its identified
                 domain fails, the face's own layout with slid vertices
                 (route 1b) meshes it;
  sector_hole    one face: the quarter ring 0.5 <= r <= 1, 0 <= angle <=
                 90 deg, less the disc of radius 0.1 about (0.62, 0.3): its
                 radial sides periodic under the rotation by 90 deg, their
                 layout crossings not images of each other (route 1b);
  ring4          the sector's ring cut by the arc r = 0.75 and the ray at
                 22.5 deg into four faces sharing four edges; its two
                 radial sides (two edges each) periodic under the rotation
                 by 45 deg;
  grid_holes     the square [0,2]^2 as four unit squares sharing four edges,
                 each with a round hole of radius 0.25 at its centre.

usage: domain_faces.py NAME OUT.step; prints the exact face areas, one a line."""
import math
import sys

import gmsh


def ring_sector(occ, angle):
    """The face 0.5 <= r <= 1, 0 <= polar angle <= angle (its tag)."""
    p = [occ.addPoint(r * math.cos(a), r * math.sin(a), 0)
         for r, a in ((0.5, 0), (1, 0), (1, angle), (0.5, angle))]
    c = occ.addPoint(0, 0, 0)
    lines = [occ.addLine(p[0], p[1]), occ.addCircleArc(p[1], c, p[2]),
             occ.addLine(p[2], p[3]), occ.addCircleArc(p[3], c, p[0])]
    s = occ.addPlaneSurface([occ.addCurveLoop(lines)])
    occ.remove([(0, c)])
    return s


def build(name):
    occ = gmsh.model.occ
    if name == "circle_square":
        a = occ.addRectangle(-1, -1, 0, 2, 2)
        b = occ.addDisk(0, 0, 0, 0.5, 0.5)
        occ.fragment([(2, a)], [(2, b)])
        return [4 - math.pi * 0.25, math.pi * 0.25]
    if name == "three_row":
        r = [occ.addRectangle(0, 0, 0, 1, 1), occ.addRectangle(1, 0, 0, 1.5, 1),
             occ.addRectangle(2.5, 0, 0, 0.5, 1)]
        occ.fragment([(2, r[0])], [(2, r[1]), (2, r[2])])
        return [1.0, 1.5, 0.5]
    if name == "hole_filled":
        a = occ.addRectangle(0, 0, 0, 2, 2)
        b = occ.addDisk(1, 1, 0, 0.6, 0.35)
        occ.fragment([(2, a)], [(2, b)])
        return [4 - math.pi * 0.6 * 0.35, math.pi * 0.6 * 0.35]
    if name == "sector":
        ring_sector(occ, math.pi / 4)
        return [math.pi / 8 * (1 - 0.25)]
    if name == "ring4":
        occ.addPoint(0, 0, 0, tag=100)
        pt = {(r, k): occ.addPoint(r * math.cos(k * math.pi / 8), r * math.sin(k * math.pi / 8), 0)
              for r in (0.5, 0.75, 1) for k in (0, 1, 2)}
        arc = {(r, k): occ.addCircleArc(pt[r, k], 100, pt[r, k + 1])
               for r in (0.5, 0.75, 1) for k in (0, 1)}
        ray = {(r, k): occ.addLine(pt[r, k], pt[s, k])
               for r, s in ((0.5, 0.75), (0.75, 1)) for k in (0, 1, 2)}
        for k in (0, 1):
            for r, s in ((0.5, 0.75), (0.75, 1)):
                loop = occ.addCurveLoop([ray[r, k], arc[s, k], ray[r, k + 1], arc[r, k]])
                occ.addPlaneSurface([loop])
        occ.remove([(0, 100)])
        return [math.pi / 16 * (s * s - r * r) for k in (0, 1) for r, s in ((0.5, 0.75), (0.75, 1))]
    if name == "grid_holes":
        cells = [occ.cut([(2, occ.addRectangle(i, j, 0, 1, 1))],
                         [(2, occ.addDisk(i + 0.5, j + 0.5, 0, 0.25, 0.25))])[0][0]
                 for j in (0, 1) for i in (0, 1)]
        occ.fragment([cells[0]], cells[1:])
        return [1 - math.pi * 0.0625] * 4
    if name == "channel":
        a = occ.addRectangle(0, 0, 0, 3, 1)
        b = occ.addDisk(1.2, 0.5, 0, 0.25, 0.25)
        occ.cut([(2, a)], [(2, b)])
        return [3 - math.pi * 0.0625]
    if name == "channel_offset":
        a = occ.addRectangle(0, 0, 0, 3, 1)
        b = occ.addDisk(1.2, 0.3, 0, 0.2, 0.2)
        occ.cut([(2, a)], [(2, b)])
        return [3 - math.pi * 0.04]
    if name == "sector_hole":
        s = ring_sector(occ, math.pi / 2)
        occ.cut([(2, s)], [(2, occ.addDisk(0.62, 0.3, 0, 0.1, 0.1))])
        return [math.pi / 4 * (1 - 0.25) - math.pi * 0.01]
    raise SystemExit("unknown domain " + name)


def main():
    gmsh.initialize(["-v", "0"])
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.model.add(sys.argv[1])
    areas = build(sys.argv[1])
    gmsh.model.occ.synchronize()
    gmsh.write(sys.argv[2])
    gmsh.finalize()
    for a in areas:
        print("area %.17g" % a)


if __name__ == "__main__":
    main()
