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

# the good path: all three outputs, nothing on stderr
"$sq" triangulate "$tmp/upper.STEP" --order 6 $outs >"$tmp/out" 2>"$tmp/err" || {
    echo "good run failed: $(cat "$tmp/err")"; fails=$((fails + 1)); }
[ -s "$tmp/err" ] && { echo "good run wrote to stderr: $(cat "$tmp/err")"; fails=$((fails + 1)); }
for f in o.vtu o.svg o.json; do
    [ -s "$tmp/$f" ] || { echo "good run: $f missing"; fails=$((fails + 1)); }
done
grep -q '"order": 6' "$tmp/o.json" || { echo "report lacks order 6"; fails=$((fails + 1)); }
grep -q 'NumberOfCells' "$tmp/o.vtu" || { echo "VTU lacks cells"; fails=$((fails + 1)); }
ls "$tmp" | grep -q tmp && { echo "temporary file left behind"; fails=$((fails + 1)); }
"$sq" info "$ex/sphere.step" >"$tmp/out" 2>&1 && grep -q sphere "$tmp/out" ||
    { echo "info on the sphere does not name its surface"; fails=$((fails + 1)); }
"$sq" --version | grep -q '^semquad [0-9]' || { echo "--version"; fails=$((fails + 1)); }
"$sq" help | grep -q triangulate || { echo "help lacks triangulate"; fails=$((fails + 1)); }

[ "$fails" -eq 0 ]
