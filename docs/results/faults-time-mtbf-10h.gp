# Drawn by prt experiment; run `gnuplot faults-time-mtbf-10h.gp` in this directory to redraw.
set terminal pngcairo noenhanced size 960,600 font "sans,11"
set output "faults-time-mtbf-10h.png"
set title "Simulated job time against the lease, MTBF 10 h, 1024 workers"
set xlabel "lease (--worker-timeout), s"
set ylabel "job time, min"
set grid ytics
set key outside right top
set datafile missing "NaN"
set logscale x 2
set yrange [0:*]
$d0 << EOD
1 61.537159
2 61.4968565
5 61.487066
15 61.4966906
60 61.507351
180 63.7404042
EOD
$d1 << EOD
1 61.3838646
2 61.4237978
5 61.3936112
15 61.3661581
60 61.6620838
180 63.9339962
EOD
$d2 << EOD
1 114.364232
2 113.119233
5 115.765892
15 114.973383
60 115.200937
180 113.817467
EOD
$d3 << EOD
1 67.38107
2 67.1058142
5 67.1788527
15 67.0430281
60 66.763147
180 67.2334996
EOD
$d4 << EOD
1 60.8890698
2 60.8892117
5 60.8898281
15 60.8913722
60 60.8973512
180 60.9126481
EOD
plot $d0 using 1:2 with linespoints linewidth 2 pointtype 5 linecolor rgb "#1f77b4" title "adaptive", \
    $d1 using 1:2 with linespoints linewidth 2 pointtype 7 linecolor rgb "#d62728" title "reservoir-scatter", \
    $d2 using 1:2 with linespoints linewidth 2 pointtype 9 linecolor rgb "#2ca02c" title "hybrid", \
    $d3 using 1:2 with linespoints linewidth 2 pointtype 11 linecolor rgb "#9467bd" title "stealing", \
    $d4 using 1:2 with linespoints linewidth 2 pointtype 5 linecolor rgb "#ff7f0e" dashtype 2 title "ideal"
