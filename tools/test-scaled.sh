#!/bin/sh
# test-scaled.sh -- TAP tests of tiny and huge states (issue 16): runs of
# the discrete, massless and smooth sleighs (and "chaplygin skate") whose
# initial speed would under- or overflow E or H run in the units of the
# library's exact velocity scaling and print the physical columns.
#
# Route: the motion is homogeneous in velocity, so each such scene is run
# a second time with V and Omega multiplied by an exact power of two 2^K
# chosen here (a speed near 1, which the program runs unscaled; for the
# smooth sleigh the duration times 2^-K too), and every column of the
# first run must equal the second's scaled back -- V, Omega, H times 2^-K,
# E times 4^-K, tau times 2^K, D, S, theta and positions as they are --
# within 4 eps (tools/scaled-cmp: the numbers read with MPFR, exactly,
# also E ~ 1e-600, which no double holds).  Why 4 eps: the two runs do
# the same floating-point operations on operands that differ by powers of
# two, which round identically (no result is subnormal in either run);
# they may differ only where a branch of the library depends on an
# absolute magnitude, and in the final rounding of the printed decimals
# (17 significant digits of each value: below 0.25 eps each).  Measured
# worst: 0 eps beyond that decimal rounding (the runs agree bit for bit).
#
# Also: a value outside the doubles is printed as an exact decimal; a time
# beyond DBL_MAX ends the run with ERANGE (exit 1), only where tau is
# asked for; the stop conditions see the physical values.
# Run by `make check', or by hand:
#   top_builddir=. top_srcdir=. sh tools/test-scaled.sh
# POSIX sh only (runs under dash).

set -u

top_builddir=${top_builddir:-.}
prog=${CHAPLYGIN:-$top_builddir/tools/chaplygin}
cmp=$top_builddir/tools/scaled-cmp

. "${top_srcdir:-.}/tools/tap-lib.sh"
tap_start test-scaled 29

TOL=4

explain () {
  echo "# exit $rc" >&2
  sed 's/^/# stderr: /' "$tmp/err" >&2
}

# x2k X K: X times 2^K as an exact hexadecimal constant.
x2k () {
  "$cmp" -s "$1" "$2"
}

# skate_scene FILE MODEL L0 DELTA V OMEGA RUN-LINES: a discrete or
# massless scene (DELTA ignored for massless).
skate_scene () {
  {
    printf '[scene]\nmodel = %s\n[parameters]\nL0 = %s\n' "$2" "$3"
    if test "$2" = discrete; then printf 'Delta = %s\n' "$4"; fi
    printf '[initial]\nV = %s\nOmega = %s\ntheta = 0.3\n[run]\n%s\n' "$5" "$6" "$7"
  } >"$1"
}

# smooth_scene FILE L V OMEGA DURATION SAMPLES
smooth_scene () {
  printf '[scene]\nmodel = smooth\n[parameters]\nL = %s\n[initial]\nV = %s\nOmega = %s\ntheta = 0.3\n[run]\nduration = %s\nsamples = %s\noutputs = E,H,theta,tau,V,Omega,path,G\n' \
    "$2" "$3" "$4" "$5" "$6" >"$1"
}

ALL=E,H,theta,tau,peg,V,Omega,path,G

# agree TEXT K [SUBCOMMAND]: run (or SUBCOMMAND, e.g. sweep) $tmp/a.ini
# and $tmp/b.ini, compare with scaled-cmp.
agree () {
  rc=0
  sub=${3:-run}
  "$prog" "$sub" --no-provenance "$tmp/a.ini" >"$tmp/a.csv" 2>"$tmp/err" \
    || rc=$?
  if test "$rc" -eq 0; then
    "$prog" "$sub" --no-provenance "$tmp/b.ini" >"$tmp/b.csv" 2>"$tmp/err" \
      || rc=$?
  fi
  if test "$rc" -eq 0; then
    "$cmp" "$TOL" "$2" "$tmp/a.csv" "$tmp/b.csv" >"$tmp/cmp" 2>&1 || rc=$?
    sed 's/^/# /' "$tmp/cmp"
  else
    explain
  fi
  result "$rc" "$1"
}

