#!/bin/sh
# apiref.sh -- TAP: the library reference and the header cannot disagree.
# lib/chaplygin.h is the one source of the public contract; the manual's
# chapter "Library reference" (doc/api.texi, doc/api-printed.texi) is
# generated from its doc comments by doc/hdr2texi.pl (doc/local.mk).
#  1. doc/hdr2texi.pl reads the header without error: every function
#     declared has a doc comment, and the markup is valid;
#  2, 3. doc/api.texi and doc/api-printed.texi are what the generator makes
#     of the header now (a hand edit, or a header edited without
#     regenerating, fails here), with the invocations of doc/local.mk;
#  4. every function the built library exports (nm) has a doc comment;
#  5. every function the header documents is exported;
#  6. every exported function has its entry (@anchor and @deftypefun) in
#     the generated chapter, and every entry there is an exported function;
#  7-10. the same for the scene engine: lib/scene/chaplygin-scene.h, the
#     chapter "Scene engine reference" (doc/api-scene.texi) and the
#     functions libchaplygin-scene exports.
# POSIX sh, perl (as makeinfo needs it), nm.

set -u
top_srcdir=${top_srcdir:-.}
top_builddir=${top_builddir:-.}
hdr=$top_srcdir/lib/chaplygin.h
gen="perl $top_srcdir/doc/hdr2texi.pl --name=lib/chaplygin.h --concordance=$top_srcdir/doc/concordance.tsv"
tmp=apiref.tmp.$$
trap 'rm -rf "$tmp"' 0 1 2 15
mkdir "$tmp" || exit 1

echo "1..10"
lib=""
for f in "$top_builddir/lib/.libs/libchaplygin.so" "$top_builddir/lib/.libs/libchaplygin.a"; do
  if [ -r "$f" ]; then lib=$f; break; fi
done
if [ -z "$lib" ]; then echo "Bail out! built library not found under $top_builddir/lib/.libs"; exit 1; fi
case $lib in
  *.so) nm -D --defined-only "$lib" ;;
  *) nm -g --defined-only "$lib" ;;
esac | awk '$2 == "T" && $3 ~ /^chaplygin_/ { print $3 }' | sort -u > "$tmp/exported"

fail=0
ok () { echo "ok $1 - $2"; }
notok () { fail=1; echo "not ok $1 - $2"; }
# The lines of file $1 not in file $2, as a TAP diagnostic.
missing () { comm -23 "$1" "$2" | sed 's/^/#   /'; }

# 1. the generator reads the header
$gen --list "$hdr" > "$tmp/list" 2> /dev/null
if $gen --chapter='Library reference' --split='Printed forms=api-printed.texi' \
     "$hdr" > "$tmp/api.texi" 2> "$tmp/err1" \
   && $gen --only='Printed forms' "$hdr" > "$tmp/api-printed.texi" 2> "$tmp/err2"; then
  ok 1 "doc/hdr2texi.pl reads lib/chaplygin.h: every function documented"
  gen_ok=1
else
  cat "$tmp"/err* | sed 's/^/# /'
  notok 1 "doc/hdr2texi.pl fails on lib/chaplygin.h"
  gen_ok=0
fi

# 2, 3. the generated files in the source tree are a fresh generation
n=2
for f in api.texi api-printed.texi; do
  if [ $gen_ok = 0 ]; then
    notok $n "doc/$f is a fresh generation (the generator failed)"
  elif cmp -s "$tmp/$f" "$top_srcdir/doc/$f"; then
    ok $n "doc/$f is what doc/hdr2texi.pl makes of lib/chaplygin.h"
  else
    diff "$top_srcdir/doc/$f" "$tmp/$f" | head -n 20 | sed 's/^/# /'
    notok $n "doc/$f differs from a fresh generation: edit lib/chaplygin.h, not doc/$f (make regenerates it)"
  fi
  n=$((n + 1))
done

# 4, 5. exported functions <-> doc comments
sed -n 's/^function //p' "$tmp/list" | sort -u > "$tmp/documented"
if [ -z "$(comm -23 "$tmp/exported" "$tmp/documented")" ]; then
  ok 4 "every exported function ($(wc -l < "$tmp/exported" | tr -d ' ')) has a doc comment in lib/chaplygin.h"
else
  missing "$tmp/exported" "$tmp/documented"
  notok 4 "exported functions without a doc comment in lib/chaplygin.h (listed above)"
fi
if [ -z "$(comm -13 "$tmp/exported" "$tmp/documented")" ]; then
  ok 5 "every function documented in lib/chaplygin.h is exported"
else
  missing "$tmp/documented" "$tmp/exported"
  notok 5 "functions documented in lib/chaplygin.h but not exported (listed above)"
