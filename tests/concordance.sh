#!/bin/sh
# concordance.sh -- keep the registry of the paper's labels, lib/labels.txt,
# honest (TAP output).  Checks:
#  - lib/labels.pl reads it (every rule of its header: the fields of every
#    record, the lists' syntax, errata and printed_function together, ...);
#  - its labels are the paper's, once each and in order: 2.1-2.4, 3.1-3.15,
#    4.1, A.1-A.6 (A.4 the unnumbered energy-momentum block between A.3 and
#    A.5), B.1-B.17, computed here from those ranges of the paper;
#  - doc/concordance.tsv, generated from it and distributed, is up to date;
#  - per label: every function named (implementing, or evaluating the
#    printed form) is exported by the built library and has an entry in the
#    library reference (doc/api*.texi) with an anchor and the generated
#    @implementsFunction call that links it back to the concordance; every unit
#    test named is a TCase in tests/*.c; every verification check named
#    has a program verification/NAME.c; every erratum named has an entry in
#    doc/errata.texi, and they are the errata that `chaplygin eq --list'
#    gives for the label; `chaplygin eq --list' shows the registry's
#    inputs, outputs and audit verdict (eq.inputs, eq.outputs, eq.paper),
#    titles and function lists (the engine's table is generated from the
#    registry: this checks the generation end to end).
# (tools/test-eq.sh evaluates the eq.example call of every label.)
set -u
top_srcdir=${top_srcdir:-.}
top_builddir=${top_builddir:-.}
PERL=${PERL:-perl}
registry=$top_srcdir/lib/labels.txt
labels_pl=$top_srcdir/lib/labels.pl
n=0
fail=0
ok () { n=$((n + 1)); echo "ok $n - $1"; }
notok () { n=$((n + 1)); fail=1; echo "not ok $n - $1"; }

if [ ! -r "$registry" ]; then echo "1..0 # SKIP"; echo "Bail out! $registry missing"; exit 1; fi

tmp=$(mktemp -d "${TMPDIR:-/tmp}/concordance.XXXXXX") || { echo "Bail out! mktemp"; exit 1; }
trap 'rm -rf "$tmp"' 0
trap 'exit 1' HUP INT TERM

if "$PERL" "$labels_pl" tsv "$registry" > "$tmp/tsv" 2> "$tmp/err"; then
  ok "lib/labels.pl reads lib/labels.txt"
else
  sed 's/^/# /' "$tmp/err"
  notok "lib/labels.pl rejects lib/labels.txt"
  echo "1..$n"
  exit 1
fi

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

# The paper's labels, from its numbering: section or appendix, last number.
expected=""
for range in 2:4 3:15 4:1 A:6 B:17; do
  i=1
  while [ "$i" -le "${range#*:}" ]; do
    expected="$expected ${range%%:*}.$i"; i=$((i + 1))
  done
done
expected=${expected# }
n_expected=$(echo "$expected" | wc -w)

labels=$(tail -n +2 "$tmp/tsv" | cut -f 1 | tr '\n' ' ' | sed 's/ $//')
if [ "$labels" = "$expected" ]; then
  ok "the paper's $n_expected labels, 2.1 ... B.17 with A.4, once each, in order"
else
  notok "labels are: $labels; the paper's: $expected"
fi

if cmp -s "$tmp/tsv" "$top_srcdir/doc/concordance.tsv"; then
  ok "doc/concordance.tsv is lib/labels.pl's from lib/labels.txt"
else
  notok "doc/concordance.tsv is not what lib/labels.txt gives (make doc/concordance.tsv)"
fi

# The manual shows the record of (3.10) as an example of the format
# (doc/concordance.texi, abridged by @dots{}): its lines are the registry's.
example=$(awk '/^@@ 3\.10$/ { p = 1 } p && /^@end example/ { exit } p' \
  "$top_srcdir/doc/concordance.texi" | sed -e 's/^@@/@/' -e '/@dots{}/d')
record=$(awk '/^@ / { p = ($0 == "@ 3.10") } p' "$registry")
missing=$(echo "$example" | while IFS= read -r line; do
  echo "$record" | grep -qxF -- "$line" || echo "$line"; done)
if [ -n "$example" ] && [ -z "$missing" ]; then
  ok "doc/concordance.texi's example record is the registry's (3.10)"
else
  echo "$missing" | sed 's/^/# not in the record of (3.10): /'
  notok "doc/concordance.texi's example record differs from the registry's (3.10)"
fi

# The library reference: FUNCTION's @deftypefun line followed by its
# @implementsFunction{} call (the macro's name: lib/TexinfoName.pm), and an
# @anchor{FUNCTION} before it.
api=$(cat "$top_srcdir"/doc/api.texi "$top_srcdir"/doc/api-printed.texi)
api_entry () {
  m=$(perl -I"$top_srcdir/lib" -MTexinfoName=implements_macro \
        -e 'print implements_macro ($ARGV[0])' "$1") || return 1
  echo "$api" | awk -v f="$1" -v m="$m" '
    prev ~ "^@anchor\\{" f "\\}$" && $0 ~ "^@deftypefun .*[ *]" f " \\(" { d = 1; prev = $0; next }
    d == 1 { ok = ($0 == "@" m "{}"); d = 0 }
    { prev = $0 }
    END { exit !ok }'
}
prog=$top_builddir/tools/chaplygin
eqerrata=$("$prog" eq --list --csv | awk -F, 'NR > 1 { e = $NF; gsub(/ /, ",", e); print $1 "\t" e }')

tab=$(printf '\t')
tail -n +2 "$tmp/tsv" > "$tmp/rows"
while IFS="$tab" read -r eq fn ut ver err pf call; do
  msg=""
  fns=$fn
  case $pf in -|same|none) ;; *) fns="$fns,$pf" ;; esac
  for f in $(echo "$fns" | tr ',' ' '); do
    echo "$symbols" | grep -qx "$f" || msg="$msg [function $f not exported]"
    api_entry "$f" || msg="$msg [no @anchor/@deftypefun/@implements entry for $f in doc/api*.texi]"
  done
  if [ "$err" != "-" ]; then
    for e in $(echo "$err" | tr ',' ' '); do
      grep -q "^@node Erratum $e\$" "$top_srcdir/doc/errata.texi" || msg="$msg [no erratum $e]"
    done
  fi
  want=$(echo "$eqerrata" | awk -F '\t' -v l="$eq" '($1 "") == (l "") { print $2 }')
  [ "$want" = "$err" ] || msg="$msg [errata '$err', chaplygin eq --list: '$want']"
  for t in $(echo "$ut" | tr ',' ' '); do
    echo "$tcases" | grep -qx "$t" || msg="$msg [no TCase $t in tests/]"
  done
  if [ "$ver" != "-" ]; then
    for v in $(echo "$ver" | tr ',' ' '); do
      [ -r "$top_srcdir/verification/$v.c" ] || msg="$msg [no verification/$v.c]"
    done
  fi
  if [ -z "$msg" ]; then ok "($eq) $fn | $ut | $ver | $err | $pf"; else notok "($eq)$msg"; fi
