# shadowmap-stress: Special cases
# remake from the output folder: gnuplot plots/special.gp
set terminal pngcairo noenhanced size 1100,1080 font ',9'
set output 'special.png'
set multiplot layout 3,1 title 'Special cases: error = acne + leak, % of the evaluation set'
set grid
set key outside right top
set ylabel 'error % (log; 0 drawn at 0.001)'
set xlabel 'case'
set logscale y
set yrange [0.001:100]
set xtics ('light_inside_box' 1, 'light_on_surface' 2, 'camera_at_light' 3, 'light_straight_down' 4, 'masked_fence' 5, 'opaque_fence' 6) rotate by -15
unset logscale x
set xrange [0.5:6.5]
set title 'spot light'
plot 'plots/special.dat' index 0 using 1:2 with points lc rgb '#1f77b4' dt 3 pt 6 lw 1.5 title 'standard d16', \
     'plots/special.dat' index 1 using 1:2 with points lc rgb '#1f77b4' dt 1 pt 7 lw 1.5 title 'standard d24', \
     'plots/special.dat' index 2 using 1:2 with points lc rgb '#1f77b4' dt 2 pt 5 lw 1.5 title 'standard d32f', \
     'plots/special.dat' index 3 using 1:2 with points lc rgb '#1f77b4' dt 4 pt 9 lw 1.5 title 'standard d32f_rz', \
     'plots/special.dat' index 4 using 1:2 with points lc rgb '#d62728' dt 3 pt 6 lw 1.5 title 'woo d16', \
     'plots/special.dat' index 5 using 1:2 with points lc rgb '#d62728' dt 1 pt 7 lw 1.5 title 'woo d24', \
     'plots/special.dat' index 6 using 1:2 with points lc rgb '#d62728' dt 2 pt 5 lw 1.5 title 'woo d32f', \
     'plots/special.dat' index 7 using 1:2 with points lc rgb '#d62728' dt 4 pt 9 lw 1.5 title 'woo d32f_rz', \
     'plots/special.dat' index 8 using 1:2 with points lc rgb '#2ca02c' dt 3 pt 6 lw 1.5 title 'backface d16', \
     'plots/special.dat' index 9 using 1:2 with points lc rgb '#2ca02c' dt 1 pt 7 lw 1.5 title 'backface d24', \
     'plots/special.dat' index 10 using 1:2 with points lc rgb '#2ca02c' dt 2 pt 5 lw 1.5 title 'backface d32f', \
     'plots/special.dat' index 11 using 1:2 with points lc rgb '#2ca02c' dt 4 pt 9 lw 1.5 title 'backface d32f_rz'
set title 'directional light'
plot 'plots/special.dat' index 12 using 1:2 with points lc rgb '#1f77b4' dt 3 pt 6 lw 1.5 title 'standard d16', \
     'plots/special.dat' index 13 using 1:2 with points lc rgb '#1f77b4' dt 1 pt 7 lw 1.5 title 'standard d24', \
     'plots/special.dat' index 14 using 1:2 with points lc rgb '#1f77b4' dt 2 pt 5 lw 1.5 title 'standard d32f', \
     'plots/special.dat' index 15 using 1:2 with points lc rgb '#1f77b4' dt 4 pt 9 lw 1.5 title 'standard d32f_rz', \
     'plots/special.dat' index 16 using 1:2 with points lc rgb '#d62728' dt 3 pt 6 lw 1.5 title 'woo d16', \
     'plots/special.dat' index 17 using 1:2 with points lc rgb '#d62728' dt 1 pt 7 lw 1.5 title 'woo d24', \
     'plots/special.dat' index 18 using 1:2 with points lc rgb '#d62728' dt 2 pt 5 lw 1.5 title 'woo d32f', \
     'plots/special.dat' index 19 using 1:2 with points lc rgb '#d62728' dt 4 pt 9 lw 1.5 title 'woo d32f_rz', \
     'plots/special.dat' index 20 using 1:2 with points lc rgb '#2ca02c' dt 3 pt 6 lw 1.5 title 'backface d16', \
     'plots/special.dat' index 21 using 1:2 with points lc rgb '#2ca02c' dt 1 pt 7 lw 1.5 title 'backface d24', \
     'plots/special.dat' index 22 using 1:2 with points lc rgb '#2ca02c' dt 2 pt 5 lw 1.5 title 'backface d32f', \
     'plots/special.dat' index 23 using 1:2 with points lc rgb '#2ca02c' dt 4 pt 9 lw 1.5 title 'backface d32f_rz'
set title 'point light'
plot 'plots/special.dat' index 24 using 1:2 with points lc rgb '#1f77b4' dt 3 pt 6 lw 1.5 title 'standard d16', \
     'plots/special.dat' index 25 using 1:2 with points lc rgb '#1f77b4' dt 1 pt 7 lw 1.5 title 'standard d24', \
     'plots/special.dat' index 26 using 1:2 with points lc rgb '#1f77b4' dt 2 pt 5 lw 1.5 title 'standard d32f', \
     'plots/special.dat' index 27 using 1:2 with points lc rgb '#1f77b4' dt 4 pt 9 lw 1.5 title 'standard d32f_rz', \
     'plots/special.dat' index 28 using 1:2 with points lc rgb '#d62728' dt 3 pt 6 lw 1.5 title 'woo d16', \
     'plots/special.dat' index 29 using 1:2 with points lc rgb '#d62728' dt 1 pt 7 lw 1.5 title 'woo d24', \
     'plots/special.dat' index 30 using 1:2 with points lc rgb '#d62728' dt 2 pt 5 lw 1.5 title 'woo d32f', \
     'plots/special.dat' index 31 using 1:2 with points lc rgb '#d62728' dt 4 pt 9 lw 1.5 title 'woo d32f_rz', \
     'plots/special.dat' index 32 using 1:2 with points lc rgb '#2ca02c' dt 3 pt 6 lw 1.5 title 'backface d16', \
     'plots/special.dat' index 33 using 1:2 with points lc rgb '#2ca02c' dt 1 pt 7 lw 1.5 title 'backface d24', \
     'plots/special.dat' index 34 using 1:2 with points lc rgb '#2ca02c' dt 2 pt 5 lw 1.5 title 'backface d32f', \
     'plots/special.dat' index 35 using 1:2 with points lc rgb '#2ca02c' dt 4 pt 9 lw 1.5 title 'backface d32f_rz'
unset multiplot
