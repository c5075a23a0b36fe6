# Drawn by prt experiment; run `gnuplot faults-time-mtbf-100h.gp` in this directory to redraw.
set terminal pngcairo noenhanced size 960,600 font "sans,11"
set output "faults-time-mtbf-100h.png"
set title "Simulated job time against the lease, MTBF 100 h, 1024 workers"
set xlabel "lease (--worker-timeout), s"
set ylabel "job time, min"
set grid ytics
set key outside right top
set datafile missing "NaN"
set logscale x 2
set yrange [0:*]
$d0 << EOD
1 60.6439997
2 60.6535563
5 60.6646598
15 60.6550309
60 60.7064657
180 60.6521108
EOD
$d1 << EOD
1 60.5785534
2 60.5346128
5 60.5655204
15 60.5541712
60 60.5766679
180 60.5552411
EOD
$d2 << EOD
1 108.893099
2 108.812096
5 109.712993
15 110.947158
60 112.660481
180 111.717738
EOD
$d3 << EOD
1 66.3921286
2 65.9298122
5 65.9298122
15 66.1704011
60 66.055441
180 65.9298122
EOD
$d4 << EOD
1 60.0781375
2 60.0781453
5 60.0781723
15 60.0782827
60 60.0791759
180 60.0796318
EOD
plot $d0 using 1:2 with linespoints linewidth 2 pointtype 5 linecolor rgb "#1f77b4" title "adaptive", \
    $d1 using 1:2 with linespoints linewidth 2 pointtype 7 linecolor rgb "#d62728" title "reservoir-scatter", \
    $d2 using 1:2 with linespoints linewidth 2 pointtype 9 linecolor rgb "#2ca02c" title "hybrid", \
    $d3 using 1:2 with linespoints linewidth 2 pointtype 11 linecolor rgb "#9467bd" title "stealing", \
    $d4 using 1:2 with linespoints linewidth 2 pointtype 5 linecolor rgb "#ff7f0e" dashtype 2 title "ideal"
