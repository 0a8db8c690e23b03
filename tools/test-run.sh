#!/bin/sh
# test-run.sh -- TAP tests of "chaplygin run": scenes of the discrete,
# massless and smooth sleighs, their CSV, the stats that show only what
# is asked for is computed, dense output, error handling.
# Run by `make check' (automake's TAP driver), or by hand:
#   top_builddir=. top_srcdir=. sh tools/test-run.sh
#   CHAPLYGIN=/path/to/chaplygin sh tools/test-run.sh
# POSIX sh only (runs under dash); numbers are compared with awk.

set -u

top_builddir=${top_builddir:-.}
prog=${CHAPLYGIN:-$top_builddir/tools/chaplygin}

. "${top_srcdir:-.}/tools/tap-lib.sh"
tap_start test-run 42

# explain: show the last stderr in the log.
explain () {
  echo "# exit $rc" >&2
  sed 's/^/# stderr: /' "$tmp/err" >&2
}

# stat NAME: the counter NAME of the last "--stats" line in $tmp/err.
stat () {
  sed -n "s/.*stats:.*[ ]$1=\([0-9]*\).*/\1/p" "$tmp/err" | tail -n 1
}

# A discrete scene: discrete NAME L0 DELTA V OMEGA COLLISIONS [EXTRA-LINES]
discrete () {
  {
    printf '[scene]\nmodel = discrete\n[parameters]\nL0 = %s\nDelta = %s\n' "$2" "$3"
    printf '[initial]\nV = %s\nOmega = %s\n[run]\ncollisions = %s\n' "$4" "$5" "$6"
    if test $# -ge 7; then printf '%s\n' "$7"; fi
  } >"$tmp/$1.ini"
}

# The awk functions shared by the numeric checks.
awk_lib='
function abs(x) { return x < 0 ? -x : x }
function rel(a, b,   s) {
  s = abs(a) > abs(b) ? abs(a) : abs(b)
  if (s < 1) s = 1
  return abs(a - b) / s
}'

