# Drawn by prt experiment; run `gnuplot joins-real.gp` in this directory to redraw.
set terminal pngcairo noenhanced size 960,600 font "sans,11"
set output "joins-real.png"
set title "Real runs: elapsed over the schedule's ideal, joiners at a third of the serial time"
set xlabel ""
set ylabel "elapsed / ideal"
set grid ytics
set key outside right top
set datafile missing "NaN"
set yrange [0:*]
set arrow from graph 0, first 1 to graph 1, first 1 nohead dashtype 2 linecolor rgb "#555555"
set label "ideal" at graph 0.01, first 1 offset 0,0.6 textcolor rgb "#555555"
$bars << EOD
"scatter" 3.75304511
"scatter-weighted" 4.05038082
"hybrid" 1.05840314
"hybrid-weighted" 1.09761279
"reservoir" 3.56237378
"reservoir-scatter" 3.48382788
"adaptive" 1.160376
"blocks" 4.09771937
"self" 1.23046007
"guided" 4.01697921
"factoring" 2.1814603
"awf-b" 2.20422975
"awf-c" 2.15055119
"af" 2.332468
"stealing" 1.11622187
EOD
set style data histograms
set style histogram clustered gap 1
set style fill solid 0.85 border -1
set boxwidth 0.9
set xtics nomirror
set xrange [-0.6:14.6]
plot $bars using 2:xtic(1) linecolor rgb "#1f77b4" title "real (median)"
