// semquad cad/ — a planar face in its 2D frame: boundary loops, edges,
// evaluation by arc length and projection.
//
// design:
//  1. frame: n = outward normal of the face (parametric normal of the plane,
//     reversed with the face).  If n is parallel to z: X, Y = global x, y and
//     O on the global z axis, so coordinates read as in the file; else X = the
//     plane's X direction, Y = n x X and O = the plane's location;
//  2. loops: outer wire (BRepTools::OuterWire) then the other wires, edges in
//     order of travel (BRepTools_WireExplorer), degenerated and zero-length
//     edges skipped, each edge travelled along its orientation in the wire;
//  3. arc length: per edge a table of (parameter, arc length) from adaptive
//     10-point Gauss-Legendre quadrature of |C'(u)| on the curve's C2
//     intervals, a piece halved until its halves agree to 1e-15 of it or
//     of the edge's length; s -> u by Newton steps inside one table interval;
//  4. orientation: signed area by Green's theorem; if the outer loop is
//     negative, it is reversed (plane z = const, normal -z) or the frame is
//     mirrored (Y -> -Y, other planes); a positive hole is reversed;
//  5. projection: the closest point of a curve to P by branch and bound on
//     chords: every chord whose distance from P minus its sagitta bound is
//     below the best distance so far gets Newton steps on (C(u) - P).C'(u)
//     inside its parameter interval (usually one chord does; no sampling of
//     the whole curve per query);
//  6. checks: each edge ends where the next one starts (within tolerance);
//     the junction point (the shared vertex's point, else the mid-point of
//     the two curve ends) is then returned exactly at s = 0 and s = length.
#include "cad_private.hxx"

#include <BRepAdaptor_Curve.hxx>
#include <BRepTools.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <Standard_ErrorHandler.hxx>
#include <BRep_Tool.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TopExp.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Vertex.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Iterator.hxx>
#include <TopoDS_Wire.hxx>
#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <memory>