# check_dense DENSE.csv COLLISIONS.csv: the dense rows of each segment
# against the per-collision rows of the same scene: the last row of
# segment n (just before collision n) has the heading, time, slot front
# and mass centre of row n within 1e-12 relative; E, H constant within a
# segment; tau strictly increasing within a segment, and across a
# collision non-decreasing to rounding (a segment's end is computed from
# its start, the next start is the step's);
# theta monotone within a segment, with the sign of H; V changes sign
# inside exactly the reversing segments, and is 0 at the turning point.
check_dense () {
  awk -F, "$awk_lib"'
    FNR == 1 { for (i = 1; i <= NF; i++) c[FILENAME, $i] = i; next }
    NR == FNR {
      n = $c[FILENAME, "n"]; k = $c[FILENAME, "k"]
      tau = $c[FILENAME, "tau"] + 0; th = $c[FILENAME, "theta"] + 0
      if (k == 0 && rel(tau, last_tau) > 1e-12 && tau < last_tau) {
        print "# tau decreases at segment " n; bad = 1
      }
      if (k == 0) {
        E[n] = $c[FILENAME, "E"]; H[n] = $c[FILENAME, "H"]
        vmin[n] = 1e300; vmax[n] = -1e300; zero[n] = 0
      } else {
        if ($c[FILENAME, "E"] != E[n] || $c[FILENAME, "H"] != H[n]) {
          print "# E or H not constant in segment " n; bad = 1
        }
        if (!(tau > last_tau)) { print "# tau not increasing in segment " n; bad = 1 }
        if ((H[n] > 0 && th < last_th) || (H[n] < 0 && th > last_th)) {
          print "# theta not monotone in segment " n; bad = 1
        }
      }
      v = $c[FILENAME, "V"] + 0
      D = $c[FILENAME, "D"] + 0
      # between rows of a leg, D moves the way V points
      if (k > 0 && v != 0 && last_v != 0 && (v > 0) == (last_v > 0) \
          && (D - last_D) * v < 0) {
        print "# V against the motion in segment " n; bad = 1
      }
      last_v = v; last_D = D
      if (v < vmin[n]) vmin[n] = v
      if (v > vmax[n]) vmax[n] = v
      if (v == 0) zero[n] = 1
      last_tau = tau; last_th = th
      th_end[n] = th; tau_end[n] = tau
      x_end[n] = $c[FILENAME, "x"]; y_end[n] = $c[FILENAME, "y"]
      gx_end[n] = $c[FILENAME, "G_x"]; gy_end[n] = $c[FILENAME, "G_y"]
      nseg = n
      next
    }
    {
      n = $c[FILENAME, "n"]
      if (n == 0) next
      d = rel(th_end[n], $c[FILENAME, "theta"]); if (d > m) m = d
      d = rel(tau_end[n], $c[FILENAME, "tau"]); if (d > m) m = d
      d = rel(x_end[n], $c[FILENAME, "x"]); if (d > m) m = d
      d = rel(y_end[n], $c[FILENAME, "y"]); if (d > m) m = d
      d = rel(gx_end[n], $c[FILENAME, "G_x"]); if (d > m) m = d
      d = rel(gy_end[n], $c[FILENAME, "G_y"]); if (d > m) m = d
      rev = $c[FILENAME, "reversal"]
      flips = vmin[n] < 0 && vmax[n] > 0
      if (rev == 1 && !(flips && zero[n])) { print "# segment " n " reverses, V does not"; bad = 1 }
      if (rev == 0 && flips) { print "# V changes sign in segment " n; bad = 1 }
      nrev += rev; checked++
    }
    END {
      printf "# %d segments (%d reversing), largest difference %.3g\n", checked, nrev, m
      exit (bad || m > 1e-12 || checked != nseg || checked == 0 || nrev == 0) ? 1 : 0
    }
  ' "$1" "$2" >&2
}

all='outputs = E,H,theta,tau,peg,V,Omega,path,G'

# ---- 1-4: a discrete scene is "chaplygin skate" -----------------------
discrete fig6 1 0.3333333333333333 1 0.5 20
run run "$tmp/fig6.ini"
cp "$tmp/out" "$tmp/fig6.csv"
"$prog" skate >"$tmp/skate.csv" 2>/dev/null
csv_only "$tmp/skate.csv"
ok=1
test "$rc" -eq 0 && cmp -s "$tmp/fig6.csv" "$tmp/skate.csv" && ok=0
test "$ok" -eq 0 || explain
result "$ok" "discrete scene = chaplygin skate with the same parameters (identical CSV)"

discrete back -2.3570226039551585 3.5355339059327378 -1 0.1 15 "method = quadrature
tolerance = 1e-13"
run run "$tmp/back.ini"
"$prog" skate --L0 -2.3570226039551585 --Delta 3.5355339059327378 --V -1 \
  --Omega 0.1 --collisions 15 --method quadrature --tol 1e-13 \
  >"$tmp/skate.csv" 2>/dev/null
csv_only "$tmp/skate.csv"
ok=1
test "$rc" -eq 0 && cmp -s "$tmp/out" "$tmp/skate.csv" && ok=0
result "$ok" "V < 0, method = quadrature: identical to skate"

run run "$tmp/fig6.ini" --stats
ok=1
test "$rc" -eq 0 && test "$(stat steps)" = 20 && test "$(stat heading_evals)" = 20 \
  && ok=0
test "$ok" -eq 0 || explain
result "$ok" "--stats: steps=20, heading_evals=20 for the default outputs"

run run "$tmp/fig6.ini" --stats
ok=1
test "$rc" -eq 0 && cmp -s "$tmp/out" "$tmp/fig6.csv" && ok=0
result "$ok" "--stats leaves the CSV unchanged"