# skate_agree TEXT MODEL L0 DELTA V OMEGA K RUN-LINES
skate_agree () {
  skate_scene "$tmp/a.ini" "$2" "$3" "$4" "$5" "$6" "$8"
  skate_scene "$tmp/b.ini" "$2" "$3" "$4" "$(x2k "$5" "$7")" \
    "$(x2k "$6" "$7")" "$8"
  agree "$1" "$7"
}

# ---- the discrete skate ----------------------------------------------------
RUN="collisions = 20
outputs = $ALL"
skate_agree "discrete, L0 = -0.5, Delta = 1, V = Omega = 1e-300 (E ~ 1e-600): the run of 2^996 V, 2^996 Omega scaled back, every column within $TOL eps" \
  discrete -0.5 1 1e-300 1e-300 996 "$RUN"
skate_agree "discrete, V = Omega = 1e-200 (E ~ 1e-400): against 2^660 V, 2^660 Omega" \
  discrete -0.5 1 1e-200 1e-200 660 "$RUN"
skate_agree "discrete, V = -1e-300, Omega = 1e-300 (backward start, peg at Delta): against 2^996" \
  discrete -0.5 1 -1e-300 1e-300 996 "$RUN"
skate_agree "discrete, V = Omega = 1e+200 (E ~ 1e400): against 2^-664 V, 2^-664 Omega" \
  discrete -0.5 1 1e200 1e200 -664 "$RUN"
skate_agree "discrete, L0 = 1, Delta = 1/3, V = 1e+200, Omega = -2.385e+199: against 2^-664" \
  discrete 1 1/3 1e200 -2.385e199 -664 "$RUN"
skate_agree "discrete, V = 1.5e+308, Omega = -1.5e+308 (sqrt(1 + L0^2) |Omega| beyond DBL_MAX, E ~ 1e616): against 2^-1020" \
  discrete -0.5 1 1.5e308 -1.5e308 -1020 "$RUN"
skate_agree "discrete, L0 = -0.5, Delta = 1, V = 1e-300, Omega = 1 (slow, not tiny: run unscaled, V+ in the state): against 2^10 V, 2^10 Omega" \
  discrete -0.5 1 1e-300 1 10 "$RUN"
DENSE="collisions = 6
samples = 5
outputs = $ALL"
skate_agree "discrete, dense rows (samples = 5), V = Omega = 1e-300: against 2^996" \
  discrete -0.5 1 1e-300 1e-300 996 "$DENSE"
skate_agree "discrete, dense rows, V = Omega = 1e+200: against 2^-664" \
  discrete -0.5 1 1e200 1e200 -664 "$DENSE"
skate_agree "discrete, method = quadrature, V = Omega = 1e-200: against 2^660" \
  discrete -0.5 1 1e-200 1e-200 660 "$RUN
method = quadrature"

# ---- the massless skate -----------------------------------------------------
skate_agree "massless, L0 = -0.3, V = Omega = 1e-300: against 2^996" \
  massless -0.3 1 1e-300 1e-300 996 "$RUN"
skate_agree "massless, L0 = 0.7, V = -1e+200, Omega = 1e+200: against 2^-664" \
  massless 0.7 1 -1e200 1e200 -664 "$RUN"
skate_agree "massless, dense rows, V = Omega = 1e-300: against 2^996" \
  massless -0.3 1 1e-300 1e-300 996 "$DENSE"

# ---- the smooth sleigh --------------------------------------------------------
smooth_scene "$tmp/a.ini" 1 1e-300 1e-300 1e9 8
smooth_scene "$tmp/b.ini" 1 "$(x2k 1e-300 996)" "$(x2k 1e-300 996)" \
  "$(x2k 1e9 -996)" 8
agree "smooth, L = 1, V = Omega = 1e-300, duration 1e9: against 2^996 V, 2^996 Omega, duration 2^-996 1e9" 996
smooth_scene "$tmp/a.ini" -0.7 1e200 1e200 0x1p-662 8
smooth_scene "$tmp/b.ini" -0.7 "$(x2k 1e200 -664)" "$(x2k 1e200 -664)" 4 8
agree "smooth, L = -0.7 (a reversal), V = Omega = 1e+200, duration 2^-662: against 2^-664 V, 2^-664 Omega, duration 4" -664

