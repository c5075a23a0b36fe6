# Drawn by prt experiment; run `gnuplot initial-percent-speedup.gp` in this directory to redraw.
set terminal pngcairo noenhanced size 960,600 font "sans,11"
set output "initial-percent-speedup.png"
set title "Fig. 18: speed-up against the initial percentage (case C, 4 workers)"
set xlabel "initial percentage"
set ylabel "speed-up (serial time / parallel time)"
set grid ytics
set key outside right top
set datafile missing "NaN"
set yrange [0:*]
set arrow from graph 0, first 1.5 to graph 1, first 1.5 nohead dashtype 2 linecolor rgb "#555555"
set label "emulated MASU 1.50" at graph 0.01, first 1.5 offset 0,0.6 textcolor rgb "#555555"
$d0 << EOD
5 0.485436871
10 0.525445761
20 0.660914087
30 0.791936645
40 0.601169251
50 0.673216523
60 0.504078221
70 0.399488047
75 0.503445645
80 0.661356873
90 0.512743497
100 0.524803701
EOD
$d1 << EOD
5 0.845250079
10 0.975529738
20 0.532619422
30 0.722594258
40 0.605563487
50 0.754057506
60 0.570480952
70 0.44162978
75 0.560297063
80 0.712870007
90 0.538175645
100 0.537454746
EOD
$d2 << EOD
5 1.25887504
10 1.35408752
20 1.37761479
30 1.39636767
40 1.40440902
50 1.33045307
60 1.38025585
70 1.3477737
75 1.20468398
80 1.31208072
90 1.41832645
100 1.3304897
EOD
$d3 << EOD
5 1.44328275
10 1.44347488
20 1.44539825
30 1.44372402
40 1.44501171
50 1.44366495
60 1.44515603
70 1.44321404
75 1.44362225
80 1.44368657
90 1.4430337
100 1.4288702
EOD
plot $d0 using 1:2 with linespoints linewidth 2 pointtype 5 linecolor rgb "#1f77b4" title "reservoir (real)", \
    $d1 using 1:2 with linespoints linewidth 2 pointtype 7 linecolor rgb "#d62728" dashtype 2 title "reservoir (simulated)", \
    $d2 using 1:2 with linespoints linewidth 2 pointtype 9 linecolor rgb "#2ca02c" title "reservoir-scatter (real)", \
    $d3 using 1:2 with linespoints linewidth 2 pointtype 11 linecolor rgb "#9467bd" dashtype 2 title "reservoir-scatter (simulated)"
