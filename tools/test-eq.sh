#!/bin/sh
# test-eq.sh -- TAP tests of "chaplygin eq".
#  - --list lists the labels of the registry lib/labels.txt, in order, and
#    every label evaluates at the inputs of its eq.example (read through
#    lib/labels.pl; tests/concordance.sh checks the rest of the registry);
#  - every row of tests/ref/eq.tsv: an output of a label, or of the paper's
#    printed form, at points other than the unit tests', against a
#    reference computed by another route (tests/ref/make_eq_refs.py, mpmath
#    and exact arithmetic), within the row's tolerance in units of 2^-52;
#  - the discrepancies the errata document, reproduced from the printed
#    forms (the errata's own numbers);
#  - errors: unknown label or input, missing or malformed input, input
#    outside the domain (exit 2 with a message naming the label's inputs),
#    and no crash on any of a set of hostile values for every input;
#  - --certified: exact p/q inputs and decimals as the doubles they
#    denote, the values the rationals' nearest doubles (awk's division of
#    integers, which rounds correctly) and the heading and time within a
#    few ulps of the closed form; every label evaluated by its certified
#    evaluator (a build without Arb refuses them all), never uncertified.
# Run by `make check', or by hand: top_builddir=. top_srcdir=. sh tools/test-eq.sh
# POSIX sh (dash).

set -u

top_builddir=${top_builddir:-.}
top_srcdir=${top_srcdir:-.}
prog=$top_builddir/tools/chaplygin
refs=$top_srcdir/tests/ref/eq.tsv
tab=$(printf '\t')

. "$top_srcdir/tools/tap-lib.sh"
tap_start test-eq 41

# The registry as doc/concordance.tsv's rows (label, functions, tests,
# verification, errata, printed_function, eq.example), with its header.
tsv=$tmp/labels.tsv
if ! ${PERL:-perl} "$top_srcdir/lib/labels.pl" tsv "$top_srcdir/lib/labels.txt" > "$tsv"; then
  echo "Bail out! lib/labels.pl cannot read lib/labels.txt"
  exit 1
fi
n_labels=$(($(wc -l < "$tsv") - 1))

# csv_get OUTPUT COLUMN: the COLUMN (value, printed, ...) of OUTPUT's row in
# $tmp/out (eq --csv).
csv_get () {
  awk -F, -v o="$1" -v col="$2" '
    NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next }
    $2 == o { print $(c[col]); exit }' "$tmp/out"
}

# close_to GOT WANT TOL_EPS: |got - want| <= tol 2^-52 |want| (tol 0: the
# same number).
close_to () {
  awk -v g="$1" -v w="$2" -v t="$3" 'BEGIN {
    if (g == "" || w == "") exit 1
    d = g - w; if (d < 0) d = -d
    a = w; if (a < 0) a = -a
    exit !(d <= t * 2 ^ -52 * a)
  }'
}

# 1: --list
run eq --list --csv
ok=1
listed=$(tail -n +2 "$tmp/out" | cut -d, -f1 | tr '\n' ' ')
expected=$(tail -n +2 "$tsv" | cut -f1 | tr '\n' ' ')
test "$rc" -eq 0 && test "$listed" = "$expected" && ok=0
result "$ok" "eq --list --csv lists the $n_labels labels of lib/labels.txt, in order"

# 2: every label evaluates at its concordance inputs
bad=""
tail -n +2 "$tsv" | cut -f1,7 > "$tmp/calls"
while IFS="$tab" read -r label args; do
  # shellcheck disable=SC2086
  run eq "$label" $args --csv
  if test "$rc" -ne 0 || test "$(wc -l < "$tmp/out")" -lt 2; then
    bad="$bad $label"
    sed "s/^/# $label: /" "$tmp/err" >&2
  fi
done < "$tmp/calls"
ok=1; test -z "$bad" && ok=0
result "$ok" "every label evaluates at its eq.example inputs${bad:+ (failed:$bad)}"

