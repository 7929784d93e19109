#!/bin/sh
# One run of a batch (docs/scale-out.md): line N of a cases file,
# "CAD_FILE [semquad mesh options...]", meshed into OUTDIR as
# STEM-NNNN.msh with its JSON report STEM-NNNN.json, its stderr
# STEM-NNNN.log and its exit status STEM-NNNN.status (what
# collect_reports.py reads).  Called by mesh_parallel.sh (GNU parallel) and
# mesh_slurm.sbatch (a Slurm job array), so both make the same files.
# The semquad command: $SEMQUAD, else `semquad` on PATH.
# usage: mesh_case.sh OUTDIR N "CAD_FILE [options...]"
set -u
[ $# -eq 3 ] || { echo "usage: mesh_case.sh OUTDIR N \"CAD_FILE [options...]\"" >&2; exit 2; }
out=$1
n=$2
# the line's words are the run's arguments (no quoting inside a line)
# shellcheck disable=SC2086
set -- $3
[ $# -ge 1 ] || { echo "mesh_case.sh: case $n is empty" >&2; exit 2; }
file=$1
shift
stem=$(basename "$file")
stem=${stem%.*}
id=$(printf '%s-%04d' "$stem" "$n")
# one thread per run unless the caller says otherwise: the batch runs one
# process per core already (a case's own --threads still wins)
SEMQUAD_THREADS=${SEMQUAD_THREADS:-1} "${SEMQUAD:-semquad}" mesh "$file" "$@" -q -o "$out/$id.msh" --report "$out/$id.json" \
    2>"$out/$id.log"
status=$?
echo "$status" >"$out/$id.status"
exit "$status"
