/* semquad — what the public API's handles hold (include/semquad.h) and the
 * helpers its files share: options into each stage's own, faces from a
 * model, messages.  Nothing here is public. */
#ifndef SQ_API_PRIVATE_H
#define SQ_API_PRIVATE_H

#include "cad.h"
#include "domain.h"
#include "layout_pipeline.h"
#include "periodic.h"
#include "quad_mesher.h"
#include "semquad.h"
#include "write_mesh_report.h"

struct sq_model {
    cad_model *cad;
    char *path;    /* as given to sq_model_open */
    double t_read; /* seconds */
    sq_options opt; /* as opened (its logger serves sq_model_info) */
};

/* One face of a model, open for a stage (results borrow their model). */
typedef struct {
    const sq_model *model;
    int index;
    cad_face *cad;
} sq_api_face;

struct sq_triangles {
    sq_api_face face;
    sq_triangulation tri;
};

struct sq_field {
    sq_api_face face;
    int htheta; /* 1: the H/θ field (ht), 0: the guiding field (an) */
    sq_field_analysis an;
    sq_htheta ht;
    int nsing;
    double *xy;
    int *valence;
};

struct sq_quad_layout {
    sq_api_face face;
    sq_periodic per; /* --periodic pairs (npairs 0: none) */
    sq_layout_result r;
    double *t_split; /* seconds writing the patches' STEP file, -1 if none (the
                        writers take a const handle: the clock is apart) */
};

/* What a mesh of several faces adds (model_mesh.c): the faces, the
 * road each took, their exact areas, the curves they share. */
typedef struct {
    int nfaces;
    int *face;           /* CAD face numbers */
    const char **road;   /* "layout" or "split" */
    double *area;        /* exact (Green's theorem on the CAD curves) */
    int ncurves, ntags, rounds;
    sq_domain_curve *curves;
    int *quad_face;      /* per quad: its CAD face (sq_mesh_quad_faces) */
    double size;         /* the size the faces were meshed at (the merge's tolerance) */
    sq_quad_mesh **q;    /* per face: the mesh merged into the handle's, in the face's
                            own frame (a family refines these, domain_refine.c) */
} sq_api_domain;
void sq_api_domain_free(sq_api_domain **d);
/* h->dom for nfaces faces and ncurves curves, its arrays allocated
 * (quad_face for h->q's quads), no face's mesh yet. */
sq_status sq_api_domain_new(sq_mesh *h, int nfaces, int ncurves, sq_error *err);

/* The faces of a domain, open: their CAD faces and info (area, corners;
 * cusps refused), and a slot for each one's mesh (model_mesh.c). */
typedef struct {
    int n;
    sq_api_face *face;
    const cad_face **cad;
    sq_face_info *info;
    sq_quad_mesh **q;
} sq_api_faces;
sq_status sq_api_faces_load(const sq_model *m, const int *faces, int n, const sq_options *o,
                            sq_api_faces *f, sq_error *err);
void sq_api_faces_close(sq_api_faces *f);
/* The tolerance of the domain's coincident curves at mesh size `size`. */
double sq_api_domain_tolerance(const sq_model *m, double size);

/* A family's step (mesh_family.c): from's quads split n × n (n = 1: the
 * same quads) at order into *out. */
typedef sq_status (*sq_api_refine_step)(void *ctx, const sq_quad_mesh *from, int n, int order,
                                        int threads, sq_quad_mesh **out, sq_error *err);
/* m's mesh refined `levels` times by step, then taken to `order`: each
 * level's periodic links found again, m's names kept; *out the last. */
sq_status sq_api_refine_levels(const sq_mesh *m, int levels, int order, const sq_options *o,
                               sq_api_refine_step step, void *ctx, sq_quad_mesh **out,
                               sq_error *err);
/* A handle for q (handed over), made from m (its face, road, threads). */
sq_status sq_api_refined_handle(const sq_mesh *m, sq_quad_mesh *q, sq_mesh **out, sq_error *err);

