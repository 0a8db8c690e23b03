#!/bin/sh
# test-certified.sh -- TAP tests of "chaplygin run" with method = certified:
# E and H of every row against the exact model computed here in Python's
# exact fractions (float(Fraction) is correctly rounded: a separate route
# from the library's FLINT rationals), the other columns against the
# closed form, the provenance, early stops, and the scenes it refuses.
# In a build without Arb the scene is refused with a message that says so,
# and the rest is skipped.
# Run by `make check', or: top_builddir=. top_srcdir=. sh tools/test-certified.sh
# POSIX sh (dash).

set -u

top_builddir=${top_builddir:-.}
prog=${CHAPLYGIN:-$top_builddir/tools/chaplygin}

. "${top_srcdir:-.}/tools/tap-lib.sh"
tap_start test-certified 14

# scene NAME EXTRA-RUN-LINES [EXTRA-OUTPUT]: Figure 3's line (L0 = -1/2,
# Delta = 1) from V = 0.3, Omega = 0.8 (a reversal, then forward motion),
# 30 collisions.
scene () {
  {
    printf '[scene]\nmodel = discrete\n[parameters]\nL0 = -0.5\nDelta = 1\n'
    printf '[initial]\nV = 0.3\nOmega = 0.8\n[run]\ncollisions = 30\n'
    printf 'outputs = E, H, theta, tau, peg%s\n%s\n' "${3:+, $3}" "$2"
  } >"$tmp/$1.ini"
}

scene cert 'method = certified' bounds
scene closed ''
run run "$tmp/cert.ini"
if test "$rc" -ne 0 && grep "no certified method" "$tmp/err" >/dev/null; then
  result 0 "a build without Arb refuses method = certified, saying why"
  i=2
  while test $i -le 14; do
    echo "ok $i # SKIP no certified method in this build"
    i=$((i + 1))
  done
  exit 0
fi
cp "$tmp/out" "$tmp/cert.csv"
cp "$tmp/raw" "$tmp/cert.raw"
ok=1
test "$rc" -eq 0 && test "$(wc -l <"$tmp/cert.csv")" -eq 32 && ok=0
result "$ok" "method = certified runs: 31 rows and a header"

ok=1
grep '^# method: certified' "$tmp/cert.raw" >/dev/null && ok=0
result "$ok" "the provenance names the certified method"

# E and H of every row: the exact map (3.7) from the exact start, the
# reversal decided by the minimum of V^2 over the leg
if command -v python3 >/dev/null 2>&1; then
  ok=0
  python3 - "$tmp/cert.csv" >"$tmp/py" 2>&1 <<'EOF' || ok=1
import csv, math, sys
from fractions import Fraction as F
rows = list(csv.DictReader(open(sys.argv[1])))
L0, Delta = F(-0.5), F(1)
ends = [L0, L0 + Delta]
V, Om = F(0.3), F(0.8)
n0 = 1 + ends[0] ** 2
E, H, d = V * V / 2 + n0 * Om * Om / 2, n0 * Om, 1
bad = 0
for r in rows:
    k = int(r['n'])
    if k > 0:
        s = 0 if d > 0 else 1
        la, lb = ends[s], ends[1 - s]
        lmin2 = 0 if la * lb <= 0 else min(la * la, lb * lb)
        rev = 2 * E * (1 + lmin2) - H * H <= 0
        b, bp = (la, lb) if rev else (lb, la)
        C1 = -Delta ** 2 / (2 * (1 + b * b) ** 2 * (1 + bp * bp))
        C2 = (1 + b * bp) / (1 + b * b)
        E, H = E + C1 * H * H, C2 * H
        d = -d if rev else d
        if int(r['reversal']) != int(rev):
            print('row %d: reversal %s, exact %d' % (k, r['reversal'], rev))
            bad += 1
    for name, x in (('E', E), ('H', H)):
        if float(r[name]) != float(x):
            print('row %d: %s = %r, nearest %r' % (k, name, float(r[name]),
                                                 float(x)))
            bad += 1
        # the enclosure: the exact value's two neighbours (one double where
        # it is one), the value returned among them
        lo, hi = float(r[name + '_lo']), float(r[name + '_hi'])
        if not (F(lo) <= x <= F(hi) and float(r[name]) in (lo, hi)
                and (lo == hi) == (F(float(x)) == x)
                and (lo == hi or math.nextafter(lo, math.inf) == hi)):
            print('row %d: %s in [%r, %r]?' % (k, name, lo, hi))
            bad += 1
    # the balls' enclosures: around the value, at most two ulps wide
    for name in ('theta', 'tau', 'peg_x', 'peg_y'):
        v, lo, hi = (float(r[name + s]) for s in ('', '_lo', '_hi'))
        if not (lo <= v <= hi and hi <= math.nextafter(math.nextafter(
                lo, math.inf), math.inf)):
            print('row %d: %s = %r, enclosure [%r, %r]' % (k, name, v, lo, hi))
            bad += 1
