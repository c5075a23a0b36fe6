# Drawn by prt experiment; run `gnuplot scale-efficiency-homogeneous.gp` in this directory to redraw.
set terminal pngcairo noenhanced size 960,600 font "sans,11"
set output "scale-efficiency-homogeneous.png"
set title "Simulated homogeneous workers: efficiency against worker count"
set xlabel "workers"
set ylabel "efficiency, %"
set grid ytics
set key outside right top
set datafile missing "NaN"
set logscale x 2
set yrange [0:105]
$d0 << EOD
4 99.3850503
8 98.9707809
16 97.2265957
32 95.5507536
64 93.4096746
128 84.3326203
256 67.8447328
512 67.4067508
1024 65.4904434
EOD
$d1 << EOD
4 99.9814122
8 99.9646022
16 99.8780692
32 99.856401
64 99.2902891
128 95.3178184
256 74.2435068
512 71.5563448
1024 67.4223483
EOD
$d2 << EOD
4 38.2665185
8 35.8676711
16 34.2727719
32 30.7744246
64 30.254941
128 29.6382892
256 26.4433844
512 25.8079566
1024 17.0944485
EOD
$d3 << EOD
4 99.9837668
8 99.9305786
16 99.9218892
32 99.8532495
64 99.7494412
128 99.2108606
256 98.2641254
512 96.8040452
1024 93.456022
EOD
$d4 << EOD
4 49.3982548
8 31.0343903
16 27.553948
32 24.858733
64 24.5984511
128 23.1989249
256 23.0654603
512 17.6575448
1024 17.0168076
EOD
$d5 << EOD
4 99.9466434
8 99.9355813
16 99.9105188
32 99.8729642
64 99.7698944
128 99.579516
256 99.1298699
512 85.5207905
1024 60.4114426
EOD
$d6 << EOD
4 51.5644456
8 49.1278618
16 47.0072629
32 46.024218
64 44.7801357
128 44.5674714
256 34.1154471
512 33.748911
1024 18.4631739
EOD
$d7 << EOD
4 62.0687862
8 55.1079138
16 49.7175238
32 49.1971288
64 46.3986558
128 46.1341077
256 35.3225617
512 34.0613903
1024 18.8843013
EOD
plot $d0 using 1:2 with linespoints linewidth 2 pointtype 5 linecolor rgb "#1f77b4" dashtype 2 title "scatter", \
    $d1 using 1:2 with linespoints linewidth 2 pointtype 7 linecolor rgb "#d62728" title "hybrid", \
    $d2 using 1:2 with linespoints linewidth 2 pointtype 9 linecolor rgb "#2ca02c" title "reservoir", \
    $d3 using 1:2 with linespoints linewidth 2 pointtype 11 linecolor rgb "#9467bd" title "reservoir-scatter", \
    $d4 using 1:2 with linespoints linewidth 2 pointtype 5 linecolor rgb "#ff7f0e" dashtype 2 title "blocks", \
    $d5 using 1:2 with linespoints linewidth 2 pointtype 7 linecolor rgb "#8c564b" title "self", \
    $d6 using 1:2 with linespoints linewidth 2 pointtype 9 linecolor rgb "#e377c2" title "guided", \
    $d7 using 1:2 with linespoints linewidth 2 pointtype 11 linecolor rgb "#17becf" title "factoring"
