#!/usr/bin/python3
"""How `semquad mesh` scales from 10^3 to 10^6 quads (issue 22), beside Gmsh.

For each target quad count N (--quads), order Q (--orders) and thread count
(--threads; 0 = every processor): `semquad mesh STEP --order Q --size H
--threads T -q --report R -o M.msh` under /usr/bin/time -v, H = sqrt(A / N) with
A the face's exact area (`semquad info --json`).  Per run: the quads made, the
report's per-stage seconds (timings_s: read, triangulate + solve + critical
points + trace + layout as "field+layout", mesh, write), the in-process time
mesh + write, peak RSS (VmHWM), quads per second of mesh + write, and
relaxed_at_quads (the coarse mesh relaxed, docs/mesh.md "Large meshes").
The growth exponent b of time ~ quads^b is the least-squares slope of
log(mesh + write) on log(quads) over the runs with 10^4 <= quads <= 10^6.

Peers, at the same H, each only up to its own --*-max-quads target (a loaded
machine cannot afford their large sizes; say so beside the numbers):
  Gmsh 4.8.4   Debian's python3-gmsh in a child /usr/bin/python3
               (bench/compare_gmsh.py's child: Frontal-Delaunay for quads,
               Blossom recombination, one thread, order 1): in-process
               open + generate + write, its max RSS;
  quadqs       Gmsh 4.13's quasi-structured mesher, a command taking
               `IN SIZE OUT.msh ORDER FACE` and printing the seconds of
               generate(2) (--quadqs or $QUADQS; skipped when neither is set);
               its wall time and max RSS, the quads counted in its MSH file.

Usage (from the repository root):
  /usr/bin/python3 bench/scaling.py [--semquad build/src/semquad]
      [--step examples/square_hole.step] [--quads 1e3,1e4,1e5,1e6] [--orders 4,8]
      [--threads 1,0] [--order8-max-quads 1e5] [--gmsh-max-quads 1e5]
      [--quadqs CMD] [--quadqs-max-quads 1e4] [--timeout 600] [--json out.json]
      [--from-json out.json] [--doc docs/benchmarks.md] [--svg docs/scaling.svg]
Prints Markdown (and replaces the doc's section with it).  Not a test.
"""
import argparse
import json
import math
import os
import shlex
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "bench"))
import benchlib  # noqa: E402
import compare_gmsh  # noqa: E402

SECTION = "Scaling to a million quads"
FIELD_STAGES = ("triangulate", "solve", "critical_points", "trace", "layout")


def timed(cmd, timeout):
    """(returncode or None on timeout, stdout, stderr, wall s, max RSS KiB)."""
    try:
        rc, so, se, wall, rss = compare_gmsh.timed(["timeout", "-s", "KILL", str(int(timeout))] + cmd)
    except OSError as e:
        return -1, "", str(e), 0.0, 0
    return (None if rc in (124, 137, -9) else rc), so, se, wall, rss


def face_area(semquad, step):
    out = subprocess.run([semquad, "info", step, "--json"], capture_output=True, text=True, check=True)
    return json.loads(out.stdout)["faces"][0]["area"]


def run_semquad(a, tmp, n, order, threads, size):
    rep, msh = os.path.join(tmp, "r.json"), os.path.join(tmp, "m.msh")
    cmd = [a.semquad, "mesh", a.step, "--order", str(order), "--size", repr(size),
           "--threads", str(threads), "-q", "--report", rep, "-o", msh]
    rc, _, se, wall, rss = timed(cmd, a.timeout)
    row = {"tool": "semquad", "target": n, "order": order, "threads": threads, "size": size,
           "exit": rc, "wall": wall, "rss_kib": rss, "command": " ".join(cmd[1:])}
    if rc == 0:
        d = json.load(open(rep))
        t = d["timings_s"] if "timings_s" in d else d["mesh"]["timings_s"]
        m = d["mesh"]
        row.update(quads=m["quads"], nodes=m["nodes"], relaxed_at=m.get("relaxed_at_quads", 0),
                   read=t["read"], field=sum(t[k] for k in FIELD_STAGES), mesh=t["mesh"],
                   write=t["write"], msh_bytes=os.path.getsize(msh))
        row["in_process"] = row["mesh"] + row["write"]
    else:
        row["error"] = compare_gmsh.last_err(se)
    for f in (rep, msh):
        if os.path.exists(f):
            os.remove(f)
    return row


