#!/usr/bin/env bash
# tests/packaging/run.sh - the CMake package and the pkg-config file work as
# docs/integrating.md's "Integrating" section says (part of `make test`, as
# build/hygiene/test_packaging). In a temporary directory: configure this
# repository with CMake, install it into a prefix, check the files
# installed, then build and run tests/packaging/consumer three ways: through
# find_package(shadowkit <this major.minor>) against that prefix, through
# pkg-config (cc $(pkg-config --cflags) ... $(pkg-config --libs)), and
# through add_subdirectory of the source tree (which must install nothing
# of shadowkit's); find_package asking for the next major version must
# fail (shadowkitConfigVersion.cmake), and shadowkit_gl.h must refuse a
# shadowkit.h of another release (tests/packaging/mismatch.c) and its
# implementation without shadowkit.h's (tests/packaging/split.c).
# Last line: "test_packaging: N passed, M failed"; exit status 0 when M = 0.
set -uo pipefail
cd "$(dirname "$0")/../.." || exit 2
ROOT=$(pwd)
T=$(mktemp -d "${TMPDIR:-/tmp}/sk_packaging.XXXXXX") || exit 2
trap 'rm -rf "$T"' EXIT
# a sub-make of the CMake builds must not join `make test`'s job server
unset MAKEFLAGS MFLAGS MAKELEVEL
CC=${CC:-cc}
pass=0
fail=0

# check DESCRIPTION COMMAND...: passes when COMMAND exits 0
check() {
    local what=$1; shift
    if "$@" > "$T/log" 2>&1; then
        pass=$((pass + 1))
    else
        fail=$((fail + 1))
        echo "FAIL $what"
        tail -n 25 "$T/log" | sed 's/^/    /'
    fi
}
# refuse DESCRIPTION COMMAND...: passes when COMMAND fails and its output has PATTERN ($REFUSE_PATTERN)
refuse() {
    local what=$1; shift
    if "$@" > "$T/log" 2>&1; then
        fail=$((fail + 1)); echo "FAIL $what: it succeeded"
    elif grep -q -- "$REFUSE_PATTERN" "$T/log"; then
        pass=$((pass + 1))
    else
        fail=$((fail + 1)); echo "FAIL $what: failed without \"$REFUSE_PATTERN\""
        tail -n 25 "$T/log" | sed 's/^/    /'
    fi
}
version_part() { sed -n "s/^#define SHADOWKIT_VERSION_$1 \\([0-9]*\\)\$/\\1/p" shadowkit.h; }
MAJOR=$(version_part MAJOR); MINOR=$(version_part MINOR); PATCH=$(version_part PATCH)
VERSION="$MAJOR.$MINOR.$PATCH"

check "cmake configure" cmake -S "$ROOT" -B "$T/build" -DCMAKE_INSTALL_PREFIX="$T/not-this-one"
check "cmake --install --prefix" cmake --install "$T/build" --prefix "$T/prefix"
P="$T/prefix"
config=$(find "$P" -name shadowkitConfig.cmake | head -n 1)
check "include/shadowkit.h installed" cmp shadowkit.h "$P/include/shadowkit.h"
check "include/shadowkit_gl.h installed" cmp shadowkit_gl.h "$P/include/shadowkit_gl.h"
check "shadowkitConfig.cmake installed" test -n "$config"
check "shadowkitConfigVersion.cmake installed" test -f "$(dirname "${config:-/nonexistent}")/shadowkitConfigVersion.cmake"
check "shadowkit.pc installed" test -f "$P/share/pkgconfig/shadowkit.pc"
check "nothing installed under the configured prefix" test ! -e "$T/not-this-one"

# find_package
check "find_package($VERSION): configure" cmake -S tests/packaging/consumer -B "$T/fp" -DSK_VIA=find_package \
    -DSK_WANT="$MAJOR.$MINOR" -DCMAKE_PREFIX_PATH="$P"
check "find_package: build" cmake --build "$T/fp"
check "find_package: run" sh -c '"$1" > "$2"' run "$T/fp/consumer" "$T/fp.out"
check "find_package: the version printed" grep -q "consumer: shadowkit $VERSION, .*: ok" "$T/fp.out"
REFUSE_PATTERN="version" refuse "find_package($((MAJOR + 1)).0) refused" cmake -S tests/packaging/consumer \
    -B "$T/fp-next" -DSK_VIA=find_package -DSK_WANT="$((MAJOR + 1)).0" -DCMAKE_PREFIX_PATH="$P"

# pkg-config
export PKG_CONFIG_PATH="$P/share/pkgconfig"
check "pkg-config --modversion = $VERSION" test "$(pkg-config --modversion shadowkit)" = "$VERSION"
check "pkg-config --cflags names the prefix" test "$(pkg-config --cflags shadowkit | tr -d ' ')" = "-I$P/include"
# shellcheck disable=SC2046
check "pkg-config: build" "$CC" -std=c99 -Wall -Wextra -Werror $(pkg-config --cflags shadowkit) \
    tests/packaging/consumer/main.c tests/packaging/consumer/gl.c -o "$T/pc-consumer" $(pkg-config --libs shadowkit)
check "pkg-config: run" sh -c '"$1" > "$2"' run "$T/pc-consumer" "$T/pc.out"
check "pkg-config: the version printed" grep -q "consumer: shadowkit $VERSION, .*: ok" "$T/pc.out"

# add_subdirectory
check "add_subdirectory: configure" cmake -S tests/packaging/consumer -B "$T/sub" -DSK_VIA=subdirectory \
    -DSK_SOURCE="$ROOT"
check "add_subdirectory: build" cmake --build "$T/sub"
check "add_subdirectory: run" "$T/sub/consumer"
check "add_subdirectory: install rules off" cmake --install "$T/sub" --prefix "$T/sub-prefix"
check "add_subdirectory: installs no shadowkit files" test ! -e "$T/sub-prefix/include/shadowkit.h"

# the checks between the headers
REFUSE_PATTERN="different releases" refuse "shadowkit_gl.h refuses another release's shadowkit.h" \
    "$CC" -std=c99 -I. -c tests/packaging/mismatch.c -o "$T/mismatch.o"
REFUSE_PATTERN="needs SHADOWKIT_IMPLEMENTATION" refuse "the GL implementation alone is refused" \
    "$CC" -std=c99 -I. -c tests/packaging/split.c -o "$T/split.o"

echo "test_packaging: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
