# Drawn by prt experiment; run `gnuplot scale-efficiency-changing.gp` in this directory to redraw.
set terminal pngcairo noenhanced size 960,600 font "sans,11"
set output "scale-efficiency-changing.png"
set title "Simulated changing workers: efficiency against worker count"
set xlabel "workers"
set ylabel "efficiency, %"
set grid ytics
set key outside right top
set datafile missing "NaN"
set logscale x 2
set yrange [0:105]
$d0 << EOD
4 76.8141715
8 66.7570779
16 64.1769578
32 62.5795361
64 37.9076065
128 34.4313133
256 26.8479464
512 28.4690133
1024 26.8899631
EOD
$d1 << EOD
4 38.2370571
8 27.9595746
16 27.8833263
32 27.9069043
64 25.4173509
128 23.9715732
256 22.8620701
512 22.4229879
1024 20.7559723
EOD
$d2 << EOD
4 97.4188802
8 94.9760467
16 91.7002416
32 82.7688232
64 74.3798623
128 59.4377081
256 37.0531745
512 31.4939875
1024 28.7828724
EOD
$d3 << EOD
4 98.7403418
8 98.5962806
16 96.8586402
32 91.8098703
64 87.8216224
128 82.9122172
256 71.4420078
512 53.8791368
1024 39.2644994
EOD
$d4 << EOD
4 54.6715978
8 48.7915379
16 14.8685399
32 13.7833579
64 7.25975493
128 6.34919576
256 5.74004977
512 5.26529782
1024 5.48951583
EOD
$d5 << EOD
4 45.886397
8 35.1263063
16 34.9718324
32 34.9301911
64 32.366136
128 30.9925834
256 29.4793272
512 27.6487098
1024 26.0856364
EOD
$d6 << EOD
4 99.7709359
8 99.2525311
16 99.0509978
32 97.2362783
64 95.6162563
128 92.0601175
256 84.6718762
512 68.7878755
1024 56.8572819
EOD
$d7 << EOD
4 46.6604317
8 28.7866652
16 16.9506747
32 10.665112
64 11.5599454
128 11.7268694
256 10.6445589
512 8.09214244
1024 7.77825048
EOD
$d8 << EOD
4 99.9509836
8 99.9194427
16 99.8481513
32 99.8007553
64 99.3106728
128 70.8764789
256 48.3318965
512 38.1084517
1024 18.5407052
EOD
$d9 << EOD
4 42.5402815
8 43.714635
16 28.0947717
32 30.2963952
64 21.2787108
128 19.0293766
256 14.0301446
512 13.0096272
1024 7.94423277
EOD
$d10 << EOD
4 42.9223319
8 36.2011637
16 33.7103014
32 23.9848696
64 12.2454213
128 12.7800689
256 11.0337526
512 8.63190294
1024 5.58150668
EOD
$d11 << EOD
4 69.852126
8 57.5003523
16 56.6578422
32 56.8441144
64 35.690238
128 28.5547136
256 32.196381
512 27.3017365
1024 29.3962329
EOD
$d12 << EOD
4 63.0090441
8 51.5502302
16 52.943811
32 52.0350135
64 50.1730156
128 47.0622291
256 47.940057
512 43.1307669
1024 43.5372353
EOD
$d13 << EOD
4 60.1611018
8 48.4818132
16 48.4130784
32 48.150771
64 45.2648415
128 44.0304421
256 56.5347275
512 91.9805856
1024 80.22927
EOD
$d14 << EOD
4 99.5971704
8 99.2310674
16 98.7096822
32 97.7529479
64 96.0974391
128 89.4309215
256 83.2857844
512 67.7131779
1024 52.2442885
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
