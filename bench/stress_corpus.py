#!/usr/bin/python3
"""Seeded generator of random planar faces, one STEP file per face (issue 14's stress corpus).

usage: /usr/bin/python3 bench/stress_corpus.py OUTDIR [--seed S] [--count N]
                                               [--ids 0,7,12] [--classes holes,sliver]

Writes OUTDIR/NNNN_CLASS.step and OUTDIR/manifest.json (one entry per face: id, file,
class, the parameters that make the face hostile, the expected area and whether the
written file reads back as the face that was built).  Face i is drawn from a random
generator seeded with (S, i) alone, so any subset (--ids) is the same faces a full
run writes, on every machine: only Python's `random` (Mersenne Twister, string seed)
and OpenCASCADE's arithmetic are involved; a face's file is the same bytes whatever
else is written with it.

Classes (face i has class CLASSES[i % len(CLASSES)]), all built at unit size in the
plane z = 0 and checked there (OpenCASCADE's default tolerance, 1e-7, forbids building
smaller):
  polygon       star-shaped polygon, 3-24 corners, acute and reflex
  orthogonal    rectilinear skyline polygon (90 and 270 degree corners)
  arcs          polygon with circular edges bulging in or out
  bspline       polygon with wavy cubic B-spline edges
  fillet        polygon with tangent circular fillets at convex and reflex corners
  holes         outline with 1-10 holes: circles, polygons, slots
  plate         filleted rectilinear outline with holes and slots (machined plates)
  tiny_edge     a corner cut by an edge 1e-6 to 1e-2 of the size
  near_tangent  a hole 1e-6 to 1e-2 (of the size) from the outline or from another hole
  sliver        rectangles, parallelograms, thin rings, aspect 10 to 1e6
  needle        triangles and spikes with an angle 0.01 to 1 degree
  near_180      polygon with corners of 180 +- (1e-4 .. 1) degrees
  many_sided    polygon or circle-like outline of 50-500 short edges
  tilted        any of the above but the extremes, rotated out of z = 0 and moved
  scaled        any of the above but the extremes, scaled by 10^k, k = -6..6 (in the
                STEP text: see scale_step; at 1e-6 the file's own 1e-7 tolerance can
                merge corners, and the manifest says so when the area read back differs)
  invalid       not a valid face, to be refused: self-intersecting outline, a hole
                crossing the outline, a hole outside it, overlapping holes
"""
import argparse
import json
import math
import os
import random
import re
import sys

import gmsh

CLASSES = ["polygon", "orthogonal", "arcs", "bspline", "fillet", "holes", "plate",
           "tiny_edge", "near_tangent", "sliver", "needle", "near_180", "many_sided",
           "tilted", "scaled", "invalid"]
# classes a tilted or scaled face is drawn from: the extremes stay separate so that
# one failure has one cause
BASE_CLASSES = ["polygon", "orthogonal", "arcs", "bspline", "fillet", "holes", "plate"]


# ------------------------------------------------------------------ 2D geometry
# A loop is {"v": [(x, y), ...], "s": [seg, ...]} with segment k from v[k] to
# v[k+1]; a segment is {"t": "line"}, {"t": "arc", "c": (x, y), "ccw": bool} or
# {"t": "bspline", "ctrl": [(x, y), ...]} (interior control points).  A full
# circle is {"circle": (x, y, r)}.  Outer loops run counter-clockwise.

def line_loop(pts):
    return {"v": list(pts), "s": [{"t": "line"} for _ in pts]}


def star_polygon(rng, n, rmin=0.25, jitter=0.375):
    """Star-shaped polygon around the origin, simple by construction: corner k at a
    random radius in [rmin, 1] and angle 2 pi (k + 1/2 + U(-jitter, jitter)) / n."""
    rot = rng.uniform(0, 2 * math.pi)
    pts = []
    for k in range(n):
        a = rot + 2 * math.pi * (k + 0.5 + rng.uniform(-jitter, jitter)) / n
        r = rng.uniform(rmin, 1.0)
        pts.append((r * math.cos(a), r * math.sin(a)))
    return pts


def skyline(rng, cols):
    """Rectilinear polygon: columns of random heights above and below y = 0."""
    xs = sorted(rng.sample(range(1, 40), cols - 1))
    xs = [0] + xs + [40]
    top = [rng.randint(4, 20) for _ in range(cols)]
    bot = [-rng.randint(0, 12) for _ in range(cols)]
    pts = []
    for k in range(cols):  # bottom, left to right
        pts += [(xs[k], bot[k]), (xs[k + 1], bot[k])]
    for k in reversed(range(cols)):  # top, right to left
        pts += [(xs[k + 1], top[k]), (xs[k], top[k])]
    out = []
    for p in pts:  # drop repeated points and collinear middles
        if out and out[-1] == p:
            continue
        out.append(p)
    if out[0] == out[-1]:
        out.pop()
    simp = []
    n = len(out)
    for k in range(n):
        a, b, c = out[k - 1], out[k], out[(k + 1) % n]
        if (b[0] - a[0]) * (c[1] - b[1]) - (b[1] - a[1]) * (c[0] - b[0]) != 0:
            simp.append(b)
    return [(x / 40.0, y / 40.0) for x, y in simp]


