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
4 40.0932491
8 39.8918388
16 39.7158547
32 39.1235751
64 38.3544443
128 34.8696065
256 27.8877059
512 28.6922079
1024 27.813419
EOD
$d1 << EOD
4 99.8774995
8 99.4664115
16 99.1381172
32 97.6901116
64 97.9207414
128 95.4207784
256 91.035735
512 85.4126113
1024 78.9860604
EOD
$d2 << EOD
4 97.9591397
8 97.1906689
16 93.4324468
32 88.0958965
64 75.6031583
128 56.3058068
256 33.5370237
512 31.3988199
1024 29.6359392
EOD
$d3 << EOD
4 99.9163865
8 99.5552699
16 99.304246
32 98.1615358
64 97.9207414
128 95.4206487
256 91.2097254
512 85.4126113
1024 78.9860604
EOD
$d4 << EOD
4 40.7864916
8 34.0086438
16 34.4063624
32 31.661544
64 29.7662332
128 29.514066
256 29.127942
512 14.7282132
1024 11.5943696
EOD
$d5 << EOD
4 99.9787341
8 99.9608871
16 99.8496579
32 99.5716526
64 99.4907976
128 98.0953464
256 96.4056386
512 92.675044
1024 86.3504181
EOD
$d6 << EOD
4 99.972926
8 99.9785887
16 99.8758607
32 99.7790369
64 99.2560209
128 98.9154362
256 97.4027842
512 94.7103558
1024 83.0157633
EOD
$d7 << EOD
4 20.3236033
8 13.3754083
16 11.8688763
32 13.0289563
64 10.4113434
128 10.3448637
256 9.77261104
512 8.10364796
1024 7.10840102
EOD
$d8 << EOD
4 99.9369083
8 99.8983237
16 99.8414705
32 99.7294759
64 99.4779097
128 88.5056105
256 68.0184056
512 44.1784822
1024 25.4256801
EOD
$d9 << EOD
4 20.6403491
8 21.127342
16 20.0972563
32 19.4914067
64 19.1512008
128 18.9357815
256 14.5157394
512 14.4384042
1024 8.08122301
EOD
$d10 << EOD
4 86.9071673
8 62.0213368
16 58.9376205
32 52.6171937
64 51.0261937
128 45.020106
256 32.4647388
512 18.2717663
1024 15.1752294
EOD
$d11 << EOD
4 99.9723113
8 99.9081799
16 99.88571
32 99.8126384
64 99.3887837
128 98.7248471
256 97.2253758
512 93.9104089
1024 87.9369603
EOD
$d12 << EOD
4 99.9851685
8 99.9515279
16 99.8792214
32 99.6659775
64 99.2291313
128 98.6483857
256 97.4365791
512 93.3549008
1024 85.9020659
EOD
$d13 << EOD
4 99.9819511
8 99.9609764
16 99.8730052
32 99.8043731
64 99.2438941
128 99.1242854
256 96.895726
512 92.3374464
1024 86.2787366
EOD
$d14 << EOD
4 99.56137
8 99.2877632
16 98.6333802
32 97.6760516
64 96.0213378
128 90.4934542
256 84.1584318
512 78.5433615
1024 57.1079936
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
