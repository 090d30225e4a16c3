# shadowmap-stress: Scene translated away from the origin, every mesh skinned to a joint
# remake from the output folder: gnuplot plots/distance_skinned.gp
set terminal pngcairo noenhanced size 1100,1080 font ',9'
set output 'distance_skinned.png'
set multiplot layout 3,1 title 'Scene translated away from the origin, every mesh skinned to a joint: error = acne + leak, % of the evaluation set'
set grid
set key outside right top
set ylabel 'error % (log; 0 drawn at 0.001)'
set xlabel 'distance from the origin'
set logscale y
set yrange [0.001:100]
set xtics ('0' 1, '1e3' 1000, '1e5' 100000, '1e6' 1000000, '1e7' 10000000)
set logscale x
set xrange [0.625:1.6e+07]
set title 'spot light'
plot 'plots/distance_skinned.dat' index 0 using 1:2 with linespoints lc rgb '#1f77b4' dt 3 pt 6 lw 1.5 title 'standard d16', \
     'plots/distance_skinned.dat' index 1 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 lw 1.5 title 'standard d24', \
     'plots/distance_skinned.dat' index 2 using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 lw 1.5 title 'standard d32f', \
     'plots/distance_skinned.dat' index 3 using 1:2 with linespoints lc rgb '#1f77b4' dt 4 pt 9 lw 1.5 title 'standard d32f_rz', \
     'plots/distance_skinned.dat' index 4 using 1:2 with linespoints lc rgb '#d62728' dt 3 pt 6 lw 1.5 title 'woo d16', \
     'plots/distance_skinned.dat' index 5 using 1:2 with linespoints lc rgb '#d62728' dt 1 pt 7 lw 1.5 title 'woo d24', \
     'plots/distance_skinned.dat' index 6 using 1:2 with linespoints lc rgb '#d62728' dt 2 pt 5 lw 1.5 title 'woo d32f', \
     'plots/distance_skinned.dat' index 7 using 1:2 with linespoints lc rgb '#d62728' dt 4 pt 9 lw 1.5 title 'woo d32f_rz', \
     'plots/distance_skinned.dat' index 8 using 1:2 with linespoints lc rgb '#2ca02c' dt 3 pt 6 lw 1.5 title 'backface d16', \
     'plots/distance_skinned.dat' index 9 using 1:2 with linespoints lc rgb '#2ca02c' dt 1 pt 7 lw 1.5 title 'backface d24', \
     'plots/distance_skinned.dat' index 10 using 1:2 with linespoints lc rgb '#2ca02c' dt 2 pt 5 lw 1.5 title 'backface d32f', \
     'plots/distance_skinned.dat' index 11 using 1:2 with linespoints lc rgb '#2ca02c' dt 4 pt 9 lw 1.5 title 'backface d32f_rz'
set title 'directional light'
plot 'plots/distance_skinned.dat' index 12 using 1:2 with linespoints lc rgb '#1f77b4' dt 3 pt 6 lw 1.5 title 'standard d16', \
     'plots/distance_skinned.dat' index 13 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 lw 1.5 title 'standard d24', \
     'plots/distance_skinned.dat' index 14 using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 lw 1.5 title 'standard d32f', \
     'plots/distance_skinned.dat' index 15 using 1:2 with linespoints lc rgb '#1f77b4' dt 4 pt 9 lw 1.5 title 'standard d32f_rz', \
     'plots/distance_skinned.dat' index 16 using 1:2 with linespoints lc rgb '#d62728' dt 3 pt 6 lw 1.5 title 'woo d16', \
     'plots/distance_skinned.dat' index 17 using 1:2 with linespoints lc rgb '#d62728' dt 1 pt 7 lw 1.5 title 'woo d24', \
     'plots/distance_skinned.dat' index 18 using 1:2 with linespoints lc rgb '#d62728' dt 2 pt 5 lw 1.5 title 'woo d32f', \
     'plots/distance_skinned.dat' index 19 using 1:2 with linespoints lc rgb '#d62728' dt 4 pt 9 lw 1.5 title 'woo d32f_rz', \
     'plots/distance_skinned.dat' index 20 using 1:2 with linespoints lc rgb '#2ca02c' dt 3 pt 6 lw 1.5 title 'backface d16', \
     'plots/distance_skinned.dat' index 21 using 1:2 with linespoints lc rgb '#2ca02c' dt 1 pt 7 lw 1.5 title 'backface d24', \
     'plots/distance_skinned.dat' index 22 using 1:2 with linespoints lc rgb '#2ca02c' dt 2 pt 5 lw 1.5 title 'backface d32f', \
     'plots/distance_skinned.dat' index 23 using 1:2 with linespoints lc rgb '#2ca02c' dt 4 pt 9 lw 1.5 title 'backface d32f_rz'
set title 'point light'
plot 'plots/distance_skinned.dat' index 24 using 1:2 with linespoints lc rgb '#1f77b4' dt 3 pt 6 lw 1.5 title 'standard d16', \
     'plots/distance_skinned.dat' index 25 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 lw 1.5 title 'standard d24', \
     'plots/distance_skinned.dat' index 26 using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 lw 1.5 title 'standard d32f', \
     'plots/distance_skinned.dat' index 27 using 1:2 with linespoints lc rgb '#1f77b4' dt 4 pt 9 lw 1.5 title 'standard d32f_rz', \
     'plots/distance_skinned.dat' index 28 using 1:2 with linespoints lc rgb '#d62728' dt 3 pt 6 lw 1.5 title 'woo d16', \
     'plots/distance_skinned.dat' index 29 using 1:2 with linespoints lc rgb '#d62728' dt 1 pt 7 lw 1.5 title 'woo d24', \
     'plots/distance_skinned.dat' index 30 using 1:2 with linespoints lc rgb '#d62728' dt 2 pt 5 lw 1.5 title 'woo d32f', \
     'plots/distance_skinned.dat' index 31 using 1:2 with linespoints lc rgb '#d62728' dt 4 pt 9 lw 1.5 title 'woo d32f_rz', \
     'plots/distance_skinned.dat' index 32 using 1:2 with linespoints lc rgb '#2ca02c' dt 3 pt 6 lw 1.5 title 'backface d16', \
     'plots/distance_skinned.dat' index 33 using 1:2 with linespoints lc rgb '#2ca02c' dt 1 pt 7 lw 1.5 title 'backface d24', \
     'plots/distance_skinned.dat' index 34 using 1:2 with linespoints lc rgb '#2ca02c' dt 2 pt 5 lw 1.5 title 'backface d32f', \
     'plots/distance_skinned.dat' index 35 using 1:2 with linespoints lc rgb '#2ca02c' dt 4 pt 9 lw 1.5 title 'backface d32f_rz'
unset multiplot