# ---- chaplygin skate ------------------------------------------------------------
rc=0
"$prog" skate --L0 -0.5 --Delta 1 --V 1e-300 --Omega 1e-300 --collisions 12 \
  --no-provenance >"$tmp/a.csv" 2>"$tmp/err" || rc=$?
if test "$rc" -eq 0; then
  "$prog" skate --L0 -0.5 --Delta 1 --V "$(x2k 1e-300 996)" \
    --Omega "$(x2k 1e-300 996)" --collisions 12 --no-provenance \
    >"$tmp/b.csv" 2>"$tmp/err" || rc=$?
fi
if test "$rc" -eq 0; then
  "$cmp" "$TOL" 996 "$tmp/a.csv" "$tmp/b.csv" >"$tmp/cmp" 2>&1 || rc=$?
  sed 's/^/# /' "$tmp/cmp"
else
  explain
fi
result "$rc" "chaplygin skate --V 1e-300 --Omega 1e-300: against 2^996"

# ---- chaplygin sweep, basins ------------------------------------------------------
# basins_scene FILE OMEGA V_LO V_HI: Figure 3's sweep (L0 = -1/2, Delta =
# 1), 6 points, 1000 collisions at most
basins_scene () {
  printf '[scene]\nmodel = discrete\n[parameters]\nL0 = -0.5\nDelta = 1\n[initial]\nOmega = %s\n[run]\ncollisions = 1000\n[sweep]\nkind = basins\nx_min = %s\nx_max = %s\nnx = 6\n' \
    "$2" "$3" "$4" >"$1"
}
basins_scene "$tmp/a.ini" 0.8e-300 -0.5e-300 0.5e-300
basins_scene "$tmp/b.ini" "$(x2k 0.8e-300 996)" "$(x2k -0.5e-300 996)" \
  "$(x2k 0.5e-300 996)"
agree "chaplygin sweep, basins at Omega = 0.8e-300, V+ in [-0.5e-300, 0.5e-300]: against 2^996" 996 sweep
grep -q 'e-60[0-9],' "$tmp/a.csv"
result $? "... E_final (~1e-601, beyond the doubles) printed exactly"

# ---- the numbers outside the doubles, as text -----------------------------------
# E of V = Omega = 1e-300 at L0 = -0.5: (1 + 1.25) 1e-600/2, exactly
# 1.1249999999999999e-600 to 17 digits (the doubles' 1e-300 squared, not
# 1.125e-600); H = 1.25e-300.
skate_scene "$tmp/a.ini" discrete -0.5 1 1e-300 1e-300 "collisions = 1
outputs = E,H,V,Omega"
run run --no-provenance "$tmp/a.ini"
row0=$(sed -n 2p "$tmp/out")
test "$rc" -eq 0 && test "$row0" = "0,0,0,1.1249999999999999e-600,1.25e-300,1e-300,1e-300"
result $? "E beyond the doubles is printed exactly, 17 digits (row 0: $row0)"

# the provenance says so; a run that needs no scaling has no such line
skate_scene "$tmp/a.ini" discrete -0.5 1 1e-300 1e-300 "collisions = 1"
run run "$tmp/a.ini"
grep -q '^# velocity scaling: computed with V, Omega times 2^997 ' "$tmp/raw" \
  && run run "${top_srcdir:-.}/scenes/example.ini" \
  && ! grep -q '^# velocity scaling' "$tmp/raw"
result $? "provenance: '# velocity scaling: ... 2^997' for V = Omega = 1e-300 only"

# ---- time beyond DBL_MAX -----------------------------------------------------------
# V = 1e-308 along a straight line (Omega = 0): each segment takes
# Delta/V = 1e308, the second collision is at 2e308.
skate_scene "$tmp/a.ini" discrete 1 1 1e-308 0 "collisions = 4
outputs = E,tau,V"
run run --no-provenance "$tmp/a.ini"
test "$rc" -eq 1 && test "$(wc -l <"$tmp/out")" -eq 3 \
  && grep -q 'collision 2: the time tau = 2e+308 is beyond the largest double: result is not representable' "$tmp/err"
