# mk/web.mk - OpenGL ES 3.0 and WebGL2 (included by the Makefile).
#   make check-glsl   every program composition and snippet, both dialects, through
#                     glslangValidator (tests/es/check_glsl.sh; part of make check and make test)
#   make web          the live demo page (web/) into $(OUT)/web, served on 127.0.0.1:$(WEB_PORT)
#   make web-shot     docs/images/web_demo.png: the page in headless Chromium
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
EMFLAGS  := -std=gnu99 -O2 -Wall -Werror -I. -Itests -sSINGLE_FILE=1 -sALLOW_MEMORY_GROWTH=1 \
            -sMIN_WEBGL_VERSION=2 -sMAX_WEBGL_VERSION=2
# the browser test runs before the load event ends (web_test.sh reads the page then)
EMTEST   := -sWASM_ASYNC_COMPILATION=0
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
check-quick: check-glsl

# ---- the browser test: the desktop masks, then the page that compares with them
$(WEB_DIR)/es_dump: tests/es/es_dump.c $(ES_HDRS) $$(TESTBED_LIB) | deps-gl
	$(MKDIR)
	$(CC) -std=c99 $(OPT) $(WARN) $(TESTBED_CFLAGS) -Itests $< -o $@ $(TESTBED_LIB) $(TESTBED_LIBS)

$(WEB_DIR)/es_data.bin: $(WEB_DIR)/es_dump
	./$< $@

$(WEB_DIR)/es_test.js: tests/es/es_web_test.c $(ES_HDRS) $(WEB_DIR)/es_data.bin | deps-web
	$(EMCC) $(EMFLAGS) $(EMTEST) $< -o $@ --embed-file $(WEB_DIR)/es_data.bin@/es_data.bin

$(WEB_DIR)/es_test.html: tests/es/es_test.html
	@mkdir -p $(@D)
	install -m 644 $< $@

$(INT_DIR)/web_browser: tests/es/web_test.sh $(WEB_DIR)/es_test.js $(WEB_DIR)/es_test.html | deps-web
	@mkdir -p $(@D)
	install -m 755 $< $@

test: $(INT_DIR)/web_browser

# ---- the live demo page: make web
# the real scenes, baked to flat arrays when ../shared/scenes is there (the page works without)
SHARED_SCENES := ../shared/scenes
WEB_SCENES := $(if $(wildcard $(SHARED_SCENES)/stanford-bunny.obj),bunny) \
              $(if $(wildcard $(SHARED_SCENES)/sponza-ivy/sponza_ivy.gltf),ivy) \
              $(if $(wildcard $(SHARED_SCENES)/sponza-curtains/sponza_curtains.gltf),curtains)
WEB_SCENE_SRC_bunny    := $(SHARED_SCENES)/stanford-bunny.obj
WEB_SCENE_SRC_ivy      := $(SHARED_SCENES)/sponza-ivy/sponza_ivy.gltf
WEB_SCENE_SRC_curtains := $(SHARED_SCENES)/sponza-curtains/sponza_curtains.gltf
WEB_SCENE_BINS := $(foreach s,$(strip $(WEB_SCENES)),$(WEB_DIR)/scenes/$(s).bin)
WEB_EXPORTS := _main,_web_set,_web_stats,_web_scenes,_web_scene_name,_web_techs,_web_tech_name

$(WEB_DIR)/scene_bake: web/scene_bake.c shadowkit.h $$(TESTBED_LIB) | deps-gl
	$(MKDIR)
	$(CC) -std=c99 $(OPT) $(WARN) $(TESTBED_CFLAGS) $< -o $@ $(TESTBED_LIB) $(TESTBED_LIBS)

$(WEB_DIR)/scenes/%.bin: $(WEB_DIR)/scene_bake
	@mkdir -p $(@D)
	./$(WEB_DIR)/scene_bake $(WEB_SCENE_SRC_$*) $@

$(WEB_OUT)/shadowkit_web.js: web/shadowkit_web.c shadowkit.h shadowkit_gl.h $(WEB_SCENE_BINS) | deps-web
	@mkdir -p $(@D)
	$(EMCC) $(EMFLAGS) -sEXPORTED_FUNCTIONS=$(WEB_EXPORTS) -sEXPORTED_RUNTIME_METHODS=UTF8ToString $< -o $@ \
	    $(foreach s,$(strip $(WEB_SCENES)),--embed-file $(WEB_DIR)/scenes/$(s).bin@/scenes/$(s).bin)

$(WEB_OUT)/index.html: web/index.html
	@mkdir -p $(@D)
	install -m 644 $< $@

.PHONY: web-page web-shot
web-page: $(WEB_OUT)/shadowkit_web.js $(WEB_OUT)/index.html

web: web-page
	@echo "web: the page is $(WEB_OUT)/index.html (it also opens from disk)"
	@echo "web: serving http://127.0.0.1:$(WEB_PORT)/ (Ctrl-C stops)"
	python3 -m http.server --bind 127.0.0.1 $(WEB_PORT) --directory $(WEB_OUT)

# docs/gles-webgl.md's picture of the page, taken by headless Chromium (SwiftShader)
web-shot: web-page | deps-web
	timeout 120 chromium --headless=new --no-sandbox --use-angle=swiftshader --enable-unsafe-swiftshader \
	    --use-gl=angle --window-size=1040,680 --virtual-time-budget=15000 \
	    --screenshot=$(abspath docs/images/web_demo.png) "file://$(abspath $(WEB_OUT))/index.html" 2>/dev/null
	@echo "web-shot: docs/images/web_demo.png"