# 3: the reference table: every row within its tolerance
n_rows=0; bad=""
tail -n +2 "$refs" > "$tmp/refs"
while IFS="$tab" read -r label args output which ref tol route; do
  n_rows=$((n_rows + 1))
  # shellcheck disable=SC2086
  run eq "$label" $args --csv
  got=$(csv_get "$output" "$which")
  if test "$rc" -ne 0; then
    bad="$bad $label:$output"
    echo "# ($label) $args: exit $rc: $(head -n 1 "$tmp/err")" >&2
  elif test "$tol" = 0 && test "$got" = "$ref"; then
    :
  elif close_to "$got" "$ref" "$tol"; then
    :
  else
    bad="$bad $label:$output"
    echo "# ($label) $args: $which $output = $got, reference $ref (tol $tol eps; $route)" >&2
  fi
done < "$tmp/refs"
ok=1; test -z "$bad" && test "$n_rows" -gt "$n_labels" && ok=0
result "$ok" "all $n_rows rows of tests/ref/eq.tsv within their tolerance${bad:+ (failed:$bad)}"

# 4: every label appears in the reference table, with and without printed rows
ok=0
for label in $(tail -n +2 "$tsv" | cut -f1); do
  if ! cut -f1 "$tmp/refs" | grep -qx "$label"; then
    ok=1; echo "# ($label) has no row in tests/ref/eq.tsv" >&2
  fi
done
for label in $(awk -F'\t' 'NR > 1 && $6 != "-" && $6 != "same" && $6 != "none" { print $1 }' "$tsv"); do
  if ! awk -F'\t' -v l="$label" '$1 == l && $4 == "printed"' "$tmp/refs" | grep -q .; then
    ok=1; echo "# ($label) has no printed-form row in tests/ref/eq.tsv" >&2
  fi
done
result "$ok" "every label has a reference row, every evaluable printed form a printed row"

# printed_check TEXT LABEL ARGS -- OUTPUT VALUE VTOL PRINTED PTOL
# The output and its printed form against the errata's numbers (relative
# tolerances as numbers: the errata quote 4 or 5 digits).
printed_check () {
  text=$1; label=$2; shift 2
  args=""
  while test "$1" != "--"; do args="$args $1"; shift; done
  shift
  output=$1 value=$2 vtol=$3 printed=$4 ptol=$5
  # shellcheck disable=SC2086
  run eq "$label" $args --csv
  gv=$(csv_get "$output" value); gp=$(csv_get "$output" printed)
  ok=1
  if test "$rc" -eq 0 && awk -v g="$gv" -v w="$value" -v t="$vtol" -v gp="$gp" -v p="$printed" -v tp="$ptol" 'BEGIN {
      if (gp == "") exit 1
      d = g - w; if (d < 0) d = -d; a = w < 0 ? -w : w
      e = gp - p; if (e < 0) e = -e; b = p < 0 ? -p : p
      exit !(d <= t * a && e <= tp * b)
    }'; then ok=0
  else
    echo "# ($label)$args: $output = $gv (want $value), printed $gp (want $printed)" >&2
  fi
  result "$ok" "$text"
}

# 5-16: the errata's own numbers
printed_check "E13: (4.1) at L0 = 1, c2 = 5/24, printed 1/24" \
  4.1 L0=1 Delta=1/3 Vstar=1 -- c2 0.20833333333333334 4.5e-16 0.041666666666666664 4.5e-16
printed_check "E12: (3.11) Figure 6's skate is stable; the chained reading says not" \
  3.11 L0=1 Delta=1/3 -- stable 1 0 0 0
printed_check "E1: (2.1) dS/dtau = |V| for V < 0; printed V" \
  2.1 L=1 V=-0.75 Omega=0.5 -- dS/dtau 0.75 0 -0.75 0
printed_check "E3: (A.1) L = 1, V0 = -1, Omega0 = 0.3, S0 = 2: Sc = 3.880, printed 0.120" \
  A.1 L=1 V=-1 Omega=0.3 S=2 -- Sc 3.880 2e-4 0.120 5e-3
printed_check "E3: (A.6) the same in energy-momentum form" \
  A.6 L=1 V0=-1 Omega0=0.3 S0=2 -- Sc 3.880 2e-4 0.120 5e-3
