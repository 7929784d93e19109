/* semquad bench — time and memory of the sem/ Poisson solvers (CG and DG)
 * against degrees of freedom, P = 2..12, on curved triangulations of a CAD
 * face (default examples/half_disc.step, isoparametric geometry of order P),
 * and the cost of evaluating a solution at arbitrary points at P = 8.
 *
 * Each (P, mesh) measurement runs in a forked child, so its peak resident
 * memory is its own: the child resets the high-water mark (Linux
 * /proc/self/clear_refs, value 5: proc(5)) after the mesh exists and reads
 * VmHWM after the solve.  Times are wall clock (best of `reps` runs).
 * Prints a Markdown section on stdout; bench/sem_bench runs it on a release
 * build with one BLAS thread and writes it into docs/benchmarks.md. */
#include "cad.h"
#include "field_eval.h"
#include "poisson.h"
#include "triangulate.h"

#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* kB of a /proc/self/status line ("VmHWM:", "VmRSS:") */
static long status_kb(const char *key)
{
    FILE *fp = fopen("/proc/self/status", "r");
    char line[256];
    long v = -1;
    size_t n = strlen(key);
    while (fp && fgets(line, sizeof line, fp))
        if (!strncmp(line, key, n)) v = atol(line + n);
    if (fp) fclose(fp);
    return v;
}

static void reset_hwm(void)
{
    FILE *fp = fopen("/proc/self/clear_refs", "w");
    if (fp) fputs("5", fp), fclose(fp);
}

/* u = e^x sin y on the boundary, f = 0 */
static double bnd(const double x[2], const double n[2], int tag, void *ctx)
{
    (void)n, (void)tag, (void)ctx;
    return exp(x[0]) * sin(x[1]);
}

typedef struct {
    int ok;
    long dofs;
    double t_create, t_solve;
    long hwm_kb, base_kb;
} measure;

static measure run_child(const sem_tri_mesh *mesh, int P, sem_method meth, int reps)
{
    measure r = {0};
    int fd[2];
    if (pipe(fd)) return r;
    pid_t pid = fork();
    if (pid == 0) {
        close(fd[0]);
        reset_hwm();
        r.base_kb = status_kb("VmRSS:");
        r.t_create = r.t_solve = INFINITY;
        sq_error err;
        r.ok = 1;
        for (int k = 0; k < reps && r.ok; k++) {
            sem_poisson *s = NULL;
            sem_field *u = NULL;
            double t0 = now_s();
            r.ok = sem_poisson_create(mesh, P, meth, NULL, NULL, &s, &err) == SQ_OK;
            double t1 = now_s();
            r.ok = r.ok && sem_field_create(mesh, P, 1, &u, &err) == SQ_OK;
            sem_poisson_data d = {NULL, NULL, bnd, NULL, 0, NULL, 0};
            double t2 = now_s();
            r.ok = r.ok && sem_poisson_solve(s, &d, u, &err) == SQ_OK;
            double t3 = now_s();
            if (r.ok) r.dofs = sem_poisson_ndofs(s);
            r.t_create = fmin(r.t_create, t1 - t0);
            r.t_solve = fmin(r.t_solve, t3 - t2);
            sem_field_free(&u);
            sem_poisson_free(&s);
        }
        r.hwm_kb = status_kb("VmHWM:");
        if (write(fd[1], &r, sizeof r) != (ssize_t)sizeof r) _exit(1);
        _exit(0);
    }
    close(fd[1]);
    if (pid > 0) {
        if (read(fd[0], &r, sizeof r) != (ssize_t)sizeof r) r.ok = 0;
        waitpid(pid, NULL, 0);
    }
    close(fd[0]);
    return r;
}

/* Triangulation of order P with about `ntris` triangles: the size scales as
 * ntris^(-1/2) from the automatic one (one correction step). */
static int mesh_for(const cad_face *f, int P, double ntris, sq_triangulation *t)
{
    sq_error err;
    sq_tri_options o;
    sq_tri_options_default(&o);
    o.order = 1;
    if (sq_triangulate(f, &o, t, &err)) return fprintf(stderr, "%s\n", err.msg), 1;
    double h = t->size * sqrt(t->mesh->ntris / ntris);
    for (int it = 0; it < 2; it++) {
        sq_triangulation_free(t);
        o.size = h;
        o.order = it ? (P < 12 ? P : 12) : 1;
        if (sq_triangulate(f, &o, t, &err)) return fprintf(stderr, "%s\n", err.msg), 1;
        if (!it) h *= sqrt(t->mesh->ntris / ntris);
    }
    return 0;
}

static double cg_dofs_per_tri(int P) { return 0.5 * P * P; } /* V/T ~ 1/2, E/T ~ 3/2 */

/* ns per evaluation at random points of the face: hint -1 (arbitrary
 * points), hint = previous element (points along a random walk), and at
 * known (element, r, s). */
