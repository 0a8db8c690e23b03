#!/bin/sh
# test-output.sh -- TAP: where the program writes (tools/output.c), under
# hostile conditions.
#  - A failed write never replaces an existing -o FILE and leaves no
#    temporary file: a full disk (a 64 KiB tmpfs; as root, where mount
#    works, else skipped), the file-size limit (ulimit -f: SIGXFSZ is
#    ignored, the write fails with EFBIG); on standard output exit 1.
#  - The output is never the scene, by identity: run/sweep/plot - -o
#    SCENE < SCENE, hard and symbolic links, ./x, /dev/stdin, standard
#    output appended to the scene, --print-scene -o SCENE.
#  - --print-scene -o FILE writes FILE (run, sweep, skate); -o onto a
#    dangling symbolic link writes its target; a link loop is an error.
#  - Control characters of names and arguments are shown as \xHH in
#    messages, never raw.
#  - Every catchable signal that ends a program, sent to a run writing
#    -o FILE, leaves no temporary file and FILE as it was (one test per
#    signal, from `kill -l`); SIGXFSZ is ignored; a signal ignored at
#    start (nohup) stays ignored.
# Run by `make check', or by hand:
#   top_builddir=. top_srcdir=. sh tools/test-output.sh
# POSIX sh; Linux (tmpfs, the signals of kill -l).

set -u
top_builddir=${top_builddir:-.}
top_srcdir=${top_srcdir:-.}
prog=${CHAPLYGIN:-$top_builddir/tools/chaplygin}

# The signals sent: every number of `kill -l` whose default action ends a
# program and that a program can catch.  Not sent: KILL and STOP (no
# program can catch them), XFSZ (ignored: a test below), the signals that
# do not end a program, and the numbers without a name below the
# real-time ones (32, 33: kept by the C library for its threads).
signals=""
n=1
while test "$n" -le 64; do
  name=$(kill -l "$n" 2>/dev/null) || name=""
  case $name in
    ""|KILL|STOP|XFSZ|CHLD|CONT|TSTP|TTIN|TTOU|URG|WINCH) ;;
    *[!0-9]*) signals="$signals $n" ;;
    *) test "$n" -lt 32 && signals="$signals $n" ;;   # 16: STKFLT in dash
  esac
  n=$((n + 1))
done
n_signals=$(echo $signals | wc -w)

. "$top_srcdir/tools/tap-lib.sh"
tap_start test-output $((14 + n_signals))

say () { echo "# $*" >&2; }
abs_prog=$(cd "$(dirname "$prog")" && pwd)/$(basename "$prog")

# no_temp DIR NAME: no temporary file .NAME.XXXXXX left in DIR.
no_temp () {
  test -z "$(ls -A "$1" | grep "^\.$2\.")"
}

cat >"$tmp/s.ini" <<'EOF'
[scene]
model = discrete
title = output
[parameters]
L0 = 1
Delta = 1/3
[initial]
V = 1
Omega = 0.5
[run]
collisions = 200
outputs = E,H,theta,tau,peg,V,Omega,path,G
EOF
cp "$tmp/s.ini" "$tmp/orig.ini"
cat >"$tmp/w.ini" <<'EOF'
[scene]
model = discrete
[parameters]
L0 = -1/2
Delta = 1
[initial]
Omega = 4/5
[run]
collisions = 1e3
[sweep]
kind = basins
x_min = 0.01
x_max = 0.5
nx = 400
EOF