printed_check "E17: (B.16) at L0 = -2/3 a reversing segment from D+ = 0: C2 = -1/2, printed -2" \
  B.16 L0=-2/3 Dplus=0 reversal=1 -- C2 -0.5 4.5e-16 -2 4.5e-16
printed_check "E4: (A.2) L = 1, V0 = -1, Omega0 = 0.3, S - S0 = 1: V = -0.83109, printed +1.0554" \
  A.2 L=1 V0=-1 Omega0=0.3 S=1 -- V -0.83109 1e-5 1.0554 1e-4
printed_check "E4: (A.2) the same: Omega = 0.49462, printed 0.1820" \
  A.2 L=1 V0=-1 Omega0=0.3 S=1 -- Omega 0.49462 1e-5 0.1820 3e-4
printed_check "E6: (A.2) the heading turns by 0.42198; printed magnitude 0.2292" \
  A.2 L=1 V0=-1 Omega0=0.3 S=1 -- theta 0.42198 1e-5 0.2292 3e-4
# E5: just past S_c = 3.7506 of L = -sqrt(2), V0 = 1, Omega0 = 0.1, the
# printed branch has Omega = 0.0171 and V = -1.014 (the motion: 0.586, ~0).
printed_check "E5: (A.2) past the reversal the printed Omega jumps to 0.0171" \
  A.2 L=-0x1.6a09e667f3bcdp0 V0=1 Omega0=0.1 S=3.7507 -- Omega 0.586 2e-3 0.0171 2e-2
run eq B.2 L0=1 D0=1/3 V0=-0.8 Omega0=0.3 D=0.1 --csv
dt=$(csv_get dtheta value); dp=$(csv_get dtheta printed)
ok=1
test "$rc" -eq 0 && awk -v a="$dt" -v b="$dp" 'BEGIN { exit !(a > 0 && b == -a) }' && ok=0
result "$ok" "E9: (B.2) backward: dtheta = $dt > 0, printed = -dtheta ($dp)"
run eq B.3 L0=1 Delta=1/3 V=-0.8 Omega=0.3 --csv
dt=$(csv_get dtheta value); dp=$(csv_get dtheta printed)
ok=1
test "$rc" -eq 0 && awk -v a="$dt" -v b="$dp" 'BEGIN { exit !(a > 0 && b == -a) }' && ok=0
result "$ok" "E10: (B.3) backward with H > 0: f3 = $dt > 0, printed f3 = -f3 ($dp)"

# 17: (B.9) n = 1: the printed sum has two terms, E + C1 (1 + C2^2) H^2
run eq B.9 L0=1 Delta=1/3 dir=+1 E=0.6 H=0.5 n=1 --csv
en=$(csv_get E_n value); ep=$(csv_get E_n printed)
run eq B.3 L0=1 Delta=1/3 dir=+1 E=0.6 H=0.5 --csv
c1=$(csv_get C1 value); c2=$(csv_get C2 value); e1=$(csv_get E_next value)
ok=1
awk -v en="$en" -v ep="$ep" -v c1="$c1" -v c2="$c2" -v e1="$e1" 'BEGIN {
  want = 0.6 + c1 * (1 + c2 * c2) * 0.25
  d = ep - want; if (d < 0) d = -d
  exit !(en == e1 && d <= 4 * 2 ^ -52 * want)
}' && ok=0
result "$ok" "E22: (B.9) n = 1 is one step of (B.3) ($en); printed E + C1 (1 + C2^2) H^2 ($ep)"

# 18: where the printed form agrees: (2.1) for V > 0, (B.16) without reversal
run eq 2.1 L=1 V=0.75 Omega=0.5 --csv
a=$(csv_get dS/dtau relative_difference)
run eq B.16 L0=-2/3 Dplus=0 reversal=0 --csv
b=$(csv_get C2 relative_difference)
ok=1; test "$a" = 0 && test "$b" = 0 && ok=0
result "$ok" "the printed forms agree where the errata say they do (E1 for V > 0, E17 without reversal)"

# 19: the printed form undefined is reported, not a failure
run eq 4.1 L0=1 Delta=1/3 Vstar=-1 --csv
ok=1
test "$rc" -eq 0 && test "$(csv_get c2 printed)" = undefined && ok=0
result "$ok" "E13: (4.1) for V* < 0 the printed series is undefined (the paper gives none)"

