#!/bin/bash
# The anchors of shadowkit.h and shadowkit_gl.h (their maps: SECTIONS and
# THE MAP): one syntax, a line of its own "// >>name"; each name once; every
# anchor in its header's map and every name of the map an anchor; no
# ">>name" anywhere else (prose refers to sections by number). Run from the
# repository root; exits 1 naming what is wrong.
fail=0
say() { echo "$1"; fail=1; }
check() {  # header, the map's first line (a pattern), the line after it
    local h=$1 from=$2 to=$3 anchors mapped
    anchors=$(grep -o '^// >>[a-z0-9_]*$' "$h" | sed 's#^// >>##' | sort)
    [ -n "$anchors" ] || say "$h: no anchors"
    for d in $(echo "$anchors" | uniq -d); do say "$h: anchor >>$d stands twice"; done
    mapped=$(awk -v a="$from" -v b="$to" '$0 ~ a {m = 1} m && $0 ~ b {exit} m' "$h" |
             grep -o ' >>[a-z0-9_]*$' | sed 's/^ >>//' | sort -u)
    for n in $(comm -23 <(echo "$anchors" | sort -u) <(echo "$mapped")); do say "$h: >>$n is not in the map"; done
    for n in $(comm -13 <(echo "$anchors" | sort -u) <(echo "$mapped")); do say "$h: the map names >>$n, which has no anchor"; done
    awk -v a="$from" -v b="$to" -v h="$h" '
        $0 ~ a {m = 1} m && $0 ~ b {m = 0}
        m || /^\/\/ >>[a-z0-9_]*$/ {next}
        />>[a-z_]/ {print h ":" NR ": an anchor name outside the map and the anchors: " $0; bad = 1}
        END {exit bad}' "$h" || fail=1
}
check shadowkit.h '^   SECTIONS \\(in the order' '^   REFERENCES'
check shadowkit_gl.h '^/\\* THE MAP of this implementation' '^\\*/'
# the summary line tests/run_tests.sh reads
if [ $fail = 0 ]; then echo "every anchor of both headers is in its map, once, and none is in prose"
    echo "check_anchors: 1 passed, 0 failed"
else echo "check_anchors: 0 passed, 1 failed"; fi
exit $fail