def corner_angle(a, b, c):
    """Interior angle at b of a counter-clockwise loop a -> b -> c, degrees."""
    t1 = math.atan2(a[1] - b[1], a[0] - b[0])
    t2 = math.atan2(c[1] - b[1], c[0] - b[0])
    return math.degrees((t1 - t2) % (2 * math.pi))


def corner_stats(pts):
    n = len(pts)
    angs = [corner_angle(pts[k - 1], pts[k], pts[(k + 1) % n]) for k in range(n)]
    lens = [math.dist(pts[k], pts[(k + 1) % n]) for k in range(n)]
    return {"corners": n, "min_angle_deg": round(min(angs), 6),
            "max_angle_deg": round(max(angs), 6),
            "reflex": sum(1 for a in angs if a > 180.0),
            "min_edge": min(lens)}


def bulge_arc(p, q, sag):
    """Arc from p to q with signed sagitta sag (> 0: to the right of p->q, i.e. outwards
    of a counter-clockwise loop)."""
    c = math.dist(p, q) / 2
    r = (c * c + sag * sag) / (2 * abs(sag))
    mx, my = (p[0] + q[0]) / 2, (p[1] + q[1]) / 2
    nx, ny = (q[1] - p[1]) / (2 * c), -(q[0] - p[0]) / (2 * c)  # right normal
    off = r - abs(sag)  # centre on the side opposite the bulge
    s = -1 if sag > 0 else 1
    return {"t": "arc", "c": (mx + s * off * nx, my + s * off * ny), "ccw": sag > 0}


def fillet_loop(pts, rng, frac_range, which):
    """Replace the corners in `which` by tangent arcs (radius from frac_range of the
    shorter adjacent edge's half); returns the new loop and the radii used."""
    n = len(pts)
    lens = [math.dist(pts[k], pts[(k + 1) % n]) for k in range(n)]
    v, s, radii = [], [], []
    for k in range(n):
        a, b, c = pts[k - 1], pts[k], pts[(k + 1) % n]
        if k not in which:
            v.append(b)
            s.append({"t": "line"})
            continue
        th = math.radians(corner_angle(a, b, c))
        half = th / 2 if th < math.pi else (2 * math.pi - th) / 2
        t = rng.uniform(*frac_range) * 0.5 * min(lens[k - 1], lens[k])
        d1 = ((a[0] - b[0]) / lens[k - 1], (a[1] - b[1]) / lens[k - 1])
        d2 = ((c[0] - b[0]) / lens[k], (c[1] - b[1]) / lens[k])
        r = t * math.tan(half)
        bis = (d1[0] + d2[0], d1[1] + d2[1])
        bl = math.hypot(*bis)
        h = r / math.sin(half)
        cen = (b[0] + h * bis[0] / bl, b[1] + h * bis[1] / bl)
        v += [(b[0] + t * d1[0], b[1] + t * d1[1]), (b[0] + t * d2[0], b[1] + t * d2[1])]
        s += [{"t": "arc", "c": cen, "ccw": th < math.pi}, {"t": "line"}]
        radii.append(r)
    return {"v": v, "s": s}, radii


def circle(x, y, r):
    return {"circle": (x, y, r)}


def regular_polygon(x, y, r, n, rot, ccw=True):
    pts = [(x + r * math.cos(rot + 2 * math.pi * k / n), y + r * math.sin(rot + 2 * math.pi * k / n))
           for k in range(n)]
    return line_loop(pts if ccw else pts[::-1])


def slot(x, y, half_len, r, rot):
    """Stadium (slot) centred at (x, y): two straight edges, two half circles."""
    cx, cy = math.cos(rot), math.sin(rot)
    nx, ny = -cy, cx
    e1 = (x + half_len * cx, y + half_len * cy)
    e0 = (x - half_len * cx, y - half_len * cy)
    v = [(e0[0] - r * nx, e0[1] - r * ny), (e1[0] - r * nx, e1[1] - r * ny),
         (e1[0] + r * nx, e1[1] + r * ny), (e0[0] + r * nx, e0[1] + r * ny)]
    s = [{"t": "line"}, {"t": "arc", "c": e1, "ccw": True},
         {"t": "line"}, {"t": "arc", "c": e0, "ccw": True}]
    return {"v": v, "s": s}


def reverse(loop):
    """The same loop run the other way (holes run clockwise)."""
    if "circle" in loop:
        return loop
    n = len(loop["v"])
    v = [loop["v"][0]] + loop["v"][:0:-1]
    s = []
    for k in range(n):  # new segment k goes v'[k] -> v'[k+1] = old segment n-1-k reversed
        old = dict(loop["s"][n - 1 - k])
        if old["t"] == "arc":
            old["ccw"] = not old["ccw"]
        if old["t"] == "bspline":
            old["ctrl"] = old["ctrl"][::-1]
        s.append(old)
    return {"v": v, "s": s}


