# mk/hygiene.mk - GL hygiene and packaging: the `hygiene` flavour of
# tests/run_tests.sh (part of `make test`; also `make test-hygiene` alone,
# `make test-packaging` for the packaging test by itself).
#   build/hygiene/<name>   every GL test (tests/gl/test_gl_*.c) built again
#                          with AddressSanitizer + LeakSanitizer + UBSan
#                          ($(SANITIZE)), so that a heap error or a host-side
#                          leak in shadowkit_gl.h (or the testbed or a test)
#                          fails the run. Linked with
#                          tests/hygiene/sanitizer_options.c (the sanitizer
#                          defaults, leak detection on) and with the
#                          implementation compiled once under the same
#                          sanitizers (build/obj/hygiene/shared_impl_gl.o;
#                          see tests/shared_impl.h). The testbed library
#                          itself stays uninstrumented (its allocations are
#                          still tracked: the runtime replaces malloc).
# OSMesa keeps 480 bytes per context; testbed/tb_gl_osmesa.c exempts exactly
# the two calls that allocate them (see there), so no suppression is needed.
# The testbed's variables come from mk/testbed.mk, read after this file:
# prerequisites naming them are expanded in the second phase.
.SECONDEXPANSION:

HYG_DIR      := $(BUILD)/hygiene
# Left out of this flavour (they run in the plain one, build/gl/):
# - test_gl_calls: it counts GL calls over the frames every other GL test
#   draws (44 CPU s plain, 4x that under the sanitizers), and the library paths
#   it reaches run under the sanitizers in test_gl_census, test_gl_debug and
#   test_gl_paths already;
# - the programs whose every reached line of shadowkit_gl.h is reached here
#   by the programs that stay. Measured with gcov (-O1, each program's
#   lines): test_gl_open_world (1829 lines; 52 CPU s under the sanitizers),
#   test_gl_soft_closed_form (1470; 37), test_gl_interior (1376; 26),
#   test_gl_closed_form (1620; 22), test_gl_large_world (2074; 20, and its
#   own copy of the implementation to compile), test_gl_forest (1464; 15)
#   and test_gl_stable (10): 0 of their lines unreached by auto, bias,
#   bias_cf, cache, cache_property, cascades, caster_varyings, casters,
#   contracts, debug, misuse, omni, paths, rings, soft, soft_rings, spot,
#   texel_limit and warp; and test_gl_bias_cf (1655; 24): 0 unreached by
#   es, multilight, census, omni, spot, paths, debug, misuse, rings,
#   contracts, bias and warp. Remeasure when a program's paths change:
#   scripts/gl_coverage.sh LEFT_OUT... -- KEPT... (gcov, line by line).
HYG_LEFT_OUT := test_gl_calls test_gl_open_world test_gl_soft_closed_form test_gl_interior test_gl_closed_form \
                test_gl_large_world test_gl_forest test_gl_stable test_gl_bias_cf
HYG_GL_TESTS := $(filter-out $(addprefix tests/gl/,$(addsuffix .c,$(HYG_LEFT_OUT))),\
                             $(sort $(wildcard tests/gl/test_gl_*.c)))
HYG_GL_BINS  := $(patsubst tests/gl/%.c,$(HYG_DIR)/%,$(HYG_GL_TESTS))
HYG_OPTIONS  := tests/hygiene/sanitizer_options.c

# the implementation compiled once under the sanitizers (gl_impl: mk/testbed.mk)
$(BUILD)/obj/hygiene/shared_impl_gl.o: tests/gl/shared_impl_gl.c shadowkit.h shadowkit_gl.h | deps-gl
	$(MKDIR)
	$(CC) -std=c99 $(SANITIZE) $(WARN) $(TESTBED_CFLAGS) $(DEPFLAGS) -c $< -o $@

$(BUILD)/obj/hygiene/shared_impl_gl_loop.o: tests/gl/shared_impl_gl.c shadowkit.h shadowkit_gl.h | deps-gl
	$(MKDIR)
	$(CC) -std=c99 $(SANITIZE) $(WARN) $(TESTBED_CFLAGS) -DSKGL_LAYERED_LOOP=1 $(DEPFLAGS) -c $< -o $@
# (the loop programs' prerequisite on it: mk/testbed.mk, where GL_LOOP_IMPL is set)

$(HYG_GL_BINS): $(HYG_DIR)/%: tests/gl/%.c $(HYG_OPTIONS) $$(GL_TEST_DEPS) $$(TESTBED_LIB) \
                $(BUILD)/obj/hygiene/shared_impl_gl.o | deps-gl
	$(MKDIR)
	$(CC) -std=c99 $(SANITIZE) $(WARN) $(TESTBED_CFLAGS) -Itests $(DEPFLAGS) $(call gl_impl,$*,hygiene) \
	    $(HYG_OPTIONS) -o $@ $(TESTBED_LIB) $(TESTBED_LIBS)

# the packaging test (tests/packaging/run.sh: CMake package, pkg-config file,
# add_subdirectory), run from here as build/hygiene/test_packaging
HYG_PACKAGING := $(HYG_DIR)/test_packaging
$(HYG_PACKAGING): tests/packaging/run.sh | deps-test
	$(MKDIR)
	printf '#!/bin/sh\n# built by mk/hygiene.mk\nexec bash tests/packaging/run.sh "$$@"\n' > $@
	chmod +x $@

.PHONY: test-hygiene test-packaging
test-hygiene: $(HYG_GL_BINS) $(HYG_PACKAGING)
	@bash tests/run_tests.sh hygiene
test-packaging: $(HYG_PACKAGING)
	@bash tests/packaging/run.sh

test: $(HYG_GL_BINS) $(HYG_PACKAGING)
