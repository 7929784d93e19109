// semquad cad/ — reading a CAD file (STEP, IGES, BREP) into a cad_model.
//
// design:
//  1. pick the reader from the file extension (case-insensitive), check the
//     file exists and is not empty;
//  2. read with OpenCASCADE with its messenger silenced (scoped: the printers
//     are restored afterwards), keeping lengths in the file's own unit
//     (STEP: read in millimetres, as Gmsh does, then scaled to the file's
//     unit; IGES: the global section's cascade unit is set to the file's unit);
//  3. enumerate the faces with TopExp::MapShapes and classify their surfaces.
#include "cad_private.hxx"

#include <BRepAdaptor_Surface.hxx>
#include <BRepBndLib.hxx>
#include <BRep_CurveRepresentation.hxx>
#include <BRep_GCurve.hxx>
#include <BRep_TEdge.hxx>
#include <Bnd_Box.hxx>
#include <Geom2d_Curve.hxx>
#include <Geom_Curve.hxx>
#include <Interface_Check.hxx>
#include <Interface_CheckIterator.hxx>
#include <OSD.hxx>
#include <StepBasic_UncertaintyMeasureWithUnit.hxx>
#include <StepShape_Face.hxx>
#include <TransferBRep.hxx>
#include <Transfer_TransientProcess.hxx>
#include <XSControl_TransferReader.hxx>
#include <StepData_StepModel.hxx>
#include <Standard_ErrorHandler.hxx>
#include <TopExp_Explorer.hxx>
#include <XSControl_WorkSession.hxx>
#include <BRepBuilderAPI_Transform.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <GeomLib_IsPlanarSurface.hxx>
#include <Geom_Surface.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <IGESControl_Reader.hxx>
#include <IGESData_GlobalSection.hxx>
#include <IGESData_IGESModel.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <STEPControl_Reader.hxx>
#include <TColStd_SequenceOfAsciiString.hxx>
#include <TopAbs.hxx>
#include <TopExp.hxx>
#include <TopoDS.hxx>
#include <gp_Ax1.hxx>
#include <gp_Trsf.hxx>
#include <gp_Vec.hxx>

#include <sys/stat.h>

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>

namespace {

// Silence OpenCASCADE's default messenger for the lifetime of the object and
// restore its printers afterwards (no lasting change to the process).
class QuietMessenger {
  public:
    QuietMessenger() : msgr_(Message::DefaultMessenger())
    {
        if (!msgr_.IsNull()) {
            saved_ = msgr_->Printers();
            msgr_->ChangePrinters().Clear();
        }
    }
    ~QuietMessenger()
    {
        if (!msgr_.IsNull()) msgr_->ChangePrinters() = saved_;
    }
    QuietMessenger(const QuietMessenger &) = delete;
    QuietMessenger &operator=(const QuietMessenger &) = delete;

