#!/bin/sh
# test-provenance.sh -- TAP: an output traced to the program and the scene,
# and the Unix conventions of the program.  The '#' lines after the CSV
# header (version, command, method, the effective scene, the "# end:"
# line); CSV readers that skip comments (Python's csv with the '#' lines
# filtered, numpy.genfromtxt with comments='#', gnuplot) read the same data;
# --print-scene, whose output reads back as the same scene; numbers read as
# the correctly rounded double; '-' for standard input and output; -o never
# the scene; -o FILE renamed into place only on success (not after a
# failure or a signal).
# Run by `make check', or by hand:
#   top_builddir=. top_srcdir=. sh tools/test-provenance.sh
# POSIX sh.

set -u
top_builddir=${top_builddir:-.}
prog=${CHAPLYGIN:-$top_builddir/tools/chaplygin}
python=${PYTHON:-python3}

. "${top_srcdir:-.}/tools/tap-lib.sh"
tap_start test-provenance 25

say () { echo "# $*" >&2; }
skip () { count=$((count + 1)); echo "ok $count # SKIP $*"; }

cat >"$tmp/fig6.ini" <<'EOF'
; Figure 6's skate
[scene]
model = discrete
title = Figure 6, per collision
[parameters]
L0 = 1
Delta = 1/3
[initial]
V = 1
Omega = 0.5
[run]
collisions = 20
outputs = E,H,theta,tau,peg,V
EOF

# ---- the provenance lines -------------------------------------------------
run run "$tmp/fig6.ini"
cp "$tmp/raw" "$tmp/fig6.raw"
cp "$tmp/out" "$tmp/fig6.csv"
version=$("$prog" --version | sed 's/^chaplygin //')
ok=1
test "$rc" -eq 0 \
  && test "$(sed -n 1p "$tmp/fig6.raw")" = "n,D,reversal,E,H,theta,tau,peg_x,peg_y,V" \
  && test "$(sed -n 2p "$tmp/fig6.raw")" = "# chaplygin $version: chaplygin run $tmp/fig6.ini" \
  && test "$(sed -n 3p "$tmp/fig6.raw")" = "# scene file: $tmp/fig6.ini" \
  && test "$(sed -n 4p "$tmp/fig6.raw")" = "# method: closed-form (tolerance not used)" \
  && test "$(tail -n 1 "$tmp/fig6.raw")" = "# end: complete: collision 20 of 20" \
  && test "$(grep -c '^#' "$tmp/fig6.raw")" -gt 10 \
  && test "$(grep -vc '^#' "$tmp/fig6.raw")" -eq 22 && ok=0
test "$ok" -eq 0 || sed -n '1,5p;$p' "$tmp/fig6.raw" | sed 's/^/# /'
result "$ok" "the header line, then '#' lines: version, command, scene file, method; last '# end: complete'"

# The effective scene in the '#' lines: every key, defaults included.
sed -n 's/^#   //p' "$tmp/fig6.raw" >"$tmp/effective.ini"
ok=1
for line in '[scene]' 'model = discrete' 'title = Figure 6, per collision' \
            'L0 = 1' 'Delta = 1/3' 'V = 1' 'Omega = 0.5' 'theta = 0' \
            'collisions = 20' 'samples = 0' 'outputs = E,H,theta,tau,peg,V' \
            'method = closed-form' 'every = 1' 'stop_fate = no' \
            'max_rows = 10000000' '[plot]' 'view = panels'; do
  grep -qxF "$line" "$tmp/effective.ini" || { say "missing: $line"; ok=2; }
done
test "$ok" -eq 2 || ok=0
result "$ok" "the '#' lines hold the effective scene, defaults included (theta, method, every, max_rows ...)"

run run "$tmp/effective.ini"
ok=1
test "$rc" -eq 0 && cmp -s "$tmp/out" "$tmp/fig6.csv" && ok=0
result "$ok" "... which, run, gives the same data"

run run --print-scene "$tmp/fig6.ini"
ok=1
test "$rc" -eq 0 && cmp -s "$tmp/raw" "$tmp/effective.ini" && ok=0
result "$ok" "--print-scene prints that scene (and runs nothing)"

