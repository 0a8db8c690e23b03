#!/bin/sh
# test-bounds.sh -- TAP: bounded runs.  The row limit (max_rows, --max-rows)
# refuses a run that would certainly write more rows, before anything is
# written, for run, skate, sweep and plot alike; stop conditions (stop_fate,
# stop_H, stop_tau) end a run of 1e9 collisions early and say why; the
# stride every = k; a run with a stop condition ends at the row limit.
# Run by `make check', or by hand:
#   top_builddir=. top_srcdir=. sh tools/test-bounds.sh
# POSIX sh.

set -u
top_builddir=${top_builddir:-.}
prog=${CHAPLYGIN:-$top_builddir/tools/chaplygin}

. "${top_srcdir:-.}/tools/tap-lib.sh"
tap_start test-bounds 24

say () { echo "# $*" >&2; }

# run_t ARGS...: as run, but killed after 5 s: a refusal or a stop that
# fails to happen would run for hours (exit status 124 then).
run_t () {
  rc=0
  timeout 5 "$prog" "$@" >"$tmp/raw" 2>"$tmp/err" || rc=$?
  grep -v '^#' "$tmp/raw" >"$tmp/out" || :
}

# scene NAME RUN-LINES...: the skate of Figure 8 (it reverses in the segment
# ending at collision 6; its fate is certain after that), [run] lines as
# given (one per argument).
scene () {
  name=$1
  shift
  {
    printf '[scene]\nmodel = discrete\n[parameters]\n'
    printf 'L0 = -1.4142135623730951\nDelta = 0.70710678118654757\n'
    printf '[initial]\nV = 1\nOmega = 0.1\n[run]\n'
    for line in "$@"; do printf '%s\n' "$line"; done
  } >"$tmp/$name.ini"
}

