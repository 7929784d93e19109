"""Shared by the stress-corpus and real-parts benchmarks: run one `semquad mesh`
under a time limit, read its report, group failures, write Markdown."""
import json
import os
import re
import resource
import signal
import subprocess
import time


QUALITY_EXIT = 8  # semquad's status for a mesh written below the quality floor


def run_mesh(semquad, step, workdir, tag, timeout, extra=(), measure=None):
    """`semquad mesh STEP -q --report R -o M` (plus extra), killed after timeout s.
    Returns a dict: exit (None on timeout, -N on signal N), seconds, stderr_line,
    the report's figures when it was written, and measure(M) as "msh" when
    measure is given and the mesh was written."""
    rep = os.path.join(workdir, tag + ".json")
    msh = os.path.join(workdir, tag + ".msh")
    for f in (rep, msh):
        if os.path.exists(f):
            os.remove(f)
    cmd = [semquad, "mesh", step, "-q", "--report", rep, "-o", msh] + list(extra)
    # CPU time (user + system) of the children reaped meanwhile: this face's
    # alone when one face runs at a time (--jobs 1), the figure that means
    # something on a loaded machine, where wall time is mostly waiting
    ru0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    # a process group of its own, so a timeout kills whatever semquad started
    p = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                         start_new_session=True)
    try:
        _, err = p.communicate(timeout=timeout)
        code = p.returncode
    except subprocess.TimeoutExpired:
        os.killpg(p.pid, signal.SIGKILL)
        _, err = p.communicate()
        code = None
    dt = time.perf_counter() - t0
    ru1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = ru1.ru_utime + ru1.ru_stime - ru0.ru_utime - ru0.ru_stime
    lines = [ln for ln in err.decode(errors="replace").splitlines() if ln.strip()]
    # the error is semquad's own line; a library may add lines of its own after it
    mine = [ln for ln in lines if ln.startswith("semquad:")]
    r = {"exit": code, "seconds": round(dt, 3), "cpu_seconds": round(cpu, 3), "stderr_lines": len(lines),
         "stderr": (mine or lines or [""])[-1], "stderr_all": lines[-20:]}
    # exit 8: the mesh is written but its worst quad is below --min-quality
    if code in (0, QUALITY_EXIT) and os.path.exists(rep):
        r.update(report_figures(rep))
        if measure and os.path.exists(msh):
            r["msh"] = measure(msh)
    for f in (rep, msh):
        if os.path.exists(f):
            os.remove(f)
    return r


# Gmsh's quadrangle element types, orders 1-10 (complete and serendipity):
# their first four nodes are the corners
QUAD_TYPES = {3, 10, 16, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51}


def msh_elements(path):
    """Nodes {tag: (x, y, z)} and 2D elements [(type, [node tags])] of an ASCII
    MSH 4.1 file (Gmsh's and semquad's default format), read without Gmsh."""
    with open(path) as f:
        lines = iter(f.read().splitlines())
    nodes, elems = {}, []
    for ln in lines:
        if ln.strip() == "$Nodes":
            blocks = int(next(lines).split()[0])
            for _ in range(blocks):
                # x y z first on each line (parametric coordinates, when present, after them)
                _dim, _tag, _param, cnt = map(int, next(lines).split())
                tags = [int(next(lines)) for _ in range(cnt)]
                for t in tags:
                    x = next(lines).split()
                    nodes[t] = (float(x[0]), float(x[1]), float(x[2]))
        elif ln.strip() == "$Elements":
            blocks = int(next(lines).split()[0])
            for _ in range(blocks):
                dim, _tag, typ, cnt = map(int, next(lines).split())
                for _ in range(cnt):
                    e = next(lines).split()
                    if dim == 2:
                        elems.append((typ, [int(v) for v in e[1:]]))
    return nodes, elems


