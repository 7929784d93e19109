#!/usr/bin/python3
"""Mesh every face of the stress corpus (bench/stress_corpus.py) at the default size.

usage: /usr/bin/python3 bench/stress_bench.py CORPUS [--semquad PATH] [--timeout 60]
           [--jobs 2] [--only 0004_fillet,0017_bspline|--classes sliver,needle]
           [--json out.json] [--doc docs/benchmarks.md] [--from-json run.json]

For each face: `semquad mesh FILE -q --report R.json -o out.msh` killed after
--timeout seconds; exit status, last stderr line, wall time, and from the report
quads, interior irregular vertices, min scaled Jacobian and, when the report has it,
gauss_bonnet_min (excess = irregular - gauss_bonnet_min).  A face succeeds when semquad
exits 0 with every scaled Jacobian > 0, or refuses with exit 4 a face that is not one
(class `invalid`, or marked by the generator as not written as drawn).  Prints Markdown (success rate per class,
failure classes with examples, time percentiles, irregular-vertex excess); --doc
replaces (or appends) the section "Stress corpus" of that file.  At most --jobs
faces at a time (default 2).  --json is rewritten after every face, so a run stopped early
leaves the faces it did.  --from-json writes the tables of an earlier --json run
instead of meshing.
"""
import argparse
import concurrent.futures
import datetime
import json
import os
import statistics
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import benchlib  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def load(corpus, only, classes):
    with open(os.path.join(corpus, "manifest.json")) as f:
        m = json.load(f)
    faces = m["faces"]
    if only:
        keep = set(only)
        faces = [e for e in faces if e["file"][:-5] in keep or str(e["id"]) in keep]
    if classes:
        faces = [e for e in faces if e["class"] in classes]
    return m, faces


def outcome(r):
    """A valid face must mesh; a face drawn invalid must be refused (exit 4).  A face
    the generator marks not written as drawn (its manifest's "valid" false, outside
    class `invalid`: OpenCASCADE's 1e-7 tolerance changed it, e.g. arcs that touch
    after scaling to 1e-6) is not the face that was drawn and may be no valid face:
    meshing it or refusing it with exit 4 are both right."""
    if r["class"] != "invalid":
        if r["exit"] == 4 and not r["valid_face"]:
            return "ok"
        return benchlib.outcome(r)
    if r["exit"] == 4:
        return "ok"
    return ("invalid face meshed" if r["exit"] in (0, benchlib.QUALITY_EXIT)
            else benchlib.failure_class(r))


def run_all(corpus, faces, semquad, timeout, jobs, json_path=None):
    work = tempfile.mkdtemp(prefix="sq-stress-")

    def one(e):
        r = benchlib.run_mesh(semquad, os.path.join(corpus, e["file"]), work, e["file"][:-5], timeout)
        r.update({"id": e["id"], "file": e["file"], "class": e["class"], "valid_face": e["valid"]})
        r["outcome"] = outcome(r)
        return r

    rows = []
    with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as ex:
        for r in ex.map(one, faces):
            rows.append(r)
            # written after every face, so that a run stopped early leaves
            # the faces it did for --from-json
            if json_path:
                with open(json_path, "w") as f:
                    json.dump(rows, f, indent=1)
            print("%-28s %-6s %7.2fs  %s" % (r["file"], r["exit"], r["seconds"],
                                             r["outcome"] if r["outcome"] != "ok" else
                                             "ok refused" if r["exit"] not in (0, benchlib.QUALITY_EXIT) else
                                             "ok %s quads=%s irr=%s sj=%.3f" % (r.get("road"), r.get("quads"),
                                                                                r.get("irregular"), r["min_sj"])),
                  file=sys.stderr, flush=True)
    os.rmdir(work)
    return rows


