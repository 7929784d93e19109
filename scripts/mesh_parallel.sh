#!/bin/sh
# Mesh many files, or a parameter sweep, on one workstation with GNU parallel
# (docs/scale-out.md): every line of CASES, "CAD_FILE [semquad mesh
# options...]" ('#' lines and blank lines skipped), is one run of
# mesh_case.sh into OUTDIR; JOBS runs at a time (default: the cores); then
# collect_reports.py gathers the runs' reports into OUTDIR/runs.csv.  GNU
# parallel's own log of the jobs (start, duration, exit status) is
# OUTDIR/joblog.tsv.  Exit status: 0 when every run exited 0, else 1 (the
# CSV names the runs that did not).  The semquad command: $SEMQUAD, else
# `semquad` on PATH.
# usage: mesh_parallel.sh [-j JOBS] OUTDIR CASES
set -eu
here=$(cd "$(dirname "$0")" && pwd)
jobs=100%
if [ "${1:-}" = "-j" ]; then
    jobs=$2
    shift 2
fi
[ $# -eq 2 ] || { echo "usage: mesh_parallel.sh [-j JOBS] OUTDIR CASES" >&2; exit 2; }
command -v parallel >/dev/null ||
    { echo "mesh_parallel.sh: GNU parallel is missing (apt-get install parallel)" >&2; exit 2; }
out=$1
cases=$2
[ -r "$cases" ] || { echo "mesh_parallel.sh: cannot read $cases" >&2; exit 2; }
mkdir -p "$out"
# {#} is the job's number: the line's rank among the cases kept
status=0
grep -v -e '^[[:space:]]*#' -e '^[[:space:]]*$' "$cases" |
    parallel --will-cite --jobs "$jobs" --joblog "$out/joblog.tsv" \
        sh "$here/mesh_case.sh" "$out" '{#}' '{}' || status=1
python3 "$here/collect_reports.py" "$out" >"$out/runs.csv"
exit "$status"
