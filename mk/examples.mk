# mk/examples.mk - the tutorial programs in examples/ (included by the Makefile).
#   make examples        build build/examples/01_hard_shadows .. 08_spot_lights
#   make examples-demo   render each one headless into out/ (part of make demo)
# Each example is one C99 file holding the shadowkit implementation, plus
# examples/common.c, linked with the testbed library and GLFW. Each builds
# alone that way; here the eight are compiled with -include
# tests/shared_impl.h, which turns their #define SHADOWKIT_[GL_]IMPLEMENTATION
# into nothing, and link one copy of the implementation
# ($(EX_DIR)/obj/shadowkit.o): 8 compiles of 13,000 header lines become 1.
# The testbed's variables (TESTBED_CFLAGS, TESTBED_LIB, TESTBED_LIBS) come
# from mk/testbed.mk, which is read after this file: prerequisites naming them
# are written $$(...) and expanded in the second phase (.SECONDEXPANSION).
.SECONDEXPANSION:

EX_DIR   := $(BUILD)/examples
EX_NAMES := 01_hard_shadows 02_cascades 03_warping 04_adaptive 05_point_light 06_soft_shadows 07_engine_casters \
            08_spot_lights
EX_BINS  := $(addprefix $(EX_DIR)/,$(EX_NAMES))
EX_OBJS  := $(addprefix $(EX_DIR)/obj/,$(addsuffix .o,$(EX_NAMES)))
EX_HDRS  := shadowkit.h shadowkit_gl.h examples/common.h
# recursive (=): pkg-config runs when a recipe needs it, after deps-examples
# has installed libglfw3-dev
EX_GLFW_CFLAGS = $(shell pkg-config --cflags glfw3)
EX_GLFW_LIBS   = $(shell pkg-config --libs glfw3)
EX_CC          = $(CC) -std=c99 $(OPT) $(WARN) $(TESTBED_CFLAGS) -Iexamples

.PHONY: examples examples-demo deps-examples

examples: $(EX_BINS)

deps-examples:
	@bash scripts/deps.sh examples

$(EX_DIR)/obj/common.o: examples/common.c $(EX_HDRS) | deps-examples
	$(MKDIR)
	$(EX_CC) $(EX_GLFW_CFLAGS) $(DEPFLAGS) -c $< -o $@

$(EX_DIR)/obj/shadowkit.o: tests/gl/shared_impl_gl.c shadowkit.h shadowkit_gl.h | deps-examples
	$(MKDIR)
	$(EX_CC) $(DEPFLAGS) -c $< -o $@

$(EX_OBJS): $(EX_DIR)/obj/%.o: examples/%.c $(EX_HDRS) tests/shared_impl.h | deps-examples
	$(MKDIR)
	$(EX_CC) -include tests/shared_impl.h -DSK_TEST_SHARED_IMPL_GL $(DEPFLAGS) -c $< -o $@

$(EX_BINS): $(EX_DIR)/%: $(EX_DIR)/obj/%.o $(EX_DIR)/obj/common.o $(EX_DIR)/obj/shadowkit.o $$(TESTBED_LIB) \
            | deps-examples
	$(MKDIR)
	$(CC) $< $(EX_DIR)/obj/common.o $(EX_DIR)/obj/shadowkit.o -o $@ $(TESTBED_LIB) $(TESTBED_LIBS) $(EX_GLFW_LIBS) \
	    $(LDLIBS)

# the headless renders; run from the repository root (paths are relative)
examples-demo: $(EX_BINS)
	@mkdir -p $(OUT)
	./$(EX_DIR)/01_hard_shadows --headless --out $(OUT)/01_hard_shadows.png
	./$(EX_DIR)/02_cascades --headless --out $(OUT)/02_cascades.png
	./$(EX_DIR)/02_cascades --headless --show-cascades --out $(OUT)/02_cascades-show.png
	./$(EX_DIR)/03_warping --headless --technique lispsm --out $(OUT)/03_warping-lispsm.png
	./$(EX_DIR)/03_warping --headless --technique psm --out $(OUT)/03_warping-psm.png
	./$(EX_DIR)/03_warping --headless --technique standard --out $(OUT)/03_warping-standard.png
	./$(EX_DIR)/04_adaptive --headless --technique ferko --out $(OUT)/04_adaptive-ferko.png
	./$(EX_DIR)/04_adaptive --headless --technique lspsm --out $(OUT)/04_adaptive-lspsm.png
	./$(EX_DIR)/04_adaptive --headless --technique rmsm --out $(OUT)/04_adaptive-rmsm.png
	./$(EX_DIR)/05_point_light --headless --technique cube --out $(OUT)/05_point_light-cube.png
	./$(EX_DIR)/06_soft_shadows --headless --technique pvsm --out $(OUT)/06_soft_shadows-pvsm.png
	./$(EX_DIR)/06_soft_shadows --headless --technique pcss --out $(OUT)/06_soft_shadows-pcss.png
	./$(EX_DIR)/06_soft_shadows --headless --technique tiles --out $(OUT)/06_soft_shadows-tiles.png
	./$(EX_DIR)/05_point_light --headless --technique vsdct --out $(OUT)/05_point_light-vsdct.png
	./$(EX_DIR)/07_engine_casters --headless --out $(OUT)/07_engine_casters.png
	./$(EX_DIR)/08_spot_lights --headless --out $(OUT)/08_spot_lights.png
	@echo "examples: images in $(OUT)/: 01_hard_shadows.png 02_cascades.png 02_cascades-show.png 03_warping-{lispsm,psm,standard}.png 04_adaptive-{ferko,lspsm,rmsm}.png 05_point_light-{cube,vsdct}.png 06_soft_shadows-{pvsm,pcss,tiles}.png 07_engine_casters.png 08_spot_lights.png"

DEMO_TARGETS += examples-demo
