#!/usr/bin/env bash
# testbed/build.sh - install what the testbed needs (Debian 12), build the
# testbed library and its self-test, run it. Run from anywhere; works in the
# repository root. Outputs: build/testbed/ (objects, libtestbed.a, selftest),
# out/ (PNG files written by the self-test).
#   testbed/build.sh            install missing packages, build, run the self-test
#   testbed/build.sh --no-run   build only
#   TB_WERROR=0 testbed/build.sh   do not turn warnings into errors
# Libraries: pkg-config assimp osmesa egl stb, plus -lembree3 -lpthread -lm
# (Debian's libembree-dev ships no .pc file).
set -euo pipefail

cd "$(dirname "$0")/.."
ROOT=$(pwd)
BUILD=build/testbed
RUN=1
[ "${1-}" = "--no-run" ] && RUN=0

# ------------------------------------------------------------------ packages
PKGS=(gcc g++ pkg-config libassimp-dev libembree-dev libosmesa6-dev libegl-dev libstb-dev)
installed() { dpkg -s "$1" 2>/dev/null | grep -q '^Status: install ok installed'; }
missing=()
if command -v dpkg >/dev/null 2>&1; then
    for p in "${PKGS[@]}"; do installed "$p" || missing+=("$p"); done
fi
if [ ${#missing[@]} -gt 0 ]; then
    echo "testbed/build.sh: installing ${missing[*]}" >&2
    SUDO=()
    if [ "$(id -u)" -ne 0 ]; then
        if command -v sudo >/dev/null 2>&1; then SUDO=(sudo); else
            echo "testbed/build.sh: not root; run: apt-get install -y ${missing[*]}" >&2; exit 1
        fi
    fi
    export DEBIAN_FRONTEND=noninteractive
    LOCK=(-o DPkg::Lock::Timeout=600)
    # apt-get update only when the package lists cannot provide them
    if ! "${SUDO[@]}" apt-get "${LOCK[@]}" install -y -qq --no-install-recommends "${missing[@]}"; then
        "${SUDO[@]}" apt-get "${LOCK[@]}" update -qq
        "${SUDO[@]}" apt-get "${LOCK[@]}" install -y -qq --no-install-recommends "${missing[@]}"
    fi
fi

# ------------------------------------------------------------------ build
CC=${CC:-gcc}
CXX=${CXX:-g++}
WARN=(-Wall -Wextra -Wpedantic)
[ "${TB_WERROR:-1}" = 1 ] && WARN+=(-Werror)
CFLAGS=(-std=c99 -O2 -g "${WARN[@]}" -I. -Itestbed $(pkg-config --cflags assimp osmesa egl))
CXXFLAGS=(-x c++ -std=c++11 -O2 "${WARN[@]}" -I. -Itestbed)
LIBS=($(pkg-config --libs assimp osmesa egl stb) -lembree3 -lpthread -lm)

SRCS=(tb_scene tb_gl_context tb_gl_osmesa tb_gl_egl tb_gl_funcs tb_gl_fbo tb_gl_scene tb_reference
      tb_metrics tb_image)
mkdir -p "$BUILD" out
objs=()
for s in "${SRCS[@]}"; do
    "$CC" "${CFLAGS[@]}" -c "testbed/$s.c" -o "$BUILD/$s.o"
    # the same source as C++11 (headers must be C++-includable; sources compile too)
    "$CXX" "${CXXFLAGS[@]}" -fsyntax-only "testbed/$s.c"
    objs+=("$BUILD/$s.o")
done
rm -f "$BUILD/libtestbed.a"
ar rcs "$BUILD/libtestbed.a" "${objs[@]}"
"$CC" "${CFLAGS[@]}" testbed/selftest.c -o "$BUILD/selftest" "$BUILD/libtestbed.a" "${LIBS[@]}"
"$CXX" "${CXXFLAGS[@]}" -fsyntax-only testbed/selftest.c
echo "testbed/build.sh: built $BUILD/libtestbed.a and $BUILD/selftest" >&2

[ $RUN = 1 ] || exit 0
cd "$ROOT"
exec "$BUILD/selftest"
