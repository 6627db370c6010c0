#!/usr/bin/env bash
# tests/run_tests.sh [FLAVOUR...] - run every built test program and add up
# their summary lines ("<prog>: N passed, M failed", see tests/sk_test.h).
#
# Flavours are the folders under $BUILD (default build/): c99 cpp asan-c99
# asan-cpp compile gl integration fuzz hygiene (the default is all of them,
# in that order; a folder that was not built is skipped); FLAVOUR/NAME runs
# that one program (make check-quick: gl/test_gl_offscreen). Every
# executable file in build/<flavour>/ is run from the repository root.
# build/gl/<name> comes from tests/gl/<name>.c (GL tests on the testbed, see
# mk/testbed.mk); they run with LSAN_OPTIONS=suppressions=testbed/lsan.supp
# (OSMesa keeps ~850 bytes after its context is destroyed).
# A program counts as its M failures; one that prints no summary line, or
# exits non-zero with M == 0 (crash, sanitizer report, leak, timeout), counts
# as 1 failure. The last line printed is exactly "N passed, M failed"; the
# exit status is non-zero if M > 0 or no program ran.
# Programs run $SK_TEST_JOBS at a time; each one's output goes to its own log,
# $BUILD/test-logs/<flavour>/<name>.log (kept), and the results are printed
# in a fixed order once all have finished: one line per program with its
# wall and CPU seconds (user+sys, children included), the output of those
# that failed, the 10 programs that took the longest (wall), the sum of the
# CPU seconds, and last the "N passed, M failed" line. The same figures go to
# $BUILD/test-logs/times.tsv (flavour, name, wall s, cpu s). Programs start
# longest first: by their last wall time (kept in
# $BUILD/test-logs/history.tsv), else by tests/test_times.tsv (the wall
# seconds of a clean run on 2 cores: a clean checkout has no history;
# refresh it from history.tsv when programs change much), else by a guess
# from their flavour.
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

LOGS=$BUILD/test-logs
mkdir -p "$LOGS" || exit 2
# CPU seconds of a program and its children (GNU time); none: "?"
TIME=()
[ -x /usr/bin/time ] && TIME=(/usr/bin/time -f '%U %S' -o)

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
    local t0=$SECONDS prog=$2
    case "$prog" in /*) ;; *) prog=./$prog ;; esac   # BUILD may be an absolute path
    rm -f "$3.cpu"
    env "${env[@]}" ${TIME[@]+"${TIME[@]}" "$3.cpu"} timeout -k 10 "$TIMEOUT" "${STDBUF[@]}" "$prog" \
        > "$3" 2>&1 < /dev/null
    echo $? > "$3.rc"
    echo $((SECONDS - t0)) > "$3.t"
}

cpu_of() {  # logfile: user+sys seconds from GNU time's last line, or "?"
    tail -n 1 "$1.cpu" 2>/dev/null | awk 'NF == 2 && $1 ~ /^[0-9.]+$/ { printf "%.1f", $1 + $2; ok = 1 }
                                           END { if (!ok) printf "?" }'
}

# start every program, at most $JOBS at a time; report in a fixed order
entries=()
i=0
for f in "${flavours[@]}"; do
    only=""
    case "$f" in */*) only=${f#*/}; f=${f%%/*} ;; esac   # FLAVOUR/NAME: that program alone
    [ -d "$BUILD/$f" ] || continue
    for b in "$BUILD/$f"/*; do
        [ -z "$only" ] || [ "$(basename "$b")" = "$only" ] || continue
        [ -f "$b" ] && [ -x "$b" ] || continue
        # skip a stale binary whose tests/<name>.c was removed or renamed
        case "$f" in
            gl) [ -f "tests/gl/$(basename "$b").c" ] || [ -f "tests/gl/$(basename "$b" | sed 's/_no_[a-z]*$//').c" ] ||
                continue ;;   # test_gl_optout_no_<switch> (mk/testbed.mk) is test_gl_optout.c
            c99|cpp|asan-*) [ -f "tests/$(basename "$b").c" ] || continue ;;
            *) ;;   # compile, integration, fuzz, hygiene: whatever mk/*.mk built
        esac
        mkdir -p "$LOGS/$f"
        log="$LOGS/$f/$(basename "$b").log"; i=$((i + 1))
        entries+=("$f|$b|$log")
    done
done

# longest first, so that no long program starts last while the other job
# slots idle: the wall seconds of its last run ($LOGS/history.tsv), else a
# figure from tests/test_times.tsv, else a guess by flavour (the GL
# programs under the sanitizers are the slowest)
declare -A hist=()
for h in tests/test_times.tsv "$LOGS/history.tsv"; do
    [ -f "$h" ] || continue
    while IFS=$'\t' read -r key secs; do hist[$key]=$secs; done < "$h"
done
expected() {  # flavour name: seconds
    local s=${hist[$1/$2]:-}
    if [ -n "$s" ]; then echo "$s"; return; fi
    case "$1" in
        hygiene) echo 60 ;; integration) echo 50 ;; gl) echo 30 ;; fuzz) echo 20 ;;
        asan-*) echo 2 ;; *) echo 1 ;;
    esac
}
order=$(for k in "${!entries[@]}"; do
            IFS='|' read -r f b log <<< "${entries[$k]}"
            printf '%s %s\n' "$(expected "$f" "$(basename "$b")")" "$k"
        done | sort -k1,1nr -k2,2n | cut -d' ' -f2)
for k in $order; do
    IFS='|' read -r f b log <<< "${entries[$k]}"
    while [ "$(jobs -rp | wc -l)" -ge "$JOBS" ]; do wait -n; done
    run_one "$f" "$b" "$log" 2> /dev/null &   # no "Aborted" job notices
done
wait

total_pass=0
total_fail=0
: > "$LOGS/times.tsv"
for e in "${entries[@]+"${entries[@]}"}"; do
    IFS='|' read -r f b log <<< "$e"
    rc=$(cat "$log.rc" 2>/dev/null || echo 255)
    secs=$(cat "$log.t" 2>/dev/null || echo "?")
    cpu=$(cpu_of "$log")
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
        printf '%-9s %s: %s passed, %s failed%s  [%ss, cpu %ss]\n' "$f" "$name" "$p" "$m" "$note" "$secs" "$cpu"
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
    printf '%s\t%s\t%s\t%s\n' "$f" "$name" "$secs" "$cpu" >> "$LOGS/times.tsv"
    [ "$secs" = "?" ] || hist[$f/$name]=$secs
    total_pass=$((total_pass + p))
    total_fail=$((total_fail + m))
done

if [ ${#entries[@]} -gt 0 ]; then
    echo "slowest programs (wall s, cpu s; logs in $LOGS/<flavour>/):"
    sort -t $'\t' -k3,3nr "$LOGS/times.tsv" | head -n 10 |
        awk -F '\t' '{ printf "  %5ss  cpu %6ss  %s/%s\n", $3, $4, $1, $2 }'
    awk -F '\t' '$4 ~ /^[0-9.]+$/ { c += $4 } END { printf "cpu seconds of all %d programs: %.0f\n", NR, c }' \
        "$LOGS/times.tsv"
fi
for key in "${!hist[@]}"; do printf '%s\t%s\n' "$key" "${hist[$key]}"; done | sort > "$LOGS/history.tsv"
if [ ${#entries[@]} -eq 0 ]; then
    echo "run_tests.sh: no test programs found under $BUILD/{$(IFS=,; echo "${flavours[*]}")}" >&2
    total_fail=1
fi
echo "$total_pass passed, $total_fail failed"
[ "$total_fail" -eq 0 ]
