# Drawn by prt experiment; run `gnuplot initial-percent-speedup.gp` in this directory to redraw.
set terminal pngcairo noenhanced size 960,600 font "sans,11"
set output "initial-percent-speedup.png"
set title "Fig. 18: speed-up against the initial percentage (case C, 4 workers)"
set xlabel "initial percentage"
set ylabel "speed-up (serial time / parallel time)"
set grid ytics
set key outside right top
set datafile missing "NaN"
set yrange [0:*]
set arrow from graph 0, first 1.5 to graph 1, first 1.5 nohead dashtype 2 linecolor rgb "#555555"
set label "emulated MASU 1.50" at graph 0.01, first 1.5 offset 0,0.6 textcolor rgb "#555555"
$d0 << EOD
20 1.10630576
80 0.567361184
100 0.5741583
EOD
$d1 << EOD
20 1.01438966
80 0.833551552
100 0.718445482
EOD
$d2 << EOD
20 0.709122157
80 0.592453166
100 0.666325399
EOD
$d3 << EOD
20 1.31919256
80 1.33083997
100 1.30977077
EOD
plot $d0 using 1:2 with linespoints linewidth 2 pointtype 5 linecolor rgb "#1f77b4" title "reservoir (real)", \
    $d1 using 1:2 with linespoints linewidth 2 pointtype 7 linecolor rgb "#d62728" dashtype 2 title "reservoir (simulated)", \
    $d2 using 1:2 with linespoints linewidth 2 pointtype 9 linecolor rgb "#2ca02c" title "reservoir-scatter (real)", \
    $d3 using 1:2 with linespoints linewidth 2 pointtype 11 linecolor rgb "#9467bd" dashtype 2 title "reservoir-scatter (simulated)"