run run --no-provenance "$tmp/fig6.ini"
ok=1
test "$rc" -eq 0 && ! grep -q '^#' "$tmp/raw" && cmp -s "$tmp/raw" "$tmp/fig6.csv" && ok=0
result "$ok" "--no-provenance: plain CSV, the same data"

# ---- CSV readers skip the '#' lines ----------------------------------------
if "$python" -c 'import numpy' 2>/dev/null; then
  "$python" - "$tmp/fig6.raw" "$tmp/fig6.csv" >"$tmp/py.out" 2>&1 <<'EOF'
import csv, sys
import numpy as np
raw, plain = sys.argv[1], sys.argv[2]
with open(raw) as f:
    rows = list(csv.reader(line for line in f if not line.startswith('#')))
with open(plain) as f:
    want = list(csv.reader(f))
assert rows == want, 'csv'
a = np.genfromtxt(raw, delimiter=',', names=True, comments='#')
b = np.genfromtxt(plain, delimiter=',', names=True)
assert a.dtype.names == tuple(want[0]), a.dtype.names
assert len(a) == 21 and all(np.array_equal(a[n], b[n]) for n in want[0])
# %.17g reads back exactly: the values are the CSV's
assert a['E'][20] == float(want[21][3])
print('ok')
EOF
  ok=1
  test "$(cat "$tmp/py.out")" = ok && ok=0
  test "$ok" -eq 0 || sed 's/^/# /' "$tmp/py.out"
  result "$ok" "Python: csv (comment lines filtered) and numpy.genfromtxt(comments='#') read the data"
else
  skip "no $python with numpy"
fi

if command -v gnuplot >/dev/null 2>&1; then
  n=$(gnuplot -d -e "set datafile separator comma; set datafile columnheaders; stats '$tmp/fig6.raw' using 'E' nooutput; print STATS_records" 2>&1)
  ok=1
  test "$n" = 21 && ok=0
  result "$ok" "gnuplot (columnheaders) reads the 21 rows ($n)"
else
  skip "no gnuplot"
fi

# ---- numbers: the correctly rounded double ------------------------------------
run skate --Delta 1/3 --L0 9007199254740993/3 --print-scene
ok=1
grep -qx 'Delta = 0.3333333333333333' "$tmp/out" \
  && grep -qx 'L0 = 3002399751580331' "$tmp/out" && ok=0
result "$ok" "skate --Delta 1/3: the double nearest 1/3; 9007199254740993/3 exactly 3002399751580331"

run skate --collisions 1e3 --every 2e2 --tol 1e-12 --method quadrature --print-scene
ok=1
grep -qx 'collisions = 1000' "$tmp/out" && grep -qx 'every = 200' "$tmp/out" \
  && grep -qx 'tolerance = 1e-12' "$tmp/out" && ok=0
result "$ok" "integers written 1e3 are integers (options and scene alike)"

# ---- '-' ----------------------------------------------------------------------
rc=0
"$prog" run - <"$tmp/fig6.ini" >"$tmp/stdin.raw" 2>"$tmp/err" || rc=$?
ok=1
test "$rc" -eq 0 && grep -v '^#' "$tmp/stdin.raw" | cmp -s - "$tmp/fig6.csv" \
  && grep -qx '# scene file: (standard input)' "$tmp/stdin.raw" && ok=0
result "$ok" "run -: the scene from standard input"

abs_prog=$(cd "$(dirname "$prog")" && pwd)/$(basename "$prog")
(cd "$tmp" && "$abs_prog" run fig6.ini -o - >stdout.raw 2>err) && rc=0 || rc=$?
ok=1
test "$rc" -eq 0 && test ! -e "$tmp/-" && grep -v '^#' "$tmp/stdout.raw" \
  | cmp -s - "$tmp/fig6.csv" && ok=0
result "$ok" "-o -: standard output, no file named '-'"

