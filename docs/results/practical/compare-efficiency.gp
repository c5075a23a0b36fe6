# Drawn by prt experiment; run `gnuplot compare-efficiency.gp` in this directory to redraw.
set terminal pngcairo noenhanced size 960,600 font "sans,11"
set output "compare-efficiency.png"
set title "Fig. 20: efficiency of every strategy, real runs, 4 emulated workers"
set xlabel ""
set ylabel "efficiency, %"
set grid ytics
set key outside right top
set datafile missing "NaN"
set yrange [*:*]
$bars << EOD
"case A" 77.7595117 79.0621308 54.9460137 76.6526345 43.3879966 66.7438403 69.0760214 71.1147204
"case C" 76.6788636 91.3789734 64.0101946 88.7054441 48.9050153 85.7690021 77.5541715 90.9163365
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
