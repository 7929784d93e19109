#!/usr/bin/python3
"""The project's own stand-ins for the optional real geometries (NekMesh's
T106 cascade and aerofoil box, tests/README.md): two planar faces in metres,
written as STEP text by step_face.py, their blades cubic B-splines
interpolating analytic profiles.

cascade.step: one periodic passage of a turbine cascade.  The blade has a
circular-arc camber line (chord 1 from the leading edge (0, 0), camber-line
angles 20 deg at the leading edge and -65 deg at the trailing edge, so the
stagger is their mean) and the half-thickness (t/2) sin(b) (1 + a cos(b))
at the fraction (1 - cos b)/2 of the arc, b in [0, pi] (an ellipse skewed by
a = 0.5 towards the leading edge; t = 0.2): round at both ends, the
trailing-edge radius of curvature (t (1 - a))^2 / 2 = 0.005.  It is the
hole, two cubic B-splines joined tangentially at mid-chord (no corner).
The passage is bounded by the inlet (x = -1.2), the outlet (x = 2.5) and
two periodic lines one pitch (0.8) apart, each of four segments: along the
inlet flow angle (36 deg) to (0.15, -0.3), horizontal to x = 0.55, along
the outlet flow angle (-65 deg) for a drop of 1.5, horizontal to the
outlet; the upper line passes 0.006 from the blade's suction side, a thin
strip like T106's.  The plane is written with its axis along -z and the
face reversed (as CADfix writes T106).

aerofoil_box.step: the NACA 4412 aerofoil (the 4-digit formula, Abbott &
von Doenhoff, "Theory of Wing Sections", sec. 6.4, with the x^4
coefficient -0.1036 that closes the trailing edge; chord 0.3) in the box
[-0.5, 1.5] x [-0.75, 0.75]; the aerofoil is the hole, two cubic B-splines
(lower, upper) meeting at the leading edge, where the profile is smooth,
and at the trailing-edge corner.

Each B-spline interpolates 121 points of the profile (spaced by arc length
plus turning, so the round ends get their share) with the profile's own
unit tangent at both ends (Piegl & Tiller, "The NURBS Book", sec. 9.2.2):
the two edges of a blade join with one tangent.

usage: cascade_aerofoil.py OUTDIR
writes OUTDIR/cascade.step, OUTDIR/aerofoil_box.step and OUTDIR/NAME.facts
(key value lines: the exact area of the face, from Green's theorem on the
B-splines' polynomial pieces, the chord and the largest spacing of the
interpolated points, the outer corners, the trailing edge), read by the
tests."""
import math
import os
import sys

import numpy as np

sys.dont_write_bytecode = True  # run at build time: nothing written into the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from step_face import Step  # noqa: E402 (the tests' own STEP writer)

POINTS = 121  # interpolated points per B-spline edge

# the cascade: chord 1 from the leading edge (0, 0); camber-line angles at
# the leading and trailing edges; thickness, its skew; pitch; inlet and
# outlet flow angles of the periodic lines, their first kink, the x of the
# second, their drop along the outlet angle; inlet and outlet x
CHI1, CHI2 = math.radians(20.0), math.radians(-65.0)
THICK, SKEW = 0.2, 0.5
PITCH = 0.8
BETA1, BETA2 = math.radians(36.0), math.radians(-65.0)
KINK1, KINK2_X, DROP = (0.15, -0.3), 0.55, 1.5
X_IN, X_OUT = -1.2, 2.5

# the aerofoil box: NACA 4412, chord 0.3
NACA_M, NACA_P, NACA_T, CHORD = 0.04, 0.4, 0.12, 0.3
BOX = (-0.5, -0.75, 1.5, 0.75)


def basis(knots, u, deg=3):
    """Values of every B-spline basis function of the clamped knot vector
    at u (Cox-de Boor; u = the last knot belongs to the last span)."""
    n = len(knots) - deg - 1
    last = u >= knots[-1]
    N = np.array([1.0 if (knots[i] <= u < knots[i + 1]) or
                  (last and knots[i] < knots[i + 1] == knots[-1]) else 0.0
                  for i in range(len(knots) - 1)])
    for d in range(1, deg + 1):
        M = np.zeros(len(knots) - 1 - d)
        for i in range(len(M)):
            a = knots[i + d] - knots[i]
            b = knots[i + d + 1] - knots[i + 1]
            M[i] = ((u - knots[i]) / a * N[i] if a > 0 else 0.0) + \
                   ((knots[i + d + 1] - u) / b * N[i + 1] if b > 0 else 0.0)
        N = M
    return N[:n]