# ---- a full disk: a 64 KiB tmpfs filled to its last 8 KiB ------------------------
full=$tmp/full
mkdir "$full"
if mount -t tmpfs -o size=64k tmpfs "$full" 2>/dev/null; then
  trap 'umount "$full" 2>/dev/null; rm -rf "$tmp"' 0
  dd if=/dev/zero of="$full/fill" bs=1024 count=56 2>/dev/null
  ok=0
  for cmd in run sweep; do
    scene=$tmp/s.ini
    test "$cmd" = sweep && scene=$tmp/w.ini
    echo previous >"$full/f.csv"
    run "$cmd" "$scene" -o "$full/f.csv"
    if test "$rc" -ne 1 || test "$(cat "$full/f.csv")" != previous \
       || ! no_temp "$full" f.csv || ! grep -q 'No space left on device' "$tmp/err"; then
      say "$cmd: exit $rc, $(cat "$tmp/err")"; ok=1
    fi
  done
  result "$ok" "a full disk: run, sweep -o FILE exit 1, FILE as it was, no temporary"
  rc=0
  "$prog" run "$tmp/s.ini" >"$full/g.csv" 2>"$tmp/err" || rc=$?
  ok=1
  test "$rc" -eq 1 && grep -q 'error writing to standard output' "$tmp/err" && ok=0
  result "$ok" "... standard output on the full disk: exit 1"
  rm -f "$full/g.csv"
  echo previous >"$full/p.ini"
  cat /dev/zero >"$full/fill2" 2>/dev/null
  run run "$tmp/s.ini" --print-scene -o "$full/p.ini"
  ok=1
  test "$rc" -eq 1 && test "$(cat "$full/p.ini")" = previous && no_temp "$full" p.ini && ok=0
  result "$ok" "... --print-scene -o FILE on a disk without a free block: exit 1, FILE as it was"
  umount "$full"
else
  for t in "a full disk: run, sweep" "... standard output" "... --print-scene"; do
    count=$((count + 1))
    echo "ok $count # SKIP $t: cannot mount a tmpfs (needs root)"
  done
fi

# ---- the file-size limit -----------------------------------------------------------
echo previous >"$tmp/f.csv"
(ulimit -f 4 && "$prog" run "$tmp/s.ini" -o "$tmp/f.csv") 2>"$tmp/err" && rc=0 || rc=$?
ok=1
test "$rc" -eq 1 && test "$(cat "$tmp/f.csv")" = previous && no_temp "$tmp" f.csv \
  && grep -q 'error writing to .*f.csv: File too large' "$tmp/err" && ok=0
test "$ok" -eq 0 || say "exit $rc: $(cat "$tmp/err")"
result "$ok" "ulimit -f: run -o FILE fails (EFBIG, not SIGXFSZ): exit 1, FILE as it was, no temporary"

(ulimit -f 4 && "$prog" run "$tmp/s.ini" >"$tmp/g.csv") 2>"$tmp/err" && rc=0 || rc=$?
ok=1
test "$rc" -eq 1 && grep -q 'error writing to standard output: File too large' "$tmp/err" && ok=0
result "$ok" "... run to standard output: exit 1 with the write error"

# /dev/full as standard output of the commands that print without -o
ok=0
for args in "eq 3.10 L0=1 Delta=1/3 dir=-1" "eq --list" "eq --help" "--help" \
            "skate --L0 1 --Delta 1/3 --V 1 --Omega 0.5"; do
  rc=0
  # shellcheck disable=SC2086
  "$prog" $args >/dev/full 2>"$tmp/err" || rc=$?
  if test "$rc" -ne 1 \
     || ! grep -q 'error writing .*No space left on device' "$tmp/err"; then
    say "$args: exit $rc: $(cat "$tmp/err")"; ok=1
  fi
done
result "$ok" "standard output on /dev/full (eq, eq --list, --help, skate): exit 1, the write error named"

# ---- the output is never the scene --------------------------------------------------
# @S@ the scene, @H@ a hard link to it, @L@ a symbolic link; a sweep's
# scene for sweep.  Each case makes them anew (a case that replaced the
# scene must not change what the next one tests).
cp "$tmp/s.ini" "$tmp/run.ini"
ln -s s.ini "$tmp/sym.ini"
ok=0
for args in "run - -o @S@" "sweep - -o @S@" "plot - -o @S@ --format svg" "run - -o @H@" \
            "run - -o @D@" "run - -o @L@" "run - -o /dev/stdin" "run - --print-scene -o @S@" \
            "sweep - --print-scene -o @H@" "run @S@ -o @H@" "run @D@ -o @L@" \
            "run @H@ --print-scene -o @S@"; do
  set -- $(echo "$args" | sed -e "s|@S@|$tmp/s.ini|g" -e "s|@D@|$tmp/./s.ini|g" \
             -e "s|@H@|$tmp/hard.ini|g" -e "s|@L@|$tmp/sym.ini|g")
  rm -f "$tmp/s.ini" "$tmp/hard.ini"
  if test "$1" = sweep; then cat "$tmp/w.ini"; else cat "$tmp/run.ini"; fi >"$tmp/s.ini"
  ln "$tmp/s.ini" "$tmp/hard.ini"
  cp "$tmp/s.ini" "$tmp/orig.ini"
  rc=0
  "$prog" "$@" <"$tmp/s.ini" >/dev/null 2>"$tmp/err" || rc=$?
  if test "$rc" -ne 2 || ! cmp -s "$tmp/s.ini" "$tmp/orig.ini" \
     || ! grep -q 'refusing to overwrite the input' "$tmp/err"; then
    say "$args: exit $rc, $(cat "$tmp/err")"; ok=1
  fi
