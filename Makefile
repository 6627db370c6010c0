# shadowkit - GNU make. Everything generated goes to build/ and out/.
#   make test       install what is missing, build tests/test_*.c four ways
#                   (C99, C++11, each plain -O2 and under ASan+UBSan) and the
#                   tests/compile checks, and through mk/*.mk the GL tests
#                   (plain and sanitized), the integration, packaging and
#                   fuzz-replay tests; run them all; ends "N passed, M failed"
#   make check      static checks: the compile checks, the embedded shaders
#                   (mk/shaders.mk), every shader composition through
#                   glslangValidator (mk/web.mk) and the documentation's
#                   links (mk/docs.mk)
#   make check-quick  for iteration (about 1 minute on 2 cores once the
#                   testbed is built): the C99 CPU tests, the compile
#                   checks, the shader checks and one GL test
#   make bench-cpu  CPU benchmark table (bench/bench_cpu.c)
#   make demo       install the demo packages, then build and run $(DEMO_TARGETS)
#   make clean      remove build/ and out/
SHELL := /bin/bash
.SHELLFLAGS := -eo pipefail -c
.DEFAULT_GOAL := test
.DELETE_ON_ERROR:
.SUFFIXES:
# every core unless the caller chose (-j N, -j1): a clean `make test`
# compiles each test program several ways, the bulk of its time
ifeq ($(filter -j%,$(MAKEFLAGS)),)
MAKEFLAGS += -j$(shell nproc 2>/dev/null || echo 2)
endif

ifeq ($(origin CC),default)
CC := gcc
endif
ifeq ($(origin CXX),default)
CXX := g++
endif

BUILD := build
OUT   := out

WARN     := -Wall -Wextra -Wpedantic -Werror
C99      := $(CC) -std=c99 $(WARN) -I.
CXX11    := $(CXX) -x c++ -std=c++11 $(WARN) -I.
CXX17    := $(CXX) -x c++ -std=c++17 $(WARN) -I.
OPT      := -O2
SANITIZE := -O1 -g -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all
LDLIBS   := -lm
MKDIR     = @mkdir -p $(@D) $(BUILD)/dep $(BUILD)/obj
DEPFLAGS  = -MMD -MP -MF $(BUILD)/dep/$(subst /,_,$@).d

# ---------------------------------------------------------------- unit tests
# every tests/test_*.c is a whole program; new ones are picked up by the wildcard.
# Each flavour compiles shadowkit.h's implementation once, tests/shared_impl.c
# into build/obj/<flavour>/shared_impl.o, and the programs link it: they are
# compiled with -include tests/shared_impl.h, which skips the implementation
# their own #define SHADOWKIT_IMPLEMENTATION asks for. A program that
# configures the implementation (an SK* macro defined before its first
# #include "...", see tests/own_impl.awk) compiles its own copy as before.
TEST_NAMES := $(sort $(basename $(notdir $(wildcard tests/test_*.c))))
FLAVOURS   := c99 cpp asan-c99 asan-cpp
TEST_BINS  := $(foreach f,$(FLAVOURS),$(addprefix $(BUILD)/$(f)/,$(TEST_NAMES)))
TEST_DEPS  := shadowkit.h tests/sk_test.h tests/shared_impl.h

# sk_own_impl: the basenames of the programs among $(1) with their own implementation
sk_own_impl = $(basename $(notdir $(shell awk -f tests/own_impl.awk $(1) /dev/null)))
CPU_OWN_IMPL := $(call sk_own_impl,$(wildcard tests/test_*.c))
# the arguments that make test program $(1) of flavour $(2) use the shared object
# (-x none: the C++ flavours' -x c++ must not apply to the object)
cpu_impl = $(if $(filter $(1),$(CPU_OWN_IMPL)),,-include tests/shared_impl.h $< -x none $(BUILD)/obj/$(2)/shared_impl.o)

