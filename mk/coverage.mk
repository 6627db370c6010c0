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
# Which GL test runs which GLSL program of shadowkit_gl.h (skgl__build_program
# callers; the line counts of their dispatch code in the report show it):
#   depth pass (depth.vert + depth.frag)          test_gl_accuracy, test_gl_cascades,
#       every skgl_shadow_render and RMSM page     test_gl_stable, test_gl_bias, test_gl_warp,
#       render; the point lights' depth too       test_gl_lspsm, test_gl_ferko, test_gl_rmsm,
#                                                  test_gl_omni, test_gl_multi, test_gl_state, ...
#   shadow mask (fullscreen.vert +                 every test above that calls skgl_shadow_mask
#       shadow_sample.glsl + shadow_mask.frag)     (all techniques: standard, PSSM, stable,
#                                                  PSM/LiSPSM, LSPSM, FERKO, RMSM)
#   FERKO analysis (fullscreen.vert +              test_gl_ferko, test_gl_state
#       ferko_analyze.frag)
#   FERKO reduction (fullscreen.vert +             test_gl_ferko, test_gl_state
#       ferko_reduce.frag)
#   RMSM analysis (fullscreen.vert +               test_gl_rmsm, test_gl_state
#       rmsm_analyze.frag)
#   RMSM page request (rmsm_request.vert +         test_gl_rmsm, test_gl_state
#       rmsm_request.frag)
#   point-light mask, cube and VSDCT (fullscreen   test_gl_omni, test_gl_multi, test_gl_state
#       .vert + point_sample.glsl + point_mask.frag)
#   forward snippets (shadow_sample.glsl,          test_gl_forward (directional),
#       point_sample.glsl in the caller's shader)  test_gl_omni (point lights)
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
