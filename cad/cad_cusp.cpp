// semquad cad/ — blunting the cusps of a planar face within the healing
// tolerance (docs/healing.md, "Cusps").
//
// A cusp: two consecutive edges of a loop tangent at their common vertex,
// the face between them (interior angle 0).  A quad conforming to both
// curves has a zero Jacobian at the tip, so the exact face has no valid
// quad mesh; but near the tip the two curves are closer than the healing
// tolerance, i.e. the face there is thinner than its own uncertainty.
// Each cusp is cut where the curves part by the tolerance: P on the
// outgoing edge whose distance to the incoming edge is tol (point-to-curve
// distance by GeomAPI_ProjectPointOnCurve, its root by math_BracketedRoot),
// Q the foot of P on the incoming edge; both edges are trimmed there
// (BRepBuilderAPI_MakeEdge on their own curves, keeping their far
// vertices) and joined by the segment QP, of length tol.  What is removed
// is the sliver between the two curves, nowhere wider than tol: its area
// is below tol times the length cut.  A cusp whose curves stay closer than
// tol over half an edge, or a tolerance below CAD_CUSP_MIN_SEGMENT of the
// face's size, leaves the face as it is (the mesher then refuses it).
#include "cad_private.hxx"

#include <BRepBuilderAPI_Copy.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepGProp.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <GCPnts_AbscissaPoint.hxx>
#include <GeomAPI_ProjectPointOnCurve.hxx>
#include <GProp_GProps.hxx>
#include <GeomAdaptor_Curve.hxx>
#include <Geom_Curve.hxx>
#include <ShapeExtend_WireData.hxx>
#include <ShapeFix_Edge.hxx>
#include <TopExp.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Iterator.hxx>
#include <TopoDS_Vertex.hxx>
#include <TopoDS_Wire.hxx>
#include <math_BracketedRoot.hxx>
#include <math_Function.hxx>

#include <cmath>
#include <vector>

