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
4 40.0866115
8 39.8851355
16 39.7040075
32 39.1000725
64 38.1986273
128 34.8294886
256 27.7675707
512 28.3840058
1024 27.8803262
EOD
$d1 << EOD
4 99.8348466
8 99.3103649
16 98.4551963
32 98.0377704
64 97.7828606
128 96.3110857
256 89.059144
512 85.9582112
1024 74.0490299
EOD
$d2 << EOD
4 96.7591534
8 96.3179764
16 94.6028616
32 88.4514376
64 75.8095786
128 58.5595451
256 34.1830287
512 31.3018125
1024 29.8450106
EOD
$d3 << EOD
4 99.8348466
8 99.6420088
16 99.3655951
32 98.2674832
64 97.6387996
128 96.5923153
256 89.2333194
512 85.9582112
1024 74.0490299
EOD
$d4 << EOD
4 40.9286498
8 34.5700195
16 34.7601193
32 32.3877761
64 30.079042
128 29.7021662
256 29.4065372
512 14.7772267
1024 11.5762288
EOD
$d5 << EOD
4 99.9787179
8 99.9465508
16 99.810171
32 99.7475608
64 99.4849671
128 98.6178243
256 96.7890613
512 92.8599897
1024 85.9683435
EOD
$d6 << EOD
4 99.9940287
8 99.9738823
16 99.9505256
32 99.7762581
64 99.1949069
128 98.8522772
256 96.6335727
512 94.4099423
1024 87.4540384
EOD
$d7 << EOD
4 20.4910025
8 13.4368582
16 11.8758011
32 13.1780867
64 10.5089032
128 10.6108542
256 9.90128037
512 8.2866269
1024 7.14656372
EOD
$d8 << EOD
4 99.9435321
8 99.9000467
16 99.8306282
32 99.713463
64 99.4836023
128 90.2925726
256 67.7490057
512 44.0452844
1024 26.1820261
EOD
$d9 << EOD
4 20.8405869
8 21.4020676
16 20.2860529
32 19.7250247
64 19.2473674
128 19.0043252
256 14.4594795
512 14.5582495
1024 8.17004164
EOD
$d10 << EOD
4 87.521756
8 62.3139653
16 58.8224605
32 52.8406256
64 51.5312537
128 44.8881431
256 32.7573462
512 18.3886943
1024 15.1974153
EOD
$d11 << EOD
4 99.9900478
8 99.9695195
16 99.9710093
32 99.6624468
64 99.5066598
128 99.0131232
256 97.1745988
512 94.2917134
1024 88.481771
EOD
$d12 << EOD
4 99.9955232
8 99.9082421
16 99.9375189
32 99.8670328
64 99.2330908
128 98.5065432
256 97.1417295
512 93.91809
1024 86.7723275
EOD
$d13 << EOD
4 99.969919
8 90.4986313
16 99.8856527
32 99.6262496
64 99.4405162
128 98.9966641
256 96.1817553
512 93.2557281
1024 86.5968398
EOD
$d14 << EOD
4 99.6510463
8 99.2379013
16 98.5341486
32 97.1003181
64 96.0155978
128 91.1320882
256 82.9290441
512 78.5075443
1024 59.1856444
EOD
plot $d0 using 1:2 with linespoints linewidth 2 pointtype 5 linecolor rgb "#1f77b4" dashtype 2 title "scatter", \
    $d1 using 1:2 with linespoints linewidth 2 pointtype 7 linecolor rgb "#d62728" dashtype 2 title "scatter-weighted", \
    $d2 using 1:2 with linespoints linewidth 2 pointtype 9 linecolor rgb "#2ca02c" title "hybrid", \
    $d3 using 1:2 with linespoints linewidth 2 pointtype 11 linecolor rgb "#9467bd" title "hybrid-weighted", \
    $d4 using 1:2 with linespoints linewidth 2 pointtype 5 linecolor rgb "#ff7f0e" title "reservoir", \
    $d5 using 1:2 with linespoints linewidth 2 pointtype 7 linecolor rgb "#8c564b" title "reservoir-scatter", \
    $d6 using 1:2 with linespoints linewidth 2 pointtype 9 linecolor rgb "#e377c2" title "adaptive", \
    $d7 using 1:2 with linespoints linewidth 2 pointtype 11 linecolor rgb "#17becf" dashtype 2 title "blocks", \
    $d8 using 1:2 with linespoints linewidth 2 pointtype 5 linecolor rgb "#7f7f7f" title "self", \
    $d9 using 1:2 with linespoints linewidth 2 pointtype 7 linecolor rgb "#bcbd22" title "guided", \
    $d10 using 1:2 with linespoints linewidth 2 pointtype 9 linecolor rgb "#1f77b4" title "factoring", \
    $d11 using 1:2 with linespoints linewidth 2 pointtype 11 linecolor rgb "#d62728" title "awf-b", \
    $d12 using 1:2 with linespoints linewidth 2 pointtype 5 linecolor rgb "#2ca02c" title "awf-c", \
    $d13 using 1:2 with linespoints linewidth 2 pointtype 7 linecolor rgb "#9467bd" title "af", \
    $d14 using 1:2 with linespoints linewidth 2 pointtype 9 linecolor rgb "#ff7f0e" title "stealing"
