#!/bin/sh
# test-sweep.sh -- TAP tests of "chaplygin sweep" (tools/sweep.c): shards,
# threads, the figures' sanity, option errors, silence of the progress bar.
# Run by `make check' (automake's TAP driver), or by hand:
#   CHAPLYGIN=tools/chaplygin sh tools/test-sweep.sh
# The program is $CHAPLYGIN, else $top_builddir/tools/chaplygin.
# POSIX sh only (runs under dash).

set -u

prog=${CHAPLYGIN:-${top_builddir:-.}/tools/chaplygin}
# the bar must not depend on the caller's environment
unset CHAPLYGIN_NO_PROGRESS

. "${top_srcdir:-.}/tools/tap-lib.sh"
tap_start test-sweep 37

# say TEXT: a diagnostic line (shown by the TAP driver).
say () {
  echo "# $*" >&2
}

# expect_status WANT TEXT ARGS...: one test: the program exits WANT, and
# with a "chaplygin: " message on stderr when WANT is not 0.
expect_status () {
  want=$1
  text=$2
  shift 2
  run "$@"
  ok=1
  if test "$rc" -eq "$want"; then
    ok=0
    if test "$want" -ne 0 && ! grep -q '^chaplygin: ' "$tmp/err"; then
      ok=1
    fi
  fi
  if test "$ok" -ne 0; then
    say "$prog $*: exit $rc, want $want"
    sed 's/^/# stderr: /' "$tmp/err" >&2
  fi
  result "$ok" "$text"
}

# ---- scenes ---------------------------------------------------------------
# Fig. 2(a), 2(b) grids on x = L0/Delta in [-2, 2] by 1/4 and y =
# (1/Delta)^2 in [0, 1] by 1/16: every grid value is a small dyadic
# rational, so the criteria below are evaluated exactly by awk too.
cat >"$tmp/sigma4.ini" <<'EOF'
[scene]
model = discrete
[sweep]
kind = sigma4
x_min = -2
x_max = 2
nx = 17
y = 0, 0.0625, 0.25, 1
dir = 1
EOF
sed 's/^dir = 1$/dir = -1/' "$tmp/sigma4.ini" >"$tmp/sigma4-back.ini"

cat >"$tmp/stability.ini" <<'EOF'
[scene]
model = discrete
[sweep]
kind = stability
x_min = -2
x_max = 2
nx = 17
y_min = 0
y_max = 1
ny = 17
EOF

# Fig. 3: L0 = -1/2, Delta = 1, Omega = 4/5 (H = 1), V+ from -1 to 2 by
# 3/100 (never 0: zero.ini has that case).
cat >"$tmp/basins.ini" <<'EOF'
[scene]
model = discrete
[parameters]
L0 = -0.5
Delta = 1
[initial]
Omega = 0.8
[run]
collisions = 100000
[sweep]
kind = basins
x_min = -1
x_max = 2
nx = 101
EOF

# V+ from -1 to 1 in 5 points: the middle one is exactly 0.
sed -e 's/^x_max = 2$/x_max = 1/' -e 's/^nx = 101$/nx = 5/' \
  "$tmp/basins.ini" >"$tmp/zero.ini"

# Speeds whose energy leaves the doubles: run in the units of the velocity
# scaling, E_final printed exactly (1e400); V+ and Omega+ further apart
# than the doubles' range: a library failure per point (CHAPLYGIN_ERANGE),
# not a failure of the sweep.
sed -e 's/^x_min = -1$/x_min = 1e200/' -e 's/^x_max = 2$/x_max = 2e200/' \
  -e 's/^nx = 101$/nx = 3/' "$tmp/basins.ini" >"$tmp/huge.ini"
sed -e 's/^Omega = 0.8$/Omega = 1e-300/' "$tmp/huge.ini" >"$tmp/apart.ini"

# An atlas over (L0, V+): a skate per point, the row V+ = 0 (i = 3 of
# y's 7) ESTATE.
cat >"$tmp/atlas.ini" <<'EOF'
[scene]
model = discrete
[parameters]
Delta = 1
[initial]
Omega = 0.8
[run]
collisions = 100000
[sweep]
kind = atlas
x = L0
x_min = -1.5
x_max = 0.5
nx = 21
y = V
y_min = -0.75
y_max = 0.75
ny = 7
EOF

