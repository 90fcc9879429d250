# workprecision.gp — the work-precision plot of bench_workprecision:
# position error at t_end versus CPU seconds, one panel per scene, one line
# per method (a point per tolerance or step size), plus the energy error of
# the long (1e5-orbit) runs. Called by the benchmark as
#   gnuplot -e "datadir='build/bench-out'; outfile='build/bench-out/workprecision.png'" bench/workprecision.gp
# Input: datadir/wp_<scene>.dat, blocks separated by two blank lines, each
# block's first line names the method (columns: cpu_s pos_err drift steps
# rhs_evals setting); datadir/wp_longrun.dat (orbits drift).
if (!exists("datadir")) datadir = "build/bench-out"
if (!exists("outfile")) outfile = datadir . "/workprecision.png"

set terminal pngcairo size 1800,1100 font "sans,10"
set output outfile
set logscale xy
set format x "10^{%L}"
set format y "10^{%L}"
set grid xtics ytics mxtics mytics lc rgb "#dddddd"
set key outside right top font "sans,8" spacing 0.9 samplen 2
set style data linespoints

# Colours: column 7 (column 3 in wp_longrun.dat) is the method's position
# in the registry (core/integrators/registry.c), 1-based; the SciPy
# baseline comes last, in black. A method has the same colour in every panel.
array C[16] = ["#1f77b4", "#6baed6", "#9ecae1", "#d62728", "#8c564b", "#bbbbbb", \
               "#7f7f7f", "#ff7f0e", "#2ca02c", "#17becf", "#9467bd", "#e377c2", \
               "#bcbd22", "#393b79", "#000000", "#000000"]
do for [k = 1:16] { set linetype k lc rgb C[k] lw 1.5 pt 7 ps 0.6 }

set multiplot layout 2,3 title "mechd work-precision: position error at t_{end} versus CPU seconds (same run, one machine)" font "sans,13"

scenes = "kepler-e0.5 kepler-e0.9 oscillator falling stiff"
array T[5] = ["Kepler e = 0.5, 1000 orbits (+ SciPy DOP853)", "Kepler e = 0.9, 1000 orbits", \
              "harmonic oscillator, 1e5 periods", "falling object, h = 100 m, 32° N (Coriolis)", \
              "stiff overdamped spring, k = 1, b = 1e3"]
do for [s = 1:5] {
    scene = word(scenes, s)
    file = datadir . "/wp_" . scene . ".dat"
    stats file using 1 nooutput
    nb = STATS_blocks
    set title T[s]
    set xlabel "CPU seconds (thread)"
    set ylabel "|q - q_{exact}| / L at t_{end}"
    plot for [b = 0:nb-1] file index b using 1:2:7 title columnheader(1) noenhanced lc variable
}

file = datadir . "/wp_longrun.dat"
stats file using 1 nooutput
nb = STATS_blocks
set title "Kepler e = 0.5, 1e5 orbits: max |ΔE/E| so far"
set xlabel "orbits"
set ylabel "max |ΔE/E|"
plot for [b = 0:nb-1] file index b using 1:2:3 title columnheader(1) noenhanced lc variable

unset multiplot