# sampled polylines, only to check a face is valid before writing it
def sample_loop(loop, per_arc=48):
    if "circle" in loop:
        x, y, r = loop["circle"]
        m = 2 * per_arc
        return [(x + r * math.cos(2 * math.pi * k / m), y + r * math.sin(2 * math.pi * k / m))
                for k in range(m)]
    out = []
    n = len(loop["v"])
    for k in range(n):
        p, q, seg = loop["v"][k], loop["v"][(k + 1) % n], loop["s"][k]
        out.append(p)
        if seg["t"] == "arc":
            cx, cy = seg["c"]
            r = math.dist(p, seg["c"])
            a0 = math.atan2(p[1] - cy, p[0] - cx)
            a1 = math.atan2(q[1] - cy, q[0] - cx)
            da = (a1 - a0) % (2 * math.pi) if seg["ccw"] else -((a0 - a1) % (2 * math.pi))
            out += [(cx + r * math.cos(a0 + da * j / per_arc), cy + r * math.sin(a0 + da * j / per_arc))
                    for j in range(1, per_arc)]
        elif seg["t"] == "bspline":
            out += bspline_points([p] + seg["ctrl"] + [q], per_arc)
    return out


def bspline_points(ctrl, m):
    """Interior points of the clamped uniform cubic B-spline of control points ctrl
    (the curve gmsh's addBSpline makes), by de Boor's algorithm."""
    deg = 3
    n = len(ctrl)
    nk = n - deg  # number of knot spans + 1
    knots = [0.0] * deg + [k / nk for k in range(nk + 1)] + [1.0] * deg
    pts = []
    for j in range(1, m):
        u = j / m
        span = min(deg + int(u * nk), n - 1)
        d = [list(ctrl[span - deg + i]) for i in range(deg + 1)]
        for r in range(1, deg + 1):
            for i in range(deg, r - 1, -1):
                lo = knots[span - deg + i]
                hi = knots[span + 1 + i - r]
                al = (u - lo) / (hi - lo) if hi > lo else 0.0
                d[i] = [(1 - al) * d[i - 1][0] + al * d[i][0], (1 - al) * d[i - 1][1] + al * d[i][1]]
        pts.append(tuple(d[deg]))
    return pts


def seg_cross(p1, p2, q1, q2):
    def orient(a, b, c):
        return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
    d1, d2 = orient(q1, q2, p1), orient(q1, q2, p2)
    d3, d4 = orient(p1, p2, q1), orient(p1, p2, q2)
    return d1 * d2 < 0 and d3 * d4 < 0


def shoelace(poly):
    return 0.5 * sum(poly[k - 1][0] * poly[k][1] - poly[k][0] * poly[k - 1][1] for k in range(len(poly)))


def inside(pt, poly):
    x, y = pt
    c = False
    for k in range(len(poly)):
        (x1, y1), (x2, y2) = poly[k - 1], poly[k]
        if (y1 > y) != (y2 > y) and x < x1 + (y - y1) * (x2 - x1) / (y2 - y1):
            c = not c
    return c


def polylines_valid(polys):
    """No two edges of the sampled loops cross (neighbours in a loop excepted), every
    hole inside the outline and outside the other holes."""
    segs = []
    for li, poly in enumerate(polys):
        n = len(poly)
        for k in range(n):
            p, q = poly[k], poly[(k + 1) % n]
            segs.append((li, k, n, p, q, min(p[0], q[0]), max(p[0], q[0]), min(p[1], q[1]), max(p[1], q[1])))
    segs.sort(key=lambda s: s[5])
    for i, a in enumerate(segs):
        for b in segs[i + 1:]:
            if b[5] > a[6]:
                break
            if b[7] > a[8] or a[7] > b[8]:
                continue
            if a[0] == b[0] and ((a[1] - b[1]) % a[2] in (1, a[2] - 1)):
                continue
            if seg_cross(a[3], a[4], b[3], b[4]):
                return False
    for li, poly in enumerate(polys[1:], 1):
        if not inside(poly[0], polys[0]):
            return False
        if any(inside(poly[0], other) for lj, other in enumerate(polys[1:], 1) if lj != li):
            return False
    return True


def loops_area(loops):
    polys = [sample_loop(lp, 400) for lp in loops]
    return abs(shoelace(polys[0])) - sum(abs(shoelace(p)) for p in polys[1:]), polys


# ------------------------------------------------------------------ the classes
def outline(rng, kind=None):
    """A random outline (counter-clockwise loop) of one of the simple kinds."""
    kind = kind or rng.choice(["rect", "star", "skyline", "round"])
    if kind == "rect":
        w, h = 1.0, rng.uniform(0.3, 1.0)
        return line_loop([(-w / 2, -h / 2), (w / 2, -h / 2), (w / 2, h / 2), (-w / 2, h / 2)]), kind
    if kind == "star":
        return line_loop(star_polygon(rng, rng.randint(5, 9), rmin=0.6)), kind
    if kind == "skyline":
        return line_loop(skyline(rng, rng.randint(2, 4))), kind
    return circle(0.0, 0.0, 0.5), kind