done < "$tmp/rows"

# `chaplygin eq --list' against the registry's fields, label by label:
# FIELD<TAB>LABEL<TAB>REGISTRY<TAB>PROGRAM for each difference.
"$prog" eq --list --csv > "$tmp/list.csv" && "$prog" eq --list > "$tmp/list.txt" \
  || echo "# chaplygin eq --list failed"
for f in title eq.inputs eq.outputs eq.paper functions; do
  "$PERL" "$labels_pl" field "$f" "$registry" | sed "s/^/$f$tab/"
done > "$tmp/fields"
"$PERL" -e '
  my ($csv, $txt, $fields) = @ARGV;
  my (%prog, @order);
  open my $c, "<", $csv or die "$csv: $!";
  <$c>;                                 # label,title,inputs,outputs,functions,errata
  while (my $line = <$c>) {
    chomp $line;
    my @f;
    push @f, $1 =~ /^"(.*)"$/s ? $1 =~ s/""/"/gr : $1
      while $line =~ /\G("(?:[^"]|"")*"|[^,]*)(?:,|$)/g && @f < 6;
    @{ $prog{$f[0]} }{qw(title eq.inputs eq.outputs functions)} = @f[1 .. 4];
  }
  open my $t, "<", $txt or die "$txt: $!";
  my $label;
  while (<$t>) {
    $label = $1 if /^\(([^)]*)\) /;
    $prog{$label}{"eq.paper"} = $1 if /^    paper: +(.*)$/;
  }
  open my $r, "<", $fields or die "$fields: $!";
  while (<$r>) {
    chomp;
    my ($field, $l, $v) = split /\t/, $_, 3;
    my $p = $prog{$l}{$field} // "(no such label)";
    print "$field\t$l\t$v\t$p\n" if $p ne $v;
  }' "$tmp/list.csv" "$tmp/list.txt" "$tmp/fields" > "$tmp/diff" \
  || echo "# comparing chaplygin eq --list with the registry failed" > "$tmp/diff"
report () {   # report FIELD...: the differences in these fields
  for f in "$@"; do
    awk -F '\t' -v f="$f" '$1 == f { print "# (" $2 ") " f ": registry \"" $3 "\", chaplygin eq \"" $4 "\"" }' "$tmp/diff"
  done
}
if [ -z "$(report eq.inputs eq.outputs eq.paper)" ] && ! grep -q '^#' "$tmp/diff"; then
  ok "chaplygin eq --list shows the registry's eq.inputs, eq.outputs and eq.paper"
else
  report eq.inputs eq.outputs eq.paper; grep '^#' "$tmp/diff"
  notok "chaplygin eq --list differs from the registry's eq.inputs, eq.outputs or eq.paper"
fi
for f in title:titles functions:"function lists"; do
  d=$(report "${f%%:*}")
  if [ -z "$d" ]; then
    ok "chaplygin eq --list shows the registry's ${f#*:}"
  else
    echo "$d"
    notok "chaplygin eq --list shows the registry's ${f#*:}"
  fi
done
echo "1..$n"
exit $fail
