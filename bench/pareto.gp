# bench/pareto.gp - one speed-vs-accuracy chart of the shadowkit bench.
# bench/bench.c writes, per scene, OUT/bench-data/<scene>.vars.gp (the
# variables below), <scene>.<method>.dat (shadow_ms, error, params per
# configuration: means over the views) and <scene>.front.dat (the Pareto
# front: shadow_ms, error, label), then runs:
#     gnuplot OUT/bench-data/<scene>.vars.gp bench/pareto.gp
# Variables: scene, device, timing (how to read the times: relative on a
# CPU rasteriser, absolute on a GPU), database (path prefix of the .dat files),
# outfile, methods (space-separated), nviews, repeat, logy, width, height,
# tmin, tmax, emin, emax, soft (1: area-light rows), floor (the mean
# error of the floor rows, an over-resolved map per view; -1: none),
# floor_texel (their mean share of texels over 1 px; -1: none), floor_what
# (which over-resolved map the floor rows used), has_auto (1: the
# chart has SKGL_AUTO rows: drawn as large black stars, labelled from
# <scene>.autolab.dat with their time over the front's at their error).
# The error (y) is bench.csv's shadow_area_pct on hard-shadow charts: wrong
# pixels as a % of the reference's shadow pixels, which the lit majority of
# the frame does not dilute (it can exceed 100); on soft charts
# (soft = 1) its penumbra_mae: the mean absolute visibility error inside the
# reference's penumbra grown by 2 px, against the whole frame's shadow time.
# The floor is drawn as a horizontal line: the error that remains with a
# map finer than the view needs, the limit every method is measured
# against. A front label's [n%] is the share of shaded pixels whose shadow
# texel spans more than one pixel (Ferko 2013's measure; bench-limit.txt
# has every configuration's).

set terminal pngcairo size 1280,940 noenhanced font 'DejaVu Sans,12'
set output outfile
set encoding utf8

set title sprintf("shadowkit bench, scene %s: shadow-area error against shadow-map time\n%dx%d, each point the mean of %d view(s); GPU time the median of %d renders; GL renderer: %s", \
                  scene, width, height, nviews, repeat, device) font 'DejaVu Sans,13'
if (!exists("timing")) { timing = "GL timer queries" }
set xlabel sprintf("shadow time per frame: depth passes + analysis (ms, %s; log scale)", timing)
set ylabel "shadow-area error (% of the reference's shadow pixels misclassified)"
if (exists("soft") && soft) {
    set title sprintf("shadowkit bench, scene %s: penumbra error against shadow time\n%dx%d, three light sizes, each point the mean of %d view(s); GPU time the median of %d renders; GL renderer: %s", \
                      scene, width, height, nviews, repeat, device) font 'DejaVu Sans,13'
    set xlabel sprintf("shadow time per frame: every pass but the G-buffer (ms, %s; log scale)", timing)
    set ylabel "penumbra MAE (mean |visibility error| in the reference's penumbra grown 2 px)"
}
set logscale x
set format x "%g"
set format y "%g"
# labelled ticks at 1-2-5 steps on log axes
set xtics add (0.01, 0.02, 0.05, 0.1, 0.2, 0.5, 1, 2, 5, 10, 20, 50, 100, 200, 500, 1000, 2000, 5000)
if (logy) {
    set logscale y
    set ylabel "shadow-area error (% of the reference's shadow pixels misclassified; log scale)"
    if (exists("soft") && soft) { set ylabel "penumbra MAE (mean |visibility error| in the penumbra grown 2 px; log scale)" }
    set ytics add (0.0001, 0.0002, 0.0005, 0.001, 0.002, 0.005, 0.01, 0.02, 0.05, 0.1, 0.2, 0.5, 1, 2, 5, 10, 20, 50, 100, 200, 500)
}
set grid xtics ytics mxtics mytics lc rgb '#e0e0e0' lw 1, lc rgb '#f0f0f0' lw 1
set border lw 1.2
set key outside below center horizontal box samplen 3 maxrows 3
set xrange [tmin / 2.2 : tmax * 1.6]
if (logy) { set yrange [emin / 1.4 : emax * 1.3] } else { set yrange [0 : emax * 1.1] }

# Front labels go below-left of their point: no run lies there (else the
# point would not be on the front). bench.c leaves a label empty where it
# would crowd the previous one.
# one colour and point type per method, in the order given
array colours[12] = ['#1f77b4', '#ff7f0e', '#2ca02c', '#d62728', '#9467bd', '#8c564b', \
                     '#e377c2', '#7f7f7f', '#bcbd22', '#17becf', '#393b79', '#ad494a']
array shapes[12] = [7, 5, 9, 11, 13, 15, 7, 5, 9, 11, 13, 15]
nm = words(methods)
if (!exists("floor")) { floor = -1 }
set label 92 "Pareto front: no other run is both faster and more accurate" \
    at graph 0.99, graph 0.97 right font 'DejaVu Sans,10' tc rgb '#333333' front
if (!soft) {
    set label 91 "front labels [n%]: shaded pixels whose shadow texel spans more than 1 pixel" \
        at graph 0.99, graph 0.93 right font 'DejaVu Sans,10' tc rgb '#333333' front
}
if (floor >= 0) {
    set arrow 90 from graph 0, first floor to graph 1, first floor nohead lw 2 dt 4 lc rgb '#b00000' front
    if (!exists("floor_texel")) { floor_texel = -1 }
    if (!exists("floor_what")) { floor_what = "the finer of RMSM 65536^2 and a 16384^2 map per view" }
    set label 90 (floor_texel >= 0 ? sprintf("floor %.3g%%: %s (texel > 1 px on %.0f%%)", floor, floor_what, floor_texel) \
                                   : sprintf("floor %.3g%%: %s", floor, floor_what)) \
        at graph 0.01, first floor offset 0,0.7 left font 'DejaVu Sans,10' tc rgb '#b00000' front
}

frontfile = database . '.front.dat'
if (!exists("has_auto")) { has_auto = 0 }
# AUTO: a large black star; without AUTO rows the label file is the front's
# (whose third column the labels below already draw) drawn with no labels
autofile = has_auto ? database . '.autolab.dat' : frontfile
is_auto(i) = word(methods, i) eq 'auto'
plot for [i = 1:nm] sprintf('%s.%s.dat', database, word(methods, i)) using 1:2 \
         with points pt (is_auto(i) ? 3 : shapes[(i - 1) % 12 + 1]) ps (is_auto(i) ? 3.2 : 1.4) \
         lw (is_auto(i) ? 2.5 : 1) lc rgb (is_auto(i) ? '#000000' : colours[(i - 1) % 12 + 1]) \
         title (is_auto(i) ? 'AUTO' : word(methods, i)), \
     autofile using 1:2:(has_auto ? stringcolumn(3) : "") with labels left offset 1.6,0.6 \
         font 'DejaVu Sans Bold,10' tc rgb '#000000' notitle, \
     frontfile using 1:2 with steps lw 2 lc rgb '#333333' dt 2 title 'Pareto front', \
     frontfile using 1:2 with points pt 6 ps 2.6 lw 1.5 lc rgb '#333333' notitle, \
     frontfile using 1:2:3 with labels right offset -1.3,-0.9 font 'DejaVu Sans,9' tc rgb '#333333' notitle
