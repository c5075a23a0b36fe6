# Drawn by prt experiment; run `gnuplot joins-simulated.gp` in this directory to redraw.
set terminal pngcairo noenhanced size 960,600 font "sans,11"
set output "joins-simulated.png"
set title "Simulated: elapsed over the schedule's ideal, by when the joiners arrive"
set xlabel "joiners arrive at (fraction of the serial time)"
set ylabel "elapsed / ideal"
set grid ytics
set key outside right top
set datafile missing "NaN"
set yrange [1:*]
$d0 << EOD
0 1.66706049
0.1 4.54574062
0.2 4.1669289
0.33 3.7596351
0.5 3.33354312
0.75 2.85732268
1 2.50015734
1.5 2.00012587
2 1.66677156
EOD
$d1 << EOD
0 1.00738416
0.1 4.54780115
0.2 4.16881772
0.33 3.7613393
0.5 3.33505418
0.75 2.85861786
1 2.50129063
1.5 2.00103251
2 1.66752709
EOD
$d2 << EOD
0 1.05583162
0.1 1.0229011
0.2 1.01943406
0.33 1.0193582
0.5 1.02659807
0.75 1.01659441
1 1.01905615
1.5 1.01362228
2 1.01727292
EOD
$d3 << EOD
0 1.00413243
0.1 1.00475868
0.2 1.00456559
0.33 1.00414925
0.5 1.00368279
0.75 1.00365022
1 1.00220676
1.5 1.00214267
2 1.00246503
EOD
$d4 << EOD
0 1.25563842
0.1 4.27158158
0.2 3.91561645
0.33 3.53288702
0.5 3.13249316
0.75 2.68499414
1 2.34936987
1.5 1.8794959
2 1.56624658
EOD
$d5 << EOD
0 1.00319066
0.1 3.6381204
0.2 3.3349437
0.33 3.00897176
0.5 2.66795496
0.75 2.28681854
1 2.00096622
1.5 1.60077298
2 1.33397748
EOD
$d6 << EOD
0 1.00311417
0.1 1.00285092
0.2 1.00260268
0.33 1.00223442
0.5 1.00429618
0.75 1.00329812
1 1.00323877
1.5 1.00164226
2 1.00108292
EOD
$d7 << EOD
0 2.05658937
0.1 4.54574062
0.2 4.1669289
0.33 3.7596351
0.5 3.33354312
0.75 2.85732268
1 2.50015734
1.5 2.00012587
2 1.66677156
EOD
$d8 << EOD
0 1.2445191
0.1 1.21052669
0.2 1.18406977
0.33 1.16189712
0.5 1.14032895
0.75 1.1176683
1 1.10133877
1.5 1.07948707
2 1.06490588
EOD
$d9 << EOD
0 1.63496232
0.1 4.54574062
0.2 4.1669289
0.33 3.7596351
0.5 3.33354312
0.75 2.85732268
1 2.50015734
1.5 2.00012587
2 1.66677156
EOD
$d10 << EOD
0 1.1753393
0.1 2.36859187
0.2 2.17120922
0.33 1.95898576
0.5 1.73696737
0.75 1.48882918
1 1.30272553
1.5 1.1279853
2 1.14832108
EOD
$d11 << EOD
0 1.00386786
0.1 2.26259037
0.2 2.07404117
0.33 1.87131534
0.5 1.65923294
0.75 1.42219966
1 1.2444247
1.5 1.00138725
2 1.2503208
EOD
$d12 << EOD
0 1.00427219
0.1 2.26259037
0.2 2.07404117
0.33 1.87131534
0.5 1.65923294
0.75 1.42219966
1 1.2444247
1.5 1.00140975
2 1.2503208
EOD
$d13 << EOD
0 1.00354161
0.1 2.26262109
0.2 2.07406933
0.33 1.87134075
0.5 1.65925547
0.75 1.42221897
1 1.2444416
1.5 1.00111195
2 1.66210959
EOD
$d14 << EOD
0 1.00542534
0.1 1.00576072
0.2 1.00491729
0.33 1.00584807
0.5 1.0032116
0.75 1.00452121
1 1.00405183
1.5 1.00314551
2 1.0023141
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
