# Drawn by prt experiment; run `gnuplot faults-time-mtbf-none.gp` in this directory to redraw.
set terminal pngcairo noenhanced size 960,600 font "sans,11"
set output "faults-time-mtbf-none.png"
set title "Simulated job time against the lease, MTBF none, 1024 workers"
set xlabel "lease (--worker-timeout), s"
set ylabel "job time, min"
set grid ytics
set key outside right top
set datafile missing "NaN"
set logscale x 2
set yrange [0:*]
$d0 << EOD
1 60.5603029
2 60.6028535
5 60.5297297
15 60.5608174
60 60.5608174
180 60.5608174
EOD
$d1 << EOD
1 60.4540332
2 60.4571822
5 60.4910327
15 60.4569322
60 60.4569322
180 60.4569322
EOD
$d2 << EOD
1 101.291116
2 101.489891
5 101.924228
15 104.321071
60 101.260793
180 101.260793
EOD
$d3 << EOD
1 65.9424856
2 65.9424856
5 65.9424856
15 65.9424856
60 65.9424856
180 65.9424856
EOD
$d4 << EOD
1 60
2 60
5 60
15 60
60 60
180 60
EOD
plot $d0 using 1:2 with linespoints linewidth 2 pointtype 5 linecolor rgb "#1f77b4" title "adaptive", \
    $d1 using 1:2 with linespoints linewidth 2 pointtype 7 linecolor rgb "#d62728" title "reservoir-scatter", \
    $d2 using 1:2 with linespoints linewidth 2 pointtype 9 linecolor rgb "#2ca02c" title "hybrid", \
    $d3 using 1:2 with linespoints linewidth 2 pointtype 11 linecolor rgb "#9467bd" title "stealing", \
    $d4 using 1:2 with linespoints linewidth 2 pointtype 5 linecolor rgb "#ff7f0e" dashtype 2 title "ideal"