def make_polygon(rng):
    pts = star_polygon(rng, rng.randint(3, 24))
    return [line_loop(pts)], corner_stats(pts)


def make_orthogonal(rng):
    pts = skyline(rng, rng.randint(2, 8))
    return [line_loop(pts)], corner_stats(pts)


def make_arcs(rng):
    pts = star_polygon(rng, rng.randint(3, 12), rmin=0.5)
    loop = line_loop(pts)
    n = len(pts)
    k_arcs = rng.randint(1, n)
    for k in rng.sample(range(n), k_arcs):
        chord = math.dist(pts[k], pts[(k + 1) % n])
        loop["s"][k] = bulge_arc(pts[k], pts[(k + 1) % n], rng.choice([-1, 1]) * rng.uniform(0.05, 0.4) * chord)
    return [loop], {"corners": n, "arcs": k_arcs}


def make_bspline(rng):
    pts = star_polygon(rng, rng.randint(3, 8), rmin=0.6)
    loop = line_loop(pts)
    n = len(pts)
    k_sp = rng.randint(1, min(3, n))
    amp = rng.uniform(0.02, 0.2)
    ncp = rng.randint(2, 10)
    for k in rng.sample(range(n), k_sp):
        p, q = pts[k], pts[(k + 1) % n]
        L = math.dist(p, q)
        nx, ny = (q[1] - p[1]) / L, -(q[0] - p[0]) / L
        ctrl = []
        for j in range(1, ncp + 1):
            t = j / (ncp + 1)
            o = rng.uniform(-amp, amp) * L
            ctrl.append((p[0] + t * (q[0] - p[0]) + o * nx, p[1] + t * (q[1] - p[1]) + o * ny))
        loop["s"][k] = {"t": "bspline", "ctrl": ctrl}
    return [loop], {"corners": n, "bsplines": k_sp, "amplitude": round(amp, 4), "control_points": ncp}


def make_fillet(rng):
    if rng.random() < 0.5:
        pts, kind = star_polygon(rng, rng.randint(3, 12), rmin=0.4), "star"
    else:
        pts, kind = skyline(rng, rng.randint(2, 6)), "skyline"
    n = len(pts)
    which = set(rng.sample(range(n), rng.randint(1, n)))
    loop, radii = fillet_loop(pts, rng, (0.1, 0.95), which)
    return [loop], {"outline": kind, "corners": n, "fillets": len(which),
                    "min_radius": round(min(radii), 6)}


def place_holes(rng, outer_poly, count, rmax, margin, kinds):
    """Up to `count` holes at random places, each `margin` clear of the outline and of
    the other holes (rejection sampling on the sampled loops)."""
    xs = [p[0] for p in outer_poly]
    ys = [p[1] for p in outer_poly]
    holes, discs, kinds_used = [], [], []
    for _ in range(count):
        for _try in range(60):
            r = rng.uniform(0.15, 1.0) * rmax
            c = (rng.uniform(min(xs), max(xs)), rng.uniform(min(ys), max(ys)))
            kind = rng.choice(kinds)
            reach = 2.2 * r if kind == "slot" else r
            if not inside(c, outer_poly):
                continue
            if min(dist_point_poly(c, outer_poly), 1e9) < reach + margin:
                continue
            if any(math.dist(c, d[0]) < reach + d[1] + margin for d in discs):
                continue
            if kind == "circle":
                h = circle(c[0], c[1], r)
            elif kind == "polygon":
                h = reverse(regular_polygon(c[0], c[1], r, rng.randint(3, 8), rng.uniform(0, math.pi)))
            else:
                h = reverse(slot(c[0], c[1], 1.2 * r, r * rng.uniform(0.3, 0.8), rng.uniform(0, math.pi)))
            holes.append(h)
            discs.append((c, reach))
            kinds_used.append(kind)
            break
    return holes, kinds_used


def dist_point_poly(c, poly):
    best = float("inf")
    for k in range(len(poly)):
        best = min(best, dist_point_seg(c, poly[k - 1], poly[k]))
    return best


def dist_point_seg(c, p, q):
    dx, dy = q[0] - p[0], q[1] - p[1]
    L2 = dx * dx + dy * dy
    t = 0.0 if L2 == 0 else max(0.0, min(1.0, ((c[0] - p[0]) * dx + (c[1] - p[1]) * dy) / L2))
    return math.dist(c, (p[0] + t * dx, p[1] + t * dy))


def make_holes(rng):
    outer, kind = outline(rng)
    want = rng.randint(1, 10)
    holes, used = place_holes(rng, sample_loop(outer), want, rng.uniform(0.05, 0.2),
                              rng.uniform(0.01, 0.05), ["circle", "polygon", "slot"])
    return [outer] + holes, {"outline": kind, "holes": len(holes), "hole_kinds": used}


