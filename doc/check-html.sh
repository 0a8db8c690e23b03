#!/bin/sh
# check-html.sh -- TAP: the HTML manual is whole.
#  1. every image and every internal link of every page resolves, in the
#     split edition and in the single page one-page.html beside it
#     (doc/check-html.pl);
#  2. every figure of the manual is shown by some page;
#  3. every equation label has its concordance entry (anchor) and index
#     entry in the single page, and every function of doc/concordance.tsv
#     its anchor in the library reference;
#  4. no page loads a remote script or style sheet, and every formula
#     (MathJax's \(...\)), those of the concordance first, is well-formed
#     TeX (doc/check-math.pl).
# The directory checked is $CHAPLYGIN_HTML_DIR (`make installcheck': the
# installed manual), else doc/chaplygin.html of the build tree (`make
# check', which builds it first).  POSIX sh; needs perl (as makeinfo does).

set -u
top_srcdir=${top_srcdir:-.}
top_builddir=${top_builddir:-.}
dir=${CHAPLYGIN_HTML_DIR:-$top_builddir/doc/chaplygin.html}
tsv=$top_srcdir/doc/concordance.tsv

echo "1..4"
if test ! -r "$dir/index.html" || test ! -r "$dir/one-page.html"; then
  echo "Bail out! $dir/index.html or one-page.html missing (make html)"
  exit 1
fi

if out=$(perl "$top_srcdir/doc/check-html.pl" "$dir" 2>&1); then
  echo "ok 1 - every image and internal link resolves ($out)"
else
  echo "$out" | sed 's/^/# /'
  echo "not ok 1 - broken images or links in $dir"
fi

# The figures: every PNG of doc/figures/ (the one list: the directory).
missing=""
n=0
for png in "$top_srcdir"/doc/figures/*.png; do
  f=$(basename "$png" .png)
  n=$((n + 1))
  test -r "$dir/$f.png" || missing="$missing $f.png(file)"
  grep -q "src=\"$f.png\"" "$dir"/*.html || missing="$missing $f.png(page)"
done
if test -z "$missing" && test "$n" -ge 13; then
  echo "ok 2 - all $n figures of doc/figures are in the directory and shown by a page"
else
  echo "not ok 2 - figures missing:$missing"
fi

missing=""
page=$dir/one-page.html
for label in $(tail -n +2 "$tsv" | cut -f1); do
  # makeinfo writes "Equation 3-10" as the id Equation-3_002d10.
  id=$(echo "$label" | sed 's/\./_002d/')
  grep -q "id=\"Equation-$id\"" "$page" || missing="$missing ($label)anchor"
  grep -q "index-_0028$(echo "$label" | sed 's/\./_002e/')_0029" "$page" \
    || missing="$missing ($label)index"
done
# ... and "chaplygin_discrete_sigma4" as chaplygin_005fdiscrete_005fsigma4.
for fn in $(tail -n +2 "$tsv" | cut -f2,6 | tr '\t,' '\n\n' | grep '^chaplygin_' | sort -u); do
  grep -q "id=\"$(echo "$fn" | sed 's/_/_005f/g')\"" "$page" || missing="$missing $fn"
done
if test -z "$missing"; then
  echo "ok 3 - every label has its concordance anchor and index entry, every function its anchor"
else
  echo "not ok 3 - missing:$missing"
fi

if out=$(perl "$top_srcdir/doc/check-math.pl" "$dir" 2>&1); then
  echo "ok 4 - $out"
else
  echo "$out" | sed 's/^/# /'
  echo "not ok 4 - a remote script or malformed TeX in $dir"
fi
