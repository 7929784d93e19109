#!/bin/sh
# Healing within the file's tolerance (issue 23, docs/healing.md).  The test
# writes its own STEP files from examples/square.step (unit square, written
# by OpenCASCADE): the file's uncertainty set to 1e-4 of the face's size,
# and edge 1 given a start vertex of its own, moved with its line by D
# along the edge: a gap of D between the end of edge 0 and the start of
# edge 1 at the corner (1, 0, 0).
#  - D = 1e-7 and 1e-5: healed, the gap reported (info, report, stderr),
#    meshed valid (no inverted quad);
#  - D = 1e-2: refused in one line naming the face, the gap, the
#    tolerance and the option; meshed with --heal-tolerance 0.02;
#  - --no-heal: the 1e-5 gap is refused by the face's own closure check;
#  - a file of three faces, one of them with the 1e-2 gap: info exits 0
#    and lists all three, the broken one with its reason; the good ones mesh.
# usage: t330-cad-heal.sh SEMQUAD EXAMPLES_DIR
set -u
sq=$1
ex=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fails=0
fail() { echo "$*"; fails=$((fails + 1)); }

# gapfile D Y OUT: Y = -0.5 + D, the moved p-curve origin in the plane's frame
gapfile() {
    sed -e "s/LENGTH_MEASURE(1.E-07)/LENGTH_MEASURE(1.E-04)/" \
        -e "s/^#44 = EDGE_CURVE('',#24,/#44 = EDGE_CURVE('',#95,/" \
        -e "s/^#49 = CARTESIAN_POINT('',(1.,0.,0.));/#49 = CARTESIAN_POINT('',(1.,$1,0.));/" \
        -e "s/^#55 = CARTESIAN_POINT('',(0.5,-0.5));/#55 = CARTESIAN_POINT('',(0.5,$2));/" \
        -e "s/^#94 = \(.*\)/#94 = \1\n#95 = VERTEX_POINT('',#96);\n#96 = CARTESIAN_POINT('',(1.,$1,0.));/" \
        "$ex/square.step" >"$3"
    grep -q "^#96 = CARTESIAN_POINT('',(1.,$1,0.));" "$3" || fail "gapfile $1: template changed"
}
gapfile 1.E-07 -0.4999999 "$tmp/g7.step"
gapfile 1.E-05 -0.49999 "$tmp/g5.step"
gapfile 1.E-02 -0.49 "$tmp/g2.step"

# healed and meshed: exit 0, the gap in info, report and stderr, no fold
for g in 7 5; do
    f="$tmp/g$g.step"
    "$sq" info "$f" >"$tmp/info" 2>"$tmp/err" || fail "info g$g failed: $(cat "$tmp/err")"
    grep -q "^face 0: plane, healed" "$tmp/info" || fail "g$g: face 0 not healed: $(head -2 "$tmp/info")"
    grep -q "healed: closed a 1e-0$g mm gap between edges 0 and 1 of wire 0" "$tmp/info" ||
        fail "g$g: gap not reported: $(cat "$tmp/info")"
    "$sq" info "$f" --json >"$tmp/info.json" 2>/dev/null
    grep -q '"kind": "gap"' "$tmp/info.json" || fail "g$g: no gap in info --json"
    "$sq" mesh "$f" -o "$tmp/m.msh" --report "$tmp/r.json" >/dev/null 2>"$tmp/err" ||
        fail "mesh g$g failed: $(cat "$tmp/err")"
    grep -q "face 0 healed within 0.0001 mm: closed a 1e-0$g mm gap" "$tmp/err" ||
        fail "g$g: no healing line on stderr: $(cat "$tmp/err")"
    grep -q '"inverted": 0' "$tmp/r.json" || fail "g$g: inverted quads"
    grep -q '"healing"' "$tmp/r.json" && grep -q '"size": 1e-0'"$g" "$tmp/r.json" ||
        fail "g$g: report lacks the healed gap"
    "$sq" mesh "$f" -q -o "$tmp/m.msh" 2>"$tmp/err" >/dev/null
    [ -s "$tmp/err" ] && fail "g$g: mesh -q wrote to stderr: $(cat "$tmp/err")"
done

