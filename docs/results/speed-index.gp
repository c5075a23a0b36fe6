# Drawn by prt experiment; run `gnuplot speed-index.gp` in this directory to redraw.
set terminal pngcairo noenhanced size 960,600 font "sans,11"
set output "speed-index.png"
set title "Fig. 17: speed indices, Towers of Hanoi vs a ray-tracing probe (reservoir 80 %, case A)"
set xlabel ""
set ylabel "median of 3 run(s)"
set grid ytics
set key outside right top
set datafile missing "NaN"
set yrange [*:*]
set arrow from graph 0, first 1.5 to graph 1, first 1.5 nohead dashtype 2 linecolor rgb "#555555"
set label "emulated MASU 1.50" at graph 0.01, first 1.5 offset 0,0.6 textcolor rgb "#555555"
$bars << EOD
"MASU" 1.3124114 1.46633536
"ASU" 0.529866283 0.455429295
"speed-up" 0.649381507 0.667812081
EOD
set style data histograms
set style histogram clustered gap 1
set style fill solid 0.85 border -1
set boxwidth 0.9
set xtics nomirror
set xrange [-0.6:2.6]
set yrange [0:*]
plot $bars using 2:xtic(1) linecolor rgb "#1f77b4" title "Towers of Hanoi (the paper's)", \
    $bars using 3 linecolor rgb "#d62728" title "ray-tracing probe"
