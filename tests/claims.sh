#!/bin/sh
# claims.sh -- keep the registry of the paper's claims, doc/claims.txt,
# honest (TAP output).  tests/test_claims runs every claim's check and
# fails unless its checks are the registry's; this checks the registry and
# its generator doc/claims.pl:
#  - doc/claims.pl reads it (every rule of its header);
#  - the generated files the build uses (tests/claims-list.h,
#    doc/claims.texi, doc/claims-figures.texi, all distributed) are what
#    doc/claims.pl makes of it now;
#  - doc/claims.pl refuses, naming the file and line, a registry with a
#    verdict outside the four, a check that is no START_TEST of the
#    claims' C files, an unknown label, erratum or figure, a reference
#    [C99] to no claim, claims out of order, a missing or misspelt field,
#    or a figure node of doc/figures.texi that does not list its claims.
set -u
top_srcdir=${top_srcdir:-.}
PERL=${PERL:-perl}
registry=$top_srcdir/doc/claims.txt
gen=$top_srcdir/doc/claims.pl
inputs="$top_srcdir/lib/labels.txt $top_srcdir/doc/errata.texi
  $top_srcdir/doc/figures.texi $top_srcdir/tests/test_claims.c
  $top_srcdir/tests/claims-motion.c"
n=0
fail=0
ok () { n=$((n + 1)); echo "ok $n - $1"; }
notok () { n=$((n + 1)); fail=1; echo "not ok $n - $1"; }

if [ ! -r "$registry" ]; then echo "1..0 # SKIP"; echo "Bail out! $registry missing"; exit 1; fi
tmp=$(mktemp -d "${TMPDIR:-/tmp}/claims.XXXXXX") || { echo "Bail out! mktemp"; exit 1; }
trap 'rm -rf "$tmp"' 0
trap 'exit 1' HUP INT TERM

# shellcheck disable=SC2086 # $inputs is a list of file names
if "$PERL" "$gen" check "$registry" $inputs 2> "$tmp/err"; then
  ok "doc/claims.pl reads doc/claims.txt"
else
  notok "doc/claims.pl reads doc/claims.txt: $(cat "$tmp/err")"
fi

for pair in list:tests/claims-list.h texi:doc/claims.texi \
            figures:doc/claims-figures.texi; do
  mode=${pair%%:*}
  file=${pair#*:}
  # shellcheck disable=SC2086
  if "$PERL" "$gen" "$mode" "$registry" $inputs > "$tmp/out" 2> "$tmp/err" \
     && cmp -s "$tmp/out" "$top_srcdir/$file"; then
    ok "$file is doc/claims.pl's from doc/claims.txt"
  else
    notok "$file is not doc/claims.pl's from doc/claims.txt (make regenerates it) $(cat "$tmp/err")"
  fi
done

# Each broken registry: a sed expression applied to a copy, and what the
# message must name.
refuse () {
  what=$1 expr=$2 want=$3
  sed "$expr" "$registry" > "$tmp/bad.txt"
  # shellcheck disable=SC2086
  if "$PERL" "$gen" check "$tmp/bad.txt" $inputs > /dev/null 2> "$tmp/err"; then
    notok "doc/claims.pl accepts $what"
  elif grep -q "$want" "$tmp/err"; then
    ok "doc/claims.pl refuses $what: $(cat "$tmp/err")"
  else
    notok "doc/claims.pl refuses $what, but says: $(cat "$tmp/err") (expected $want)"
  fi
}
refuse "an unknown verdict" '0,/^verdict: confirmed$/s//verdict: plausible/' \
  "bad.txt:[0-9]*: C1: verdict 'plausible'"
refuse "a check that is no test" '0,/^check: claim_/s//check: claim_no_such_/' \
  "is no START_TEST"
refuse "an unknown label" '0,/^labels: .*/s//labels: 3.99/' \
  "label 3.99 is not in lib/labels.txt"
refuse "an unknown erratum" '0,/^errata: -$/s//errata: E99/' \
  "erratum E99 is not a node"
refuse "an unknown figure" '0,/^figures: -$/s//figures: 11/' \
  "figure 11 has no node"
refuse "a reference to no claim" '0,/^evidence:$/{n;s/^    /    [C99] /}' \
  "refers to \[C99\]"
refuse "claims out of order" 's/^@ C2$/@ C3x/; s/^@ C3$/@ C2/; s/^@ C3x$/@ C3/' \
  "numbered C1, C2"
refuse "a missing field" '0,/^figures: /{/^figures: /d}' \
  "no field 'figures'"
refuse "a misspelt field" '0,/^where: /s//wehre: /' \
  "unknown field 'wehre'"

sed 's/^@claimsFigureNine{}$//' "$top_srcdir/doc/figures.texi" > "$tmp/figures.texi"
# shellcheck disable=SC2086
if "$PERL" "$gen" check "$registry" $(echo $inputs | sed "s|[^ ]*/figures.texi|$tmp/figures.texi|") \
     > /dev/null 2> "$tmp/err"; then
  notok "doc/claims.pl accepts a figure node without its claims"
elif grep -q "Figure 9 does not list its claims" "$tmp/err"; then
  ok "doc/claims.pl refuses a figure node without its claims: $(cat "$tmp/err")"
else
  notok "doc/claims.pl refuses a figure node without its claims, but says: $(cat "$tmp/err")"
fi

echo "1..$n"
exit $fail
