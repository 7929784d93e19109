#!/usr/bin/python3
"""Mesh the planar faces of real CAD parts (bench/real_parts.md lists the files).

usage: /usr/bin/python3 bench/real_parts_bench.py PARTS_DIR [--semquad PATH] [--timeout 60]
           [--jobs 2] [--max-faces K] [--files a.stp,b.brep] [--gmsh] [--peer CMD]
           [--json out.json] [--doc docs/benchmarks.md] [--from-json run.json]

For every STEP/IGES/BREP file of PARTS_DIR: `semquad info FILE --json` lists its faces;
every planar face (or K of them, evenly spread over the file's face indices, with
--max-faces K) is meshed by `semquad mesh FILE --face N -q --report R -o M` at the
default size, killed after --timeout s.  A face succeeds when semquad exits 0 with
every scaled Jacobian > 0.  A file `info` cannot read counts as one failure.

--gmsh   also meshes each face with Gmsh 4.8.4 (Debian's python3-gmsh, this
         interpreter): Frontal-Delaunay for quads + Blossom recombination, size
         sqrt(area)/8 (semquad's default), one child process per file; a face is
         covered when every element is a quadrangle.
--peer CMD (or $SQ_QUADQS): a command run as `CMD FILE SIZE OUT.msh 1 FACE` per face
         (the calling convention of a Gmsh 4.13 quasi-structured wrapper: FACE is the
         0-based surface index in OCC's order), same size; covered when OUT.msh holds
         quadrangles only.  Where both mesh a face, both MSH files are measured alike
         (benchlib.quad_figures: interior irregular vertices, corner scaled Jacobians).
Prints Markdown; --doc replaces (or appends) the section "Planar faces of real parts";
--from-json writes the tables of an earlier --json run instead of meshing.
"""
import argparse
import concurrent.futures
import datetime
import json
import math
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import benchlib  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EXTS = (".step", ".stp", ".iges", ".igs", ".brep", ".brp")