run run - --print-scene <"$tmp/fig6.ini"
ok=1
"$prog" run --print-scene - <"$tmp/raw" >"$tmp/again.ini" 2>/dev/null \
  && cmp -s "$tmp/raw" "$tmp/again.ini" && ok=0
result "$ok" "--print-scene of --print-scene's output is the same (a fixed point)"

# ---- -o is never the scene ----------------------------------------------------
cp "$tmp/fig6.ini" "$tmp/keep.ini"
ln -s keep.ini "$tmp/link.ini"
ok=0
for out in "$tmp/keep.ini" "$tmp/link.ini" "$tmp/../$(basename "$tmp")/keep.ini"; do
  run run "$tmp/keep.ini" -o "$out"
  if test "$rc" -ne 2 || ! grep -q 'refusing to overwrite the input' "$tmp/err" \
     || ! cmp -s "$tmp/keep.ini" "$tmp/fig6.ini"; then
    say "-o $out: exit $rc"; ok=1
  fi
done
run sweep "$tmp/keep.ini" -o "$tmp/link.ini"
test "$rc" -eq 2 || ok=1
result "$ok" "-o the scene itself (by name, symbolic link, another path): refused, the scene intact"

# ---- -o FILE: a temporary file renamed on success ------------------------------
rm -f "$tmp/o.csv"
(umask 027 && "$prog" run "$tmp/fig6.ini" -o "$tmp/o.csv" 2>/dev/null)
ok=1
test "$(stat -c %a "$tmp/o.csv")" = 640 && test -z "$(ls -A "$tmp" | grep '^\.o\.csv\.')" && ok=0
result "$ok" "-o FILE: a new file has the permissions of the umask (640 under 027), no temporary left"

chmod 604 "$tmp/o.csv"
"$prog" run "$tmp/fig6.ini" -o "$tmp/o.csv" 2>/dev/null
ok=1
test "$(stat -c %a "$tmp/o.csv")" = 604 && ok=0
result "$ok" "... an existing FILE keeps its permissions"

ln -s o.csv "$tmp/o-link.csv"
"$prog" run --no-provenance "$tmp/fig6.ini" -o "$tmp/o-link.csv" 2>/dev/null
ok=1
test -L "$tmp/o-link.csv" && cmp -s "$tmp/o.csv" "$tmp/fig6.csv" && ok=0
result "$ok" "... a symbolic link stays one; its target is written"

# A library failure: the motion spins at collision 1 (2E = H^2 with the
# mass centre in the slot).
cat >"$tmp/spin.ini" <<'EOF'
[scene]
model = discrete
[parameters]
L0 = -0.5
Delta = 1
[initial]
V = 0.4472135954999579
Omega = 0.8
[run]
collisions = 5
EOF
echo "old" >"$tmp/old.csv"
run run "$tmp/spin.ini" -o "$tmp/old.csv"
ok=1
test "$rc" -eq 1 && test "$(cat "$tmp/old.csv")" = old \
  && test -z "$(ls -A "$tmp" | grep '^\.old\.csv\.')" && ok=0
test "$ok" -eq 0 || sed 's/^/# /' "$tmp/err"
result "$ok" "a run the library fails (exit 1): -o FILE left as it was, no temporary left"

run run "$tmp/spin.ini"
ok=1
test "$rc" -eq 1 && test "$(grep -vc '^#' "$tmp/raw")" -ge 2 \
  && tail -n 1 "$tmp/raw" | grep -q '^# end: failed at collision [0-9]*: ' && ok=0
result "$ok" "... on standard output the rows before stay, the last line says it failed"

