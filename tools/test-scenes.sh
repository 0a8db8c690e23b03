#!/bin/sh
# test-scenes.sh -- TAP: the scenes of the paper's figures (scenes/*.ini)
# run, and reproduce the behaviour their captions describe.  Each figure
# scene is run per collision (its dense "samples" key removed) and the
# rows are checked with awk, columns found by name in the header line.
# Run by `make check', or by hand:
#   top_builddir=. top_srcdir=. sh tools/test-scenes.sh
set -u

top_builddir=${top_builddir:-.}
top_srcdir=${top_srcdir:-.}
prog=${CHAPLYGIN:-$top_builddir/tools/chaplygin}
scenes=$top_srcdir/scenes

tmp=$(mktemp -d "${TMPDIR:-/tmp}/test-scenes.XXXXXX") || {
  echo "Bail out! cannot create a temporary directory"; exit 1; }
trap 'rm -rf "$tmp"' 0
trap 'exit 1' HUP INT TERM

echo "1..12"
test -x "$prog" || { echo "Bail out! $prog is not built"; exit 1; }

count=0
result () {
  count=$((count + 1))
  if test "$1" -eq 0; then echo "ok $count - $2"; else echo "not ok $count - $2"; fi
}

# per_collision FIG: run scenes/FIG.ini without dense output into $tmp/FIG.csv.
per_collision () {
  sed '/^samples *=/d' "$scenes/$1.ini" >"$tmp/$1.ini"
  "$prog" run --no-provenance "$tmp/$1.ini" >"$tmp/$1.csv" 2>"$tmp/$1.err"
}

# check FIG TEXT AWK-PROGRAM: one test; the awk program sees the columns
# by name in c["name"] and must set ok = 1 in END to pass.  Its
# diagnostics (print > "/dev/stderr") go to the log.
check () {
  fig=$1 text=$2 prog_awk=$3
  ok=1
  if per_collision "$fig"; then
    awk -F, '
      NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next }
      '"$prog_awk" "$tmp/$fig.csv" && ok=0
  else
    sed "s/^/# $fig: /" "$tmp/$fig.err"
  fi
  result "$ok" "$fig: $text"
}

# Figures 4 and 6 (L0 = 1): no reversal, |H| decays monotonically (more
# than tenfold in 20 collisions, sigma4 = L0/(L0 + Delta) ~ 0.75 a
# collision far from the fixed point's neighbourhood: about 0.85 here).
for fig in fig4 fig6; do
  check $fig "stable: no reversal, |H| decays monotonically" '
    { n++; if ($c["reversal"] != 0) bad = 1
      h = $c["H"] < 0 ? -$c["H"] : $c["H"]
      if (n > 1 && !(h < hp)) bad = 1
      if (n == 1) h0 = h; hp = h }
    END { if (bad || !(hp < 0.1 * h0)) exit 1 }'
done

# Figure 5 (L0 = -1): one reversal; H grows before it and decays after.
check fig5 "one reversal as H passes its maximum" '
  { n++; r += $c["reversal"]; h = $c["H"]
    if ($c["reversal"] == 1) at = n
    if (at == 0 && n > 1 && !(h > hp)) bad = 1
    if (at > 0 && n > at && !(h < hp)) bad = 1
    hp = h }
  END { if (r != 1 || bad) exit 1 }'

# Figure 7: a stable wobble: H changes sign at every collision with |H|
# decreasing, no reversal, V stays positive (energy decreasing).
check fig7 "stable wobble: H alternates in sign and decays, no reversal" '
  { n++; h = $c["H"]; a = h < 0 ? -h : h
    if ($c["reversal"] != 0) bad = 1
    if (n > 1 && !(h * hp < 0 && a < ap)) bad = 1
    if (n > 1 && !($c["E"] < ep)) bad = 1
    hp = h; ap = a; ep = $c["E"] }
  END { if (bad || n != 16) exit 1 }'

# Figure 8 (L0 = -sqrt(2)): unstable at first: |H| grows, one reversal,
# then |H| decays; the heading turns by more than pi/2.
check fig8 "initially unstable: |H| grows, one reversal, then decays" '
  { n++; h = $c["H"] < 0 ? -$c["H"] : $c["H"]; r += $c["reversal"]
    if ($c["reversal"] == 1) at = n
    if (at == 0 && n > 1 && !(h > hp)) bad = 1
    if (at > 0 && n > at && !(h < hp)) bad = 1
    hp = h; th = $c["theta"] }
  END { if (r != 1 || bad || !(th > 1.5708)) exit 1 }'

