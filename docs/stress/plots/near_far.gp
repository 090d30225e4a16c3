# shadowmap-stress: Light near/far ratio forced (near_plane, far_plane)
# remake from the output folder: gnuplot plots/near_far.gp
set terminal pngcairo noenhanced size 1100,720 font ',9'
set output 'near_far.png'
set multiplot layout 2,1 title 'Light near/far ratio forced (near_plane, far_plane): error = acne + leak, % of the evaluation set'
set grid
set key outside right top
set ylabel 'error % (log; 0 drawn at 0.001)'
set xlabel 'near / far'
set logscale y
set yrange [0.001:100]
set xtics ('1e-2' 0.01, '1e-3' 0.001, '1e-4' 0.0001, '1e-5' 1e-05, '1e-6' 1e-06, '1e-7' 1e-07, 'inf' 1e-08)
set logscale x
set xrange [0.016:6.25e-09]
set title 'spot light'
plot 'plots/near_far.dat' index 0 using 1:2 with linespoints lc rgb '#1f77b4' dt 3 pt 6 lw 1.5 title 'standard d16', \
     'plots/near_far.dat' index 1 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 lw 1.5 title 'standard d24', \
     'plots/near_far.dat' index 2 using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 lw 1.5 title 'standard d32f', \
     'plots/near_far.dat' index 3 using 1:2 with linespoints lc rgb '#1f77b4' dt 4 pt 9 lw 1.5 title 'standard d32f_rz', \
     'plots/near_far.dat' index 4 using 1:2 with linespoints lc rgb '#d62728' dt 3 pt 6 lw 1.5 title 'woo d16', \
     'plots/near_far.dat' index 5 using 1:2 with linespoints lc rgb '#d62728' dt 1 pt 7 lw 1.5 title 'woo d24', \
     'plots/near_far.dat' index 6 using 1:2 with linespoints lc rgb '#d62728' dt 2 pt 5 lw 1.5 title 'woo d32f', \
     'plots/near_far.dat' index 7 using 1:2 with linespoints lc rgb '#d62728' dt 4 pt 9 lw 1.5 title 'woo d32f_rz', \
     'plots/near_far.dat' index 8 using 1:2 with linespoints lc rgb '#2ca02c' dt 3 pt 6 lw 1.5 title 'backface d16', \
     'plots/near_far.dat' index 9 using 1:2 with linespoints lc rgb '#2ca02c' dt 1 pt 7 lw 1.5 title 'backface d24', \
     'plots/near_far.dat' index 10 using 1:2 with linespoints lc rgb '#2ca02c' dt 2 pt 5 lw 1.5 title 'backface d32f', \
     'plots/near_far.dat' index 11 using 1:2 with linespoints lc rgb '#2ca02c' dt 4 pt 9 lw 1.5 title 'backface d32f_rz'
set title 'point light'
plot 'plots/near_far.dat' index 12 using 1:2 with linespoints lc rgb '#1f77b4' dt 3 pt 6 lw 1.5 title 'standard d16', \
     'plots/near_far.dat' index 13 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 lw 1.5 title 'standard d24', \
     'plots/near_far.dat' index 14 using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 lw 1.5 title 'standard d32f', \
     'plots/near_far.dat' index 15 using 1:2 with linespoints lc rgb '#1f77b4' dt 4 pt 9 lw 1.5 title 'standard d32f_rz', \
     'plots/near_far.dat' index 16 using 1:2 with linespoints lc rgb '#d62728' dt 3 pt 6 lw 1.5 title 'woo d16', \
     'plots/near_far.dat' index 17 using 1:2 with linespoints lc rgb '#d62728' dt 1 pt 7 lw 1.5 title 'woo d24', \
     'plots/near_far.dat' index 18 using 1:2 with linespoints lc rgb '#d62728' dt 2 pt 5 lw 1.5 title 'woo d32f', \
     'plots/near_far.dat' index 19 using 1:2 with linespoints lc rgb '#d62728' dt 4 pt 9 lw 1.5 title 'woo d32f_rz', \
     'plots/near_far.dat' index 20 using 1:2 with linespoints lc rgb '#2ca02c' dt 3 pt 6 lw 1.5 title 'backface d16', \
     'plots/near_far.dat' index 21 using 1:2 with linespoints lc rgb '#2ca02c' dt 1 pt 7 lw 1.5 title 'backface d24', \
     'plots/near_far.dat' index 22 using 1:2 with linespoints lc rgb '#2ca02c' dt 2 pt 5 lw 1.5 title 'backface d32f', \
     'plots/near_far.dat' index 23 using 1:2 with linespoints lc rgb '#2ca02c' dt 4 pt 9 lw 1.5 title 'backface d32f_rz'
unset multiplot
