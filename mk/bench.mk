# mk/bench.mk - the speed-vs-accuracy bench (bench/bench.c; included by the Makefile).
#   make bench        full sweep of every shadowkit_gl.h method (210 configurations,
#                     SKGL_AUTO and the fit_to_depth rows among them; 8 scenes, the forest
#                     among them; 3 views, plus the LSPSM walk and the floor; about 20 minutes
#                     on 2 cores under llvmpipe before AUTO and the forest): out/bench.csv,
#                     out/bench-walk.{csv,txt}, out/pareto-<scene>.png (gnuplot,
#                     bench/pareto.gp) and out/bench-auto.txt (AUTO against the front)
#   make bench-demo   the quick sweep (40 configurations; about 3 minutes before AUTO and
#                     the forest) for `make demo`
#   make bench-plot   redraw the charts from an existing out/bench.csv (one written
#                     by this bench: an older CSV without the texel and band columns
#                     is refused)
# Both sweeps write the same files: the last one run is what out/ holds.
# The point-light scenes run after the directional ones: "room" (one light),
# "room-spot" and "interior" (six point lights shadowed every frame, 3 views,
# about 5 minutes on 2 cores under llvmpipe, bench-demo 1 view;
# out/pareto-interior.png;
# make bench BENCH_ARGS="--only interior" runs it alone).
# bench.csv: DESIGN.md's 14 columns, then (appended) the hard-shadow scores
# shadow_area_pct,false_shadow_pct,false_light_pct,edge_mean_px,edge_p95_px,
# covered_pct, the soft ones penumbra_mae,penumbra_max,umbra_mae,lit_mae,
# excluded_px, the texel-to-pixel figure texel_over{1,2,4}_pct,texel_median_px
# and the shadow-area error by view-depth band area_{0_10,10_50,50_200,200}_pct;
# the header comment of bench/bench.c defines each. The charts plot
# shadow_area_pct (soft charts: penumbra_mae) against shadow time, and the
# floor (method "floor": an over-resolved map per view) as a line;
# out/bench-limit.txt and out/bench-bands.txt are their companion tables.
# Extra arguments: make bench BENCH_ARGS="--only fence,terrace --repeat 5"
# The shared scenes are read from ../shared/scenes when it exists (else
# procedural scenes only, said on stderr). SK_GL=osmesa|egl picks the GL backend.
# The testbed's variables come from mk/testbed.mk, read after this file:
# prerequisites naming them are expanded in the second phase.
.SECONDEXPANSION:

BENCH_BIN  := $(BUILD)/bench/bench
BENCH_ARGS ?=
# Both benches are built from objects: their own, the shared code
# (bench/bench_common.c: scenes, views, GL context, reference, output
# helpers; bench/bench_texel.c: the texel-to-pixel figure) and shadowkit's
# implementation compiled once (the GL tests' build/obj/gl/shared_impl_gl.o,
# mk/testbed.mk).
BENCH_OBJ    := $(BUILD)/bench/obj
BENCH_HDRS   := shadowkit.h shadowkit_gl.h bench/bench_common.h bench/bench_texel.h
BENCH_SHARED := $(BENCH_OBJ)/bench_common.o $(BENCH_OBJ)/bench_texel.o $(BUILD)/obj/gl/shared_impl_gl.o

$(BENCH_OBJ)/%.o: bench/%.c $(BENCH_HDRS) | deps-gl
	$(MKDIR)
	$(CC) -std=c99 $(OPT) $(WARN) $(TESTBED_CFLAGS) -Ibench $(DEPFLAGS) -c $< -o $@

$(BENCH_BIN): $(BENCH_OBJ)/bench.o $(BENCH_SHARED) $$(TESTBED_LIB) | deps-gl
	$(MKDIR)
	$(CC) $(BENCH_OBJ)/bench.o $(BENCH_SHARED) -o $@ $(TESTBED_LIB) $(TESTBED_LIBS) $(LDLIBS)

.PHONY: bench bench-demo bench-plot
# deps-demo brings gnuplot (scripts/deps.sh demo)
bench: $(BENCH_BIN) | deps-demo
	@mkdir -p $(OUT)
	./$(BENCH_BIN) --out $(OUT) $(BENCH_ARGS)
	@echo "bench: $(OUT)/bench.csv and the charts $(OUT)/pareto-*.png"
	@$(MAKE) --no-print-directory bench-cache

bench-demo: $(BENCH_BIN) | deps-demo
	@mkdir -p $(OUT)
	./$(BENCH_BIN) --quick --out $(OUT) $(BENCH_ARGS)
	@echo "bench-demo: $(OUT)/bench.csv and the charts $(OUT)/pareto-*.png"

bench-plot: $(BENCH_BIN) | deps-demo
	./$(BENCH_BIN) --plot-only --out $(OUT) $(BENCH_ARGS)

DEMO_TARGETS += bench-demo

# ------------------------------------------------- cached maps (bench_cache.c)
#   make bench-cache       cached (desc.cache = 1) against uncached shadow maps
#                          along a 60-frame camera walk, with and without a
#                          moving caster: PSSM-4 stable, the stable focused map
#                          and a cube point light, every bench scene (the
#                          shared ones when ../shared/scenes exists);
#                          out/bench-cache.{csv,txt}, out/bench-cache-<scene>.png
#                          (gnuplot, bench/cache.gp); about 7 minutes on 2
#                          cores under llvmpipe. Part of `make bench` (run
#                          after the sweep), not of `make test`.
#   make bench-cache-demo  the quick run (procedural scenes, 20 frames; about
#                          1 minute) for `make demo`
# Extra arguments: make bench-cache BENCH_CACHE_ARGS="--only fence --frames 30"
BENCH_CACHE_BIN  := $(BUILD)/bench/bench_cache
BENCH_CACHE_ARGS ?=

$(BENCH_CACHE_BIN): $(BENCH_OBJ)/bench_cache.o $(BENCH_SHARED) $$(TESTBED_LIB) | deps-gl
	$(MKDIR)
	$(CC) $(BENCH_OBJ)/bench_cache.o $(BENCH_SHARED) -o $@ $(TESTBED_LIB) $(TESTBED_LIBS) $(LDLIBS)

.PHONY: bench-cache bench-cache-demo
bench-cache: $(BENCH_CACHE_BIN) | deps-demo
	@mkdir -p $(OUT)
	./$(BENCH_CACHE_BIN) --out $(OUT) $(BENCH_CACHE_ARGS)
	@echo "bench-cache: $(OUT)/bench-cache.csv, $(OUT)/bench-cache.txt and the charts $(OUT)/bench-cache-*.png"

bench-cache-demo: $(BENCH_CACHE_BIN) | deps-demo
	@mkdir -p $(OUT)
	./$(BENCH_CACHE_BIN) --quick --out $(OUT) $(BENCH_CACHE_ARGS)
	@echo "bench-cache-demo: $(OUT)/bench-cache.csv, $(OUT)/bench-cache.txt and the charts $(OUT)/bench-cache-*.png"

# `make bench` runs bench-cache as its last step (after the sweep, so that
# the two never share the CPU under make -j)
DEMO_TARGETS += bench-cache-demo