def quad_figures(path):
    """The same figures for any planar quad mesh, whoever wrote it (a face in a
    tilted plane included): quads, other 2D elements, interior irregular
    vertices (corners on other than 4 quads, not on a boundary edge: an edge of
    one quad only), and the scaled Jacobian at the corners of the straight
    corner quads (the cross product of the two sides over their lengths, signed
    by the mesh's mean normal: min over the mesh, and the mean over the quads of
    each quad's least), the measure Gmsh's and semquad's meshes share."""
    nodes, elems = msh_elements(path)
    quads = [c[:4] for t, c in elems if t in QUAD_TYPES]
    out = {"quads": len(quads), "other": len(elems) - len(quads)}
    if not quads:
        return out
    edges, valence = {}, {}
    for q in quads:
        for k in range(4):
            a, b = q[k], q[(k + 1) % 4]
            key = (min(a, b), max(a, b))
            edges[key] = edges.get(key, 0) + 1
            valence[a] = valence.get(a, 0) + 1
    boundary = {v for e, n in edges.items() if n == 1 for v in e}
    out["irregular"] = sum(1 for v, n in valence.items() if v not in boundary and n != 4)

    def sub(a, b):
        return (a[0] - b[0], a[1] - b[1], a[2] - b[2])

    def cross(a, b):
        return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])

    normal = [0.0, 0.0, 0.0]
    for q in quads:
        c = cross(sub(nodes[q[2]], nodes[q[0]]), sub(nodes[q[3]], nodes[q[1]]))
        normal = [normal[i] + c[i] for i in range(3)]
    nn = sum(v * v for v in normal) ** 0.5 or 1.0
    normal = [v / nn for v in normal]
    worst = []
    for q in quads:
        least = 1.0
        for k in range(4):
            p, a, b = nodes[q[k]], nodes[q[(k + 1) % 4]], nodes[q[(k + 3) % 4]]
            e1, e2 = sub(a, p), sub(b, p)
            l1 = sum(v * v for v in e1) ** 0.5
            l2 = sum(v * v for v in e2) ** 0.5
            c = cross(e1, e2)
            least = min(least, sum(c[i] * normal[i] for i in range(3)) / (l1 * l2) if l1 * l2 > 0 else -1.0)
        worst.append(least)
    out["min_sj"] = min(worst)
    out["mean_sj"] = sum(worst) / len(worst)
    return out


def report_figures(path):
    with open(path) as f:
        d = json.load(f)
    m = d.get("mesh", {})
    lay = d.get("layout", {})
    out = {"quads": m.get("quads"), "irregular": m.get("irregular_interior_vertices"),
           "min_sj": m.get("min_scaled_jacobian"), "inverted": m.get("inverted"),
           "field": d.get("field", {}).get("kind"), "road": d.get("road", "layout")}
    if d.get("road_reason"):
        out["road_reason"] = d["road_reason"]
    # the key's place in the report is not settled: the layout's, the mesh's or the top level
    gb = next((o["gauss_bonnet_min"] for o in (lay, m, d) if "gauss_bonnet_min" in o), None)
    if gb is not None:
        out["gauss_bonnet_min"] = gb
        if out["irregular"] is not None:
            out["excess"] = out["irregular"] - gb
    return out


def outcome(r):
    """ok: a valid mesh written (exit 0, or 8: below the quality floor) with every
    scaled Jacobian > 0; else a failure class."""
    if r["exit"] in (0, QUALITY_EXIT):
        sj = r.get("min_sj")
        if sj is not None and sj > 0:
            return "ok"
        return "exit %d but min scaled Jacobian %s" % (r["exit"], "missing" if sj is None else "<= 0")
    return failure_class(r)


_NUMS = re.compile(r"[-+]?\d[\d.]*(?:e[-+]?\d+)?", re.I)


def blank(msg):
    """A message with its numbers, file names and parentheses blanked, so faces failing
    in the same place group together."""
    msg = re.sub(r"^semquad:\s*", "", msg)
    msg = re.sub(r"\S+\.(step|stp|brep|igs|iges|json|msh)\b:?", "FILE", msg)
    msg = re.sub(r"\([^()]*\)", "(…)", msg)
    msg = _NUMS.sub("N", msg)
    return " ".join(msg.split()[:9])


def below_floor_line(ok):
    """Markdown: how many of the valid meshes are below the quality floor (exit 8)."""
    low = sorted((r for r in ok if r["exit"] == QUALITY_EXIT), key=lambda r: r["min_sj"])
    return ("Of these, %d are below the default quality floor (exit 8: written, worst scaled "
            "Jacobian below `--min-quality` 0.01)%s." %
            (len(low), "" if not low else ", the worst at %.2g" % low[0]["min_sj"]))


