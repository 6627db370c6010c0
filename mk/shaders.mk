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
               shaders_embedded/layered.geom shaders_embedded/soft_dilate.frag
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
test: $(GL_HEADER_BINS)
check-compile: $(GL_HEADER_BINS)
check-quick: check-shaders $(GL_HEADER_BINS)
