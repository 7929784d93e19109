#!/usr/bin/python3
"""semquad mesh against Gmsh 4.8.4 on the examples (issue 7's benchmark).

For every examples/*.step (sphere.step excepted: not a planar face):
  semquad  `semquad mesh FILE --order 1 --size H -o out.msh --report r.json -q`
  Gmsh     Debian's python3-gmsh 4.8.4 in a child /usr/bin/python3 process:
           gmsh.open(FILE) (OpenCASCADE STEP import), Mesh.Algorithm = 8
           (Frontal-Delaunay for quads), Mesh.RecombineAll = 1,
           Mesh.RecombinationAlgorithm = 3 (Blossom full-quad),
           Mesh.CrossFieldClosestPoint = 0, Mesh.MeshSizeMax = H,
           Mesh.MeshSizeFactor = f, General.NumThreads = 1, generate(2),
           write MSH 4.1.  f is calibrated (a few untimed runs) until Gmsh's
           quad count is within 10 % (at worst 20 %) of semquad's.
Both meshes are measured with tests/msh_quad_stats.py (or --quadstats PATH, a
script printing the same JSON keys):
quads, leftover triangles, interior irregular vertices, eta mean, eta worst,
tau = % of quads with eta > 0.9.  Times are medians of --runs runs, two for
each mesher: the whole process (wall clock; peak memory is its max RSS,
/usr/bin/time -v) — for Gmsh, Debian's `gmsh` executable (4.8.4, the same
library) with the same options on the command line (-setnumber), or, if it
is not installed, the Python child's import + initialize + run (its
interpreter's start-up left out); and the in-process time from reading the
STEP file to the mesh file written (Gmsh: open + generate + write timed
inside the Python child; semquad: its report's timings_s.total).  Targets
are judged like against like.

Usage (from the repository root; needs Debian's /usr/bin/python3 with gmsh):
  /usr/bin/python3 bench/compare_gmsh.py [--semquad PATH] [--size 0.1] [--runs 3]
        [--examples a,b] [--json out.json] [--keep DIR]
The semquad binary: --semquad, else $SEMQUAD, else build/src/semquad (built
by the caller: a release build, e.g. build-release/src/semquad, for numbers).
Prints Markdown on stdout.  Not a test.
"""
import argparse
import glob
import json
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
QUADSTATS_DEFAULT = os.path.join(ROOT, "tests", "msh_quad_stats.py")
PY = "/usr/bin/python3"  # the interpreter with Debian's gmsh module


# ---------------------------------------------------------------- Gmsh child
def gmsh_child(step, out, hmax, factor, rec_alg):
    t0 = time.perf_counter()
    import gmsh
    gmsh.initialize(["gmsh", "-v", "0"])
    t1 = time.perf_counter()
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.option.setNumber("General.NumThreads", 1)
    gmsh.open(step)
    t2 = time.perf_counter()
    gmsh.option.setNumber("Mesh.Algorithm", 8)
    gmsh.option.setNumber("Mesh.RecombineAll", 1)
    gmsh.option.setNumber("Mesh.RecombinationAlgorithm", rec_alg)
    gmsh.option.setNumber("Mesh.CrossFieldClosestPoint", 0)
    gmsh.option.setNumber("Mesh.MeshSizeMax", hmax)
    gmsh.option.setNumber("Mesh.MeshSizeFactor", factor)
    gmsh.option.setNumber("Mesh.ElementOrder", 1)
    gmsh.option.setNumber("Mesh.MshFileVersion", 4.1)
    gmsh.model.mesh.generate(2)
    t3 = time.perf_counter()
    gmsh.write(out)
    t4 = time.perf_counter()
    info = {"version": gmsh.option.getString("General.Version"),
            "import_init": t1 - t0, "open": t2 - t1, "mesh": t3 - t2, "write": t4 - t3,
            "in_process": t4 - t1, "surfaces": len(gmsh.model.getEntities(2))}
    gmsh.finalize()
    print(json.dumps(info))


# ---------------------------------------------------------------- helpers
def timed(cmd):
    """Run under /usr/bin/time -v: (returncode, stdout, stderr, wall s, max RSS KiB)."""
    t0 = time.perf_counter()
    p = subprocess.run(["/usr/bin/time", "-v"] + cmd, stdout=subprocess.PIPE,
                       stderr=subprocess.PIPE, text=True)
    wall = time.perf_counter() - t0
    rss = 0
    for line in p.stderr.splitlines():
        if "Maximum resident set size" in line:
            rss = int(line.split(":")[1])
    return p.returncode, p.stdout, p.stderr, wall, rss


