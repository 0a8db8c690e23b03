#!/bin/sh
# test-merge.sh -- TAP tests of "chaplygin merge" (tools/merge.c) and of the
# Slurm job array of examples/slurm, without Slurm: atlas.sbatch is run
# with bash for SLURM_ARRAY_TASK_ID = 0 .. N-1 and SLURM_ARRAY_TASK_COUNT =
# N, then merge.sbatch; the merged CSV must be the unsharded sweep (its rows
# and end line byte for byte, its '#' lines but the command's and the
# merge's).  Then every refusal: a gap, an overlap, a shard cut short, one
# of another scene or version, a --no-provenance output, an unreadable
# file, a row lost inside a shard, a write to /dev/full; GNU parallel's
# line of examples/slurm/README if parallel is installed (else SKIP).
# Run by `make check', or by hand:
#   CHAPLYGIN=tools/chaplygin sh tools/test-merge.sh
# POSIX sh (dash); the .sbatch scripts need bash (else their tests SKIP).

set -u

prog=${CHAPLYGIN:-${top_builddir:-.}/tools/chaplygin}
slurm=${top_srcdir:-.}/examples/slurm
unset CHAPLYGIN_NO_PROGRESS SLURM_ARRAY_TASK_ID SLURM_ARRAY_TASK_COUNT \
  SLURM_ARRAY_TASK_MIN SLURM_ARRAY_TASK_MAX SLURM_ARRAY_TASK_STEP \
  SLURM_CPUS_PER_TASK SCENE SHARD_DIR MERGED

. "${top_srcdir:-.}/tools/tap-lib.sh"
tap_start test-merge 33

