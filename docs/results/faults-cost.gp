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
1 1.55980139
2 1.47518306
5 1.64985101
15 1.60444068
60 2.2132065
180 4.56930432
EOD
$d2 << EOD
1 18.8243877
2 18.4219456
5 19.6083728
15 17.7766097
60 18.4919885
180 21.6594704
EOD
plot $d0 using 1:2 with linespoints linewidth 2 pointtype 5 linecolor rgb "#1f77b4" title "MTBF 100 h", \
    $d1 using 1:2 with linespoints linewidth 2 pointtype 7 linecolor rgb "#d62728" title "MTBF 10 h", \
    $d2 using 1:2 with linespoints linewidth 2 pointtype 9 linecolor rgb "#2ca02c" title "MTBF 1 h"
