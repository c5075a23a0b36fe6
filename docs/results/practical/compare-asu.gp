# Drawn by prt experiment; run `gnuplot compare-asu.gp` in this directory to redraw.
set terminal pngcairo noenhanced size 960,600 font "sans,11"
set output "compare-asu.png"
set title "Fig. 21: achieved speed-up (ASU) of every strategy, real runs, 4 emulated workers"
set xlabel ""
set ylabel "ASU, %"
set grid ytics
set key outside right top
set datafile missing "NaN"
set yrange [*:*]
$bars << EOD
"case A" 30.6667082 29.744082 36.1135633 28.8983442 22.1114431 26.0227542 24.8677134 24.0348341
"case C" 42.903138 47.1046507 61.356337 71.6377128 56.4418079 90.2830484 58.6706759 52.5236312
EOD
set style data histograms
set style histogram clustered gap 1
set style fill solid 0.85 border -1
set boxwidth 0.9
set xtics nomirror
set xrange [-0.6:1.6]
set yrange [0:*]
plot $bars using 2:xtic(1) linecolor rgb "#1f77b4" title "scatter", \
    $bars using 3 linecolor rgb "#d62728" title "hybrid", \
    $bars using 4 linecolor rgb "#2ca02c" title "reservoir", \
    $bars using 5 linecolor rgb "#9467bd" title "reservoir-scatter", \
    $bars using 6 linecolor rgb "#ff7f0e" title "blocks", \
    $bars using 7 linecolor rgb "#8c564b" title "self", \
    $bars using 8 linecolor rgb "#e377c2" title "guided", \
    $bars using 9 linecolor rgb "#17becf" title "factoring"