sys.exit(1 if bad else 0)
EOF
  sed 's/^/# /' "$tmp/py"
  result "$ok" "E and H of every row are the nearest doubles to the exact map's; outputs bounds: their enclosures the exact values' neighbours, the balls' at most 2 ulps wide"
else
  count=$((count + 1))
  echo "ok $count # SKIP no python3"
fi

# the other columns: the closed form's within its few ulps (1e-14
# relative, or absolute below 1: theta and the peg pass through 0)
run run "$tmp/closed.ini"
ok=1
test "$rc" -eq 0 && awk -F, '
  function abs(x) { return x < 0 ? -x : x }
  NR == FNR { for (i = 1; i <= NF; i++) a[FNR, i] = $i; next }
  { for (i = 1; i <= NF; i++) {
      s = abs(a[FNR, i]) > 1 ? abs(a[FNR, i]) : 1
      if (abs(a[FNR, i] - $i) > 1e-14 * s) { print FNR, i, a[FNR, i], $i; bad = 1 } } }
  END { exit bad }' "$tmp/cert.csv" "$tmp/out" >&2 && ok=0
result "$ok" "every column within 1e-14 of the closed form's"

scene stop 'method = certified
stop_tau = 10'
run run "$tmp/stop.ini"
ok=1
test "$rc" -eq 0 && grep 'stop_tau' "$tmp/raw" >/dev/null && ok=0
result "$ok" "stop_tau ends a certified run early"

scene dense 'method = certified
samples = 10'
scene densec 'samples = 10'
run run "$tmp/dense.ini"
cp "$tmp/out" "$tmp/dense.csv"
rc_cert=$rc
run run "$tmp/densec.ini"
ok=1
if test "$rc_cert" -eq 0 && test "$rc" -eq 0 \
  && awk -F, '
    function abs(x) { return x < 0 ? -x : x }
    NR == FNR { for (i = 1; i <= NF; i++) a[FNR, i] = $i; n = FNR; next }
    { for (i = 1; i <= NF; i++) {
        s = abs(a[FNR, i]) > 1 ? abs(a[FNR, i]) : 1
        if (abs(a[FNR, i] - $i) > 1e-13 * s) { print FNR, i, a[FNR, i], $i; bad = 1 } } }
    END { exit bad || n != FNR }' "$tmp/dense.csv" "$tmp/out" >&2; then
  # each segment's first row is the state after the collision before it:
  # theta, tau as the per-collision run's, bit for bit
  if command -v python3 >/dev/null 2>&1; then
    python3 - "$tmp/dense.csv" "$tmp/cert.csv" >"$tmp/py" 2>&1 <<'EOF' && ok=0
import csv, sys
dense = list(csv.DictReader(open(sys.argv[1])))
per = {int(r['n']): r for r in csv.DictReader(open(sys.argv[2]))}
bad = seen = 0
for r in dense:
    if r['k'] == '0' and int(r['n']) >= 2:
        p = per[int(r['n']) - 1]
        seen += 1
        for c in ('theta', 'tau', 'E', 'H'):
            if r[c] != p[c]:
                print('segment %s: %s %s, per collision %s' % (r['n'], c, r[c], p[c]))
                bad += 1
sys.exit(1 if bad or seen < 25 else 0)
EOF
    sed 's/^/# /' "$tmp/py"
  else
    ok=0
  fi