  private:
    Handle(Message_Messenger) msgr_;
    Message_SequenceOfPrinters saved_;
};

std::string lower(const std::string &s)
{
    std::string r(s);
    for (char &c : r) c = (char)std::tolower((unsigned char)c);
    return r;
}

std::string extension(const char *path)
{
    const char *slash = std::strrchr(path, '/');
    const char *base = slash ? slash + 1 : path;
    const char *dot = std::strrchr(base, '.');
    return dot ? lower(dot + 1) : std::string();
}

// Unit name of the contract from a length factor in millimetres.
const char *unit_from_mm(double mm)
{
    struct {
        double mm;
        const char *name;
    } const table[] = {{1.0, "mm"},   {1000.0, "m"},     {10.0, "cm"},
                       {25.4, "inch"}, {304.8, "foot"}, {0.001, "micrometre"}};
    for (const auto &t : table)
        if (std::fabs(mm - t.mm) <= 1e-9 * t.mm) return t.name;
    return "unknown";
}

// Millimetres per unit from a STEP unit name ("millimetre", "METRE", "inch",
// ...); <= 0 if unrecognised.
double step_unit_mm(const std::string &name)
{
    std::string n = lower(name);
    if (n.find("inch") != std::string::npos) return 25.4;
    if (n.find("foot") != std::string::npos || n.find("feet") != std::string::npos) return 304.8;
    if (n.find("mile") != std::string::npos) return 1609344.0;
    if (n.find("metre") == std::string::npos && n.find("meter") == std::string::npos) return -1;
    if (n.find("nano") != std::string::npos) return 1e-6;
    if (n.find("micro") != std::string::npos) return 1e-3;
    if (n.find("milli") != std::string::npos) return 1.0;
    if (n.find("centi") != std::string::npos) return 10.0;
    if (n.find("deci") != std::string::npos) return 100.0;
    if (n.find("kilo") != std::string::npos) return 1e6;
    return 1000.0; // plain metre
}

// Millimetres per unit for an IGES unit flag (IGES 5.3, global section
// parameter 14); <= 0 if unknown.
double iges_flag_mm(int flag)
{
    switch (flag) {
    case 1: return 25.4;        // inch
    case 2: return 1.0;         // mm
    case 4: return 304.8;       // foot
    case 5: return 1609344.0;   // mile
    case 6: return 1000.0;      // metre
    case 7: return 1e6;         // km
    case 8: return 0.0254;      // mil
    case 9: return 1e-3;        // micron
    case 10: return 10.0;       // cm
    case 11: return 25.4e-6;    // microinch
    default: return -1;
    }
}

// The reader's healing (ShapeFix) splits a face of the file whose loops
// cross, or whose hole lies outside its outline, into several valid faces:
// meshing one of them would mesh another face than the file's, so each is
// marked (heal_model makes it broken).  to_unit maps the reader's faces to
// the model's (the scaling to the file's unit), NULL if none.
void mark_split_faces(STEPControl_Reader &reader, BRepBuilderAPI_Transform *to_unit, cad_model *m)
{
    Handle(StepData_StepModel) model = reader.StepModel();
    Handle(Transfer_TransientProcess) tp = reader.WS()->TransferReader()->TransientProcess();
    for (int i = 1; !model.IsNull() && !tp.IsNull() && i <= model->NbEntities(); ++i) {
        Handle(StepShape_Face) f = Handle(StepShape_Face)::DownCast(model->Value(i));
        if (f.IsNull()) continue;
        TopoDS_Shape s = TransferBRep::ShapeResult(tp, f);
        int n = 0;
        for (TopExp_Explorer ex(s, TopAbs_FACE); ex.More(); ex.Next()) ++n;
        if (n < 2) continue;
        char buf[300];
        std::snprintf(buf, sizeof buf, "the file's face #%d has loops that cross or a hole outside "
                      "its outer loop (OpenCASCADE's reader split it into %d faces)",
                      model->IdentLabel(f), n);
        for (TopExp_Explorer ex(s, TopAbs_FACE); ex.More(); ex.Next())
            m->split.push_back(std::make_pair(
                to_unit ? to_unit->ModifiedShape(ex.Current()) : ex.Current(), std::string(buf)));
    }
}

sq_status read_step(const char *path, cad_model *m, sq_error *err)
{
    STEPControl_Reader reader;
    if (reader.ReadFile(path) != IFSelect_RetDone)
        return SQ_FAIL(err, SQ_ERR_INPUT, "%s: not a readable STEP file", path);
    TColStd_SequenceOfAsciiString lengths, angles, solids;
    reader.FileUnits(lengths, angles, solids);
    double mm = -1;
    for (int i = 1; i <= lengths.Length() && mm <= 0; ++i)
        mm = step_unit_mm(lengths(i).ToCString());
    // Read in millimetres, the reader's own unit, as Gmsh does: the reader's
    // healing (ShapeFix_Face's FixSplitFace) splits a face or not on the
    // round-off of the coordinates, so reading in another unit may list
    // another number of faces than Gmsh (as_tie_rod.step, inch: 67, not 68).
    // The shape is then scaled to the file's unit.
    m->unit = mm > 0 ? unit_from_mm(mm) : "mm"; // unknown unit: millimetres
    Handle(StepData_StepModel) model = reader.StepModel();
    for (int i = 1; !model.IsNull() && i <= model->NbEntities(); ++i) {
        Handle(StepBasic_UncertaintyMeasureWithUnit) u =
            Handle(StepBasic_UncertaintyMeasureWithUnit)::DownCast(model->Value(i));
        if (!u.IsNull() && std::isfinite(u->ValueComponent()))
            m->uncertainty = std::max(m->uncertainty, u->ValueComponent());
    }
    if (reader.NbRootsForTransfer() <= 0)
        return SQ_FAIL(err, SQ_ERR_INPUT, "%s: STEP file holds no shape", path);
    reader.TransferRoots();
    if (reader.NbShapes() <= 0) {
        // The reader's own first failure says why (an unresolved reference,
        // an unknown entity type, ...).
        std::string why;
        Interface_CheckIterator checks = reader.WS()->ModelCheckList();
        for (checks.Start(); checks.More() && why.empty(); checks.Next())
            if (checks.Value()->HasFailed()) why = checks.Value()->CFail(1);
        return SQ_FAIL(err, SQ_ERR_INPUT, "%s: no shape could be read from the STEP file%s%s%s",
                       path, why.empty() ? "" : " (", why.c_str(), why.empty() ? "" : ")");
    }
    m->shape = reader.OneShape();
    if (!(mm > 0) || mm == 1.0) {
        mark_split_faces(reader, NULL, m);
        sqcad::read_step_names(reader, 1.0, m);
        return SQ_OK;
    }
    gp_Trsf scale;
    scale.SetScale(gp_Pnt(0, 0, 0), 1.0 / mm);
    BRepBuilderAPI_Transform to_unit(m->shape, scale, Standard_True);
    m->shape = to_unit.Shape();
    mark_split_faces(reader, &to_unit, m);
    sqcad::read_step_names(reader, 1.0 / mm, m);
    return SQ_OK;
}

sq_status read_iges(const char *path, cad_model *m, sq_error *err)
{
    IGESControl_Reader reader;
    if (reader.ReadFile(path) != IFSelect_RetDone)
        return SQ_FAIL(err, SQ_ERR_INPUT, "%s: not a readable IGES file", path);
    Handle(IGESData_IGESModel) model = reader.IGESModel();
    if (model.IsNull()) return SQ_FAIL(err, SQ_ERR_INPUT, "%s: not a readable IGES file", path);
    IGESData_GlobalSection gs = model->GlobalSection();
    double mm = iges_flag_mm(gs.UnitFlag());
    if (mm <= 0 && !gs.UnitName().IsNull()) mm = step_unit_mm(gs.UnitName()->ToCString());
    if (mm <= 0 && !gs.UnitName().IsNull()) {
        std::string n = lower(gs.UnitName()->ToCString());
        if (n == "mm") mm = 1;
        else if (n == "m") mm = 1000;
        else if (n == "cm") mm = 10;
        else if (n == "in") mm = 25.4;
        else if (n == "ft") mm = 304.8;
    }
    if (mm > 0) {
        gs.SetCascadeUnit(mm); // keep lengths in the file's unit
        model->SetGlobalSection(gs);
        m->unit = unit_from_mm(mm);
    } else {
        m->unit = "mm";
    }
    if (reader.NbRootsForTransfer() <= 0)
        return SQ_FAIL(err, SQ_ERR_INPUT, "%s: IGES file holds no shape", path);
    reader.TransferRoots();
    if (reader.NbShapes() <= 0)
        return SQ_FAIL(err, SQ_ERR_INPUT, "%s: no shape could be read from the IGES file", path);
    m->shape = reader.OneShape();
    return SQ_OK;
}

sq_status read_brep(const char *path, cad_model *m, sq_error *err)
{
    BRep_Builder builder;
    TopoDS_Shape shape;
    if (!BRepTools::Read(shape, path, builder) || shape.IsNull())
        return SQ_FAIL(err, SQ_ERR_INPUT, "%s: not a readable BREP file", path);
    m->shape = shape;
    m->unit = "unknown";
    return SQ_OK;
}

bool finite(const gp_Pnt &p)
{
    return std::isfinite(p.X()) && std::isfinite(p.Y()) && std::isfinite(p.Z());
}

bool finite_curve(const Handle(Geom_Curve) &c, double f, double l)
{
    return c.IsNull() || (std::isfinite(f) && std::isfinite(l) && finite(c->Value(f)) &&
                          finite(c->Value(0.5 * (f + l))) && finite(c->Value(l)));
}

bool finite_pcurve(const Handle(Geom2d_Curve) &c, double f, double l)
{
    if (c.IsNull()) return true;
    if (!std::isfinite(f) || !std::isfinite(l)) return false;
    for (double u : {f, 0.5 * (f + l), l}) {
        gp_Pnt2d p = c->Value(u);
        if (!std::isfinite(p.X()) || !std::isfinite(p.Y())) return false;
    }
    return true;
}

// True if an edge's 3D curve and every p-curve it holds are finite at the
// ends and middle of their ranges.
bool finite_edge(const TopoDS_Edge &e)
{
    const Handle(BRep_TEdge) te = Handle(BRep_TEdge)::DownCast(e.TShape());
    if (te.IsNull()) return true;
    for (BRep_ListIteratorOfListOfCurveRepresentation it(te->Curves()); it.More(); it.Next()) {
        const Handle(BRep_GCurve) gc = Handle(BRep_GCurve)::DownCast(it.Value());
        if (gc.IsNull()) continue;
        double f, l;
        gc->Range(f, l);
        if (gc->IsCurve3D() && !finite_curve(gc->Curve3D(), f, l)) return false;
        if (gc->IsCurveOnSurface() && !finite_pcurve(gc->PCurve(), f, l)) return false;
    }
    return true;
}

// Every point, curve and plane of the shape is finite: OpenCASCADE loops
// forever on NaN parameters (a NaN coordinate hung `info`), so nothing may
// touch the geometry before this check.
sq_status check_finite(const TopoDS_Shape &shape, const char *path, sq_error *err)
{
    const char *what = NULL;
    for (TopExp_Explorer ex(shape, TopAbs_VERTEX); ex.More() && !what; ex.Next())
        if (!finite(BRep_Tool::Pnt(TopoDS::Vertex(ex.Current())))) what = "point";
    for (TopExp_Explorer ex(shape, TopAbs_EDGE); ex.More() && !what; ex.Next())
        if (!finite_edge(TopoDS::Edge(ex.Current()))) what = "curve";
    for (TopExp_Explorer ex(shape, TopAbs_FACE); ex.More() && !what; ex.Next()) {
        TopLoc_Location loc;
        Handle(Geom_Surface) srf = BRep_Tool::Surface(TopoDS::Face(ex.Current()), loc);
        double u0, u1, v0, v1;
        if (srf.IsNull()) continue;
        srf->Bounds(u0, u1, v0, v1);
        double u = std::isfinite(u0) && std::isfinite(u1) ? 0.5 * (u0 + u1) : 0.0;
        double v = std::isfinite(v0) && std::isfinite(v1) ? 0.5 * (v0 + v1) : 0.0;
        gp_Pnt p;
        gp_Vec du, dv;
        srf->D1(u, v, p, du, dv);
        if (!finite(p) || !finite(gp_Pnt(du.XYZ())) || !finite(gp_Pnt(dv.XYZ()))) what = "surface";
    }
    if (what)
        return SQ_FAIL(err, SQ_ERR_INPUT, "%s: a %s has a NaN or infinite coordinate", path, what);
    return SQ_OK;
}

// Healing tolerance from the options: the given one, else the largest of
// the file's uncertainty and the shape's vertex and edge tolerances.
double heal_tolerance(const cad_model *m, const cad_read_options *o)
{
    if (!o->heal) return 0;
    if (o->heal_tolerance > 0) return o->heal_tolerance;
    double t = m->uncertainty;
    for (TopExp_Explorer ex(m->shape, TopAbs_VERTEX); ex.More(); ex.Next())
        t = std::max(t, BRep_Tool::Tolerance(TopoDS::Vertex(ex.Current())));
    for (TopExp_Explorer ex(m->shape, TopAbs_EDGE); ex.More(); ex.Next())
        t = std::max(t, BRep_Tool::Tolerance(TopoDS::Edge(ex.Current())));
    return t;
}

sq_status model_read(const char *path, const cad_read_options *opts, cad_model **out,
                     sq_error *err)
{
    std::string ext = extension(path);
    enum { STEP, IGES, BREP } kind;
    if (ext == "step" || ext == "stp") kind = STEP;
    else if (ext == "iges" || ext == "igs") kind = IGES;
    else if (ext == "brep" || ext == "brp") kind = BREP;
    else
        return SQ_FAIL(err, SQ_ERR_INPUT,
                       "%s: unknown CAD file extension (expected .step, .stp, .iges, .igs, "
                       ".brep or .brp)",
                       path);

    struct stat st;
    if (stat(path, &st) != 0)
        return SQ_FAIL(err, SQ_ERR_INPUT, "%s: cannot open: %s", path, std::strerror(errno));
    if (S_ISDIR(st.st_mode)) return SQ_FAIL(err, SQ_ERR_INPUT, "%s: is a directory", path);
    std::FILE *f = std::fopen(path, "rb");
    if (!f) return SQ_FAIL(err, SQ_ERR_INPUT, "%s: cannot open: %s", path, std::strerror(errno));
    int c = std::fgetc(f);
    std::fclose(f);
    if (c == EOF) return SQ_FAIL(err, SQ_ERR_INPUT, "%s: file is empty", path);

    std::unique_ptr<cad_model> m(new cad_model);
    m->path = path;
    {
        QuietMessenger quiet;
        sq_status s = kind == STEP   ? read_step(path, m.get(), err)
                      : kind == IGES ? read_iges(path, m.get(), err)
                                     : read_brep(path, m.get(), err);
        if (s != SQ_OK) return s;
    }
    if (m->shape.IsNull()) return SQ_FAIL(err, SQ_ERR_INPUT, "%s: no shape in the file", path);
    SQ_TRY(check_finite(m->shape, path, err));
    TopExp::MapShapes(m->shape, TopAbs_FACE, m->faces);
    int nf = m->faces.Extent();
    if (nf <= 0) return SQ_FAIL(err, SQ_ERR_INPUT, "%s: the file holds no face", path);

    int nplanar = 0, first_planar = -1;
    for (int i = 0; i < nf; ++i) {
        const TopoDS_Face &face = TopoDS::Face(m->faces(i + 1));
        m->surface.push_back(sqcad::surface_name(face));
        int p = sqcad::face_plane(face, nullptr) ? 1 : 0;
        m->planar.push_back(p);
        if (p) {
            ++nplanar;
            if (first_planar < 0) first_planar = i;
        }
    }
    if (nplanar == 1) {
        m->default_face = first_planar;
    } else {
        m->default_face = 0;
        char buf[256];
        if (nplanar == 0)
            std::snprintf(buf, sizeof buf, "no planar face among %d faces; face 0 (%s) by default",
                          nf, m->surface[0].c_str());
        else
            std::snprintf(buf, sizeof buf,
                          "%d planar faces among %d; face 0 by default (choose one with --face)",
                          nplanar, nf);
        m->note = buf;
    }
    sqcad::resolve_names(m.get()); // before healing replaces faces
    m->heal_tol = heal_tolerance(m.get(), opts);
    sqcad::heal_model(m.get(), m->heal_tol, opts->heal_tolerance > 0);
    *out = m.release();
    return SQ_OK;
}

} // namespace