# ---- 5-8: model only what the scene requires ---------------------------
discrete eh 1 0.3333333333333333 1 0.5 2000 "outputs = H,E"
discrete ehfull 1 0.3333333333333333 1 0.5 2000 "$all"
run run "$tmp/eh.ini" --stats
cp "$tmp/out" "$tmp/eh.csv"
ok=1
test "$rc" -eq 0 && test "$(stat heading_evals)" = 0 && test "$(stat steps)" = 2000 \
  && ok=0
test "$ok" -eq 0 || explain
result "$ok" "outputs = H,E: 2000 steps, heading_evals=0 (no elliptic integral)"

ok=1
test "$(head -n 1 "$tmp/eh.csv")" = "n,D,reversal,E,H" && ok=0
result "$ok" "outputs = H,E: header n,D,reversal,E,H (canonical order)"

run run "$tmp/ehfull.ini" --stats
ok=1
if test "$rc" -eq 0 && test "$(stat heading_evals)" = 2000; then
  cut -d, -f1-5 "$tmp/out" | cmp -s - "$tmp/eh.csv" && ok=0
fi
result "$ok" "the full run has heading_evals=2000 and the same n,D,reversal,E,H"

ok=1
test "$(head -n 1 "$tmp/out")" = \
  "n,D,reversal,E,H,theta,tau,peg_x,peg_y,V,Omega,x,y,G_x,G_y" && ok=0
result "$ok" "all outputs: header n,D,reversal,E,H,theta,tau,peg_x,peg_y,V,Omega,x,y,G_x,G_y"

# ---- 9-11: per-collision geometry --------------------------------------
# Figure 7's skate, backwards: pegs at both ends in turn
discrete geo -2.3570226039551585 3.5355339059327378 -1 0.9 12 "$all"
run run "$tmp/geo.ini"
ok=1
test "$rc" -eq 0 && awk -F, "$awk_lib"'
  NR == 1 { next }
  {
    # slot front = peg + D e, G = front + L0 e, Omega+ = H/(1 + l^2)
    L0 = -2.3570226039551585
    c = cos($6); s = sin($6); l = L0 + $2
    if (rel($12, $8 + $2 * c) > 1e-13 || rel($13, $9 + $2 * s) > 1e-13) bad = 1
    if (rel($14, $12 + L0 * c) > 1e-13 || rel($15, $13 + L0 * s) > 1e-13) bad = 1
    if (rel($11, $5 / (1 + l * l)) > 1e-13) bad = 1
    if (($10 < 0) != ($2 > 0)) bad = 1
    if ($2 > 0) rear++; else front++
    if (NR == 2 && ($10 != -1 || $11 != 0.9)) bad = 1
  }
  END { exit (bad || !rear || !front) ? 1 : 0 }
' "$tmp/out" && ok=0
result "$ok" "x,y = peg + D e, G = front + L0 e, Omega = H/(1 + l^2), sgn V, row 0 as given"

discrete spin -0.75 1.5 15 16 5
run run "$tmp/spin.ini"
ok=1
test "$rc" -eq 1 && test "$(wc -l <"$tmp/out" | tr -d ' ')" = 2 \
  && grep "spin.ini: collision 1: .*spinning" "$tmp/err" >/dev/null && ok=0
test "$ok" -eq 0 || explain
result "$ok" "a motion into the spinning equilibrium: exit 1, row 0 written, 'collision 1'"

# A slow start: V+ = 1e-10 beside l Omega = 1, which E and H alone lose
# (V+^2 below their rounding); the state keeps V+.  Reference: 40-digit
# tanh-sinh quadrature (mpmath) of Omega/V and 1/V from the phase state,
# V^2 = V0^2 + D (2 L0 + D) (1 + L0^2) Omega0^2/(1 + (L0 + D)^2).
discrete tiny 1 0.3 1e-10 1 5 "outputs = theta,tau"
run run "$tmp/tiny.ini"
ok=1
test "$rc" -eq 0 && awk -F, "$awk_lib"'
  $1 == 1 { got = 1
            # 16 eps relative (the closed form: test_map)
            if (rel($4, 0.7210948537883594738502921) > 16 * 2.220446e-16) exit 1
            if (rel($5, 0.7950424984909253398291428) > 16 * 2.220446e-16) exit 1 }
  END { exit got ? 0 : 1 }' "$tmp/out" && ok=0
