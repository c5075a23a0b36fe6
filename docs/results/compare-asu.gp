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
"case A" 66.9884141 85.7819456 55.105788 92.8654355 42.2522825 89.9632404 36.5909906 64.2985267
"case B" 70.0702336 90.4388863 41.7559971 85.8854388 36.1687395 98.4014445 29.9656469 59.8480495
"case C" 58.6647859 96.6035345 39.3246406 93.1612836 39.4093941 90.8135748 25.8730013 48.542654
"case D" 71.5350864 96.3805885 56.4836429 96.8021758 33.3604866 103.318689 26.7453446 51.3730438
EOD
set style data histograms
set style histogram clustered gap 1
set style fill solid 0.85 border -1
set boxwidth 0.9
set xtics nomirror
set xrange [-0.6:3.6]
set yrange [0:*]
plot $bars using 2:xtic(1) linecolor rgb "#1f77b4" title "scatter", \
    $bars using 3 linecolor rgb "#d62728" title "hybrid", \
    $bars using 4 linecolor rgb "#2ca02c" title "reservoir", \
    $bars using 5 linecolor rgb "#9467bd" title "reservoir-scatter", \
    $bars using 6 linecolor rgb "#ff7f0e" title "blocks", \
    $bars using 7 linecolor rgb "#8c564b" title "self", \
    $bars using 8 linecolor rgb "#e377c2" title "guided", \
    $bars using 9 linecolor rgb "#17becf" title "factoring"
