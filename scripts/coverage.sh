#!/usr/bin/env bash
# scripts/coverage.sh - run the instrumented tests and report the coverage of
# shadowkit.h and shadowkit_gl.h (called by `make coverage`, mk/coverage.mk,
# once the programs under $COV_DIR/c99 and $COV_DIR/gl are built).
#   1. delete the counters (.gcda) of earlier runs, so the report is of this run
#   2. run the programs through tests/run_tests.sh (BUILD=$COV_DIR, flavours c99 gl)
#   3. lcov --capture (branch coverage on), keep the two headers only,
#      genhtml into $COV_OUT/index.html
#   4. print lines and branches per header; exit non-zero if a test failed
#      or shadowkit.h is below COV_MIN_LINES % lines or COV_MIN_BRANCHES %
#      branches.
# Environment: COV_DIR (build/coverage), COV_OUT (out/coverage),
# COV_MIN_LINES (95), COV_MIN_BRANCHES (90); SK_TEST_JOBS and SK_TEST_TIMEOUT
# as in tests/run_tests.sh (the timeout defaults to 900 s here: -O0).
set -euo pipefail

cd "$(dirname "$0")/.."
ROOT=$(pwd)
COV_DIR=${COV_DIR:-build/coverage}
COV_OUT=${COV_OUT:-out/coverage}
MIN_LINES=${COV_MIN_LINES:-95}
MIN_BRANCHES=${COV_MIN_BRANCHES:-90}
export SK_TEST_TIMEOUT=${SK_TEST_TIMEOUT:-900}
# lcov 1.16: branch data is off unless asked for, in every lcov/genhtml call
RC=(--rc lcov_branch_coverage=1)

start=$(date +%s)
find "$COV_DIR/obj" -name '*.gcda' -delete 2>/dev/null || true

tests_rc=0
BUILD=$COV_DIR bash tests/run_tests.sh c99 gl || tests_rc=$?

mkdir -p "$COV_OUT"
raw="$COV_OUT/raw.info"
info="$COV_OUT/coverage.info"
# (Debian's lcov 1.16 has geninfo warn that it redefines its own subroutines:
# those lines are dropped, every other message is kept)
lcov "${RC[@]}" --quiet --capture --directory "$COV_DIR/obj" --output-file "$raw" \
    2> >(grep -v '^Subroutine .* redefined at .*geninfo' >&2)
lcov "${RC[@]}" --quiet --extract "$raw" "$ROOT/shadowkit.h" "$ROOT/shadowkit_gl.h" \
    --output-file "$info"
rm -f "$raw"
genhtml "${RC[@]}" --quiet --branch-coverage --prefix "$ROOT" --title shadowkit \
    --output-directory "$COV_OUT" "$info"

# "lines......: 96.1% (1234 of 1284 lines)" -> "96.1 1234 1284"
figures() {  # info-file kind(lines|branches)
    lcov "${RC[@]}" --summary "$1" 2>&1 |
        sed -n "s/^ *$2\.*: \([0-9.]*\)% (\([0-9]*\) of \([0-9]*\) .*/\1 \2 \3/p"
}

status=0
echo "coverage (this run; report: $COV_OUT/index.html)"
for h in shadowkit.h shadowkit_gl.h; do
    one="$COV_OUT/$h.info"
    lcov "${RC[@]}" --quiet --extract "$info" "$ROOT/$h" --output-file "$one"
    read -r lp lh lf <<< "$(figures "$one" lines)"
    read -r bp bh bf <<< "$(figures "$one" branches)"
    rm -f "$one"
    if [ -z "${lp:-}" ] || [ -z "${bp:-}" ]; then
        echo "  $h: no coverage data" >&2
        status=1
        continue
    fi
    printf '  %-15s lines %6s%% (%s of %s)   branches %6s%% (%s of %s)\n' \
        "$h" "$lp" "$lh" "$lf" "$bp" "$bh" "$bf"
    if [ "$h" = shadowkit.h ]; then
        # the threshold test on the counts, not on lcov's rounded percentage
        if [ $((lh * 100)) -lt $((lf * MIN_LINES)) ]; then
            echo "coverage: shadowkit.h lines below ${MIN_LINES}%" >&2
            status=1
        fi
        if [ $((bh * 100)) -lt $((bf * MIN_BRANCHES)) ]; then
            echo "coverage: shadowkit.h branches below ${MIN_BRANCHES}%" >&2
            status=1
        fi
    fi
done
if [ "$tests_rc" -ne 0 ]; then
    echo "coverage: some tests failed (see above)" >&2
    status=1
fi
echo "coverage: tests, capture and report took $(( $(date +%s) - start )) s"
exit $status