fi
result "$ok" "samples with method = certified: dense rows within 1e-13 of the closed form's, each segment's start the per-collision run's, bit for bit"

# stop_fate: decided on the orbit's exact state, at the collision where
# the double route decides it too (away from a boundary), E_final the
# nearest double to (B.10)
scene fate 'method = certified
stop_fate = yes'
scene fatecf 'stop_fate = yes'
run run "$tmp/fate.ini"
cp "$tmp/raw" "$tmp/fate.raw"
run run "$tmp/fatecf.ini"
ok=1
test "$rc" -eq 0 && grep 'stopped at collision 1 of 30: stop_fate: the fate is certain: backward' "$tmp/fate.raw" >/dev/null \
  && test "$(grep -c '^[0-9]' "$tmp/fate.raw")" -eq "$(grep -c '^[0-9]' "$tmp/raw")" && ok=0
result "$ok" "stop_fate with method = certified stops where the fate is certain"

scene tol 'method = certified
tolerance = 1e-9'
run run "$tmp/tol.ini"
ok=1
test "$rc" -eq 2 && grep "not used by method certified" "$tmp/err" >/dev/null && ok=0
result "$ok" "tolerance with method = certified: exit 2, not used"

# a basins sweep (Figure 3's line, V+ from 1e-6 to 0.6): every fate and
# reversal count against (B.13)'s boundaries (3/5)^n/sqrt(5) (erratum
# E15), compared exactly in fractions: V+ in the n-th interval reverses
# n times and ends (-1)^n
{
  printf '[scene]\nmodel = discrete\n[parameters]\nL0 = -0.5\nDelta = 1\n'
  printf '[initial]\nOmega = 0.8\n[run]\ncollisions = 1000000\nmethod = certified\n'
  printf '[sweep]\nkind = basins\nx_min = 1e-6\nx_max = 0.6\nnx = 3000\n'
} >"$tmp/basins.ini"
run sweep "$tmp/basins.ini"
if command -v python3 >/dev/null 2>&1; then
  ok=1
  test "$rc" -eq 0 && grep '^# method: certified' "$tmp/raw" >/dev/null \
    && python3 - "$tmp/out" >"$tmp/py" 2>&1 <<'EOF' && ok=0
import csv, sys
from fractions import Fraction as F
rows = list(csv.DictReader(open(sys.argv[1])))
bad = 0
for r in rows:
    V = F(float(r['V0']))
    n = 0
    while V * V < F(9, 25) ** n / 5:
        n += 1
    if (r['status'], int(r['fate']), int(r['reversals'])) \
            != ('SUCCESS', 1 if n % 2 == 0 else -1, n):
        print('V+ = %r: %s, expected fate %d after %d reversals'
              % (float(V), r, 1 if n % 2 == 0 else -1, n))
        bad += 1
sys.exit(1 if bad or len(rows) != 3000 else 0)
EOF
  sed 's/^/# /' "$tmp/py"
  result "$ok" "a certified basins sweep: every fate on (B.13)'s exact intervals"
else
  count=$((count + 1))
  echo "ok $count # SKIP no python3"
fi

sed 's/^method = certified$/method = ode/' "$tmp/basins.ini" >"$tmp/bode.ini"
run sweep "$tmp/bode.ini"
ok=1
test "$rc" -eq 2 && grep "method closed-form (the default) or certified" "$tmp/err" >/dev/null && ok=0
result "$ok" "a basins sweep with method = ode: exit 2, saying which methods apply"

# a sigma4 sweep (Figure 2(a)'s grid, both directions): every sigma4
# the double nearest to (3.10)'s exact value at the grid's doubles,
# [y + x (x + 1)]/[y + (x + 1)^2] (dir +1) or /[y + x^2] (dir -1), in
# fractions
sigma4_scene () {
  {
    printf '[scene]\nmodel = discrete\n[run]\nmethod = %s\n' "$2"
    printf '[sweep]\nkind = sigma4\nx_min = -4\nx_max = 2\nnx = 1201\n'
    printf 'y = 0, 0.01, 0.1, 0.25, 0.5, 1\ndir = %s\n' "$3"
  } >"$tmp/$1.ini"
}
if command -v python3 >/dev/null 2>&1; then
  ok=0
  for dir in 1 -1; do
    sigma4_scene s4 certified "$dir"
    run sweep "$tmp/s4.ini"
    { test "$rc" -eq 0 && grep '^# method: certified' "$tmp/raw" >/dev/null \
      && python3 - "$tmp/out" "$dir" >"$tmp/py" 2>&1 <<'EOF'; } || ok=1