namespace
{

// 10-point Gauss-Legendre rule on [-1, 1] (Abramowitz & Stegun, table 25.4).
const double GL_X[5] = {0.1488743389816312108848260, 0.4333953941292471907992659,
                        0.6794095682990244062343274, 0.8650633666889845107320967,
                        0.9739065285171717200779640};
const double GL_W[5] = {0.2955242247147528701738930, 0.2692667193099963550912269,
                        0.2190863625159820439955349, 0.1494513491505805931457763,
                        0.0666713443086881375935688};

const size_t PROJ_BLOCK = 16;

struct ProjBlock {
    double lo[3], hi[3], sag;
};

struct Edge {
    TopoDS_Edge edge;
    Handle(BRepAdaptor_Curve) curve;
    double u0 = 0, u1 = 0; // parameter range
    bool reversed = false; // travelled from u1 to u0
    double length = 0;
    cad_edge_type type = CAD_EDGE_OTHER;
    int loop = 0;
    std::vector<double> tu; // table: parameters, increasing, tu[0] = u0, back = u1
    std::vector<double> ts; // forward arc length at tu
    // projection: curve points pp at parameters pu (increasing, the C2
    // intervals refined until each chord turns little) and, per chord, a bound
    // psag on how far the curve strays from it
    std::vector<double> pu, psag;
    std::vector<gp_Pnt> pp;
    // per block of PROJ_BLOCK chords: the box of their points and their
    // largest sagitta bound, to skip blocks far from the point projected
    std::vector<ProjBlock> pblock;
    double start[2] = {0, 0}, end[2] = {0, 0}; // 2D end points in the direction of travel,
                                               // shared exactly with the neighbouring edges
    // start and end minus the curve's own ends (within the closure
    // tolerance): blend_gaps adds them in along the edge so that its points
    // run continuously into the shared corners
    double gap0[2] = {0, 0}, gap1[2] = {0, 0};
};

double speed(const Edge &e, double u)
{
    gp_Pnt p;
    gp_Vec d1;
    e.curve->D1(u, p, d1);
    return d1.Magnitude();
}

// Arc length of the curve between a and b by one 10-point rule.
double gl_length(const Edge &e, double a, double b)
{
    double c = 0.5 * (a + b), h = 0.5 * (b - a), sum = 0;
    for (int i = 0; i < 5; ++i)
        sum += GL_W[i] * (speed(e, c - h * GL_X[i]) + speed(e, c + h * GL_X[i]));
    return sum * h;
}

// Halve [a, b] until the two halves' lengths add up to the whole's to
// 1e-15 of it, or to tol: a piece's share of the edge's round-off (the
// speeds carry the round-off of the curve's evaluation, often far above
// 1e-15 of the piece on scaled or off-origin curves, and a relative rule
// alone then halves to the depth bound: 2^24 pieces).
void adapt(Edge &e, double a, double b, double whole, double tol, int depth)
{
    double m = 0.5 * (a + b);
    double l = gl_length(e, a, m), r = gl_length(e, m, b);
    if (depth >= 24 || std::fabs(l + r - whole) <= std::max(1e-15 * whole, tol) + 1e-300) {
        e.tu.push_back(m);
        e.ts.push_back(e.ts.back() + l);
        e.tu.push_back(b);
        e.ts.push_back(e.ts.back() + r);
        return;
    }
    adapt(e, a, m, l, tol, depth + 1);
    adapt(e, m, b, r, tol, depth + 1);
}

// The ends of the curve's C2 intervals inside [u0, u1], u0 and u1 included.
std::vector<double> smooth_breaks(const Edge &e)
{
    int n = e.curve->NbIntervals(GeomAbs_C2);
    TColStd_Array1OfReal iv(1, n + 1);
    e.curve->Intervals(iv, GeomAbs_C2);
    std::vector<double> br;
    br.push_back(e.u0);
    for (int i = 1; i <= n + 1; ++i)
        if (iv(i) > br.back() && iv(i) < e.u1) br.push_back(iv(i));
    br.push_back(e.u1);
    return br;
}

void build_table(Edge &e)
{
    const std::vector<double> br = smooth_breaks(e);
    const int split = 4; // start with 4 pieces per smooth interval
    std::vector<double> pa, pb, whole;
    double length = 0;
    for (size_t k = 0; k + 1 < br.size(); ++k) {
        double a = br[k], h = (br[k + 1] - br[k]) / split;
        for (int j = 0; j < split; ++j) {
            pa.push_back(a + j * h);
            pb.push_back(j + 1 == split ? br[k + 1] : a + (j + 1) * h);
            whole.push_back(gl_length(e, pa.back(), pb.back()));
            length += whole.back();
        }
    }
    e.tu.assign(1, e.u0);
    e.ts.assign(1, 0.0);
    // 1e-15 of the edge's length per piece: about 4 ulps, reached once the
    // pieces are short enough for their round-off to fall below it
    for (size_t k = 0; k < pa.size(); ++k)
        adapt(e, pa[k], pb[k], whole[k], 1e-15 * length, 0);
    e.length = e.ts.back();
}

// Distance from P to the segment [A, B] and the segment parameter t of the foot.
double segment_distance(const gp_Pnt &P, const gp_Pnt &A, const gp_Pnt &B, double *t)
{
    gp_Vec ab(A, B), ap(A, P);
    const double l2 = ab.SquareMagnitude();
    double tt = l2 > 0 ? std::min(1.0, std::max(0.0, ap.Dot(ab) / l2)) : 0.0;
    if (t) *t = tt;
    return P.Distance(A.Translated(tt * ab));
}

// Chords of [a, b] (curve points A, B) appended to the projection table: split
// while the curve at 1/4, 1/2, 3/4 of the interval is more than 1/200 of the
// chord from it (a turn of about 2 degrees).  The sagitta bound is twice the
// largest of those three distances.
void project_chords(Edge &e, double a, const gp_Pnt &A, double b, const gp_Pnt &B, double floor,
                    int depth)
{
    double dev = 0;
    for (int i = 1; i <= 3; ++i)
        dev = std::max(dev, segment_distance(e.curve->Value(a + 0.25 * i * (b - a)), A, B, NULL));
    const double m = 0.5 * (a + b);
    if (depth < 20 && dev > 0.005 * A.Distance(B) + floor) {
        const gp_Pnt M = e.curve->Value(m);
        project_chords(e, a, A, m, M, floor, depth + 1);
        project_chords(e, m, M, b, B, floor, depth + 1);
        return;
    }
    e.psag.push_back(2 * dev + floor);
    e.pu.push_back(b);
    e.pp.push_back(B);
}

// From the C2 intervals, each in 4 pieces to start with.
void build_projection(Edge &e)
{
    const double floor = 1e-12 * e.length;
    const std::vector<double> br = smooth_breaks(e);
    e.pu.assign(1, e.u0);
    e.pp.assign(1, e.curve->Value(e.u0));
    e.psag.clear();
    for (size_t k = 0; k + 1 < br.size(); ++k)
        for (int j = 1; j <= 4; ++j) {
            const double b = j == 4 ? br[k + 1] : br[k] + 0.25 * j * (br[k + 1] - br[k]);
            const gp_Pnt A = e.pp.back(); // a copy: the table grows under it
            project_chords(e, e.pu.back(), A, b, e.curve->Value(b), floor, 0);
        }
    const size_t n = e.pu.size() - 1;
    e.pblock.clear();
    for (size_t k0 = 0; k0 < n; k0 += PROJ_BLOCK) {
        const size_t k1 = std::min(n, k0 + PROJ_BLOCK);
        ProjBlock b = {{HUGE_VAL, HUGE_VAL, HUGE_VAL}, {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL}, 0.0};
        for (size_t k = k0; k <= k1; ++k)
            for (int c = 0; c < 3; ++c) {
                b.lo[c] = std::min(b.lo[c], e.pp[k].Coord(c + 1));
                b.hi[c] = std::max(b.hi[c], e.pp[k].Coord(c + 1));
            }
        for (size_t k = k0; k < k1; ++k)
            b.sag = std::max(b.sag, e.psag[k]);
        e.pblock.push_back(b);
    }
}

// Lines and circles move at constant speed: arc length is affine in the
// parameter, no quadrature or Newton step needed between table entries.
bool uniform_speed(const Edge &e)
{
    return e.type == CAD_EDGE_LINE || e.type == CAD_EDGE_CIRCLE;
}

// Forward arc length at parameter u.
double s_of_u(const Edge &e, double u)
{
    if (u <= e.tu.front()) return 0;
    if (u >= e.tu.back()) return e.length;
    size_t k = (size_t)(std::upper_bound(e.tu.begin(), e.tu.end(), u) - e.tu.begin()) - 1;
    if (uniform_speed(e)) // u < tu.back(): k + 1 is in the table
        return e.ts[k] + (u - e.tu[k]) / (e.tu[k + 1] - e.tu[k]) * (e.ts[k + 1] - e.ts[k]);
    return e.ts[k] + gl_length(e, e.tu[k], u);
}

// Parameter at forward arc length s.
double u_of_s(const Edge &e, double s)
{
    if (s <= 0) return e.u0;
    if (s >= e.length) return e.u1;
    size_t k = (size_t)(std::upper_bound(e.ts.begin(), e.ts.end(), s) - e.ts.begin()) - 1;
    if (k + 1 >= e.ts.size()) return e.u1;
    double ua = e.tu[k], ub = e.tu[k + 1], sa = e.ts[k], sb = e.ts[k + 1];
    double u = sb > sa ? ua + (s - sa) / (sb - sa) * (ub - ua) : ua;
    if (uniform_speed(e)) return u;
    double tol = 1e-15 * std::max(e.length, 1e-300);
    for (int it = 0; it < 30; ++it) {
        double f = sa + gl_length(e, ua, u) - s;
        double d = speed(e, u);
        if (d <= 0) break;
        double un = std::min(ub, std::max(ua, u - f / d));
        double step = std::fabs(un - u);
        u = un;
        // Newton converges quadratically: from a residual below 1e-8 of
        // the table piece (whose speed varies little: the 10-point rule
        // is exact on it) the step just taken leaves round-off only
        if (std::fabs(f) <= std::max(tol, 1e-8 * (sb - sa)) ||
            step <= 1e-16 * std::max(1.0, std::fabs(u)))
            break;
    }
    return u;
}

cad_edge_type edge_type(GeomAbs_CurveType t)
{
    switch (t) {
    case GeomAbs_Line: return CAD_EDGE_LINE;
    case GeomAbs_Circle: return CAD_EDGE_CIRCLE;
    case GeomAbs_Ellipse: return CAD_EDGE_ELLIPSE;
    case GeomAbs_Hyperbola: return CAD_EDGE_HYPERBOLA;
    case GeomAbs_Parabola: return CAD_EDGE_PARABOLA;
    case GeomAbs_BezierCurve: return CAD_EDGE_BEZIER;
    case GeomAbs_BSplineCurve: return CAD_EDGE_BSPLINE;
    case GeomAbs_OffsetCurve: return CAD_EDGE_OFFSET;
    default: return CAD_EDGE_OTHER;
    }
}

} // namespace