cat >"$tmp/nosweep.ini" <<'EOF'
[scene]
model = discrete
[parameters]
L0 = 1
Delta = 0.333
[initial]
V = 1
Omega = 0.5
[run]
collisions = 20
EOF

# ---- shards: concatenated (repeated header lines dropped) = unsharded -----
# concat_shards SCENE N: the shards 0/N .. N-1/N of SCENE concatenated into
# $tmp/cat, dropping the header line of all but the first; 0 on success.
concat_shards () {
  : >"$tmp/cat"
  s=0
  while test "$s" -lt "$2"; do
    "$prog" sweep "$1" --shard "$s/$2" --no-provenance >"$tmp/shard" \
      2>"$tmp/err" || return 1
    if test "$s" -eq 0; then
      cat "$tmp/shard" >>"$tmp/cat"
    else
      sed 1d "$tmp/shard" >>"$tmp/cat"
    fi
    s=$((s + 1))
  done
}

for kind in sigma4 stability basins atlas; do
  ok=1
  if "$prog" sweep "$tmp/$kind.ini" --no-provenance >"$tmp/$kind.csv" \
       2>"$tmp/err" \
     && concat_shards "$tmp/$kind.ini" 3 \
     && cmp "$tmp/$kind.csv" "$tmp/cat" >/dev/null; then
    ok=0
  fi
  result "$ok" "$kind: shards 0/3, 1/3, 2/3 concatenated = the unsharded sweep"
done

# More shards than points: the empty shards write the header alone.
ok=1
if "$prog" sweep "$tmp/zero.ini" --no-provenance >"$tmp/zero.csv" \
     2>"$tmp/err" \
   && concat_shards "$tmp/zero.ini" 7 \
   && cmp "$tmp/zero.csv" "$tmp/cat" >/dev/null \
   && "$prog" sweep "$tmp/zero.ini" --shard 0/7 --no-provenance >"$tmp/out" \
   && test "$(wc -l <"$tmp/out")" -eq 1; then
  ok=0
fi
result "$ok" "basins, 5 points in 7 shards (some empty): concatenated = unsharded"

# ---- threads: the same bytes ---------------------------------------------
for kind in sigma4 stability basins atlas; do
  ok=0
  for t in 1 2 4; do
    "$prog" sweep "$tmp/$kind.ini" --threads "$t" --no-provenance \
      >"$tmp/t$t" 2>"$tmp/err" || ok=1
  done
  cmp "$tmp/t1" "$tmp/t2" >/dev/null || ok=1
  cmp "$tmp/t1" "$tmp/t4" >/dev/null || ok=1
  cmp "$tmp/t1" "$tmp/$kind.csv" >/dev/null || ok=1
  result "$ok" "$kind: 1, 2 and 4 threads write the same bytes"
done

# More points than one block of rows (65536): 301 x 301 = 90601 points,
# written in order (k = 0, 1, 2, ... on consecutive lines) with any number
# of threads and shards.
sed -e 's/^nx = 17$/nx = 301/' -e 's/^ny = 17$/ny = 301/' \
  "$tmp/stability.ini" >"$tmp/big.ini"
ok=1
if "$prog" sweep "$tmp/big.ini" --threads 1 --no-provenance >"$tmp/big1" \
     2>"$tmp/err" \
   && "$prog" sweep "$tmp/big.ini" --threads 2 --no-provenance >"$tmp/big2" \
     2>"$tmp/err" \
   && cmp "$tmp/big1" "$tmp/big2" >/dev/null \
   && concat_shards "$tmp/big.ini" 2 \
   && cmp "$tmp/big1" "$tmp/cat" >/dev/null \
   && awk -F, 'NR > 1 && $1 != NR - 2 { exit 1 } END { exit NR != 90602 }' \
        "$tmp/big1"; then
  ok=0
fi
rm -f "$tmp/big1" "$tmp/big2" "$tmp/cat" "$tmp/shard"
result "$ok" "90601 points (two blocks): in order, same for 1, 2 threads, 2 shards"