test "$ok" -eq 0 || explain
result "$ok" "a slow start (V+ = 1e-10 beside l Omega = 1): theta, tau of collision 1 within 16 eps of 40-digit quadrature"

# ---- 12-17: dense output -----------------------------------------------
# Figure 7's skate from a state with three reversing segments.
discrete rev -2.3570226039551585 3.5355339059327378 1 0.9 30 "$all"
discrete revd -2.3570226039551585 3.5355339059327378 1 0.9 30 "$all
samples = 9"
run run "$tmp/rev.ini"
cp "$tmp/out" "$tmp/rev.csv"
run run "$tmp/revd.ini" --stats
cp "$tmp/out" "$tmp/revd.csv"
ok=1
test "$rc" -eq 0 && check_dense "$tmp/revd.csv" "$tmp/rev.csv" && ok=0
test "$ok" -eq 0 || explain
result "$ok" "dense (closed form): segment ends = collision rows within 1e-12, E, H constant, V flips in reversing segments"

ok=1
test "$(head -n 1 "$tmp/revd.csv")" = \
  "n,k,reversal,tau,D,E,H,theta,peg_x,peg_y,V,Omega,x,y,G_x,G_y" && ok=0
result "$ok" "dense header n,k,reversal,tau,D,E,H,theta,peg_x,peg_y,V,Omega,x,y,G_x,G_y"

# rows: N + 2 per segment (start, N samples, end); a reversing one has
# floor(N/2) on each leg and the turning point: N + 3 rows for N even
# rows_ok FILE N SEGMENTS
rows_ok () {
  awk -F, -v N="$2" -v nseg="$3" 'NR > 1 { rows[$1]++; rev[$1] = $3 }
    END {
      for (n = 1; n <= nseg; n++)
        if (rows[n] != N + 2 + (rev[n] && N % 2 == 0)) bad = 1
      exit bad ? 1 : 0
    }' "$1"
}
ok=1
rows_ok "$tmp/revd.csv" 9 30 && ok=0
result "$ok" "dense, N = 9: N + 2 rows per segment (start, 4 + turning point + 4, end)"

for method in quadrature ode; do
  discrete revm -2.3570226039551585 3.5355339059327378 1 0.9 30 "$all
method = $method
tolerance = 1e-13"
  discrete revmd -2.3570226039551585 3.5355339059327378 1 0.9 30 "$all
method = $method
tolerance = 1e-13
samples = 6"
  run run "$tmp/revm.ini"
  cp "$tmp/out" "$tmp/revm.csv"
  run run "$tmp/revmd.ini"
  ok=1
  test "$rc" -eq 0 && check_dense "$tmp/out" "$tmp/revm.csv" \
    && rows_ok "$tmp/out" 6 30 && ok=0
  test "$ok" -eq 0 || explain
  result "$ok" "dense with method = $method: consistent with its own collisions"
done

discrete notau 1 0.3333333333333333 1 0.5 3 "outputs = E,V
samples = 2"
run run "$tmp/notau.ini" --stats
ok=1
test "$rc" -eq 0 && test "$(head -n 1 "$tmp/out")" = "n,k,reversal,tau,D,E,V" \
  && test "$(stat heading_evals)" = 12 && ok=0
test "$ok" -eq 0 || explain
result "$ok" "dense without tau in outputs: tau still a column; 3 steps + 3 x (2 samples + end) timed"