def markdown(rows, corpus, semquad, timeout, classes_order):
    ok = [r for r in rows if r["outcome"] == "ok"]
    lines = []
    n = len(rows)
    lines.append("%d faces, %d succeeded (%.1f %%): a valid face meshed (every scaled Jacobian "
                 "> 0: exit 0, or 8 below the quality floor), an invalid one (class `invalid`, or marked by the generator as not written as drawn) "
                 "refused with exit 4; timeout %g s per face."
                 % (n, len(ok), 100.0 * len(ok) / max(n, 1), timeout))
    lines.append(benchlib.below_floor_line([r for r in ok if r["class"] != "invalid"]))
    lines.append("")
    lines.append("| class | faces | succeeded | % | failures (exit codes) |")
    lines.append("|---|---|---|---|---|")
    for c in classes_order:
        rs = [r for r in rows if r["class"] == c]
        if not rs:
            continue
        k = sum(1 for r in rs if r["outcome"] == "ok")
        codes = {}
        for r in rs:
            if r["outcome"] != "ok":
                key = "timeout" if r["exit"] is None else str(r["exit"])
                codes[key] = codes.get(key, 0) + 1
        lines.append("| %s | %d | %d | %.0f | %s |" % (c, len(rs), k, 100.0 * k / len(rs),
                                                       ", ".join("%s×%d" % kv for kv in sorted(codes.items())) or "—"))
    lines.append("")
    refused = [r for r in ok if r["exit"] == 4]
    lines.append("Refused, as they must be (the generator's reason → semquad's message, numbers blanked):")
    lines.append("")
    lines += benchlib.group_table(refused, lambda r: "%s → %s" % (
        r["invalid_reason"] if r["class"] == "invalid" else
        "not written as drawn: %s" % benchlib.blank(r["invalid_reason"]), benchlib.blank(r["stderr"])),
        "why the face is not a face", lambda r: r["file"])
    lines.append("")
    lines += benchlib.road_lines([r for r in ok if r["exit"] == 0], lambda r: r["file"])
    lines.append("")
    lines.append("Failure classes (exit status and the first words of the message, numbers blanked):")
    lines.append("")
    lines += benchlib.failure_table(rows, lambda r: r["file"])
    lines.append("")
    lines.append("Wall time per face, seconds (every face, failures included; meshed faces only):")
    lines.append("")
    lines.append("| faces | p50 | p90 | p99 | max |")
    lines.append("|---|---|---|---|---|")
    lines.append(benchlib.time_row(rows))
    lines.append(benchlib.time_row(ok))
    lines.append("")
    if all("cpu_seconds" in r for r in rows):
        lines.append("CPU time (user + system) per face, seconds, exact when one face ran at a time "
                     "(every face, failures included; meshed faces only):")
        lines.append("")
        lines.append("| faces | p50 | p90 | p99 | max |")
        lines.append("|---|---|---|---|---|")
        lines.append(benchlib.time_row(rows, "cpu_seconds"))
        lines.append(benchlib.time_row(ok, "cpu_seconds"))
        slow = sorted(rows, key=lambda r: -r["cpu_seconds"])[:8]
        lines.append("")
        lines.append("Most CPU: " + ", ".join("`%s` %.1f s (wall %.1f s%s)" % (
            r["file"], r["cpu_seconds"], r["seconds"], ", timeout" if r["exit"] is None else "")
            for r in slow) + ".")
        lines.append("")
    # the excess is the layout road's: the split road's irregular vertices are its price
    ok = [r for r in ok if r["exit"] == 0 and r.get("road", "layout") == "layout"]
    ex = [r["excess"] for r in ok if "excess" in r]
    irr = [r["irregular"] for r in ok if r.get("irregular") is not None]
    if ex:
        lines.append("Interior irregular vertices over `gauss_bonnet_min`, faces meshed by the layout road "
                     "(%d with the key):" % len(ex))
        lines.append("")
        lines.append("| excess | 0 | 1-2 | 3-4 | 5-8 | > 8 | mean | max |")
        lines.append("|---|---|---|---|---|---|---|---|")
        bins = [sum(1 for x in ex if x <= 0), sum(1 for x in ex if 1 <= x <= 2), sum(1 for x in ex if 3 <= x <= 4),
                sum(1 for x in ex if 5 <= x <= 8), sum(1 for x in ex if x > 8)]
        lines.append("| faces | %s | %.2f | %d |" % (" | ".join(map(str, bins)), statistics.mean(ex), max(ex)))
        worst = sorted((r for r in ok if "excess" in r), key=lambda r: -r["excess"])[:5]
        lines.append("")
        lines.append("Largest excess: " + ", ".join("`%s` %d (%d irregular, bound %d)" % (
            r["file"], r["excess"], r["irregular"], r["gauss_bonnet_min"]) for r in worst) + ".")
    elif irr:
        lines.append("The reports have no `gauss_bonnet_min` yet: interior irregular vertices of the "
                     "meshed faces, mean %.2f, max %d." % (statistics.mean(irr), max(irr)))
    return "\n".join(lines) + "\n"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("corpus")
    benchlib.common_args(ap, ROOT, "Stress corpus")
    ap.add_argument("--only", help="comma-separated face names (0004_fillet) or ids")
    ap.add_argument("--classes", help="comma-separated classes")
    a = ap.parse_args()
    m, faces = load(a.corpus, a.only.split(",") if a.only else None,
                    set(a.classes.split(",")) if a.classes else None)
    if a.from_json:
        with open(a.from_json) as f:
            rows = json.load(f)
        for r in rows:
            r["outcome"] = outcome(r)
    else:
        rows = run_all(a.corpus, faces, a.semquad, a.timeout, min(a.jobs, 2), a.json)
    reasons = {e["file"]: e.get("invalid_reason", "") for e in m["faces"]}
    for r in rows:
        r["invalid_reason"] = reasons[r["file"]]
    md = markdown(rows, a.corpus, a.semquad, a.timeout, m["classes"])
    print(md)
    if a.json:
        with open(a.json, "w") as f:
            json.dump(rows, f, indent=1)
    if a.doc:
        rev = benchlib.source_commit(ROOT)
        head = ("Issue 14's stress corpus: random planar faces written by bench/stress_corpus.py, "
                "one STEP file each, %d faces in %d classes (its docstring describes them: polygons with acute "
                "and reflex corners, circular and B-spline edges, fillets, 0-10 holes, tiny edges, "
                "near-tangent holes, slivers, needles, near-180 degree corners, 50-500 edges, tilted "
                "planes, scales 1e-6 to 1e6, and faces that are not faces). Face i depends on the seed "
                "and i only, so the corpus is the same on every machine; tests/t701-stress-corpus.py "
                "meshes 34 of them. Each face: `semquad mesh FILE -q --report R -o M` at the default "
                "size.\n\n"
                "`/usr/bin/python3 bench/stress_corpus.py CORPUS --seed %d --count %d` then "
                "`/usr/bin/python3 bench/stress_bench.py CORPUS --doc docs/benchmarks.md` "
                "(semquad built from commit %s, `build/` (debugoptimized), %s UTC, shared 2-core machine "
                "under load, %d face(s) at a time).\n\n"
                % (len(m["faces"]), len(m["classes"]), m["seed"], len(m["faces"]), rev,
                   datetime.datetime.utcnow().strftime("%Y-%m-%d %H:%M"), a.jobs))
        benchlib.replace_section(a.doc, "Stress corpus", head + md)


if __name__ == "__main__":
    main()
