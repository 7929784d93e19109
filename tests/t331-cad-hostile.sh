#!/bin/sh
# Hostile CAD files (issue 14): no input crashes or hangs `info` or `mesh`.
# Each file is examples/square.step with one entity broken by the test:
# unreadable ones exit 3 (input), readable ones whose face is unusable exit
# 4 from mesh (info lists the face as broken and exits 0); always exactly
# one line on stderr and no output file.  Each run is bounded by 60 s: a
# hang fails the test instead of blocking the suite.
# usage: t331-cad-hostile.sh SEMQUAD EXAMPLES_DIR
set -u
sq=$1
ex=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fails=0
sq_file="$ex/square.step"

# expect STATUS NAME CMD ARGS...: exit status, one stderr line, no output file
expect() {
    want=$1; name=$2; shift 2
    timeout 60 "$sq" "$@" >"$tmp/out" 2>"$tmp/err"
    got=$?
    if [ "$got" -ne "$want" ]; then
        echo "$name ($1): exit $got, expected $want; stderr: $(cat "$tmp/err")"; fails=$((fails + 1))
    fi
    if [ "$want" -ne 0 ] && [ "$(wc -l <"$tmp/err")" -ne 1 ]; then
        echo "$name ($1): stderr is not one line:"; cat "$tmp/err"; fails=$((fails + 1))
    fi
    if ls "$tmp"/o.* >/dev/null 2>&1; then
        echo "$name ($1): left an output file"; fails=$((fails + 1)); rm -f "$tmp"/o.*
    fi
}

# bad NAME SED-EXPRESSION: the square with one line edited
bad() {
    sed -e "$2" "$sq_file" >"$tmp/$1.step"
    cmp -s "$sq_file" "$tmp/$1.step" && { echo "$1: template changed"; fails=$((fails + 1)); }
}
bad dangling "s/^#22 = VERTEX_POINT('',#23);/#22 = VERTEX_POINT('',#99999);/"
bad unknown "s/^#23 = CARTESIAN_POINT/#23 = XARTESIAN_POINT/"
bad nan_point "s/^#23 = CARTESIAN_POINT('',(0.,0.,0.));/#23 = CARTESIAN_POINT('',(NAN,0.,0.));/"
bad nan_plane "s/^#34 = CARTESIAN_POINT('',(0.5,0.5,0.));/#34 = CARTESIAN_POINT('',(NAN,0.5,0.));/"
bad overflow "s/^#25 = CARTESIAN_POINT('',(1.,0.,0.));/#25 = CARTESIAN_POINT('',(1.E400,0.,0.));/"
bad inf "s/^#25 = CARTESIAN_POINT('',(1.,0.,0.));/#25 = CARTESIAN_POINT('',(INF,0.,0.));/"
bad nan_direction "s/^#30 = DIRECTION('',(1.,0.,0.));/#30 = DIRECTION('',(NAN,0.,0.));/"
bad zero_length "s/^#60 = EDGE_CURVE('',#45,#61,/#60 = EDGE_CURVE('',#45,#45,/"
head -c 1500 "$sq_file" >"$tmp/truncated.step"

for f in dangling unknown nan_point nan_plane overflow inf truncated; do
    expect 3 "$f" info "$tmp/$f.step"
    expect 3 "$f" mesh "$tmp/$f.step" -o "$tmp/o.msh" --report "$tmp/o.json"
done
# read, but the face cannot be used: listed as broken by info, refused by mesh
for f in nan_direction zero_length; do
    expect 0 "$f" info "$tmp/$f.step" -q
    grep -q "^face 0: plane, broken: " "$tmp/out" || {
        echo "$f: face 0 not listed as broken: $(cat "$tmp/out")"; fails=$((fails + 1)); }
    expect 4 "$f" mesh "$tmp/$f.step" -o "$tmp/o.msh" --report "$tmp/o.json"
done
expect 2 "negative --heal-tolerance" info "$sq_file" --heal-tolerance -1
expect 2 "info with -o" info "$sq_file" -o "$tmp/o.txt"

[ "$fails" -eq 0 ] && echo "t331: all checks passed"
exit "$fails"
