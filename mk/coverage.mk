# mk/coverage.mk - line and branch coverage of shadowkit.h and shadowkit_gl.h
# (included by the Makefile; not part of `make test`).
#   make coverage   build tests/test_*.c and tests/gl/test_gl_*.c with gcov
#                   instrumentation (C99, -O0 --coverage) under build/coverage/,
#                   run them (tests/run_tests.sh, flavours c99 and gl of that
#                   folder), and write the lcov report restricted to the two
#                   headers: out/coverage/index.html (genhtml, with branches),
#                   out/coverage/coverage.info, and a summary per header on
#                   stdout. Fails when a test fails, or when shadowkit.h is
#                   below COV_MIN_LINES % of its lines or COV_MIN_BRANCHES % of
#                   its branches (shadowkit_gl.h is reported, not checked).
# The CPU tests are built as C99 only: the C++ builds of the same header
# number their branches differently, and lcov would add the two up as if
# they were one program. The testbed library (build/testbed/libtestbed.a,
# mk/testbed.mk) is shared with `make test` and not instrumented.
# scripts/coverage.sh does the running and the reporting.
#
# Which GL tests run each GLSL program of shadowkit_gl.h (the programs built
# by skgl_create and skgl_point_create from shaders_embedded/), read from each
# test's own counters (build/coverage/obj/gl/<test>.gcda) at the program's
# glUseProgram in the pass that draws with it:
#   depth (depth.vert + depth.frag)                 accuracy bias cascades ferko forward
#     directional layers (skgl_shadow_render)        lspsm model offscreen rmsm stable
#                                                    state warp
#     u_model other than the identity               model (skgl_set_model)
#     RMSM pages (skgl__render_rmsm)                rmsm state
#     point-light faces (skgl_point_render)         omni multi state
#   shadow mask (fullscreen.vert +                  the tests of the directional layers above
#     shadow_sample.glsl + shadow_mask.frag)
#   FERKO analysis (ferko_analyze.frag)             ferko state
#   FERKO reduction (ferko_reduce.frag)             ferko state
#   RMSM analysis (rmsm_analyze.frag)               rmsm state
#   RMSM page requests (rmsm_request.vert/.frag)    rmsm state
#   point mask, cube and VSDCT variants             omni multi state
#     (fullscreen.vert + point_sample.glsl + point_mask.frag)
#   forward snippets in the test's own shader:
#     shadow_sample.glsl (skgl_glsl_snippet)        forward state
#     point_sample.glsl (skgl_point_glsl_snippet)   omni
# (test_ prefixes left out; test_gl_testbed runs no shadowkit_gl.h code.)
.SECONDEXPANSION:

COV_DIR          := $(BUILD)/coverage
COV_OUT          := $(OUT)/coverage
COV_MIN_LINES    ?= 95
COV_MIN_BRANCHES ?= 90
COV_FLAGS        := -O0 -g --coverage
COV_CPU_BINS     := $(addprefix $(COV_DIR)/c99/,$(TEST_NAMES))
COV_GL_BINS      := $(patsubst tests/gl/%.c,$(COV_DIR)/gl/%,$(sort $(wildcard tests/gl/test_gl_*.c)))

# compile and link apart, so that each object's .gcno (and the .gcda its run
# writes) sits beside it under build/coverage/obj/
$(COV_DIR)/c99/%: tests/%.c $(TEST_DEPS) | deps-coverage
	$(MKDIR) $(COV_DIR)/obj/c99
	$(C99) $(COV_FLAGS) $(DEPFLAGS) -c $< -o $(COV_DIR)/obj/c99/$*.o
	$(CC) --coverage $(COV_DIR)/obj/c99/$*.o -o $@ $(LDLIBS)

$(COV_DIR)/gl/%: tests/gl/%.c $$(GL_TEST_DEPS) $$(TESTBED_LIB) | deps-coverage
	$(MKDIR) $(COV_DIR)/obj/gl
	$(CC) -std=c99 $(COV_FLAGS) $(WARN) $(TESTBED_CFLAGS) -Itests $(DEPFLAGS) -c $< \
	    -o $(COV_DIR)/obj/gl/$*.o
	$(CC) --coverage $(COV_DIR)/obj/gl/$*.o -o $@ $(TESTBED_LIB) $(TESTBED_LIBS)

.PHONY: coverage deps-coverage
coverage: $(COV_CPU_BINS) $(COV_GL_BINS) scripts/coverage.sh
	@COV_DIR=$(COV_DIR) COV_OUT=$(COV_OUT) COV_MIN_LINES=$(COV_MIN_LINES) \
	    COV_MIN_BRANCHES=$(COV_MIN_BRANCHES) bash scripts/coverage.sh

deps-coverage:
	@bash scripts/deps.sh coverage
