#!/bin/sh
# figure.sh FIG SCENEDIR OUTDIR -- run scenes/FIG.ini with $CHAPLYGIN and
# draw OUTDIR/FIG.png with $GNUPLOT (pngcairo).  Used by `make figures'.
# Trajectory figures: panels (a) the path in the plane (the slot front of
# the discrete skate, solid, pegs marked "+"; the smooth skate's contact
# point, dashed), then V, Omega, theta, E and H against time (dense output:
# the jumps at collisions show).  Figures 4 and 5: the (S, E/E_f, H)
# space curves.  Sweeps: Figure 2(a) curves, 2(b) regions, 3 basins.
set -eu
fig=$1 scenes=$2 out=$3
prog=${CHAPLYGIN:?CHAPLYGIN must name the program}
gp=${GNUPLOT:-gnuplot}
here=$(cd "$(dirname "$0")" && pwd)
tmp=$(mktemp -d "${TMPDIR:-/tmp}/figure.XXXXXX")
trap 'rm -rf "$tmp"' 0

"$prog" run "$scenes/$fig.ini" >"$tmp/d.csv"
if grep '^compare *=' "$scenes/$fig.ini" >/dev/null; then
  "$prog" run --compare "$scenes/$fig.ini" >"$tmp/s.csv"
  have_smooth=1
else
  have_smooth=0
fi
title=$(sed -n 's/^title *= *//p' "$scenes/$fig.ini")
png=$out/$fig.png

case $fig in
fig2a)
  cat >"$tmp/p.gp" <<EOF
    set output '$png'; set title '$title'
    set xlabel 'L_0/{/Symbol D}'; set ylabel '{/Symbol s}_4'
    set yrange [-3:3]; set key top left
    plot for [y in '0.01 0.1 0.25 0.5 1'] '$tmp/d.csv' \
      using 'x':(abs(column('y') - y) < 1e-12 ? column('sigma4') : NaN) \
      with lines lw 1.5 title sprintf('(1/{/Symbol D})^2 = %s', y), \
      1 with lines dt 3 lc rgb 'black' notitle, -1 with lines dt 3 lc rgb 'black' notitle
EOF
  "$gp" "$here/style.gp" "$tmp/p.gp"
  ;;
fig2b)
  cat >"$tmp/p.gp" <<EOF
    set output '$png'; set title '$title'
    set xlabel 'L_0/{/Symbol D}'; set ylabel '(1/{/Symbol D})^2'
    set palette defined (0 'white', 1 '#b0b0b0', 2 '#7fa7d9', 3 '#2c4f7c')
    set cbrange [-0.5:3.5]; set palette maxcolors 4; set cbtics ('unstable' 0, 'V*>0 stable' 1, 'V*<0 stable' 2, 'both' 3)
    set xrange [-4:2]; set yrange [0:1]
    plot '$tmp/d.csv' using 'x':'y':'region' with image
EOF
  "$gp" "$here/style.gp" "$tmp/p.gp"
  ;;
fig3)
  cat >"$tmp/p.gp" <<EOF
    set output '$png'; set title '$title'
    set xlabel 'initial V^+'; set ylabel 'fate'
    $(awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next }
      { v = $c["V0"]; f = $c["fate"]
        if (NR > 2 && f != fp) printf "set arrow from %.17g, graph 0 to %.17g, graph 1 nohead dt 3 lc rgb \"#888888\"\n", (v + vp) / 2, (v + vp) / 2
        fp = f; vp = v }' "$tmp/d.csv")
    set ytics ('V* < 0' -1, 'spin' 0, 'V* > 0' 1); set yrange [-1.5:1.5]
    set arrow from 1/sqrt(5), graph 0 to 1/sqrt(5), graph 1 nohead dt 2 lc rgb 'black'
    plot '$tmp/d.csv' using 'V0':'fate' with points pt 7 ps 0.3 lc rgb '#1f3b73'
