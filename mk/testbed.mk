# testbed/ as a library, and the GL tests (tests/gl/test_gl_*.c) built on it.
#   build/testbed/libtestbed.a   testbed/*.c except selftest.c, C99 -O2
#   build/gl/<name>              one program per tests/gl/<name>.c (the `gl`
#                                flavour of tests/run_tests.sh, part of `make test`)
#   make testbed-selftest        the testbed's own self-test (testbed/selftest.c)
# Variables for the other fragments (examples, bench), all recursive so that
# pkg-config runs after deps-gl has installed it:
#   TESTBED_CFLAGS  include paths and pkg-config cflags (add your own -std/-O/warnings)
#   TESTBED_LIB     the archive path (a prerequisite; link it before TESTBED_LIBS)
#   TESTBED_LIBS    the libraries it needs
# A rule that links the testbed: `target: src $(TESTBED_LIB) | deps-gl`, recipe
#   $(CC) -std=c99 $(TESTBED_CFLAGS) src -o $@ $(TESTBED_LIB) $(TESTBED_LIBS)

TESTBED_PCS    := assimp osmesa egl
TESTBED_CFLAGS  = -I. -Itestbed $(shell pkg-config --cflags $(TESTBED_PCS) 2>/dev/null)
TESTBED_LIB    := $(BUILD)/testbed/libtestbed.a
# Debian's libembree-dev has no .pc file; the fallback is for a missing pkg-config
TESTBED_LIBS    = $(shell pkg-config --libs $(TESTBED_PCS) stb 2>/dev/null || \
                    echo -lassimp -lOSMesa -lEGL -lstb) -lembree3 -lpthread -lm