static void eval_cost(const sem_tri_mesh *mesh, int P, double out[3], long *dofs, double *npts)
{
    sq_error err;
    sem_poisson *s = NULL;
    sem_field *u = NULL;
    sem_field_evaluator *ev = NULL;
    out[0] = out[1] = out[2] = NAN;
    if (sem_poisson_create(mesh, P, SEM_CG, NULL, NULL, &s, &err) ||
        sem_field_create(mesh, P, 1, &u, &err))
        return;
    sem_poisson_data d = {NULL, NULL, bnd, NULL, 0, NULL, 0};
    if (sem_poisson_solve(s, &d, u, &err) || sem_field_evaluator_create(u, NULL, &ev, &err))
        return;
    *dofs = sem_poisson_ndofs(s);
    double bb[4] = {INFINITY, INFINITY, -INFINITY, -INFINITY};
    for (int k = 0; k < mesh->nverts; k++) {
        bb[0] = fmin(bb[0], mesh->vxy[2 * k]), bb[2] = fmax(bb[2], mesh->vxy[2 * k]);
        bb[1] = fmin(bb[1], mesh->vxy[2 * k + 1]), bb[3] = fmax(bb[3], mesh->vxy[2 * k + 1]);
    }
    const int N = 1000000;
    double *xy = malloc(sizeof(double) * 2 * N), *walk = malloc(sizeof(double) * 2 * N);
    int *el = malloc(sizeof(int) * N);
    double *rs = malloc(sizeof(double) * 2 * N);
    unsigned long long seed = 12345;
    int n = 0, tries = 0;
    while (n < N && tries < 20 * N) {
        tries++;
        seed = seed * 6364136223846793005ULL + 1442695040888963407ULL;
        double a = (double)(seed >> 11) / 9007199254740992.0;
        seed = seed * 6364136223846793005ULL + 1442695040888963407ULL;
        double b = (double)(seed >> 11) / 9007199254740992.0;
        double p[2] = {bb[0] + a * (bb[2] - bb[0]), bb[1] + b * (bb[3] - bb[1])}, v;
        int e = -1;
        if (sem_field_evaluator_eval(ev, p, &e, &v, NULL)) continue;
        xy[2 * n] = p[0], xy[2 * n + 1] = p[1], el[n] = e;
        seed = seed * 6364136223846793005ULL + 1442695040888963407ULL;
        double r = (double)(seed >> 11) / 9007199254740992.0;
        seed = seed * 6364136223846793005ULL + 1442695040888963407ULL;
        double q = (double)(seed >> 11) / 9007199254740992.0;
        if (r + q > 1.0) r = 1.0 - r, q = 1.0 - q;
        rs[2 * n] = r, rs[2 * n + 1] = q;
        n++;
    }
    /* a random walk with steps of 1e-3 of the box, kept inside */
    int e = -1;
    double w[2] = {xy[0], xy[1]}, acc = 0.0, v, g[2];
    for (int k = 0; k < n; k++) {
        seed = seed * 6364136223846793005ULL + 1442695040888963407ULL;
        double ang = 6.283185307179586 * (double)(seed >> 11) / 9007199254740992.0;
        double tw[2] = {w[0] + 1e-3 * (bb[2] - bb[0]) * cos(ang), w[1] + 1e-3 * (bb[2] - bb[0]) * sin(ang)};
        int te = e;
        if (!sem_field_evaluator_eval(ev, tw, &te, &v, NULL)) w[0] = tw[0], w[1] = tw[1], e = te;
        walk[2 * k] = w[0], walk[2 * k + 1] = w[1];
    }
    double t0 = now_s();
    for (int k = 0; k < n; k++) {
        int h = -1;
        sem_field_evaluator_eval(ev, xy + 2 * k, &h, &v, g);
        acc += v + g[0];
    }
    double t1 = now_s();
    e = -1;
    for (int k = 0; k < n; k++) {
        sem_field_evaluator_eval(ev, walk + 2 * k, &e, &v, g);
        acc += v + g[1];
    }
    double t2 = now_s();
    for (int k = 0; k < n; k++) {
        sem_field_evaluator_eval_ref(ev, el[k], rs[2 * k], rs[2 * k + 1], &v, g, NULL);
        acc += v + g[0];
    }
    double t3 = now_s();
    out[0] = 1e9 * (t1 - t0) / n, out[1] = 1e9 * (t2 - t1) / n, out[2] = 1e9 * (t3 - t2) / n;
    *npts = n + 1e-300 * acc; /* keep acc alive */
    free(xy), free(walk), free(el), free(rs);
    sem_field_evaluator_free(&ev);
    sem_field_free(&u);
    sem_poisson_free(&s);
}