# Figure 9: a growing wobble (H alternating, |H| growing), a reversal,
# then a decaying wobble.
check fig9 "lurching: growing wobble, one reversal, decaying wobble" '
  { n++; h = $c["H"]; a = h < 0 ? -h : h; r += $c["reversal"]
    if ($c["reversal"] == 1) at = n
    if (n > 1 && !(h * hp < 0)) bad = 1
    if (at == 0 && n > 1 && !(a > ap)) bad = 1
    if (at > 0 && n > at && !(a < ap)) bad = 1
    hp = h; ap = a }
  END { if (r != 1 || bad || n != 26) exit 1 }'

# Figure 10 (massless, L0 = -2/3): period 2 (rows n and n + 2 agree in E,
# H to 1e-13 relative, a few ulps per collision over 20 collisions), a
# reversal in every segment, no energy lost (E constant to 1e-13).
check fig10 "period 2, a reversal in every segment, no energy lost" '
  function rel(a, b) { d = a - b; d = d < 0 ? -d : d; s = b < 0 ? -b : b
                       return d / s }
  { n++; E[n] = $c["E"]; H[n] = $c["H"]
    if (n > 1 && $c["reversal"] != 1) bad = 1
    if (rel(E[n], E[1]) > 1e-13) bad = 1
    if (n > 2 && rel(H[n], H[n - 2]) > 1e-13) bad = 1 }
  END { if (bad || n != 21 || !(rel(H[2], H[1]) > 0.01)) exit 1 }'

# Figure 10: the mass centre moves on a straight line: every G is on the
# line through the first two, within 1e-12 of the distance covered.
check fig10 "the mass centre moves on a straight line" '
  { n++; x[n] = $c["G_x"]; y[n] = $c["G_y"] }
  END { dx = x[n] - x[1]; dy = y[n] - y[1]; L = sqrt(dx * dx + dy * dy)
        if (!(L > 0)) exit 1
        for (i = 2; i < n; i++) {
          e = ((x[i] - x[1]) * dy - (y[i] - y[1]) * dx) / L
          if (e < 0) e = -e
          if (e > 1e-12 * L) exit 1 }
        exit 0 }'

# The sweeps: Figure 3 (L0 = -1/2, Delta = 1, Omega = 4/5): every V0 above
# 1/sqrt(5) ends forward (the caption), and both fates occur below.
ok=1
if "$prog" run --no-provenance "$scenes/fig3.ini" >"$tmp/fig3.csv" \
     2>"$tmp/fig3.err"; then
  awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next }
    { v = $c["V0"]; f = $c["fate"]
      if (v > 0.4472136 && f != 1) bad = 1
      if (v < 0.44 && f == 1) fw = 1
      if (v < 0.44 && f == -1) bw = 1 }
    END { if (bad || !fw || !bw || NR != 4001) exit 1 }' "$tmp/fig3.csv" && ok=0
fi
result "$ok" "fig3: forward above V0 = 1/sqrt(5), both fates below"

# Figure 2(b): stability regions; the two regions overlap only where the
# mass centre is inside the slot, -1 < L0/Delta < 0 (Section 3.1.2: "if
# the mass centre lies within the slot ... both ... simultaneously
# stable"), and there they do overlap.
ok=1
if "$prog" run --no-provenance "$scenes/fig2b.ini" >"$tmp/fig2b.csv" \
     2>"$tmp/fig2b.err"; then
  awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next }
    { if ($c["region"] == 3) { both = 1
        if (!($c["x"] > -1 && $c["x"] < 0)) bad = 1 } }
    END { if (bad || !both || NR != 601 * 201 + 1) exit 1 }' \
    "$tmp/fig2b.csv" && ok=0
fi
result "$ok" "fig2b: both directions stable somewhere, and only for -1 < L0/Delta < 0"

# Figure 2(a): the curve set the scene asks for (5 values of y, 1201 x);
# the values are the sweep's and (3.10)'s tests' business.
ok=1
if "$prog" run --no-provenance "$scenes/fig2a.ini" >"$tmp/fig2a.csv" \
     2>"$tmp/fig2a.err"; then
  test "$(wc -l <"$tmp/fig2a.csv")" -eq $((5 * 1201 + 1)) && ok=0
fi
result "$ok" "fig2a: 5 curves of 1201 points"

# Every scene of scenes/ runs with exit status 0 as written (dense output
# and the smooth companion included).
ok=0
for f in "$scenes"/*.ini; do
  "$prog" run "$f" >/dev/null 2>"$tmp/err" || { ok=1; echo "# $f failed:"; sed 's/^/#   /' "$tmp/err"; }
  if grep '^compare *=' "$f" >/dev/null; then
    "$prog" run --compare "$f" >/dev/null 2>"$tmp/err" || { ok=1; echo "# $f --compare failed:"; sed 's/^/#   /' "$tmp/err"; }
  fi
done
result "$ok" "every scene of scenes/ runs (and its smooth companion)"