namespace sqcad {

const char *surface_name(const TopoDS_Face &face)
{
    BRepAdaptor_Surface as(face, Standard_False);
    switch (as.GetType()) {
    case GeomAbs_Plane: return "plane";
    case GeomAbs_Cylinder: return "cylinder";
    case GeomAbs_Cone: return "cone";
    case GeomAbs_Sphere: return "sphere";
    case GeomAbs_Torus: return "torus";
    case GeomAbs_BezierSurface: return "bezier";
    case GeomAbs_BSplineSurface: return "bspline";
    case GeomAbs_SurfaceOfRevolution: return "revolution";
    case GeomAbs_SurfaceOfExtrusion: return "extrusion";
    case GeomAbs_OffsetSurface: return "offset";
    default: return "other";
    }
}

double face_size(const TopoDS_Face &face)
{
    Bnd_Box box;
    BRepBndLib::AddOptimal(face, box, Standard_False, Standard_False); // no tolerance added
    if (box.IsVoid()) return 0;
    double x0, y0, z0, x1, y1, z1;
    box.Get(x0, y0, z0, x1, y1, z1);
    return std::max(x1 - x0, std::max(y1 - y0, z1 - z0));
}

bool face_plane(const TopoDS_Face &face, gp_Pln *pln)
{
    BRepAdaptor_Surface as(face, Standard_True);
    gp_Pln p;
    gp_Dir normal; // parametric normal D1U x D1V
    if (as.GetType() == GeomAbs_Plane) {
        p = as.Plane();
        const gp_Ax3 &ax = p.Position();
        normal = ax.XDirection().Crossed(ax.YDirection());
    } else {
        TopLoc_Location loc;
        Handle(Geom_Surface) surf = BRep_Tool::Surface(face, loc);
        if (surf.IsNull()) return false;
        GeomLib_IsPlanarSurface isp(surf, 1e-7 * face_size(face));
        if (!isp.IsPlanar()) return false;
        if (!pln) return true;
        p = isp.Plan().Transformed(loc.Transformation());
        double u = 0.5 * (as.FirstUParameter() + as.LastUParameter());
        double v = 0.5 * (as.FirstVParameter() + as.LastVParameter());
        gp_Pnt pt;
        gp_Vec du, dv;
        as.D1(u, v, pt, du, dv);
        gp_Vec nv = du.Crossed(dv);
        if (nv.Magnitude() <= 1e-300) return false;
        normal = gp_Dir(nv);
    }
    if (!pln) return true;
    if (face.Orientation() == TopAbs_REVERSED) normal.Reverse();
    // The plane with its axis along the outward normal, X kept.
    gp_Dir x = p.Position().XDirection();
    gp_Vec xv = gp_Vec(x) - gp_Vec(normal) * gp_Vec(x).Dot(gp_Vec(normal));
    if (xv.Magnitude() < 1e-12) xv = gp_Vec(normal.IsParallel(gp::DX(), 1e-3) ? gp::DY() : gp::DX());
    *pln = gp_Pln(gp_Ax3(p.Location(), normal, gp_Dir(xv)));
    return true;
}

} // namespace sqcad