# ---- 18-21: the massless skate -----------------------------------------
massless () {
  {
    printf '[scene]\nmodel = massless\n[parameters]\nL0 = %s\n' "$2"
    printf '[initial]\nV = %s\nOmega = %s\n[run]\ncollisions = %s\n' "$3" "$4" "$5"
    if test $# -ge 6; then printf '%s\n' "$6"; fi
  } >"$tmp/$1.ini"
}
massless p2 -0.6666666666666666 1 0.9 10 "$all"
run run "$tmp/p2.ini"
cp "$tmp/out" "$tmp/p2.csv"
ok=1
test "$rc" -eq 0 && awk -F, "$awk_lib"'
  NR == 1 { next }
  { E[$1] = $4; H[$1] = $5; th[$1] = $6; rev[$1] = $3 }
  END {
    for (n = 0; n + 2 <= 10; n++) {
      if (rel(E[n], E[n + 2]) > 1e-13 || rel(H[n], H[n + 2]) > 1e-13) bad = 1
      if (rel(th[n], th[n + 2]) > 1e-13) bad = 1
      if (n > 0 && rev[n] != 1) bad = 1
    }
    exit bad ? 1 : 0
  }' "$tmp/p2.csv" && ok=0
test "$ok" -eq 0 || explain
result "$ok" "massless L0 = -2/3: period 2 (rows n, n+2: E, H, theta within 1e-13), every segment reverses"

massless p2d -0.6666666666666666 1 0.9 10 "$all
samples = 7"
run run "$tmp/p2d.ini"
ok=1
test "$rc" -eq 0 && check_dense "$tmp/out" "$tmp/p2.csv" && ok=0
test "$ok" -eq 0 || explain
result "$ok" "massless dense: segment ends = collision rows, V flips at the turning point"

# G moves on a straight line at speed sqrt(2E) within a segment
ok=1
awk -F, "$awk_lib"'
  NR == 1 { next }
  $2 == 0 { n = $1; x0 = $15; y0 = $16; t0 = $4; s = sqrt(2 * $6); next }
  $4 > t0 {
    d = sqrt(($15 - x0)^2 + ($16 - y0)^2)
    if (rel(d, s * ($4 - t0)) > 1e-12) { bad = 1; print "# segment " n ": |G - G0| != s tau" }
  }
  END { exit bad ? 1 : 0 }' "$tmp/out" >&2 && ok=0
result "$ok" "massless dense: G moves at the constant speed sqrt(2E) on a straight line"

massless espin 0 -1 1 5
run run "$tmp/espin.ini"
ok=1
test "$rc" -eq 1 && grep "espin.ini: collision 1:" "$tmp/err" >/dev/null && ok=0
result "$ok" "massless L0 = 0: the new peg on the point mass: exit 1 at collision 1"

# ---- 22-27: the smooth sleigh ------------------------------------------
smooth () {
  {
    printf '[scene]\nmodel = smooth\n[parameters]\nL = %s\n' "$2"
    printf '[initial]\nV = %s\nOmega = %s\ntheta = 0.3\n[run]\nduration = %s\n' "$3" "$4" "$5"
    if test $# -ge 6; then printf '%s\n' "$6"; fi
  } >"$tmp/$1.ini"
}
smooth sm -0.7 1 0.8 12 "outputs = G,path,Omega,V,theta,H,E,tau"
run run "$tmp/sm.ini" --stats
cp "$tmp/out" "$tmp/sm.csv"
ok=1
test "$rc" -eq 0 && test "$(head -n 1 "$tmp/sm.csv")" = "S,tau,E,H,theta,V,Omega,x,y,G_x,G_y" \
  && test "$(wc -l <"$tmp/sm.csv" | tr -d ' ')" = 202 && ok=0
test "$ok" -eq 0 || explain
result "$ok" "smooth: header S,tau,E,H,theta,V,Omega,x,y,G_x,G_y and 201 rows by default"

