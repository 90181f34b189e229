# bench/plots.gp - the README plots from bench/report.py's data files.
# Run from the repository root after `make bench` (it does this itself):
#   gnuplot bench/plots.gp      -> bench/out/{ns_per_call,speed_vs_error,media_efficiency,batch_vs_scalar,latency_ratio}.png
load 'bench/out/plot_vars.gp'
set terminal pngcairo noenhanced size 1600,700 font "sans,8"
set datafile missing "NaN"
set grid ytics mytics lc rgb "#dddddd"

# (a) ns per call of every public function, per build
set output 'bench/out/ns_per_call.png'
set title "appear.h: ns per call of every public eval / pdf / sample (lower is better; one run on a shared 2-core Xeon)"
set style data histograms
set style histogram clustered gap 1
set style fill solid 0.9 noborder
set logscale y
set ylabel "ns per call (log)"
set xtics rotate by 60 right font ",6.5" nomirror
set key top left
set xrange [-1:n_a]
set yrange [0.5:5000]
plot for [c=3:2+n_builds] 'bench/out/plot_ns.dat' using c:xtic(2) title word(builds, c-2)
unset xrange
unset yrange

# (b) speed against error: each approximation and its reference
set terminal pngcairo noenhanced size 1000,700 font "sans,9"
set output 'bench/out/speed_vs_error.png'
set title sprintf("Speed against error (gcc %s): filled = appear.h, open = libm / textbook / plain baseline", fast)
set style data points
unset style
set logscale xy
set xlabel "ns per call (log)"
set ylabel "max error vs double (log; 1e-9 = exact or reference)"
set xtics auto norotate font ",9"
set format y "1e%T"
set key off
set xrange [0.8:1e5]
set yrange [5e-10:3]
plot 'bench/out/plot_err.dat' using 1:($3 == 0 ? $2 : 1/0) with points pt 7 ps 1.3 lc rgb "#1f77b4", \
     '' using 1:($3 == 1 ? $2 : 1/0) with points pt 6 ps 1.3 lc rgb "#d62728", \
     '' using 1:2:4 with labels offset char 0.8,0.5 left font ",7" tc rgb "#333333"
set format y "% h"
unset xlabel
unset xrange
unset yrange

# (c) media: relative efficiency of the transmittance estimators against majorant tightness
set terminal pngcairo noenhanced size 1200,700 font "sans,8"
set output 'bench/out/media_efficiency.png'
set multiplot layout 2,3 title "Transmittance estimators: 1/(MSE x lookups) relative to ratio tracking vs majorant tightness (max sigma / majorant); clipped at 1e4 (exact cases)"
set logscale xy
set xrange [0.007:1.4]
set yrange [1e-3:1e4]
set xlabel "tightness"
set ylabel "relative efficiency (log)"
set format y "1e%T"
set key bottom left font ",6.5" samplen 2 spacing 0.9
do for [p=0:n_prof-1] {
    set title word(profs, p+1)
    if (p == 0) { set key } else { unset key }
    plot for [e=0:n_est-1] 'bench/out/plot_media.dat' index (p*n_est+e) using 1:2 with linespoints pt (e%7)+1 lw 1.5 title word(ests, e+1)
}
unset multiplot
unset xrange
unset yrange
set format y "% h"

# (d) batch (SoA) vs scalar loop, ns per element, per build
set terminal pngcairo noenhanced size 1200,560 font "sans,8"
set output 'bench/out/batch_vs_scalar.png'
set title "Batch (structure of arrays) vs a loop over the scalar function: ns per element"
set style data histograms
set style histogram clustered gap 1
set style fill solid 0.9 noborder
set logscale y
unset logscale x
unset xlabel
set ylabel "ns per element (log)"
set xtics rotate by 30 right font ",8"
set key top left
colors = "#9ecae1 #08519c #fdae6b #a63603 #a1d99b #006d2c"
plot for [c=2:1+2*n_builds] 'bench/out/plot_batch.dat' using c:xtic(1) \
     title (c % 2 == 0 ? "scalar " : "batch ").word(builds, (c-2)/2+1) lc rgb word(colors, c-1)

# (e) multiple scattering between microfacets: time against white-furnace error
#     (bench/bench_multiscatter.c writes bench/out/ms_tradeoff_<build>.dat)
set terminal pngcairo noenhanced size 1300,600 font "sans,9"
set output 'bench/out/ms_tradeoff.png'
unset style
set style data points
set multiplot layout 1,2 title sprintf("Multiple scattering (conductor, F = 1; gcc %s): time against max_mu |furnace albedo - 1|; circles GGX, squares Beckmann, labels = alpha", fast)
set logscale xy
set xrange [1:30000]
set yrange [5e-7:1]
set format y "1e%T"
set ylabel "max |E - 1| (log; exact 0 drawn at 1e-6)"
set xtics auto norotate font ",9"
set key at graph 0.03, graph 0.55 left font ",9" box opaque
msdat = 'bench/out/ms_tradeoff_'.fast.'.dat'
vcol(v) = v eq "single_scattering" ? "#d62728" : (v eq "compensated" ? "#1f77b4" : "#2ca02c")
vt(v) = v eq "single_scattering" ? "single scattering" : (v eq "random_walk" ? "random walk" : v)
do for [pan=0:1] {
    set title (pan == 0 ? "eval" : "sample")
    set xlabel (pan == 0 ? "ns per eval (log; random walk: one estimate = two walks)" : "ns per sample (log)")
    plot for [v in "single_scattering compensated random_walk"] for [ty in "ggx beckmann"] msdat \
           using (column(4+pan)):((strcol(1) eq ty && strcol(3) eq v) ? ($6 > 1e-6 ? $6 : 1e-6) : 1/0) \
           with points pt (ty eq "ggx" ? 7 : 5) ps 1.4 lc rgb vcol(v) title (ty eq "ggx" ? vt(v) : ""), \
         msdat using (column(4+pan)):($6 > 1e-6 ? $6 : 1e-6):(sprintf("%g", $2)) with labels offset char 0.9,0.4 left font ",7" tc rgb "#333333" notitle
}
unset multiplot

# (f) latency: appear / baseline per function and build (points; < 1: appear is faster)
if (n_lat > 0) {
    reset
    set terminal pngcairo noenhanced size 1000,1300 font "sans,8"
    set output 'bench/out/latency_ratio.png'
    set datafile missing "NaN"
    set title "Latency (dependent chain, noinline): appear.h / the peers' own functions transcribed (pbrt-v4, Mitsuba 3, Mitsuba 0.6) (median of paired runs; < 1 = appear faster)"
    set grid xtics lc rgb "#dddddd"
    set logscale x 2
    set xrange [0.1:8]
    set yrange [n_lat:-1]
    set ytics font ",7" nomirror
    set xlabel "ratio appear / baseline (log)"
    set key bottom right
    set arrow from 1, graph 0 to 1, graph 1 nohead lc rgb "#cc0000" lw 1.5
    plot for [c=3:5] 'bench/out/plot_latency.dat' using c:1:ytic(2) with points pt (c == 3 ? 7 : c == 4 ? 5 : 9) ps 1.2 \
         title word("O2 O3native clang_O3native", c-2)
}