# The program by an absolute name (the scripts run in other directories).
case $prog in
  /*) ;;
  *) prog=$(cd "$(dirname "$prog")" && pwd)/$(basename "$prog") ;;
esac
case $slurm in
  /*) ;;
  *) slurm=$(cd "$slurm" && pwd) ;;
esac
fig3=$(cd "${top_srcdir:-.}/scenes" && pwd)/fig3.ini

say () {
  echo "# $*" >&2
}

# skip TEXT WHY: one test skipped.
skip () {
  count=$((count + 1))
  echo "ok $count - $1 # SKIP $2"
}

have_bash=0
command -v bash >/dev/null 2>&1 && have_bash=1

# ---- scenes ---------------------------------------------------------------
# A small atlas: 40 x 30 = 1200 points.
cat >"$tmp/atlas.ini" <<'EOF'
[scene]
model = discrete
[parameters]
L0 = -0.5
Delta = 1
[run]
collisions = 100000
[sweep]
kind = atlas
x = V
x_min = 0.01
x_max = 0.5
nx = 40
y = Omega
y_min = 0.1
y_max = 2
ny = 30
EOF
# The same but one grid value: another sweep of the same size.
sed 's/^x_max = 0.5$/x_max = 0.6/' "$tmp/atlas.ini" >"$tmp/other.ini"
# Basins of Figure 3 (4000 points), and 5 points of which the middle one is
# V0 = 0 (a row with status ESTATE), split in more shards than points.
cat >"$tmp/zero.ini" <<'EOF'
[scene]
model = discrete
[parameters]
L0 = -0.5
Delta = 1
[initial]
Omega = 0.8
[run]
collisions = 1000
[sweep]
kind = basins
x_min = -1
x_max = 1
nx = 5
EOF

# shards SCENE N DIR: SCENE's N shards into DIR/shard-i.csv by
# atlas.sbatch, run with bash as Slurm would run task i of N.  0 if every
# task succeeded.
shards () {
  mkdir -p "$3" || return 1
  s=0
  while test "$s" -lt "$2"; do
    (cd "$3" && SLURM_ARRAY_TASK_ID=$s SLURM_ARRAY_TASK_COUNT=$2 \
       CHAPLYGIN=$prog SCENE=$1 bash "$slurm/atlas.sbatch") \
      2>>"$tmp/err" || { say "atlas.sbatch, task $s of $2, failed"; return 1; }
    s=$((s + 1))
  done
}

# merged DIR: merge.sbatch run with bash in DIR (its shard-*.csv into
# DIR/atlas.csv).
merged () {
  (cd "$1" && CHAPLYGIN=$prog bash "$slurm/merge.sbatch") 2>>"$tmp/err"
}

# same_as_unsharded SCENE MERGED: MERGED is the unsharded sweep of SCENE:
# its rows and end line byte for byte, and its '#' lines but the command's
# and the merge's ("# chaplygin ", "# merged from ", "# shard ").
same_as_unsharded () {
  (cd "$(dirname "$2")" && "$prog" sweep "$1" -o unsharded.csv) \
    2>>"$tmp/err" || return 1
  u=$(dirname "$2")/unsharded.csv
  grep -v '^#' "$u" >"$tmp/u.rows" && grep -v '^#' "$2" >"$tmp/m.rows" \
    && cmp "$tmp/u.rows" "$tmp/m.rows" >/dev/null \
    && tail -n 1 "$u" >"$tmp/u.end" && tail -n 1 "$2" >"$tmp/m.end" \
    && grep -q '^# end: complete: ' "$tmp/u.end" \
    && cmp "$tmp/u.end" "$tmp/m.end" >/dev/null \
    && grep -v '^# chaplygin \|^# merged from \|^# shard ' "$u" >"$tmp/u.all" \
    && grep -v '^# chaplygin \|^# merged from \|^# shard ' "$2" >"$tmp/m.all" \
    && cmp "$tmp/u.all" "$tmp/m.all" >/dev/null
}

# ---- the job array, without Slurm -------------------------------------------
: >"$tmp/err"
if test "$have_bash" -eq 1; then
  ok=1
  if shards "$tmp/atlas.ini" 4 "$tmp/a"; then
    ok=0
    for s in 0 1 2 3; do
      test -s "$tmp/a/shard-$s.csv" || ok=1
    done
  fi
  result "$ok" "atlas.sbatch: tasks 0..3 of 4 write shard-0.csv .. shard-3.csv"
  ok=1
  merged "$tmp/a" && test -s "$tmp/a/atlas.csv" && ok=0
  result "$ok" "merge.sbatch: the shards merged into atlas.csv"
  ok=1
  same_as_unsharded "$tmp/atlas.ini" "$tmp/a/atlas.csv" && ok=0
  result "$ok" "atlas, 4 shards: merged = unsharded (rows, end line, scene)"
  ok=1
  test "$(grep -c '^k,' "$tmp/a/atlas.csv")" -eq 1 \
    && grep -q '^# merged from 4 shards' "$tmp/a/atlas.csv" \
    && test "$(grep -c '^# shard k = ' "$tmp/a/atlas.csv")" -eq 4 \
    && grep -q '^# shard k = 300 \.\. 599 (.*shard-1\.csv): chaplygin [^ ]*: chaplygin sweep .* --shard 1/4 ' \
         "$tmp/a/atlas.csv" \
    && test "$(tail -n 1 "$tmp/a/atlas.csv")" \
         = "# end: complete: 1200 points, k = 0 .. 1199 of 1200" && ok=0
  result "$ok" "atlas: one header line, the merge's and each shard's command, the end line"
else
  for t in "atlas.sbatch: 4 tasks" "merge.sbatch" "atlas: merged = unsharded" \
           "atlas: the merge's provenance"; do
    skip "$t" "no bash"
  done
  mkdir -p "$tmp/a"
  for s in 0 1 2 3; do
    "$prog" sweep "$tmp/atlas.ini" --shard $s/4 -o "$tmp/a/shard-$s.csv"
  done
fi

# The shards named in any order: the same output but the command line.
ok=1
if (cd "$tmp/a" && "$prog" merge -o rev.csv shard-3.csv shard-1.csv \
      shard-0.csv shard-2.csv && "$prog" merge -o in-order.csv shard-0.csv \
      shard-1.csv shard-2.csv shard-3.csv) 2>"$tmp/err"; then
  sed 1,2d "$tmp/a/rev.csv" >"$tmp/rev" && sed 1,2d "$tmp/a/in-order.csv" >"$tmp/ord" \
    && cmp "$tmp/rev" "$tmp/ord" >/dev/null && ok=0
fi
result "$ok" "shards given in any order: the same output"

if test "$have_bash" -eq 1; then
  ok=1
  shards "$fig3" 3 "$tmp/b" && merged "$tmp/b" \
    && same_as_unsharded "$fig3" "$tmp/b/atlas.csv" && ok=0
  result "$ok" "basins (scenes/fig3.ini), 3 shards by the scripts: merged = unsharded"
  ok=1
  shards "$tmp/zero.ini" 7 "$tmp/z" && merged "$tmp/z" \
    && same_as_unsharded "$tmp/zero.ini" "$tmp/z/atlas.csv" \
    && grep -q ',ESTATE$' "$tmp/z/atlas.csv" \
    && test "$(grep -c '^# shard without points' "$tmp/z/atlas.csv")" -eq 2 \
    && ok=0
  result "$ok" "basins, 5 points (one ESTATE) in 7 shards, 2 empty: merged = unsharded"
  ok=1
  (cd "$tmp" && SLURM_ARRAY_TASK_ID=17 SLURM_ARRAY_TASK_COUNT=1 \
     SLURM_ARRAY_TASK_MIN=17 SLURM_ARRAY_TASK_MAX=17 CHAPLYGIN=$prog \
     SCENE=$tmp/atlas.ini bash "$slurm/atlas.sbatch") 2>"$tmp/err"
  rc=$?
  test "$rc" -eq 2 && grep -q 'the array must be 0-0' "$tmp/err" \
    && test ! -e "$tmp/shard-17.csv" && ok=0
  result "$ok" "atlas.sbatch refuses an array that does not start at 0 (exit 2)"
  ok=1
  (cd "$tmp" && CHAPLYGIN=$prog bash "$slurm/atlas.sbatch") 2>"$tmp/err"
  rc=$?
  test "$rc" -eq 2 && grep -q 'SLURM_ARRAY_TASK_ID' "$tmp/err" && ok=0
  result "$ok" "atlas.sbatch outside an array: exit 2, says what to set"
else
  for t in "basins by the scripts" "basins, empty shards" \
           "atlas.sbatch: array not from 0" "atlas.sbatch outside an array"; do
    skip "$t" "no bash"
  done
fi

# GNU parallel: the README's line.
if command -v parallel >/dev/null 2>&1; then
  ok=1
  mkdir -p "$tmp/p"
  if (cd "$tmp/p" && parallel "$prog" sweep "$tmp/atlas.ini" --shard {}/5 \
        -o shard-{}.csv ::: $(seq 0 4) \
        && "$prog" merge -o atlas.csv shard-*.csv) >/dev/null 2>"$tmp/err" \
     && same_as_unsharded "$tmp/atlas.ini" "$tmp/p/atlas.csv"; then
    ok=0
  fi
  result "$ok" "GNU parallel, 5 shards: merged = unsharded"
else
  skip "GNU parallel, 5 shards: merged = unsharded" "GNU parallel not installed"
fi

# ---- refusals -----------------------------------------------------------------
# refuse TEXT PATTERN ARGS...: merge -o $tmp/r.csv ARGS... exits 2 with a
# "chaplygin: " message matching PATTERN (grep), and $tmp/r.csv holds what
# it held before ("old").
refuse () {
  text=$1
  pattern=$2
  shift 2
  echo old >"$tmp/r.csv"
  rc=0
  (cd "$tmp/a" && "$prog" merge -o "$tmp/r.csv" "$@") >"$tmp/out" \
    2>"$tmp/err" || rc=$?
  ok=1
  if test "$rc" -eq 2 && grep -q "^chaplygin: .*$pattern" "$tmp/err" \
     && test "$(cat "$tmp/r.csv")" = old && test ! -s "$tmp/out"; then
    ok=0
  else
    say "merge $*: exit $rc, want 2 and /$pattern/"
    sed 's/^/# stderr: /' "$tmp/err" >&2
  fi
  result "$ok" "$text"
}

cd "$tmp/a" || exit 1
refuse "a missing shard: a gap, with its k range" \
  'a gap: no shard has the points k = 300 \.\. 599 of 1200, between shard-0\.csv (k = 0 \.\. 299) and shard-2\.csv' \
  shard-0.csv shard-2.csv shard-3.csv
refuse "a missing last shard: a gap at the end" \
  'a gap: no shard has the points k = 900 \.\. 1199 of 1200, after shard-2\.csv' \
  shard-0.csv shard-1.csv shard-2.csv
refuse "a missing first shard: a gap at the start" \
  'a gap: no shard has the points k = 0 \.\. 299 of 1200, before shard-1\.csv' \
  shard-3.csv shard-1.csv shard-2.csv
cp shard-1.csv copy-of-1.csv
refuse "a duplicated shard: an overlap, with its k range" \
  'an overlap: shard-1\.csv (k = 300 \.\. 599) and copy-of-1\.csv (k = 300 \.\. 599) both have the points k = 300 \.\. 599' \
  shard-0.csv shard-1.csv shard-2.csv shard-3.csv copy-of-1.csv
"$prog" sweep "$tmp/atlas.ini" --shard 1/3 -o third-1.csv 2>"$tmp/err"
refuse "shards of two splits (1/3 over 1/4, 2/4): an overlap" \
  'an overlap: shard-1\.csv (k = 300 \.\. 599) and third-1\.csv (k = 400 \.\. 799) both have the points k = 400 \.\. 599' \
  shard-0.csv shard-1.csv third-1.csv shard-2.csv shard-3.csv
sed '$d' shard-2.csv >cut.csv
refuse "a shard without its end line (cut short)" \
  "cut\.csv: no '# end:' line at its end .*cut short" \
  shard-0.csv shard-1.csv cut.csv shard-3.csv
head -c 3000 shard-2.csv >cut2.csv
refuse "a shard cut inside a line" \
  'cut2\.csv: its last line has no line end: the shard was cut short' \
  shard-0.csv shard-1.csv cut2.csv shard-3.csv
sed '$s/^# end: .*/# end: stopped at collision 3 of 9: the row limit/' \
  shard-2.csv >stopped.csv
