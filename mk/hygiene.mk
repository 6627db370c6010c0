# mk/hygiene.mk - GL hygiene: the `hygiene` flavour of tests/run_tests.sh
# (part of `make test`; also `make test-hygiene` alone).
#   build/hygiene/<name>   every GL test (tests/gl/test_gl_*.c) built again
#                          with AddressSanitizer + LeakSanitizer + UBSan
#                          ($(SANITIZE)), so that a heap error or a host-side
#                          leak in shadowkit_gl.h (or the testbed or a test)
#                          fails the run. Linked with
#                          tests/hygiene/sanitizer_options.c (the sanitizer
#                          defaults, leak detection on). The testbed library
#                          itself stays uninstrumented (its allocations are
#                          still tracked: the runtime replaces malloc).
# OSMesa keeps 480 bytes per context; testbed/tb_gl_osmesa.c exempts exactly
# the two calls that allocate them (see there), so no suppression is needed.
# The testbed's variables come from mk/testbed.mk, read after this file:
# prerequisites naming them are expanded in the second phase.
.SECONDEXPANSION:

HYG_DIR      := $(BUILD)/hygiene
HYG_GL_TESTS := $(sort $(wildcard tests/gl/test_gl_*.c))
HYG_GL_BINS  := $(patsubst tests/gl/%.c,$(HYG_DIR)/%,$(HYG_GL_TESTS))
HYG_OPTIONS  := tests/hygiene/sanitizer_options.c

$(HYG_GL_BINS): $(HYG_DIR)/%: tests/gl/%.c $(HYG_OPTIONS) $$(GL_TEST_DEPS) $$(TESTBED_LIB) | deps-gl
	$(MKDIR)
	$(CC) -std=c99 $(SANITIZE) $(WARN) $(TESTBED_CFLAGS) -Itests $(DEPFLAGS) $< $(HYG_OPTIONS) -o $@ \
	    $(TESTBED_LIB) $(TESTBED_LIBS)

.PHONY: test-hygiene
test-hygiene: $(HYG_GL_BINS)
	@bash tests/run_tests.sh hygiene

test: $(HYG_GL_BINS)