# ---- -o FILE ----------------------------------------------------------------
ok=1
if "$prog" sweep "$tmp/stability.ini" --shard 1/3 -o "$tmp/o.csv" \
     >"$tmp/out" 2>"$tmp/err" \
   && test ! -s "$tmp/out" \
   && "$prog" sweep "$tmp/stability.ini" --shard 1/3 >"$tmp/ref" \
   && csv_only "$tmp/o.csv" && csv_only "$tmp/ref" \
   && cmp "$tmp/o.csv" "$tmp/ref" >/dev/null; then
  ok=0
fi
result "$ok" "-o FILE: the same rows as on standard output"

# ---- Fig. 2(b): the criteria (3.11), (3.12) -----------------------------
# As printed in the manual (doc/api.texi, chaplygin_sweep_stability;
# errata E12), in x = L0/Delta, y = (1/Delta)^2:
#   (3.11) V* > 0 stable iff  x > -1  and  2y + (1 + 2x)(1 + x) > 0,
#   (3.12) V* < 0 stable iff  x < 0   and  2y + x (1 + 2x) > 0.
# Points worked out from them by hand:
#   x = 1 (G ahead of the slot): V* > 0 stable, V* < 0 not: region 1 at
#     every y;
#   x = -2 (G behind the slot): region 2 at every y;
#   x = -3/4: (3.12) holds for all y (2y + 3/8 > 0); (3.11) needs
#     y > 1/16: region 2 at y = 0 and at y = 1/16 (the boundary, strict),
#     region 3 (both stable) at y = 1;
#   x = -1/4: (3.11) always (2y + 3/8 > 0); (3.12) needs y > 1/16:
#     region 1 at y = 0, region 3 at y = 1;
#   x = 0: region 1 (3.12 needs x < 0).
# stability_at X Y: the region column of the row at (X, Y).
stability_at () {
  awk -F, -v x="$1" -v y="$2" 'NR > 1 && $2 == x && $3 == y { print $4 }' \
    "$tmp/stability.csv"
}
ok=0
for case in "1 0 1" "1 1 1" "-2 0 2" "-2 1 2" "-0.75 0 2" "-0.75 0.0625 2" \
            "-0.75 1 3" "-0.25 0 1" "-0.25 1 3" "0 0 1" "0 1 1"; do
  set -- $case
  got=$(stability_at "$1" "$2")
  if test "$got" != "$3"; then
    say "stability at x = $1, y = $2: region '$got', want $3"
    ok=1
  fi
done
result "$ok" "Fig. 2(b): regions at points worked out from (3.11), (3.12)"

# Every point of the grid against the criteria, evaluated by awk (exact on
# this dyadic grid), and region = forward + 2 backward.
ok=1
if awk -F, 'NR == 1 { next }
  { x = $2 + 0; y = $3 + 0
    f = (x > -1 && 2 * y + (1 + 2 * x) * (1 + x) > 0) ? 1 : 0
    b = (x < 0 && 2 * y + x * (1 + 2 * x) > 0) ? 1 : 0
    if ($5 != f || $6 != b || $4 != f + 2 * b || NF != 6) bad++
    n++ }
  END { exit !(n == 289 && bad == 0) }' "$tmp/stability.csv"; then
  ok=0
fi
result "$ok" "Fig. 2(b): all 289 grid points agree with (3.11), (3.12)"

# ---- Fig. 2(a): sigma4 (3.10) --------------------------------------------
# |sigma4| < 1 is the stability of the direction: |sigma4| < 1 for dir +1
# (-1) iff forward (backward) in the stability sweep at the same (x, y).
# A point with a status other than SUCCESS (sigma4 infinite) counts as
# unstable.
ok=0
for dir in 1 -1; do
  if test "$dir" -eq 1; then
    scene=$tmp/sigma4.ini col=5
  else
    scene=$tmp/sigma4-back.ini col=6
  fi
  "$prog" sweep "$scene" >"$tmp/s4" 2>"$tmp/err" || ok=1
  csv_only "$tmp/s4"
  awk -F, -v col="$col" '
    FNR == 1 { next }
    NR == FNR { stable[$2 "," $3] = $col; next }
    { s = ($5 == "SUCCESS" && $4 < 1 && $4 > -1) ? 1 : 0
      if (!(($3 "," $2) in stable) || stable[$3 "," $2] != s) bad++
      n++ }
    END { exit !(n == 68 && bad == 0) }' "$tmp/stability.csv" "$tmp/s4" \
    || { ok=1; say "sigma4 dir $dir disagrees with the stability sweep"; }