def list_faces(semquad, path, timeout):
    """(planar faces [(index, area)], total faces, the file's unit, error line or '')."""
    try:
        p = subprocess.run([semquad, "info", path, "--json"], capture_output=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return [], 0, "", "timeout"
    if p.returncode != 0:
        err = [ln for ln in p.stderr.decode(errors="replace").splitlines() if ln.strip()]
        return [], 0, "", "exit %d: %s" % (p.returncode, err[-1] if err else "")
    d = json.loads(p.stdout)
    faces = d["faces"]
    # a broken face (info's status "broken: ...") has no area: it is listed all the same
    return ([(f["index"], f.get("area", 0.0)) for f in faces if f["surface"] == "plane"],
            len(faces), d.get("unit", ""), "")


def spread(items, k):
    """k items evenly spread over the list (all of them when k <= 0 or k >= len)."""
    if k <= 0 or k >= len(items):
        return items
    return [items[int(j * len(items) / k)] for j in range(k)]


GMSH_CHILD = r"""
import json, sys, gmsh
path, faces, unit = sys.argv[1], json.loads(sys.argv[2]), sys.argv[3]
gmsh.initialize(["gmsh", "-v", "0"]); gmsh.option.setNumber("General.Terminal", 0)
gmsh.option.setNumber("General.NumThreads", 1)
if unit:  # Gmsh converts STEP/IGES to mm unless told the unit to keep; semquad keeps the file's
    gmsh.option.setString("Geometry.OCCTargetUnit", unit.upper())
# every dimension, as semquad lists them: the default keeps only the highest (a free face
# beside a solid, NIST CTC 02's face 663, would be missed and the indices would not match)
ents = gmsh.model.occ.importShapes(path, highestDimOnly=False); gmsh.model.occ.synchronize()
surfs = gmsh.model.getEntities(2)
for idx, area, h in faces:
    out = {"face": idx}
    if idx >= len(surfs) or abs(gmsh.model.occ.getMass(2, surfs[idx][1]) - area) > 1e-6 * max(area, 1e-300):
        out["error"] = "face index mismatch"
    else:
        tag = surfs[idx][1]
        gmsh.model.mesh.clear()
        gmsh.model.setVisibility(gmsh.model.getEntities(), 0)
        gmsh.model.setVisibility([(2, tag)], 1, recursive=True)
        for k, v in [("Mesh.MeshOnlyVisible", 1), ("Mesh.Algorithm", 8), ("Mesh.RecombineAll", 1),
                     ("Mesh.RecombinationAlgorithm", 3), ("Mesh.MeshSizeMax", h),
                     ("Mesh.MeshSizeFromCurvature", 0), ("Mesh.CrossFieldClosestPoint", 0)]:
            gmsh.option.setNumber(k, v)
        try:
            gmsh.model.mesh.generate(2)
            types, elems, _ = gmsh.model.mesh.getElements(2, tag)
            n = {gmsh.model.mesh.getElementProperties(t)[0]: len(e) for t, e in zip(types, elems)}
            out["elements"] = n
        except Exception as e:
            out["error"] = str(e).splitlines()[0] if str(e) else "exception"
    print(json.dumps(out), flush=True)
gmsh.finalize()
"""


def gmsh_file(path, faces, unit, timeout):
    """Gmsh 4.8.4 per face of one file, {face: (covered, note)}; a child that dies
    (Gmsh can crash on a face) costs that face only: the next child resumes after it."""
    res = {}
    todo = list(faces)
    while todo:
        arg = json.dumps([[i, a, math.sqrt(a) / 8] for i, a in todo])
        try:
            p = subprocess.run([sys.executable, "-c", GMSH_CHILD, path, arg, unit], capture_output=True,
                               timeout=timeout * len(todo), text=True)
            out, why = p.stdout, "exit %d" % p.returncode
        except subprocess.TimeoutExpired as e:
            out = e.stdout.decode() if isinstance(e.stdout, bytes) else (e.stdout or "")
            why = "timeout"
        for line in out.splitlines():
            d = json.loads(line)
            if "error" in d:
                res[d["face"]] = (False, d["error"])
            else:
                n = d["elements"]
                quads = sum(v for k, v in n.items() if k.startswith("Quadrilateral"))
                other = sum(v for k, v in n.items() if not k.startswith("Quadrilateral"))
                res[d["face"]] = (quads > 0 and other == 0, "%d quads, %d other" % (quads, other))
        todo = [f for f in todo if f[0] not in res]
        if todo:
            res[todo[0][0]] = (False, why)
            todo = todo[1:]
    return res


def peer_face(cmd, path, idx, area, unit, work, timeout):
    out = os.path.join(work, "peer_%d_%d.msh" % (os.getpid(), idx))
    env = dict(os.environ, QUADQS_UNIT=unit.upper())  # keep the file's unit, as semquad does
    try:
        p = subprocess.run(cmd.split() + [path, repr(math.sqrt(area) / 8), out, "1", str(idx)],
                           capture_output=True, timeout=timeout, text=True, env=env)
    except subprocess.TimeoutExpired:
        return False, "timeout"
    if p.returncode != 0 or not os.path.exists(out):
        err = [ln for ln in p.stderr.splitlines() if ln.strip()]
        return False, "exit %d: %s" % (p.returncode, err[-1][:80] if err else "")
    fig = benchlib.quad_figures(out)
    os.remove(out)
    return fig["quads"] > 0 and fig["other"] == 0, "%d quads, %d other" % (fig["quads"], fig["other"]), fig


def run(args):
    files = sorted(f for f in os.listdir(args.parts) if f.lower().endswith(EXTS))
    if args.files:
        keep = set(args.files.split(","))
        files = [f for f in files if f in keep]
    work = tempfile.mkdtemp(prefix="sq-parts-")
    jobs = []
    file_rows = []
    for f in files:
        path = os.path.join(args.parts, f)
        planar, total, unit, err = list_faces(args.semquad, path, args.timeout)
        chosen = spread(planar, args.max_faces)
        file_rows.append({"file": f, "faces": total, "planar": len(planar), "meshed_faces": len(chosen),
                          "unit": unit, "info_error": err})
        for idx, area in chosen:
            jobs.append((f, path, idx, area, unit))
        print("%s: %d faces, %d planar, %d chosen %s" % (f, total, len(planar), len(chosen), err),
              file=sys.stderr, flush=True)

    def one(job):
        f, path, idx, area, unit = job
        r = benchlib.run_mesh(args.semquad, path, work, "%s_%d" % (f, idx), args.timeout, ["--face", str(idx)],
                             measure=benchlib.quad_figures if args.peer else None)
        r.update({"file": f, "face": idx, "area": area})
        r["outcome"] = benchlib.outcome(r)
        if args.peer:
            r["peer"] = peer_face(args.peer, path, idx, area, unit, work, args.timeout)
        return r

    rows = []
    with concurrent.futures.ThreadPoolExecutor(max_workers=min(args.jobs, 2)) as ex:
        for r in ex.map(one, jobs):
            rows.append(r)
            print("%-45s face %-4d %-5s %6.2fs %s" % (r["file"], r["face"], r["exit"], r["seconds"], r["outcome"]),
                  file=sys.stderr, flush=True)
    if args.gmsh:
        gmsh_stage(args, file_rows, rows)
    try:
        os.rmdir(work)
    except OSError as e:  # a peer that bind-mounts its output's folder (a chroot) keeps it busy
        print("left the empty folder %s: %s" % (work, e.strerror), file=sys.stderr)
    return file_rows, rows


def gmsh_stage(args, file_rows, rows):
    """Gmsh 4.8.4 on the faces semquad meshed, one child process per file."""
    unit = {fr["file"]: fr.get("unit") for fr in file_rows}
    by_file = {}
    for r in rows:
        by_file.setdefault(r["file"], []).append(r)
    for f, rs in by_file.items():
        path = os.path.join(args.parts, f)
        if unit.get(f) is None:  # a run from before units were recorded
            unit[f] = list_faces(args.semquad, path, args.timeout)[2]
        res = gmsh_file(path, [(r["face"], r["area"]) for r in rs], unit[f], args.timeout)
        for r in rs:
            r["gmsh"] = res[r["face"]]


def peer_lines(got):
    """semquad against the peer on the faces both mesh all-quad, each mesh's
    figures from its MSH file by benchlib.quad_figures (one measure for both)."""
    both = [r for r in got if r["outcome"] == "ok" and r["peer"][0] and len(r["peer"]) > 2 and "msh" in r]
    if not both:
        return []

    def med(v):
        v = sorted(v)
        return v[len(v) // 2]

    lines = ["", "On the %d faces both mesh (figures of the MSH files, corners only: `quad_figures` "
             "of bench/benchlib.py):" % len(both), "",
             "| mesher | quads | interior irregular (sum) | faces with 0 irregular | faces with fewer irregular "
             "| median min scaled Jacobian | mean of each quad's least scaled Jacobian | worst scaled Jacobian |",
             "|---|---|---|---|---|---|---|---|"]
    for name, fig, other in (("semquad", lambda r: r["msh"], lambda r: r["peer"][2]),
                             ("peer", lambda r: r["peer"][2], lambda r: r["msh"])):
        lines.append("| %s | %d | %d | %d | %d | %.3f | %.3f | %.3f |" % (
            name, sum(fig(r)["quads"] for r in both), sum(fig(r)["irregular"] for r in both),
            sum(1 for r in both if fig(r)["irregular"] == 0),
            sum(1 for r in both if fig(r)["irregular"] < other(r)["irregular"]),
            med([fig(r)["min_sj"] for r in both]),
            sum(fig(r)["mean_sj"] * fig(r)["quads"] for r in both) / sum(fig(r)["quads"] for r in both),
            min(fig(r)["min_sj"] for r in both)))
    return lines


def markdown(file_rows, rows, args):
    ok = [r for r in rows if r["outcome"] == "ok"]
    bad_files = [fr for fr in file_rows if fr["info_error"]]
    n = len(rows)
    lines = ["%d files, %d planar faces in all, %d meshed here (%s per file); %d meshed (%.1f %%): "
             "exit 0 or 8 (below the quality floor) with every scaled Jacobian > 0; timeout %g s per face."
             % (len(file_rows), sum(fr["planar"] for fr in file_rows), n,
                "all" if args.max_faces <= 0 else "at most %d, evenly spread" % args.max_faces,
                len(ok), 100.0 * len(ok) / max(n, 1), args.timeout),
             benchlib.below_floor_line(ok)]
    if bad_files:
        lines.append("")
        lines.append("Files `semquad info` cannot read (their faces are not counted above): " +
                     "; ".join("`%s` (%s)" % (fr["file"], fr["info_error"]) for fr in bad_files) + ".")
    lines += ["", "| file | faces | planar | meshed here | ok |", "|---|---|---|---|---|"]
    for fr in file_rows:
        rs = [r for r in rows if r["file"] == fr["file"]]
        lines.append("| %s | %d | %d | %d | %d |" % (fr["file"], fr["faces"], fr["planar"], len(rs),
                                                    sum(1 for r in rs if r["outcome"] == "ok")))
    lines += [""] + benchlib.road_lines(ok, lambda r: "%s --face %d" % (r["file"], r["face"]))
    lines += ["", "Failure classes (exit status and the first words of the message, numbers blanked):", ""]
    lines += benchlib.failure_table(rows, lambda r: "%s --face %d" % (r["file"], r["face"]))
    lines += ["", "Wall time per face, seconds (every face; meshed faces only):", "",
              "| faces | p50 | p90 | p99 | max |", "|---|---|---|---|---|",
              benchlib.time_row(rows), benchlib.time_row(ok)]
    for key, name in (("gmsh", "Gmsh 4.8.4 (Frontal-Delaunay for quads + Blossom, size sqrt(area)/8)"),
                      ("peer", "peer (`--peer`)")):
        # a face the other mesher numbers differently (it merged or split faces) is left out
        got = [r for r in rows if key in r and r[key][1] != "face index mismatch"]
        if got:
            cov = sum(1 for r in got if r[key][0])
            sq = sum(1 for r in got if r["outcome"] == "ok")
            lines += ["", "%s, on the %d faces it numbers as semquad does: all-quad mesh on %d (%.1f %%), "
                      "semquad on %d (%.1f %%); both on %d, semquad only on %d, it only on %d."
                      % (name, len(got), cov, 100.0 * cov / len(got), sq, 100.0 * sq / len(got),
                         sum(1 for r in got if r[key][0] and r["outcome"] == "ok"),
                         sum(1 for r in got if r["outcome"] == "ok" and not r[key][0]),
                         sum(1 for r in got if r["outcome"] != "ok" and r[key][0]))]
            if key == "peer":
                lines += peer_lines(got)
        elif key == "peer":
            lines += ["", "No peer run here (`--peer CMD` or `$SQ_QUADQS`: a Gmsh 4.13 quasi-structured wrapper)."]
    return "\n".join(lines) + "\n"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("parts")
    benchlib.common_args(ap, ROOT, "Planar faces of real parts")
    ap.add_argument("--max-faces", type=int, default=0, help="planar faces per file (default all)")
    ap.add_argument("--files", help="comma-separated file names of PARTS_DIR")
    ap.add_argument("--gmsh", action="store_true", help="Gmsh 4.8.4's coverage too")
    ap.add_argument("--peer", default=os.environ.get("SQ_QUADQS"), help="peer command (default $SQ_QUADQS)")
    args = ap.parse_args()
    if args.from_json:
        with open(args.from_json) as f:
            d = json.load(f)
        file_rows, rows = d["files"], d["faces"]
        if args.gmsh:  # the Gmsh comparison anew on the faces of that run
            gmsh_stage(args, file_rows, rows)
    else:
        file_rows, rows = run(args)
    md = markdown(file_rows, rows, args)
    print(md)
    if args.json:
        with open(args.json, "w") as f:
            json.dump({"files": file_rows, "faces": rows}, f, indent=1)
    if args.doc:
        rev = benchlib.source_commit(ROOT)
        head = ("Issue 14's real parts: the planar faces of 30 public CAD files (mechanical parts, an "
                "assembly, sheet metal, walls with openings, NIST test parts; bench/real_parts.md lists "
                "their sources), each meshed alone (`semquad mesh FILE --face N`) at the default size.\n\n"
                "`/usr/bin/python3 bench/real_parts_bench.py PARTS --max-faces %d%s --doc docs/benchmarks.md` "
                "with those files in PARTS (semquad built from commit %s, `build/` (debugoptimized), %s UTC, "
                "shared 2-core machine under load, %d face(s) at a time).\n\n"
                % (args.max_faces, " --gmsh" if any("gmsh" in r for r in rows) else "", rev,
                   datetime.datetime.utcnow().strftime("%Y-%m-%d %H:%M"), args.jobs))
        benchlib.replace_section(args.doc, "Planar faces of real parts", head + md)


if __name__ == "__main__":
    main()
