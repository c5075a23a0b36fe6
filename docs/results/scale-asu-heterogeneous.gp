# Drawn by prt experiment; run `gnuplot scale-asu-heterogeneous.gp` in this directory to redraw.
set terminal pngcairo noenhanced size 960,600 font "sans,11"
set output "scale-asu-heterogeneous.png"
set title "Simulated heterogeneous workers: ASU against worker count"
set xlabel "workers"
set ylabel "ASU, %"
set grid ytics
set key outside right top
set datafile missing "NaN"
set logscale x 2
set yrange [0:105]
$d0 << EOD
4 40.0375805
8 39.9167921
16 39.6157425
32 39.0068765
64 37.8083734
128 34.4104477
256 27.1464353
512 27.2880137
1024 27.1515408
EOD
$d1 << EOD
4 97.8109636
8 95.771969
16 93.1222277
32 86.6088822
64 73.3495706
128 55.4573099
256 31.35807
512 29.8928287
1024 28.9395788
EOD
$d2 << EOD
4 37.5424394
8 32.6008931
16 33.5226583
32 31.2663318
64 28.109331
128 27.3829108
256 27.1340785
512 14.012102
1024 10.4402407
EOD
$d3 << EOD
4 99.7978705
8 99.9589955
16 99.8743219
32 99.575077
64 99.2125726
128 98.7972811
256 96.9931706
512 92.4824713
1024 84.4638823
EOD
$d4 << EOD
4 19.7593049
8 12.4137593
16 11.021587
32 11.9324903
64 9.83945638
128 10.5775597
256 9.22717311
512 7.70691385
1024 6.81514945
EOD
$d5 << EOD
4 99.9375111
8 99.9154442
16 99.828612
32 99.7053765
64 99.4679223
128 92.092802
256 71.6294749
512 48.6243112
1024 26.2460025
EOD
$d6 << EOD
4 20.6257814
8 19.6511527
16 18.8029276
32 18.4097611
64 17.9123056
128 17.8279349
256 13.6483463
512 13.5079042
1024 7.39520635
EOD
$d7 << EOD
4 83.562878
8 57.3815996
16 54.8242515
32 49.2194404
64 48.369948
128 42.1512963
256 29.7689359
512 16.6239639
1024 14.4940774
EOD
plot $d0 using 1:2 with linespoints linewidth 2 pointtype 5 linecolor rgb "#1f77b4" dashtype 2 title "scatter", \
    $d1 using 1:2 with linespoints linewidth 2 pointtype 7 linecolor rgb "#d62728" title "hybrid", \
    $d2 using 1:2 with linespoints linewidth 2 pointtype 9 linecolor rgb "#2ca02c" title "reservoir", \
    $d3 using 1:2 with linespoints linewidth 2 pointtype 11 linecolor rgb "#9467bd" title "reservoir-scatter", \
    $d4 using 1:2 with linespoints linewidth 2 pointtype 5 linecolor rgb "#ff7f0e" dashtype 2 title "blocks", \
    $d5 using 1:2 with linespoints linewidth 2 pointtype 7 linecolor rgb "#8c564b" title "self", \
    $d6 using 1:2 with linespoints linewidth 2 pointtype 9 linecolor rgb "#e377c2" title "guided", \
    $d7 using 1:2 with linespoints linewidth 2 pointtype 11 linecolor rgb "#17becf" title "factoring"
