#!/bin/sh
# semquad converge: the CSV header and one row per run; bad options give
# exit 2, one stderr line and no output file.
# usage: t902-converge-cli.sh SEMQUAD EXAMPLES_DIR
set -u
sq=$1
ex=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fails=0
fail() { echo "$*"; fails=$((fails + 1)); }

# a good run: 2 methods x 3 orders x 2 sizes = 12 rows
"$sq" converge "$ex/square.step" --orders 1-3 --sizes 0.5,0.25 --csv "$tmp/o.csv" \
    --svg "$tmp/o.svg" >"$tmp/out" 2>"$tmp/err" || fail "good run: exit $?: $(cat "$tmp/err")"
[ "$(head -n 1 "$tmp/o.csv")" = "method,P,h,dofs,L2,H1" ] ||
    fail "CSV header: '$(head -n 1 "$tmp/o.csv")'"
rows=$(($(wc -l <"$tmp/o.csv") - 1))
[ "$rows" -eq 12 ] || fail "CSV rows: $rows, expected 12"
grep -q '^cg,3,0.25,' "$tmp/o.csv" || fail "CSV: no row cg,3,0.25"
grep -q '^dg,1,0.5,' "$tmp/o.csv" || fail "CSV: no row dg,1,0.5"
grep -q '</svg>' "$tmp/o.svg" || fail "SVG not complete"
grep -q 'observed h-rates' "$tmp/out" || fail "table: no observed rates"
rm -f "$tmp"/o.*

# one method, automatic size: one row per P
"$sq" converge "$ex/half_disc.step" --method dg --orders 2-4 --solution re-z5 --quiet \
    --csv "$tmp/o.csv" >"$tmp/out" 2>"$tmp/err" || fail "dg run: exit $?: $(cat "$tmp/err")"
[ "$(wc -l <"$tmp/o.csv")" -eq 4 ] || fail "dg run: $(wc -l <"$tmp/o.csv") CSV lines, expected 4"
[ -s "$tmp/out" ] && fail "--quiet printed: $(cat "$tmp/out")"
rm -f "$tmp"/o.*

# expect STATUS DESCRIPTION ARGS...
expect() {
    want=$1; what=$2; shift 2
    "$sq" converge "$@" --csv "$tmp/o.csv" --svg "$tmp/o.svg" >"$tmp/out" 2>"$tmp/err"
    got=$?
    [ "$got" -eq "$want" ] || fail "$what: exit $got, expected $want: $(cat "$tmp/err")"
    [ "$(wc -l <"$tmp/err")" -eq 1 ] || fail "$what: stderr is not one line: $(cat "$tmp/err")"
    if ls "$tmp"/o.* >/dev/null 2>&1; then fail "$what: left $(ls "$tmp"/o.*)"; fi
    rm -f "$tmp"/o.*
}
expect 2 "reversed orders" "$ex/square.step" --orders 4-2
expect 2 "orders not a range" "$ex/square.step" --orders 2-x
expect 2 "orders too high" "$ex/square.step" --orders 1-17
expect 2 "orders missing end" "$ex/square.step" --orders 3-
expect 2 "orders zero" "$ex/square.step" --orders 0-3
expect 2 "bad sizes" "$ex/square.step" --sizes 0.5,-1
expect 2 "bad sizes list" "$ex/square.step" --sizes 0.5,,0.2
expect 2 "bad method" "$ex/square.step" --method fem
expect 2 "bad solution" "$ex/square.step" --solution sin
expect 2 "bad geometry order" "$ex/square.step" --geom-order 13
expect 2 "unknown option" "$ex/square.step" --bogus
expect 2 "missing file" --orders 1-2
expect 3 "missing input" "$tmp/nothere.step" --orders 1-2
[ "$fails" -eq 0 ]
