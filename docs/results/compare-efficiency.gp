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
"case A" 67.6186844 85.6686563 49.4318078 86.5461338 42.5825007 78.634002 37.9111737 57.6799114
"case B" 70.6015918 90.7733209 46.8628723 91.4268449 43.964002 86.3612514 37.9910259 58.8607944
"case C" 71.5971154 90.3537101 44.875227 95.7214211 38.6588375 93.4770097 32.1290388 53.2706171
"case D" 73.7674021 92.7581134 45.5596147 97.2698466 38.4978931 95.9140552 32.467477 58.5565759
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
