# Embedded GLSL: shaders_embedded/* are the sources, shadowkit_gl.h holds them
# as string literals between its SKGL_EMBEDDED_SHADERS markers.
#   make shaders        rewrite the literals in shadowkit_gl.h from the sources
#   make check-shaders  fail if they differ (part of `make check` and `make test`)
SHADER_SRCS := shaders_embedded/depth.vert shaders_embedded/depth.frag \
               shaders_embedded/fullscreen.vert shaders_embedded/shadow_sample.glsl \
               shaders_embedded/shadow_mask.frag shaders_embedded/ferko_analyze.frag \
               shaders_embedded/ferko_reduce.frag shaders_embedded/rmsm_analyze.frag \
               shaders_embedded/rmsm_request.vert shaders_embedded/rmsm_request.frag \
               shaders_embedded/point_sample.glsl shaders_embedded/point_mask.frag \
               shaders_embedded/soft_common.glsl shaders_embedded/soft_kernel.frag \
               shaders_embedded/soft_smtg.vert shaders_embedded/soft_smtg.frag \
               shaders_embedded/soft_reduce.vert shaders_embedded/soft_reduce.frag shaders_embedded/soft_filter.frag \
               shaders_embedded/soft_resolve.frag shaders_embedded/soft_cons.geom \
               shaders_embedded/soft_cons.frag shaders_embedded/soft_gbuffer.vert \
               shaders_embedded/soft_gbuffer.frag shaders_embedded/pcss_mask.frag \
               shaders_embedded/layered.geom shaders_embedded/soft_dilate.frag \
               shaders_embedded/evsm_moments.frag
EMBED := $(BUILD)/tools/embed

$(EMBED): shaders_embedded/embed.c | deps-test
	$(MKDIR)
	$(CC) -std=c99 -O2 -Wall -Wextra -Werror $< -o $@

.PHONY: shaders check-shaders
shaders: $(EMBED)
	$(EMBED) --write shadowkit_gl.h $(SHADER_SRCS)
check-shaders: $(EMBED)
	$(EMBED) --check shadowkit_gl.h $(SHADER_SRCS)
	@echo "check-shaders: shadowkit_gl.h matches shaders_embedded/"

check: check-shaders
test: check-shaders

# shadowkit_gl.h compiled as C99, C++11 and C++17 (no GL needed to link)
GL_HEADER_BINS := $(addprefix $(BUILD)/compile/,gl-header-c99 gl-header-cpp11 gl-header-cpp17)
$(BUILD)/compile/gl-header-c99: tests/compile/gl_header.c shadowkit.h shadowkit_gl.h tests/sk_test.h | deps-test
	$(MKDIR)
	$(C99) $(OPT) $< -o $@ $(LDLIBS)
$(BUILD)/compile/gl-header-cpp11: tests/compile/gl_header.c shadowkit.h shadowkit_gl.h tests/sk_test.h | deps-test
	$(MKDIR)
	$(CXX11) $(OPT) $< -o $@ $(LDLIBS)
$(BUILD)/compile/gl-header-cpp17: tests/compile/gl_header.c shadowkit.h shadowkit_gl.h tests/sk_test.h | deps-test
	$(MKDIR)
	$(CXX17) $(OPT) $< -o $@ $(LDLIBS)

# the opt-outs (shadowkit_gl.h's CONFIGURATION: SKGL_NO_*): gl_header.c
# with each alone and with all together, as C99 and C++17; gl-no-all-* is
# what the object size and line count of the report compare. At -Og: the
# same warnings as -O2 where only the switches' code differs (unused
# functions and variables, uninitialized reads), in 2 CPU s instead of 5
# (the gl-header-* builds above keep -O2 for everything)
GL_OPTOUTS := soft rmsm cache casters ferko
gl_optout_flags = $(foreach o,$(if $(filter all,$(1)),$(GL_OPTOUTS),$(1)),-DSKGL_NO_$(shell echo $(o) | tr a-z A-Z))
GL_OPTOUT_BINS := $(foreach o,$(GL_OPTOUTS) all,$(BUILD)/compile/gl-no-$(o)-c99 $(BUILD)/compile/gl-no-$(o)-cpp17)
$(BUILD)/compile/gl-no-%-c99: tests/compile/gl_header.c shadowkit.h shadowkit_gl.h tests/sk_test.h | deps-test
	$(MKDIR)
	$(C99) -Og $(call gl_optout_flags,$*) $< -o $@ $(LDLIBS)
$(BUILD)/compile/gl-no-%-cpp17: tests/compile/gl_header.c shadowkit.h shadowkit_gl.h tests/sk_test.h | deps-test
	$(MKDIR)
	$(CXX17) -Og $(call gl_optout_flags,$*) $< -o $@ $(LDLIBS)

# SKGL_MALLOC alone, and SKGL_FREE alone, must stop at shadowkit_gl.h's
# #error: the rule fails when the file compiles, or fails with another
# message, and otherwise leaves a program that says so for the compile
# flavour of tests/run_tests.sh
GL_ALONE_BINS := $(addprefix $(BUILD)/compile/,gl-malloc-alone gl-free-alone)
$(BUILD)/compile/gl-%-alone: tests/compile/gl_alloc_alone.c shadowkit.h shadowkit_gl.h | deps-test
	$(MKDIR)
	@if $(C99) $(OPT) -fsyntax-only $(if $(filter free,$*),-DSK_FREE_ALONE) $< > $(BUILD)/obj/gl-$*-alone.log 2>&1; \
	then echo "$<: SKGL $* alone compiled: shadowkit_gl.h must refuse it"; exit 1; fi
	@grep -q 'define both SKGL_MALLOC and SKGL_FREE, or neither' $(BUILD)/obj/gl-$*-alone.log || \
	    { cat $(BUILD)/obj/gl-$*-alone.log; echo "$<: SKGL $* alone failed without the #error"; exit 1; }
	@printf '#!/bin/sh\necho "SKGL %s alone: refused by the #error"\necho "%s: 1 passed, 0 failed"\n' $* $@ > $@ && chmod +x $@

# the headers' anchors against their maps (tests/compile/check_anchors.sh,
# run by the compile flavour from the repository root)
$(BUILD)/compile/anchors: tests/compile/check_anchors.sh
	$(MKDIR)
	cp $< $@ && chmod +x $@

test: $(GL_HEADER_BINS) $(GL_ALONE_BINS) $(GL_OPTOUT_BINS) $(BUILD)/compile/anchors
check-compile: $(GL_HEADER_BINS) $(GL_ALONE_BINS) $(GL_OPTOUT_BINS) $(BUILD)/compile/anchors
check-quick: check-shaders $(GL_HEADER_BINS) $(GL_ALONE_BINS) $(GL_OPTOUT_BINS) $(BUILD)/compile/anchors
