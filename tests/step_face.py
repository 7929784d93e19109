"""Test helper: a STEP file of one planar face in z = 0 (mm, inch or metre),
written as text (AP214: lines, circles and cubic B-splines; no p-curves, the
reader makes them), so that tests build their own faces without Gmsh; and
that face as `semquad info --json` reads it."""
import json
import subprocess


class Step:
    """Minimal AP214 writer of one planar face in z = 0, in mm, inch or m."""

    def __init__(self, unit="mm"):
        self.ents = []
        self.unit = unit

    @staticmethod
    def real(x):
        """A STEP real: a point and an upper-case exponent (the reader takes
        a lower-case one for the end of the number)."""
        return "%.17E" % float(x)

    def add(self, s):
        self.ents.append(s)
        return "#%d" % len(self.ents)

    def pt(self, x, y, z=0.0):
        """z: a B-spline's pole off the plane (an edge within the tolerance of it)."""
        return self.add("CARTESIAN_POINT('',(%s,%s,%s))" % (self.real(x), self.real(y), self.real(z)))

    def dirn(self, x, y, z=0.0):
        return self.add("DIRECTION('',(%s,%s,%s))" % (self.real(x), self.real(y), self.real(z)))

    def axis(self, x, y):
        return self.add("AXIS2_PLACEMENT_3D('',%s,%s,%s)" % (self.pt(x, y), self.dirn(0, 0, 1),
                                                             self.dirn(1, 0)))

    def polygon(self, pts):
        vs = [self.add("VERTEX_POINT('',%s)" % self.pt(*p)) for p in pts]
        oes = []
        for i, p in enumerate(pts):
            q = pts[(i + 1) % len(pts)]
            dx, dy = q[0] - p[0], q[1] - p[1]
            ln = (dx * dx + dy * dy) ** 0.5
            vec = self.add("VECTOR('',%s,%s)" % (self.dirn(dx / ln, dy / ln), self.real(ln)))
            line = self.add("LINE('',%s,%s)" % (self.pt(*p), vec))
            ec = self.add("EDGE_CURVE('',%s,%s,%s,.T.)" % (vs[i], vs[(i + 1) % len(pts)], line))
            oes.append(self.add("ORIENTED_EDGE('',*,*,%s,.T.)" % ec))
        return self.add("EDGE_LOOP('',(%s))" % ",".join(oes))

    def circle(self, cx, cy, r):
        """A clockwise circle (a hole)."""
        v = self.add("VERTEX_POINT('',%s)" % self.pt(cx + r, cy))
        c = self.add("CIRCLE('',%s,%s)" % (self.axis(cx, cy), self.real(r)))
        ec = self.add("EDGE_CURVE('',%s,%s,%s,.T.)" % (v, v, c))
        return self.add("EDGE_LOOP('',(%s))" % self.add("ORIENTED_EDGE('',*,*,%s,.F.)" % ec))

    def line(self, v0, v1, p, q):
        """An oriented edge: the line from p to q, vertices v0, v1."""
        dx, dy = q[0] - p[0], q[1] - p[1]
        ln = (dx * dx + dy * dy) ** 0.5
        vec = self.add("VECTOR('',%s,%s)" % (self.dirn(dx / ln, dy / ln), self.real(ln)))
        ec = self.add("EDGE_CURVE('',%s,%s,%s,.T.)" % (v0, v1, self.add("LINE('',%s,%s)" % (self.pt(*p), vec))))
        return self.add("ORIENTED_EDGE('',*,*,%s,.T.)" % ec)

    def vertex(self, p):
        return self.add("VERTEX_POINT('',%s)" % self.pt(*p))

    def bspline(self, v0, v1, poles, knots, mults, weights=None):
        """An oriented edge: the clamped cubic B-spline of these poles, knots
        and multiplicities (weights: rational), vertices v0, v1.  A
        non-rational one is the simple entity (OpenCASCADE's reader knows
        the complex one only with RATIONAL_B_SPLINE_CURVE in it)."""
        curve = "3,(%s),.UNSPECIFIED.,.F.,.F." % ",".join(self.pt(*p) for p in poles)
        with_knots = "(%s),(%s),.UNSPECIFIED." % (",".join(map(str, mults)),
                                                  ",".join(self.real(k) for k in knots))
        if weights:
            bsp = self.add("( BOUNDED_CURVE() B_SPLINE_CURVE(%s) B_SPLINE_CURVE_WITH_KNOTS(%s) CURVE() "
                           "GEOMETRIC_REPRESENTATION_ITEM() RATIONAL_B_SPLINE_CURVE((%s)) "
                           "REPRESENTATION_ITEM('') )" % (curve, with_knots,
                                                          ",".join(map(self.real, weights))))
        else:
            bsp = self.add("B_SPLINE_CURVE_WITH_KNOTS('',%s,%s)" % (curve, with_knots))
        ec = self.add("EDGE_CURVE('',%s,%s,%s,.T.)" % (v0, v1, bsp))
        return self.add("ORIENTED_EDGE('',*,*,%s,.T.)" % ec)

    def loop(self, oriented_edges):
        return self.add("EDGE_LOOP('',(%s))" % ",".join(oriented_edges))

    def bspline_loop(self, poles, weights=None, knots=None):
        """A cubic B-spline (clamped; knots: its n + 1 distinct knots, by
        default 0, 1, ..., n; weights: rational) from the first pole to the
        last, closed by a line back."""
        v0, v1 = self.vertex(poles[0]), self.vertex(poles[-1])
        n = len(poles) - 3  # knot spans
        first = self.bspline(v0, v1, poles, list(knots or range(n + 1)), [4] + [1] * (n - 1) + [4],
                             weights)
        return self.loop([first, self.line(v1, v0, poles[-1], poles[0])])

    def length_unit(self):
        if self.unit == "m":
            return self.add("( LENGTH_UNIT() NAMED_UNIT(*) SI_UNIT($,.METRE.) )")
        mm = self.add("( LENGTH_UNIT() NAMED_UNIT(*) SI_UNIT(.MILLI.,.METRE.) )")
        if self.unit == "mm":
            return mm
        m = self.add("LENGTH_MEASURE_WITH_UNIT(LENGTH_MEASURE(25.4),%s)" % mm)
        d = self.add("DIMENSIONAL_EXPONENTS(1.,0.,0.,0.,0.,0.,0.)")
        return self.add("( CONVERSION_BASED_UNIT('INCH',%s) LENGTH_UNIT() NAMED_UNIT(%s) )" % (m, d))

    def write(self, path, loops, plane_down=False):
        """plane_down: the plane's axis along -z and the face of reversed
        sense (its normal still +z), as some CAD systems write planes."""
        bounds = [self.add("%s('',%s,.T.)" % ("FACE_OUTER_BOUND" if i == 0 else "FACE_BOUND", l))
                  for i, l in enumerate(loops)]
        if plane_down:
            axis = self.add("AXIS2_PLACEMENT_3D('',%s,%s,%s)" % (self.pt(0, 0), self.dirn(0, 0, -1),
                                                                 self.dirn(1, 0)))
        else:
            axis = self.axis(0, 0)
        face = self.add("ADVANCED_FACE('',(%s),%s,%s)" % (",".join(bounds),
                                                          self.add("PLANE('',%s)" % axis),
                                                          ".F." if plane_down else ".T."))
        mm = self.length_unit()
        rad = self.add("( NAMED_UNIT(*) PLANE_ANGLE_UNIT() SI_UNIT($,.RADIAN.) )")
        sr = self.add("( NAMED_UNIT(*) SI_UNIT($,.STERADIAN.) SOLID_ANGLE_UNIT() )")
        unc = self.add("UNCERTAINTY_MEASURE_WITH_UNIT(LENGTH_MEASURE(1.E-07),%s,"
                       "'distance_accuracy_value','')" % mm)
        ctx = self.add("( GEOMETRIC_REPRESENTATION_CONTEXT(3) GLOBAL_UNCERTAINTY_ASSIGNED_CONTEXT((%s)) "
                       "GLOBAL_UNIT_ASSIGNED_CONTEXT((%s,%s,%s)) REPRESENTATION_CONTEXT('',''))"
                       % (unc, mm, rad, sr))
        model = self.add("SHELL_BASED_SURFACE_MODEL('',(%s))" % self.add("OPEN_SHELL('',(%s))" % face))
        app = self.add("APPLICATION_CONTEXT('core data for automotive mechanical design processes')")
        self.add("APPLICATION_PROTOCOL_DEFINITION('international standard','automotive_design',2000,%s)" % app)
        prod = self.add("PRODUCT('face','face','',(%s))" % self.add("PRODUCT_CONTEXT('',%s,'mechanical')" % app))
        pd = self.add("PRODUCT_DEFINITION('design','',%s,%s)" % (
            self.add("PRODUCT_DEFINITION_FORMATION('','',%s)" % prod),
            self.add("PRODUCT_DEFINITION_CONTEXT('part definition',%s,'design')" % app)))
        rep = self.add("MANIFOLD_SURFACE_SHAPE_REPRESENTATION('',(%s,%s),%s)" % (self.axis(0, 0), model, ctx))
        self.add("SHAPE_DEFINITION_REPRESENTATION(%s,%s)" % (self.add("PRODUCT_DEFINITION_SHAPE('','',%s)" % pd), rep))
        with open(path, "w") as fh:
            fh.write("ISO-10303-21;\nHEADER;\nFILE_DESCRIPTION((''),'2;1');\n"
                     "FILE_NAME('face','',(''),(''),'','','');\n"
                     "FILE_SCHEMA(('AUTOMOTIVE_DESIGN { 1 0 10303 214 1 1 1 1 }'));\nENDSEC;\nDATA;\n")
            fh.writelines("#%d = %s;\n" % (i + 1, e) for i, e in enumerate(self.ents))
            fh.write("ENDSEC;\nEND-ISO-10303-21;\n")