/* sq_mesh_refine of a mesh of several faces (domain_refine.c): each
 * face's mesh refined in its own frame, then merged as sq_model_mesh
 * merges them, the periodic links found again. */
sq_status sq_api_domain_refine(const sq_mesh *m, int levels, int order, const sq_options *o,
                               sq_mesh **out, sq_error *err);

struct sq_mesh {
    sq_api_face face; /* of a domain: its first face (the frame, the model) */
    sq_api_domain *dom; /* NULL: one face */
    sq_face_info info;
    sq_layout_result r;   /* the layout road's, if it ran (reported on that road only);
                             zeroed in a refined mesh */
    sq_road_choice road;
    int all_quad;         /* the layout road's layout is the all-quad last resort */
    sq_quad_mesh *q;
    sq_quad_quality quality;
    sq_mesh_timings t;
    double t0;            /* sq_now() when meshing began, for timings.total */
    double *t_write;      /* seconds in sq_mesh_write so far (apart, as t_split) */
    sq_progress progress; /* the caller's, for the "write" events */
    double **xyz;         /* the nodes in 3D, made by the first sq_mesh_nodes (a million
                             order-4 quads: 384 MB; apart, as t_write) */
    double *sjac, *eta;
    int *bnd;
    int nbl;              /* boundary layers asked for (sq_options.nbl), for the blame */
    int *bl_edges;        /* their walls (nbl), first height, ratio and layers, for the report */
    double bl_first, bl_ratio;
    int bl_layers;
    int threads;          /* sq_options.threads, for the quality and the edges */
    sq_size_field *sizes; /* the user's sizes (NULL: none), read by the mesher */
    double far_size;      /* the size the mesh was made at (--size, or the default) */
    sq_periodic per;      /* --periodic pairs (npairs 0: none) */
    int *per_held;        /* their edges, held by the mesher */
    double origin[3], xdir[3], ydir[3];
};

/* The per-quad quality arrays and summary of h->q (once per mesh made),
 * and the plain arrays of the public accessors. */
sq_status sq_api_mesh_quality(sq_mesh *h, sq_error *err);
sq_status sq_api_mesh_arrays(sq_mesh *h, sq_error *err);
/* Boundary names (mesh_names.c): the options' names checked, and given
 * to m's curves (m->tag_name) by edge or nearest point. */
sq_status sq_api_names_check(const sq_options *o, sq_error *err);
sq_status sq_api_name_tags(sq_quad_mesh *m, const sq_options *o, sq_error *err);
/* The options' face names given to a domain's faces (m->region_name) by
 * number or by a point inside; SQ_ERR_USAGE for a mesh of one face (m
 * NULL: one face, before it is meshed). */
sq_status sq_api_name_faces(sq_quad_mesh *m, const sq_options *o, sq_error *err);
/* The names the CAD file gives m's curves (cad_face_edge_name): curve t
 * is edge t of cad[0] (curves NULL: one face), or, of a domain, curve c's
 * tag is edge curves[c].edge[0] of cad[curves[c].face[0]]; and a domain's
 * faces (cad_model_face_name of model's face region_face[r]). */
sq_status sq_api_file_names(sq_quad_mesh *m, const cad_model *model, const cad_face *const *cad,
                            const sq_domain_curve *curves, int ncurves, sq_error *err);


/* --periodic: the pairs of face (periodic.h design 1) into per, logged;
 * the translations identified in lo's field and tracing (face_mesh.c). */
sq_status sq_api_periodic_find(const cad_face *face, const sq_face_info *info,
                               const sq_options *o, sq_periodic *per, sq_layout_options *lo,
                               sq_error *err);
/* The pairs found and the candidates left, as notes; the identified
 * domain's Gauss–Bonnet count against q's (its periodic_* fields). */