struct cad_face {
    double O[3], X[3], Y[3];
    std::vector<Edge> edges;
    std::vector<int> loop_first, loop_n;
    std::vector<std::string> edge_name; // per edge, the file's name ("" none)

    void to2d(const gp_Pnt &p, double xy[2]) const
    {
        double d[3] = {p.X() - O[0], p.Y() - O[1], p.Z() - O[2]};
        xy[0] = d[0] * X[0] + d[1] * X[1] + d[2] * X[2];
        xy[1] = d[0] * Y[0] + d[1] * Y[1] + d[2] * Y[2];
    }
    void vec2d(const gp_Vec &v, double xy[2]) const
    {
        xy[0] = v.X() * X[0] + v.Y() * X[1] + v.Z() * X[2];
        xy[1] = v.X() * Y[0] + v.Y() * Y[1] + v.Z() * Y[2];
    }
    gp_Pnt to3d(const double xy[2]) const
    {
        return gp_Pnt(O[0] + xy[0] * X[0] + xy[1] * Y[0], O[1] + xy[0] * X[1] + xy[1] * Y[1],
                      O[2] + xy[0] * X[2] + xy[1] * Y[2]);
    }
    // Point, unit tangent and curvature at parameter u, direction of travel.
    void eval_u(const Edge &e, double u, double xy[2], double t[2], double *kappa) const
    {
        gp_Pnt p;
        gp_Vec d1, d2;
        e.curve->D2(u, p, d1, d2);
        double a[2], b[2];
        vec2d(d1, a);
        vec2d(d2, b);
        double sg = e.reversed ? -1.0 : 1.0, n = std::hypot(a[0], a[1]);
        if (xy) to2d(p, xy);
        if (t) {
            t[0] = n > 0 ? sg * a[0] / n : 0;
            t[1] = n > 0 ? sg * a[1] / n : 0;
        }
        if (kappa) *kappa = n > 0 ? sg * (a[0] * b[1] - a[1] * b[0]) / (n * n * n) : 0;
    }
    // int (x dy - y dx) along the curve forward from parameter ua to ub, on
    // the pieces of the arc-length table (each smooth and short enough for
    // the 10-point rule to be exact to round-off: see build_table).
    double green_u(const Edge &e, double ua, double ub) const
    {
        std::vector<double> br(1, ua);
        for (size_t k = (size_t)(std::upper_bound(e.tu.begin(), e.tu.end(), ua) - e.tu.begin());
             k < e.tu.size() && e.tu[k] < ub; ++k)
            br.push_back(e.tu[k]);
        br.push_back(ub);
        double sum = 0;
        for (size_t k = 0; k + 1 < br.size(); ++k) {
            double c = 0.5 * (br[k] + br[k + 1]), h = 0.5 * (br[k + 1] - br[k]);
            for (int i = 0; i < 10; ++i) {
                double u = c + (i < 5 ? -h * GL_X[i] : h * GL_X[i - 5]);
                gp_Pnt p;
                gp_Vec d1;
                e.curve->D1(u, p, d1);
                double xy[2], v[2];
                to2d(p, xy);
                vec2d(d1, v);
                sum += GL_W[i % 5] * h * (xy[0] * v[1] - xy[1] * v[0]);
            }
        }
        return sum;
    }
    // Signed area contribution 1/2 int (x dy - y dx) along the travel.
    double edge_area(const Edge &e) const
    {
        double sum = 0.5 * green_u(e, e.u0, e.u1);
        return e.reversed ? -sum : sum;
    }
    double loop_area(int l) const
    {
        double a = 0;
        for (int k = 0; k < loop_n[(size_t)l]; ++k)
            a += edge_area(edges[(size_t)(loop_first[(size_t)l] + k)]);
        return a;
    }
    // Loop l becomes loop 0, the others keep their order.
    void make_first(int l)
    {
        std::vector<Edge> e;
        std::vector<int> first, n;
        for (int k : {l, -1})
            for (int j = 0; j < (int)loop_first.size(); ++j) {
                if ((k >= 0) != (j == l)) continue;
                first.push_back((int)e.size());
                n.push_back(loop_n[(size_t)j]);
                for (int i = 0; i < loop_n[(size_t)j]; ++i)
                    e.push_back(std::move(edges[(size_t)(loop_first[(size_t)j] + i)]));
            }
        edges.swap(e);
        loop_first.swap(first);
        loop_n.swap(n);
        for (int j = 0; j < (int)loop_first.size(); ++j)
            for (int i = 0; i < loop_n[(size_t)j]; ++i)
                edges[(size_t)(loop_first[(size_t)j] + i)].loop = j;
    }
    void reverse_loop(int l)
    {
        auto b = edges.begin() + loop_first[(size_t)l];
        std::reverse(b, b + loop_n[(size_t)l]);
        for (int k = 0; k < loop_n[(size_t)l]; ++k)
            b[k].reversed = !b[k].reversed;
    }
    gp_Pnt start3d(const Edge &e) const { return e.curve->Value(e.reversed ? e.u1 : e.u0); }
    gp_Pnt end3d(const Edge &e) const { return e.curve->Value(e.reversed ? e.u0 : e.u1); }
};

