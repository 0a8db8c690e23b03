#!/bin/sh
# check-texi-math.sh -- TAP: every formula of the hand-written chapters is
# in the manual's form (doc/texi-math.pl --check): each @math{} written
# with the math macros (lib/TexinfoMath.pm), each displayed formula in
# its one pattern (a plain @example for Info, its TeX a @displaymath a
# line, the two with the same symbols).  The chapters: every doc/*.texi
# but those marked "do not edit" in their first lines (generated, their
# generators convert) and figures.texi, claims.texi and
# claims-figures.texi (written by doc/claims.pl's rules, not yet
# converted).  POSIX sh; needs perl.

set -u
top_srcdir=${top_srcdir:-.}
PERL=${PERL:-perl}

echo "1..1"
files=""
for f in "$top_srcdir"/doc/*.texi; do
  case $(basename "$f") in
    figures.texi | claims.texi | claims-figures.texi) continue ;;
  esac
  head -n 3 "$f" | grep -qi 'do not edit' && continue
  files="$files $f"
done
# shellcheck disable=SC2086  # the file names: doc/*.texi, no spaces
if out=$("$PERL" "$top_srcdir/doc/texi-math.pl" --check $files 2>&1); then
  echo "ok 1 - the formulas of$(for f in $files; do printf ' %s' "$(basename "$f")"; done) are in the manual's form"
else
  echo "$out" | sed 's/^/# /'
  echo "not ok 1 - formulas not in the manual's form (doc/texi-math.pl FILE converts them)"
fi