def interpolate(pts, t0, t1):
    """Cubic B-spline through pts (chord-length parameters) with unit end
    tangents t0, t1: (poles, distinct knots, multiplicities, full knots)."""
    pts = np.asarray(pts, dtype=float)
    u = np.concatenate([[0.0], np.cumsum(np.hypot(*np.diff(pts, axis=0).T))])
    full = np.concatenate([[u[0]] * 4, u[1:-1], [u[-1]] * 4])
    n = len(pts)
    P = np.zeros((n + 2, 2))
    P[0], P[-1] = pts[0], pts[-1]
    P[1] = pts[0] + (u[1] - u[0]) / 3 * np.asarray(t0)
    P[-2] = pts[-1] - (u[-1] - u[-2]) / 3 * np.asarray(t1)
    A = np.array([basis(full, uk) for uk in u[1:-1]])
    rhs = pts[1:-1] - A[:, [0, 1, -2, -1]] @ P[[0, 1, -2, -1]]
    P[2:-2] = np.linalg.solve(A[:, 2:-2], rhs)
    return P, list(u), [4] + [1] * (n - 2) + [4], full


def bspline_area(P, full):
    """Integral of (x dy - y dx) / 2 along the B-spline, exact: 4-point
    Gauss-Legendre on every span (the integrand has degree 5)."""
    g, w = np.polynomial.legendre.leggauss(4)
    dP = 3 * (P[1:] - P[:-1]) / (full[4:-1] - full[1:-4])[:, None]
    total = 0.0
    for a, b in zip(full[3:-4], full[4:-3]):
        if b <= a:
            continue
        for gi, wi in zip(g, w):
            uk = 0.5 * (a + b) + 0.5 * (b - a) * gi
            x, y = basis(full, uk) @ P
            dx, dy = basis(full[1:-1], uk, 2) @ dP
            total += 0.5 * (b - a) * wi * 0.5 * (x * dy - y * dx)
    return total


def sample(curve, b0, b1, n=POINTS):
    """n points of curve(b) on [b0, b1], equally spaced in arc length / L
    plus turning / pi; the unit tangents at both ends."""
    b = np.linspace(b0, b1, 20001)
    xy = np.array([curve(bi) for bi in b])
    d = np.diff(xy, axis=0)
    ds = np.hypot(d[:, 0], d[:, 1])
    ang = np.unwrap(np.arctan2(d[:, 1], d[:, 0]))
    turn = np.concatenate([[0.0], np.abs(np.diff(ang))])
    w = np.concatenate([[0.0], np.cumsum(ds / ds.sum() + turn / math.pi)])
    pts = [xy[np.searchsorted(w, s)] for s in np.linspace(0, w[-1], n)[1:-1]]
    return [xy[0]] + pts + [xy[-1]], [tangent(curve, b0, 1), tangent(curve, b1, -1)]


def tangent(curve, b, side):
    """Unit tangent (in the direction of growing b) at the end b of a piece
    lying on side +1 (after b) or -1 (before): secant directions over h
    and h/2 extrapolated to 0 (Richardson), so that it holds where
    d curve / db vanishes (x = (1 - cos b)/2 at the trailing edge): error
    O(h^2) = 1e-8 rad."""
    def secant(h):
        d = side * np.subtract(curve(b + side * h), curve(b))
        return d / np.hypot(*d)
    t = 2 * secant(5e-5) - secant(1e-4)
    return t / np.hypot(*t)


def blade(b):
    """The cascade blade, b in R (period 2 pi): 0 leading edge, pi trailing
    edge; the pressure side (below the camber line) for b in (0, pi)."""
    theta = CHI1 - CHI2  # camber angle
    r = 1 / (2 * math.sin(theta / 2))
    stagger = (CHI1 + CHI2) / 2
    s = (1 - math.cos(b)) / 2  # fraction of the camber arc
    phi = theta / 2 - theta * s  # the arc point's angle seen from its centre
    cx, cy = 0.5 - r * math.sin(phi), r * math.cos(phi) - r * math.cos(theta / 2)
    nx, ny = -math.sin(phi), math.cos(phi)  # outward normal of the arc (upwards)
    half = THICK / 2 * math.sin(b) * (1 + SKEW * math.cos(b))
    x, y = cx - half * nx, cy - half * ny  # sin(b) > 0: below the camber line
    c, sn = math.cos(stagger), math.sin(stagger)
    return (c * x - sn * y, sn * x + c * y)


def naca(b):
    """NACA 4412 with the closed trailing edge, b in [-pi, pi]: x/c =
    (1 - cos b)/2, b = 0 the leading edge, b > 0 the upper surface."""
    x = (1 - math.cos(b)) / 2
    yt = 5 * NACA_T * (0.2969 * math.sin(abs(b) / 2) - 0.1260 * x - 0.3516 * x ** 2
                       + 0.2843 * x ** 3 - 0.1036 * x ** 4)
    m, p = NACA_M, NACA_P
    if x < p:
        yc, dyc = m / p ** 2 * (2 * p * x - x * x), 2 * m / p ** 2 * (p - x)
    else:
        yc, dyc = m / (1 - p) ** 2 * (1 - 2 * p + 2 * p * x - x * x), 2 * m / (1 - p) ** 2 * (p - x)
    th = math.atan(dyc)
    sign = 1.0 if b > 0 else -1.0
    return (CHORD * (x - sign * yt * math.sin(th)), CHORD * (yc + sign * yt * math.cos(th)))