def make_plate(rng):
    pts = skyline(rng, rng.randint(1, 4)) if rng.random() < 0.6 else \
        [(-0.5, -0.3), (0.5, -0.3), (0.5, 0.3), (-0.5, 0.3)]
    n = len(pts)
    which = set(k for k in range(n) if rng.random() < 0.7)
    outer, radii = fillet_loop(pts, rng, (0.05, 0.4), which)
    holes, used = place_holes(rng, sample_loop(outer), rng.randint(0, 10), rng.uniform(0.03, 0.1),
                              rng.uniform(0.01, 0.04), ["circle", "circle", "slot"])
    return [outer] + holes, {"corners": n, "fillets": len(which), "holes": len(holes), "hole_kinds": used}


def make_tiny_edge(rng):
    eps = 10 ** rng.uniform(-6, -2)
    if rng.random() < 0.5:  # a corner of a polygon cut off by an edge of length eps
        pts = star_polygon(rng, rng.randint(4, 10), rmin=0.5)
        kind = "star"
    else:
        pts = [(-0.5, -0.5), (0.5, -0.5), (0.5, 0.5), (-0.5, 0.5)]
        kind = "square"
    k = rng.randrange(len(pts))
    a, b, c = pts[k - 1], pts[k], pts[(k + 1) % len(pts)]
    # cut points on both edges so that the new edge has length eps
    th = math.radians(corner_angle(a, b, c))
    t = eps / (2 * math.sin(th / 2)) if th < math.pi else eps / (2 * math.sin((2 * math.pi - th) / 2))
    p = (b[0] + t * (a[0] - b[0]) / math.dist(a, b), b[1] + t * (a[1] - b[1]) / math.dist(a, b))
    q = (b[0] + t * (c[0] - b[0]) / math.dist(c, b), b[1] + t * (c[1] - b[1]) / math.dist(c, b))
    new = pts[:k] + [p, q] + pts[k + 1:]
    return [line_loop(new)], {"outline": kind, "tiny_edge": eps, "corners": len(new)}


def make_near_tangent(rng):
    gap = 10 ** rng.uniform(-6, -2)
    mode = rng.choice(["hole_to_edge", "hole_to_hole", "eccentric_ring", "hole_to_arc"])
    if mode == "hole_to_edge":  # a circle `gap` above the bottom edge of a rectangle
        r = rng.uniform(0.05, 0.3)
        outer = line_loop([(-0.5, 0.0), (0.5, 0.0), (0.5, 0.8), (-0.5, 0.8)])
        return [outer, circle(rng.uniform(-0.4 + r, 0.4 - r), r + gap, r)], {"mode": mode, "gap": gap, "radius": r}
    if mode == "hole_to_hole":
        r1, r2 = rng.uniform(0.05, 0.2), rng.uniform(0.05, 0.2)
        outer = line_loop([(-0.6, -0.5), (0.6, -0.5), (0.6, 0.5), (-0.6, 0.5)])
        a = rng.uniform(0, math.pi)
        d = r1 + r2 + gap
        c1 = (-d / 2 * math.cos(a), -d / 2 * math.sin(a))
        c2 = (d / 2 * math.cos(a), d / 2 * math.sin(a))
        return [outer, circle(*c1, r1), circle(*c2, r2)], {"mode": mode, "gap": gap}
    if mode == "eccentric_ring":  # inner circle `gap` from the outer one
        ri = rng.uniform(0.1, 0.45)
        return [circle(0, 0, 0.5), circle(0.5 - ri - gap, 0, ri)], {"mode": mode, "gap": gap, "radius": ri}
    # a circle inside a quarter-disc-like outline, near its arc: outline = sector
    R = 1.0
    ri = rng.uniform(0.05, 0.2)
    a = math.radians(45)
    cen = ((R - ri - gap) * math.cos(a), (R - ri - gap) * math.sin(a))
    outer = {"v": [(0, 0), (R, 0), (0, R)], "s": [{"t": "line"}, {"t": "arc", "c": (0, 0), "ccw": True}, {"t": "line"}]}
    return [outer, circle(*cen, ri)], {"mode": mode, "gap": gap, "radius": ri}


def make_sliver(rng):
    ar = 10 ** rng.uniform(1, 6)
    mode = rng.choice(["rectangle", "parallelogram", "ring", "curved_strip"])
    h = 1.0 / ar
    if mode == "rectangle":
        loops = [line_loop([(0, 0), (1, 0), (1, h), (0, h)])]
    elif mode == "parallelogram":
        sk = rng.uniform(0.05, 0.5)
        loops = [line_loop([(0, 0), (1, 0), (1 + sk, h), (sk, h)])]
    elif mode == "ring":  # thin annulus: aspect = circumference / width
        w = 2 * math.pi * 0.5 / ar
        loops = [circle(0, 0, 0.5), circle(0, 0, 0.5 - w)]
    else:  # a quarter of a thin ring: two arcs, two short lines
        w = 0.5 * math.pi / 2 / ar
        ro, ri = 0.5, 0.5 - w
        loops = [{"v": [(ri, 0), (ro, 0), (0, ro), (0, ri)],
                  "s": [{"t": "line"}, {"t": "arc", "c": (0, 0), "ccw": True},
                        {"t": "line"}, {"t": "arc", "c": (0, 0), "ccw": False}]}]
    return loops, {"mode": mode, "aspect": ar}


