#!/usr/bin/env bash
# scripts/deps.sh [GROUP...] - install the Debian packages a make target needs,
# only those that are missing. Quiet when nothing is missing.
#   test   compilers, libc headers, sanitizer runtimes, clang and its libFuzzer
#          runtime (make test, make check, make fuzz)
#   gl     test + pkg-config, OSMesa, EGL, Embree, assimp, stb (testbed, GL tests)
#   examples  gl + GLFW (the examples in examples/)
#   demo   examples + gnuplot (make demo)
#   integration  examples + GLEW, glad (python3-glad), Xvfb and Mesa's
#          GLX driver (tests/integration, part of make test)
#   coverage  gl + lcov (genhtml; make coverage, mk/coverage.mk)
#   web    gl + Emscripten, Chromium and glslang-tools, as one group (the
#          browser test and the shader check in make test, make web)
# To add a group or a package, edit the arrays and the case below.
# Debian 12 (bookworm); needs root (or sudo) only when something is missing.
set -euo pipefail

PKGS_TEST=(gcc g++ make libc6-dev libasan8 libubsan1 clang libclang-rt-14-dev cmake)
PKGS_GL=(pkg-config libosmesa6-dev libegl-dev libembree-dev libassimp-dev libstb-dev)
PKGS_EXAMPLES=(libglfw3-dev)
PKGS_DEMO=(gnuplot-nox)
PKGS_INTEGRATION=(libglew-dev python3-glad xvfb libgl1-mesa-dri)
PKGS_COVERAGE=(lcov)
PKGS_WEB=(emscripten chromium glslang-tools)

groups=("$@")
[ ${#groups[@]} -gt 0 ] || groups=(test)

want=()
for g in "${groups[@]}"; do
    case "$g" in
        test) want+=("${PKGS_TEST[@]}") ;;
        gl) want+=("${PKGS_TEST[@]}" "${PKGS_GL[@]}") ;;
        examples) want+=("${PKGS_TEST[@]}" "${PKGS_GL[@]}" "${PKGS_EXAMPLES[@]}") ;;
        demo) want+=("${PKGS_TEST[@]}" "${PKGS_GL[@]}" "${PKGS_EXAMPLES[@]}" "${PKGS_DEMO[@]}") ;;
        integration) want+=("${PKGS_TEST[@]}" "${PKGS_GL[@]}" "${PKGS_EXAMPLES[@]}" "${PKGS_INTEGRATION[@]}") ;;
        coverage) want+=("${PKGS_TEST[@]}" "${PKGS_GL[@]}" "${PKGS_COVERAGE[@]}") ;;
        web) want+=("${PKGS_TEST[@]}" "${PKGS_GL[@]}" "${PKGS_WEB[@]}") ;;
        *) echo "deps.sh: unknown group '$g' (known: test gl examples demo integration coverage web)" >&2; exit 2 ;;
    esac
done

# (not `dpkg -s | grep -q`: grep -q exits at the first match, dpkg dies of
# SIGPIPE on a long record such as libc6-dev's, and pipefail fails the test)
installed() {
    [ "$(dpkg-query -W -f='${Status}' "$1" 2>/dev/null)" = "install ok installed" ]
}

missing=()
for p in "${want[@]}"; do
    case " ${missing[*]-} " in *" $p "*) continue ;; esac
    installed "$p" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "deps.sh: installing missing packages: ${missing[*]}" >&2
if ! command -v apt-get >/dev/null 2>&1; then
    echo "deps.sh: apt-get not found; install these yourself: ${missing[*]}" >&2
    exit 1
fi
SUDO=()
if [ "$(id -u)" -ne 0 ]; then
    if command -v sudo >/dev/null 2>&1; then
        SUDO=(sudo)
    else
        echo "deps.sh: not root and no sudo; run as root:" >&2
        echo "  apt-get update && apt-get install -y --no-install-recommends ${missing[*]}" >&2
        exit 1
    fi
fi
export DEBIAN_FRONTEND=noninteractive
LOCK=(-o DPkg::Lock::Timeout=600)   # wait for another apt/dpkg to finish
# `make -j` may start several groups at once: one installs at a time, and
# each looks again at what is missing once it has the turn
if command -v flock >/dev/null 2>&1 && exec 9> "${TMPDIR:-/tmp}/shadowkit-deps.lock"; then
    flock -w 900 9 || true
    still=()
    for p in "${missing[@]}"; do installed "$p" || still+=("$p"); done
    [ ${#still[@]} -eq 0 ] && exit 0
    missing=("${still[@]}")
fi
"${SUDO[@]}" apt-get "${LOCK[@]}" update -qq
"${SUDO[@]}" env DEBIAN_FRONTEND=noninteractive \
    apt-get "${LOCK[@]}" install -y -qq --no-install-recommends "${missing[@]}"

still=()
for p in "${missing[@]}"; do installed "$p" || still+=("$p"); done
if [ ${#still[@]} -gt 0 ]; then
    echo "deps.sh: still missing after install: ${still[*]}" >&2
    exit 1
fi
