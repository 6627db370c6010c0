#!/usr/bin/env bash
# scripts/gl_coverage.sh DROP... -- KEEP... - which lines of shadowkit_gl.h
# would the sanitizer flavour stop reaching if the GL tests DROP left it?
#
# Builds each named tests/gl/<name>.c with gcc --coverage at -O1 (the
# shared implementation once; a program with its own copy of the
# implementation, tests/own_impl.awk, compiles it itself), runs it from the
# repository root, and lists the lines of shadowkit_gl.h that gcov marks
# executed. Prints, for each DROP program, how many of its lines no KEEP
# program reaches, and those lines. mk/hygiene.mk's HYG_LEFT_OUT was chosen
# this way: 0 for each. Needs `make testbed` first. Work files go to
# $COV_DIR (default build/coverage). Exit status 1 if any DROP line is
# unreached.
#   scripts/gl_coverage.sh test_gl_forest -- test_gl_auto test_gl_cache
set -uo pipefail
cd "$(dirname "$0")/.." || exit 2
DIR=${COV_DIR:-build/coverage}
mkdir -p "$DIR" || exit 2
drop=(); keep=(); side=drop
for a in "$@"; do
    if [ "$a" = "--" ]; then side=keep; continue; fi
    if [ $side = drop ]; then drop+=("$a"); else keep+=("$a"); fi
done
[ ${#drop[@]} -gt 0 ] && [ ${#keep[@]} -gt 0 ] || { sed -n '2,14p' "$0"; exit 2; }

CF=(-std=c99 -O1 -g --coverage -I. -Itestbed -Itests $(pkg-config --cflags assimp osmesa egl 2>/dev/null))
LIBS=(build/testbed/libtestbed.a $(pkg-config --libs assimp osmesa egl stb 2>/dev/null || echo -lassimp -lOSMesa -lEGL -lstb)
      -lembree3 -lpthread -lm)
own=$(awk -f tests/own_impl.awk tests/gl/test_gl_*.c /dev/null | xargs -n1 basename 2>/dev/null | sed 's/\.c$//')
[ -f "$DIR/impl.o" ] || gcc "${CF[@]}" -c tests/gl/shared_impl_gl.c -o "$DIR/impl.o" || exit 2

lines_of() {  # name: writes $DIR/name.lines (shadowkit_gl.h:N, sorted)
    local t=$1 obj d=$DIR/$1
    rm -rf "$d"; mkdir -p "$d"
    if echo "$own" | grep -qx "$t"; then
        gcc "${CF[@]}" -c "tests/gl/$t.c" -o "$d/$t.o" && gcc --coverage "$d/$t.o" -o "$d/bin" "${LIBS[@]}" || return 1
        obj=$d/$t
    else
        gcc "${CF[@]}" -include tests/shared_impl.h -DSK_TEST_SHARED_IMPL_GL "tests/gl/$t.c" "$DIR/impl.o" \
            -o "$d/bin" "${LIBS[@]}" || return 1
        obj=$DIR/impl
    fi
    rm -f "$obj.gcda"
    "$d/bin" > "$d/log" 2>&1
    echo "$t: $(tail -n 1 "$d/log")" >&2
    mkdir -p "$d/g"; cp "$obj.gcno" "$d/g/x.gcno"; cp "$obj.gcda" "$d/g/x.gcda"; rm -f "$obj.gcda"
    gcov -t -o "$d/g" "$d/g/x.gcda" 2> /dev/null |
        awk -F: '/Source:/ { src = $NF } { c = $1; gsub(/ /, "", c) } c ~ /^[0-9]+$/ && c > 0 { print src ":" $2 + 0 }' |
        sed 's#.*shadowkit_gl.h:#shadowkit_gl.h:#' | grep '^shadowkit_gl.h:' | sort -u > "$DIR/$t.lines"
}
for t in "${drop[@]}" "${keep[@]}"; do lines_of "$t" || { echo "$t: did not build" >&2; exit 2; }; done
sort -u $(for t in "${keep[@]}"; do echo "$DIR/$t.lines"; done) > "$DIR/keep.lines"
bad=0
for t in "${drop[@]}"; do
    n=$(comm -23 "$DIR/$t.lines" "$DIR/keep.lines" | wc -l)
    echo "$t: $(wc -l < "$DIR/$t.lines") lines of shadowkit_gl.h, $n reached by no KEEP program"
    comm -23 "$DIR/$t.lines" "$DIR/keep.lines" | head -n 20 | sed 's/^/    /'
    [ "$n" -eq 0 ] || bad=1
done
exit $bad