def make_needle(rng):
    alpha = 10 ** rng.uniform(-2, 0)  # degrees
    if rng.random() < 0.5:  # isoceles-ish triangle with apex angle alpha
        L = 1.0
        b = rng.uniform(0.2, 0.8)
        a = math.radians(alpha)
        pts = [(0, 0), (L, -L * math.tan(a) * b), (L, L * math.tan(a) * (1 - b))]
        return [line_loop(pts)], {"mode": "triangle", "angle_deg": alpha}
    # a square with a needle spike of angle alpha on its top edge
    a = math.radians(alpha)
    w = 0.5 * math.tan(a / 2)
    pts = [(-0.5, -0.5), (0.5, -0.5), (0.5, 0.0), (w, 0.0), (0.0, 0.5), (-w, 0.0), (-0.5, 0.0)]
    return [line_loop(pts)], {"mode": "spike", "angle_deg": alpha}


def make_near_180(rng):
    pts = star_polygon(rng, rng.randint(3, 8), rmin=0.5)
    n = len(pts)
    new = []
    devs = []
    for k in range(n):  # split some edges at a point pushed off by a tiny turn
        p, q = pts[k], pts[(k + 1) % n]
        new.append(p)
        if rng.random() < 0.6 or k == 0:
            dev = rng.choice([-1, 1]) * 10 ** rng.uniform(-4, 0)  # degrees of turn
            t = rng.uniform(0.3, 0.7)
            L = math.dist(p, q)
            off = math.tan(math.radians(dev) / 2) * L * min(t, 1 - t)
            nx, ny = (q[1] - p[1]) / L, -(q[0] - p[0]) / L
            new.append((p[0] + t * (q[0] - p[0]) + off * nx, p[1] + t * (q[1] - p[1]) + off * ny))
            devs.append(dev)
    return [line_loop(new)], {"corners": len(new), "near_180": len(devs),
                              "min_turn_deg": min(abs(d) for d in devs)}


def make_many_sided(rng):
    n = rng.randint(50, 500)
    if rng.random() < 0.5:  # polygon inscribed in a wobbly circle
        pts = [(0.5 * (1 + 0.1 * math.sin(3 * 2 * math.pi * k / n)) * math.cos(2 * math.pi * k / n),
                0.5 * (1 + 0.1 * math.sin(3 * 2 * math.pi * k / n)) * math.sin(2 * math.pi * k / n))
               for k in range(n)]
        return [line_loop(pts)], {"mode": "wobbly", "corners": n}
    pts = star_polygon(rng, n, rmin=0.85)
    return [line_loop(pts)], corner_stats(pts) | {"mode": "star"}


INVALID_MODES = {"bowtie": "the outline crosses itself",
                 "hole_crossing": "a hole crosses the outline",
                 "hole_outside": "a hole lies outside the outline",
                 "holes_overlap": "two holes overlap"}


def make_invalid(rng):
    mode = rng.choice(sorted(INVALID_MODES))
    rect = line_loop([(-0.5, -0.3), (0.5, -0.3), (0.5, 0.3), (-0.5, 0.3)])
    r = rng.uniform(0.08, 0.2)
    if mode == "bowtie":  # a star polygon with two non-adjacent corners swapped
        pts = star_polygon(rng, rng.randint(5, 9), rmin=0.6)
        k = rng.randrange(len(pts))
        j = (k + 2) % len(pts)
        pts[k], pts[j] = pts[j], pts[k]
        return [line_loop(pts)], {"mode": mode}
    if mode == "hole_crossing":
        return [rect, circle(rng.uniform(-0.3, 0.3), 0.3, r)], {"mode": mode, "radius": r}
    if mode == "hole_outside":
        return [rect, circle(rng.uniform(-0.3, 0.3), 0.35 + r, r)], {"mode": mode, "radius": r}
    return [rect, circle(-0.5 * r, 0, r), circle(0.5 * r, 0, r)], {"mode": mode, "radius": r}


MAKERS = {"polygon": make_polygon, "orthogonal": make_orthogonal, "arcs": make_arcs,
          "bspline": make_bspline, "fillet": make_fillet, "holes": make_holes,
          "plate": make_plate, "tiny_edge": make_tiny_edge, "near_tangent": make_near_tangent,
          "sliver": make_sliver, "needle": make_needle, "near_180": make_near_180,
          "many_sided": make_many_sided, "invalid": make_invalid}


