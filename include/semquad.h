/* semquad — the public C API of libsemquad.
 *
 * CAD (STEP, IGES, BREP) in, block-structured high-order quadrilateral
 * meshes out.  This header is the whole contract: it names no OpenCASCADE,
 * CGAL or CHOLMOD type, and the `semquad` command uses nothing else.
 *
 * Conventions (those of CHOLMOD and libCEED):
 *   - Every fallible function returns an sq_status (SQ_OK = 0; the other
 *     values are the `semquad` command's exit statuses) and, on failure,
 *     fills the caller's sq_error (last argument, may be NULL) with one line.
 *     The library never prints, never exits and keeps no global state.
 *   - Handles are opaque.  What a function creates (`**out`) the caller
 *     frees with the matching `_free(&h)`, which accepts NULL and NULLs the
 *     handle; a failing create leaves *out NULL.  Strings and arrays handed
 *     over as `char **` or `T **` are freed with sq_free.  Pointers returned
 *     by accessors are borrowed: valid until their handle is freed.
 *   - Options live in one struct, sq_options, initialised by
 *     sq_options_init; fields added later get defaults there, so code that
 *     calls sq_options_init first keeps compiling and meaning the same.
 *   - Methods are chosen by name (sq_options.field, sq_options.road), so
 *     new fields and new roads to quads add names, not functions.
 *
 * Life cycle:  sq_model_open → sq_face_mesh (or sq_face_triangulate,
 * sq_face_field, sq_face_layout for the pipeline's intermediate stages) →
 * accessors / sq_mesh_write → sq_mesh_free → sq_model_free.
 * Several results of one model may live at once; each borrows its model,
 * so free them before the model.  One handle must not be used from two
 * threads at once. */
#ifndef SEMQUAD_H
#define SEMQUAD_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

#if defined(__GNUC__)
#define SQ_API __attribute__((visibility("default")))
#else
#define SQ_API
#endif

#define SEMQUAD_VERSION_MAJOR 0
#define SEMQUAD_VERSION_MINOR 2
#define SEMQUAD_VERSION_PATCH 0

/* "MAJOR.MINOR.PATCH" of the library actually linked (compare with the
 * macros to detect a header/library mismatch).  Never NULL. */
SQ_API const char *sq_version(void);

/* ---- Status and errors ------------------------------------------------- */

typedef enum {
    SQ_OK = 0,
    SQ_ERR_INTERNAL = 1, /* bug, allocation failure, numerical breakdown */
    SQ_ERR_USAGE = 2,    /* bad argument or option value */
    SQ_ERR_INPUT = 3,    /* input file missing, unreadable or not valid CAD */
    SQ_ERR_GEOMETRY = 4, /* geometry not supported or not a valid face */
    SQ_ERR_PATTERN = 5,  /* invalid singularity pattern */
    SQ_ERR_LAYOUT = 6,   /* no valid layout / no valid all-quad mesh */
    SQ_ERR_OUTPUT = 7,   /* output could not be written */
    SQ_ERR_QUALITY = 8,  /* a mesh was made, but its worst quad is below the quality floor
                            (sq_mesh_check_quality) */
    SQ_ERR_PERIODIC = 9  /* periodic edges named that do not match, or none found
                            (sq_options.periodic) */
} sq_status;

typedef struct {
    sq_status code;
    const char *file; /* source file and line where it was raised */
    int line;
    const char *func;
    char msg[512]; /* one line, no trailing newline */
} sq_error;

/* Reset err (NULL-safe) to SQ_OK with an empty message. */
SQ_API void sq_error_clear(sq_error *err);

/* Fill err (if not NULL) with code and a printf-style message, where it
 * was raised, and return code: for callers' own errors and callbacks. */
SQ_API sq_status sq_error_set(sq_error *err, sq_status code, const char *file, int line,
                              const char *func, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 6, 7)))
#endif
    ;

/* Raise an error from the current function; propagate a failing status
 * (the callee filled err). */
#define SQ_FAIL(err, code, ...) sq_error_set((err), (code), __FILE__, __LINE__, __func__, __VA_ARGS__)
#define SQ_TRY(expr)                                                                               \
    do {                                                                                           \
        sq_status sq_try_status_ = (expr);                                                         \
        if (sq_try_status_ != SQ_OK) return sq_try_status_;                                        \
    } while (0)

