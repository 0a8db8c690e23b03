#!/bin/sh
# test-cli.sh -- TAP tests of the command-line program tools/chaplygin.
# Run by `make check' (automake's TAP driver), or by hand:
#   top_builddir=. top_srcdir=. sh tools/test-cli.sh
# POSIX sh only (runs under dash).

set -u

top_builddir=${top_builddir:-.}
top_srcdir=${top_srcdir:-.}
prog=$top_builddir/tools/chaplygin

. "${top_srcdir:-.}/tools/tap-lib.sh"
tap_start test-cli 16

# expect_status WANT TEXT ARGS...: one test: the program exits WANT.
expect_status () {
  want=$1
  text=$2
  shift 2
  run "$@"
  ok=1
  test "$rc" -eq "$want" && ok=0
  if test "$ok" -ne 0; then
    echo "# $prog $*: exit $rc, want $want" >&2
    sed 's/^/# stderr: /' "$tmp/err" >&2
  fi
  result "$ok" "$text"
}

# 1: --help
run --help
ok=1
test "$rc" -eq 0 && grep skate "$tmp/out" >/dev/null && ok=0
result "$ok" "--help exits 0 and mentions skate"

# 2: --version
run --version
ok=1
test "$rc" -eq 0 && head -n 1 "$tmp/out" | grep '^chaplygin ' >/dev/null && ok=0
result "$ok" "--version prints 'chaplygin VERSION'"

# 3-6: skate with the defaults
run skate
cp "$tmp/out" "$tmp/default.csv"
ok=1
test "$rc" -eq 0 && test "$(wc -l <"$tmp/default.csv" | tr -d ' ')" = 22 && ok=0
result "$ok" "skate with defaults exits 0 and prints a header and 21 rows"

ok=1
test "$(head -n 1 "$tmp/default.csv")" = "n,D,reversal,E,H,theta,tau,peg_x,peg_y" \
  && ok=0
result "$ok" "skate header is n,D,reversal,E,H,theta,tau,peg_x,peg_y"

ok=1
sed -n 2p "$tmp/default.csv" | grep '^0,0,0,' >/dev/null && ok=0
result "$ok" "skate first row starts 0,0,0,"

ok=1
awk -F, '
  NR == 1 { next }
  NF != 9 { bad = 1 }
  NR > 2 && $4 + 0 > prev { bad = 1 }
  { prev = $4 + 0; rows++ }
  END { exit (bad || rows != 21) ? 1 : 0 }
' "$tmp/default.csv" && ok=0
result "$ok" "skate energy E is non-increasing"

# 7-13: usage errors
expect_status 2 "unknown option exits 2" skate --no-such-option 1

run skate --Delta 0
ok=1
test "$rc" -ne 0 && test -s "$tmp/err" && ok=0
result "$ok" "--Delta 0 fails with a message on stderr"

expect_status 2 "--Delta nan exits 2" skate --Delta nan
expect_status 2 "--collisions -1 exits 2" skate --collisions -1
expect_status 2 "--collisions 3x exits 2" skate --collisions 3x
expect_status 2 "--V 0 exits 2" skate --V 0
expect_status 2 "--method bogus exits 2" skate --method bogus

# 14-15: the other methods agree with the closed form on theta
run skate --collisions 5
cp "$tmp/out" "$tmp/closed.csv"
crc=$rc
for method in quadrature ode; do
  run skate --method "$method" --collisions 5
  ok=1
  if test "$crc" -eq 0 && test "$rc" -eq 0; then
    awk -F, '
      function abs(x) { return x < 0 ? -x : x }
      FNR == 1 { next }
      NR == FNR { ref[FNR] = $6 + 0; nref++; next }
      {
        n++
        if (!(FNR in ref)) { bad = 1; next }
        a = ref[FNR]; b = $6 + 0
        d = abs(a - b); s = abs(a) > abs(b) ? abs(a) : abs(b)
        if (d > 1e-9 * s) {
          printf "# row %d: theta %.17g vs closed form %.17g\n", FNR - 1, b, a
          bad = 1
        }
      }
      END { exit (bad || n != nref || n != 6) ? 1 : 0 }
    ' "$tmp/closed.csv" "$tmp/out" >&2 && ok=0
  fi
  result "$ok" "--method $method --collisions 5: exits 0, theta agrees with closed-form to 1e-9"
done

# 16: a backward start puts the peg at the rear, D = Delta
run skate --V -1
ok=1
if test "$rc" -eq 0; then
  sed -n 2p "$tmp/out" | awk -F, '
    { d = $2 - 1/3; if (d < 0) d = -d; bad = ($1 != "0" || d > 1e-15) }
    END { exit (NR == 1 && !bad) ? 0 : 1 }
  ' && ok=0
fi
result "$ok" "--V -1: row 0 has D = Delta = 1/3"

if test "$count" -ne "$plan"; then
  echo "# ran $count tests, planned $plan" >&2
  exit 1
fi
exit 0