$(BUILD)/obj/c99/shared_impl.o: tests/shared_impl.c shadowkit.h | deps-test
	$(MKDIR)
	$(C99) $(OPT) $(DEPFLAGS) -c $< -o $@
$(BUILD)/obj/cpp/shared_impl.o: tests/shared_impl.c shadowkit.h | deps-test
	$(MKDIR)
	$(CXX11) $(OPT) $(DEPFLAGS) -c $< -o $@
$(BUILD)/obj/asan-c99/shared_impl.o: tests/shared_impl.c shadowkit.h | deps-test
	$(MKDIR)
	$(C99) $(SANITIZE) $(DEPFLAGS) -c $< -o $@
$(BUILD)/obj/asan-cpp/shared_impl.o: tests/shared_impl.c shadowkit.h | deps-test
	$(MKDIR)
	$(CXX11) $(SANITIZE) $(DEPFLAGS) -c $< -o $@

$(BUILD)/c99/%: tests/%.c $(TEST_DEPS) $(BUILD)/obj/c99/shared_impl.o | deps-test
	$(MKDIR)
	$(C99) $(OPT) $(DEPFLAGS) $(or $(call cpu_impl,$*,c99),$<) -o $@ $(LDLIBS)
$(BUILD)/cpp/%: tests/%.c $(TEST_DEPS) $(BUILD)/obj/cpp/shared_impl.o | deps-test
	$(MKDIR)
	$(CXX11) $(OPT) $(DEPFLAGS) $(or $(call cpu_impl,$*,cpp),$<) -o $@ $(LDLIBS)
$(BUILD)/asan-c99/%: tests/%.c $(TEST_DEPS) $(BUILD)/obj/asan-c99/shared_impl.o | deps-test
	$(MKDIR)
	$(C99) $(SANITIZE) $(DEPFLAGS) $(or $(call cpu_impl,$*,asan-c99),$<) -o $@ $(LDLIBS)
$(BUILD)/asan-cpp/%: tests/%.c $(TEST_DEPS) $(BUILD)/obj/asan-cpp/shared_impl.o | deps-test
	$(MKDIR)
	$(CXX11) $(SANITIZE) $(DEPFLAGS) $(or $(call cpu_impl,$*,asan-cpp),$<) -o $@ $(LDLIBS)

