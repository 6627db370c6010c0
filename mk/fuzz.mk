# mk/fuzz.mk - libFuzzer targets for shadowkit.h (included by the Makefile).
# Every tests/fuzz/fuzz_<name>.c is one target (its top comment says what it
# calls and checks); tests/fuzz/corpus/<name>/ holds its seeds and
# tests/fuzz/regress/<name>/ the inputs that once failed.
#   make fuzz          run each target for FUZZ_SECONDS (60) seconds, one after
#                      another; new inputs accumulate in build/fuzz-corpus/<name>/,
#                      a failing input is saved under build/fuzz-artifacts/<name>/.
#                      FUZZ_TARGETS="psm lispsm" picks targets, FUZZ_ARGS adds
#                      libFuzzer options (e.g. FUZZ_ARGS=-runs=10000000).
#   make fuzz-corpus   rewrite tests/fuzz/corpus/<name>/seed-* from each
#                      target's fz_seeds() (the targets' own checks run on them)
#   make test          builds build/fuzz/<name>: replays the corpus and the
#                      regression inputs, then fuzzes for a share of
#                      FUZZ_TEST_SECONDS (60 s of wall clock on 2 cores, all
#                      targets together); tests/run_tests.sh runs them (flavour fuzz)
# Targets are built with clang (FUZZ_CC) under
# -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=all; the
# implementation is compiled once, instrumented, into build/fuzz-bin/obj/.
# Two choices make a target run several times faster with no check lost
# that matters: the implementation goes without UBSan's pointer-overflow
# check (ASan already reports every access out of bounds, and the check's
# two comparisons per array access, traced for the fuzzer, took 80% of
# sk_estimate_resolution's time), and the harness (fuzz_<name>.c) goes
# without comparison tracing (its checks and canary scans are not what the
# fuzzer should steer by; the implementation's comparisons are traced).

FUZZ_CC           ?= clang
FUZZ_SECONDS      ?= 60
FUZZ_TEST_SECONDS ?= 60
FUZZ_TIMEOUT      ?= 10
# make test fuzzes from a fixed seed and stops at this many runs (or its
# time share): the same inputs on every machine of this speed or faster, so
# a CI run fails on a change, not on the luck of the draw; `make fuzz` is
# the open-ended search
FUZZ_TEST_RUNS    ?= 20000
FUZZ_ARGS         ?=
FUZZ_NAMES   := $(sort $(patsubst tests/fuzz/fuzz_%.c,%,$(wildcard tests/fuzz/fuzz_*.c)))
FUZZ_TARGETS ?= $(FUZZ_NAMES)
FUZZ_BIN     := $(BUILD)/fuzz-bin
FUZZ_OBJ     := $(FUZZ_BIN)/obj/shadowkit.o
FUZZ_SEEDGEN := $(BUILD)/fuzz-seed
FUZZ_CFLAGS  := -std=c99 -g -O2 -fno-omit-frame-pointer $(WARN) -I. -Itests/fuzz
FUZZ_SAN     := -fsanitize=address,undefined -fno-sanitize-recover=all
FUZZ_HDRS    := tests/fuzz/fuzz_common.h shadowkit.h
# make test: each target's share of the budget (the wrappers run 2 at a time)
FUZZ_EACH    := $(shell n=$(words $(FUZZ_NAMES)); echo $$(( n && $(FUZZ_TEST_SECONDS) * 2 >= n ? $(FUZZ_TEST_SECONDS) * 2 / n : 1 )))

$(FUZZ_OBJ): tests/fuzz/impl.c shadowkit.h | deps-test
	$(MKDIR)
	$(FUZZ_CC) $(FUZZ_CFLAGS) -fsanitize=fuzzer-no-link $(FUZZ_SAN) -fno-sanitize=pointer-overflow -c $< -o $@

$(addprefix $(FUZZ_BIN)/,$(FUZZ_NAMES)): $(FUZZ_BIN)/%: tests/fuzz/fuzz_%.c $(FUZZ_HDRS) $(FUZZ_OBJ) | deps-test
	$(MKDIR)
	$(FUZZ_CC) $(FUZZ_CFLAGS) -fsanitize=fuzzer -fno-sanitize-coverage=trace-cmp $(FUZZ_SAN) $< $(FUZZ_OBJ) -o $@ $(LDLIBS)

# the make-test wrappers (executables, as tests/run_tests.sh wants them)
FUZZ_WRAPPERS := $(addprefix $(BUILD)/fuzz/,$(FUZZ_NAMES))
$(FUZZ_WRAPPERS): $(BUILD)/fuzz/%: $(FUZZ_BIN)/% tests/fuzz/run_target.sh mk/fuzz.mk
	@mkdir -p $(@D)
	@printf '#!/usr/bin/env bash\n# written by mk/fuzz.mk: replay the corpus of %s, then fuzz it for %s s (seed 1, at most %s runs)\nexec bash tests/fuzz/run_target.sh --bin %s --seconds %s --timeout %s %s -seed=1 -runs=%s\n' \
	    '$*' '$(FUZZ_EACH)' '$(FUZZ_TEST_RUNS)' '$(FUZZ_BIN)/$*' '$(FUZZ_EACH)' '$(FUZZ_TIMEOUT)' '$*' '$(FUZZ_TEST_RUNS)' > $@
	@chmod +x $@

test: $(FUZZ_WRAPPERS)

.PHONY: fuzz fuzz-build fuzz-corpus
fuzz-build: $(addprefix $(FUZZ_BIN)/,$(FUZZ_NAMES))

fuzz: $(addprefix $(FUZZ_BIN)/,$(FUZZ_TARGETS))
	@failed=""; for t in $(FUZZ_TARGETS); do \
	    bash tests/fuzz/run_target.sh --bin $(FUZZ_BIN)/$$t --seconds $(FUZZ_SECONDS) \
	        --timeout $(FUZZ_TIMEOUT) --corpus $(BUILD)/fuzz-corpus/$$t $$t $(FUZZ_ARGS) || failed="$$failed $$t"; \
	done; \
	if [ -n "$$failed" ]; then echo "fuzz: failed:$$failed (inputs under $(BUILD)/fuzz-artifacts/)"; exit 1; fi; \
	echo "fuzz: $(words $(FUZZ_TARGETS)) targets, $(FUZZ_SECONDS) s each, no failure"

# seed writers: each target built with -DFZ_SEED_MAIN (no fuzzer, no sanitizer)
$(addprefix $(FUZZ_SEEDGEN)/,$(FUZZ_NAMES)): $(FUZZ_SEEDGEN)/%: tests/fuzz/fuzz_%.c $(FUZZ_HDRS) tests/fuzz/impl.c | deps-test
	$(MKDIR)
	$(CC) -std=c99 -O1 $(WARN) -DFZ_SEED_MAIN -I. -Itests/fuzz $< tests/fuzz/impl.c -o $@ $(LDLIBS)

fuzz-corpus: $(addprefix $(FUZZ_SEEDGEN)/,$(FUZZ_NAMES))
	@for t in $(FUZZ_NAMES); do \
	    mkdir -p tests/fuzz/corpus/$$t && rm -f tests/fuzz/corpus/$$t/seed-* && \
	    ./$(FUZZ_SEEDGEN)/$$t tests/fuzz/corpus/$$t || exit 1; \
	done
