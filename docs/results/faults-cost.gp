# Drawn by prt experiment; run `gnuplot faults-cost.gp` in this directory to redraw.
set terminal pngcairo noenhanced size 960,600 font "sans,11"
set output "faults-cost.png"
set title "Simulated cost of failures for adaptive: job time over the same job without failures"
set xlabel "lease (--worker-timeout), s"
set ylabel "extra job time, %"
set grid ytics
set key outside right top
set datafile missing "NaN"
set logscale x 2
set yrange [*:*]
$d0 << EOD
1 0.138204107
2 0.0836641673
5 0.222915475
15 0.155568376
60 0.240499208
180 0.150746524
EOD
$d1 << EOD
1 1.61303046
2 1.47518306
5 1.58159686
15 1.54534431
60 1.56294717
180 5.25023756
EOD
$d2 << EOD
1 17.2115628
2 16.6940235
5 16.6787762
15 16.8858643
60 17.6578957
180 22.4682134
EOD
plot $d0 using 1:2 with linespoints linewidth 2 pointtype 5 linecolor rgb "#1f77b4" title "MTBF 100 h", \
    $d1 using 1:2 with linespoints linewidth 2 pointtype 7 linecolor rgb "#d62728" title "MTBF 10 h", \
    $d2 using 1:2 with linespoints linewidth 2 pointtype 9 linecolor rgb "#2ca02c" title "MTBF 1 h"
