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
4 99.1346247
8 98.5535187
16 96.0329061
32 94.9163813
64 91.9277534
128 85.0943729
256 69.396583
512 68.796414
1024 67.0156325
EOD
$d1 << EOD
4 99.9462162
8 99.6255358
16 99.1216178
32 98.8117996
64 97.7615972
128 96.9842218
256 94.1194998
512 91.1868286
1024 85.8174741
EOD
$d2 << EOD
4 99.9776898
8 99.9539124
16 99.9158555
32 99.6196749
64 99.3154131
128 96.3773014
256 77.4378032
512 74.5486993
1024 68.9678644
EOD
$d3 << EOD
4 99.9462162
8 99.8481142
16 99.7588077
32 99.4723959
64 98.7155835
128 97.547707
256 95.4347356
512 91.1860752
1024 85.8161394
EOD
$d4 << EOD
4 38.8635467
8 38.7753093
16 34.9672271
32 33.0381951
64 32.231404
128 31.6117737
256 28.0588879
512 27.5998844
1024 18.5629262
EOD
$d5 << EOD
4 99.9861351
8 99.9771339
16 99.9266041
32 99.8664828
64 99.7386633
128 99.2876225
256 98.4341556
512 97.3860027
1024 93.8269803
EOD
$d6 << EOD
4 99.9947467
8 99.9840271
16 99.9382056
32 99.8678045
64 99.672387
128 99.2311642
256 98.535724
512 96.50337
1024 90.9698175
EOD
$d7 << EOD
4 51.2274982
8 33.5921361
16 28.4237162
32 26.7673474
64 26.2720414
128 24.8368014
256 24.750354
512 19.0851461
1024 17.8432459
EOD
$d8 << EOD
4 99.9456409
8 99.9381488
16 99.9199554
32 99.8794306
64 99.7952516
128 99.6263032
256 99.2349845
512 80.9259191
1024 56.3344099
EOD
$d9 << EOD
4 52.101459
8 53.5051455
16 50.7150669
32 49.3123497
64 48.1176928
128 47.5081244
256 36.142617
512 36.371407
1024 20.394788
EOD
$d10 << EOD
4 67.1842789
8 59.3789805
16 53.5347619
32 52.5443412
64 49.6745266
128 49.5043777
256 38.1790215
512 35.7170316
1024 20.9277045
EOD
$d11 << EOD
4 99.9975494
8 99.9745658
16 99.9797977
32 99.9310759
64 99.7724164
128 99.5827784
256 98.671605
512 97.3653391
1024 94.3508808
EOD
$d12 << EOD
4 99.9970336
8 99.9802527
16 99.9378086
32 99.8879719
64 99.7069309
128 99.5676865
256 98.6918286
512 97.2064422
1024 93.8635191
EOD
$d13 << EOD
4 99.9967938
8 99.9893332
16 99.9497989
32 99.86255
64 99.7106069
128 99.4436379
256 98.72255
512 97.2547239
1024 93.6611704
EOD
$d14 << EOD
4 99.946209
8 99.9268474
16 99.6706575
32 99.4064262
64 98.7897749
128 97.6370235
256 95.5906196
512 91.4803849
1024 85.8986017
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