/* Short name of a status: "ok", "internal error", "usage error", "input
 * error", "unsupported geometry", "invalid singularity pattern", "no valid layout",
 * "output error", "quality below the floor".  Never NULL. */
SQ_API const char *sq_status_name(sq_status code);

/* Free a string or array the library handed over (NULL-safe). */
SQ_API void sq_free(void *p);

/* ---- Messages ---------------------------------------------------------- */

typedef enum {
    SQ_LOG_INFO = 0,     /* a stage done (with its time), what healing fixed */
    SQ_LOG_NOTE = 1,     /* a choice made for the user (default face, fallback road, healing) */
    SQ_LOG_WARNING = 2   /* a result that may not be what was asked for */
} sq_log_level;

/* Called with one line (no newline) as the work proceeds; `data` is
 * sq_options.log_data.  NULL: silent. */
typedef void (*sq_log_fn)(void *data, sq_log_level level, const char *line);

/* Called as a stage that loops advances: `done` of `total` units of
 * `stage`: "trace" (separatrices finished), "mesh" (layout patches
 * filled), "relax" (Newton steps of the most allowed; a relaxation that
 * converges stops short of total), "write" (records of a mesh file
 * written: 0 when it is begun, total when its last is written; nodes and
 * elements for MSH and VTU, edges and quads for Nektar++ XML, quads and
 * boundary sides for SVG; at most about 100 events per file, at the same
 * counts on every run).  A stage may run more than once (a
 * retry, the second road).  `data` is sq_options.progress_data.  NULL:
 * none. */
typedef void (*sq_progress_fn)(void *data, const char *stage, long done, long total);

/* ---- Options ----------------------------------------------------------- */

/* A size the user sets (docs/sizes.md): size h at a source, growing
 * linearly with the distance d from it, h + (ratio - 1) d, up to the far
 * size (sq_options.size).  The mesh's target size h(x) is the minimum of
 * the far size and every source's; a source's ratio is capped by
 * sq_options.size_gradation, so neighbouring cells' sizes stay within that
 * ratio.  Coordinates are in the face's frame (those of `semquad info`).
 * New kinds may be added; the values of these do not change. */
typedef enum {
    SQ_SIZE_EDGE = 1,  /* h on CAD edge `edge` (as semquad info numbers them) */
    SQ_SIZE_POINT = 2, /* h within radius r of point x */
    SQ_SIZE_BOX = 3    /* h inside the box from corner x to corner x1 */
} sq_size_kind;

typedef struct {
    sq_size_kind kind;
    int edge;     /* SQ_SIZE_EDGE */
    double x[2];  /* SQ_SIZE_POINT: the centre; SQ_SIZE_BOX: lower-left corner */
    double x1[2]; /* SQ_SIZE_BOX: upper-right corner */
    double r;     /* SQ_SIZE_POINT: radius (0: the point alone) */
    double h;     /* the size at the source, > 0 */
    double ratio; /* growth ratio away from it, >= 1; 0: size_gradation */
} sq_size_source;

/* A name for boundary curves (docs/formats.md, "Named boundaries"): the
 * curve `edge` (the N of the generic group boundary_N: for one face its
 * CAD edge index as `semquad info` numbers them, for several faces the
 * domain curve's tag as the report lists them), or, with edge = -1, the
 * curve nearest the point (x, y).  Curves with the same name form one
 * group; curves not named keep boundary_N.  name: [A-Za-z0-9_-]+. */
typedef struct {
    int edge;
    double x, y;
    const char *name;
} sq_boundary_name;

/* A name for a face of a domain (docs/domains.md, "Outputs"): the face
 * numbered `face` in the CAD file (as `semquad info` lists them), or, with
 * face = -1, the face holding the point (x, y).  It names the face's group
 * (MSH physical name, Nektar++ face composite, the VTU's face_name, the
 * report's groups) over the file's name; a name another face took gets
 * "_<face number>" (each face is its own group).  name: [A-Za-z0-9_-]+. */
typedef struct {
    int face;
    double x, y;
    const char *name;
} sq_face_name;

/* The characters of a boundary name. */
#define SQ_NAME_CHARS "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789_-"


/* The default of sq_options.size_gradation. */
#define SQ_SIZE_GRADATION 1.3

