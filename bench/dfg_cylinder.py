#!/usr/bin/python3
"""DFG benchmark "flow around a cylinder", case 2D-2 (Schaefer & Turek 1996,
Re = 100, periodic): semquad meshes the channel [0, 2.2] x [0, 0.41] minus
the circle of diameter 0.1 at (0.2, 0.2) at order 2, DOLFINx solves the
incompressible Navier-Stokes equations on its 9-node quads with
Taylor-Hood Q2-Q1, and the run reports max c_D, max c_L and the Strouhal
number against the published intervals.

The solver (our own, with DOLFINx's assembly and PETSc's LU):
  - monolithic, linearly implicit BDF2: (3u - 4u^n + u^{n-1}) / (2 dt)
    + (u* . grad) u - nu Lap u + grad p = 0, div u = 0 with the advecting
    velocity extrapolated, u* = 2u^n - u^{n-1} (one linear solve a step,
    second order, no splitting error in the pressure); BDF1 with u* = u^n
    on the first step and whenever dt changes;
  - inflow U(y) = 4 Um y (H - y) / H^2, Um = 1.5 (mean 1), nu = 1e-3, rho = 1,
    no slip on the walls and the cylinder, do-nothing outlet (the natural
    condition of the nu grad u : grad v form);
  - forces by the volume form (Babuska & Miller 1984; John 2004): with
    phi = e_x (e_y) on the cylinder's velocity nodes and 0 elsewhere,
    F = -R(u, p; phi), R the discrete momentum residual, so F is what the
    scheme's own equations put on the boundary nodes (more accurate than a
    surface integral of the stress); c = 2 F / (rho Ubar^2 D) = 20 F;
  - start from rest with the inflow ramped in over the first second and
    the cylinder turned briefly (t in [1, 2], surface speed --kick) so the
    symmetric wake breaks at once rather than from round-off; an optional
    spin-up at a larger time step (--dt-spinup until --t-spinup) then the
    measured time step until --t-end; --save keeps the last two steps'
    solutions and --restart continues from them (another time step, a
    longer run) without the spin-up again;
  - over the last --window seconds: max c_D, max c_L (the discrete maxima
    refined by a parabola through three samples), St = D f / Ubar with f
    from the mean spacing of the lift's maxima.

Run with Debian's /usr/bin/python3 (python3-dolfinx, python3-gmsh;
scripts/bootstrap.sh --bench installs them).  The mesh: --mesh-args "..."
passes options to `semquad mesh` (the STEP is built here from
tests/step_face.py; its cylinder is CAD edge 4), or --msh FILE solves a
given order-2 quad MSH (e.g. one made by Gmsh).  Appends one JSON row per
run to --json, writes the force history to --history (CSV).

usage: dfg_cylinder.py [--semquad PATH] (--mesh-args "..." | --msh FILE)
                       [--dt DT] [--t-end T] [--dt-spinup DT --t-spinup T]
                       [--window W] [--save NPZ] [--restart NPZ] [--json OUT]
                       [--history CSV] [--name NAME]

The time step matters: on the 2255-quad mesh max c_L is 1.152 at dt = 0.01,
1.095 at 0.005 (docs/benchmarks.md), so measure at dt <= 0.0025."""
import argparse
import json
import logging
import math
import os
import shlex
import subprocess
import sys
import tempfile
import time

# one thread each: BLAS threads fighting over a loaded machine's cores made a
# step 5x slower (measured); set before numpy and PETSc load their BLAS
os.environ.setdefault("OMP_NUM_THREADS", "1")
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
import numpy as np  # noqa: E402
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "tests"))
sys.path.insert(0, os.path.join(ROOT, "bench"))
from benchlib import source_commit  # noqa: E402
from step_face import step_face  # noqa: E402

import gmsh  # noqa: E402
import ufl  # noqa: E402
from dolfinx import fem  # noqa: E402
from dolfinx import mesh as dmesh  # noqa: E402
from dolfinx.fem import petsc as fpetsc  # noqa: E402
from dolfinx.io import gmshio  # noqa: E402
from mpi4py import MPI  # noqa: E402
from petsc4py import PETSc  # noqa: E402

logging.getLogger().setLevel(logging.WARNING)  # not FFCx's compiler lines