import csv, sys
from fractions import Fraction as F
rows = list(csv.DictReader(open(sys.argv[1])))
d = int(sys.argv[2])
bad = 0
for r in rows:
    x, y = F(float(r['x'])), F(float(r['y']))
    den = y + ((x + 1) ** 2 if d > 0 else x * x)
    if den == 0:
        ok = r['status'] == 'ERANGE' and r['sigma4'] == ''
    else:
        ok = r['status'] == 'SUCCESS' \
            and float(r['sigma4']) == float((y + x * (x + 1)) / den)
    if not ok:
        print('dir %d, x = %r, y = %r: %s' % (d, float(x), float(y), r))
        bad += 1
sys.exit(1 if bad or len(rows) != 6 * 1201 else 0)
EOF
    sed 's/^/# /' "$tmp/py"
  done
  result "$ok" "a certified sigma4 sweep: every value (3.10)'s exact value rounded, both directions (ERANGE where infinite)"
else
  count=$((count + 1))
  echo "ok $count # SKIP no python3"
fi

# a stability sweep on a grid through the boundaries (y = 0 with
# x = -1/2, where (3.11) and (3.12) are both 0): every region decided
# exactly, a boundary point neutral
{
  printf '[scene]\nmodel = discrete\n[run]\nmethod = certified\n'
  printf '[sweep]\nkind = stability\nx_min = -2\nx_max = 1\nnx = 49\n'
  printf 'y_min = 0\ny_max = 0.5\nny = 33\n'
} >"$tmp/stab.ini"
run sweep "$tmp/stab.ini"
if command -v python3 >/dev/null 2>&1; then
  ok=1
  test "$rc" -eq 0 && python3 - "$tmp/out" >"$tmp/py" 2>&1 <<'EOF' && ok=0
import csv, sys
from fractions import Fraction as F
rows = list(csv.DictReader(open(sys.argv[1])))
bad = boundary = 0
for r in rows:
    x, y = F(float(r['x'])), F(float(r['y']))
    a, b = 2 * y + (1 + 2 * x) * (1 + x), 2 * y + x * (1 + 2 * x)
    boundary += (x > -1 and a == 0) + (x < 0 and b == 0)
    fwd, bwd = int(x > -1 and a > 0), int(x < 0 and b > 0)
    if (int(r['region']), int(r['forward']), int(r['backward'])) \
            != (fwd + 2 * bwd, fwd, bwd):
        print('x = %r, y = %r: %s' % (float(x), float(y), r))
        bad += 1
print('boundary points: %d' % boundary)
sys.exit(1 if bad or boundary < 2 or len(rows) != 49 * 33 else 0)
EOF
  sed 's/^/# /' "$tmp/py"
  result "$ok" "a certified stability sweep: every region decided exactly, the boundary points neutral"
else
  count=$((count + 1))
  echo "ok $count # SKIP no python3"
fi

scene bclosed '' bounds
run run "$tmp/bclosed.ini"
ok=1
test "$rc" -eq 2 && grep "'bounds' (the enclosures of the certified method) needs" "$tmp/err" >/dev/null && ok=0
result "$ok" "outputs bounds without method = certified: exit 2, saying what it needs"

sigma4_scene s4ode ode 1
run sweep "$tmp/s4ode.ini"
ok=1
test "$rc" -eq 2 && grep "a sigma4 sweep evaluates rational closed forms" "$tmp/err" >/dev/null && ok=0
result "$ok" "a sigma4 sweep with method = ode: exit 2, saying which methods apply"

if test "$count" -ne "$plan"; then
  echo "# ran $count tests, planned $plan" >&2
  exit 1
fi
exit 0
