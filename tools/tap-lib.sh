# tap-lib.sh -- the common part of the program's TAP test scripts, sourced
# after they set $prog:  . "$top_srcdir/tools/tap-lib.sh"; tap_start NAME PLAN
# POSIX sh (dash).

# tap_start NAME PLAN: a temporary directory $tmp (removed at exit), the
# plan line, and a bail-out if $prog is not built.
tap_start () {
  tmp=$(mktemp -d "${TMPDIR:-/tmp}/$1.XXXXXX" 2>/dev/null) || {
    tmp=${TMPDIR:-/tmp}/$1.$$
    mkdir "$tmp" || { echo "Bail out! cannot create a temporary directory"; exit 1; }
  }
  trap 'rm -rf "$tmp"' 0
  trap 'exit 1' HUP INT TERM
  plan=$2
  echo "1..$plan"
  if test ! -x "$prog"; then
    echo "Bail out! $prog is not built"
    exit 1
  fi
  count=0
}

# result STATUS TEXT: print "ok" if STATUS is 0, else "not ok".
result () {
  count=$((count + 1))
  if test "$1" -eq 0; then
    echo "ok $count - $2"
  else
    echo "not ok $count - $2"
  fi
}

# run ARGS...: run the program; stdout in $tmp/raw, and without its '#'
# lines (provenance) in $tmp/out; stderr in $tmp/err, exit status in $rc.
run () {
  rc=0
  "$prog" "$@" >"$tmp/raw" 2>"$tmp/err" || rc=$?
  grep -v '^#' "$tmp/raw" >"$tmp/out" || :
}

# csv_only FILE: FILE without its '#' lines, in place.
csv_only () {
  grep -v '^#' "$1" >"$1.csv-only" || :
  mv "$1.csv-only" "$1"
}
