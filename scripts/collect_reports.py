#!/usr/bin/env python3
"""Gather a batch's runs into one CSV on standard output (docs/scale-out.md):
every STEM-NNNN.status in OUTDIR (written by mesh_case.sh, whether the run
came from GNU parallel or a Slurm array) is one row, its JSON report
STEM-NNNN.json (docs/formats.md) supplying the numbers and, for a run that
failed before writing one, its stderr's last line the reason.  Rows sorted by
case number; columns:

  case, id, input, exit_status, road, quads, order, nodes,
  irregular_interior_vertices, eta_mean, eta_min, min_scaled_jacobian,
  time_total_s, error

usage: collect_reports.py OUTDIR > runs.csv"""
import csv
import glob
import json
import os
import sys

COLUMNS = ["case", "id", "input", "exit_status", "road", "quads", "order", "nodes",
           "irregular_interior_vertices", "eta_mean", "eta_min", "min_scaled_jacobian",
           "time_total_s", "error"]


def row(status_path):
    base = status_path[: -len(".status")]
    ident = os.path.basename(base)
    with open(status_path) as f:
        r = {"id": ident, "case": int(ident.rsplit("-", 1)[1]), "exit_status": int(f.read())}
    if os.path.exists(base + ".json"):
        with open(base + ".json") as f:
            rep = json.load(f)
        mesh = rep.get("mesh", {})
        r.update(input=rep.get("input"), road=rep.get("road"), quads=mesh.get("quads"),
                 order=mesh.get("order"), nodes=mesh.get("nodes"),
                 irregular_interior_vertices=mesh.get("irregular_interior_vertices"),
                 eta_mean=mesh.get("quality", {}).get("mean"),
                 eta_min=mesh.get("quality", {}).get("min"),
                 min_scaled_jacobian=mesh.get("min_scaled_jacobian"),
                 time_total_s=rep.get("timings_s", {}).get("total"))
    if r["exit_status"] != 0 and os.path.exists(base + ".log"):
        with open(base + ".log") as f:
            lines = [ln.strip() for ln in f if ln.strip()]
        r["error"] = lines[-1] if lines else ""
    return r


def main():
    if len(sys.argv) != 2 or not os.path.isdir(sys.argv[1]):
        sys.exit("usage: collect_reports.py OUTDIR > runs.csv")
    rows = sorted((row(p) for p in glob.glob(os.path.join(sys.argv[1], "*.status"))),
                  key=lambda r: r["case"])
    w = csv.DictWriter(sys.stdout, fieldnames=COLUMNS, lineterminator="\n")
    w.writeheader()
    for r in rows:
        w.writerow(r)


main()