def failure_class(r):
    """Exit status and the first words of the message, blanked."""
    if r["exit"] is None:
        return "timeout"
    if r["exit"] < 0:
        return "signal %s" % signal.Signals(-r["exit"]).name
    return "exit %d: %s" % (r["exit"], blank(r["stderr"]))


def road_lines(ok, name_of, examples=3):
    """Markdown: the meshed faces by road, and why the layout road gave way to the
    split road (quad_split.h) where it did."""
    split = [r for r in ok if r.get("road") == "split"]
    out = ["Meshed by the layout road: %d; by the split road (the fallback: a triangulation "
           "split into quads, many irregular vertices): %d." % (len(ok) - len(split), len(split))]
    if split:
        out += ["", "Why the layout road gave way:", ""]
        out += group_table(split, lambda r: blank(r.get("road_reason", "")), "layout road's failure",
                           name_of, examples)
    return out


def percentile(xs, q):
    xs = sorted(xs)
    if not xs:
        return float("nan")
    k = (len(xs) - 1) * q
    lo = int(k)
    hi = min(lo + 1, len(xs) - 1)
    return xs[lo] + (xs[hi] - xs[lo]) * (k - lo)


def time_row(rows, key="seconds"):
    ts = [r[key] for r in rows]
    return "| %d | %.2f | %.2f | %.2f | %.2f |" % (len(ts), percentile(ts, 0.5), percentile(ts, 0.9),
                                                   percentile(ts, 0.99), max(ts) if ts else float("nan"))


def group_table(rows, class_of, title, name_of, examples=3):
    """Markdown table of rows grouped by class_of(row), most frequent first, with examples."""
    groups = {}
    for r in rows:
        groups.setdefault(class_of(r), []).append(r)
    out = ["| %s | faces | examples |" % title, "|---|---|---|"]
    for c, rs in sorted(groups.items(), key=lambda kv: (-len(kv[1]), kv[0])):
        ex = ", ".join("`%s`" % name_of(r) for r in rs[:examples])
        out.append("| %s | %d | %s |" % (c.replace("|", "/"), len(rs), ex))
    return out


def failure_table(rows, name_of, examples=3):
    """Markdown table of the failure classes, most frequent first, with examples."""
    out = group_table([r for r in rows if r["outcome"] != "ok"], lambda r: r["outcome"],
                      "failure class", name_of, examples)
    if len(out) == 2:
        out.append("| (none) | 0 | |")
    return out


def common_args(ap, root, section):
    """The options both benchmarks take."""
    ap.add_argument("--semquad", default=os.environ.get("SEMQUAD", os.path.join(root, "build", "src", "semquad")))
    ap.add_argument("--timeout", type=float, default=60.0, help="seconds per face (default 60)")
    ap.add_argument("--jobs", type=int, default=2, help="faces at a time (at most 2)")
    ap.add_argument("--json", help="write every face's record here")
    ap.add_argument("--doc", help="replace the '%s' section of this Markdown file" % section)
    ap.add_argument("--from-json", help="tables of this earlier --json run, no meshing")


def source_commit(root):
    """The last commit that changed semquad's sources (the bench files' own commits
    do not change the binary)."""
    return subprocess.run(["git", "-C", root, "log", "-1", "--format=%h", "--", "src", "cad", "sem", "common"],
                          capture_output=True, text=True).stdout.strip()


def replace_section(doc_path, title, body):
    """Replace the `## title` section of doc_path (up to the next `## `), or append it."""
    with open(doc_path) as f:
        text = f.read()
    head = "## " + title + "\n"
    new = head + "\n" + body.rstrip("\n") + "\n"
    i = text.find(head)
    if i < 0:
        text = text.rstrip("\n") + "\n\n" + new
    else:
        j = text.find("\n## ", i + len(head))
        text = text[:i] + new + ("\n" + text[j + 1:] if j >= 0 else "")
    with open(doc_path, "w") as f:
        f.write(text)