typedef struct {
    /* Reading (sq_model_open) */
    int heal;              /* 1: heal defects within the tolerance (default); 0: refuse them */
    double heal_tolerance; /* file unit; 0: the file's own uncertainty (default) */

    /* The face's curved triangulation, on which the fields are solved */
    int tri_order;            /* geometry order 1..12; 0: the field's order, at most 12 */
    double tri_size;          /* target edge length; 0: automatic */
    double tri_min_angle_deg; /* 0: the default (sq_face_triangulate) */
    double tri_max_turn_deg;  /* boundary turning per edge; 0: the default */

    /* The field that guides the layout, by name:
     *   "auto"    the guiding field (u, v) = (cos 4θ, sin 4θ) (Marcon 2019),
     *             then the H/θ field of a better pattern when its singular
     *             points are poor (Jezdimirović 2021 §4) — the default;
     *   "htheta"  the H/θ field of `singularities` ("natural" if NULL).
     * Unknown names are SQ_ERR_USAGE. */
    const char *field;
    const char *singularities; /* NULL, "natural", or a pattern file */
    const char *method;        /* "auto" (default), "cg" or "dg" */
    int field_order;           /* spectral order P 1..16; 0: the stage's default */
    int field_grading;         /* 1: grade the triangulation at singular corners (default) */
    int allow_misaligned;      /* 1: trace even when a hole breaks holonomy */
    double merge_distance;     /* separatrix merging, in local sizes; 0: default */

    /* The quads (sq_face_mesh), by road:
     *   "auto"    the layout road, the split road when it fails (default);
     *   "layout"  field → layout → patches (block-structured);
     *   "split"   a triangulation split into quads (never fails a valid face). */
    const char *road;
    int order;          /* element order Q 1..10 (default 4) */
    double size;        /* target quad size; 0: sqrt(area)/8, halved when quads fold */
    int nsizes;         /* user sizes sizes[nsizes] (0: the uniform size alone) */
    const sq_size_source *sizes;
    int nnames;         /* boundary names names[nnames] (0: generic boundary_N) */
    const sq_boundary_name *names;
    /* Periodic boundaries of a face or of several (docs/domains.md): NULL,
     * none; "auto", the pairs of edges that match under a translation or a
     * rotation; "A:B[,C:D...]", those edges (SQ_ERR_PERIODIC if they do not
     * match; of several faces, the domain's boundary curve numbers). The
     * mesh's nodes on B are the images of A's. */
    const char *periodic;
    double size_gradation; /* bound g > 1 of neighbours' size ratio (default 1.3) */
    /* Curvature sizes (docs/sizes.md): N elements per radian of the CAD
     * curves' turning, h = 1 / (N kappa) on a curve, growing away from it
     * as a size source does; 0: none (default) */
    double curvature_elements;
    const char *nodes;  /* "gll" (default) or "equispaced" */
    double max_quads;   /* refuse sizes giving more quads (default 2e7) */
    int nbl;            /* boundary layers on the CAD edges bl_edges[nbl] (0: none) */
    const int *bl_edges;
    double bl_first, bl_ratio; /* first layer thickness, growth ratio (default 1.2) */
    int bl_layers;
    /* The quality floor (sq_mesh_check_quality): the least scaled Jacobian
     * (min det J / max |det J| over a whole quad, proven by Bézier bounds)
     * a mesh may have, in [0, 1]; 0: no floor.  Default SQ_MIN_QUALITY. */
    double min_quality;

    /* A convergence study of the solvers (sq_face_converge): -Δu = 0 with
     * u exact on the boundary, CG and/or DG, orders and sizes */
    const char *study_solution; /* "exp-sin" (default), "re-z5", "poly", "sin-sinh" */
    const char *study_methods;  /* "cg", "dg" or "both" (default) */
    int study_pmin, study_pmax; /* orders; 0: 1 and 12 */
    int study_nsizes;           /* 0: one run per order at the automatic size */
    const double *study_sizes;  /* longest triangle edge of each run */
    int study_geom_order;       /* 0: max(P, 8) capped at 12 */

    /* Messages */
    sq_log_fn log; /* NULL: silent (default) */
    void *log_data;
    sq_progress_fn progress; /* NULL: no progress events (default) */
    void *progress_data;

    /* Large meshes (appended: fields above keep their places) */
    int threads; /* threads for the faces of a domain (sq_model_mesh:
                    each face's field, layout and mesh; the log's lines
                    in face order, progress events only when one face
                    runs at a time), a large mesh's refinement, the
                    quality pass and the MSH text's formatting; 0: the
                    processors online (default).  Files are
                    byte-identical for every count. */
    /* The relaxation's largest mesh (default SQ_RELAX_MAX_QUADS): a layout
     * road mesh of more quads is relaxed with its chords quantized at 2^k
     * times the size, the least k giving at most this many quads, and its
     * quads then split 2 x 2 k times along their own maps (sq_mesh_refine's
     * nested refinement, new boundary nodes on the CAD curves); 0: always
     * relax the whole mesh.  docs/mesh.md, "Large meshes". */
    double relax_max_quads;
    /* Face names (appended): names of a domain's faces over the file's
     * (a mesh of one face has one group, "domain": SQ_ERR_USAGE) */
    int nface_names;
    const sq_face_name *face_names;
} sq_options;