def draw(seed, i):
    """The face i of seed: (class, loops, params, transform)."""
    rng = random.Random("%d:%d" % (seed, i))
    cls = CLASSES[i % len(CLASSES)]
    base = cls
    transform = {}
    if cls in ("tilted", "scaled"):
        base = rng.choice(BASE_CLASSES)
        if cls == "tilted":
            ax = [rng.gauss(0, 1) for _ in range(3)]
            transform = {"rotate_axis": ax, "rotate_deg": rng.uniform(5, 175),
                         "translate": [rng.uniform(-5, 5) for _ in range(3)]}
        else:
            transform = {"scale": 10.0 ** rng.randint(-6, 6)}
    for attempt in range(50):
        loops, params = MAKERS[base](rng)
        area, polys = loops_area(loops)
        # near-tangent faces are valid by construction; their gaps are below the
        # sampling's chord error, so the sampled check would see false crossings
        if base in ("near_tangent", "invalid") or polylines_valid(polys):
            break
    else:
        raise RuntimeError("face %d: no valid %s face in 50 draws" % (i, base))
    if base != cls:
        params = dict(params, base_class=base)
    return cls, loops, params, transform, area


# ------------------------------------------------------------------ gmsh/OCC
def build_loop(occ, loop):
    """Curve loop tag of a loop (arcs through addCircle, whose end points OCC's wire
    builder merges with the lines' coincident ones)."""
    if "circle" in loop:
        x, y, r = loop["circle"]
        return occ.addCurveLoop([occ.addCircle(x, y, 0, r)])
    pts = [occ.addPoint(x, y, 0) for x, y in loop["v"]]
    n = len(pts)
    curves = []
    for k in range(n):
        p, q, seg = loop["v"][k], loop["v"][(k + 1) % n], loop["s"][k]
        if seg["t"] == "line":
            curves.append(occ.addLine(pts[k], pts[(k + 1) % n]))
        elif seg["t"] == "bspline":
            ctrl = [occ.addPoint(x, y, 0) for x, y in seg["ctrl"]]
            curves.append(occ.addBSpline([pts[k]] + ctrl + [pts[(k + 1) % n]], degree=3))
        else:
            cx, cy = seg["c"]
            r = 0.5 * (math.dist(p, seg["c"]) + math.dist(q, seg["c"]))
            a0 = math.atan2(p[1] - cy, p[0] - cx)
            a1 = math.atan2(q[1] - cy, q[0] - cx)
            if seg["ccw"]:
                a1 = a0 + (a1 - a0) % (2 * math.pi)
                curves.append(occ.addCircle(cx, cy, 0, r, angle1=a0, angle2=a1))
            else:
                a0 = a1 + (a0 - a1) % (2 * math.pi)
                curves.append(-occ.addCircle(cx, cy, 0, r, angle1=a1, angle2=a0))
    return occ.addCurveLoop(curves)


class _Quiet:
    """OpenCASCADE's STEP writer prints its statistics on the C stdout."""
    def __enter__(self):
        sys.stdout.flush()
        self.fd = os.dup(1)
        nul = os.open(os.devnull, os.O_WRONLY)
        os.dup2(nul, 1)
        os.close(nul)

    def __exit__(self, *exc):
        os.dup2(self.fd, 1)
        os.close(self.fd)


def write_face(path, loops, transform, autofix=True):
    """Build the face in a fresh model, move it, write it.  autofix=False builds it
    without Gmsh's shape fixing, which would make an invalid face valid: it drops
    the outline of a face whose hole lies outside it and keeps only the disc."""
    occ = gmsh.model.occ
    gmsh.clear()
    tags = [build_loop(occ, lp) for lp in loops]
    gmsh.option.setNumber("Geometry.OCCAutoFix", 1 if autofix else 0)
    try:
        s = occ.addPlaneSurface(tags)
    finally:  # the reader (reread) fixes as before
        gmsh.option.setNumber("Geometry.OCCAutoFix", 1)
    if "rotate_axis" in transform:
        ax = transform["rotate_axis"]
        occ.rotate([(2, s)], 0, 0, 0, ax[0], ax[1], ax[2], math.radians(transform["rotate_deg"]))
        occ.translate([(2, s)], *transform["translate"])
    occ.synchronize()
    # keep the face and what bounds it, not the construction points
    keep = set(gmsh.model.getBoundary([(2, s)], combined=False, oriented=False, recursive=True))
    keep |= set(e for c in gmsh.model.getBoundary([(2, s)], combined=False, oriented=False)
                for e in gmsh.model.getBoundary([c], combined=False, oriented=False))
    for dim in (1, 0):  # curves first: a point a curve still uses is not removed
        extra = [e for e in gmsh.model.getEntities(dim) if e not in keep]
        if extra:
            occ.remove(extra)
            occ.synchronize()
    with _Quiet():
        gmsh.write(path)
    with open(path) as f:
        text = f.read()
    if "scale" in transform:
        text = scale_step(text, transform["scale"])
    with open(path, "w") as f:
        f.write(stable_header(text, os.path.basename(path)[:-5]))