def corner_angle(a, b, c):
    """Interior angle (degrees) at b of a loop walked a -> b -> c with the
    face on the left."""
    ux, uy = c[0] - b[0], c[1] - b[1]
    vx, vy = a[0] - b[0], a[1] - b[1]
    return math.degrees(math.atan2(ux * vy - uy * vx, ux * vx + uy * vy)) % 360


def write_face(path, outer, hole, plane_down, extra):
    """outer: polygon (counter-clockwise); hole: [(curve, b0, b1)], the
    pieces of one closed curve end to start, walked either way (made
    clockwise here).  Writes the STEP file and NAME.facts."""
    hole_edges = [(pts, t[0], t[1]) for pts, t in (sample(*h) for h in hole)]
    ring = np.concatenate([np.asarray(e[0]) for e in hole_edges])
    if np.sum(ring[:, 0] * np.roll(ring[:, 1], -1) - np.roll(ring[:, 0], -1) * ring[:, 1]) > 0:
        hole_edges = [(e[0][::-1], -e[2], -e[1]) for e in hole_edges[::-1]]
    s = Step("m")
    vs = [s.vertex(p) for p in outer]
    oes = [s.line(vs[i], vs[(i + 1) % len(outer)], outer[i], outer[(i + 1) % len(outer)])
           for i in range(len(outer))]
    area = 0.5 * sum(outer[i][0] * outer[(i + 1) % len(outer)][1] -
                     outer[(i + 1) % len(outer)][0] * outer[i][1] for i in range(len(outer)))
    splines = [interpolate(*e) for e in hole_edges]
    hv = [s.vertex(P[0]) for P, _, _, _ in splines]
    hoes = []
    for k, (P, knots, mults, full) in enumerate(splines):
        hoes.append(s.bspline(hv[k], hv[(k + 1) % len(hv)], [tuple(p) for p in P], knots, mults))
        area += bspline_area(P, full)
    s.write(path, [s.loop(oes), s.loop(hoes)], plane_down)
    chord = max(np.hypot(*(p - q)) for p in ring for q in ring)
    spacing = max(np.hypot(*np.diff(np.asarray(e[0]), axis=0).T).max() for e in hole_edges)
    with open(os.path.splitext(path)[0] + ".facts", "w") as fh:
        fh.write("area %.17g\nchord %.17g\nsample_spacing %.17g\n" % (area, chord, spacing))
        for i in range(len(outer)):
            fh.write("corner %.17g %.17g %.17g\n" % (outer[i][0], outer[i][1], corner_angle(
                outer[i - 1], outer[i], outer[(i + 1) % len(outer)])))
        for k, v in extra.items():
            fh.write("%s %s\n" % (k, v))


def cascade(path):
    # the lower periodic line: from the inlet along the inlet flow angle to
    # p1, horizontal to p2, along the outlet flow angle to p3, horizontal
    # to the outlet; the upper one a pitch above
    p1, p2 = KINK1, (KINK2_X, KINK1[1])
    p3 = (p2[0] + DROP / math.tan(-BETA2), p2[1] - DROP)
    p0 = (X_IN, p1[1] - (p1[0] - X_IN) * math.tan(BETA1))
    lower = [p0, p1, p2, p3, (X_OUT, p3[1])]
    outer = lower + [(x, y + PITCH) for x, y in lower][::-1]
    hole = [(blade, math.pi / 2, 3 * math.pi / 2), (blade, -math.pi / 2, math.pi / 2)]
    write_face(path, outer, hole, True,
               {"pitch": "%.17g" % PITCH, "te": "%.17g %.17g" % blade(math.pi),
                "te_radius": "%.17g" % ((THICK * (1 - SKEW)) ** 2 / 2)})


def aerofoil_box(path):
    x0, y0, x1, y1 = BOX
    outer = [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]
    hole = [(naca, -math.pi, 0.0), (naca, 0.0, math.pi)]  # lower, upper side
    te = naca(math.pi)
    # the angle between the two sides at the trailing edge, from the
    # tangents the B-splines end with, seen from the fluid
    te_angle = 360 - math.degrees(math.acos(-tangent(naca, math.pi, -1) @ tangent(naca, -math.pi, 1)))
    write_face(path, outer, hole, False, {"trailing_edge": "%.17g %.17g %.17g" % (*te, te_angle)})


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    os.makedirs(sys.argv[1], exist_ok=True)
    cascade(os.path.join(sys.argv[1], "cascade.step"))
    aerofoil_box(os.path.join(sys.argv[1], "aerofoil_box.step"))