# seconds CMD...: run CMD, its wall time in seconds in $secs (date +%s.%N).
seconds () {
  t0=$(date +%s.%N)
  "$@"
  t1=$(date +%s.%N)
  secs=$(awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.3f", b - a }')
}

# ---- the row limit: refused before anything is written -------------------
scene runaway 'collisions = 1e9'
rm -f "$tmp/o.csv"
run_t run "$tmp/runaway.ini" -o "$tmp/o.csv"
ok=1
test "$rc" -eq 2 && test ! -e "$tmp/o.csv" && test ! -s "$tmp/raw" \
  && test -z "$(ls -A "$tmp" | grep '^\.o\.csv')" && ok=0
result "$ok" "collisions = 1e9: refused (exit 2), no file created, nothing written"

ok=1
grep -q 'would write 1000000001 rows (up to about [0-9.]* GB), more than max_rows = 10000000' \
  "$tmp/err" && grep -q 'max_rows' "$tmp/err" && grep -q 'stop_fate' "$tmp/err" \
  && ok=0
test "$ok" -eq 0 || sed 's/^/# /' "$tmp/err"
result "$ok" "... the message gives the rows, the size, the limit and how to lift it"

scene dense 'collisions = 1e6' 'samples = 1e6'
run_t run "$tmp/dense.ini"
ok=1
test "$rc" -eq 2 && test ! -s "$tmp/raw" \
  && grep -q 'would write 1000003000000 rows' "$tmp/err" && ok=0
result "$ok" "collisions = 1e6, samples = 1e6 (1e12 rows): refused"

run_t skate --collisions 1e9
ok=1
test "$rc" -eq 2 && test ! -s "$tmp/raw" && grep -q 'max_rows = 10000000' "$tmp/err" && ok=0
result "$ok" "skate --collisions 1e9: the same limit refuses it"

cat >"$tmp/sweep.ini" <<'EOF'
[scene]
model = discrete
[sweep]
kind = stability
x_min = -4
x_max = 2
nx = 1e4
y_min = 0
y_max = 1
ny = 1001
EOF
rm -f "$tmp/o.csv"
run_t sweep "$tmp/sweep.ini" -o "$tmp/o.csv"
ok=1
test "$rc" -eq 2 && test ! -e "$tmp/o.csv" \
  && grep -q 'the sweep would write 10010000 rows' "$tmp/err" && ok=0
result "$ok" "a sweep of 1.001e7 points: refused by the same limit, no file"

sed -e 's/^nx = 1e4$/nx = 101/' -e 's/^ny = 1001$/ny = 101/' \
  "$tmp/sweep.ini" >"$tmp/small.ini"
run sweep "$tmp/small.ini" --max-rows 1e4
ok=1
test "$rc" -eq 2 && grep -q 'the sweep would write 10201 rows' "$tmp/err" \
  && run sweep "$tmp/small.ini" --shard 0/2 --max-rows 1e4 \
  && test "$rc" -eq 0 && test "$(wc -l <"$tmp/out")" -eq 5101 && ok=0
result "$ok" "--max-rows 1e4: 10201 points refused, the shard 0/2 of 5100 runs"

run_t run "$tmp/sweep.ini"
ok=1
test "$rc" -eq 2 && test ! -s "$tmp/raw" && ok=0
result "$ok" "... and run refuses it as sweep does"

scene limit 'collisions = 30' 'max_rows = 30'
run run "$tmp/limit.ini"
ok=1
test "$rc" -eq 2 && grep -q 'would write 31 rows' "$tmp/err" && ok=0
result "$ok" "[run] max_rows = 30: 31 rows refused"
run run "$tmp/limit.ini" --max-rows 31
ok=1
test "$rc" -eq 0 && test "$(wc -l <"$tmp/out")" -eq 32 && ok=0
result "$ok" "... --max-rows 31 lifts it (the option wins over the key)"

# ---- stop conditions ------------------------------------------------------
scene fate 'collisions = 1e9' 'stop_fate = yes'
seconds run_t run "$tmp/fate.ini"
ok=1
last=$(tail -n 1 "$tmp/out" | cut -d, -f1)
test "$rc" -eq 0 && test "$last" -ge 6 && test "$last" -lt 100 \
  && awk -v s="$secs" 'BEGIN { exit !(s < 0.5) }' && ok=0
say "stop_fate: last row $last, $secs s"
result "$ok" "stop_fate = yes ends a 1e9-collision run after the reversal, in $secs s (< 0.5 s)"

ok=1
grep -q "^chaplygin: $tmp/fate.ini: stopped at collision $last of 1000000000: stop_fate: the fate is certain: backward" \
  "$tmp/err" && ok=0
test "$ok" -eq 0 || sed 's/^/# /' "$tmp/err"
result "$ok" "... and says why on stderr (collision, fate), exit 0"

ok=1
tail -n 1 "$tmp/raw" | grep -q "^# end: stopped at collision $last of 1000000000: stop_fate" && ok=0
result "$ok" "... and in the last line of the output"

# Where it stopped: the fate is certain there, not one collision before
# (the library's chaplygin_discrete_fate through the same run with a
# maximum of collisions just short of it).
scene fate2 "collisions = $((last - 1))"
run run "$tmp/fate2.ini"
ok=1
test "$rc" -eq 0 && ! grep -q stopped "$tmp/err" && ok=0
scene fate3 "collisions = $((last - 1))" 'stop_fate = yes'
run run "$tmp/fate3.ini"
test "$rc" -eq 0 && ! grep -q stopped "$tmp/err" || ok=1
result "$ok" "... not before: with collisions = $((last - 1)) it runs to the end"

scene H 'collisions = 1e9' 'stop_H = 1e-10' 'outputs = E,H'
seconds run_t run "$tmp/H.ini"
ok=1
test "$rc" -eq 0 && awk -F, -v s="$secs" '
  NR == 1 { next }
  { n++; E = $4; H = $5; if (H < 0) H = -H
    # every row before the last: |H| >= 1e-10 sqrt(2E)
    if (prev_bad) bad = 1
    prev_bad = (H < 1e-10 * sqrt(2 * E)) }
  END { exit !(n > 10 && prev_bad && !bad && s < 0.5) }' "$tmp/out" && ok=0
result "$ok" "stop_H = 1e-10: ends at the first row with |H| < 1e-10 sqrt(2E), in $secs s"

scene T 'collisions = 1e9' 'stop_tau = 50' 'outputs = tau'
run_t run "$tmp/T.ini"
ok=1
test "$rc" -eq 0 && awk -F, '
  NR == 1 { next }
  { if (prev >= 50) bad = 1; prev = $4 + 0; n++ }
  END { exit !(n > 10 && prev >= 50 && !bad) }' "$tmp/out" \
  && grep -q 'stop_tau: tau = ' "$tmp/err" && ok=0
result "$ok" "stop_tau = 50: ends at the first collision with tau >= 50"

scene Tdense 'collisions = 1e9' 'stop_tau = 20' 'samples = 8'
run_t run "$tmp/Tdense.ini"
ok=1
test "$rc" -eq 0 && awk -F, '
  NR == 1 { next }
  { n = $1; tau = $4 + 0; if (tau > tmax) tmax = tau; if ($2 == 0) start = tau }
  END { exit !(start < 20 && tmax >= 20) }' "$tmp/out" && ok=0
result "$ok" "stop_tau, dense: the last segment is the one that reaches tau = 20"

cat >"$tmp/massless.ini" <<'EOF'
[scene]
model = massless
[parameters]
L0 = 1
[initial]
V = 1
Omega = 1
[run]
collisions = 1e9
stop_H = 1e-6
EOF
run_t run "$tmp/massless.ini"
ok=1
test "$rc" -eq 0 && grep -q 'stop_H' "$tmp/err" && ok=0
result "$ok" "massless: stop_H ends a 1e9-collision run"

run_t skate --collisions 1e9 --stop-fate
ok=1
test "$rc" -eq 0 && grep -q 'stopped at collision 0 of 1000000000: stop_fate: the fate is certain: forward' "$tmp/err" && ok=0
result "$ok" "skate --stop-fate: Figure 6's skate is certain from the start"

# ---- every ------------------------------------------------------------------
scene all 'collisions = 25'
scene every 'collisions = 25' 'every = 10'
run run "$tmp/all.ini"
cp "$tmp/out" "$tmp/all.csv"
run run "$tmp/every.ini"
ok=1
awk -F, 'NR == 1 || $1 % 10 == 0 || $1 == 25' "$tmp/all.csv" >"$tmp/want.csv"
test "$rc" -eq 0 && cmp -s "$tmp/out" "$tmp/want.csv" \
  && test "$(cut -d, -f1 "$tmp/out" | tr '\n' ' ')" = "n 0 10 20 25 " && ok=0
result "$ok" "every = 10: rows 0, 10, 20 and the last (25), the same as in the full run"

scene dall 'collisions = 9' 'samples = 4'
scene devery 'collisions = 9' 'samples = 4' 'every = 4'
run run "$tmp/dall.ini"
cp "$tmp/out" "$tmp/dall.csv"
run run "$tmp/devery.ini"
ok=1
awk -F, 'NR == 1 || $1 % 4 == 0 || $1 == 9' "$tmp/dall.csv" >"$tmp/want.csv"
test "$rc" -eq 0 && cmp -s "$tmp/out" "$tmp/want.csv" \
  && test "$(cut -d, -f1 "$tmp/out" | uniq | tr '\n' ' ')" = "n 4 8 9 " && ok=0
result "$ok" "dense, every = 4: segments 4, 8 and the last (9), as in the full run"

run run "$tmp/every.ini" --stats
ok=1
grep -q 'steps=25,' "$tmp/err" && ok=0
result "$ok" "... every map step is still taken (steps=25)"

scene stride 'collisions = 1e9' 'every = 1e8'
run_t run "$tmp/stride.ini" --max-rows 10
ok=1
test "$rc" -eq 2 && grep -q 'would write 11 rows' "$tmp/err" && ok=0
result "$ok" "the estimate counts every: 1e9 collisions every 1e8 are 11 rows"

# ---- a stop condition that never holds: the row limit ends the run ---------
scene never 'collisions = 1e9' 'stop_tau = 1e300' 'max_rows = 40'
run_t run "$tmp/never.ini"
ok=1
test "$rc" -eq 0 && test "$(wc -l <"$tmp/out")" -eq 41 \
  && grep -q 'stopped at collision 39 of 1000000000: max_rows: the limit of 40 rows is reached' "$tmp/err" \
  && tail -n 1 "$tmp/raw" | grep -q '^# end: stopped at collision 39' && ok=0
test "$ok" -eq 0 || sed 's/^/# /' "$tmp/err"
result "$ok" "a stop condition that never holds: the run ends at max_rows rows, saying so"

scene neverd 'collisions = 1e9' 'stop_tau = 1e300' 'max_rows = 40' 'samples = 5'
run_t run "$tmp/neverd.ini"
ok=1
test "$rc" -eq 0 && test "$(wc -l <"$tmp/out")" -eq 41 && grep -q 'max_rows' "$tmp/err" && ok=0
result "$ok" "... dense too (a segment cut at the limit)"
test "$count" -eq "$plan" || echo "Bail out! ran $count tests, planned $plan"