def quadstats(qs, msh):
    p = subprocess.run([PY, qs, msh], stdout=subprocess.PIPE,
                       stderr=subprocess.PIPE, text=True)
    if p.returncode != 0:
        return None
    return json.loads(p.stdout)


GMSH_EXE = shutil.which("gmsh")


def gmsh_exe_cmd(step, out, hmax, factor, rec_alg):
    """The gmsh executable with the options of gmsh_child."""
    opts = [("General.NumThreads", 1), ("Mesh.Algorithm", 8), ("Mesh.RecombineAll", 1),
            ("Mesh.RecombinationAlgorithm", rec_alg), ("Mesh.CrossFieldClosestPoint", 0),
            ("Mesh.MeshSizeMax", hmax), ("Mesh.MeshSizeFactor", factor), ("Mesh.ElementOrder", 1)]
    cmd = [GMSH_EXE, step, "-2", "-format", "msh41", "-o", out, "-v", "0"]
    for k, v in opts:
        cmd += ["-setnumber", k, repr(v)]
    return cmd


def gmsh_cmd(step, out, hmax, factor, rec_alg):
    return [PY, os.path.abspath(__file__), "--gmsh-child", step, out,
            repr(hmax), repr(factor), str(rec_alg)]


def last_err(stderr):
    lines = [l for l in stderr.splitlines() if l.strip() and not l.startswith("\t")
             and not l.startswith("Command ")]
    return lines[-1].strip() if lines else ""


def run_gmsh_once(step, out, hmax, factor, rec_alg):
    rc, so, se, wall, rss = timed(gmsh_cmd(step, out, hmax, factor, rec_alg))
    info = None
    if rc == 0:
        try:
            info = json.loads(so.strip().splitlines()[-1])
        except (ValueError, IndexError):
            rc = -1
    return rc, info, wall, rss, se


def calibrate(step, out, hmax, target, rec_alg, qs, log):
    """Find Mesh.MeshSizeFactor so Gmsh's quad count is close to target."""
    f, best = 2.0, None  # full-quad splits every element in 4: start at 2h
    for it in range(8):
        rc, info, _, _, se = run_gmsh_once(step, out, hmax, f, rec_alg)
        if rc != 0:
            return None, "exit %d: %s" % (rc, last_err(se))
        st = quadstats(qs, out)
        n = st["quads"] if st else 0
        log.append((f, n))
        if n == 0:
            return None, "no quads"
        dev = abs(n / target - 1)
        if best is None or dev < best[1]:
            best = (f, dev, n)
        if dev < 0.10:
            break
        f *= (n / target) ** 0.5
    if best[1] > 0.20:
        return best[0], "quad count %d vs %d (%.0f %% off) after calibration" % (
            best[2], target, 100 * best[1])
    return best[0], None


def med(x):
    return statistics.median(x)


def fmt_row(name, tool, st, wall, rss, extra=""):
    if st is None:
        return "| %s | %s | — | — | — | — | — | — | — | — | %s |" % (name, tool, extra)
    return "| %s | %s | %d%s | %d | %.3f | %.3f | %.1f | %s | %.0f | %s |" % (
        name, tool, st["quads"], (" + %d tri" % st["triangles"]) if st["triangles"] else "",
        st["interior_irregular"], st["eta_mean"], st["eta_min"], st["eta_pct_gt_0.9"],
        wall, rss / 1024.0, extra)


def both_meshed(results, ncols):
    """(name, semquad's result, Gmsh's) of the examples both meshed; a row of
    ncols n/a for the others."""
    for name, r in results.items():
        sq, g = r["semquad"], r["gmsh"]
        if "error" in sq or "error" in g:
            print("| %s | %s |" % (name, " | ".join(["n/a"] * ncols)))
            continue
        yield name, sq, g