refuse "a shard whose end line is not complete" \
  "stopped\.csv: the shard is not complete: its end line is '# end: stopped" \
  shard-0.csv shard-1.csv stopped.csv shard-3.csv
sed '$s/ of 1200$/ of 1500/' shard-2.csv >total.csv
refuse "a shard whose end line gives another number of points in all" \
  'total\.csv: a shard of a sweep of 1500 points, shard-0\.csv of one of 1200' \
  shard-0.csv shard-1.csv total.csv shard-3.csv
# A row deleted inside the shard: its end line is intact, so only the
# copy (pass 2) sees it; the output is still not written.
awk '!/^#/ && $0 ~ /^650,/ { next } { print }' shard-2.csv >lost.csv
refuse "a row lost inside a shard: found while copying, by line and k" \
  'lost\.csv: line [0-9]*: the row .651,.* where the next row must have k = 650' \
  shard-0.csv shard-1.csv lost.csv shard-3.csv
(printf '%s\n' '# a note') | cat shard-2.csv - >after.csv
refuse "text after the end line (the end line not last)" \
  "after\.csv: no '# end:' line at its end (its last line: '# a note')" \
  shard-0.csv shard-1.csv after.csv shard-3.csv
"$prog" sweep "$tmp/other.ini" --shard 2/4 -o other-2.csv 2>"$tmp/err"
refuse "a shard of another scene, named, with the differing line" \
  "other-2\.csv: its effective scene differs from that of shard-0\.csv (line [0-9]*: '#   x_max = 0\.6', where shard-0\.csv has '#   x_max = 0\.5')" \
  shard-0.csv shard-1.csv other-2.csv shard-3.csv
