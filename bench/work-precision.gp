# work-precision.gp -- the work-precision diagram of `make bench' (after
# doc/figures/style.gp): max relative error (x) against ns per collision
# (y), log-log, one curve per method swept over its tolerance or precision
# (labelled; labels of points of a method at the same error are stacked
# below the first), the baseline, eh-only and certified rows as points
# (the certified method's where the CSV has them: a build with Arb);
# SciPy's solve_ivp rows (bench/scipy-ivp.py) where the CSV has them.
#   gnuplot -e "csv = 'bench/work-precision.csv'" \
#     -e "png = 'doc/figures/work-precision.png'" \
#     doc/figures/style.gp bench/work-precision.gp
set output png
set title 'Work-precision of one step of the return map (B.3)/(B.4), make bench'
set logscale xy
set format x '10^{%L}'
set format y '10^{%L}'
set xrange [1e-17:1]
set xlabel "max relative error over the states (E', H', heading and time increments)"
set ylabel 'ns per collision (minimum of repetitions)'
set key bottom right box opaque
eps = 2.0**-52
set arrow from eps, graph 0 to eps, graph 1 nohead dt 3 lc rgb '#888888'
set label 'eps' at eps, graph 0.97 offset 0.5, 0 tc rgb '#888888'
sel(m) = strcol('method') eq m ? column('max_rel_error') : NaN
# the SciPy rows are there only where make bench found SciPy: their key
# entry only then
stats csv using (strcol('method') eq 'scipy-dop853' ? 1 : 0) name 'SCIPY' nooutput
scipy_title = SCIPY_sum > 0 ? 'SciPy solve_ivp DOP853 (one segment), rtol' : ''
stats csv using (strcol('method') eq 'certified' ? 1 : 0) name 'CERT' nooutput
cert_title = CERT_sum > 0 ? 'certified (correctly rounded; lower: E, H only)' : ''
# the y of a label: that of the point, or below the first point of a run
# of points with the same error
px = NaN; py = 0; j = 0; pm = ''
ylab(y) = (j = (column('max_rel_error') == px && strcol('method') eq pm \
                ? j + 1 : 0), \
           py = (j == 0 ? y : py), px = column('max_rel_error'), \
           pm = strcol('method'), py / 1.35**j)
labels = "font ',8' left offset 0.8, 0"
plot csv using (sel('ode')):'ns_per_collision' with linespoints pt 7 ps 1 lw 1.5 lc rgb '#c0392b' title 'ode (odeiv2 rk8pd), tol', \
     csv using (sel('ode')):(ylab(column('ns_per_collision'))):'setting' with labels @labels tc rgb '#c0392b' notitle, \
     csv using (sel('quadrature')):'ns_per_collision' with linespoints pt 5 ps 1 lw 1.5 lc rgb '#1f3b73' title 'quadrature (Gauss-Kronrod), tol', \
     csv using (sel('quadrature')):(ylab(column('ns_per_collision'))):'setting' with labels @labels tc rgb '#1f3b73' notitle, \
     csv using (sel('closed-form')):'ns_per_collision' with linespoints pt 9 ps 1.6 lw 1.5 lc rgb '#27ae60' title 'closed-form (Carlson), precision', \
     csv using (sel('closed-form')):(ylab(column('ns_per_collision'))):'setting' with labels @labels tc rgb '#27ae60' notitle, \
     csv using (sel('scipy-dop853')):'ns_per_collision' with linespoints pt 11 ps 1 lw 1.5 dt 2 lc rgb '#d35400' title scipy_title noenhanced, \
     csv using (sel('scipy-dop853')):(ylab(column('ns_per_collision'))):'setting' with labels @labels tc rgb '#d35400' notitle, \
     csv using (sel('certified')):'ns_per_collision' with points pt 15 ps 1.6 lc rgb '#16a085' title cert_title noenhanced, \
     csv using (sel('certified')):'ns_per_collision':'setting' with labels @labels tc rgb '#16a085' notitle, \
     csv using (sel('eh-only')):'ns_per_collision' with points pt 13 ps 1.6 lc rgb '#8e44ad' title 'eh-only (E, H only; lower: n steps per call)', \
     csv using (sel('baseline')):'ns_per_collision' with points pt 3 ps 1.6 lc rgb 'black' title 'baseline (bare (E, H) arithmetic)'
