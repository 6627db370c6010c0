#!/usr/bin/env bash
# tests/fuzz/run_target.sh --bin BIN [--seconds S] [--corpus DIR] [--timeout T] NAME [libFuzzer args...]
#
# Runs one libFuzzer target (built by mk/fuzz.mk from tests/fuzz/fuzz_NAME.c):
#   1. replays, one by one, every file of tests/fuzz/corpus/NAME/ and
#      tests/fuzz/regress/NAME/ (deterministic: each input runs once);
#   2. fuzzes for S seconds (-max_total_time; 0 skips this step) starting
#      from those inputs. New inputs go to DIR (default: a temporary
#      directory, removed afterwards); a crashing, leaking or hanging input
#      (one running longer than T seconds, default 10) is saved under
#      build/fuzz-artifacts/NAME/.
# Prints the number of executions and, last, "NAME: N passed, M failed"
# (tests/run_tests.sh adds these up): N counts the replayed inputs plus 1 for
# a clean fuzzing run, M is 1 for a failed replay plus 1 for a failed fuzzing
# run. Exits non-zero if M > 0. Runs from the repository root.
set -uo pipefail
cd "$(dirname "$0")/../.." || exit 2

bin="" seconds=0 corpus="" timeout=10
while [ $# -gt 0 ]; do
    case "$1" in
        --bin) bin=$2; shift 2 ;;
        --seconds) seconds=$2; shift 2 ;;
        --corpus) corpus=$2; shift 2 ;;
        --timeout) timeout=$2; shift 2 ;;
        *) break ;;
    esac
done
name=${1:?usage: run_target.sh --bin BIN [--seconds S] [--corpus DIR] [--timeout T] NAME [args...]}
shift
[ -x "$bin" ] || { echo "$name: no fuzz binary $bin"; echo "$name: 0 passed, 1 failed"; exit 1; }

export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
# the library allocates nothing: a small quarantine keeps each run light
export ASAN_OPTIONS=${ASAN_OPTIONS:-quarantine_size_mb=16}
common=(-timeout="$timeout" -rss_limit_mb=2048)
dirs=()
for d in "tests/fuzz/corpus/$name" "tests/fuzz/regress/$name"; do
    [ -d "$d" ] && dirs+=("$d")
done
art="build/fuzz-artifacts/$name"
mkdir -p "$art"
log=$(mktemp "${TMPDIR:-/tmp}/fuzz_$name.XXXXXX") || exit 2
tmpdir=""
trap 'rm -f "$log"; [ -n "$tmpdir" ] && rm -rf "$tmpdir"' EXIT

passed=0 failed=0

# 1. replay
files=()
for d in "${dirs[@]+"${dirs[@]}"}"; do
    for f in "$d"/*; do [ -f "$f" ] && files+=("$f"); done
done
if [ ${#files[@]} -gt 0 ]; then
    if "$bin" "${common[@]}" "${files[@]}" > "$log" 2>&1; then
        passed=$((passed + ${#files[@]}))
    else
        failed=$((failed + 1))
        echo "$name: replay failed on $(grep '^Running: ' "$log" | tail -n 1 | cut -c10-)"
        grep -E 'check failed|ERROR: |runtime error|SUMMARY' "$log" | head -n 10
    fi
fi

# 2. fuzz
if [ "$seconds" -gt 0 ]; then
    if [ -z "$corpus" ]; then
        tmpdir=$(mktemp -d "${TMPDIR:-/tmp}/fuzz_corpus_$name.XXXXXX") || exit 2
        corpus=$tmpdir
    fi
    mkdir -p "$corpus"
    if "$bin" "${common[@]}" -max_total_time="$seconds" -print_final_stats=1 \
            -artifact_prefix="$art/" "$@" "$corpus" "${dirs[@]+"${dirs[@]}"}" > "$log" 2>&1; then
        passed=$((passed + 1))
    else
        failed=$((failed + 1))
        echo "$name: fuzzing failed; the input is under $art/"
        grep -E 'check failed|ERROR: |runtime error|SUMMARY|Test unit written' "$log" | head -n 10
    fi
    execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -n 1)
    rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -n 1)
    echo "$name: fuzzed ${seconds}s: ${execs:-?} executions (${rate:-?}/s), corpus $(find "$corpus" -type f | wc -l) new inputs"
fi
echo "$name: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