L, H, XC, YC, D = 2.2, 0.41, 0.2, 0.2, 0.1
NU, UM = 1e-3, 1.5
# GMRES iterations above which the next step refactors its matrix
REFACTOR_ITS = 6
# Gauss points per direction exact to degree 6 (the convection term's
# Q2 x Q2 x Q2, one derivative down, on the affine part of the map); UFL's
# own estimate on the curved Q2 map asks for a far higher degree
DX = ufl.dx(metadata={"quadrature_degree": 6})
# Schaefer & Turek 1996, table 4 (case 2D-2)
BOUNDS = {"cd_max": (3.22, 3.24), "cl_max": (0.99, 1.01), "st": (0.295, 0.305)}


def make_msh(semquad, mesh_args, workdir):
    """The channel's STEP and `semquad mesh --order 2` on it; the MSH path and
    semquad's report."""
    step = os.path.join(workdir, "dfg.step")
    step_face(step, [[(0, 0), (L, 0), (L, H), (0, H)], ("circle", XC, YC, D / 2)], unit="m")
    msh, rep = os.path.join(workdir, "dfg.msh"), os.path.join(workdir, "dfg.json")
    cmd = [semquad, "mesh", step, "-q", "--order", "2", "-o", msh, "--report", rep] + mesh_args
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode not in (0, 8):  # 8: written below the quality floor
        sys.exit("dfg_cylinder: semquad mesh exit %d: %s" % (r.returncode, r.stderr.strip()))
    with open(rep) as f:
        report = json.load(f)
    return msh, report


def read_quads(path):
    """A DOLFINx mesh of the MSH file's 9-node quads (Gmsh's node order
    permuted to DOLFINx's by gmshio.cell_perm_array)."""
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.open(path)
    tags, xyz, _ = gmsh.model.mesh.getNodes()
    types, _, nodes = gmsh.model.mesh.getElements(2)
    gmsh.finalize()
    if list(types) != [10]:
        sys.exit("dfg_cylinder: %s: expected 9-node quads only (Gmsh type 10), found types %s"
                 % (path, list(types)))
    index = np.zeros(int(tags.max()) + 1, dtype=np.int64)
    index[tags.astype(np.int64)] = np.arange(len(tags))
    cells = index[nodes[0].astype(np.int64)].reshape(-1, 9)
    cells = cells[:, gmshio.cell_perm_array(dmesh.CellType.quadrilateral, 9)]
    x = xyz.reshape(-1, 3)[:, :2].copy()
    return dmesh.create_mesh(MPI.COMM_WORLD, cells, x, gmshio.ufl_mesh(10, 2))