done
result "$ok" "Fig. 2(a): |sigma4| < 1 exactly where Fig. 2(b) is stable"

# sigma4 = [y + x (x + 1)]/[y + (x + 1)^2]: 2 at x = -2, y = 0; -1 at
# x = -3/4, y = 1/16; infinite at x = -1, y = 0 (status ERANGE, empty
# field).
ok=1
if grep -q '^[0-9]*,0,-2,2,SUCCESS$' "$tmp/sigma4.csv" \
   && grep -q '^[0-9]*,0.0625,-0.75,-1,SUCCESS$' "$tmp/sigma4.csv" \
   && grep -q '^4,0,-1,,ERANGE$' "$tmp/sigma4.csv" \
   && test "$(head -n 1 "$tmp/sigma4.csv")" = "k,y,x,sigma4,status"; then
  ok=0
fi
result "$ok" "Fig. 2(a): sigma4 values and the status of an infinite one"

# ---- Fig. 3: basins ------------------------------------------------------
# L0 = -1/2, Delta = 1, Omega = 4/5: every V+ > 1/sqrt(5) = 0.4472... ends
# in the forward straight-line motion (fate 1), and (by the symmetry of
# L0 = -Delta/2) every V+ < -1/sqrt(5) backward (-1).  Below it both fates
# occur.
ok=1
if awk -F, 'NR == 1 { next }
  { v = $2 + 0
    if ($8 != "SUCCESS" || NF != 8) bad++
    if (v > 0.4473 && $3 != 1) bad++
    if (v < -0.4473 && $3 != -1) bad++
    if (v > -0.4472 && v < 0.4472) seen[$3] = 1
    n++ }
  END { exit !(n == 101 && bad == 0 && seen[1] && seen[-1]) }' \
  "$tmp/basins.csv"; then
  ok=0
fi
result "$ok" "Fig. 3: V+ > 1/sqrt(5) ends forward, V+ < -1/sqrt(5) backward"

# The grid point V+ = 0 is not a post-collision state: a row with status
# ESTATE (CHAPLYGIN_ESTATE) and empty fate fields, the other rows computed.
ok=1
if test "$(sed -n 4p "$tmp/zero.csv")" = "2,0,,,,,,ESTATE" \
   && test "$(wc -l <"$tmp/zero.csv")" -eq 6 \
   && test "$(awk -F, 'NR > 1 && $8 == "SUCCESS"' "$tmp/zero.csv" | wc -l)" -eq 4
then
  ok=0
fi
result "$ok" "basins: the grid point V+ = 0 is a row with status ESTATE"

expect_status 0 "basins: speeds whose energy leaves the doubles, exit 0" \
  sweep "$tmp/huge.ini"
ok=1
if test "$(awk -F, 'NR > 1 && $3 == 1 && $6 ~ /e\+(399|400)$/ && $8 == "SUCCESS"' "$tmp/out" | wc -l)" -eq 3
then
  ok=0
fi
result "$ok" "basins: ... each forward, E_final ~ 1e400 printed exactly (the velocity scaling)"

# A failure of the library at a point is its row's status, exit 0.
expect_status 0 "basins: V+, Omega+ further apart than the doubles: rows, exit 0" \
  sweep "$tmp/apart.ini"
ok=1
if test "$(awk -F, 'NR > 1 && $3 == "" && $8 == "ERANGE"' "$tmp/out" | wc -l)" -eq 3
then
  ok=0
fi
result "$ok" "basins: ... each with status ERANGE (CHAPLYGIN_ERANGE)"

