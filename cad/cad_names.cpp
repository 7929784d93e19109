// semquad cad/ — the names a STEP file gives its faces and edges (cad.h,
// "Names"): the name of each face (ADVANCED_FACE, FACE_SURFACE) and edge
// (EDGE_CURVE) item, the same names OCCT's XDE reader attaches to sub-shape
// labels with read.stepcaf.subshapes.name, taken here from the very reader
// that made the model's shape, without a second read into an XCAF
// document.  The reader's own fixing (ShapeFix, on a shell of several
// faces) replaces the shapes it made of the items, so the named shapes are
// matched by place: a face by its centre of mass and area, an edge by its
// middle point; a face that semquad's healing rebuilt keeps its names too.
#include "cad_private.hxx"

#include <BRepAdaptor_Curve.hxx>
#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>
#include <STEPControl_Reader.hxx>
#include <StepData_StepModel.hxx>
#include <StepShape_EdgeCurve.hxx>
#include <StepShape_Face.hxx>
#include <TCollection_HAsciiString.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TransferBRep.hxx>
#include <Transfer_TransientProcess.hxx>
#include <XSControl_TransferReader.hxx>
#include <XSControl_WorkSession.hxx>

#include <cctype>
#include <cmath>

namespace {

// The file's name as a group name: characters other than [A-Za-z0-9_-]
// become '_', at most 63 of them; "" and "NONE" (what exporters write for
// none) are no name.
std::string group_name(const Handle(TCollection_HAsciiString) &s)
{
    std::string in = s.IsNull() ? "" : s->ToCString(), out;
    if (in == "NONE") return out;
    for (char c : in) {
        if (out.size() == 63) break;
        out += std::isalnum((unsigned char)c) || c == '_' || c == '-' ? c : '_';
    }
    return out;
}

// The middle of an edge's curve (in its parameter).
gp_Pnt edge_middle(const TopoDS_Edge &e)
{
    BRepAdaptor_Curve c(e);
    return c.Value(0.5 * (c.FirstParameter() + c.LastParameter()));
}

// Centre of mass and area of a face.
double face_centre(const TopoDS_Shape &face, gp_Pnt *centre)
{
    GProp_GProps g;
    BRepGProp::SurfaceProperties(face, g);
    *centre = g.CentreOfMass();
    return g.Mass();
}

} // namespace

void sqcad::read_step_names(STEPControl_Reader &reader, double scale, cad_model *m)
{
    Handle(StepData_StepModel) model = reader.StepModel();
    Handle(Transfer_TransientProcess) tp = reader.WS()->TransferReader()->TransientProcess();
    for (int i = 1; !model.IsNull() && !tp.IsNull() && i <= model->NbEntities(); ++i) {
        Handle(StepRepr_RepresentationItem) item =
            Handle(StepRepr_RepresentationItem)::DownCast(model->Value(i));
        bool face = !item.IsNull() && item->IsKind(STANDARD_TYPE(StepShape_Face));
        if (!face && (item.IsNull() || !item->IsKind(STANDARD_TYPE(StepShape_EdgeCurve)))) continue;
        std::string name = group_name(item->Name());
        TopoDS_Shape s = name.empty() ? TopoDS_Shape() : TransferBRep::ShapeResult(tp, item);
        if (s.IsNull() || s.ShapeType() != (face ? TopAbs_FACE : TopAbs_EDGE)) continue;
        gp_Pnt p;
        double area = face ? face_centre(s, &p) * scale * scale : 0.0;
        if (!face) p = edge_middle(TopoDS::Edge(s));
        p.SetXYZ(p.XYZ() * scale);
        (face ? m->named_faces : m->named_edges).push_back({p, area, name});
    }
}

void sqcad::resolve_names(cad_model *m)
{
    int nf = m->faces.Extent();
    m->face_name.assign((size_t)nf, std::string());
    for (int i = 0; i < nf && !m->named_faces.empty(); ++i) {
        gp_Pnt c;
        double area = face_centre(m->faces(i + 1), &c), tol = 1e-6 * sqcad::face_size(TopoDS::Face(m->faces(i + 1)));
        for (const auto &n : m->named_faces)
            if (n.at.Distance(c) <= tol && std::fabs(n.area - area) <= 1e-6 * area)
                m->face_name[(size_t)i] = n.name;
    }
}

std::string sqcad::edge_name(const cad_model *m, const TopoDS_Edge &e, double tol)
{
    if (m->named_edges.empty()) return std::string();
    gp_Pnt mid = edge_middle(e);
    const std::string *best = nullptr;
    double dbest = tol;
    for (const auto &n : m->named_edges) {
        double d = n.at.Distance(mid);
        if (d <= dbest) dbest = d, best = &n.name;
    }
    return best ? *best : std::string();
}

extern "C" {

const char *cad_model_face_name(const cad_model *model, int index)
{
    if (!model || index < 0 || index >= (int)model->face_name.size()) return NULL;
    const std::string &s = model->face_name[(size_t)index];
    return s.empty() ? NULL : s.c_str();
}

} // extern "C"