/* The default of sq_options.relax_max_quads: meshes of up to this many
 * quads are relaxed whole (about 4 kB a quad while relaxing). */
#define SQ_RELAX_MAX_QUADS 5e4

/* The default quality floor: the examples' worst quads at the default
 * size lie at 0.057 (naca0012) and above (docs/conventions.md, "Quality"). */
#define SQ_MIN_QUALITY 0.01

/* Fill o with the defaults above.  Call before setting fields. */
SQ_API void sq_options_init(sq_options *o);

/* SQ_ERR_USAGE naming the first bad value (an unknown name, an order out
 * of range, a negative or non-finite length, tolerance or size, boundary
 * layers without thickness...): every stage checks its options, this
 * checks them all before any work. */
SQ_API sq_status sq_options_check(const sq_options *o, sq_error *err);

/* ---- Output files -------------------------------------------------------
 * Every writer (sq_*_write, sq_*_write_report) writes a regular file, all
 * or nothing (a temporary file beside it, renamed when complete), or, for
 * the path "-", standard output (text formats; not STEP).  A path naming a
 * directory, a FIFO, a device or a socket is refused with SQ_ERR_USAGE
 * before anything is written: a rename would replace it with a file. */

/* SQ_ERR_USAGE if path names something other than a regular file, a new
 * file or "-" (check every output before the work that makes it). */
SQ_API sq_status sq_output_check(const char *path, sq_error *err);

/* ---- A CAD model -------------------------------------------------------- */

typedef struct sq_model sq_model;

/* Read a STEP (.step/.stp), IGES (.iges/.igs) or BREP (.brep/.brp) file,
 * by its extension, healing it as opt says (NULL: defaults); opt's logger
 * serves sq_model_info.  SQ_ERR_INPUT if the file cannot be read.  Turns
 * GSL's aborting error handler off and installs OpenCASCADE's signal
 * handlers (OSD::SetSignal), process-wide, so that a hostile file gives an
 * error, not a crash. */
SQ_API sq_status sq_model_open(const char *path, const sq_options *opt, sq_model **out,
                               sq_error *err);
SQ_API void sq_model_free(sq_model **m);

/* Number of faces; faces are numbered 0..n-1 in the file's order. */
SQ_API int sq_model_num_faces(const sq_model *m);

/* The face a command meshes when none is named: the only planar face,
 * else face 0 (*why, if not NULL, then says so; else NULL). */
SQ_API int sq_model_default_face(const sq_model *m, const char **why);

/* The file's length unit ("mm", "m", "inch", ...) and healing tolerance. */
SQ_API const char *sq_model_unit(const sq_model *m);
SQ_API double sq_model_heal_tolerance(const sq_model *m);

/* Status of face `face`: "ok", "healed", "not planar" or "broken"; *reason
 * (if not NULL) says why a face is broken (else NULL).  NULL when face is
 * out of range. */
SQ_API const char *sq_model_face_status(const sq_model *m, int face, const char **reason);

/* What the file holds (`semquad info`): every face (face < 0) or one, as
 * text (json = 0) or JSON (json = 1), in *text (sq_free it). */
SQ_API sq_status sq_model_info(const sq_model *m, int face, int json, char **text, sq_error *err);

/* One line saying what healing fixed on `face` (*text NULL if nothing). */
SQ_API sq_status sq_model_heal_summary(const sq_model *m, int face, char **text, sq_error *err);

