#!/usr/bin/env bash
# tests/run_tests.sh [FLAVOUR...] - run every built test program and add up
# their summary lines ("<prog>: N passed, M failed", see tests/sk_test.h).
#
# Flavours are the folders under $BUILD (default build/): c99 cpp asan-c99
# asan-cpp compile gl integration fuzz hygiene (the default is all of them,
# in that order; a folder that was not built is skipped). Every
# executable file in build/<flavour>/ is run from the repository root.
# build/gl/<name> comes from tests/gl/<name>.c (GL tests on the testbed, see
# mk/testbed.mk); they run with LSAN_OPTIONS=suppressions=testbed/lsan.supp
# (OSMesa keeps ~850 bytes after its context is destroyed).
# A program counts as its M failures; one that prints no summary line, or
# exits non-zero with M == 0 (crash, sanitizer report, leak, timeout), counts
# as 1 failure. The last line printed is exactly "N passed, M failed"; the
# exit status is non-zero if M > 0 or no program ran.
#
# Environment: BUILD (build), SK_TEST_JOBS (nproc) programs run at once,
# SK_TEST_TIMEOUT (300) seconds per program.
set -uo pipefail

cd "$(dirname "$0")/.." || exit 2
BUILD=${BUILD:-build}
JOBS=${SK_TEST_JOBS:-$(nproc 2>/dev/null || echo 2)}
TIMEOUT=${SK_TEST_TIMEOUT:-300}
flavours=("$@")
[ ${#flavours[@]} -gt 0 ] || flavours=(c99 cpp asan-c99 asan-cpp compile gl integration fuzz hygiene)

LOGS=$(mktemp -d "${TMPDIR:-/tmp}/sk_tests.XXXXXX") || exit 2
trap 'rm -rf "$LOGS"' EXIT

# stdout line-buffered (stdbuf), so a crash or sanitizer abort keeps the FAIL
# lines printed before it; verify_asan_link_order=0 lets ASan accept the
# preloaded libstdbuf.
STDBUF=()
command -v stdbuf > /dev/null 2>&1 && STDBUF=(stdbuf -oL)

run_one() {  # flavour binary logfile
    local env=()
    case "$1" in asan-*)
        env=(ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:verify_asan_link_order=0
             UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1) ;;
        gl) env=(LSAN_OPTIONS=suppressions=testbed/lsan.supp) ;;
    esac
    local t0=$SECONDS
    env "${env[@]}" timeout -k 10 "$TIMEOUT" "${STDBUF[@]}" "./$2" > "$3" 2>&1 < /dev/null
    echo $? > "$3.rc"
    echo $((SECONDS - t0)) > "$3.t"
}

# start every program, at most $JOBS at a time; report in a fixed order
entries=()
i=0
for f in "${flavours[@]}"; do
    [ -d "$BUILD/$f" ] || continue
    for b in "$BUILD/$f"/*; do
        [ -f "$b" ] && [ -x "$b" ] || continue
        # skip a stale binary whose tests/<name>.c was removed or renamed
        case "$f" in
            gl) [ -f "tests/gl/$(basename "$b").c" ] || continue ;;
            c99|cpp|asan-*) [ -f "tests/$(basename "$b").c" ] || continue ;;
            *) ;;   # compile, integration, fuzz, hygiene: whatever mk/*.mk built
        esac
        log="$LOGS/$i.log"; i=$((i + 1))
        entries+=("$f|$b|$log")
        while [ "$(jobs -rp | wc -l)" -ge "$JOBS" ]; do wait -n; done
        run_one "$f" "$b" "$log" 2> /dev/null &   # no "Aborted" job notices
    done
done
wait

total_pass=0
total_fail=0
for e in "${entries[@]+"${entries[@]}"}"; do
    IFS='|' read -r f b log <<< "$e"
    rc=$(cat "$log.rc" 2>/dev/null || echo 255)
    secs=$(cat "$log.t" 2>/dev/null || echo "?")
    summary=$(grep -E ': [0-9]+ passed, [0-9]+ failed$' "$log" | tail -n 1)
    name=$(basename "$b")
    if [ -n "$summary" ]; then
        counts=${summary##*: }                   # "N passed, M failed"
        p=${counts%% passed*}
        m=${counts#*passed, }; m=${m%% failed*}
        note=""
        if [ "$rc" -ne 0 ] && [ "$m" -eq 0 ]; then
            m=1; note="  (exit status $rc after its summary: counted as 1 failure)"
        fi
        printf '%-9s %s: %s passed, %s failed%s  [%ss]\n' "$f" "$name" "$p" "$m" "$note" "$secs"
    else
        p=0; m=1
        case "$rc" in
            124|137) why="timed out after ${TIMEOUT}s" ;;
            *) why="exit status $rc" ;;
        esac
        printf '%-9s %s: no summary line (%s): counted as 1 failure\n' "$f" "$name" "$why"
    fi
    if [ "$m" -ne 0 ]; then  # show what it said (FAIL lines, sanitizer report)
        grep -vE ': [0-9]+ passed, [0-9]+ failed$' "$log" | tail -n 40 | sed 's/^/    | /'
    fi
    total_pass=$((total_pass + p))
    total_fail=$((total_fail + m))
done

if [ ${#entries[@]} -eq 0 ]; then
    echo "run_tests.sh: no test programs found under $BUILD/{$(IFS=,; echo "${flavours[*]}")}" >&2
    total_fail=1
fi
echo "$total_pass passed, $total_fail failed"
[ "$total_fail" -eq 0 ]