int main(int argc, char **argv)
{
    /* one thread, as semquad runs (src/cli/main.c): OpenBLAS is its serial
     * build, and CHOLMOD's OpenMP regions run on the calling thread */
    omp_set_max_active_levels(0);
    const char *path = argc > 1 ? argv[1] : "examples/half_disc.step";
    const int pmax = argc > 2 ? atoi(argv[2]) : 12;
    sq_error err;
    cad_model *m = NULL;
    cad_face *f = NULL;
    if (cad_model_read(path, &m, &err) ||
        cad_face_create(m, cad_model_default_face(m, NULL), &f, &err))
        return fprintf(stderr, "sem-bench: %s\n", err.msg), 1;
    const char *base = strrchr(path, '/');
    base = base ? base + 1 : path;
    printf("## sem/ solver\n\n");
    printf("Generated by `bench/sem_bench` (release build, one thread: serial OpenBLAS, "
           "CHOLMOD's OpenMP regions on the calling thread) on `%s`: -Δu = 0 with u = e^x sin y on the boundary, curved triangulations of "
           "geometry order P, sized for about 10^4 and 10^5 CG unknowns; CG and DG on the same "
           "mesh. *assemble+factor*: `sem_poisson_create` (element matrices, static "
           "condensation for CG, CHOLMOD analysis and factorization); *solve*: "
           "`sem_poisson_solve` (right-hand side, forward/back substitution, interior "
           "recovery); best of 3 below 10^5 unknowns. *peak MB*: peak resident memory of a "
           "fresh process holding the mesh during assembly, factorization and solve (VmHWM); "
           "*+MB*: the part above the resident size before it started.\n\n",
           base);
    char la[64] = "?";
    FILE *lf = fopen("/proc/loadavg", "r");
    if (lf) {
        if (!fgets(la, sizeof la, lf)) strcpy(la, "?");
        fclose(lf);
        la[strcspn(la, "\n")] = 0;
    }
    printf("Conditions: %ld cores online, /proc/loadavg at the start: %s (other work on a "
           "shared machine inflates the times; rerun for a quiet figure).\n\n",
           sysconf(_SC_NPROCESSORS_ONLN), la);
    printf("| P | method | triangles | dofs | assemble+factor s | solve s | total s | peak MB | +MB |\n");
    printf("| ---: | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n");
    fflush(stdout);
    double cg1e5[13] = {0};
    long cg1e5_dofs[13] = {0};
    for (int P = 2; P <= pmax; P++) {
        for (int lev = 0; lev < 2; lev++) {
            const double target = lev ? 1e5 : 1e4;
            sq_triangulation t;
            if (mesh_for(f, P, target / cg_dofs_per_tri(P), &t)) return 1;
            for (int mi = 0; mi < 2; mi++) {
                sem_method meth = mi ? SEM_DG : SEM_CG;
                measure r = run_child(t.mesh, P, meth, lev ? 1 : 3);
                if (!r.ok) {
                    printf("| %d | %s | %d | | failed | | | | |\n", P, mi ? "DG" : "CG",
                           t.mesh->ntris);
                    continue;
                }
                printf("| %d | %s | %d | %ld | %.3f | %.4f | %.3f | %.0f | %.0f |\n", P,
                       mi ? "DG" : "CG", t.mesh->ntris, r.dofs, r.t_create, r.t_solve,
                       r.t_create + r.t_solve, r.hwm_kb / 1024.0,
                       (r.hwm_kb - r.base_kb) / 1024.0);
                fflush(stdout);
                if (!mi && lev) cg1e5[P] = r.t_create + r.t_solve, cg1e5_dofs[P] = r.dofs;
            }
            sq_triangulation_free(&t);
        }
    }
    printf("\n**100 000-dof CG target (< 1 s on one core)**: ");
    for (int P = 2; P <= pmax; P++)
        printf("%sP=%d %.2f s (%ld dofs) %s", P > 2 ? ", " : "", P, cg1e5[P], cg1e5_dofs[P],
               cg1e5[P] < 1.0 ? "✓" : "✗");
    printf(".\n\n");
    /* evaluation at P = 8 */
    printf("**Evaluation at P = 8** (value and physical gradient, CG solution, %s; "
           "10^6 points):\n\n", base);
    printf("| triangles | dofs | arbitrary point (locate + Newton + eval) ns | along a path "
           "(hint = last element) ns | at known (element, r, s) ns |\n| ---: | ---: | ---: | ---: "
           "| ---: |\n");
    for (int lev = 0; lev < 3; lev++) {
        const double target = lev == 0 ? 0.0 : lev == 1 ? 1e4 : 1e5;
        sq_triangulation t;
        if (lev == 0) {
            sq_tri_options o;
            sq_tri_options_default(&o);
            o.order = 8;
            if (sq_triangulate(f, &o, &t, &err)) return 1;
        } else if (mesh_for(f, 8, target / cg_dofs_per_tri(8), &t)) {
            return 1;
        }
        double ns[3], npts = 0;
        long dofs = 0;
        eval_cost(t.mesh, 8, ns, &dofs, &npts);
        printf("| %d | %ld | %.0f | %.0f | %.0f |\n", t.mesh->ntris, dofs, ns[0], ns[1], ns[2]);
        fflush(stdout);
        sq_triangulation_free(&t);
    }
    printf("\nTarget: <= 1000 ns per arbitrary point at P = 8.\n");
    cad_face_free(&f);
    cad_model_free(&m);
    return 0;
}