done
cat "$tmp/run.ini" >"$tmp/s.ini"
cp "$tmp/s.ini" "$tmp/orig.ini"
result "$ok" "-o the scene (standard input, hard link, symbolic link, ./x, /dev/stdin; run, sweep, plot, --print-scene): refused, exit 2, intact"

rc=0
"$prog" run "$tmp/s.ini" >>"$tmp/s.ini" 2>"$tmp/err" || rc=$?
ok=1
test "$rc" -eq 2 && cmp -s "$tmp/s.ini" "$tmp/orig.ini" \
  && grep -q 'standard output: refusing to overwrite the input' "$tmp/err" && ok=0
result "$ok" "standard output appended to the scene: refused, exit 2, intact"

# ---- --print-scene -o FILE -------------------------------------------------------
cp "$tmp/w.ini" "$tmp/sweep.ini"
ok=0
for cmd in "run $tmp/orig.ini" "sweep $tmp/sweep.ini" "skate --collisions 7"; do
  rm -f "$tmp/p.ini"
  run $cmd --print-scene -o "$tmp/p.ini"
  if test "$rc" -ne 0 || test -s "$tmp/raw" || ! test -s "$tmp/p.ini" \
     || ! "$prog" run "$tmp/p.ini" --print-scene 2>/dev/null | cmp -s - "$tmp/p.ini"; then
    say "$cmd: exit $rc"; ok=1
  fi
done
result "$ok" "--print-scene -o FILE (run, sweep, skate): FILE is the scene (it reads back the same), nothing on standard output"

# ---- symbolic links ------------------------------------------------------------------
mkdir "$tmp/sub"
ln -s target.csv "$tmp/dangling.csv"
ln -s ../sub/t2.csv "$tmp/sub/rel.csv"
run run "$tmp/orig.ini" --no-provenance -o "$tmp/dangling.csv"
rc1=$rc
run run "$tmp/orig.ini" --no-provenance -o "$tmp/sub/rel.csv"
ok=1
test "$rc1" -eq 0 && test "$rc" -eq 0 && test -L "$tmp/dangling.csv" && test -f "$tmp/target.csv" \
  && test -L "$tmp/sub/rel.csv" && cmp -s "$tmp/target.csv" "$tmp/sub/t2.csv" \
  && test "$(head -c 12 "$tmp/target.csv")" = "n,D,reversal" && ok=0
result "$ok" "-o a dangling symbolic link (absolute, relative): the link stays, its target is created"

ln -s loop1 "$tmp/loop2"
ln -s loop2 "$tmp/loop1"
run run "$tmp/orig.ini" -o "$tmp/loop1"
ok=1
test "$rc" -eq 1 && grep -q 'Too many levels of symbolic links' "$tmp/err" && test -L "$tmp/loop1" && ok=0
result "$ok" "-o a loop of symbolic links: exit 1, the link left"

# ---- control characters in messages ---------------------------------------------------
esc=$(printf '\033')
ok=0
for args in "run NAME" "run $tmp/orig.ini -o DIR/x.csv" "run --NAME" "NAME" \
            "plot $tmp/orig.ini -o NAME.pdf" "sweep NAME" "run $tmp/orig.ini NAME" \
            "skate --NAME" "eq NAME" "eq 3.10 L0=NAME"; do
  set -- $args
  i=0
  for a in "$@"; do
    i=$((i + 1))
    case $a in
      *NAME*) a=$(echo "$a" | sed "s|NAME|red${esc}[31mtab	x|") ;;
      *DIR*) a=$(echo "$a" | sed "s|DIR|$tmp/no${esc}[2Jdir|") ;;
    esac
    set -- "$@" "$a"
  done
  shift "$i"
  rc=0
  "$prog" "$@" >/dev/null 2>"$tmp/err" || rc=$?
  if test "$rc" -eq 0 || grep -q "$esc" "$tmp/err" || grep -q '	' "$tmp/err" \
     || ! grep -q '\\x1b\[' "$tmp/err"; then
    say "$args: exit $rc: $(od -c "$tmp/err" | head -n 3)"; ok=1
  fi