void sq_api_periodic_log(const sq_options *o, const sq_periodic *per);
void sq_api_periodic_log_identified(const sq_options *o, const sq_quad_mesh *q, const char *road);
/* sq_face_mesh with the vertices on the face's edges where held_edges[e]
 * is 1 held where they are placed (a domain's shared curves; NULL: none),
 * on the layout road at least min_chords[e] chords on edge e and its
 * vertices on edge e slid onto edge_points[e] where n > 0 (NULL: none;
 * quad_mesher.h). */
sq_status sq_api_face_mesh(const sq_model *model, int face, const sq_options *o,
                           const int *held_edges, const int *min_chords,
                           const sq_edge_points *edge_points, sq_mesh **out, sq_error *err);

/* sq_api_face_mesh of faces[i], i in [0, n), of m into out[i] (NULLs on
 * entry), held[i] and minc[i] as there (held NULL: none; minc[i] NULL:
 * none): the faces on o->threads threads (model_mesh_faces.c), each
 * face's mesh stage on its share of them; the log lines in face order;
 * on failure the first failing face's status and error, out all NULL. */
sq_status sq_api_faces_mesh(const sq_model *m, int n, const int *faces, const sq_options *o,
                            int *const *held, int *const *minc, sq_mesh **out, sq_error *err);

/* Appended to a cusp's refusal (sq_face_check_cusps): why healing left
 * it, the option that would blunt it. */
void sq_api_cusp_hint(const cad_model *model, const sq_face_info *fi, sq_error *err);

/* The report of a mesh of several faces (model_mesh_report.c). */
sq_status sq_api_domain_report(const sq_mesh *m, const sq_mesh_timings *t, char **json,
                               sq_error *err);
sq_status sq_api_domain_write_report(const sq_mesh *m, const sq_mesh_timings *t,
                                     const char *path, sq_error *err);

/* Open face `face` of m (-1: the default face, logged as a note). */
sq_status sq_api_face_open(const sq_model *m, int face, const sq_options *o, sq_api_face *f,
                           sq_error *err);
void sq_api_face_close(sq_api_face *f);

/* One line to o->log, printf-style (nothing without a logger). */
void sq_api_log(const sq_options *o, sq_log_level level, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

/* o, or the defaults in *def when o is NULL (every entry point takes
 * NULL for the defaults). */
const sq_options *sq_api_options(const sq_options *o, sq_options *def);

/* The pattern traced from: o->singularities, or "natural" for the field
 * "htheta" without one; NULL for the guiding field. */
const char *sq_api_singularities(const sq_options *o);

/* sq_options into the stages' own options; SQ_ERR_USAGE naming a bad
 * value.  `for_mesh`: the mesh command's cheaper field settings. */
sq_status sq_api_field_options(const sq_options *o, sq_field_options *fo, sq_error *err);
sq_status sq_api_layout_options(const sq_options *o, int for_mesh, sq_layout_options *lo,
                                sq_error *err);
sq_status sq_api_mesher_options(const sq_options *o, sq_mesher_options *mo, sq_error *err);

/* sq_options.study_methods as SQ_CONV_* bits (the solution name checked). */
sq_status sq_api_study_methods(const sq_options *o, int *methods, sq_error *err);

/* sq_options.road */
typedef enum { SQ_API_ROAD_AUTO = 0, SQ_API_ROAD_LAYOUT, SQ_API_ROAD_SPLIT } sq_api_road;
sq_status sq_api_parse_road(const char *val, sq_api_road *road, sq_error *err);

/* 1 if path s ends with suffix (the output formats go by extension). */
int sq_api_ends_with(const char *s, const char *suffix);

/* Text written to a memory stream, handed over as a string. */
typedef struct {
    FILE *fp;
    char *buf;
    size_t len;
} sq_api_text;
sq_status sq_api_text_open(sq_api_text *t, sq_error *err);
sq_status sq_api_text_close(sq_api_text *t, char **text, sq_error *err);

#endif