result $? "tau beyond DBL_MAX: ERANGE at collision 2 (exit 1), rows 0 and 1 written, the time said exactly"
skate_scene "$tmp/a.ini" discrete 1 1 1e-308 0 "collisions = 4
outputs = E,V"
run run --no-provenance "$tmp/a.ini"
test "$rc" -eq 0 && test "$(wc -l <"$tmp/out")" -eq 6
result $? "the same run without tau: complete (the time is not computed)"
# a run that needs no velocity scaling (V = 1e-110 at |l| ~ 1e100) whose
# first segment takes 1e310: the library's own ERANGE
skate_scene "$tmp/a.ini" discrete 1e100 1e200 1e-110 0 "collisions = 2
outputs = tau"
run run --no-provenance "$tmp/a.ini"
test "$rc" -eq 1 && grep -q 'collision 1: .*not representable' "$tmp/err"
result $? "an unscaled run whose time overflows: ERANGE at collision 1 (exit 1)"

# ---- stop conditions on the physical values ----------------------------------------
# stop_tau in physical time: the same collision as the reference's
# stop_tau 2^-996 times.
skate_scene "$tmp/a.ini" discrete -0.5 1 1e-300 1e-300 "collisions = 100
outputs = tau
stop_tau = 3e300"
skate_scene "$tmp/b.ini" discrete -0.5 1 "$(x2k 1e-300 996)" "$(x2k 1e-300 996)" \
  "collisions = 100
outputs = tau
stop_tau = $(x2k 3e300 -996)"
agree "stop_tau = 3e300 on a tiny run: stops where the reference does (its stop_tau 2^-996 times)" 996
# the stop is reached: rows 0..3 (3.17e300 >= 3e300 > 2.16e300)
test "$(grep -c . "$tmp/a.csv")" -eq 5
result $? "stop_tau = 3e300: stopped at collision 3, tau = $(sed -n '$s/.*,//p' "$tmp/a.csv")"
skate_scene "$tmp/a.ini" discrete 1 1/3 1e-300 1e-300 "collisions = 1000
outputs = E
stop_fate = yes"
run run --no-provenance "$tmp/a.ini"
grep -q 'stop_fate: the fate is certain: forward (V\* > 0), E_final = [0-9.]*e-60[0-9], V_final = [0-9.]*e-30[0-9]' "$tmp/err"
result $? "stop_fate: E_final and V_final in physical units ($(sed -n 's/.*E_final/E_final/p' "$tmp/err"))"
skate_scene "$tmp/a.ini" discrete 1 1/3 1e-300 1e-300 "collisions = 1000
outputs = H
stop_H = 1e-3"
run run --no-provenance "$tmp/a.ini"
grep -q 'stop_H: .*(H = [0-9.]*e-30[0-9], 2E/H^2 = ' "$tmp/err"
result $? "stop_H: H in physical units, 2E/H^2 scale-free ($(sed -n 's/.*(H/(H/p' "$tmp/err"))"

# ---- what stays refused -------------------------------------------------------------
# V below 2^-1074 of the speed: 2^m V would lose its bits
skate_scene "$tmp/a.ini" discrete -0.5 1 1e-300 1e300 "collisions = 1"
run run --no-provenance "$tmp/a.ini"
test "$rc" -eq 2 && grep -q 'not representable' "$tmp/err"
result $? "V = 1e-300 beside Omega = 1e300 (no exact scaling): refused, exit 2"
# a huge speed over a duration whose path leaves the doubles
smooth_scene "$tmp/a.ini" 1 1e300 0 1e9 2
run run --no-provenance "$tmp/a.ini"
test "$rc" -eq 2 && grep -q 'duration = 1000000000.*not representable' "$tmp/err"
result $? "smooth, V = 1e300 for duration 1e9 (a path of 1e309): refused, exit 2"