namespace {

// An edge of a loop with its 3D curve, parameters in the direction of
// travel (t0 at its first vertex, t1 at its last).
struct travel_edge {
    TopoDS_Edge e;
    Handle(Geom_Curve) c;
    double t0 = 0, t1 = 0;
    // the cut at either end, if any: new parameter and vertex
    bool cut0 = false, cut1 = false;
    double s0 = 0, s1 = 0;
    TopoDS_Vertex v0, v1;
};

bool make_travel_edge(const TopoDS_Edge &e, travel_edge &te)
{
    double a, b;
    te.e = e;
    te.c = BRep_Tool::Curve(e, a, b);
    if (te.c.IsNull()) return false;
    const bool fwd = e.Orientation() != TopAbs_REVERSED;
    te.t0 = fwd ? a : b, te.t1 = fwd ? b : a;
    return true;
}

// Tangent along the direction of travel at parameter t.
gp_Vec travel_tangent(const travel_edge &te, double t)
{
    gp_Pnt p;
    gp_Vec d;
    te.c->D1(t, p, d);
    return te.t1 > te.t0 ? d : -d;
}

// Distance from the point of the outgoing edge at travel fraction u to the
// incoming edge, minus tol: its root is where the two curves part by tol.
class parting : public math_Function {
public:
    parting(const travel_edge &in, const travel_edge &out, double tol)
        : in_(in), out_(out), tol_(tol)
    {
    }
    Standard_Boolean Value(const Standard_Real u, Standard_Real &f) override
    {
        GeomAPI_ProjectPointOnCurve pj(point(u), in_.c, std::min(in_.t0, in_.t1),
                                       std::max(in_.t0, in_.t1));
        if (pj.NbPoints() == 0) return Standard_False;
        f = pj.LowerDistance() - tol_;
        return Standard_True;
    }
    gp_Pnt point(double u) const { return out_.c->Value(out_.t0 + u * (out_.t1 - out_.t0)); }

private:
    const travel_edge &in_, &out_;
    double tol_;
};

double arc_length(const travel_edge &te, double a, double b)
{
    return GCPnts_AbscissaPoint::Length(GeomAdaptor_Curve(te.c), std::min(a, b), std::max(a, b));
}

// Blunt the cusp between `in` (ending at the vertex) and `out` (starting
// there), if the face lies between them and the cut stays within the first
// half of both edges; fills the cuts and the record.  False: no cusp to
// blunt there.
bool blunt_one(travel_edge &in, travel_edge &out, const gp_Dir &normal, double tol, double span,
               sqcad::heal_record &r)
{
    const gp_Vec tin = travel_tangent(in, in.t1), tout = travel_tangent(out, out.t0);
    if (tin.Magnitude() <= gp::Resolution() || tout.Magnitude() <= gp::Resolution())
        return false;
    // tangent as far as the face is resolved (cad.h, CAD_CUSP_REL_TOL): the
    // same test as the mesher's refusal (src/face/face_info.c)
    const double shorter = std::min(arc_length(in, in.t0, in.t1), arc_length(out, out.t0, out.t1));
    if (tout.Angle(-tin) * shorter >= span) return false;
    // first travel fraction 2^-k of the outgoing edge (k from 52 down) where
    // the curves are more than tol apart: the root is bracketed below it
    parting f(in, out, tol);
    double hi = 0, g;
    for (int k = 52; k >= 1 && hi == 0; --k)
        if (f.Value(std::ldexp(1.0, -k), g) && g > 0) hi = std::ldexp(1.0, -k);
    if (hi == 0 || hi == std::ldexp(1.0, -52)) return false;
    math_BracketedRoot root(f, 0.5 * hi, hi, 1e-9 * hi);
    if (!root.IsDone()) return false;
    const double tp = out.t0 + root.Root() * (out.t1 - out.t0);
    const gp_Pnt P = out.c->Value(tp), V = out.c->Value(out.t0);
    GeomAPI_ProjectPointOnCurve pj(P, in.c, std::min(in.t0, in.t1), std::max(in.t0, in.t1));
    if (pj.NbPoints() == 0) return false;
    const double tq = pj.LowerDistanceParameter();
    if (std::fabs(tq - in.t1) > 0.5 * std::fabs(in.t1 - in.t0)) return false;
    const gp_Pnt Q = in.c->Value(tq);
    // a horn of the face: seen from the outward normal, the incoming edge
    // lies counter-clockwise of the outgoing one, within 180 degrees (the
    // face is on the left of travel); a horn of the outside (360 degrees)
    // is meshed as it is
    if (gp_Vec(V, P).Crossed(gp_Vec(V, Q)).Dot(gp_Vec(normal)) <= 0) return false;
    in.cut1 = true, in.s1 = tq, in.v1 = BRepBuilderAPI_MakeVertex(Q);
    out.cut0 = true, out.s0 = tp, out.v0 = BRepBuilderAPI_MakeVertex(P);
    r.kind = "cusp";
    r.size = P.Distance(Q);
    r.at[0] = V.X(), r.at[1] = V.Y(), r.at[2] = V.Z();
    r.cut[0] = arc_length(in, tq, in.t1);
    r.cut[1] = arc_length(out, out.t0, tp);
    return true;
}

// The edge on its own curve between its (possibly cut) ends, oriented as
// before; its uncut ends keep their vertices (shared with the neighbours).
TopoDS_Edge trimmed(const travel_edge &te)
{
    TopoDS_Vertex v0 = te.cut0 ? te.v0 : TopExp::FirstVertex(te.e, Standard_True);
    TopoDS_Vertex v1 = te.cut1 ? te.v1 : TopExp::LastVertex(te.e, Standard_True);
    const double s0 = te.cut0 ? te.s0 : te.t0, s1 = te.cut1 ? te.s1 : te.t1;
    const bool fwd = te.t1 > te.t0;
    BRepBuilderAPI_MakeEdge mk = fwd ? BRepBuilderAPI_MakeEdge(te.c, v0, v1, s0, s1)
                                     : BRepBuilderAPI_MakeEdge(te.c, v1, v0, s1, s0);
    if (!mk.IsDone()) return TopoDS_Edge();
    TopoDS_Edge e = mk.Edge();
    if (!fwd) e.Reverse();
    return e;
}

// The loop with its cusps blunted (records appended to out); the loop
// itself if it has none or if only the records are wanted (!build); a null
// wire if the new edges cannot be built.
TopoDS_Wire blunt_wire(const TopoDS_Wire &wire, const TopoDS_Face &face, int w,
                       const gp_Dir &normal, double tol, double span, bool build,
                       std::vector<sqcad::heal_record> &out, std::vector<TopoDS_Edge> &made)
{
    std::vector<travel_edge> E;
    for (BRepTools_WireExplorer wx(wire, face); wx.More(); wx.Next()) {
        E.emplace_back();
        if (!make_travel_edge(wx.Current(), E.back())) return wire;
    }
    const int n = (int)E.size();
    const size_t before = out.size();
    for (int i = 0; n > 1 && i < n; ++i) {
        const int prev = i == 0 ? n - 1 : i - 1;
        sqcad::heal_record r;
        if (!blunt_one(E[(size_t)prev], E[(size_t)i], normal, tol, span, r)) continue;
        r.wire = w, r.edge_a = prev, r.edge_b = i;
        out.push_back(r);
    }
    if (out.size() == before || !build) return wire;
    Handle(ShapeExtend_WireData) wd = new ShapeExtend_WireData;
    for (int i = 0; i < n; ++i) {
        const travel_edge &te = E[(size_t)i], &next = E[(size_t)((i + 1) % n)];
        TopoDS_Edge e = te.cut0 || te.cut1 ? trimmed(te) : te.e;
        if (e.IsNull()) return TopoDS_Wire();
        if (te.cut0 || te.cut1) made.push_back(e);
        wd->Add(e);
        if (!te.cut1) continue;
        BRepBuilderAPI_MakeEdge seg(te.v1, next.v0);
        if (!seg.IsDone()) return TopoDS_Wire();
        made.push_back(seg.Edge());
        wd->Add(seg.Edge());
    }
    return wd->Wire();
}

// The face's wires, each blunted (build) or only analysed; false if a
// new edge cannot be built.
bool blunt_wires(const TopoDS_Face &face, const gp_Dir &normal, double tol, bool build,
                 TopoDS_Face &res, std::vector<sqcad::heal_record> &out,
                 std::vector<TopoDS_Edge> &made)
{
    BRep_Builder b;
    GProp_GProps boundary;
    BRepGProp::LinearProperties(face, boundary);
    const double span = CAD_CUSP_REL_TOL * boundary.Mass();
    int w = 0;
    for (TopoDS_Iterator it(face); it.More(); it.Next()) {
        if (it.Value().ShapeType() != TopAbs_WIRE) continue;
        TopoDS_Wire nw = blunt_wire(TopoDS::Wire(it.Value()), face, w++, normal, tol, span, build,
                                    out, made);
        if (nw.IsNull()) return false;
        if (build) b.Add(res, nw);
    }
    return true;
}

} // namespace