def msh_quads(path):
    """Quads (types 3, 10, 36, ...: Gmsh's quadrangles of every order) in an MSH 4.1 text file."""
    quad_types = {3, 10, 16, 36, 37, 38, 47, 48, 49, 50, 51}
    n, blocks = 0, 0
    with open(path) as f:
        for line in f:
            if line.startswith("$Elements"):
                nb = int(f.readline().split()[0])
                for _ in range(nb):
                    dim, _, typ, cnt = (int(x) for x in f.readline().split())
                    for _ in range(cnt):
                        f.readline()
                    n += cnt if typ in quad_types else 0
                    blocks += 1
                break
    return n


def run_gmsh(a, tmp, n, size):
    msh = os.path.join(tmp, "g.msh")
    rc, info, wall, rss, se = compare_gmsh.run_gmsh_once(a.step, msh, size, 1.0, 3)
    row = {"tool": "Gmsh 4.8.4 fdq", "target": n, "order": 1, "threads": 1, "size": size,
           "exit": rc, "wall": wall, "rss_kib": rss}
    if rc == 0 and info:
        row.update(quads=msh_quads(msh), mesh=info["mesh"], write=info["write"],
                   in_process=info["open"] + info["mesh"] + info["write"])
    if os.path.exists(msh):
        os.remove(msh)
    return row


def run_quadqs(a, n, size):
    # quadqs bind-mounts the output's folder into its chroot and leaves it
    # mounted: the system's temporary folder (mounted by quadqs anyway), not
    # a folder of ours that is removed afterwards
    msh = os.path.join(tempfile.gettempdir(), "scaling-quadqs-%d.msh" % os.getpid())
    cmd = shlex.split(a.quadqs) + [a.step, repr(size), msh, "1", "0"]
    rc, so, se, wall, rss = timed(cmd, a.timeout)
    row = {"tool": "Gmsh 4.13 quasi-structured", "target": n, "order": 1, "threads": 1,
           "size": size, "exit": rc, "wall": wall, "rss_kib": rss}
    if rc == 0 and os.path.exists(msh):
        row.update(quads=msh_quads(msh), in_process=wall)
        try:
            row["mesh"] = float(so.split()[-1])
        except (ValueError, IndexError):
            pass
    if os.path.exists(msh):
        os.remove(msh)
    return row


def exponent(rows):
    pts = [(math.log(r["quads"]), math.log(r["in_process"])) for r in rows
           if r.get("quads") and r.get("in_process") and 1e4 <= r["quads"] <= 1e6]
    if len(pts) < 2:
        return None
    mx = sum(p[0] for p in pts) / len(pts)
    my = sum(p[1] for p in pts) / len(pts)
    sxx = sum((p[0] - mx) ** 2 for p in pts)
    return sum((p[0] - mx) * (p[1] - my) for p in pts) / sxx if sxx > 0 else None


def series_of(rows):
    out = {}
    for r in rows:
        key = (r["tool"], r["order"], r["threads"])
        out.setdefault(key, []).append(r)
    return out


def label(key, nproc):
    tool, order, threads = key
    t = "%d thread%s" % (threads or nproc, "" if (threads or nproc) == 1 else "s")
    return "%s, order %d, %s" % (tool, order, t)


def fmt(x, spec="%.2f"):
    return "—" if x is None else spec % x