def as_read_outer(s, short, lift, gap):
    """The outer loop of a face that healing would spoil (t340): the
    rectangle [0, 1] x [0, 1.5], its bottom side in three lines with a
    middle one of length `short`, its top side a cubic B-spline whose inner
    poles leave the plane by `lift` and whose first pole misses its vertex
    by `gap`."""
    pts = [(0, 0), (0.5, 0), (0.5 + short, 0), (1, 0), (1, 1.5), (0, 1.5)]
    v = [s.vertex(p) for p in pts]
    top = s.bspline(v[4], v[5], [(1, 1.5 + gap, 0), (2 / 3, 1.5, lift), (1 / 3, 1.5, lift),
                                 (0, 1.5, 0)], [0, 1], [4, 4])
    return s.loop([s.line(v[k], v[k + 1], pts[k], pts[k + 1]) for k in range(4)]
                  + [top, s.line(v[5], v[0], pts[5], pts[0])])


def step_face(path, loops, unit="mm"):
    """loops: polygons [(x, y), ...] (the first counter-clockwise) or ('circle', cx, cy, r)."""
    s = Step(unit)
    s.write(path, [s.circle(*l[1:]) if l[0] == "circle" else s.polygon(l) for l in loops])


def info_face(sq, path, *args):
    """(the file's one face as `semquad info --json` gives it, or None; what went
    wrong otherwise)."""
    r = subprocess.run([sq, "info", path, "--json", "-q", *args], capture_output=True, text=True,
                       timeout=120)
    faces = json.loads(r.stdout)["faces"] if r.returncode == 0 else []
    if len(faces) != 1:
        return None, f"info: exit {r.returncode}, {len(faces)} faces: {r.stderr.strip()}"
    return faces[0], ""