namespace
{

// gap = corner - curve end, or 0 if below 1e-9 of the edge's length (plus
// the coordinates' rounding): a file's own digits (STEP writes 13-17) leave
// gaps of 1e-13 of a part, and such a jump is below anything the
// triangulation resolves (its splits stop at 1e-2 of segments of 2^-16 of
// the size), so the curve's points stay the curve's, to the last bit.
static void end_gap(const double corner[2], const double curve_end[2], double length,
                    double gap[2])
{
    double g[2] = {corner[0] - curve_end[0], corner[1] - curve_end[1]};
    double least = 1e-9 * length + 8 * DBL_EPSILON * (std::fabs(corner[0]) + std::fabs(corner[1]));
    bool real = std::hypot(g[0], g[1]) > least;
    gap[0] = real ? g[0] : 0, gap[1] = real ? g[1] : 0;
}

sq_status face_create(const cad_model *model, int index, cad_face **out, sq_error *err)
{
    int nf = model->faces.Extent();
    if (index < 0 || index >= nf)
        return SQ_FAIL(err, SQ_ERR_USAGE, "face %d out of range (%s has %d face%s)", index,
                       model->path.c_str(), nf, nf == 1 ? "" : "s");
    if (index < (int)model->status.size() && model->status[(size_t)index] == CAD_FACE_BROKEN)
        return SQ_FAIL(err, SQ_ERR_GEOMETRY, "face %d: %s", index,
                       model->reason[(size_t)index].c_str());
    TopoDS_Face face = TopoDS::Face(model->faces(index + 1));
    gp_Pln pln;
    if (!sqcad::face_plane(face, &pln))
        return SQ_FAIL(err, SQ_ERR_GEOMETRY, "face %d is not planar (surface: %s)", index,
                       model->surface[(size_t)index].c_str());

    std::unique_ptr<cad_face> f(new cad_face);
    gp_Dir n = pln.Axis().Direction();
    gp_Pnt o = pln.Location();
    gp_Dir x, y;
    const bool zplane = std::fabs(n.Z()) >= 1.0 - 1e-12;
    if (zplane) {
        // Plane z = const: the file's own x and y (whichever side the face's
        // normal points to), origin above/below the global origin.
        x = gp::DX();
        y = gp::DY();
        o = gp_Pnt(0, 0, o.Z() + (n.X() * o.X() + n.Y() * o.Y()) / n.Z());
    } else {
        x = pln.Position().XDirection();
        y = n.Crossed(x);
    }
    f->O[0] = o.X(), f->O[1] = o.Y(), f->O[2] = o.Z();
    f->X[0] = x.X(), f->X[1] = x.Y(), f->X[2] = x.Z();
    f->Y[0] = y.X(), f->Y[1] = y.Y(), f->Y[2] = y.Z();

    // Wires: OpenCASCADE's outer one first (checked below by area: its
    // choice compares boxes enlarged by the tolerances, wrong on faces not
    // much larger than their tolerances).
    TopoDS_Wire outer = BRepTools::OuterWire(face);
    std::vector<TopoDS_Wire> wires;
    if (!outer.IsNull()) wires.push_back(outer);
    for (TopoDS_Iterator it(face); it.More(); it.Next())
        if (it.Value().ShapeType() == TopAbs_WIRE && !it.Value().IsSame(outer))
            wires.push_back(TopoDS::Wire(it.Value()));
    if (wires.empty()) return SQ_FAIL(err, SQ_ERR_GEOMETRY, "face %d has no outer boundary", index);

    double tol_vertex = 0;
    for (size_t w = 0; w < wires.size(); ++w) {
        int first = (int)f->edges.size();
        for (BRepTools_WireExplorer wx(wires[w], face); wx.More(); wx.Next()) {
            const TopoDS_Edge &edge = wx.Current();
            TopAbs_Orientation ori = wx.Orientation();
            if (ori != TopAbs_FORWARD && ori != TopAbs_REVERSED) continue; // internal/external
            if (BRep_Tool::Degenerated(edge)) continue;
            if (!BRep_Tool::IsGeometric(edge)) continue;
            Edge e;
            e.edge = edge;
            e.curve = new BRepAdaptor_Curve(edge);
            e.u0 = e.curve->FirstParameter();
            e.u1 = e.curve->LastParameter();
            if (!(e.u1 > e.u0)) continue;
            e.reversed = ori == TopAbs_REVERSED;
            e.type = edge_type(e.curve->GetType());
            e.loop = (int)w;
            build_table(e);
            build_projection(e);
            tol_vertex = std::max(tol_vertex, BRep_Tool::Tolerance(edge));
            f->edges.push_back(std::move(e));
        }
        int cnt = (int)f->edges.size() - first;
        if (cnt == 0) {
            if (w == 0)
                return SQ_FAIL(err, SQ_ERR_GEOMETRY, "face %d: outer loop has no edge", index);
            continue; // an empty inner wire: ignore
        }
        f->loop_first.push_back(first);
        f->loop_n.push_back(cnt);
    }
    int nl = (int)f->loop_first.size();
    for (int l = 0; l < nl; ++l)
        for (int k = 0; k < f->loop_n[(size_t)l]; ++k)
            f->edges[(size_t)(f->loop_first[(size_t)l] + k)].loop = l;

    // Size of the face: drop edges shorter than a tiny fraction of it.
    double total = 0;
    for (const Edge &e : f->edges)
        total += e.length;
    if (!(total > 0))
        return SQ_FAIL(err, SQ_ERR_GEOMETRY, "face %d has a degenerate boundary", index);
    {
        std::vector<Edge> kept;
        std::vector<int> first, cnt;
        for (int l = 0; l < nl; ++l) {
            int fi = (int)kept.size();
            for (int k = 0; k < f->loop_n[(size_t)l]; ++k) {
                Edge &e = f->edges[(size_t)(f->loop_first[(size_t)l] + k)];
                if (e.length > 1e-13 * total) kept.push_back(std::move(e));
            }
            if ((int)kept.size() > fi) {
                first.push_back(fi);
                cnt.push_back((int)kept.size() - fi);
            } else if (l == 0) {
                return SQ_FAIL(err, SQ_ERR_GEOMETRY, "face %d: outer loop has zero length", index);
            }
        }
        f->edges.swap(kept);
        f->loop_first.swap(first);
        f->loop_n.swap(cnt);
        nl = (int)f->loop_first.size();
        for (int l = 0; l < nl; ++l)
            for (int k = 0; k < f->loop_n[(size_t)l]; ++k)
                f->edges[(size_t)(f->loop_first[(size_t)l] + k)].loop = l;
    }

    // The outer loop encloses the largest area.
    int lo = 0;
    for (int l = 1; l < nl; ++l)
        if (std::fabs(f->loop_area(l)) > std::fabs(f->loop_area(lo))) lo = l;
    if (lo != 0) f->make_first(lo);
    // Orientation: outer counter-clockwise, holes clockwise.
    double aout = f->loop_area(0);
    if (!(std::fabs(aout) > 0))
        return SQ_FAIL(err, SQ_ERR_GEOMETRY, "face %d: outer loop encloses no area", index);
    if (aout < 0) {
        if (zplane)
            f->reverse_loop(0); // face normal along -z: keep x, y, walk the loops the other way
        else
            for (double &c : f->Y)
                c = -c; // mirrored frame
    }
    for (int l = 1; l < nl; ++l)
        if (f->loop_area(l) > 0) f->reverse_loop(l);

    // Closure: each edge ends where the next one starts.
    double gap_tol = std::max(1e-7 * total, 2.0 * tol_vertex);
    for (int l = 0; l < nl; ++l) {
        int n0 = f->loop_first[(size_t)l], cnt = f->loop_n[(size_t)l];
        for (int k = 0; k < cnt; ++k) {
            const Edge &a = f->edges[(size_t)(n0 + k)], &b = f->edges[(size_t)(n0 + (k + 1) % cnt)];
            double gap = f->end3d(a).Distance(f->start3d(b));
            if (gap > gap_tol)
                return SQ_FAIL(err, SQ_ERR_GEOMETRY,
                               "face %d: loop %d is not closed: edge %d ends %.3g away from the "
                               "start of edge %d, beyond the closure tolerance %.3g (healing "
                               "with --heal-tolerance %.2g would close it)",
                               index, l, n0 + k, gap, n0 + (k + 1) % cnt, gap_tol, 1.5 * gap);
        }
    }
    // Shared corners: each junction gets the mid-point of the two curve ends,
    // so that an edge ends exactly where the next one starts.
    for (int l = 0; l < nl; ++l) {
        int n0 = f->loop_first[(size_t)l], cnt = f->loop_n[(size_t)l];
        for (int k = 0; k < cnt; ++k) {
            Edge &a = f->edges[(size_t)(n0 + k)], &b = f->edges[(size_t)(n0 + (k + 1) % cnt)];
            gp_Pnt ea = f->end3d(a), sb = f->start3d(b);
            // The topological vertex (the file's point) if both curve ends are
            // close to it, else the mid-point of the two ends.
            TopoDS_Edge fa = TopoDS::Edge(a.edge.Oriented(TopAbs_FORWARD));
            TopoDS_Vertex v = a.reversed ? TopExp::FirstVertex(fa) : TopExp::LastVertex(fa);
            gp_Pnt j(0.5 * (ea.XYZ() + sb.XYZ()));
            if (!v.IsNull()) {
                gp_Pnt pv = BRep_Tool::Pnt(v);
                if (pv.Distance(ea) <= gap_tol && pv.Distance(sb) <= gap_tol) j = pv;
            }
            double pj[2];
            f->to2d(j, pj);
            for (int d = 0; d < 2; ++d)
                a.end[d] = b.start[d] = pj[d];
        }
    }
    for (Edge &e : f->edges) {
        double c0[2], c1[2];
        f->eval_u(e, e.reversed ? e.u1 : e.u0, c0, nullptr, nullptr);
        f->eval_u(e, e.reversed ? e.u0 : e.u1, c1, nullptr, nullptr);
        end_gap(e.start, c0, e.length, e.gap0);
        end_gap(e.end, c1, e.length, e.gap1);
    }
    for (const Edge &e : f->edges) f->edge_name.push_back(sqcad::edge_name(model, e.edge, gap_tol));
    *out = f.release();
    return SQ_OK;
}

} // namespace