def table(rows, nproc):
    out = ["| mesher | order | threads | target | quads | relaxed at | field + layout s | mesh s | write s "
           "| mesh + write s | quads/s | peak RSS MB | kB/quad |",
           "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"]
    for r in rows:
        q = r.get("quads")
        ok = q and r.get("in_process") is not None
        rss = r["rss_kib"] * 1024 / 1e6
        out.append("| %s | %d | %s | %.0e | %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
            r["tool"], r["order"], r["threads"] or nproc, r["target"],
            q if q else ("timeout" if r["exit"] is None else "exit %s" % r["exit"]),
            r.get("relaxed_at") or "—", fmt(r.get("field")), fmt(r.get("mesh")), fmt(r.get("write")),
            fmt(r.get("in_process")), fmt(q / r["in_process"], "%.0f") if ok and r["in_process"] > 0 else "—",
            "%.0f" % rss if rss else "—", "%.2f" % (rss * 1e3 / q) if ok and rss else "—"))
    return out


def exponents(rows, nproc):
    out = ["| series | growth exponent b (10⁴–10⁶ quads) |", "| --- | --- |"]
    for key, rs in series_of(rows).items():
        b = exponent(rs)
        if b is not None:
            out.append("| %s | %.3f |" % (label(key, nproc), b))
    return out


COLOURS = ["#1b6ca8", "#d1495b", "#66a182", "#edae49", "#8d5a97", "#00798c", "#444444", "#a05195"]


def svg_plot(rows, nproc, path):
    """Log-log: in-process seconds (mesh + write) against quads, one polyline per series."""
    W, H, L, R, T, B = 900, 460, 70, 340, 20, 50
    pts = [(r["quads"], r["in_process"]) for r in rows if r.get("quads") and r.get("in_process")]
    if not pts:
        return
    # a tenth of a decade of margin around the points; grid lines at whole decades
    x0 = math.log10(min(p[0] for p in pts)) - 0.1
    x1 = math.log10(max(p[0] for p in pts)) + 0.1
    y0 = math.log10(min(p[1] for p in pts)) - 0.1
    y1 = math.log10(max(p[1] for p in pts)) + 0.1

    def X(q):
        return L + (math.log10(q) - x0) / (x1 - x0) * (W - L - R)

    def Y(t):
        return H - B - (math.log10(t) - y0) / (y1 - y0) * (H - T - B)

    s = ['<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" font-family="sans-serif" '
         'font-size="12">' % (W, H), '<rect width="100%" height="100%" fill="white"/>']
    for e in range(math.ceil(x0), math.floor(x1) + 1):
        s.append('<line x1="%.1f" y1="%d" x2="%.1f" y2="%d" stroke="#ddd"/>' % (X(10 ** e), T, X(10 ** e), H - B))
        s.append('<text x="%.1f" y="%d" text-anchor="middle">10<tspan dy="-6" font-size="9">%d</tspan></text>'
                 % (X(10 ** e), H - B + 18, e))
    for e in range(math.ceil(y0), math.floor(y1) + 1):
        s.append('<line x1="%d" y1="%.1f" x2="%d" y2="%.1f" stroke="#ddd"/>' % (L, Y(10 ** e), W - R, Y(10 ** e)))
        s.append('<text x="%d" y="%.1f" text-anchor="end">10<tspan dy="-6" font-size="9">%d</tspan></text>'
                 % (L - 6, Y(10 ** e) + 4, e))
    s.append('<text x="%.1f" y="%d" text-anchor="middle">quads</text>' % ((L + W - R) / 2, H - 12))
    s.append('<text x="16" y="%.1f" transform="rotate(-90 16 %.1f)" text-anchor="middle">'
             'seconds in process (mesh + write)</text>' % ((T + H - B) / 2, (T + H - B) / 2))
    s.append('<rect x="%d" y="%d" width="%d" height="%d" fill="none" stroke="#888"/>' % (L, T, W - L - R, H - T - B))
    for i, (key, rs) in enumerate(series_of(rows).items()):
        c = COLOURS[i % len(COLOURS)]
        p = [(X(r["quads"]), Y(r["in_process"])) for r in rs if r.get("quads") and r.get("in_process")]
        if not p:
            continue
        dash = ' stroke-dasharray="5 3"' if key[0] != "semquad" else ""
        s.append('<polyline fill="none" stroke="%s" stroke-width="2"%s points="%s"/>'
                 % (c, dash, " ".join("%.1f,%.1f" % q for q in p)))
        for q in p:
            s.append('<circle cx="%.1f" cy="%.1f" r="3" fill="%s"/>' % (q[0], q[1], c))
        ly = T + 14 + 18 * i
        s.append('<line x1="%d" y1="%d" x2="%d" y2="%d" stroke="%s" stroke-width="2"%s/>'
                 % (W - R + 10, ly - 4, W - R + 34, ly - 4, c, dash))
        s.append('<text x="%d" y="%d" font-size="11">%s</text>' % (W - R + 40, ly, label(key, nproc)))
    s.append("</svg>")
    with open(path, "w") as f:
        f.write("\n".join(s) + "\n")