done
result "$ok" "names and arguments with an escape sequence or a tab: shown as \\xHH in every message, never raw"

# ---- signals ------------------------------------------------------------------------
ulimit -c 0 2>/dev/null || :           # no core files of QUIT, ILL, ...
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
collisions = 1e9
outputs = E,H
every = 1e6
EOF

# spawn ARGS...: the program in the background with every signal at its
# default (a script's background job starts with SIGINT and SIGQUIT
# ignored), its pid in $pid; "" if that cannot be done.
if env --default-signal true 2>/dev/null; then
  spawn () { env --default-signal "$prog" "$@" 2>/dev/null & pid=$!; }
elif perl -e 1 2>/dev/null; then
  spawn () {
    perl -e '$SIG{$_} = "DEFAULT" for keys %SIG; exec @ARGV' "$prog" "$@" \
      2>/dev/null & pid=$!
  }
else
  spawn () { pid=""; }
fi

# wait_temp DIR NAME: until the temporary file of NAME exists (5 s at most).
wait_temp () {
  i=0
  while test "$i" -lt 500 && no_temp "$1" "$2"; do
    sleep 0.01
    i=$((i + 1))
  done
}

# One run at a time: a run spins until its signal (several at once would
# starve this shell of the CPU).
mkdir "$tmp/sig"
for s in $signals; do
  echo previous >"$tmp/sig/f$s.csv"
  spawn run "$tmp/long.ini" -o "$tmp/sig/f$s.csv"
  if test -z "$pid"; then
    count=$((count + 1))
    echo "ok $count # SKIP signal $s: neither env --default-signal nor perl"
    continue
  fi
  wait_temp "$tmp/sig" "f$s.csv"
  had_temp=1
  no_temp "$tmp/sig" "f$s.csv" && had_temp=0
  kill -"$s" "$pid"
  wait "$pid" 2>/dev/null && st=0 || st=$?
  ok=1
  test "$had_temp" -eq 1 && test "$st" -eq $((128 + s)) && no_temp "$tmp/sig" "f$s.csv" \
    && test "$(cat "$tmp/sig/f$s.csv")" = previous && ok=0
  result "$ok" "signal $s ($(kill -l "$s" 2>/dev/null)) during run -o FILE: killed by it (status $st), no temporary, FILE as it was"
done

# SIGXFSZ is ignored; a signal ignored at start (nohup) stays ignored.
echo previous >"$tmp/sig/x.csv"
spawn run "$tmp/long.ini" -o "$tmp/sig/x.csv"
ok=1
if test -n "$pid"; then
  wait_temp "$tmp/sig" x.csv
  kill -XFSZ "$pid"
  sleep 0.2
  if kill -0 "$pid" 2>/dev/null; then
    kill -TERM "$pid"
    wait "$pid" 2>/dev/null && st=0 || st=$?
    test "$st" -eq 143 && no_temp "$tmp/sig" x.csv && test "$(cat "$tmp/sig/x.csv")" = previous && ok=0
  fi
fi
result "$ok" "SIGXFSZ is ignored (the run goes on; a SIGTERM then removes the temporary)"

sed 's/^collisions = 1e9$/collisions = 1e6/' "$tmp/long.ini" >"$tmp/mid.ini"
echo previous >"$tmp/sig/h.csv"
ok=1
if env --ignore-signal=HUP true 2>/dev/null; then
  env --ignore-signal=HUP "$prog" run "$tmp/mid.ini" -o "$tmp/sig/h.csv" 2>/dev/null &
  pid=$!
  wait_temp "$tmp/sig" h.csv
  kill -HUP "$pid"
  wait "$pid" 2>/dev/null && st=0 || st=$?
  test "$st" -eq 0 && no_temp "$tmp/sig" h.csv && grep -q '^# end: complete' "$tmp/sig/h.csv" && ok=0
  result "$ok" "SIGHUP ignored at start (nohup) stays ignored: the run completes, FILE written (exit $st)"
else
  count=$((count + 1))
  echo "ok $count # SKIP SIGHUP ignored at start: env --ignore-signal not found"
fi

test "$count" -eq "$plan" || echo "Bail out! ran $count tests, planned $plan"