# A run interrupted by a signal: FILE is never a truncated CSV.
cat >"$tmp/long.ini" <<'EOF'
[scene]
model = discrete
[parameters]
L0 = 1
Delta = 1/3
[initial]
V = 1
Omega = 0.5
[run]
collisions = 9e6
outputs = E,H,theta,tau,peg,V,Omega,path,G
EOF
for case in new existing; do
  rm -f "$tmp/long.csv"
  test "$case" = existing && echo "old" >"$tmp/long.csv"
  "$prog" run "$tmp/long.ini" -o "$tmp/long.csv" 2>/dev/null &
  pid=$!
  # until the temporary file has rows
  i=0
  while test "$i" -lt 100; do
    t=$(ls -A "$tmp" | grep '^\.long\.csv\.' | head -n 1)
    test -n "$t" && test -s "$tmp/$t" && break
    sleep 0.05
    i=$((i + 1))
  done
  kill -TERM "$pid"
  wait "$pid" && st=0 || st=$?
  ok=1
  if test "$case" = new; then
    test ! -e "$tmp/long.csv" && ok=0
  else
    test "$(cat "$tmp/long.csv")" = old && ok=0
  fi
  test -n "$t" && test -z "$(ls -A "$tmp" | grep '^\.long\.csv\.')" \
    && test "$st" -eq 143 || ok=1
  result "$ok" "SIGTERM during a run -o FILE ($case FILE): FILE not written, the temporary removed (exit $st)"
done

# ---- sweeps --------------------------------------------------------------------
cat >"$tmp/basins.ini" <<'EOF'
[scene]
model = discrete
title = basins
[parameters]
L0 = -1/2
Delta = 1
[initial]
Omega = 4/5
[run]
collisions = 1e4
[sweep]
kind = basins
x_min = 0.01
x_max = 0.5
nx = 50
EOF
run sweep "$tmp/basins.ini" --shard 1/2
ok=1
test "$rc" -eq 0 \
  && test "$(sed -n 1p "$tmp/raw")" = "k,V0,fate,collisions,reversals,E_final,V_final,status" \
  && grep -qx "# chaplygin $version: chaplygin sweep $tmp/basins.ini --shard 1/2" "$tmp/raw" \
  && grep -qx '#   kind = basins' "$tmp/raw" && grep -qx '#   collisions = 10000' "$tmp/raw" \
  && test "$(tail -n 1 "$tmp/raw")" = "# end: complete: 25 points, k = 25 .. 49 of 50" && ok=0
result "$ok" "sweep: the same provenance lines, the shard in the command and the end line"

# Shards concatenated, comments and repeated header lines dropped: the
# unsharded sweep's data.
run sweep "$tmp/basins.ini"
cp "$tmp/out" "$tmp/whole.csv"
{
  "$prog" sweep "$tmp/basins.ini" --shard 0/2 2>/dev/null
  "$prog" sweep "$tmp/basins.ini" --shard 1/2 2>/dev/null | sed 1d
} | grep -v '^#' >"$tmp/cat.csv"
ok=1
cmp -s "$tmp/cat.csv" "$tmp/whole.csv" && ok=0
result "$ok" "... shards concatenated ('#' lines and later headers dropped) = the whole sweep"

run sweep --print-scene "$tmp/basins.ini"
ok=1
test "$rc" -eq 0 && grep -qx 'nx = 50' "$tmp/out" && grep -qx 'max_rows = 10000000' "$tmp/out" \
  && ! grep -q '^samples' "$tmp/out" && ok=0
result "$ok" "sweep --print-scene: the keys of a basins sweep only"

run run "$tmp/basins.ini" -o "$tmp/b.csv"
ok=1
test "$rc" -eq 0 && test ! -s "$tmp/raw" && grep -v '^#' "$tmp/b.csv" | cmp -s - "$tmp/whole.csv" && ok=0
result "$ok" "run of a sweep scene: the same data, -o renamed into place"

# ---- statuses by name -------------------------------------------------------
sed -e 's/^x_min = 0.01$/x_min = -0.5/' -e 's/^nx = 50$/nx = 3/' \
  "$tmp/basins.ini" >"$tmp/zero.ini"
run sweep "$tmp/zero.ini"
ok=1
test "$(cut -d, -f8 "$tmp/out" | tr '\n' ' ')" = "status SUCCESS ESTATE SUCCESS " && ok=0
result "$ok" "sweep statuses are names (SUCCESS, ESTATE for the grid point V+ = 0)"

test "$count" -eq "$plan" || echo "Bail out! ran $count tests, planned $plan"