EOF
  "$gp" "$here/style.gp" "$tmp/p.gp"
  ;;
fig4|fig5)
  # S along the discrete run: the arc length travelled by the slot over
  # the pegs, sum of |dD| within segments (D jumps at collisions, S does
  # not), as the library's S of the smooth sleigh (dS/dtau = |V|).
  awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; print "S,E,H"; next }
    { n = $c["n"]; D = $c["D"]
      if (NR > 2 && n == nprev) S += (D > Dp ? D - Dp : Dp - D)
      nprev = n; Dp = D; print S "," $c["E"] "," $c["H"] }' "$tmp/d.csv" >"$tmp/seh.csv"
  Ef=$(tail -n 1 "$tmp/seh.csv" | cut -d, -f2)
  # the smooth skate's energy (conserved): its first row
  Es=$(awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == "E") k = i; next }
    { print $k; exit }' "$tmp/s.csv")
  cat >"$tmp/p.gp" <<EOF
    set output '$png'; set title '$title'
    set xlabel 'S'; set ylabel 'E/E_f'; set zlabel 'H' rotate
    set view 60, 30; set key top left
    splot '$tmp/seh.csv' using 'S':(column('E')/$Ef):'H' with lines @discrete title 'discrete skate', \
          '$tmp/s.csv' using 'S':(column('E')/$Es):'H' with lines @smooth title 'smooth skate'
EOF
  "$gp" "$here/style.gp" "$tmp/p.gp"
  ;;
*)
  smoothplot () { if test $have_smooth = 1; then echo ", '$tmp/s.csv' using $1 with lines @smooth"; fi; }
  # the massless skate: the mass centre just after each collision (Fig.
  # 10(a)), from a run without dense output
  gplot=
  if grep '^model *= *massless' "$scenes/$fig.ini" >/dev/null; then
    sed '/^samples *=/d' "$scenes/$fig.ini" >"$tmp/c.ini"
    "$prog" run "$tmp/c.ini" >"$tmp/c.csv"
    gplot=", '$tmp/c.csv' using 'G_x':'G_y' with linespoints pt 6 ps 1 dt 3 lc rgb '#c0392b'"
    ptitle='(a) path (slot front; pegs +; G o)'
  else
    ptitle='(a) path (slot front; pegs +)'
  fi
  cat >"$tmp/p.gp" <<EOF
    set output '$png'
    set multiplot layout 2,3 title '$title'
    set title '$ptitle'; set size ratio -1
    set xlabel 'x/{/Symbol r}'; set ylabel 'y/{/Symbol r}'
    plot '$tmp/d.csv' using 'x':'y' with lines @discrete, \
         '$tmp/d.csv' using 'peg_x':'peg_y' with points pt 1 ps 1.2 lc rgb 'black' $gplot $(smoothplot "'x':'y'")
    set size noratio; set xlabel '{/Symbol t}'
    set title '(b) V'; set ylabel 'V'
    plot '$tmp/d.csv' using 'tau':'V' with lines @discrete $(smoothplot "'tau':'V'")
    set title '(c) {/Symbol W}'; set ylabel '{/Symbol W}'
    plot '$tmp/d.csv' using 'tau':'Omega' with lines @discrete $(smoothplot "'tau':'Omega'")
    set title '(d) {/Symbol q}'; set ylabel '{/Symbol q} (rad)'
    plot '$tmp/d.csv' using 'tau':'theta' with lines @discrete $(smoothplot "'tau':'theta'")
    set title '(e) E'; set ylabel 'E'
    plot '$tmp/d.csv' using 'tau':'E' with lines @discrete $(smoothplot "'tau':'E'")
    set title '(f) H (discrete: about the peg; smooth: about C)'; set ylabel 'H'
    plot '$tmp/d.csv' using 'tau':'H' with lines @discrete $(smoothplot "'tau':'H'")
    unset multiplot
EOF
  "$gp" "$here/style.gp" "$tmp/p.gp"
  ;;
esac