class Channel:
    """The discrete problem: spaces, boundary conditions, BDF forms, LU solver."""

    def __init__(self, msh):
        self.msh = msh
        cell = msh.ufl_cell()
        th = ufl.MixedElement([ufl.VectorElement("Lagrange", cell, 2), ufl.FiniteElement("Lagrange", cell, 1)])
        self.W = W = fem.FunctionSpace(msh, th)
        self.V, _ = W.sub(0).collapse()
        self.ndofs = W.dofmap.index_map.size_global * W.dofmap.index_map_bs
        self.facets(msh)
        self.bcs_setup()
        self.forms()

    def facets(self, msh):
        fdim = 1
        msh.topology.create_connectivity(fdim, 2)
        on = lambda f: dmesh.locate_entities_boundary(msh, fdim, f)  # noqa: E731
        tol = 1e-6
        self.inlet = on(lambda x: x[0] < tol)
        self.walls = on(lambda x: (x[1] < tol) | (x[1] > H - tol))
        self.cyl = on(lambda x: (x[0] - XC) ** 2 + (x[1] - YC) ** 2 < (0.6 * D) ** 2)
        if len(self.inlet) == 0 or len(self.walls) == 0 or len(self.cyl) == 0:
            sys.exit("dfg_cylinder: the mesh lacks the inlet, a wall or the cylinder")

    def bcs_setup(self):
        W, V = self.W, self.V
        both = (W.sub(0), V)
        self.u_in, self.u_cyl, zero = fem.Function(V), fem.Function(V), fem.Function(V)
        dofs = lambda f: fem.locate_dofs_topological(both, 1, f)  # noqa: E731
        # walls last: the inlet's corner nodes have U = 0 anyway
        self.bcs = [fem.dirichletbc(self.u_in, dofs(self.inlet), W.sub(0)),
                    fem.dirichletbc(self.u_cyl, dofs(self.cyl), W.sub(0)),
                    fem.dirichletbc(zero, dofs(self.walls), W.sub(0))]
        # the force's test functions: e_x, e_y on the cylinder's velocity nodes
        cdofs = fem.locate_dofs_topological(V, 1, self.cyl)
        self.phi = []
        for k in range(2):
            f = fem.Function(V)
            f.x.array[2 * cdofs + k] = 1.0
            self.phi.append(f)

    def set_boundary(self, t, kick):
        ramp = 0.5 * (1 - math.cos(math.pi * t)) if t < 1 else 1.0
        self.u_in.interpolate(lambda x: np.vstack([ramp * 4 * UM * x[1] * (H - x[1]) / H ** 2, 0 * x[0]]))
        s = kick * math.sin(math.pi * (t - 1)) if 1 < t < 2 else 0.0
        w = s / (D / 2)
        self.u_cyl.interpolate(lambda x: np.vstack([-w * (x[1] - YC), w * (x[0] - XC)]))

    def forms(self):
        W, msh = self.W, self.msh
        self.w, self.w1, self.w2 = fem.Function(W), fem.Function(W), fem.Function(W)
        self.k = fem.Constant(msh, PETSc.ScalarType(0.01))
        # BDF: du/dt ~ (a0 u + a1 u^n + a2 u^{n-1}) / dt; u* = e1 u^n + e2 u^{n-1}
        self.a0, self.a1, self.a2 = (fem.Constant(msh, PETSc.ScalarType(0)) for _ in range(3))
        self.e1, self.e2 = (fem.Constant(msh, PETSc.ScalarType(0)) for _ in range(2))
        u, p = ufl.TrialFunctions(W)
        v, q = ufl.TestFunctions(W)
        u1, u2 = ufl.split(self.w1)[0], ufl.split(self.w2)[0]
        ustar = self.e1 * u1 + self.e2 * u2
        old = (self.a1 * u1 + self.a2 * u2) / self.k

        def momentum(uu, pp, vv):
            return (ufl.inner(self.a0 * uu / self.k + old, vv) + ufl.inner(ufl.grad(uu) * ustar, vv)
                    + NU * ufl.inner(ufl.grad(uu), ufl.grad(vv)) - pp * ufl.div(vv))

        # the momentum form is affine in u: its bilinear part goes left, old right
        a = (ufl.inner(self.a0 * u / self.k, v) + ufl.inner(ufl.grad(u) * ustar, v)
             + NU * ufl.inner(ufl.grad(u), ufl.grad(v)) - p * ufl.div(v) - q * ufl.div(u)) * DX
        rhs = -ufl.inner(old, v) * DX
        self.a, self.L = fem.form(a), fem.form(rhs)
        un, pn = ufl.split(self.w)
        self.force = [fem.form(momentum(un, pn, f) * DX) for f in self.phi]
        self.A = fpetsc.create_matrix(self.a)
        self.b = fpetsc.create_vector(self.L)
        self.iterations, self.factorizations, self.fresh = 0, 0, True
        self.ksp = PETSc.KSP().create(msh.comm)
        # GMRES preconditioned by the LU of a recent step's matrix, refactored
        # when the iterations grow past REFACTOR_ITS, when the scheme changes
        # and when GMRES fails: u* moves little in a step, so a few iterations
        # replace most factorizations (the factorization is most of a step)
        self.ksp.setType("gmres")
        self.ksp.setTolerances(rtol=1e-9, atol=1e-14, max_it=50)
        pc = self.ksp.getPC()
        pc.setType("lu")
        pc.setFactorSolverType("mumps")

    def solve(self):
        self.ksp.getPC().setReusePreconditioner(not self.fresh)
        self.factorizations += self.fresh
        self.ksp.solve(self.b, self.w.vector)
        self.iterations += self.ksp.getIterationNumber()

    def step(self, dt, bdf2):
        if dt != self.k.value or bdf2 != (self.a0.value == 1.5):
            self.fresh = True
        self.k.value = dt
        c = (1.5, -2.0, 0.5, 2.0, -1.0) if bdf2 else (1.0, -1.0, 0.0, 1.0, 0.0)
        for const, val in zip((self.a0, self.a1, self.a2, self.e1, self.e2), c):
            const.value = val
        self.A.zeroEntries()
        fpetsc.assemble_matrix(self.A, self.a, bcs=self.bcs)
        self.A.assemble()
        with self.b.localForm() as bl:
            bl.set(0)
        fpetsc.assemble_vector(self.b, self.L)
        fpetsc.apply_lifting(self.b, [self.a], bcs=[self.bcs])
        self.b.ghostUpdate(addv=PETSc.InsertMode.ADD, mode=PETSc.ScatterMode.REVERSE)
        fem.set_bc(self.b, self.bcs)
        self.ksp.setOperators(self.A)
        self.solve()
        if self.ksp.getConvergedReason() <= 0 and not self.fresh:
            self.fresh = True
            self.solve()
        if self.ksp.getConvergedReason() <= 0:
            sys.exit("dfg_cylinder: the linear solve failed (reason %d)" % self.ksp.getConvergedReason())
        self.fresh = self.ksp.getIterationNumber() > REFACTOR_ITS
        self.w.x.scatter_forward()
        # F = -R(phi): the force on the cylinder, before u^n, u^{n-1} move on
        fx, fy = (-fem.assemble_scalar(f) for f in self.force)
        self.w2.x.array[:] = self.w1.x.array
        self.w1.x.array[:] = self.w.x.array
        return 2 * fx / (D * 1.0 ** 2), 2 * fy / (D * 1.0 ** 2)


