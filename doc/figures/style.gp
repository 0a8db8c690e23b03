# style.gp -- common settings of the figures (gnuplot 5.4, pngcairo).
set datafile separator comma
set datafile columnheaders
set terminal pngcairo size 1200,760 font "DejaVu Sans,10" linewidth 1.3
set grid lc rgb "#dddddd"
set key noautotitle
discrete = "lc rgb '#1f3b73' lw 1.6"
smooth = "lc rgb '#c0392b' dt 2 lw 1.6"
