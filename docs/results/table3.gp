# Drawn by prt experiment; run `gnuplot table3.gp` in this directory to redraw.
set terminal pngcairo noenhanced size 960,600 font "sans,11"
set output "table3.png"
set title "Table III: serial time of each test case, relative to case A"
set xlabel ""
set ylabel "time / time of case A (log scale)"
set grid ytics
set key outside right top
set datafile missing "NaN"
set logscale y
set yrange [*:*]
$bars << EOD
"A" 1 1
"B" 2.22407397 2.02019567
"C" 4.48697619 75.9302189
"D" 8.2514143 152.33979
EOD
set style data histograms
set style histogram clustered gap 1
set style fill solid 0.85 border -1
set boxwidth 0.9
set xtics nomirror
set xrange [-0.6:3.6]
plot $bars using 2:xtic(1) linecolor rgb "#1f77b4" title "PRT, this machine (640x480)", \
    $bars using 3 linecolor rgb "#d62728" title "the paper's SRT (Table III)"