def peaks(t, y):
    """Times and values of the interior local maxima of y(t), each refined by
    the parabola through it and its two neighbours."""
    out = []
    for i in range(1, len(y) - 1):
        if y[i] >= y[i - 1] and y[i] > y[i + 1]:
            d = y[i - 1] - 2 * y[i] + y[i + 1]
            s = 0.5 * (y[i - 1] - y[i + 1]) / d if d else 0.0
            h = t[i + 1] - t[i]
            out.append((t[i] + s * h, y[i] - 0.25 * (y[i - 1] - y[i + 1]) * s))
    return out


def aitken(x):
    """The limit of a geometrically converging sequence from its last three
    terms (Aitken's delta-squared); the last term when they do not converge."""
    if len(x) < 3:
        return x[-1]
    d1, d2 = x[-2] - x[-3], x[-1] - x[-2]
    if d1 == d2 or abs(d2) >= abs(d1):
        return x[-1]
    return x[-1] - d2 * d2 / (d2 - d1)


def analyse(hist, window):
    """The last period's maxima: max c_L its last lift maximum, max c_D the
    largest drag maximum since the lift maximum before it, St from the lift
    maxima's mean spacing over the window.  After a change of time step the
    amplitude relaxes slowly (the lift's maxima approach their limit by a
    ratio of about 0.7 a period, measured), so the drift of the last
    maxima and their Aitken limit are reported too."""
    t = np.array([r[0] for r in hist])
    sel = t >= t[-1] - window
    t, cd, cl = t[sel], np.array([r[1] for r in hist])[sel], np.array([r[2] for r in hist])[sel]
    pl, pd = peaks(t, cl), peaks(t, cd)
    if len(pl) < 2 or not pd:
        return {"periodic": False}
    tl = np.array([p[0] for p in pl])
    last_d = [p[1] for p in pd if p[0] > tl[-2]]
    # drag peaks twice a lift period: the period's largest, per period
    per = [max([p[1] for p in pd if a < p[0] <= b] or [np.nan]) for a, b in zip(tl[:-1], tl[1:])]
    per = [x for x in per if x == x]
    res = {"cd_max": max(last_d), "cl_max": pl[-1][1], "st": D / float(np.mean(np.diff(tl))),
           "lift_peaks": len(pl), "cl_drift": pl[-1][1] - pl[-2][1],
           "cl_max_limit": aitken([p[1] for p in pl]), "cd_max_limit": aitken(per) if per else max(last_d),
           "periodic": True}
    res["inside"] = all(BOUNDS[k][0] <= res[k] <= BOUNDS[k][1] for k in BOUNDS)
    return res


def schedule(a):
    """(dt, t_end) phases: the spin-up, then the measured time step."""
    out = []
    if a.dt_spinup and a.t_spinup:
        out.append((a.dt_spinup, a.t_spinup))
    out.append((a.dt, a.t_end))
    return out


def load_mesh(a, row):
    """The run's mesh (semquad's, or --msh), its figures added to row."""
    with tempfile.TemporaryDirectory() as d:
        if a.msh:
            path, row["msh"] = a.msh, os.path.basename(a.msh)
        else:
            path, report = make_msh(a.semquad, shlex.split(a.mesh_args), d)
            row["mesh_args"] = a.mesh_args
            row["semquad_commit"] = source_commit(ROOT)
            row["worst_eta"] = report["mesh"]["quality"]["min"]
            row["min_scaled_jacobian"] = report["mesh"]["min_scaled_jacobian"]
            if a.keep_msh:
                with open(path, "rb") as f, open(a.keep_msh, "wb") as g:
                    g.write(f.read())
        msh = read_quads(path)
    row["quads"] = msh.topology.index_map(2).size_global
    return msh