/* ---- Stages of one face -------------------------------------------------
 * Each computes one stage of the pipeline on face `face` of m (-1: the
 * default face) and hands over a result.  Every result can describe itself
 * as the `semquad` command prints it (sq_*_describe, text for sq_free),
 * write its outputs (format from the path's extension) and its JSON report. */

typedef struct sq_triangles sq_triangles;   /* curved triangulation */
typedef struct sq_field sq_field;           /* guiding or H/θ field, singular points */
typedef struct sq_quad_layout sq_quad_layout; /* quad layout (patches) */
typedef struct sq_mesh sq_mesh;             /* high-order quad mesh */

/* The face a result belongs to. */
SQ_API int sq_triangles_face(const sq_triangles *t);
SQ_API int sq_field_face(const sq_field *f);
SQ_API int sq_quad_layout_face(const sq_quad_layout *l);
SQ_API int sq_mesh_face(const sq_mesh *m);

/* Curved triangulation of order opt->tri_order (`semquad triangulate`).
 * Writes .vtu and .svg. */
SQ_API sq_status sq_face_triangulate(const sq_model *m, int face, const sq_options *opt,
                                     sq_triangles **out, sq_error *err);
SQ_API void sq_triangles_free(sq_triangles **t);
SQ_API int sq_triangles_count(const sq_triangles *t);
SQ_API sq_status sq_triangles_describe(const sq_triangles *t, char **text, sq_error *err);
SQ_API sq_status sq_triangles_write(const sq_triangles *t, const char *path, sq_error *err);
SQ_API sq_status sq_triangles_write_report(const sq_triangles *t, const char *path,
                                           sq_error *err);

/* The field and its singular points (`semquad field`): opt->field and
 * opt->singularities choose it (the guiding field unless a pattern is
 * given).  Writes .vtu and .svg. */
SQ_API sq_status sq_face_field(const sq_model *m, int face, const sq_options *opt,
                               sq_field **out, sq_error *err);
SQ_API void sq_field_free(sq_field **f);
/* Singular points: n of them; xy[2k], xy[2k+1] in the face's frame and
 * valence[k] (3, 5, ...: the quads that meet there).  Borrowed. */
SQ_API int sq_field_num_singular_points(const sq_field *f);
SQ_API const double *sq_field_singular_xy(const sq_field *f);
SQ_API const int *sq_field_singular_valence(const sq_field *f);
SQ_API sq_status sq_field_describe(const sq_field *f, char **text, sq_error *err);
SQ_API sq_status sq_field_write(const sq_field *f, const char *path, sq_error *err);
SQ_API sq_status sq_field_write_report(const sq_field *f, const char *path, sq_error *err);

/* The quad layout (`semquad layout`).  SQ_ERR_LAYOUT when no valid layout
 * was found: *out then still holds the last one (to draw and report), and
 * the caller frees it in every case.  Writes .svg (the layout) and .step
 * (the face split into its patches, in the file's 3D frame). */
SQ_API sq_status sq_face_layout(const sq_model *m, int face, const sq_options *opt,
                                sq_quad_layout **out, sq_error *err);
SQ_API void sq_quad_layout_free(sq_quad_layout **l);
SQ_API int sq_quad_layout_num_patches(const sq_quad_layout *l);
SQ_API int sq_quad_layout_num_singular_points(const sq_quad_layout *l);
SQ_API sq_status sq_quad_layout_describe(const sq_quad_layout *l, char **text, sq_error *err);
SQ_API sq_status sq_quad_layout_write(const sq_quad_layout *l, const char *path, sq_error *err);
SQ_API sq_status sq_quad_layout_write_report(const sq_quad_layout *l, const char *path,
                                             sq_error *err);

/* ---- The mesh ----------------------------------------------------------- */

/* Mesh face `face` with quads of order opt->order (`semquad mesh`). */
SQ_API sq_status sq_face_mesh(const sq_model *m, int face, const sq_options *opt, sq_mesh **out,
                              sq_error *err);
SQ_API void sq_mesh_free(sq_mesh **m);

/* Mesh faces faces[0..nfaces-1] of m (faces NULL or nfaces 0: every
 * planar face that is not broken) as one conforming mesh (docs/domains.md):
 * one face is sq_face_mesh; faces sharing a curve (the same CAD edge, or
 * coincident edges of unsewn faces) share its nodes, high-order ones
 * included.  Nodes in the first face's frame (the faces must lie in one
 * plane: SQ_ERR_GEOMETRY otherwise); sq_mesh_quad_faces gives each quad's
 * face; boundary tags number the domain's boundary curves (the report
 * names each curve's face and edge); the writers give each face its own
 * group.  SQ_ERR_LAYOUT if the faces' meshes do not conform. */
