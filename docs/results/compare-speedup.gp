# Drawn by prt experiment; run `gnuplot compare-speedup.gp` in this directory to redraw.
set terminal pngcairo noenhanced size 960,600 font "sans,11"
set output "compare-speedup.png"
set title "Fig. 19: speed-up of every strategy, real runs, 4 emulated workers"
set xlabel ""
set ylabel "speed-up"
set grid ytics
set key outside right top
set datafile missing "NaN"
set yrange [*:*]
$bars << EOD
"case A" 0.918771575 1.30837603 0.771015162 1.24037205 0.578251167 1.19216636 0.480709368 0.818510158
"case B" 0.916172671 1.40800082 0.606384104 1.30800616 0.56806425 1.33431953 0.470761994 0.862819972
"case C" 0.872829255 1.25056277 0.622475587 1.25303045 0.482623211 1.2680438 0.371961469 0.74269049
"case D" 0.955510378 1.34437524 0.692154271 1.45039446 0.492933171 1.3747736 0.3774527 0.792172497
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
