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
5 45.0280409
10 44.9273638
20 41.7301682
30 41.5762409
40 33.2771023
50 52.8296961
60 48.5397797
70 34.5255804
75 39.0672711
80 50.4409273
90 27.74686
100 27.812009
EOD
$d1 << EOD
5 44.4098203
10 51.290866
20 40.0238311
30 38.30617
40 34.0232586
50 55.4367814
60 51.6350461
70 35.4476775
75 40.9076253
80 45.3970528
90 28.1720253
100 28.0481659
EOD
$d2 << EOD
5 95.4793471
10 95.7304575
20 95.5813828
30 95.5869258
40 95.806907
50 94.9114914
60 95.3573962
70 95.668922
75 95.4719516
80 95.3402682
90 95.3978138
100 88.9284794
EOD
$d3 << EOD
5 96.2316442
10 96.2445763
20 96.3516379
30 96.2601331
40 96.323079
50 96.2593855
60 96.3384399
70 96.2256219
75 96.2520161
80 96.2551445
90 96.2258149
100 95.3367992
EOD
plot $d0 using 1:2 with linespoints linewidth 2 pointtype 5 linecolor rgb "#1f77b4" title "reservoir (real)", \
    $d1 using 1:2 with linespoints linewidth 2 pointtype 7 linecolor rgb "#d62728" dashtype 2 title "reservoir (simulated)", \
    $d2 using 1:2 with linespoints linewidth 2 pointtype 9 linecolor rgb "#2ca02c" title "reservoir-scatter (real)", \
    $d3 using 1:2 with linespoints linewidth 2 pointtype 11 linecolor rgb "#9467bd" dashtype 2 title "reservoir-scatter (simulated)"