SQ_API sq_status sq_model_mesh(const sq_model *m, const int *faces, int nfaces,
                               const sq_options *opt, sq_mesh **out, sq_error *err);
/* Faces of the mesh (1 for sq_face_mesh's), and the CAD face of each quad
 * (NULL for one face: every quad is on sq_mesh_face).  Borrowed. */
SQ_API int sq_mesh_num_faces(const sq_mesh *m);
SQ_API const int *sq_mesh_quad_faces(const sq_mesh *m);

/* Element order Q; each quad has (Q+1)^2 nodes. */
SQ_API int sq_mesh_order(const sq_mesh *m);
/* "layout" or "split": the road that made the mesh; "domain" for a mesh
 * of several faces (its report gives each face's road). */
SQ_API const char *sq_mesh_road(const sq_mesh *m);

/* Nodes: xyz[3k..3k+2], in the mesh's frame (sq_mesh_frame); for a planar
 * face its plane's frame, so z = 0.  Borrowed; made on the first call (NULL
 * if memory runs out). */
SQ_API int sq_mesh_num_nodes(const sq_mesh *m);
SQ_API const double *sq_mesh_nodes(const sq_mesh *m);
/* The frame: origin[3], xdir[3], ydir[3] in the file's coordinates; the
 * file's point of node k is origin + x xdir + y ydir (+ z xdir × ydir). */
SQ_API void sq_mesh_frame(const sq_mesh *m, double origin[3], double xdir[3], double ydir[3]);

/* Quads: nodes[(Q+1)^2 q + (Q+1) j + i] is node (i, j) of quad q,
 * 0 <= i, j <= Q; (0,0), (Q,0), (Q,Q), (0,Q) its corners counter-
 * clockwise; side k joins corner k to corner k+1.  Nodes along a side at
 * Gauss–Lobatto–Legendre or equispaced parameters (opt->nodes).  Borrowed. */
SQ_API int sq_mesh_num_quads(const sq_mesh *m);
SQ_API const int *sq_mesh_quads(const sq_mesh *m);

/* Boundary: n element sides, side[3s..3s+2] = quad, local side 0..3, and
 * the CAD edge of the face it lies on (its tag: 0..sq_mesh_num_tags-1,
 * the face's edges in `semquad info` order).  Borrowed. */
SQ_API int sq_mesh_num_boundary_sides(const sq_mesh *m);
SQ_API const int *sq_mesh_boundary_sides(const sq_mesh *m);
SQ_API int sq_mesh_num_tags(const sq_mesh *m);

/* Per-quad quality, nquads values each: the scaled Jacobian (min det J /
 * max |det J| over the whole quad, a lower bound proven by the Bézier
 * coefficients of det J (Johnen, Remacle & Geuzaine 2013), within 2e-6 of
 * the exact value unless a cap stopped its refinement (the report's
 * jacobian_capped); > 0 for a quad proven valid) and η (1 − max corner
 * angle deviation from 90° / 90°).  Borrowed. */
SQ_API const double *sq_mesh_scaled_jacobians(const sq_mesh *m);
SQ_API const double *sq_mesh_eta(const sq_mesh *m);

/* SQ_OK if the mesh's worst scaled Jacobian reaches opt->min_quality
 * (or that is 0; opt NULL: the default floor), else SQ_ERR_QUALITY with one
 * line naming the worst quad (its index, centre and scaled Jacobian) and
 * what made it (the road, its patch, the CAD edge under it, boundary
 * layers).  sq_face_mesh returns SQ_OK for a mesh below the floor, so the
 * caller can write it first: the command writes every output, then exits
 * with this status. */
SQ_API sq_status sq_mesh_check_quality(const sq_mesh *m, const sq_options *opt, sq_error *err);

/* The area the quads cover: the sum over quads of the integral of det J
 * (Gauss quadrature, exact for the element maps); compare with the face's. */
SQ_API double sq_mesh_area(const sq_mesh *m);

/* The report (docs/formats.md: counts, quality, field, layout, timings)
 * as JSON text in *json (sq_free it), or written to a file. */
