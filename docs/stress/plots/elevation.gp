# shadowmap-stress: Light elevation over the floor (grazing at the end)
# remake from the output folder: gnuplot plots/elevation.gp
set terminal pngcairo noenhanced size 1100,720 font ',9'
set output 'elevation.png'
set multiplot layout 2,1 title 'Light elevation over the floor (grazing at the end): error = acne + leak, % of the evaluation set'
set grid
set key outside right top
set ylabel 'error % (log; 0 drawn at 0.001)'
set xlabel 'elevation (degrees)'
set logscale y
set yrange [0.001:100]
set xtics ('45' 45, '30' 30, '15' 15, '5' 5, '2' 2, '1' 1, '0.5' 0.5)
set logscale x
set xrange [72:0.3125]
set title 'spot light'
plot 'plots/elevation.dat' index 0 using 1:2 with linespoints lc rgb '#1f77b4' dt 3 pt 6 lw 1.5 title 'standard d16', \
     'plots/elevation.dat' index 1 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 lw 1.5 title 'standard d24', \
     'plots/elevation.dat' index 2 using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 lw 1.5 title 'standard d32f', \
     'plots/elevation.dat' index 3 using 1:2 with linespoints lc rgb '#1f77b4' dt 4 pt 9 lw 1.5 title 'standard d32f_rz', \
     'plots/elevation.dat' index 4 using 1:2 with linespoints lc rgb '#d62728' dt 3 pt 6 lw 1.5 title 'woo d16', \
     'plots/elevation.dat' index 5 using 1:2 with linespoints lc rgb '#d62728' dt 1 pt 7 lw 1.5 title 'woo d24', \
     'plots/elevation.dat' index 6 using 1:2 with linespoints lc rgb '#d62728' dt 2 pt 5 lw 1.5 title 'woo d32f', \
     'plots/elevation.dat' index 7 using 1:2 with linespoints lc rgb '#d62728' dt 4 pt 9 lw 1.5 title 'woo d32f_rz', \
     'plots/elevation.dat' index 8 using 1:2 with linespoints lc rgb '#2ca02c' dt 3 pt 6 lw 1.5 title 'backface d16', \
     'plots/elevation.dat' index 9 using 1:2 with linespoints lc rgb '#2ca02c' dt 1 pt 7 lw 1.5 title 'backface d24', \
     'plots/elevation.dat' index 10 using 1:2 with linespoints lc rgb '#2ca02c' dt 2 pt 5 lw 1.5 title 'backface d32f', \
     'plots/elevation.dat' index 11 using 1:2 with linespoints lc rgb '#2ca02c' dt 4 pt 9 lw 1.5 title 'backface d32f_rz'
set title 'directional light'
plot 'plots/elevation.dat' index 12 using 1:2 with linespoints lc rgb '#1f77b4' dt 3 pt 6 lw 1.5 title 'standard d16', \
     'plots/elevation.dat' index 13 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 lw 1.5 title 'standard d24', \
     'plots/elevation.dat' index 14 using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 lw 1.5 title 'standard d32f', \
     'plots/elevation.dat' index 15 using 1:2 with linespoints lc rgb '#1f77b4' dt 4 pt 9 lw 1.5 title 'standard d32f_rz', \
     'plots/elevation.dat' index 16 using 1:2 with linespoints lc rgb '#d62728' dt 3 pt 6 lw 1.5 title 'woo d16', \
     'plots/elevation.dat' index 17 using 1:2 with linespoints lc rgb '#d62728' dt 1 pt 7 lw 1.5 title 'woo d24', \
     'plots/elevation.dat' index 18 using 1:2 with linespoints lc rgb '#d62728' dt 2 pt 5 lw 1.5 title 'woo d32f', \
     'plots/elevation.dat' index 19 using 1:2 with linespoints lc rgb '#d62728' dt 4 pt 9 lw 1.5 title 'woo d32f_rz', \
     'plots/elevation.dat' index 20 using 1:2 with linespoints lc rgb '#2ca02c' dt 3 pt 6 lw 1.5 title 'backface d16', \
     'plots/elevation.dat' index 21 using 1:2 with linespoints lc rgb '#2ca02c' dt 1 pt 7 lw 1.5 title 'backface d24', \
     'plots/elevation.dat' index 22 using 1:2 with linespoints lc rgb '#2ca02c' dt 2 pt 5 lw 1.5 title 'backface d32f', \
     'plots/elevation.dat' index 23 using 1:2 with linespoints lc rgb '#2ca02c' dt 4 pt 9 lw 1.5 title 'backface d32f_rz'
unset multiplot