sed '2s/^# chaplygin [^:]*:/# chaplygin 99.0:/' shard-2.csv >version.csv
refuse "a shard of another version of the program" \
  'version\.csv: written by chaplygin 99\.0, shard-0\.csv by chaplygin' \
  shard-0.csv shard-1.csv version.csv shard-3.csv
"$prog" sweep "$tmp/atlas.ini" --shard 2/4 --no-provenance -o plain-2.csv \
  2>"$tmp/err"
refuse "a --no-provenance shard, saying why it is needed" \
  "plain-2\.csv: no provenance .*--no-provenance: merge needs them" \
  shard-0.csv shard-1.csv plain-2.csv shard-3.csv
refuse "a --no-provenance shard given first" \
  "plain-2\.csv: no provenance .*--no-provenance" \
  plain-2.csv shard-0.csv shard-1.csv shard-3.csv
refuse "a file that does not exist, named" \
  'no-such\.csv: No such file or directory' \
  shard-0.csv shard-1.csv no-such.csv shard-3.csv
cp shard-2.csv unreadable.csv
chmod 000 unreadable.csv
if test -r unreadable.csv; then
  skip "an unreadable file (permission denied)" "running as root"
else
  refuse "an unreadable file (permission denied), named" \
    'unreadable\.csv: Permission denied' \
    shard-0.csv shard-1.csv unreadable.csv shard-3.csv
