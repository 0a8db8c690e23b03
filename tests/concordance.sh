#!/bin/sh
# concordance.sh -- keep doc/concordance.tsv and doc/equations.txt honest
# (TAP output).  Checks: the header; every equation label 2.1 ... B.17
# (with A.4) present once and in order, in both files; per row: every
# function named (implementing, or evaluating the printed form) is
# exported by the built library and has an entry in the library reference
# (doc/api*.texi) with an anchor and the generated @implements_ call that
# links it back to the concordance; every unit test named is a TCase in
# tests/*.c; every verification check named has a program
# verification/NAME.c; every erratum named has an entry in doc/errata.texi,
# and they are the errata that `chaplygin eq --list' gives for the label.
# (tools/test-eq.sh evaluates the eq call of every row.)
set -u
top_srcdir=${top_srcdir:-.}
top_builddir=${top_builddir:-.}
tsv="$top_srcdir/doc/concordance.tsv"
n=0
fail=0
ok () { n=$((n + 1)); echo "ok $n - $1"; }
notok () { n=$((n + 1)); fail=1; echo "not ok $n - $1"; }

if [ ! -r "$tsv" ]; then echo "1..0 # SKIP"; echo "Bail out! $tsv missing"; exit 1; fi

lib=""
for f in "$top_builddir/lib/.libs/libchaplygin.so" "$top_builddir/lib/.libs/libchaplygin.a"; do
  if [ -r "$f" ]; then lib=$f; break; fi
done
if [ -z "$lib" ]; then echo "Bail out! built library not found under $top_builddir/lib/.libs"; exit 1; fi
case $lib in
  *.so) symbols=$(nm -D --defined-only "$lib" | awk '$2 == "T" { print $3 }') ;;
  *) symbols=$(nm -g --defined-only "$lib" | awk '$2 == "T" { print $3 }') ;;
esac
# TCase names: literal first arguments of tcase_create() or of the add()
# helper tu_add (s, "eq_3_1", ...) of tests/testutil.h.
tcases=$(cat "$top_srcdir"/tests/*.c \
  | sed -n -e 's/.*tcase_create *( *"\([^"]*\)".*/\1/p' \
           -e 's/.*add *( *s *, *"\([^"]*\)".*/\1/p')

expected="2.1 2.2 2.3 2.4"
i=1; while [ $i -le 15 ]; do expected="$expected 3.$i"; i=$((i + 1)); done
expected="$expected 4.1 A.1 A.2 A.3 A.4 A.5 A.6"
i=1; while [ $i -le 17 ]; do expected="$expected B.$i"; i=$((i + 1)); done

header=$(head -n 1 "$tsv")
if [ "$header" = "$(printf 'equation\tfunction\tunit_test\tverification\terratum\tprinted_function\teq')" ]; then
  ok "header"
else
  notok "header is '$header'"
fi

labels=$(tail -n +2 "$tsv" | cut -f 1 | tr '\n' ' ' | sed 's/ $//')
if [ "$labels" = "$expected" ]; then
  ok "all 43 labels present, once each, in order"
else
  notok "labels are: $labels"
fi

eqlabels=$(sed -n 's/^@ //p' "$top_srcdir/doc/equations.txt" | tr '\n' ' ' | sed 's/ $//')
if [ "$eqlabels" = "$expected" ]; then
  ok "doc/equations.txt: all 43 labels, once each, in order"
else
  notok "doc/equations.txt labels are: $eqlabels"
fi

# The library reference: FUNCTION's @deftypefun line followed by its
# @implements_FUNCTION{} call, and an @anchor{FUNCTION} before it.
api=$(cat "$top_srcdir"/doc/api.texi "$top_srcdir"/doc/api-printed.texi)
api_entry () {
  echo "$api" | awk -v f="$1" '
    prev ~ "^@anchor\\{" f "\\}$" && $0 ~ "^@deftypefun .*[ *]" f " \\(" { d = 1; prev = $0; next }
    d == 1 { ok = ($0 == "@implements_" f "{}"); d = 0 }
    { prev = $0 }
    END { exit !ok }'
}
prog=$top_builddir/tools/chaplygin
eqerrata=$("$prog" eq --list --csv | awk -F, 'NR > 1 { e = $NF; gsub(/ /, ",", e); print $1 "\t" e }')

tab=$(printf '\t')
tail -n +2 "$tsv" > concordance.rows.tmp
while IFS="$tab" read -r eq fn ut ver err pf call; do
  msg=""
  nf=$(printf '%s\n' "$eq$tab$fn$tab$ut$tab$ver$tab$err$tab$pf$tab$call" | awk -F '\t' '{ print NF }')
  [ "$nf" -eq 7 ] || msg="$msg [row has $nf fields]"
  fns=$fn
  case $pf in -|same|none) ;; *) fns="$fns,$pf" ;; esac
  for f in $(echo "$fns" | tr ',' ' '); do
    echo "$symbols" | grep -qx "$f" || msg="$msg [function $f not exported]"
    api_entry "$f" || msg="$msg [no @anchor/@deftypefun/@implements_ entry for $f in doc/api*.texi]"
  done
  if [ "$err" = "-" ]; then
    [ "$pf" = "-" ] || msg="$msg [printed_function without erratum]"
  else
    [ "$pf" != "-" ] || msg="$msg [erratum without printed_function]"
    for e in $(echo "$err" | tr ',' ' '); do
      grep -q "^@node Erratum $e\$" "$top_srcdir/doc/errata.texi" || msg="$msg [no erratum $e]"
    done
  fi
  want=$(echo "$eqerrata" | awk -F '\t' -v l="$eq" '($1 "") == (l "") { print $2 }')
  [ "$want" = "$err" ] || msg="$msg [errata '$err', chaplygin eq --list: '$want']"
  [ -n "$call" ] || msg="$msg [no eq call]"
  if [ "$ut" != "-" ]; then
    for t in $(echo "$ut" | tr ',' ' '); do
      echo "$tcases" | grep -qx "$t" || msg="$msg [no TCase $t in tests/]"
    done
  fi
  if [ "$ver" != "-" ]; then
    for v in $(echo "$ver" | tr ',' ' '); do
      [ -r "$top_srcdir/verification/$v.c" ] || msg="$msg [no verification/$v.c]"
    done
  fi
  if [ -z "$msg" ]; then ok "($eq) $fn | $ut | $ver | $err | $pf"; else notok "($eq)$msg"; fi
done < concordance.rows.tmp
rm -f concordance.rows.tmp
echo "1..$n"
exit $fail