# ---------------------------------------------------------------- main
def main():
    if len(sys.argv) > 1 and sys.argv[1] == "--gmsh-child":
        a = sys.argv[2:]
        gmsh_child(a[0], a[1], float(a[2]), float(a[3]), int(a[4]))
        return 0
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--semquad", default=os.environ.get("SEMQUAD", os.path.join(ROOT, "build", "src",
                                                                                "semquad")),
                    help="the semquad binary (default $SEMQUAD, else build/src/semquad)")
    ap.add_argument("--size", type=float, default=0.1)
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--examples", default="")
    ap.add_argument("--recombination", type=int, default=3,
                    help="Mesh.RecombinationAlgorithm (3 Blossom full-quad, 2 simple full-quad)")
    ap.add_argument("--quadstats", default=QUADSTATS_DEFAULT)
    ap.add_argument("--json", default="")
    ap.add_argument("--keep", default="", help="keep the .msh files in this folder")
    a = ap.parse_args()

    if not os.access(a.semquad, os.X_OK):
        print("compare_gmsh: %s is not an executable (--semquad or $SEMQUAD)" % a.semquad,
              file=sys.stderr)
        return 2

    files = sorted(glob.glob(os.path.join(ROOT, "examples", "*.step")))
    files = [f for f in files if os.path.basename(f) != "sphere.step"]
    if a.examples:
        want = set(a.examples.split(","))
        files = [f for f in files if os.path.basename(f)[:-5] in want]

    tmp = a.keep or tempfile.mkdtemp(prefix="sq-gmsh-")
    os.makedirs(tmp, exist_ok=True)
    # baseline of the Gmsh child: Python start-up + import gmsh + initialize
    base = [timed([PY, "-c", "import gmsh; gmsh.initialize(); gmsh.finalize()"])
            for _ in range(a.runs)]
    base_wall, base_rss = med([b[3] for b in base]), max(b[4] for b in base)

    results = {}
    rows = []
    for f in files:
        name = os.path.basename(f)[:-5]
        r = results[name] = {}
        sq_msh, sq_rep = os.path.join(tmp, name + ".semquad.msh"), os.path.join(tmp, name + ".json")
        walls, inproc, meshing, rss, err = [], [], [], 0, None
        for _ in range(a.runs):
            rc, _, se, wall, m = timed([a.semquad, "mesh", f, "--order", "1", "--size", repr(a.size),
                                        "-o", sq_msh, "--report", sq_rep, "-q"])
            if rc != 0:
                err = "exit %d: %s" % (rc, last_err(se))
                break
            walls.append(wall)
            t = json.load(open(sq_rep))["timings_s"]
            inproc.append(t["total"])
            meshing.append(t["total"] - t.get("read", 0.0) - t.get("write", 0.0))
            rss = max(rss, m)
        sq_st = None if err else quadstats(a.quadstats, sq_msh)
        rep = None if err else json.load(open(sq_rep))
        r["semquad"] = {"error": err} if err else {
            "wall_s": med(walls), "in_process_s": med(inproc), "mesh_s": med(meshing),
            "field": rep.get("field", {}).get("kind", "?"), "max_rss_kib": rss,
            "quadstats": sq_st, "report_timings_s": rep.get("timings_s")}
        # Gmsh: calibrate on semquad's quad count (or on its own size if semquad failed)
        g_msh = os.path.join(tmp, name + ".gmsh.msh")
        log = []
        target = sq_st["quads"] if sq_st else None
        if target:
            factor, gerr = calibrate(f, g_msh, a.size, target, a.recombination, a.quadstats, log)
        else:
            factor, gerr = 2.0, None
        note = ""
        if factor is None:
            r["gmsh"] = {"error": gerr, "calibration": log}
        else:
            if gerr:
                note = gerr
            gw, gin, ggen, gload, gexe, grss, gfail = [], [], [], [], [], 0, None
            for _ in range(a.runs):
                rc, info, wall, m, se = run_gmsh_once(f, g_msh, a.size, factor, a.recombination)
                if rc != 0:
                    gfail = "exit %d: %s" % (rc, last_err(se))
                    break
                gw.append(wall)
                gin.append(info["in_process"])
                ggen.append(info["mesh"])
                gload.append(info["import_init"] + info["in_process"])
                grss = max(grss, m)
                if GMSH_EXE:
                    g_exe_msh = os.path.join(tmp, name + ".gmsh-exe.msh")
                    rc, _, se, wall, m = timed(gmsh_exe_cmd(f, g_exe_msh, a.size, factor,
                                                            a.recombination))
                    if rc != 0:
                        gfail = "gmsh executable: exit %d: %s" % (rc, last_err(se))
                        break
                    gexe.append((wall, m))
            if gfail:
                r["gmsh"] = {"error": gfail}
            else:
                g_st = quadstats(a.quadstats, g_msh)
                if gexe:  # the executable's process is Gmsh's process
                    exe_st = quadstats(a.quadstats, g_exe_msh)
                    if exe_st and exe_st["quads"] != g_st["quads"]:
                        note += "; executable: %d quads" % exe_st["quads"]
                    process, prss, how = med([w for w, _ in gexe]), max(m for _, m in gexe), "exe"
                else:
                    process, prss, how = med(gload), grss, "python load+run"
                r["gmsh"] = {"wall_s": med(gw), "in_process_s": med(gin), "generate_s": med(ggen),
                             "load_and_run_s": med(gload), "process_s": process,
                             "process_max_rss_kib": prss, "process_how": how,
                             "max_rss_kib": grss,
                             "size_factor": factor, "calibration": log, "quadstats": g_st,
                             "version": info["version"], "note": note}
        results[name] = r

        sq = r["semquad"]
        g = r["gmsh"]
        rows.append(fmt_row(name, "semquad", sq.get("quadstats"),
                            "%.3f | %.3f" % (sq["wall_s"], sq["in_process_s"])
                            if "wall_s" in sq else "— | —",
                            sq.get("max_rss_kib", 0), sq.get("error", "") or ""))
        if "error" in g:
            rows.append(fmt_row(name, "Gmsh", None, "— | —", 0, "fails: " + g["error"]))
        else:
            rows.append(fmt_row(name, "Gmsh", g["quadstats"],
                                "%.3f | %.3f" % (g["process_s"], g["in_process_s"]),
                                g["process_max_rss_kib"],
                                ("f = %.3g" % g["size_factor"]) + ("; " + g["note"] if g["note"] else "")))
        print(rows[-2] + "\n" + rows[-1], file=sys.stderr, flush=True)

    # ------------------------------------------------------------ report
    print("### semquad mesh vs Gmsh %s, --size %g, order 1\n" %
          (next((v["gmsh"]["version"] for v in results.values() if "version" in v.get("gmsh", {})), "?"),
           a.size))
    how = next((v["gmsh"]["process_how"] for v in results.values()
                if "process_how" in v.get("gmsh", {})), "exe")
    print("Times: median of %d runs, in seconds. *process*: the whole process, wall clock "
          "(Gmsh: %s); *in-process*: reading the STEP file to the mesh file written (Gmsh: "
          "open + generate + write timed inside a Python child, which on its own takes "
          "%.3f s and %.0f MiB to start Python and import gmsh; semquad: its report's "
          "timings_s.total). Peak RSS of the process. Quality columns from msh_quad_stats.py on "
          "the .msh files.\n"
          % (a.runs, "Debian's gmsh 4.8.4 executable with the same options on its command "
             "line" if how == "exe" else "Python child's import + initialize + run, the "
             "interpreter's start-up left out (no gmsh executable installed)",
             base_wall, base_rss / 1024.0))
    print("| example | mesher | quads | interior irregular | η̄ | η_w | τ (%) | process (s) | in-process (s) | peak RSS (MiB) | notes |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for row in rows:
        print(row)
    print()
    # targets
    print("| example | fewer irregular | better η_w | process ≤ Gmsh process | in-process ≤ Gmsh in-process |")
    print("|---|---|---|---|---|")
    for name, sq, g in both_meshed(results, 4):
        s, t = sq["quadstats"], g["quadstats"]
        yn = lambda b: "yes" if b else "**no**"
        print("| %s | %s (%d vs %d) | %s (%.3f vs %.3f) | %s (%.3f vs %.3f) | %s (%.3f vs %.3f) |" % (
            name, ("tie" if s["interior_irregular"] == t["interior_irregular"] else yn(s["interior_irregular"] < t["interior_irregular"])), s["interior_irregular"],
            t["interior_irregular"], yn(s["eta_min"] > t["eta_min"]), s["eta_min"], t["eta_min"],
            yn(sq["wall_s"] <= g["process_s"]), sq["wall_s"], g["process_s"],
            yn(sq["in_process_s"] <= g["in_process_s"]), sq["in_process_s"], g["in_process_s"]))
    print()
    # meshing alone, per quad: semquad's timings_s.total minus read and write
    # against Gmsh's generate, and which field each example's layout took
    print("| example | semquad field | semquad mesh (ms) | µs/quad | Gmsh generate (ms) | µs/quad "
          "| ratio per quad |")
    print("|---|---|---|---|---|---|---|")
    for name, sq, g in both_meshed(results, 6):
        us = 1e6 * sq["mesh_s"] / sq["quadstats"]["quads"]
        ug = 1e6 * g["generate_s"] / g["quadstats"]["quads"]
        print("| %s | %s | %.1f | %.1f | %.1f | %.1f | %.2f |" % (
            name, sq["field"], 1e3 * sq["mesh_s"], us, 1e3 * g["generate_s"], ug, us / ug))
    print()
    if a.json:
        with open(a.json, "w") as fh:
            json.dump({"size": a.size, "runs": a.runs, "baseline_python_gmsh_s": base_wall,
                       "baseline_python_gmsh_rss_kib": base_rss, "results": results}, fh, indent=1)
    if not a.keep:
        shutil.rmtree(tmp, ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
