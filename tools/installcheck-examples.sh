#!/bin/sh
# installcheck-examples.sh -- `make installcheck': every command of the
# installed man page's EXAMPLES runs, as written, with the installed
# program first on PATH, in an empty directory (so that nothing of the
# source tree is used), and succeeds; the installed scenes are all there.
#   CHAPLYGIN_MAN       the installed man page
#   CHAPLYGIN_BINDIR    the directory of the installed program
#   CHAPLYGIN_DATADIR   the installed $(pkgdatadir) as the man page names it
#   CHAPLYGIN_LIBDIR    the directory of the installed library
#   CHAPLYGIN_DESTDIR   $(DESTDIR) (the files are under it; the library
#                       is then found through LD_LIBRARY_PATH)
# TAP on stdout.  POSIX sh.

set -u
man=${CHAPLYGIN_MAN:?}
bindir=${CHAPLYGIN_BINDIR:?}
datadir=${CHAPLYGIN_DATADIR:?}
libdir=${CHAPLYGIN_LIBDIR:?}
destdir=${CHAPLYGIN_DESTDIR:-}

tmp=$(mktemp -d "${TMPDIR:-/tmp}/examples.XXXXXX") || exit 1
trap 'rm -rf "$tmp"' 0
trap 'exit 1' HUP INT TERM

if test ! -r "$man"; then
  echo "1..0 # SKIP no installed man page $man"
  exit 0
fi

# The lines of the .nf blocks of EXAMPLES, roff escapes undone; with a
# DESTDIR, the data directory is where the files are.
awk '/^\.SH / { on = ($0 == ".SH EXAMPLES"); next }
     on && /^\.nf/ { nf = 1; next }
     on && /^\.fi/ { nf = 0; next }
     on && nf' "$man" \
  | sed -e 's/\\-/-/g' -e 's/\\e/\\/g' -e "s|$datadir|$destdir$datadir|g" \
  > "$tmp/commands"
n=$(wc -l < "$tmp/commands" | tr -d ' ')
echo "1..$((n + 1))"

i=0
missing=""
for f in example fig2a fig2b fig3 fig4 fig5 fig6 fig7 fig8 fig9 fig10 \
    atlas-omega atlas-bistable; do
  test -r "$destdir$datadir/scenes/$f.ini" || missing="$missing $f.ini"
done
i=$((i + 1))
if test -z "$missing"; then
  echo "ok $i - the 13 scenes are installed in $datadir/scenes"
else
  echo "not ok $i - scenes missing from $datadir/scenes:$missing"
fi

mkdir "$tmp/work"
while IFS= read -r cmd; do
  i=$((i + 1))
  if (cd "$tmp/work" && PATH="$destdir$bindir:$PATH" && export PATH \
        && if test -n "$destdir"; then
             LD_LIBRARY_PATH="$destdir$libdir${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
             export LD_LIBRARY_PATH
           fi \
        && eval "$cmd") > "$tmp/out" 2> "$tmp/err"; then
    echo "ok $i - $cmd"
  else
    sed 's/^/# /' "$tmp/err"
    echo "not ok $i - $cmd"
  fi
done < "$tmp/commands"
