# bench/cache.gp - one chart of the shadowkit cache bench (bench/bench_cache.c):
# shadow time per frame along the camera walk, cached against uncached.
# bench_cache.c writes, per scene, OUT/bench-cache-data/<scene>.vars.gp (the
# variables below) and <scene>.dat (one block per walk, technique and mode,
# in that nesting: "frame shadow_ms" lines, two blank lines between blocks),
# then runs:
#     gnuplot OUT/bench-cache-data/<scene>.vars.gp bench/cache.gp
# Variables: scene, device, timing (how to read the times), datafile,
# outfile, techniques (space-separated, in the data's order), ntech, nmode
# (2: cached, uncached), frames.
# Block index = (walk * ntech + technique) * nmode + mode: walk 0 static, 1
# moving; mode 0 cached (solid line), 1 uncached (dashed).

set terminal pngcairo size 1280,1100 noenhanced font 'DejaVu Sans,12'
set output outfile
set encoding utf8

array colours[6] = ['#1f77b4', '#d62728', '#2ca02c', '#ff7f0e', '#9467bd', '#8c564b']
modes = "cached uncached"

set logscale y
set format y "%g"
set ytics add (0.1, 0.2, 0.5, 1, 2, 5, 10, 20, 50, 100, 200, 500, 1000)
set grid xtics ytics mytics lc rgb '#e0e0e0' lw 1, lc rgb '#f0f0f0' lw 1
set border lw 1.2
set xrange [-0.5 : frames - 0.5]
set xlabel "frame of the camera walk"
set ylabel "shadow time per frame (ms, log scale)"
set key outside right top vertical box samplen 3

set multiplot layout 2,1 title sprintf("shadowkit cached maps, scene %s: shadow time along the walk, cached (solid) against uncached (dashed)\nGL renderer: %s; times: %s", scene, device, timing) font 'DejaVu Sans,13'

do for [wk = 0:1] {
    set title (wk == 0 ? "static walk: the camera moves, no caster does" \
                       : "moving walk: the same path, one box caster (skgl_set_dynamic) crossing the view")
    # series k: technique k / nmode, mode k % nmode (integer division)
    plot for [k = 0:ntech * nmode - 1] datafile index (wk * ntech * nmode + k) using 1:2 \
         with linespoints lw 1.6 pt (k % nmode == 0 ? 7 : 6) ps 0.6 dt 1 + k % nmode \
         lc rgb colours[k / nmode + 1] title sprintf("%s %s", word(techniques, k / nmode + 1), word(modes, k % nmode + 1))
}
unset multiplot