# beyond the tolerance: one line, exit 4, no output file
"$sq" mesh "$tmp/g2.step" -o "$tmp/o.msh" >/dev/null 2>"$tmp/err"
rc=$?
[ "$rc" -eq 4 ] || fail "g2: exit $rc, expected 4"
[ "$(wc -l <"$tmp/err")" -eq 1 ] || fail "g2: stderr is not one line: $(cat "$tmp/err")"
grep -q "face 0: gap of 0.01 mm between edges .* exceeds the healing tolerance .* (--heal-tolerance 0.015 would allow it)" \
    "$tmp/err" || fail "g2: refusal does not name gap, tolerance and option: $(cat "$tmp/err")"
[ -e "$tmp/o.msh" ] && fail "g2: left an output file"
"$sq" mesh "$tmp/g2.step" --heal-tolerance 0.02 -q -o "$tmp/o.msh" --report "$tmp/r.json" \
    >/dev/null 2>"$tmp/err" || fail "g2 --heal-tolerance 0.02 failed: $(cat "$tmp/err")"
grep -q '"inverted": 0' "$tmp/r.json" || fail "g2 --heal-tolerance: inverted quads"

# --no-heal: the face as read; its own closure check refuses the 1e-5 gap,
# naming its tolerance and the option that would close it
"$sq" mesh "$tmp/g5.step" --no-heal -o "$tmp/n.msh" >/dev/null 2>"$tmp/err"
rc=$?
[ "$rc" -eq 4 ] && grep -q "is not closed" "$tmp/err" &&
    grep -q "beyond the closure tolerance .* (healing with --heal-tolerance 1.5e-05 would close it)" "$tmp/err" ||
    fail "g5 --no-heal: exit $rc, expected 4 'not closed': $(cat "$tmp/err")"
[ -e "$tmp/n.msh" ] && fail "g5 --no-heal: left an output file"

# three faces: the square, the 1e-5 gap and the 1e-2 gap (entities of the
# last two renumbered +1000 and +2000)
{
    sed -n '1,/^#94 = /p' "$ex/square.step" | sed -e "s/LENGTH_MEASURE(1.E-07)/LENGTH_MEASURE(1.E-04)/" \
        -e "s/^#16 = OPEN_SHELL('',(#17));/#16 = OPEN_SHELL('',(#17,#1017,#2017));/"
    for k in 1000 2000; do
        src="$tmp/g5.step"
        [ "$k" -eq 2000 ] && src="$tmp/g2.step"
        { sed -n '/^#17 = /,/^#88 = /p' "$src"; sed -n '/^#88 = /,/^#89 = /p' "$src" | sed '1d;$d'
          sed -n '/^#95 = /,/^#96 = /p' "$src"; } |
            perl -pe "s/#(\d+)/'#'.(\$1 + $k)/ge"
    done
    printf 'ENDSEC;\nEND-ISO-10303-21;\n'
} >"$tmp/three.step"
"$sq" info "$tmp/three.step" >"$tmp/info" 2>"$tmp/err" || fail "three: info exit $?: $(cat "$tmp/err")"
[ "$(grep -c '^face [0-9]' "$tmp/info")" -eq 3 ] || fail "three: info lists $(grep -c '^face' "$tmp/info") faces"
grep -q "^face [0-2]: plane, broken: gap of 0.01 mm" "$tmp/info" || fail "three: no broken face: $(grep '^face' "$tmp/info")"
grep -q "^face [0-2]: plane, healed" "$tmp/info" && grep -q "^face [0-2]: plane, ok" "$tmp/info" ||
    fail "three: not one ok and one healed face: $(grep '^face' "$tmp/info")"
grep -q "1 broken" "$tmp/err" || fail "three: no summary on stderr: $(cat "$tmp/err")"
# the reader's face order is its own: each face by its listed status
for k in 0 1 2; do
    "$sq" mesh "$tmp/three.step" --face $k -q -o "$tmp/f$k.msh" >/dev/null 2>"$tmp/err"
    rc=$?
    if grep -q "^face $k: plane, broken" "$tmp/info"; then
        [ "$rc" -eq 4 ] && [ ! -e "$tmp/f$k.msh" ] || fail "three: broken face $k: exit $rc: $(cat "$tmp/err")"
    else
        [ "$rc" -eq 0 ] || fail "three: face $k does not mesh: $(cat "$tmp/err")"
    fi
done

[ "$fails" -eq 0 ] && echo "t330: all checks passed"
exit "$fails"
