# Drawn by prt experiment; run `gnuplot faults-time-mtbf-1h.gp` in this directory to redraw.
set terminal pngcairo noenhanced size 960,600 font "sans,11"
set output "faults-time-mtbf-1h.png"
set title "Simulated job time against the lease, MTBF 1 h, 1024 workers"
set xlabel "lease (--worker-timeout), s"
set ylabel "job time, min"
set grid ytics
set key outside right top
set datafile missing "NaN"
set logscale x 2
set yrange [0:*]
$d0 << EOD
1 70.9836775
2 70.7199081
5 70.6253478
15 70.7870349
60 71.2545834
180 74.1677511
EOD
$d1 << EOD
1 70.3052721
2 70.2899965
5 70.2932588
15 70.3061068
60 70.9058077
180 74.6310784
EOD
$d2 << EOD
1 111.072855
2 112.816688
5 113.087282
15 112.22603
60 114.008608
180 115.258772
EOD
$d3 << EOD
1 78.2648491
2 78.9856317
5 79.3380769
15 78.4351564
60 79.2469042
180 80.2649688
EOD
$d4 << EOD
1 69.283441
2 69.2851897
5 69.291483
15 69.3103932
60 69.3878266
180 69.5854924
EOD
plot $d0 using 1:2 with linespoints linewidth 2 pointtype 5 linecolor rgb "#1f77b4" title "adaptive", \
    $d1 using 1:2 with linespoints linewidth 2 pointtype 7 linecolor rgb "#d62728" title "reservoir-scatter", \
    $d2 using 1:2 with linespoints linewidth 2 pointtype 9 linecolor rgb "#2ca02c" title "hybrid", \
    $d3 using 1:2 with linespoints linewidth 2 pointtype 11 linecolor rgb "#9467bd" title "stealing", \
    $d4 using 1:2 with linespoints linewidth 2 pointtype 5 linecolor rgb "#ff7f0e" dashtype 2 title "ideal"