TESTBED_SRCS := $(filter-out testbed/selftest.c,$(sort $(wildcard testbed/*.c)))
TESTBED_OBJS := $(patsubst testbed/%.c,$(BUILD)/testbed/%.o,$(TESTBED_SRCS))
TESTBED_HDRS := $(wildcard testbed/*.h) shadowkit.h

$(BUILD)/testbed/%.o: testbed/%.c $(TESTBED_HDRS) | deps-gl
	$(MKDIR)
	$(CC) -std=c99 $(OPT) -g $(WARN) $(TESTBED_CFLAGS) -c $< -o $@

$(TESTBED_LIB): $(TESTBED_OBJS)
	@mkdir -p $(@D)
	rm -f $@
	ar rcs $@ $^

$(BUILD)/testbed/selftest: testbed/selftest.c $(TESTBED_LIB) $(TESTBED_HDRS) | deps-gl
	$(MKDIR)
	$(CC) -std=c99 $(OPT) -g $(WARN) $(TESTBED_CFLAGS) $< -o $@ $(TESTBED_LIB) $(TESTBED_LIBS)

# ---------------------------------------------------------------- GL tests
# Every tests/gl/test_gl_*.c is a whole program (tests/sk_test.h) that
# includes shadowkit_gl.h with its implementation and links the testbed.
# The implementation is compiled once (tests/gl/shared_impl_gl.c into
# build/obj/gl/shared_impl_gl.o) and linked by every program compiled with
# -include tests/shared_impl.h (see there: the program's own
# #define SHADOWKIT_[GL_]IMPLEMENTATION then adds nothing). The programs that
# configure the implementation (tests/own_impl.awk: an SK* macro defined
# before the first #include "...") compile their own, as before.
GL_TESTS     := $(sort $(wildcard tests/gl/test_gl_*.c))
GL_TEST_BINS := $(patsubst tests/gl/%.c,$(BUILD)/gl/%,$(GL_TESTS))
GL_TEST_DEPS := shadowkit.h shadowkit_gl.h tests/sk_test.h tests/shared_impl.h $(wildcard tests/gl/*.h)
# The programs whose one configuration is the line "#define SKGL_LAYERED_LOOP 1"
# (test_gl_*_loop.c: the layered passes through the looping geometry
# shader; each asserts stats.layered == 1) link a second shared object,
# shared_impl_gl_loop.o, compiled with it.
GL_LOOP_IMPL := $(basename $(notdir $(shell grep -lx '\#define SKGL_LAYERED_LOOP 1' $(GL_TESTS) /dev/null)))
GL_OWN_IMPL  := $(filter-out $(GL_LOOP_IMPL),$(call sk_own_impl,$(GL_TESTS)))
# the shared object GL test $(1) of flavour $(2) (gl, hygiene) links
gl_impl_obj = $(BUILD)/obj/$(2)/shared_impl_gl$(if $(filter $(1),$(GL_LOOP_IMPL)),_loop).o
# the source and objects that make GL test $(1) of flavour $(2) use the shared object
gl_impl = $(if $(filter $(1),$(GL_OWN_IMPL)),$<,-include tests/shared_impl.h -DSK_TEST_SHARED_IMPL_GL $< \
              $(call gl_impl_obj,$(1),$(2)))

$(BUILD)/obj/gl/shared_impl_gl.o: tests/gl/shared_impl_gl.c shadowkit.h shadowkit_gl.h | deps-gl
	$(MKDIR)
	$(CC) -std=c99 $(OPT) -g $(WARN) $(TESTBED_CFLAGS) $(DEPFLAGS) -c $< -o $@
$(BUILD)/obj/gl/shared_impl_gl_loop.o: tests/gl/shared_impl_gl.c shadowkit.h shadowkit_gl.h | deps-gl
	$(MKDIR)
	$(CC) -std=c99 $(OPT) -g $(WARN) $(TESTBED_CFLAGS) -DSKGL_LAYERED_LOOP=1 $(DEPFLAGS) -c $< -o $@
$(addprefix $(BUILD)/gl/,$(GL_LOOP_IMPL)): $(BUILD)/obj/gl/shared_impl_gl_loop.o
$(addprefix $(BUILD)/hygiene/,$(GL_LOOP_IMPL)): $(BUILD)/obj/hygiene/shared_impl_gl_loop.o

$(BUILD)/gl/%: tests/gl/%.c $(GL_TEST_DEPS) $(TESTBED_LIB) $(BUILD)/obj/gl/shared_impl_gl.o | deps-gl
	$(MKDIR)
	$(CC) -std=c99 $(OPT) -g $(WARN) $(TESTBED_CFLAGS) -Itests $(DEPFLAGS) $(call gl_impl,$*,gl) -o $@ \
	    $(TESTBED_LIB) $(TESTBED_LIBS)

# test_gl_optout.c once per opt-out with that SKGL_NO_* alone (mk/shaders.mk's
# GL_OPTOUTS; every switch together is test_gl_optout itself): the switch's
# refusals, and the features that stay (RMSM, FERKO's analysis) still
# shadow. At -Og, as the compile checks (only the switches' code differs
# from the -O2 programs). tests/run_tests.sh runs them with the GL flavour.
GL_OPTOUT_ONE := $(addprefix $(BUILD)/gl/test_gl_optout_no_,$(GL_OPTOUTS))
$(BUILD)/gl/test_gl_optout_no_%: tests/gl/test_gl_optout.c $(GL_TEST_DEPS) $(TESTBED_LIB) | deps-gl
	$(MKDIR)
	$(CC) -std=c99 -Og -g $(WARN) $(TESTBED_CFLAGS) -Itests -DSK_OPTOUT_ONE $(call gl_optout_flags,$*) $< -o $@ \
	    $(TESTBED_LIB) $(TESTBED_LIBS)

.PHONY: deps-gl testbed testbed-selftest test-gl
deps-gl:
	@bash scripts/deps.sh gl

testbed: $(TESTBED_LIB)

testbed-selftest: $(BUILD)/testbed/selftest
	@mkdir -p $(OUT)
	LSAN_OPTIONS=suppressions=testbed/lsan.supp ./$(BUILD)/testbed/selftest

# the GL flavour alone
test-gl: $(GL_TEST_BINS) $(GL_OPTOUT_ONE)
	@bash tests/run_tests.sh gl

test: $(GL_TEST_BINS) $(GL_OPTOUT_ONE)
check-quick: $(BUILD)/gl/$(QUICK_GL)