# ---------------------------------------------------- compile checks (tests/compile)
# static-*: two SHADOWKIT_STATIC copies of the implementation in one program.
# extern-*: implementation in one TU, used from another TU without it;
# mixed-*:  the same with the two TUs in different languages (extern "C").
CD := tests/compile
COMPILE_DEPS   := shadowkit.h tests/sk_test.h $(wildcard $(CD)/*.h)
STATIC_SRCS    := $(CD)/static_a.c $(CD)/static_b.c $(CD)/static_main.c
COMPILE_BINS   := $(addprefix $(BUILD)/compile/,static-c99 static-cpp11 \
                  extern-c99 extern-cpp11 extern-cpp17 mixed-cimpl mixed-cppimpl)

$(BUILD)/compile/static-c99: $(STATIC_SRCS) $(COMPILE_DEPS) | deps-test
	$(MKDIR)
	$(C99) $(OPT) $(STATIC_SRCS) -o $@ $(LDLIBS)
$(BUILD)/compile/static-cpp11: $(STATIC_SRCS) $(COMPILE_DEPS) | deps-test
	$(MKDIR)
	$(CXX11) $(OPT) $(STATIC_SRCS) -o $@ $(LDLIBS)
$(BUILD)/compile/extern-c99: $(CD)/extern_impl.c $(CD)/extern_use.c $(COMPILE_DEPS) | deps-test
	$(MKDIR)
	$(C99) $(OPT) $(CD)/extern_impl.c $(CD)/extern_use.c -o $@ $(LDLIBS)
$(BUILD)/compile/extern-cpp11: $(CD)/extern_impl.c $(CD)/extern_use.c $(COMPILE_DEPS) | deps-test
	$(MKDIR)
	$(CXX11) $(OPT) $(CD)/extern_impl.c $(CD)/extern_use.c -o $@ $(LDLIBS)
$(BUILD)/compile/extern-cpp17: $(CD)/extern_impl.c $(CD)/extern_use.c $(COMPILE_DEPS) | deps-test
	$(MKDIR)
	$(CXX17) $(OPT) $(CD)/extern_impl.c $(CD)/extern_use.c -o $@ $(LDLIBS)
# C implementation, C++ user, and the reverse (objects kept under build/obj/)
$(BUILD)/compile/mixed-cimpl: $(CD)/extern_impl.c $(CD)/extern_use.c $(COMPILE_DEPS) | deps-test
	$(MKDIR)
	$(C99) $(OPT) -c $(CD)/extern_impl.c -o $(BUILD)/obj/mixed-cimpl-impl.o
	$(CXX11) $(OPT) -c $(CD)/extern_use.c -o $(BUILD)/obj/mixed-cimpl-use.o
	$(CXX) $(BUILD)/obj/mixed-cimpl-impl.o $(BUILD)/obj/mixed-cimpl-use.o -o $@ $(LDLIBS)
$(BUILD)/compile/mixed-cppimpl: $(CD)/extern_impl.c $(CD)/extern_use.c $(COMPILE_DEPS) | deps-test
	$(MKDIR)
	$(CXX11) $(OPT) -c $(CD)/extern_impl.c -o $(BUILD)/obj/mixed-cppimpl-impl.o
	$(C99) $(OPT) -c $(CD)/extern_use.c -o $(BUILD)/obj/mixed-cppimpl-use.o
	$(CXX) $(BUILD)/obj/mixed-cppimpl-impl.o $(BUILD)/obj/mixed-cppimpl-use.o -o $@ $(LDLIBS)

# ---------------------------------------------------------------- targets
.PHONY: test check check-quick check-compile bench-cpu demo clean deps-test deps-demo

test: $(TEST_BINS) $(COMPILE_BINS)
	@bash tests/run_tests.sh

# one line per check; each must fail (exit non-zero) when its check fails
CHECKS := check-compile
check: $(CHECKS)

check-compile: $(COMPILE_BINS)
	@bash tests/run_tests.sh compile

# for iteration: the CPU tests (C99 only), the compile checks, the shader
# checks and one GL smoke test (QUICK_GL); the shader checks and the GL
# test's build are added by mk/shaders.mk, mk/web.mk and mk/testbed.mk
QUICK_GL := test_gl_offscreen
check-quick: $(addprefix $(BUILD)/c99/,$(TEST_NAMES)) $(COMPILE_BINS)
	@bash tests/run_tests.sh c99 compile gl/$(QUICK_GL)

$(BUILD)/bench_cpu: bench/bench_cpu.c shadowkit.h | deps-test
	$(MKDIR)
	$(CC) -O2 -Wall -Wextra -I. $(DEPFLAGS) $< -o $@ $(LDLIBS)

bench-cpu: $(BUILD)/bench_cpu
	@mkdir -p $(OUT)
	./$(BUILD)/bench_cpu | tee $(OUT)/bench-cpu.txt
	@echo "bench-cpu: table saved to $(OUT)/bench-cpu.txt"

# mk/examples.mk and mk/bench.mk append theirs: DEMO_TARGETS += examples-demo ...
DEMO_TARGETS := bench-cpu
demo: deps-demo
	@echo "demo: building and running: $(DEMO_TARGETS); output goes to $(OUT)/"
	@# one target at a time: the benches time themselves
	@$(MAKE) -j1 --no-print-directory $(DEMO_TARGETS)
	@echo "demo: done; output is in $(OUT)/"

deps-test:
	@bash scripts/deps.sh test
deps-demo:
	@bash scripts/deps.sh demo

clean:
	rm -rf $(BUILD) $(OUT)

# GL tests, examples and the bench add their rules in mk/*.mk
include $(sort $(wildcard mk/*.mk))

-include $(wildcard $(BUILD)/dep/*.d)