fi
chmod 644 unreadable.csv
mkdir -p dir.csv
refuse "a directory given as a shard" \
  'dir\.csv: not a regular file' \
  shard-0.csv shard-1.csv dir.csv shard-3.csv
ok=1
cp shard-1.csv keep-1.csv
rc=0
"$prog" merge -o shard-1.csv shard-0.csv shard-1.csv shard-2.csv shard-3.csv \
  2>"$tmp/err" || rc=$?
test "$rc" -eq 2 && grep -q 'refusing to overwrite the input shard-1\.csv' \
  "$tmp/err" && cmp shard-1.csv keep-1.csv >/dev/null && ok=0
result "$ok" "-o one of the shards: refused (exit 2), the shard unchanged"

# ---- output errors, usage -------------------------------------------------------
ok=1
rc=0
"$prog" merge -o /dev/full shard-0.csv shard-1.csv shard-2.csv shard-3.csv \
  2>"$tmp/err" || rc=$?
test "$rc" -eq 1 && grep -q '^chaplygin: error writing to /dev/full: ' \
  "$tmp/err" && ok=0
result "$ok" "-o /dev/full: exit 1, 'error writing to /dev/full'"
ok=1
rc=0
"$prog" merge shard-0.csv shard-1.csv shard-2.csv shard-3.csv >/dev/full \
  2>"$tmp/err" || rc=$?
test "$rc" -eq 1 && grep -q '^chaplygin: error writing to standard output: ' \
  "$tmp/err" && ok=0
result "$ok" "standard output /dev/full: exit 1, a message"
ok=1
rc=0
"$prog" merge 2>"$tmp/err" || rc=$?
test "$rc" -eq 2 && grep -q '^chaplygin: merge: no shard files' "$tmp/err" \
  && ok=0
rc=0
"$prog" merge --bogus shard-0.csv 2>"$tmp/err" || rc=$?
test "$rc" -eq 2 && grep -q "^chaplygin: merge: unknown option '--bogus'" \
  "$tmp/err" || ok=1
result "$ok" "no shard, an unknown option: exit 2, a message"
ok=1
"$prog" merge --help >"$tmp/out" 2>"$tmp/err" \
  && grep -q '^Usage: chaplygin merge \[-o FILE\] SHARD\.csv\.\.\.' "$tmp/out" \
  && "$prog" --help | grep -q '^  merge  ' && ok=0
result "$ok" "merge --help, and merge in chaplygin --help"