# 20: rationals and hex floats are read correctly rounded
run eq 3.10 L0=0x1p0 Delta=1/3 dir=+1
ok=1
test "$rc" -eq 0 && grep -q 'Delta = 0.33333333333333331$' "$tmp/out" \
  && grep -q 'L0 = 1$' "$tmp/out" && ok=0
result "$ok" "inputs p/q and hex floats are read and echoed to 17 digits"

# expect_usage TEXT PATTERN ARGS...: exit 2, a message matching PATTERN
# and the label's inputs, nothing on stdout.
expect_usage () {
  text=$1; pattern=$2; shift 2
  run "$@"
  ok=1
  test "$rc" -eq 2 && ! test -s "$tmp/out" && grep -q -- "$pattern" "$tmp/err" && ok=0
  test "$ok" -eq 0 || { echo "# $*: exit $rc" >&2; sed 's/^/# stderr: /' "$tmp/err" >&2; }
  result "$ok" "$text"
}

expect_usage "unknown label" "unknown equation label 'Q.3'" eq Q.3 L0=1
expect_usage "unknown input names the label's inputs" "inputs of (3.10): L0 Delta dir" \
  eq 3.10 L0=1 Delta=1 dir=1 Lo=2
expect_usage "missing input" "missing input dir" eq 3.10 L0=1 Delta=1
expect_usage "malformed number" "Delta = '1/0' divides by zero" eq 3.10 L0=1 Delta=1/0 dir=1
expect_usage "input given twice" "given twice" eq 3.10 L0=1 L0=2 Delta=1 dir=1
expect_usage "E, H and V, Omega together" "give either E, H or V, Omega, not both" \
  eq B.3 L0=1 Delta=1 dir=1 E=1 H=0.5 V=1
expect_usage "input outside the domain" "outside the domain" eq 3.10 L0=1 Delta=-1 dir=1
expect_usage "a direction must be +1 or -1" "not a direction" eq 3.10 L0=1 Delta=1 dir=0

