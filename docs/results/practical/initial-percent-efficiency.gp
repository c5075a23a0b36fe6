# Drawn by prt experiment; run `gnuplot initial-percent-efficiency.gp` in this directory to redraw.
set terminal pngcairo noenhanced size 960,600 font "sans,11"
set output "initial-percent-efficiency.png"
set title "Fig. 18: efficiency against the initial percentage (case C, 4 workers)"
set xlabel "initial percentage"
set ylabel "efficiency, %"
set grid ytics
set key outside right top
set datafile missing "NaN"
set yrange [0:100]
$d0 << EOD
20 70.2050069
80 58.026893
100 52.9364515
EOD
$d1 << EOD
20 64.8944827
80 57.0036619
100 44.718962
EOD
$d2 << EOD
20 93.2108972
80 87.1202088
100 74.6588211
EOD
$d3 << EOD
20 88.1053734
80 88.8045206
100 86.3772526
EOD
plot $d0 using 1:2 with linespoints linewidth 2 pointtype 5 linecolor rgb "#1f77b4" title "reservoir (real)", \
    $d1 using 1:2 with linespoints linewidth 2 pointtype 7 linecolor rgb "#d62728" dashtype 2 title "reservoir (simulated)", \
    $d2 using 1:2 with linespoints linewidth 2 pointtype 9 linecolor rgb "#2ca02c" title "reservoir-scatter (real)", \
    $d3 using 1:2 with linespoints linewidth 2 pointtype 11 linecolor rgb "#9467bd" dashtype 2 title "reservoir-scatter (simulated)"
