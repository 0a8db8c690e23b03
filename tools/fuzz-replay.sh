#!/bin/sh
# fuzz-replay.sh -- TAP: replay the scene fuzzer's corpus
# (tools/fuzz-corpus/, kept from libFuzzer runs of `make fuzz') through
# the fuzz target built with the project's compiler: every input must be
# parsed (accepted or rejected with a message) without a crash, and, in
# the build of `make check-sanitizers', without a sanitizer finding.
# The inputs named by hand keep their names honest: `chaplygin run
# --print-scene' refuses each bad-*.ini (exit 2, a message naming it) and
# accepts each valid-*.ini (exit 0).
set -u
top_builddir=${top_builddir:-.}
top_srcdir=${top_srcdir:-.}
target=$top_builddir/tools/fuzz-scene
prog=${CHAPLYGIN:-$top_builddir/tools/chaplygin}
corpus=$top_srcdir/tools/fuzz-corpus
echo "1..2"
test -x "$target" || { echo "Bail out! $target is not built"; exit 1; }
test -x "$prog" || { echo "Bail out! $prog is not built"; exit 1; }
n=$(ls "$corpus" | wc -l)
if "$target" "$corpus"; then
  echo "ok 1 - the fuzz target parses all $n corpus inputs"
else
  echo "not ok 1 - the fuzz target failed on the corpus ($n inputs)"
fi

ok=ok
named=0
for f in "$corpus"/bad-*.ini "$corpus"/valid-*.ini; do
  name=$(basename "$f")
  rc=0
  msg=$("$prog" run "$f" --print-scene -o /dev/null 2>&1) || rc=$?
  case $name in
    bad-*) test "$rc" -eq 2 && case $msg in "chaplygin: $f:"*) : ;; *) false ;; esac ;;
    *) test "$rc" -eq 0 ;;
  esac || { ok="not ok"; echo "# $name: exit $rc: $msg" | cut -c 1-200; }
  named=$((named + 1))
done
echo "$ok 2 - the $named inputs named bad-*/valid-* are refused/accepted by the program"