# 29-40: --certified (exact inputs, correctly rounded values).  The
# references: awk's division of two integers that are doubles (IEEE
# division rounds correctly) for the rational values; the closed form for
# the heading and time, within its few ulps, at inputs that are doubles.
# the certified method is in the library where it was built with Arb
# (chaplygin_method_available): without it, these are skipped and every
# label is refused below
have_cert=1
run eq --certified 3.10 L0=1 Delta=1 dir=1
grep -q "has no certified method" "$tmp/err" && have_cert=0
if test "$have_cert" -eq 1; then
  run eq --certified 3.10 L0=1 Delta=1/3 dir=-1 --csv
  s4=$(csv_get sigma4 value); m4=$(csv_get sigma4 method)
  run eq 3.10 L0=1 Delta=1/3 dir=-1 --csv
  u4=$(csv_get sigma4 value)
  ok=1
  test "$s4" = 1.1666666666666667 && test "$s4" = "$(awk 'BEGIN { printf "%.17g", 7 / 6 }')" \
    && test "$m4" = certified && test "$u4" = 1.1666666666666665 && ok=0
  result "$ok" "--certified (3.10) at L0 = 1, Delta = 1/3, dir = -1: sigma4 = 7/6 = $s4 (the closed form at the double nearest 1/3: $u4)"

  # exact_is VALUE P Q: VALUE is %.17g of the double nearest P/Q
  exact_is () {
    test "$1" = "$(awk -v p="$2" -v q="$3" 'BEGIN { printf "%.17g", p / q }')"
  }

  # (B.3): E = 3/4, H = 1 from V = 1, Omega = 1/2 at L0 = 1; the collision at
  # L0 + Delta = 4/3: C1 = -9/2500, C2 = 21/25, E' = 1866/2500, H' = 21/25
  run eq --certified B.3 L0=1 Delta=1/3 V=1 Omega=1/2 --csv
  ok=1
  test "$rc" -eq 0 && exact_is "$(csv_get C1 value)" -9 2500 \
    && exact_is "$(csv_get C2 value)" 21 25 \
    && exact_is "$(csv_get E_next value)" 1866 2500 \
    && exact_is "$(csv_get H_next value)" 21 25 \
    && test "$(csv_get reversal value)" = 0 \
    && test "$(csv_get dtheta method)" = certified && ok=0
  result "$ok" "--certified (B.3) from V, Omega given exactly: C1, C2, E', H' are the rationals' nearest doubles"

  # (3.5) from the same state: Omega' = H'/(1 + L0^2) = 21/50, theta' the
  # step's dtheta, the same certified value as (B.3)'s
  dth=$(csv_get dtheta value)
  run eq --certified 3.5 L0=1 Delta=1/3 V=1 Omega=1/2 --csv
  ok=1
  test "$rc" -eq 0 && exact_is "$(csv_get Omega_next value)" 21 50 \
    && test "$(csv_get D_next value)" = 0 \
    && test "$(csv_get theta_next value)" = "$dth" && ok=0
  result "$ok" "--certified (3.5): Omega' = 21/50's nearest double, theta' = (B.3)'s dtheta ($dth)"

  # (B.4) from E = 1, H = 11/5, dir = -1: reverses; E' = 61411/62500,
  # H' = 231/125; Dc = sqrt(1.42) - 1
  run eq --certified B.4 L0=1 Delta=1/3 E=1 H=11/5 dir=-1 --csv
  ok=1
  test "$rc" -eq 0 && test "$(csv_get reversal value)" = 1 \
    && exact_is "$(csv_get E_next value)" 61411 62500 \
    && exact_is "$(csv_get H_next value)" 231 125 \
    && close_to "$(csv_get Dc value)" "$(awk 'BEGIN { printf "%.17g", sqrt(1.42) - 1 }')" 8 \
    && ok=0
  result "$ok" "--certified (B.4), a reversal from E, H exact: E', H' the rationals' nearest doubles, Dc"

  # the heading and time against the closed form at inputs that are doubles
  run eq --certified B.3 L0=1 Delta=0.5 V=1 Omega=0.5 --csv
  ct=$(csv_get dtheta value); cu=$(csv_get dtau value)
  run eq B.3 L0=1 Delta=0.5 V=1 Omega=0.5 --csv
  ok=1
  test "$rc" -eq 0 && close_to "$ct" "$(csv_get dtheta value)" 8 \
    && close_to "$cu" "$(csv_get dtau value)" 8 && ok=0
  result "$ok" "--certified (B.3) dtheta, dtau ($ct, $cu) within 8 eps of the closed form"

  # p/q inputs exact, a decimal the double it denotes: (3.3)
  run eq --certified 3.3 L0=1/3 D=0 V=1/7 Omega=2/3 --csv
  e1=$(csv_get E value)
  run eq --certified 3.3 L0=0 D=0 V=0.1 Omega=0 --csv
  e2=$(csv_get E value)
  run eq --certified 3.3 L0=0 D=0 V=3602879701896397/36028797018963968 Omega=0 --csv
  e3=$(csv_get E value)
  run eq --certified 3.3 L0=0 D=0 V=1/10 Omega=0 --csv
  e4=$(csv_get E value)
  ok=1
  exact_is "$e1" 2041 7938 && test "$e2" = "$e3" && test "$e4" != "$e2" \
    && exact_is "$e4" 1 200 && ok=0
  result "$ok" "--certified: p/q is exact (E = 2041/7938: $e1; V = 1/10: $e4), a decimal the double it denotes (V = 0.1: $e2)"

  # on a stability boundary: L0 = -17/6, Delta = 25/6 has sigma4 = -1 exactly
  run eq --certified 3.10 L0=-17/6 Delta=25/6 dir=1 --csv
  a=$(csv_get sigma4 value)
  run eq --certified 3.11 L0=-17/6 Delta=25/6 --csv
  b=$(csv_get stable value)
  ok=1
  test "$a" = -1 && test "$b" = 0 && ok=0
  result "$ok" "--certified on the boundary of (3.11): sigma4 = $a exactly, stable = $b (neutral)"

  run eq --certified 2.1 L=1 V=1/3 Omega=1/2 --csv
  ok=1
  test "$rc" -eq 0 && test "$(csv_get "dOmega/dtau" value)" = -0.083333333333333329 \
    && test "$(csv_get "dOmega/dtau" method)" = certified && ok=0
  result "$ok" "--certified (2.1): dOmega/dtau = -1/12, the rational's nearest double (every label has a certified evaluator)"
  expect_usage "--certified: p/q must be a ratio of two doubles" \
    "is not a ratio of two doubles" eq --certified 3.10 L0=1 Delta=1/9007199254740993 dir=1
  expect_usage "--certified: (3.7) takes E and H, not V and Omega" \
    "takes E and H" eq --certified 3.7 L0=1 Delta=1/3 D=1/3 V=0.9 Omega=0.4
  expect_usage "--certified: method options do not apply" \
    "method does not apply with --certified" eq --certified B.3 L0=1 Delta=1/3 V=1 Omega=1/2 method=ode