ok=1
awk -F, "$awk_lib"'
  NR == 1 { next }
  NR == 2 { E0 = $3; H0 = $4 }
  { if (abs($3 - E0) > 1e-13 * E0) bad = 1 }
  { if ($4 != 1.49 * $7 && rel($4, 1.49 * $7) > 1e-15) bad = 1 }
  { if ($6 < 0) flips = 1 }
  END { exit (bad || !flips) ? 1 : 0 }' "$tmp/sm.csv" && ok=0
result "$ok" "smooth: E conserved to 1e-13 relative through the reversal, H = (1 + L^2) Omega"

ok=1
awk -F, 'END { exit ($2 == "12") ? 0 : 1 }' "$tmp/sm.csv" && ok=0
result "$ok" "smooth: the last row is at tau = duration exactly"

# equally spaced in tau; the arc length grows by at most sqrt(2E) dtau;
# the chord |dC| at most the arc dS; G = C + L e(theta)
ok=1
awk -F, "$awk_lib"'
  NR == 1 { next }
  NR > 2 {
    if (rel($2 - t, 12 / 200) > 1e-12) { bad = 1; print "# tau spacing" }
    if ($1 - S > sqrt(2 * $3) * ($2 - t) * (1 + 1e-12) || $1 < S) { bad = 1; print "# S" }
    if (sqrt(($8 - x)^2 + ($9 - y)^2) > ($1 - S) * (1 + 1e-12)) { bad = 1; print "# chord" }
  }
  {
    if (rel($10, $8 - 0.7 * cos($5)) > 1e-13 || rel($11, $9 - 0.7 * sin($5)) > 1e-13) {
      bad = 1; print "# G"
    }
    S = $1; t = $2; x = $8; y = $9
  }
  END { exit bad ? 1 : 0 }' "$tmp/sm.csv" >&2 && ok=0
result "$ok" "smooth: tau equally spaced, S increments <= sqrt(2E) dtau, chord <= arc, G = C + L e"

# against a Runge-Kutta 4 integration of (2.1) with dC/dtau = V e(theta),
# h = 1e-3 (60 steps a sample): x, y, theta, V, Omega within 1e-9
ok=1
awk -F, "$awk_lib"'
  function f(v, th, om, d) {
    d["V"] = L * om * om; d["th"] = om; d["om"] = -L * v * om / (1 + L * L)
    d["x"] = v * cos(th); d["y"] = v * sin(th)
  }
  function rk4(   k1, k2, k3, k4) {
    f(v, th, om, k1)
    f(v + h / 2 * k1["V"], th + h / 2 * k1["th"], om + h / 2 * k1["om"], k2)
    f(v + h / 2 * k2["V"], th + h / 2 * k2["th"], om + h / 2 * k2["om"], k3)
    f(v + h * k3["V"], th + h * k3["th"], om + h * k3["om"], k4)
    v += h / 6 * (k1["V"] + 2 * k2["V"] + 2 * k3["V"] + k4["V"])
    th += h / 6 * (k1["th"] + 2 * k2["th"] + 2 * k3["th"] + k4["th"])
    om += h / 6 * (k1["om"] + 2 * k2["om"] + 2 * k3["om"] + k4["om"])
    x += h / 6 * (k1["x"] + 2 * k2["x"] + 2 * k3["x"] + k4["x"])
    y += h / 6 * (k1["y"] + 2 * k2["y"] + 2 * k3["y"] + k4["y"])
  }
  BEGIN { L = -0.7; v = 1; om = 0.8; th = 0.3; x = 0; y = 0; h = 0.001 }
  NR == 1 { next }
  {
    if (NR > 2) for (i = 0; i < 60; i++) rk4()
    d = abs($5 - th) + abs($6 - v) + abs($7 - om) + abs($8 - x) + abs($9 - y)
    if (d > m) m = d
  }
  END { printf "# largest difference from RK4: %.3g\n", m; exit (m > 1e-9) ? 1 : 0 }
