#!/bin/sh
# Batches on one machine (docs/scale-out.md): scripts/mesh_parallel.sh runs a
# cases file through GNU parallel, two at a time, and collect_reports.py
# gathers the runs into runs.csv.  Three examples (orders 2, 4, 3; the last
# by the split road) and one face semquad refuses (sphere.step, not planar:
# exit 4).  Checked: the script's exit status (1: a run failed), one CSV row
# per case in case order with its exit status, the report's quads, order and
# road in each row and the refusal's one line as its error, the mesh files
# of the runs that succeeded (none of the refused one), GNU parallel's job
# log, and the same mesh files byte for byte from a serial run (-j 1): the
# batch changes nothing of a run.  Skipped (77) without GNU parallel.
# usage: t906-batch-parallel.sh SEMQUAD EXAMPLES_DIR SCRIPTS_DIR
set -u
command -v parallel >/dev/null ||
    { echo "GNU parallel is missing (apt-get install parallel): skipped"; exit 77; }
sq=$1
ex=$2
scripts=$3
d=$(mktemp -d)
trap 'rm -rf "$d"' EXIT
cat >"$d/cases.txt" <<CASES
# three examples and a face semquad refuses
$ex/disc.step --order 2
$ex/half_disc.step --order 4 --size 0.2

$ex/square.step --road split --order 3
$ex/sphere.step
CASES
fail=0
SEMQUAD=$sq sh "$scripts/mesh_parallel.sh" -j 2 "$d/par" "$d/cases.txt" >"$d/par.out" 2>&1
st=$?
[ "$st" -eq 1 ] || { echo "FAIL: mesh_parallel.sh exit $st, expected 1 (sphere refused)"; fail=1; }
SEMQUAD=$sq sh "$scripts/mesh_parallel.sh" -j 1 "$d/ser" "$d/cases.txt" >/dev/null 2>&1
for id in disc-0001 half_disc-0002 square-0003; do
    cmp -s "$d/par/$id.msh" "$d/ser/$id.msh" ||
        { echo "FAIL: $id.msh differs between -j 2 and -j 1 (or is missing)"; fail=1; }
done
[ ! -e "$d/par/sphere-0004.msh" ] || { echo "FAIL: the refused run left a mesh"; fail=1; }
[ "$(grep -c . "$d/par/joblog.tsv")" -eq 5 ] ||
    { echo "FAIL: joblog.tsv: header and 4 jobs expected"; cat "$d/par/joblog.tsv"; fail=1; }
python3 - "$d/par" <<'PY' || fail=1
import csv, json, os, sys
out = sys.argv[1]
with open(os.path.join(out, "runs.csv")) as f:
    rows = list(csv.DictReader(f))
bad = []
want = [("disc-0001", 0, "2", None), ("half_disc-0002", 0, "4", None),
        ("square-0003", 0, "3", "split"), ("sphere-0004", 4, None, None)]
if [r["id"] for r in rows] != [w[0] for w in want]:
    bad.append(f"rows {[r['id'] for r in rows]}")
for r, (ident, status, order, road) in zip(rows, want):
    if int(r["exit_status"]) != status:
        bad.append(f"{ident}: exit {r['exit_status']}, expected {status}")
    if status == 0:
        with open(os.path.join(out, ident + ".json")) as f:
            rep = json.load(f)
        if r["quads"] != str(rep["mesh"]["quads"]) or r["order"] != order:
            bad.append(f"{ident}: quads {r['quads']} order {r['order']} vs the report's")
        if road and r["road"] != road:
            bad.append(f"{ident}: road {r['road']}")
        if float(r["min_scaled_jacobian"]) <= 0:
            bad.append(f"{ident}: min scaled Jacobian {r['min_scaled_jacobian']}")
    elif "not planar" not in r["error"]:
        bad.append(f"{ident}: error {r['error']!r}")
for b in bad:
    print("FAIL:", b)
sys.exit(1 if bad else 0)
PY
exit "$fail"
