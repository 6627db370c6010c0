# mk/web.mk - OpenGL ES 3.0 and WebGL2 (included by the Makefile).
#   make check-glsl   every program composition and snippet, both dialects, through
#                     glslangValidator (tests/es/check_glsl.sh; part of make check and make test)
#   make web          the live demo page (web/) into $(OUT)/web, served on 127.0.0.1
#   build/integration/web_browser   the browser test (tests/es/web_test.sh): every technique
#                     on WebGL2 in headless Chromium against the desktop masks (part of make test)
# Packages: scripts/deps.sh web (emscripten, chromium, glslang-tools). Nothing is downloaded
# at build time: Debian's emcc with no ports, the pages load from disk.
# The testbed's variables come from mk/testbed.mk, read after this file (.SECONDEXPANSION).
.SECONDEXPANSION:

WEB_DIR  := $(BUILD)/web
WEB_OUT  := $(OUT)/web
WEB_PORT ?= 8017
# Debian's emcc needs its own node modules when another node comes first on PATH
EMCC     := NODE_PATH=/usr/share/nodejs emcc
EMFLAGS  := -std=gnu99 -O2 -Wall -Werror -I. -Itests -sSINGLE_FILE=1 -sWASM_ASYNC_COMPILATION=0 \
            -sALLOW_MEMORY_GROWTH=1 -sMIN_WEBGL_VERSION=2 -sMAX_WEBGL_VERSION=2
ES_HDRS  := shadowkit.h shadowkit_gl.h tests/es/es_core.h

.PHONY: deps-web check-glsl web

deps-web:
	@bash scripts/deps.sh web

# ---- the shader check
$(BUILD)/tools/glsl_dump: tests/es/glsl_dump.c $(ES_HDRS) $$(TESTBED_LIB) | deps-gl
	$(MKDIR)
	$(CC) -std=c99 $(OPT) $(WARN) $(TESTBED_CFLAGS) -Itests $< -o $@ $(TESTBED_LIB) $(TESTBED_LIBS)

check-glsl: $(BUILD)/tools/glsl_dump | deps-web
	@bash tests/es/check_glsl.sh $(BUILD)/tools/glsl_dump $(BUILD)/glsl

check: check-glsl
test: check-glsl

# ---- the browser test: the desktop masks, then the page that compares with them
$(WEB_DIR)/es_dump: tests/es/es_dump.c $(ES_HDRS) $$(TESTBED_LIB) | deps-gl
	$(MKDIR)
	$(CC) -std=c99 $(OPT) $(WARN) $(TESTBED_CFLAGS) -Itests $< -o $@ $(TESTBED_LIB) $(TESTBED_LIBS)

$(WEB_DIR)/es_data.bin: $(WEB_DIR)/es_dump
	./$< $@

$(WEB_DIR)/es_test.js: tests/es/es_web_test.c $(ES_HDRS) $(WEB_DIR)/es_data.bin | deps-web
	$(EMCC) $(EMFLAGS) $< -o $@ --embed-file $(WEB_DIR)/es_data.bin@/es_data.bin

$(WEB_DIR)/es_test.html: tests/es/es_test.html
	@mkdir -p $(@D)
	install -m 644 $< $@

$(INT_DIR)/web_browser: tests/es/web_test.sh $(WEB_DIR)/es_test.js $(WEB_DIR)/es_test.html | deps-web
	@mkdir -p $(@D)
	install -m 755 $< $@

test: $(INT_DIR)/web_browser