SQ_API sq_status sq_mesh_report(const sq_mesh *m, char **json, sq_error *err);
SQ_API sq_status sq_mesh_write_report(const sq_mesh *m, const char *path, sq_error *err);

/* The one-line summary the command prints ("320 quads, order 4, ..."). */
SQ_API sq_status sq_mesh_describe(const sq_mesh *m, char **text, sq_error *err);

/* Write the mesh; the format from the extension: .msh (Gmsh MSH 4.1),
 * .xml (Nektar++), .vtu (VTK), .svg (a picture).  Nothing is left at path
 * on failure. */
SQ_API sq_status sq_mesh_write(const sq_mesh *m, const char *path, sq_error *err);
/* The same in the format named ("msh", "xml", "vtu" or "svg"; NULL: by
 * the extension; "msh-binary": binary MSH 4.1, the same groups, nodes and
 * elements as "msh"; "xml-compressed": Nektar++'s compressed XML, the same
 * vertices, edges, quads and curves as "xml", COMPRESSED="B64Z-LittleEndian"),
 * whatever path's name; path "-" is standard output. */
SQ_API sq_status sq_mesh_write_format(const sq_mesh *m, const char *path, const char *format,
                                      sq_error *err);
/* 1 if sq_mesh_write knows path's format, else 0 (check before meshing). */
SQ_API int sq_mesh_format_known(const char *path);

/* ---- Mesh families for grid-convergence studies ------------------------ */

/* A mesh of m's block layout (docs/convergence-families.md): every quad
 * split 2 × 2, `levels` times (0: the same quads), then at order `order`
 * (0: m's).  A child is the sub-map of its parent's own high-order map
 * (so a curved quad's children keep its curve); a side on a CAD edge is
 * placed on the curve instead, its new vertex at the arc length midway.
 * Nested: every vertex of m is a vertex of *out with the same coordinates,
 * bit for bit.  Nothing is relaxed again (that would move m's vertices);
 * the quality is proven again, by the Bézier bounds (sq_mesh_scaled_jacobians,
 * sq_mesh_check_quality).  m's periodic links are found again on *out,
 * its image nodes set to the images of their masters.  A mesh of several
 * faces (sq_model_mesh): each face's mesh refined in its own frame, then
 * merged as m was (the nodes of a shared curve one node), the faces'
 * groups kept.  SQ_ERR_USAGE when the quads would exceed opt->max_quads
 * (opt NULL: the defaults).  *out borrows m's model, not m. */
SQ_API sq_status sq_mesh_refine(const sq_mesh *m, int levels, int order, const sq_options *opt,
                                sq_mesh **out, sq_error *err);

/* The mesh's sizes h: the mean (*mean) and largest (*max) straight
 * distance between the two vertices of an element edge, each edge once. */
SQ_API sq_status sq_mesh_edge_lengths(const sq_mesh *m, double *mean, double *max,
                                      sq_error *err);

/* The manifest of a family of n meshes of one face or domain (docs/
 * convergence-families.md): one JSON object, the input, the face's exact
 * area (of a domain: its faces, and the sum of their areas) and, per
 * mesh, files[k], levels[k] (1: the mesh as made), its order, quads,
 * nodes, degrees of freedom of a scalar CG field of its order (its nodes),
 * h (sq_mesh_edge_lengths, and sqrt(area / quads)), area and least scaled
 * Jacobian. */
SQ_API sq_status sq_mesh_family_write_manifest(const char *path, int n,
                                               const sq_mesh *const *meshes,
                                               const char *const *files, const int *levels,
                                               sq_error *err);

/* ---- A convergence study of the field solvers ------------------------- */

typedef struct sq_study sq_study;

/* L2 and H1 errors and rates of the sem/ solvers on face `face`
 * (`semquad converge`), as the study_* options say. */
SQ_API sq_status sq_face_converge(const sq_model *m, int face, const sq_options *opt,
                                  sq_study **out, sq_error *err);
SQ_API void sq_study_free(sq_study **s);
/* The table the command prints. */
SQ_API sq_status sq_study_describe(const sq_study *s, char **text, sq_error *err);
/* .csv (every run) or .svg (log-log plot of the errors). */
SQ_API sq_status sq_study_write(const sq_study *s, const char *path, sq_error *err);

#ifdef __cplusplus
}
#endif
#endif