fi

# 6. exported functions <-> entries of the generated chapter
cat "$top_srcdir/doc/api.texi" "$top_srcdir/doc/api-printed.texi" 2>/dev/null | awk '
  /^@anchor\{/ { a = substr($0, 9, length($0) - 9); next }
  /^@deftypefun / {
    if (match($0, /[ *]chaplygin_[a-z0-9_]+ \(/)) {
      f = substr($0, RSTART + 1, RLENGTH - 3)
      print (f == a ? f : f " (without its @anchor)")
    }
  }
  { a = "" }' | sort -u > "$tmp/entries"
if [ -z "$(comm -3 "$tmp/exported" "$tmp/entries")" ]; then
  ok 6 "every exported function has its @anchor/@deftypefun entry in doc/api*.texi, and every entry is exported"
else
  missing "$tmp/exported" "$tmp/entries" | sed 's/$/ (exported, no entry)/'
  missing "$tmp/entries" "$tmp/exported" | sed 's/$/ (an entry, not exported)/'
  notok 6 "doc/api*.texi and the library's exports disagree (listed above)"
fi
# 7-10: the scene engine
shdr=$top_srcdir/lib/scene/chaplygin-scene.h
sgen="perl $top_srcdir/doc/hdr2texi.pl --name=lib/scene/chaplygin-scene.h"
slib=""
for f in "$top_builddir/lib/.libs/libchaplygin-scene.so" "$top_builddir/lib/.libs/libchaplygin-scene.a"; do
  if [ -r "$f" ]; then slib=$f; break; fi
done
if [ -z "$slib" ]; then echo "Bail out! libchaplygin-scene not found under $top_builddir/lib/.libs"; exit 1; fi
case $slib in
  *.so) nm -D --defined-only "$slib" ;;
  *) nm -g --defined-only "$slib" ;;
esac | awk '$2 == "T" && $3 ~ /^chaplygin_/ { print $3 }' | sort -u > "$tmp/sexported"
$sgen --list "$shdr" 2>/dev/null | sed -n 's/^function //p' | sort -u > "$tmp/sdocumented"
if $sgen --chapter='Scene engine reference' "$shdr" > "$tmp/api-scene.texi" 2> "$tmp/serr"; then
  ok 7 "doc/hdr2texi.pl reads lib/scene/chaplygin-scene.h: every function documented"
  if cmp -s "$tmp/api-scene.texi" "$top_srcdir/doc/api-scene.texi"; then
    ok 8 "doc/api-scene.texi is what doc/hdr2texi.pl makes of lib/scene/chaplygin-scene.h"
  else
    diff "$top_srcdir/doc/api-scene.texi" "$tmp/api-scene.texi" | head -n 20 | sed 's/^/# /'
    notok 8 "doc/api-scene.texi differs from a fresh generation: edit the header"
  fi
else
  sed 's/^/# /' "$tmp/serr"
  notok 7 "doc/hdr2texi.pl fails on lib/scene/chaplygin-scene.h"
  notok 8 "doc/api-scene.texi is a fresh generation (the generator failed)"
fi
if cmp -s "$tmp/sexported" "$tmp/sdocumented"; then
  ok 9 "the functions libchaplygin-scene exports ($(wc -l < "$tmp/sexported" | tr -d ' ')) are those documented in its header"
else
  missing "$tmp/sexported" "$tmp/sdocumented" | sed 's/$/ (exported, not documented)/'
  missing "$tmp/sdocumented" "$tmp/sexported" | sed 's/$/ (documented, not exported)/'
  notok 9 "libchaplygin-scene's exports and its header's doc comments disagree"
fi
awk '/^@anchor\{/ { a = substr($0, 9, length($0) - 9); next }
     /^@deftypefun / { if (match($0, /[ *]chaplygin_[a-z0-9_]+ \(/)) {
         f = substr($0, RSTART + 1, RLENGTH - 3); print (f == a ? f : f " (without its @anchor)") } }
     { a = "" }' "$top_srcdir/doc/api-scene.texi" 2>/dev/null | sort -u > "$tmp/sentries"
if cmp -s "$tmp/sexported" "$tmp/sentries"; then
  ok 10 "every function libchaplygin-scene exports has its entry in doc/api-scene.texi, and only those"
else
  missing "$tmp/sexported" "$tmp/sentries" | sed 's/$/ (exported, no entry)/'
  missing "$tmp/sentries" "$tmp/sexported" | sed 's/$/ (an entry, not exported)/'
  notok 10 "doc/api-scene.texi and libchaplygin-scene's exports disagree"
fi
exit $fail