# ---- the atlas: each row of it a basins sweep --------------------------------
# Row i of an atlas over (V, Omega) is the basins sweep at Omega = y_i over
# the same V grid (another kind of sweep, run separately): the same fate
# cells, and the ESTATE row of V = 0 in both.
ok=0
for om in 0.25 0.8 3; do
  sed -e 's/^kind = basins$/kind = atlas\nx = V/' -e '/^Omega = /d' \
      -e '/^\[initial\]$/d' "$tmp/basins.ini" >"$tmp/row.ini"
  printf 'y = Omega\ny_min = %s\ny_max = %s\nny = 1\n' "$om" "$om" \
    >>"$tmp/row.ini"
  sed "s/^Omega = 0.8$/Omega = $om/" "$tmp/basins.ini" >"$tmp/b.ini"
  "$prog" sweep "$tmp/row.ini" --no-provenance >"$tmp/a.csv" 2>"$tmp/err" \
    && "$prog" sweep "$tmp/b.ini" --no-provenance >"$tmp/b.csv" \
         2>>"$tmp/err" \
    && test "$(sed 1d "$tmp/a.csv" | wc -l)" -eq 101 \
    && sed 1d "$tmp/a.csv" | cut -d, -f1,2,4- >"$tmp/a.cut" \
    && sed 1d "$tmp/b.csv" >"$tmp/b.cut" \
    && cmp "$tmp/a.cut" "$tmp/b.cut" >/dev/null \
    || { say "Omega = $om: the atlas row differs"; cat "$tmp/err" >&2; ok=1; }
done
head -1 "$tmp/a.csv" \
  | grep -qx 'k,V,Omega,fate,collisions,reversals,E_final,V_final,status' \
  || ok=1
result "$ok" "atlas over (V, Omega): each row is the basins sweep at its Omega"

# ---- the command line ------------------------------------------------------
expect_status 0 "--shard 0/1 is the whole sweep" \
  sweep "$tmp/stability.ini" --shard 0/1
cmp "$tmp/out" "$tmp/stability.csv" >/dev/null
result $? "... the same bytes"
expect_status 0 "--shard 999999/1000000 (N at its maximum)" \
  sweep "$tmp/stability.ini" --shard 999999/1000000
for bad in 1/1 3/3 -1/2 a/b 1/0 2 "" 1/2x " 1/2" 0.5/2 0/1000001 1//2; do
  run sweep "$tmp/stability.ini" --shard "$bad"
  if test "$rc" -ne 2 || ! grep -q '^chaplygin: ' "$tmp/err"; then
    say "--shard '$bad': exit $rc, want 2"
    bad_shards=1
  fi
done
result "${bad_shards:-0}" "invalid --shard values (1/1 3/3 -1/2 a/b 1/0 2 ...) exit 2"

expect_status 2 "a scene without [sweep] exits 2" sweep "$tmp/nosweep.ini"
grep -q 'no \[sweep\] section' "$tmp/err"
result $? "... saying 'no [sweep] section'"
expect_status 2 "a missing scene file exits 2" sweep "$tmp/absent.ini"
expect_status 2 "no scene file exits 2" sweep
expect_status 2 "--threads 0 exits 2" sweep "$tmp/stability.ini" --threads 0
expect_status 2 "an unknown option exits 2" sweep "$tmp/stability.ini" --bogus

# The output file is created only once everything is checked.
run sweep "$tmp/stability.ini" --shard 3/3 -o "$tmp/never.csv"
ok=1
test "$rc" -eq 2 && test ! -e "$tmp/never.csv" && ok=0
result "$ok" "-o FILE is not created when the arguments are bad"

# A write error exits 1.
if test -w /dev/full; then
  expect_status 1 "-o /dev/full: a write error exits 1" \
    sweep "$tmp/stability.ini" -o /dev/full
else
  count=$((count + 1))
  echo "ok $count # SKIP no /dev/full"
fi

# ---- the progress bar ------------------------------------------------------
# stderr is a file here: not a byte on it, for every kind, on success.
ok=0
for kind in sigma4 stability basins atlas; do
  run sweep "$tmp/$kind.ini" -o "$tmp/o.csv"
  if test "$rc" -ne 0 || test -s "$tmp/err"; then
    say "$kind: exit $rc, stderr not empty"
    ok=1
  fi
done
result "$ok" "no progress bar (stderr empty) when stderr is not a terminal"

expect_status 0 "--help exits 0" sweep --help
grep -q '^Usage: chaplygin sweep' "$tmp/out"
result $? "... and prints the usage"

test "$count" -eq "$plan" || echo "Bail out! ran $count tests, planned $plan"