def march(ch, a, t, out):
    """Every phase of the schedule from time t; the (t, c_D, c_L) of each step."""
    hist, t0 = [], time.perf_counter()
    last = t0
    for dt, t_end in schedule(a):
        first = True
        for _ in range(int(round((t_end - t) / dt))):
            t += dt
            ch.set_boundary(t, a.kick)
            cd, cl = ch.step(dt, bdf2=not first)
            first = False
            hist.append((t, cd, cl))
            if out:
                out.write("%.6f,%.8f,%.8f\n" % hist[-1])
                out.flush()
            if time.perf_counter() - last > 30:
                last = time.perf_counter()
                print("dfg: t %.4f c_D %.5f c_L %+.5f (%.0f s)" % (t, cd, cl, last - t0), flush=True)
    return hist


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--semquad", default=os.environ.get("SEMQUAD", os.path.join(ROOT, "build-release", "src",
                                                                                   "semquad")))
    g = ap.add_mutually_exclusive_group(required=True)
    g.add_argument("--analyse", metavar="CSV", help="only analyse this --history file")
    g.add_argument("--mesh-args", help='options for `semquad mesh`, e.g. "--size 0.02"')
    g.add_argument("--msh", help="solve on this order-2 quad MSH instead")
    ap.add_argument("--dt", type=float, default=0.0025, help="measured time step (default 0.0025)")
    ap.add_argument("--t-end", type=float, default=6.0, help="(default 6)")
    ap.add_argument("--dt-spinup", type=float, default=0.02, help="spin-up time step (default 0.02; 0: none)")
    ap.add_argument("--t-spinup", type=float, default=4.0, help="spin-up until (default 4)")
    ap.add_argument("--window", type=float, default=1.0, help="seconds at the end measured (default 1)")
    ap.add_argument("--kick", type=float, default=0.5, help="cylinder surface speed at t = 1.5 (default 0.5)")
    ap.add_argument("--save", help="write the last two steps' solutions here (.npz) for --restart")
    ap.add_argument("--restart", help="start from a --save file of the same mesh (a BDF1 step first)")
    ap.add_argument("--json", help="append the run's row (JSON, one line) here")
    ap.add_argument("--history", help="write t, c_D, c_L of every step here (CSV)")
    ap.add_argument("--name", default="")
    ap.add_argument("--keep-msh", help="copy the semquad MSH here")
    a = ap.parse_args()
    if a.analyse:
        hist = [tuple(float(v) for v in ln.split(",")) for ln in open(a.analyse).readlines()[1:]]
        print(json.dumps(analyse(hist, a.window)))
        return
    load0 = os.getloadavg()[0]
    t0 = time.perf_counter()
    row = {"name": a.name, "dt": a.dt, "t_end": a.t_end, "dt_spinup": a.dt_spinup, "t_spinup": a.t_spinup}
    ch = Channel(load_mesh(a, row))
    row["dofs"] = ch.ndofs
    print("dfg: %d quads, %d dofs" % (row["quads"], row["dofs"]), flush=True)
    t = 0.0
    if a.restart:
        z = np.load(a.restart)
        if len(z["w1"]) != len(ch.w1.x.array):
            sys.exit("dfg_cylinder: %s is not of this mesh" % a.restart)
        t, ch.w1.x.array[:], ch.w2.x.array[:] = float(z["t"]), z["w1"], z["w2"]
        row["restart_t"] = t
    # written as it goes, so a long run can be watched (and analysed if cut)
    out = open(a.history, "w") if a.history else None
    if out:
        out.write("t,cd,cl\n")
    hist = march(ch, a, t, out)
    if out:
        out.close()
    if a.save:
        np.savez(a.save, t=hist[-1][0], w1=ch.w1.x.array, w2=ch.w2.x.array)
    row["gmres_per_step"] = round(ch.iterations / max(1, len(hist)), 2)
    row["factorizations"] = ch.factorizations
    row.update(analyse(hist, a.window))
    row["seconds"] = round(time.perf_counter() - t0, 1)
    row["load"] = [round(load0, 2), round(os.getloadavg()[0], 2)]
    line = json.dumps(row)
    print(line, flush=True)
    if a.json:
        with open(a.json, "a") as f:
            f.write(line + "\n")


if __name__ == "__main__":
    main()
