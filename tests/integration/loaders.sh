#!/usr/bin/env bash
# tests/integration/loaders.sh - the GLEW and glad applications, and their
# images compared across loaders.
#
# Runs build/integration/bin/loader_glew (GLEW on the testbed's EGL
# context) and loader_glad (glad on OSMesa); each renders the same PSSM
# frame through its loader and through the testbed's own GL table and
# checks the two agree (loader_test.h). Then image_compare checks, to
# within 0.1% of the pixels: GLEW against glad, and each loader against
# the testbed-table render of the other program's context. Measured: 0 of
# 230400 pixels differ in every pair (both contexts are Mesa's llvmpipe).
# It can fail: an image missing (a program that stopped early) fails its
# pairs, and a frame drawn with another light (tried: the sun's x negated
# in loader_glad.c's copy of loader_render.h) differs in 14.0% of the
# pixels: 3 failed checks.
#
# Prints every program's lines, then one summary line adding them up:
# "loaders: N passed, M failed". Run from the repository root (mk/integration.mk
# installs it as build/integration/loaders).
set -uo pipefail

BUILD=${BUILD:-build}
BIN=$BUILD/integration/bin
IMG=out/tests/integration
mkdir -p "$IMG"
rm -f "$IMG"/loader-glew*.png "$IMG"/loader-glad*.png

pass=0
fail=0
run() {   # a test program; its summary line is added to ours
    local out rc line
    out=$("$@" 2>&1); rc=$?
    printf '%s\n' "$out" | grep -vE ': [0-9]+ passed, [0-9]+ failed$'
    line=$(printf '%s\n' "$out" | grep -E ': [0-9]+ passed, [0-9]+ failed$' | tail -n 1)
    if [ -z "$line" ]; then
        echo "FAIL $1: no summary line (exit status $rc)"
        fail=$((fail + 1))
        return
    fi
    line=${line##*: }
    pass=$((pass + ${line%% passed*}))
    local m=${line#*passed, }; m=${m%% failed*}
    [ "$rc" -ne 0 ] && [ "$m" -eq 0 ] && m=1
    fail=$((fail + m))
}

run "$BIN/loader_glew"
run "$BIN/loader_glad"
run "$BIN/image_compare" --name loaders-cross --max-pct 0.1 \
    glew-vs-glad "$IMG/loader-glew.png" "$IMG/loader-glad.png" \
    glew-vs-testbed-osmesa "$IMG/loader-glew.png" "$IMG/loader-glad-testbed.png" \
    glad-vs-testbed-egl "$IMG/loader-glad.png" "$IMG/loader-glew-testbed.png"

echo "loaders: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
