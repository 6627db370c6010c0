#!/usr/bin/env bash
# check_glsl.sh DUMP OUTDIR - make check-glsl: DUMP (tests/es/glsl_dump.c)
# writes every program composition shadowkit_gl.h compiles, in the desktop
# and the ES dialects, and the snippets inside a minimal user shader, into
# OUTDIR; glslangValidator (Debian's glslang-tools) compiles each one.
# glslang rejects `layout(invocations = N)` under "#version 330 core" even
# with GL_ARB_gpu_shader5 required, which drivers accept: such a geometry
# shader is checked as "#version 400 core" (where invocations are core).
# Ends "check-glsl: N shaders, M failed"; exit 1 when M > 0 or none ran.
set -uo pipefail
dump=${1:?usage: check_glsl.sh DUMP OUTDIR}
dir=${2:?usage: check_glsl.sh DUMP OUTDIR}
rm -rf "$dir" && mkdir -p "$dir" || exit 1
"$dump" "$dir" || { echo "check-glsl: $dump failed"; exit 1; }
# one file: its errors into FILE.fail (the files run $(nproc) at a time)
check_one() {
    local f=$1 src=$1 log
    if grep -q '^#extension GL_ARB_gpu_shader5 : require' "$f"; then
        src="${f%.geom}.v400.geom"
        sed -e 's/^#version 330 core$/#version 400 core/' -e '/^#extension GL_ARB_gpu_shader5/d' "$f" > "$src"
    fi
    if ! log=$(glslangValidator "$src" 2>&1); then
        { echo "check-glsl: $(basename "$f"):"
          printf '%s\n' "$log" | grep -E 'ERROR|error' | head -n 5 | sed 's/^/    /'; } > "$f.fail"
    fi
}
export -f check_one
files=()
for f in "$dir"/*.vert "$dir"/*.frag "$dir"/*.geom; do [ -f "$f" ] && files+=("$f"); done
n=${#files[@]}
[ "$n" -eq 0 ] || printf '%s\0' "${files[@]}" | xargs -0 -n 1 -P "$(nproc 2>/dev/null || echo 2)" bash -c 'check_one "$1"' _
failed=0
for f in "${files[@]+"${files[@]}"}"; do
    [ -f "$f.fail" ] || continue
    failed=$((failed + 1))
    cat "$f.fail"
done
echo "check-glsl: $n shaders, $failed failed"
[ "$n" -gt 0 ] && [ "$failed" -eq 0 ]