const TopoDS_Edge *sqcad::face_edge(const cad_face *face, int edge)
{
    return face && edge >= 0 && edge < (int)face->edges.size() ? &face->edges[(size_t)edge].edge : nullptr;
}

extern "C" {

const char *cad_edge_type_name(cad_edge_type type)
{
    switch (type) {
    case CAD_EDGE_LINE: return "line";
    case CAD_EDGE_CIRCLE: return "circle";
    case CAD_EDGE_ELLIPSE: return "ellipse";
    case CAD_EDGE_HYPERBOLA: return "hyperbola";
    case CAD_EDGE_PARABOLA: return "parabola";
    case CAD_EDGE_BEZIER: return "bezier";
    case CAD_EDGE_BSPLINE: return "bspline";
    case CAD_EDGE_OFFSET: return "offset";
    case CAD_EDGE_OTHER: return "other";
    }
    return "other";
}

sq_status cad_face_create(const cad_model *model, int index, cad_face **out, sq_error *err)
{
    if (!out) return SQ_FAIL(err, SQ_ERR_USAGE, "cad_face_create: out is NULL");
    *out = NULL;
    if (!model) return SQ_FAIL(err, SQ_ERR_USAGE, "cad_face_create: model is NULL");
    try {
        OCC_CATCH_SIGNALS
        return face_create(model, index, out, err);
    } catch (const Standard_Failure &e) {
        return SQ_FAIL(err, SQ_ERR_GEOMETRY, "face %d: OpenCASCADE %s: %s", index,
                       e.DynamicType()->Name(), e.GetMessageString() ? e.GetMessageString() : "");
    }
    SQCAD_CATCH_REST(err)
}

void cad_face_free(cad_face **face)
{
    if (!face || !*face) return;
    try {
        delete *face;
    } catch (...) {
    }
    *face = NULL;
}

void cad_face_frame(const cad_face *face, double origin[3], double xdir[3], double ydir[3])
{
    for (int i = 0; i < 3; ++i) {
        if (origin) origin[i] = face ? face->O[i] : 0;
        if (xdir) xdir[i] = face ? face->X[i] : (i == 0);
        if (ydir) ydir[i] = face ? face->Y[i] : (i == 1);
    }
}

int cad_face_num_loops(const cad_face *face) { return face ? (int)face->loop_first.size() : 0; }

int cad_face_loop_first_edge(const cad_face *face, int loop)
{
    if (!face || loop < 0 || loop >= (int)face->loop_first.size()) return -1;
    return face->loop_first[(size_t)loop];
}

int cad_face_loop_num_edges(const cad_face *face, int loop)
{
    if (!face || loop < 0 || loop >= (int)face->loop_n.size()) return 0;
    return face->loop_n[(size_t)loop];
}

int cad_face_num_edges(const cad_face *face) { return face ? (int)face->edges.size() : 0; }

const char *cad_face_edge_name(const cad_face *face, int edge)
{
    if (!face || edge < 0 || edge >= (int)face->edge_name.size()) return NULL;
    const std::string &s = face->edge_name[(size_t)edge];
    return s.empty() ? NULL : s.c_str();
}

int cad_face_edge_loop(const cad_face *face, int edge)
{
    if (!face || edge < 0 || edge >= (int)face->edges.size()) return -1;
    return face->edges[(size_t)edge].loop;
}

int cad_face_edge_closed(const cad_face *face, int edge)
{
    int loop = cad_face_edge_loop(face, edge);
    return loop >= 0 && face->loop_n[(size_t)loop] == 1;
}

cad_edge_type cad_face_edge_type(const cad_face *face, int edge)
{
    if (!face || edge < 0 || edge >= (int)face->edges.size()) return CAD_EDGE_OTHER;
    return face->edges[(size_t)edge].type;
}

double cad_face_edge_length(const cad_face *face, int edge)
{
    if (!face || edge < 0 || edge >= (int)face->edges.size()) return 0;
    return face->edges[(size_t)edge].length;
}

// The face exists and has edge `edge` (fn names the caller in the message).
static sq_status check_edge(const cad_face *face, int edge, const char *fn, sq_error *err)
{
    if (!face) return SQ_FAIL(err, SQ_ERR_USAGE, "%s: face is NULL", fn);
    if (edge < 0 || edge >= (int)face->edges.size())
        return SQ_FAIL(err, SQ_ERR_USAGE, "edge %d out of range (face has %d edges)", edge,
                       (int)face->edges.size());
    return SQ_OK;
}

static bool has_gap(const Edge &e)
{
    return e.gap0[0] != 0 || e.gap0[1] != 0 || e.gap1[0] != 0 || e.gap1[1] != 0;
}

// xy, the curve's point at arc length s (direction of travel), made the
// edge's: its end gaps blended in linearly in s, exactly the shared corners
// at both ends.  A file's curves may miss its vertices by up to the closure
// tolerance; without the blend the edge would jump there, and a chord
// halved towards the corner would never come close to it.
static void blend_gaps(const Edge &e, double s, double xy[2])
{
    if (s == 0) {
        xy[0] = e.start[0], xy[1] = e.start[1];
    } else if (s == e.length) {
        xy[0] = e.end[0], xy[1] = e.end[1];
    } else if (has_gap(e)) {
        double t = s / e.length;
        for (int d = 0; d < 2; ++d) xy[d] += (1 - t) * e.gap0[d] + t * e.gap1[d];
    }
}

sq_status cad_face_edge_eval(const cad_face *face, int edge, double s, double xy[2],
                             double tangent[2], double *curvature, sq_error *err)
{
    SQ_TRY(check_edge(face, edge, "cad_face_edge_eval", err));
    const Edge &e = face->edges[(size_t)edge];
    double slack = 1e-9 * e.length;
    if (!(s >= -slack && s <= e.length + slack))
        return SQ_FAIL(err, SQ_ERR_USAGE, "arc length %.17g outside [0, %.17g] on edge %d", s,
                       e.length, edge);
    try {
        s = std::min(e.length, std::max(0.0, s));
        double sf = e.reversed ? e.length - s : s;
        face->eval_u(e, u_of_s(e, sf), xy, tangent, curvature);
        if (xy) blend_gaps(e, s, xy);
        return SQ_OK;
    }
    SQCAD_CATCH(err)
}

sq_status cad_face_edge_green(const cad_face *face, int edge, double s0, double s1, double *val,
                              sq_error *err)
{
    if (!val) return SQ_FAIL(err, SQ_ERR_USAGE, "cad_face_edge_green: val is NULL");
    *val = 0;
    SQ_TRY(check_edge(face, edge, "cad_face_edge_green", err));
    const Edge &e = face->edges[(size_t)edge];
    double slack = 1e-9 * e.length;
    if (!(s0 >= -slack && s1 <= e.length + slack))
        return SQ_FAIL(err, SQ_ERR_USAGE,
                       "arc lengths [%.17g, %.17g] outside [0, %.17g] on edge %d", s0, s1, e.length,
                       edge);
    if (!(s1 > s0)) return SQ_OK;
    try {
        s0 = std::max(0.0, s0), s1 = std::min(e.length, s1);
        double ua = u_of_s(e, e.reversed ? e.length - s1 : s0);
        double ub = u_of_s(e, e.reversed ? e.length - s0 : s1);
        double sum = face->green_u(e, ua, ub);
        *val = e.reversed ? -sum : sum;
        return SQ_OK;
    }
    SQCAD_CATCH(err)
}

// Newton steps on (C(u) - P) . C'(u) = 0 from u inside [a, b], each kept only
// if it brings the curve closer to P than *best_d2.
static void polish(const Edge &e, const gp_Pnt &P, double a, double b, double u, double *best_u,
                   double *best_d2)
{
    double d2 = P.SquareDistance(e.curve->Value(u));
    if (d2 < *best_d2) *best_d2 = d2, *best_u = u;
    for (int it = 0; it < 12; ++it) {
        gp_Pnt c;
        gp_Vec d1, d2v;
        e.curve->D2(u, c, d1, d2v);
        gp_Vec r(P, c);
        double g = r.Dot(d1), dg = d1.SquareMagnitude() + r.Dot(d2v);
        if (!(dg > 0)) break;
        double un = std::min(b, std::max(a, u - g / dg));
        double dn = P.SquareDistance(e.curve->Value(un));
        if (!(dn < d2)) break;
        double step = std::fabs(un - u);
        u = un, d2 = dn;
        if (d2 < *best_d2) *best_d2 = d2, *best_u = u;
        if (step <= 1e-16 * std::max(1.0, std::fabs(u))) break;
    }
}

// Squared distance from P to block b's box: at most the squared distance
// P.SquareDistance(Q) of any of its points Q, as computed (each difference
// and the sum of squares round monotonically).
static double box_d2(const ProjBlock &b, const gp_Pnt &P)
{
    double d2 = 0, d;
    for (int c = 0; c < 3; ++c) {
        const double x = P.Coord(c + 1);
        d = x < b.lo[c] ? b.lo[c] - x : x > b.hi[c] ? x - b.hi[c] : 0.0;
        d2 += d * d;
    }
    return d2;
}

// Parameter of the closest point of edge e to P, and its squared distance
// (design 5).  The blocks whose box is farther than a point already found
// are skipped in both passes: the points they hold cannot be nearer, nor
// their chords candidates, so the nearest point (the first of equals), the
// candidates and their order are those of the scan of every chord.
static double closest_u(const Edge &e, const gp_Pnt &P, double *d2_out)
{
    const size_t n = e.pu.size() - 1, nb = e.pblock.size();
    std::vector<double> bd2(nb);
    size_t near = 0;
    for (size_t b = 0; b < nb; ++b) {
        bd2[b] = box_d2(e.pblock[b], P);
        if (bd2[b] < bd2[near]) near = b;
    }
    double seed = HUGE_VAL; // a squared distance the nearest point does not exceed
    for (size_t k = near * PROJ_BLOCK; k <= std::min(n, (near + 1) * PROJ_BLOCK); ++k)
        seed = std::min(seed, P.SquareDistance(e.pp[k]));
    double best_u = e.pu[0], best_d2 = HUGE_VAL;
    for (size_t b = 0; b < nb; ++b) {
        if (bd2[b] > seed) continue;
        for (size_t k = b * PROJ_BLOCK; k <= std::min(n, (b + 1) * PROJ_BLOCK); ++k) {
            double d2 = P.SquareDistance(e.pp[k]);
            if (d2 < best_d2) best_d2 = d2, best_u = e.pu[k];
        }
    }
    struct Chord {
        double lb; // distance from the chord minus its sagitta bound
        size_t k;
        double t; // the foot on the chord
        bool operator<(const Chord &o) const { return lb < o.lb; }
    };
    // a chord's computed distance to P may fall short of the box's by the
    // round-off of its foot: a margin of 1e-12 of the coordinates' size
    double scale = std::fabs(P.X()) + std::fabs(P.Y()) + std::fabs(P.Z());
    std::vector<Chord> cand;
    for (size_t b = 0; b < nb; ++b) {
        const ProjBlock &B = e.pblock[b];
        const double m = 1e-12 * (scale + std::fabs(B.lo[0]) + std::fabs(B.lo[1]) +
                                  std::fabs(B.lo[2]) + std::fabs(B.hi[0]) + std::fabs(B.hi[1]) +
                                  std::fabs(B.hi[2]));
        const double blb = std::sqrt(bd2[b]) - B.sag - m;
        if (blb > 0 && blb * blb >= best_d2) continue;
        for (size_t k = b * PROJ_BLOCK; k < std::min(n, (b + 1) * PROJ_BLOCK); ++k) {
            double t, lb = segment_distance(P, e.pp[k], e.pp[k + 1], &t) - e.psag[k];
            if (lb <= 0 || lb * lb < best_d2) cand.push_back({lb, k, t});
        }
    }
    std::sort(cand.begin(), cand.end());
    for (const Chord &c : cand) {
        if (c.lb > 0 && c.lb * c.lb >= best_d2) break;
        const double a = e.pu[c.k], b = e.pu[c.k + 1];
        polish(e, P, a, b, a + c.t * (b - a), &best_u, &best_d2);
    }
    *d2_out = best_d2;
    return best_u;
}

sq_status cad_face_edge_project(const cad_face *face, int edge, const double p[2], double *s,
                                double foot[2], double *dist, sq_error *err)
{
    SQ_TRY(check_edge(face, edge, "cad_face_edge_project", err));
    if (!p) return SQ_FAIL(err, SQ_ERR_USAGE, "cad_face_edge_project: NULL point");
    try {
        const Edge &e = face->edges[(size_t)edge];
        double best_d2;
        const double best_u = closest_u(e, face->to3d(p), &best_d2);
        double sf = s_of_u(e, best_u);
        double st = std::min(e.length, std::max(0.0, e.reversed ? e.length - sf : sf));
        if (s) *s = st;
        // the foot only when asked for, or for the distance across a gap:
        // most callers want the arc length alone (boundary data)
        const bool gap_dist = dist && has_gap(e);
        if (!foot && !gap_dist) {
            if (dist) *dist = std::sqrt(best_d2);
            return SQ_OK;
        }
        double q[2];
        face->eval_u(e, best_u, q, NULL, NULL);
        blend_gaps(e, st, q);
        if (foot) foot[0] = q[0], foot[1] = q[1];
        if (dist) *dist = gap_dist ? std::hypot(p[0] - q[0], p[1] - q[1]) : std::sqrt(best_d2);
        return SQ_OK;
    }
    SQCAD_CATCH(err)
}

sq_status cad_face_edge_tangent_near(const cad_face *face, int edge, const double p[2],
                                     double tangent[2], sq_error *err)
{
    SQ_TRY(check_edge(face, edge, "cad_face_edge_tangent_near", err));
    if (!p || !tangent)
        return SQ_FAIL(err, SQ_ERR_USAGE, "cad_face_edge_tangent_near: NULL point or tangent");
    try {
        const Edge &e = face->edges[(size_t)edge];
        double d2;
        face->eval_u(e, closest_u(e, face->to3d(p), &d2), NULL, tangent, NULL);
        return SQ_OK;
    }
    SQCAD_CATCH(err)
}

} // extern "C"