' "$tmp/sm.csv" >&2 && ok=0
result "$ok" "smooth through a reversal: theta, V, Omega, x, y = RK4 on (2.1) within 1e-9"

# the path against the straight line (Omega = 0) and the circle (L = 0)
smooth line 0.5 -2 0 3 "outputs = path
samples = 3"
run run "$tmp/line.ini"
ok=1
test "$rc" -eq 0 && awk -F, "$awk_lib"'
  NR == 1 { next }
  { if (rel($3, -2 * $2 * cos(0.3)) > 1e-13 || rel($4, -2 * $2 * sin(0.3)) > 1e-13) bad = 1 }
  END { exit bad ? 1 : 0 }' "$tmp/out" && ok=0
result "$ok" "smooth, Omega = 0: C = V tau e(theta0) (backwards)"

smooth circ 0 1 2 5 "outputs = path,theta
samples = 10"
run run "$tmp/circ.ini" --stats
ok=1
test "$rc" -eq 0 && test "$(stat path_quadratures)" -gt 0 && awk -F, "$awk_lib"'
  NR == 1 { next }
  {
    # radius V/Omega = 1/2: C = (sin theta - sin theta0, cos theta0 - cos theta)/2
    if (abs($4 - (sin($3) - sin(0.3)) / 2) > 1e-13 || abs($5 - (cos(0.3) - cos($3)) / 2) > 1e-13) bad = 1
    # and theta = theta0 + Omega tau: S found for the right tau
    if (abs($3 - (0.3 + 2 * $2)) > 1e-13 * (1 + abs($3))) bad = 1
  }
  END { exit bad ? 1 : 0 }' "$tmp/out" && ok=0
result "$ok" "smooth, L = 0: theta = theta0 + Omega tau, C on the circle of radius V/Omega, to 1e-13"

smooth nopath -0.7 1 0.8 12 "outputs = E,V"
run run "$tmp/nopath.ini" --stats
ok=1
test "$rc" -eq 0 && test "$(stat path_quadratures)" = 0 \
  && test "$(head -n 1 "$tmp/out")" = "S,tau,E,V" \
  && cut -d, -f1,2,3,6 "$tmp/sm.csv" | cmp -s - "$tmp/out" && ok=0
test "$ok" -eq 0 || explain
result "$ok" "smooth without path, G: no path quadrature, the same S, tau, E, V"

# ---- 28-29: --compare ---------------------------------------------------
{
  printf '[scene]\nmodel = discrete\ncompare = smooth\n[parameters]\nL0 = 1\n'
  printf 'Delta = 0.3333333333333333\nL = 1\n[initial]\nV = 1\nOmega = 0.5\n'
  printf '[run]\ncollisions = 20\nduration = 5.64\n'
  printf 'outputs = E,H,theta,tau,peg,V,Omega,path\n'
} >"$tmp/cmp2.ini"
run run "$tmp/cmp2.ini" --compare
cp "$tmp/out" "$tmp/cmp.csv"
{
  printf '[scene]\nmodel = smooth\n[parameters]\nL = 1\n[initial]\nV = 1\n'
  printf 'Omega = 0.5\n[run]\nduration = 5.64\nsamples = 200\n'
  printf 'outputs = E,H,theta,tau,V,Omega,path\n'
} >"$tmp/cmps.ini"
"$prog" run "$tmp/cmps.ini" >"$tmp/cmps.csv" 2>/dev/null
csv_only "$tmp/cmps.csv"
ok=1
test "$rc" -eq 0 && test -s "$tmp/cmp.csv" && cmp -s "$tmp/cmp.csv" "$tmp/cmps.csv" && ok=0
test "$ok" -eq 0 || explain
result "$ok" "--compare: the smooth companion = the smooth scene with L, V, Omega, theta, duration"

run run "$tmp/fig6.ini" --compare
ok=1
test "$rc" -eq 2 && grep "fig6.ini: --compare" "$tmp/err" >/dev/null && ok=0
result "$ok" "--compare without compare = smooth: exit 2"

