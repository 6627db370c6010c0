#!/usr/bin/env bash
# tests/integration/examples_anywhere.sh - every example run from a
# directory that is not the repository root.
#
# Each example runs --headless for one frame with the working directory a
# fresh temporary one and no --out: it must exit 0 and write its default
# out/NAME.png there (07 finds its leaf textures through /proc/self/exe:
# examples/assets two levels above build/examples/07_engine_casters).
# Then 07_engine_casters --scene with a 2 m block (an OBJ written here):
# the log must name the file (the scene is loaded, not ignored) and the
# picture must differ from the procedural scene's.
#
# It can fail: 07 built from the sources before it looked for its assets
# next to the executable exits 1 from any other directory
# ("examples/assets/minetest/default_leaves.png: can't fopen (run from the
# repository root)"), and with --scene it printed "--scene is ignored" and
# drew the procedural scene ("scene: procedural scene").
#
# Run from the repository root after `make examples` (mk/integration.mk
# installs this script as build/integration/examples_anywhere). Ends with
# the summary line "examples_anywhere: N passed, M failed".
set -uo pipefail

EX=$(cd "${BUILD:-build}/examples" && pwd)
TMP=$(mktemp -d "${TMPDIR:-/tmp}/sk_anywhere.XXXXXX") || exit 2
trap 'rm -rf "$TMP"' EXIT
pass=0
fail=0
check() {   # check NAME CONDITION-STATUS MESSAGE
    if [ "$2" -eq 0 ]; then pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAIL $1: $3"; fi
}

for name in 01_hard_shadows 02_cascades 03_warping 04_adaptive 05_point_light 06_soft_shadows 07_engine_casters; do
    dir="$TMP/$name"
    mkdir -p "$dir"
    ( cd "$dir" && SK_GL=osmesa "$EX/$name" --headless --frames 1 > run.log 2>&1 )
    rc=$?
    check "$name" "$rc" "exit $rc from $dir: $(tail -n 3 "$dir/run.log" | tr '\n' ' ')"
    [ -s "$dir/out/$name.png" ]
    check "$name" $? "no out/$name.png written in $dir"
done

# 07 with a scene of the user's: a block on the ground, the foliage around it
dir="$TMP/07-scene"
mkdir -p "$dir"
{
    printf 'v -1 0 -1\nv 1 0 -1\nv 1 0 1\nv -1 0 1\nv -1 2 -1\nv 1 2 -1\nv 1 2 1\nv -1 2 1\n'
    printf 'f 1 2 3\nf 1 3 4\nf 5 7 6\nf 5 8 7\nf 1 5 6\nf 1 6 2\nf 2 6 7\nf 2 7 3\nf 3 7 8\nf 3 8 4\nf 4 8 5\nf 4 5 1\n'
} > "$dir/block.obj"
( cd "$dir" && SK_GL=osmesa "$EX/07_engine_casters" --headless --frames 1 --scene block.obj > run.log 2>&1 )
rc=$?
check "07 --scene" "$rc" "exit $rc: $(tail -n 3 "$dir/run.log" | tr '\n' ' ')"
grep -q 'scene: block.obj' "$dir/run.log"
check "07 --scene" $? "the log does not name block.obj: $(head -n 3 "$dir/run.log" | tr '\n' ' ')"
! grep -q 'ignored' "$dir/run.log"
check "07 --scene" $? "--scene ignored"
if [ -s "$dir/out/07_engine_casters.png" ] && [ -s "$TMP/07_engine_casters/out/07_engine_casters.png" ]; then
    ! cmp -s "$dir/out/07_engine_casters.png" "$TMP/07_engine_casters/out/07_engine_casters.png"
    check "07 --scene" $? "the picture is the procedural scene's"
else
    check "07 --scene" 1 "no picture to compare"
fi

echo "examples_anywhere: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