namespace sqcad {

TopoDS_Face blunt_cusps(const TopoDS_Face &face, double tol, double prec,
                        std::vector<heal_record> &out)
{
    gp_Pln pln;
    if (!(tol > 0) || !face_plane(face, &pln)) return face;
    const gp_Dir normal = pln.Axis().Direction();
    std::vector<TopoDS_Edge> made;
    const size_t before = out.size();
    TopoDS_Face res;
    if (!blunt_wires(face, normal, tol, false, res, out, made) || out.size() == before ||
        tol < CAD_CUSP_MIN_SEGMENT * face_size(face)) {
        out.resize(before);
        return face;
    }
    out.resize(before);
    // on a copy: the shared vertices of the neighbouring faces keep their
    // tolerances when the new edges' are fixed
    const TopoDS_Face copy = TopoDS::Face(BRepBuilderAPI_Copy(face).Shape());
    res = TopoDS::Face(copy.EmptyCopied());
    if (!blunt_wires(copy, normal, tol, true, res, out, made)) {
        out.resize(before);
        return face;
    }
    // the new edges' p-curves on the plane, vertex tolerances, same parameter
    ShapeFix_Edge fe;
    for (const TopoDS_Edge &e : made) {
        fe.FixAddPCurve(e, res, Standard_False, prec);
        fe.FixVertexTolerance(e, res);
        fe.FixSameParameter(e, res);
    }
    return res;
}

} // namespace sqcad