# ---- 30-34: invalid scenes ---------------------------------------------
# bad NAME TEXT-IN-MESSAGE CONTENT: exit 2, the file and key named
bad () {
  printf '%s\n' "$3" >"$tmp/$1.ini"
  run run "$tmp/$1.ini"
  ok=1
  test "$rc" -eq 2 && test ! -s "$tmp/out" && grep "$1.ini" "$tmp/err" >/dev/null \
    && grep -- "$2" "$tmp/err" >/dev/null && ok=0
  test "$ok" -eq 0 || explain
  result "$ok" "invalid scene ($1): exit 2, message names the file and '$2'"
}
bad missing collisions '[scene]
model = discrete
[parameters]
L0 = 1
Delta = 1
[initial]
V = 1
Omega = 0.5'
bad badnumber L0 '[scene]
model = discrete
[parameters]
L0 = 1x
Delta = 1
[initial]
V = 1
Omega = 0.5
[run]
collisions = 3'
bad delta0 Delta '[scene]
model = discrete
[parameters]
L0 = 1
Delta = 0
[initial]
V = 1
Omega = 0.5
[run]
collisions = 3'
bad unknown colisions '[scene]
model = discrete
[parameters]
L0 = 1
Delta = 1
[initial]
V = 1
Omega = 0.5
[run]
colisions = 3'
# (V = 1e200 alone runs since issue 16, in the units of the velocity
# scaling: tools/test-scaled.sh; V beside an Omega 2^1000 times larger
# has no exact scaling and is still refused)
bad huge '\[initial\] V = ' '[scene]
model = discrete
[parameters]
L0 = 1
Delta = 1
[initial]
V = 1e-300
Omega = 1e300
[run]
collisions = 3'

# ---- 35-40: files and usage --------------------------------------------
rm -f "$tmp/o.csv"
run run "$tmp/fig6.ini" -o "$tmp/o.csv"
ok=1
test "$rc" -eq 0 && test ! -s "$tmp/raw" && csv_only "$tmp/o.csv" \
  && cmp -s "$tmp/o.csv" "$tmp/fig6.csv" && ok=0
result "$ok" "-o FILE: the CSV in FILE, nothing on stdout"

rm -f "$tmp/o.csv"
run run "$tmp/delta0.ini" -o "$tmp/o.csv"
ok=1
test "$rc" -eq 2 && test ! -e "$tmp/o.csv" && ok=0
result "$ok" "-o FILE with an invalid scene: exit 2, FILE not created"

if test -w /dev/full; then
  run run "$tmp/fig6.ini" -o /dev/full
  ok=1
  test "$rc" -eq 1 && test -s "$tmp/err" && ok=0
  result "$ok" "-o /dev/full: exit 1 with a message"
  rc=0
  "$prog" run "$tmp/eh.ini" >/dev/full 2>"$tmp/err" || rc=$?
  ok=1
  test "$rc" -eq 1 && grep "error writing" "$tmp/err" >/dev/null && ok=0
  result "$ok" "stdout on /dev/full: exit 1 with a message"
else
  echo "ok $((count + 1)) # SKIP no /dev/full"
  echo "ok $((count + 2)) # SKIP no /dev/full"
  count=$((count + 2))
fi

run run "$tmp/no-such-scene.ini"
ok=1
test "$rc" -eq 2 && grep "no-such-scene.ini" "$tmp/err" >/dev/null && ok=0
result "$ok" "a nonexistent scene file: exit 2, named"

: >"$tmp/empty.ini"
run run "$tmp/empty.ini"
ok=1
test "$rc" -eq 2 && grep "empty.ini" "$tmp/err" >/dev/null && ok=0
result "$ok" "an empty scene file: exit 2 with a message, no crash"

if test "$count" -ne "$plan"; then
  echo "# ran $count tests, planned $plan" >&2
  exit 1
fi
exit 0
