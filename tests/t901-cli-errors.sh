#!/bin/sh
# Bad input gets one clear line on stderr, the right exit status and no
# output file; good input gets exit 0, a VTU, an SVG and a JSON report.
# usage: t901-cli-errors.sh SEMQUAD EXAMPLES_DIR
set -u
sq=$1
ex=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fails=0

# expect STATUS DESCRIPTION ARGS...: exit status, one stderr line, no output
expect() {
    want=$1; what=$2; shift 2
    "$sq" "$@" >"$tmp/out" 2>"$tmp/err"
    got=$?
    lines=$(wc -l <"$tmp/err")
    if [ "$got" -ne "$want" ]; then
        echo "$what: exit $got, expected $want; stderr: $(cat "$tmp/err")"; fails=$((fails + 1))
    fi
    if [ "$want" -ne 0 ] && [ "$lines" -ne 1 ]; then
        echo "$what: $lines stderr lines, expected 1:"; cat "$tmp/err"; fails=$((fails + 1))
    fi
    if grep -qE '^semquad: ([^:]+): \1[:;]' "$tmp/err"; then # said once, at the source
        echo "$what: the error repeats its prefix: $(cat "$tmp/err")"; fails=$((fails + 1))
    fi
    if [ "$want" -ne 0 ] && ls "$tmp"/o.* >/dev/null 2>&1; then
        echo "$what: left an output file: $(ls "$tmp"/o.*)"; fails=$((fails + 1))
    fi
    rm -f "$tmp"/o.*
}
outs="-o $tmp/o.vtu --svg $tmp/o.svg --report $tmp/o.json"

: >"$tmp/empty.step"
echo "this is not a CAD file" >"$tmp/text.step"
head -c 2000 "$ex/half_disc.step" >"$tmp/truncated.step"
printf 'ISO-10303-21;\nHEADER;\nENDSEC;\nDATA;\nENDSEC;\nEND-ISO-10303-21;\n' >"$tmp/noface.step"
cp "$ex/half_disc.step" "$tmp/upper.STEP"

expect 2 "no command"
expect 2 "unknown command" frobnicate
expect 2 "missing file argument" triangulate
expect 2 "unknown option" triangulate "$ex/half_disc.step" --bogus
expect 2 "order out of range" triangulate "$ex/half_disc.step" --order 13 $outs
expect 2 "bad size" triangulate "$ex/half_disc.step" --size abc $outs
expect 2 "face out of range" triangulate "$ex/half_disc.step" --face 3 $outs
expect 3 "missing file" triangulate "$tmp/nothere.step" $outs
expect 3 "missing file (info)" info "$tmp/nothere.step"
expect 3 "empty file" triangulate "$tmp/empty.step" $outs
expect 3 "text file" triangulate "$tmp/text.step" $outs
expect 3 "truncated STEP" triangulate "$tmp/truncated.step" $outs
expect 3 "STEP without a face" triangulate "$tmp/noface.step" $outs
expect 3 "unknown extension" info "$ex/../README.md"
expect 4 "sphere (non-planar face)" triangulate "$ex/sphere.step" $outs
expect 7 "unwritable output" triangulate "$ex/half_disc.step" -o "$tmp/no/such/dir/o.vtu"
expect 2 "unknown mesh format" mesh "$ex/half_disc.step" -o "$tmp/o.xyz"
expect 2 "mesh order out of range" mesh "$ex/half_disc.step" --order 11 -o "$tmp/o.msh"
expect 4 "mesh of a sphere" mesh "$ex/sphere.step" -o "$tmp/o.msh" --report "$tmp/o.json"
expect 7 "unwritable mesh" mesh "$ex/half_disc.step" -o "$tmp/no/such/dir/o.msh" -q
expect 2 "bad merge distance" layout "$ex/half_disc.step" --merge-distance -1

# layout: the patches as STEP re-import as 4 faces (Marcon's half disc)
"$sq" layout "$ex/half_disc.step" -o "$tmp/p.step" --report "$tmp/l.json" -q ||
    { echo "layout failed"; fails=$((fails + 1)); }
"$sq" info "$tmp/p.step" | grep -q "4 faces" || { echo "patches STEP is not 4 faces"; fails=$((fails + 1)); }
grep -q '"quad_patches": 4' "$tmp/l.json" || { echo "layout report lacks 4 quad patches"; fails=$((fails + 1)); }
# mesh: each format by extension, a quality line on stdout, progress on stderr
for ext in msh xml vtu; do
    "$sq" mesh "$ex/half_disc.step" --size 0.3 -o "$tmp/m.$ext" >"$tmp/out" 2>"$tmp/err" ||
        { echo "mesh -o m.$ext failed: $(cat "$tmp/err")"; fails=$((fails + 1)); }
    [ -s "$tmp/m.$ext" ] || { echo "mesh: m.$ext missing"; fails=$((fails + 1)); }
    grep -q "quads, order 4" "$tmp/out" || { echo "mesh: no summary line"; fails=$((fails + 1)); }
    grep -q "singular points" "$tmp/err" || { echo "mesh: no progress lines"; fails=$((fails + 1)); }
done
head -2 "$tmp/m.msh" | grep -q '^4.1 0 8' || { echo "MSH version line"; fails=$((fails + 1)); }
"$sq" mesh "$ex/half_disc.step" --size 0.3 -q -o "$tmp/q.msh" 2>"$tmp/err" >/dev/null
[ -s "$tmp/err" ] && { echo "mesh -q wrote to stderr"; fails=$((fails + 1)); }

# the good path: all three outputs, nothing on stderr
"$sq" triangulate "$tmp/upper.STEP" --order 6 $outs >"$tmp/out" 2>"$tmp/err" || {
    echo "good run failed: $(cat "$tmp/err")"; fails=$((fails + 1)); }
[ -s "$tmp/err" ] && { echo "good run wrote to stderr: $(cat "$tmp/err")"; fails=$((fails + 1)); }
for f in o.vtu o.svg o.json; do
    [ -s "$tmp/$f" ] || { echo "good run: $f missing"; fails=$((fails + 1)); }
done
[ "$(stat -c %a "$tmp/o.vtu")" = "$(printf '%o' $((0666 & ~$(umask))))" ] ||
    { echo "output mode $(stat -c %a "$tmp/o.vtu") ignores the umask $(umask)"; fails=$((fails + 1)); }
grep -q '"order": 6' "$tmp/o.json" || { echo "report lacks order 6"; fails=$((fails + 1)); }
grep -q 'NumberOfCells' "$tmp/o.vtu" || { echo "VTU lacks cells"; fails=$((fails + 1)); }
ls "$tmp" | grep -q tmp && { echo "temporary file left behind"; fails=$((fails + 1)); }
"$sq" info "$ex/sphere.step" >"$tmp/out" 2>&1 && grep -q sphere "$tmp/out" ||
    { echo "info on the sphere does not name its surface"; fails=$((fails + 1)); }
"$sq" --version | grep -q '^semquad [0-9]' || { echo "--version"; fails=$((fails + 1)); }
"$sq" help | grep -q triangulate || { echo "help lacks triangulate"; fails=$((fails + 1)); }

[ "$fails" -eq 0 ]