def measure(a):
    nproc = os.cpu_count() or 1
    area = face_area(a.semquad, a.step)
    targets = [float(x) for x in a.quads.split(",")]
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for order in (int(x) for x in a.orders.split(",") if x):
            for threads in (int(x) for x in a.threads.split(",")):
                for n in targets:
                    if order > 4 and n > a.order8_max_quads:
                        continue
                    r = run_semquad(a, tmp, n, order, threads, math.sqrt(area / n))
                    print(json.dumps(r), file=sys.stderr)
                    rows.append(r)
        for n in targets:
            if n <= a.gmsh_max_quads:
                rows.append(run_gmsh(a, tmp, n, math.sqrt(area / n)))
                print(json.dumps(rows[-1]), file=sys.stderr)
            if a.quadqs and n <= a.quadqs_max_quads:
                rows.append(run_quadqs(a, n, math.sqrt(area / n)))
                print(json.dumps(rows[-1]), file=sys.stderr)
    load = open("/proc/loadavg").read().split()[:3]
    return {"rows": rows, "nproc": nproc, "area": area, "load": load,
            "commit": benchlib.source_commit(ROOT), "step": os.path.relpath(a.step, ROOT)}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--semquad", default=os.environ.get("SEMQUAD", os.path.join(ROOT, "build", "src", "semquad")))
    ap.add_argument("--step", default=os.path.join(ROOT, "examples", "square_hole.step"))
    ap.add_argument("--quads", default="1e3,1e4,1e5,1e6")
    ap.add_argument("--orders", default="4,8", help="semquad's orders (empty: the peers only)")
    ap.add_argument("--threads", default="1,0", help="thread counts (0: every processor)")
    ap.add_argument("--order8-max-quads", type=float, default=1e5)
    ap.add_argument("--gmsh-max-quads", type=float, default=1e5)
    ap.add_argument("--quadqs", default=os.environ.get("QUADQS"), help="Gmsh 4.13 quasi-structured command")
    ap.add_argument("--quadqs-max-quads", type=float, default=1e4)
    ap.add_argument("--timeout", type=float, default=600.0)
    ap.add_argument("--json")
    ap.add_argument("--from-json")
    ap.add_argument("--doc")
    ap.add_argument("--svg")
    a = ap.parse_args()
    if a.from_json:
        res = json.load(open(a.from_json))
    else:
        res = measure(a)
        if a.json:
            with open(a.json, "w") as f:
                json.dump(res, f, indent=1)
    rows, nproc = res["rows"], res["nproc"]
    body = ["`/usr/bin/python3 bench/scaling.py` on %s (face area %.6g), source commit %s, %d processors, "
            "load average %s at the end." % (res["step"], res["area"], res["commit"], nproc,
                                                " ".join(res["load"])), ""]
    body += table(rows, nproc) + [""] + exponents(rows, nproc)
    if a.svg:
        svg_plot(rows, nproc, a.svg)
        body += ["", "![seconds against quads](%s)" % os.path.relpath(a.svg, os.path.dirname(a.doc or a.svg))]
    print("\n".join(body))
    if a.doc:
        benchlib.replace_section(a.doc, SECTION, "\n".join(body))


if __name__ == "__main__":
    main()
