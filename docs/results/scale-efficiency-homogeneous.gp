# Drawn by prt experiment; run `gnuplot scale-efficiency-homogeneous.gp` in this directory to redraw.
set terminal pngcairo noenhanced size 960,600 font "sans,11"
set output "scale-efficiency-homogeneous.png"
set title "Simulated homogeneous workers: efficiency against worker count"
set xlabel "workers"
set ylabel "efficiency, %"
set grid ytics
set key outside right top
set datafile missing "NaN"
set logscale x 2
set yrange [0:105]
$d0 << EOD
4 99.2410006
8 98.7480853
16 96.7904046
32 95.4390335
64 93.3288696
128 85.8802675
256 69.6967272
512 69.0798331
1024 67.5101704
EOD
$d1 << EOD
4 99.8727612
8 99.5857465
16 99.4303081
32 99.2071085
64 98.6132148
128 97.6499752
256 95.6366242
512 93.0600636
1024 86.2695842
EOD
$d2 << EOD
4 99.9743953
8 99.9412205
16 99.9035983
32 99.6577918
64 99.5074359
128 96.7145973
256 77.057983
512 74.3555722
1024 69.3333084
EOD
$d3 << EOD
4 99.8983027
8 99.8745256
16 99.723547
32 99.4919166
64 99.0202911
128 97.6497585
256 95.859654
512 93.0592789
1024 86.1778675
EOD
$d4 << EOD
4 38.6004044
8 38.4333461
16 34.2449673
32 32.897758
64 31.9139784
128 31.2859017
256 27.8608522
512 27.4873909
1024 18.2791817
EOD
$d5 << EOD
4 99.9944705
8 99.9798865
16 99.9308239
32 99.8756493
64 99.752876
128 99.2848712
256 98.4230459
512 96.8343949
1024 93.7466999
EOD
$d6 << EOD
4 99.9936151
8 99.9788115
16 99.9204751
32 99.8877531
64 99.6843264
128 99.2387992
256 98.3329396
512 97.1568617
1024 92.1088581
EOD
$d7 << EOD
4 50.8090003
8 33.4385116
16 27.8941762
32 26.6927877
64 26.028146
128 24.5175344
256 24.4287542
512 18.7673488
1024 17.7480857
EOD
$d8 << EOD
4 99.9451942
8 99.9359867
16 99.9169684
32 99.8788909
64 99.8034735
128 99.5862443
256 99.1183155
512 79.5547542
1024 55.0117743
EOD
$d9 << EOD
4 51.6008647
8 52.818332
16 50.2430766
32 48.7283096
64 47.8772836
128 47.3367846
256 36.2832192
512 36.0721906
1024 20.1733965
EOD
$d10 << EOD
4 66.8770297
8 59.3443567
16 53.3856421
32 52.0565457
64 49.035969
128 48.8610833
256 37.5431386
512 35.5263862
1024 20.6745725
EOD
$d11 << EOD
4 99.99781
8 99.9752738
16 99.9790047
32 99.9312628
64 99.7788883
128 99.5898766
256 98.6816893
512 97.1642641
1024 93.9525427
EOD
$d12 << EOD
4 99.9961388
8 99.9809805
16 99.9430793
32 99.9377375
64 99.7003892
128 99.3712106
256 98.6819343
512 97.0786955
1024 93.9562116
EOD
$d13 << EOD
4 99.9962159
8 99.9843058
16 99.941205
32 99.8631512
64 99.6956001
128 99.3727661
256 98.6691046
512 97.0265799
1024 94.3716387
EOD
$d14 << EOD
4 99.897782
8 99.7727059
16 99.7253375
32 99.5673146
64 99.0175895
128 98.1177594
256 96.0027633
512 93.0710776
1024 86.2783281
EOD
plot $d0 using 1:2 with linespoints linewidth 2 pointtype 5 linecolor rgb "#1f77b4" dashtype 2 title "scatter", \
    $d1 using 1:2 with linespoints linewidth 2 pointtype 7 linecolor rgb "#d62728" dashtype 2 title "scatter-weighted", \
    $d2 using 1:2 with linespoints linewidth 2 pointtype 9 linecolor rgb "#2ca02c" title "hybrid", \
    $d3 using 1:2 with linespoints linewidth 2 pointtype 11 linecolor rgb "#9467bd" title "hybrid-weighted", \
    $d4 using 1:2 with linespoints linewidth 2 pointtype 5 linecolor rgb "#ff7f0e" title "reservoir", \
    $d5 using 1:2 with linespoints linewidth 2 pointtype 7 linecolor rgb "#8c564b" title "reservoir-scatter", \
    $d6 using 1:2 with linespoints linewidth 2 pointtype 9 linecolor rgb "#e377c2" title "adaptive", \
    $d7 using 1:2 with linespoints linewidth 2 pointtype 11 linecolor rgb "#17becf" dashtype 2 title "blocks", \
    $d8 using 1:2 with linespoints linewidth 2 pointtype 5 linecolor rgb "#7f7f7f" title "self", \
    $d9 using 1:2 with linespoints linewidth 2 pointtype 7 linecolor rgb "#bcbd22" title "guided", \
    $d10 using 1:2 with linespoints linewidth 2 pointtype 9 linecolor rgb "#1f77b4" title "factoring", \
    $d11 using 1:2 with linespoints linewidth 2 pointtype 11 linecolor rgb "#d62728" title "awf-b", \
    $d12 using 1:2 with linespoints linewidth 2 pointtype 5 linecolor rgb "#2ca02c" title "awf-c", \
    $d13 using 1:2 with linespoints linewidth 2 pointtype 7 linecolor rgb "#9467bd" title "af", \
    $d14 using 1:2 with linespoints linewidth 2 pointtype 9 linecolor rgb "#ff7f0e" title "stealing"
