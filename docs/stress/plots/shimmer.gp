# shadowmap-stress: Shimmer of four cascades on a one-pixel pan
# remake from the output folder: gnuplot plots/shimmer.gp
set terminal pngcairo noenhanced size 1100,360 font ',9'
set output 'shimmer.png'
set multiplot layout 1,1 title 'Shimmer of four cascades on a one-pixel pan: error = acne + leak, % of the evaluation set'
set grid
set key outside right top
set ylabel 'error % (log; 0 drawn at 0.001)'
set xlabel 'cascades'
set logscale y
set yrange [0.001:100]
set xtics ('stable' 1, 'fitted' 2) rotate by -15
unset logscale x
set xrange [0.5:2.5]
set title 'directional light'
plot 'plots/shimmer.dat' index 0 using 1:2 with points lc rgb '#1f77b4' dt 3 pt 6 lw 1.5 title 'standard d16', \
     'plots/shimmer.dat' index 1 using 1:2 with points lc rgb '#1f77b4' dt 1 pt 7 lw 1.5 title 'standard d24', \
     'plots/shimmer.dat' index 2 using 1:2 with points lc rgb '#1f77b4' dt 2 pt 5 lw 1.5 title 'standard d32f', \
     'plots/shimmer.dat' index 3 using 1:2 with points lc rgb '#1f77b4' dt 4 pt 9 lw 1.5 title 'standard d32f_rz', \
     'plots/shimmer.dat' index 4 using 1:2 with points lc rgb '#d62728' dt 3 pt 6 lw 1.5 title 'woo d16', \
     'plots/shimmer.dat' index 5 using 1:2 with points lc rgb '#d62728' dt 1 pt 7 lw 1.5 title 'woo d24', \
     'plots/shimmer.dat' index 6 using 1:2 with points lc rgb '#d62728' dt 2 pt 5 lw 1.5 title 'woo d32f', \
     'plots/shimmer.dat' index 7 using 1:2 with points lc rgb '#d62728' dt 4 pt 9 lw 1.5 title 'woo d32f_rz', \
     'plots/shimmer.dat' index 8 using 1:2 with points lc rgb '#2ca02c' dt 3 pt 6 lw 1.5 title 'backface d16', \
     'plots/shimmer.dat' index 9 using 1:2 with points lc rgb '#2ca02c' dt 1 pt 7 lw 1.5 title 'backface d24', \
     'plots/shimmer.dat' index 10 using 1:2 with points lc rgb '#2ca02c' dt 2 pt 5 lw 1.5 title 'backface d32f', \
     'plots/shimmer.dat' index 11 using 1:2 with points lc rgb '#2ca02c' dt 4 pt 9 lw 1.5 title 'backface d32f_rz'
unset multiplot
