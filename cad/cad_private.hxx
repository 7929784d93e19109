// semquad cad/ — private C++ declarations shared by the cad_*.cpp files.
// Never included from C.
#ifndef SQ_CAD_PRIVATE_HXX
#define SQ_CAD_PRIVATE_HXX

#include "cad.h"

#include <Standard_Failure.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>
#include <gp_Pln.hxx>
#include <gp_Pnt.hxx>

#include <exception>
#include <new>
#include <string>
#include <utility>
#include <vector>

class STEPControl_Reader;

namespace sqcad {
// A named face or edge of the file (cad_names.cpp): its centre of mass
// (a face, with its area) or the middle of its curve (an edge).
struct named_place {
    gp_Pnt at;
    double area;
    std::string name;
};

// One defect found on a face, healed or not (cad_heal.cpp).
struct heal_record {
    std::string kind;   // "gap", "connection", "small edge", "order", ...
    int wire = 0;       // wire of the face, in the file's order
    int edge_a = -1, edge_b = -1; // edges of that wire (-1: none)
    double size = 0;    // gap width or edge length, file unit (0: no size)
    double cut[2] = {0, 0}; // "cusp": length cut off edges edge_a and edge_b
    double at[3] = {0, 0, 0};
    std::string defect; // "as read": the kind of defect the fix would leave
};
} // namespace sqcad

struct cad_model {
    TopoDS_Shape shape;
    TopTools_IndexedMapOfShape faces; // 1-based inside OCCT
    std::string path;
    const char *unit = "unknown";
    std::vector<std::string> surface; // per face, type name
    std::vector<int> planar;          // per face, 1 if planar
    int default_face = 0;
    std::string note; // empty: no note
    double uncertainty = 0; // the file's own (STEP), 0 if none
    double heal_tol = 0;    // tolerance healing used, 0: healing off
    std::vector<int> status; // per face, a cad_face_status
    std::vector<std::string> reason; // per face, why it is broken
    std::vector<std::vector<sqcad::heal_record>> heals; // per face, what was healed
    // faces the STEP reader made by splitting one face of the file whose
    // loops cross, each with the reason it is broken
    std::vector<std::pair<TopoDS_Shape, std::string>> split;
    // names the file gives (cad_names.cpp): its named faces and edges by
    // place, and per face its name ("" none)
    std::vector<sqcad::named_place> named_faces, named_edges;
    std::vector<std::string> face_name;
};

namespace sqcad {

// Name of the surface type of a face ("plane", ...).
const char *surface_name(const TopoDS_Face &face);

// True if the face lies in a plane; then *pln is that plane with its axis
// along the face's outward normal (the face orientation applied).
bool face_plane(const TopoDS_Face &face, gp_Pln *pln);

// Longest side of the face's bounding box (geometry only, no triangulation).
double face_size(const TopoDS_Face &face);

// Fill m->status, reason and heals; heal the planar faces whose defects
// are within tol (given: tol is the user's, not capped by the face's size;
// tol <= 0: no healing); a planar face in m->split, or whose loops cross
// or whose holes are not inside its outer loop, is broken.
void heal_model(cad_model *m, double tol, bool given);

// The planar face with every cusp (two consecutive edges tangent at their
// vertex, the face between them) blunted within tol: both edges cut where
// they part by tol and joined by a segment (cad_cusp.cpp); one "cusp"
// record per blunted cusp appended to out.  The face itself if it has no
// cusp that can be blunted within tol.
TopoDS_Face blunt_cusps(const TopoDS_Face &face, double tol, double prec,
                        std::vector<heal_record> &out);

// Names (cad_names.cpp): the STEP items' names, placed in the file's unit
// (scale: the reader's unit to it); then, the model's faces known, each
// face's name; the name of the named edge whose middle is within tol of
// e's ("" if none).
void read_step_names(STEPControl_Reader &reader, double scale, cad_model *m);
void resolve_names(cad_model *m);
std::string edge_name(const cad_model *m, const TopoDS_Edge &e, double tol);

// The OCCT edge under edge `edge` of a face (cad_face.cpp), NULL if out of range.
const TopoDS_Edge *face_edge(const cad_face *face, int edge);

} // namespace sqcad

// Turn the exception being handled into an sq_status (use inside catch (...)).
#define SQCAD_CATCH(err)                                                                           \
    catch (const Standard_Failure &e_) {                                                           \
        return SQ_FAIL((err), SQ_ERR_INTERNAL, "OpenCASCADE: %s: %s", e_.DynamicType()->Name(),    \
                       e_.GetMessageString() ? e_.GetMessageString() : "");                        \
    }                                                                                              \
    SQCAD_CATCH_REST(err)

// The same without the Standard_Failure handler (write your own before it).
#define SQCAD_CATCH_REST(err)                                                                      \
    catch (const std::bad_alloc &) {                                                               \
        return SQ_FAIL((err), SQ_ERR_INTERNAL, "out of memory");                                   \
    }                                                                                              \
    catch (const std::exception &e_) {                                                             \
        return SQ_FAIL((err), SQ_ERR_INTERNAL, "%s", e_.what());                                   \
    }                                                                                              \
    catch (...) {                                                                                  \
        return SQ_FAIL((err), SQ_ERR_INTERNAL, "unknown C++ exception");                           \
    }

#endif
