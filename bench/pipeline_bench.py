#!/usr/bin/env python3
"""Benchmarks of the layout pipeline's first stages (issues 4 and 5).

  field   time of the guiding-field solve + critical-point search + valences
          (`semquad field FILE --field-order P`), per example and order P;
          target: < 100 ms for half_disc at P = 8.
  layout  time of separatrix tracing + layout (graph, checks, repairs) + CAD
          split (`semquad layout FILE -o patches.step`) per example at P = 8;
          target: < 200 ms per example, tracing <= 2 us per integration step.

Every number is the median of --runs runs (default 3) of the timings_s that
semquad writes to its JSON report (so process start-up, reading the STEP file
and the coarse triangulation are not included; they are shown separately).
The number of integration steps is the report's layout.integration_steps.

Usage (from the repository root; builds build-release if needed):
  python3 bench/pipeline_bench.py [field|layout|all] [--runs N]
        [--orders 4,6,8,10,12] [--examples a,b,...] [--json out.json]
Prints Markdown tables on stdout.  Not a test: it never fails on a missed
target, it says so.
"""
import argparse
import glob
import json
import os
import statistics
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BUILD = os.path.join(ROOT, "build-release")
SEMQUAD = os.path.join(BUILD, "src", "semquad")


def build_release():
    if not os.path.isdir(BUILD):
        subprocess.run(["meson", "setup", BUILD, "--buildtype=release"], cwd=ROOT,
                       check=True, stdout=subprocess.DEVNULL)
    subprocess.run(["ninja", "-C", BUILD, "src/semquad"], check=True,
                   stdout=subprocess.DEVNULL)


def examples(selected):
    files = sorted(glob.glob(os.path.join(ROOT, "examples", "*.step")))
    files = [f for f in files if os.path.basename(f) != "sphere.step"]  # not planar
    if selected:
        want = set(selected.split(","))
        files = [f for f in files if os.path.basename(f)[:-5] in want]
    return files