else
  i=0
  while test "$i" -lt 11; do
    count=$((count + 1)); i=$((i + 1))
    echo "ok $count - --certified # SKIP the library has no certified method (built without Arb)"
  done
fi

# every label: with --certified, the labels --list shows 'certified:'
# evaluate at their example (or refuse V, Omega, saying so), each output
# certified or exact: every label has one (lib/labels.pl requires it),
# and none is evaluated uncertified
"$prog" eq --list | awk '/^\(/ { l = substr($1, 2, length($1) - 2) } /^    certified:/ { print l }' \
  > "$tmp/certified"
bad=""
n_cert=0
while IFS="$tab" read -r label args; do
  # shellcheck disable=SC2086
  run eq --certified "$label" $args --csv
  if test "$have_cert" -eq 0; then
    n_cert=$((n_cert + 1))
    { test "$rc" -eq 2 && grep -q "has no certified method" "$tmp/err"; } \
      || bad="$bad $label(not refused)"
  elif grep -qx "$label" "$tmp/certified"; then
    n_cert=$((n_cert + 1))
    if test "$rc" -eq 0; then
      other=$(tail -n +2 "$tmp/out" | awk -F, '$5 != "certified" && $5 != "exact"')
      test -z "$other" || bad="$bad $label(uncertified output)"
    elif ! { test "$rc" -eq 2 && grep -q "takes E and H" "$tmp/err"; }; then
      bad="$bad $label(exit $rc)"
    fi
  else
    bad="$bad $label(no certified evaluator)"
  fi
done < "$tmp/calls"
n_labels=$(tail -n +2 "$tsv" | wc -l)
ok=1; test -z "$bad" && test "$n_cert" -eq "$n_labels" && ok=0
if test "$have_cert" -eq 1; then
  result "$ok" "--certified: all $n_cert of the $n_labels labels evaluate at their examples (or refuse V, Omega, saying why)${bad:+ (failed:$bad)}"
else
  result "$ok" "--certified without the certified method: every label is refused${bad:+ (failed:$bad)}"
fi

# 41: no crash: every input of every label set to hostile values
bad=""
for label in $(tail -n +2 "$tsv" | cut -f1); do
  args=$(awk -F'\t' -v l="$label" '$1 == l { print $7 }' "$tsv")
  for a in $args; do
    name=${a%%=*}
    for v in nan inf -1e308 1e308 0 -0 1e-320 -1 9999999999999999999 1/3 x ""; do
      # shellcheck disable=SC2086
      new=$(echo " $args " | sed "s| $a | $name=$v |")
      # shellcheck disable=SC2086
      run eq "$label" $new
      if test "$rc" -gt 2; then
        bad="$bad ($label $name=$v: exit $rc)"
      fi
      if grep -qx "$label" "$tmp/certified"; then
        # shellcheck disable=SC2086
        run eq --certified "$label" $new
        test "$rc" -le 2 || bad="$bad ($label --certified $name=$v: exit $rc)"
      fi
    done
  done
done
ok=1; test -z "$bad" && ok=0
result "$ok" "no crash with hostile values for every input of every label${bad:+:$bad}"
