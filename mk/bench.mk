# mk/bench.mk - the speed-vs-accuracy bench (bench/bench.c; included by the Makefile).
#   make bench        full sweep of every shadowkit_gl.h method (184 configurations,
#                     6 scenes, 3 views, plus the LSPSM walk; about 20 minutes on
#                     2 cores under llvmpipe): out/bench.csv, out/bench-walk.{csv,txt}
#                     and out/pareto-<scene>.png (gnuplot, bench/pareto.gp)
#   make bench-demo   the quick sweep (33 configurations; about 3 minutes) for `make demo`
#   make bench-plot   redraw the charts from an existing out/bench.csv (one written
#                     by this bench: an older CSV without shadow_area_pct is refused)
# Both sweeps write the same files: the last one run is what out/ holds.
# bench.csv: DESIGN.md's 14 columns, then (appended) the hard-shadow scores
# shadow_area_pct,false_shadow_pct,false_light_pct,edge_mean_px,edge_p95_px,
# covered_pct, the soft ones penumbra_mae,penumbra_max,umbra_mae,lit_mae and
# excluded_px; the header comment of bench/bench.c defines each. The charts
# plot shadow_area_pct (soft charts: penumbra_mae) against shadow time.
# Extra arguments: make bench BENCH_ARGS="--only fence,terrace --repeat 5"
# The shared scenes are read from ../shared/scenes when it exists (else
# procedural scenes only, said on stderr). SK_GL=osmesa|egl picks the GL backend.
# The testbed's variables come from mk/testbed.mk, read after this file:
# prerequisites naming them are expanded in the second phase.
.SECONDEXPANSION:

BENCH_BIN  := $(BUILD)/bench/bench
BENCH_ARGS ?=

$(BENCH_BIN): bench/bench.c shadowkit.h shadowkit_gl.h $$(TESTBED_LIB) | deps-gl
	$(MKDIR)
	$(CC) -std=c99 $(OPT) $(WARN) $(TESTBED_CFLAGS) $(DEPFLAGS) $< -o $@ $(TESTBED_LIB) $(TESTBED_LIBS) $(LDLIBS)

.PHONY: bench bench-demo bench-plot
# deps-demo brings gnuplot (scripts/deps.sh demo)
bench: $(BENCH_BIN) | deps-demo
	@mkdir -p $(OUT)
	./$(BENCH_BIN) --out $(OUT) $(BENCH_ARGS)
	@echo "bench: $(OUT)/bench.csv and the charts $(OUT)/pareto-*.png"

bench-demo: $(BENCH_BIN) | deps-demo
	@mkdir -p $(OUT)
	./$(BENCH_BIN) --quick --out $(OUT) $(BENCH_ARGS)
	@echo "bench-demo: $(OUT)/bench.csv and the charts $(OUT)/pareto-*.png"

bench-plot: $(BENCH_BIN) | deps-demo
	./$(BENCH_BIN) --plot-only --out $(OUT) $(BENCH_ARGS)

DEMO_TARGETS += bench-demo