extern "C" {

void cad_catch_signals(void) { OSD::SetSignal(OSD_SignalMode_Set, Standard_False); }

void cad_read_options_default(cad_read_options *o)
{
    o->heal = 1;
    o->heal_tolerance = 0;
}

sq_status cad_model_read(const char *path, cad_model **out, sq_error *err)
{
    cad_read_options o;
    cad_read_options_default(&o);
    return cad_model_read_with(path, &o, out, err);
}

sq_status cad_model_read_with(const char *path, const cad_read_options *opts, cad_model **out,
                              sq_error *err)
{
    if (!out) return SQ_FAIL(err, SQ_ERR_USAGE, "cad_model_read: out is NULL");
    *out = NULL;
    if (!path || !*path) return SQ_FAIL(err, SQ_ERR_USAGE, "cad_model_read: no file name");
    if (!opts) return SQ_FAIL(err, SQ_ERR_USAGE, "cad_model_read: no options");
    try {
        OCC_CATCH_SIGNALS
        return model_read(path, opts, out, err);
    }
    catch (const Standard_Failure &e) {
        return SQ_FAIL(err, SQ_ERR_INPUT, "%s: cannot be read (OpenCASCADE %s: %s)", path,
                       e.DynamicType()->Name(), e.GetMessageString() ? e.GetMessageString() : "");
    }
    catch (const std::bad_alloc &) {
        return SQ_FAIL(err, SQ_ERR_INTERNAL, "%s: out of memory while reading", path);
    }
    catch (const std::exception &e) {
        return SQ_FAIL(err, SQ_ERR_INPUT, "%s: cannot be read (%s)", path, e.what());
    }
    catch (...) {
        return SQ_FAIL(err, SQ_ERR_INPUT, "%s: cannot be read (unknown exception)", path);
    }
}

void cad_model_free(cad_model **model)
{
    if (!model || !*model) return;
    try {
        delete *model;
    } catch (...) {
    }
    *model = NULL;
}

const char *cad_model_unit(const cad_model *model) { return model ? model->unit : "unknown"; }

int cad_model_num_faces(const cad_model *model) { return model ? model->faces.Extent() : 0; }

const char *cad_model_face_surface(const cad_model *model, int index)
{
    if (!model || index < 0 || index >= (int)model->surface.size()) return NULL;
    return model->surface[(size_t)index].c_str();
}

int cad_model_face_planar(const cad_model *model, int index)
{
    if (!model || index < 0 || index >= (int)model->planar.size()) return 0;
    return model->planar[(size_t)index];
}

cad_face_status cad_model_face_status(const cad_model *model, int index, const char **reason)
{
    if (reason) *reason = NULL;
    if (!model || index < 0 || index >= (int)model->status.size()) return CAD_FACE_BROKEN;
    if (reason && model->status[(size_t)index] == CAD_FACE_BROKEN)
        *reason = model->reason[(size_t)index].c_str();
    return (cad_face_status)model->status[(size_t)index];
}

double cad_model_heal_tolerance(const cad_model *model) { return model ? model->heal_tol : 0; }

int cad_model_face_num_heals(const cad_model *model, int index)
{
    if (!model || index < 0 || index >= (int)model->heals.size()) return 0;
    return (int)model->heals[(size_t)index].size();
}

int cad_model_face_heal(const cad_model *model, int index, int k, cad_heal *out)
{
    if (!out || k < 0 || k >= cad_model_face_num_heals(model, index)) return -1;
    const sqcad::heal_record &r = model->heals[(size_t)index][(size_t)k];
    out->kind = r.kind.c_str();
    out->defect = r.defect.c_str();
    out->wire = r.wire;
    out->edge_a = r.edge_a;
    out->edge_b = r.edge_b;
    out->size = r.size;
    for (int d = 0; d < 3; ++d)
        out->at[d] = r.at[d];
    out->cut[0] = r.cut[0], out->cut[1] = r.cut[1];
    return 0;
}

sq_status cad_model_transform(cad_model *model, const double axis[3], double angle, double scale,
                              const double t[3], sq_error *err)
{
    if (!model || !axis || !t || !(scale > 0.0))
        return SQ_FAIL(err, SQ_ERR_USAGE, "cad_model_transform: bad arguments (scale %g)", scale);
    try {
        gp_Trsf rot, scl, tr;
        rot.SetRotation(gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(axis[0], axis[1], axis[2])), angle);
        scl.SetScale(gp_Pnt(0, 0, 0), scale);
        tr.SetTranslation(gp_Vec(t[0], t[1], t[2]));
        gp_Trsf all = tr * scl * rot;
        model->shape = BRepBuilderAPI_Transform(model->shape, all, Standard_True).Shape();
        // face by face: the healed faces replace those of the shape
        for (int i = 1; i <= model->faces.Extent(); ++i)
            model->faces.Substitute(
                i, BRepBuilderAPI_Transform(model->faces(i), all, Standard_True).Shape());
        return SQ_OK;
    }
    SQCAD_CATCH(err)
}

int cad_model_default_face(const cad_model *model, const char **note)
{
    if (note) *note = NULL;
    if (!model) return 0;
    if (note && !model->note.empty()) *note = model->note.c_str();
    return model->default_face;
}

} // extern "C"