def run_semquad(args, report):
    p = subprocess.run([SEMQUAD] + args + ["--report", report, "-q"],
                       stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    if p.returncode != 0:
        msg = p.stderr.strip().splitlines()
        return p.returncode, (msg[-1] if msg else "")
    with open(report) as f:
        return 0, json.load(f)


def med(xs):
    return statistics.median(xs) if xs else float("nan")


def ms(x):
    return "%.1f" % (1e3 * x)


def valences(rep):
    sing = rep.get("singularities", [])
    if not sing:
        return "none"
    hist = {}
    for s in sing:
        hist[s["valence"]] = hist.get(s["valence"], 0) + 1
    return ", ".join("%d×V%d" % (n, v) for v, n in sorted(hist.items()))


def bench_field(files, orders, runs, tmp, out):
    print("### Field solve + critical points + valences (`semquad field FILE --field-order P`)\n")
    print("Median of %d runs, milliseconds. `field` = solve + critical_points "
          "(the critical-point search includes the valences and corner valences); "
          "read and triangulate are shown for P = 8 only.\n" % runs)
    hdr = "| example | method | singular points | read+tri. (P=8) | " + \
          " | ".join("P=%d" % p for p in orders) + " |"
    print(hdr)
    print("|" + "---|" * (3 + 1 + len(orders)))
    res = {}
    for f in files:
        name = os.path.basename(f)[:-5]
        row, method, vals, pre = [], "?", "?", ""
        res[name] = {}
        for p in orders:
            tot, solve, crit, prep = [], [], [], []
            err = None
            for _ in range(runs):
                rc, rep = run_semquad(["field", f, "--field-order", str(p)],
                                      os.path.join(tmp, "f.json"))
                if rc:
                    err = "exit %d" % rc
                    break
                t = rep["timings_s"]
                solve.append(t["solve"])
                crit.append(t["critical_points"])
                tot.append(t["solve"] + t["critical_points"])
                prep.append(t.get("read", 0) + t.get("triangulate", 0))
                method, vals = rep["field"]["method"], valences(rep)
                dofs = rep["field"].get("dofs")
            if err:
                row.append(err)
                res[name][p] = {"error": err}
                continue
            row.append("%s (%s+%s)" % (ms(med(tot)), ms(med(solve)), ms(med(crit))))
            res[name][p] = {"solve": med(solve), "critical_points": med(crit),
                            "field": med(tot), "read_triangulate": med(prep),
                            "dofs": dofs, "method": method, "singular_points": vals}
            if p == 8:
                pre = ms(med(prep))
        print("| %s | %s | %s | %s | %s |" % (name, method, vals, pre, " | ".join(row)))
    print("\nCells: total (solve + critical points).\n")
    hd = res.get("half_disc", {}).get(8)
    if hd and "field" in hd:
        ok = hd["field"] < 0.1
        print("Target (half_disc, P = 8, < 100 ms): %s ms — %s.\n"
              % (ms(hd["field"]), "met" if ok else "NOT met"))
    out["field"] = res


def bench_layout(files, runs, tmp, out):
    print("### Tracing + layout + split (`semquad layout FILE -o patches.step`, P = 8)\n")
    print("Median of %d runs, milliseconds. `steps`: the AB4 integration steps of the "
          "trace stage (`layout.integration_steps` of the report), from which `µs/step` "
          "is trace time / steps (the trace time also holds the start-direction search "
          "of Algorithm 1 and the meeting checks).\n" % runs)
    print("| example | separatrices traced / kept | patches | trace | layout | split "
          "| total | < 200 ms | steps | µs/step |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    res = {}
    for f in files:
        name = os.path.basename(f)[:-5]
        tr, la, sp, tot = [], [], [], []
        err, rep = None, None
        for _ in range(runs):
            rc, rep = run_semquad(["layout", f, "-o", os.path.join(tmp, "p.step")],
                                  os.path.join(tmp, "l.json"))
            if rc:
                err = "exit %d: %s" % (rc, rep)
                break
            t = rep["timings_s"]
            tr.append(t["trace"])
            la.append(t["layout"])
            sp.append(t["split"])
            tot.append(t["trace"] + t["layout"] + t["split"])
        if err:
            print("| %s | — | — | — | — | — | — | — | — | %s |" % (name, err.replace("|", "/")))
            res[name] = {"error": err}
            continue
        L = rep["layout"]
        steps = L.get("integration_steps", 0)
        # with no separatrix traced from a singular point or corner (square,
        # annulus: its cut lines are traced inside the layout stage) the trace
        # time holds no steps: no per-step figure
        us = 1e6 * med(tr) / steps if steps and L["separatrices_traced"] else float("nan")
        print("| %s | %d / %d | %d | %s | %s | %s | %s | %s | %s | %s |" % (
            name, L["separatrices_traced"], L["separatrices"], L["quad_patches"],
            ms(med(tr)), ms(med(la)), ms(med(sp)), ms(med(tot)),
            "yes" if med(tot) < 0.2 else "**no**",
            str(steps) if L["separatrices_traced"] else "—",
            "%.2f" % us if us == us else "—"))
        res[name] = {"trace": med(tr), "layout": med(la), "split": med(sp),
                     "total": med(tot), "steps": steps,
                     "us_per_step": us, "layout_keys": L}
    print()
    out["layout"] = res


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("what", nargs="?", default="all", choices=["field", "layout", "all"])
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--orders", default="4,6,8,10,12")
    ap.add_argument("--examples", default="")
    ap.add_argument("--json", default="")
    a = ap.parse_args()
    build_release()
    files = examples(a.examples)
    out = {"runs": a.runs, "semquad": SEMQUAD}
    with tempfile.TemporaryDirectory(prefix="sq-bench-") as tmp:
        if a.what in ("field", "all"):
            bench_field(files, [int(x) for x in a.orders.split(",")], a.runs, tmp, out)
        if a.what in ("layout", "all"):
            bench_layout(files, a.runs, tmp, out)
    if a.json:
        with open(a.json, "w") as fh:
            json.dump(out, fh, indent=1)
    return 0


if __name__ == "__main__":
    sys.exit(main())