def stable_header(text, name):
    """The same bytes for the same face: OCCT's writer stamps the time and numbers
    its products by the count of files written in the session."""
    text = re.sub(r"FILE_NAME\('[^']*',\s*'[^']*'", "FILE_NAME('%s.step','2000-01-01T00:00:00'" % name, text, count=1)
    return re.sub(r"'Open CASCADE STEP translator ([0-9.]+) [0-9]+'", "'%s'" % name, text)


_NUM = r"[-+]?[0-9.]+(?:E[-+]?[0-9]+)?"


def scale_step(text, f):
    """The STEP text of the same face scaled by f.  gmsh's dilate cannot do this: it
    goes through BRepBuilderAPI_GTransform, which turns the plane and the circles into
    B-splines.  Every length of the file is a point's coordinate, a circle's radius
    or a vector's magnitude (the lines' directions); a plane's parameters are
    lengths too, so the same rule scales the edges' pcurves.  The uncertainty (1e-7)
    stays: a CAD system writes its own fixed tolerance whatever the part's size."""
    def num(m):
        return "%.15E" % (float(m.group(0)) * f)

    def coords(m):
        return m.group(1) + re.sub(_NUM, num, m.group(2)) + m.group(3)

    def last(m):
        return m.group(1) + num(re.match(_NUM, m.group(2))) + m.group(3)

    text = re.sub(r"(CARTESIAN_POINT\('[^']*',\()([^)]*)(\))", coords, text)
    return re.sub(r"((?:VECTOR|CIRCLE)\('[^']*',\s*#\d+,\s*)(" + _NUM + r")(\s*\))", last, text)


def reread(path):
    """(faces, area) of the written file as OCC reads it back."""
    gmsh.clear()
    try:
        with _Quiet():
            ents = gmsh.model.occ.importShapes(path)
        gmsh.model.occ.synchronize()
    except Exception as e:  # noqa: BLE001 (gmsh raises plain Exception)
        return 0, 0.0, str(e)
    faces = [t for d, t in ents if d == 2]
    return len(faces), sum(gmsh.model.occ.getMass(2, t) for t in faces), ""


def generate(outdir, seed=1, ids=None, count=320, classes=None):
    """Write the faces `ids` (default 0..count-1) of `seed` to outdir; returns the
    manifest entries."""
    os.makedirs(outdir, exist_ok=True)
    ids = list(range(count)) if ids is None else ids
    gmsh.initialize(["gmsh", "-v", "0"])
    gmsh.option.setNumber("General.Terminal", 0)
    entries = []
    try:
        for i in ids:
            cls = CLASSES[i % len(CLASSES)]
            if classes and cls not in classes:
                continue
            cls, loops, params, transform, area = draw(seed, i)
            name = "%04d_%s.step" % (i, cls)
            path = os.path.join(outdir, name)
            scale2 = transform.get("scale", 1.0) ** 2
            write_face(path, loops, transform, autofix=cls != "invalid")
            nf, back, err = reread(path)
            # the face is what was drawn if OCC reads back one face of the drawn area
            # (1e-3: the sampling's chord error, (pi/400)^2/6 of an arc's area, is < 1e-5,
            # but OCC's own integral over faces bounded by wavy B-splines is off by up to
            # 2e-4 — faces 131 and 227 of seed 1 — while a feature lost to OCC's 1e-7
            # tolerance changes the area by far more: 10 % for face 62)
            ok = nf == 1 and abs(back - area * scale2) <= 1e-3 * area * scale2 and cls != "invalid"
            e = {"id": i, "file": name, "class": cls, "seed": seed, "params": params,
                 "transform": transform, "area": area * scale2, "reread_area": back, "valid": ok}
            if cls == "invalid":
                e["invalid_reason"] = INVALID_MODES[params["mode"]]
            elif not ok:
                e["invalid_reason"] = err or ("read back %d face(s) of area %.6g, drawn %.6g"
                                              % (nf, back, area * scale2))
            entries.append(e)
    finally:
        gmsh.finalize()
    return entries


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("outdir")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--count", type=int, default=320)
    ap.add_argument("--ids", help="comma-separated face ids (default 0..count-1)")
    ap.add_argument("--classes", help="comma-separated classes to keep")
    a = ap.parse_args()
    ids = [int(x) for x in a.ids.split(",")] if a.ids else None
    classes = set(a.classes.split(",")) if a.classes else None
    entries = generate(a.outdir, a.seed, ids, a.count, classes)
    with open(os.path.join(a.outdir, "manifest.json"), "w") as f:
        json.dump({"seed": a.seed, "classes": CLASSES, "faces": entries}, f, indent=1, sort_keys=True)
    bad = [e for e in entries if not e["valid"]]
    print("%d faces written to %s (%d invalid: drawn so, or not read back as drawn)"
          % (len(entries), a.outdir, len(bad)))
    for e in bad:
        print("  %s: %s" % (e["file"], e["invalid_reason"]))


if __name__ == "__main__":
    main()
