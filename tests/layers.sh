#!/bin/sh
# layers.sh -- TAP: the structure of lib/, read from the objects' own symbol
# tables (nm of the built archive: which file defines a symbol, which file
# uses it), not from the sources' text.
#  1. every source of lib/ is either a kernel file or a section file (the
#     lists below, which the manual's chapter "Layers" shows);
#  2. no kernel file uses a section file;
#  3. no two files depend on each other in a circle (the file graph is
#     acyclic);
#  4. the scene engine (lib/scene/, libchaplygin-scene) uses the library
#     through its public interface only: every symbol of libchaplygin-core
#     it uses is a public chaplygin_ function;
# and prints the graph (`make check' keeps it in tests/layers.sh.log).
# POSIX sh and awk.

set -u
top_builddir=${top_builddir:-.}
top_srcdir=${top_srcdir:-.}
archive=$top_builddir/lib/.libs/libchaplygin-core.a

# The kernel, in layer order: each uses only files before it.
kernel="eft status carlson ellint quad collision motion ode leg far series cert-round cert-leg cert-eval"
# The paper's sections (they may use the kernel and each other, acyclically).
sections="units smooth discrete flow map stability reversal energy fate massless skate sweep printed certified cert-algebraic cert-series certified-none"

echo "1..4"
if test ! -r "$archive"; then
  echo "Bail out! $archive is not built"
  exit 1
fi

# "user used" pairs of files: U symbols of one object defined (T) in another.
nm -A "$archive" 2>/dev/null | awk '
  {
    split($1, p, ":"); obj = p[2]
    sub(/^libchaplygin_core_la-/, "", obj); sub(/\.o$/, "", obj)
    if ($2 == "T" || $2 == "D" || $2 == "R" || $2 == "B") def[$3] = obj
    else if ($2 == "U") { nu++; uobj[nu] = obj; usym[nu] = $3 }
    files[obj] = 1
  }
  END {
    for (f in files) print "file " f
    for (i = 1; i <= nu; i++)
      if ((usym[i] in def) && def[usym[i]] != uobj[i])
        print "edge " uobj[i] " " def[usym[i]]
  }' | sort -u > layers.graph.tmp

files=$(awk '$1 == "file" { print $2 }' layers.graph.tmp)
missing=""
for f in $files; do
  case " $kernel $sections " in *" $f "*) ;; *) missing="$missing $f" ;; esac
done
if test -z "$missing"; then
  echo "ok 1 - every source of lib/ is a kernel or a section file"
else
  echo "not ok 1 - not classified:$missing"
fi

bad=""
for k in $kernel; do
  for used in $(awk -v f="$k" '$1 == "edge" && $2 == f { print $3 }' layers.graph.tmp); do
    case " $sections " in *" $used "*) bad="$bad $k->$used" ;; esac
  done
done
if test -z "$bad"; then
  echo "ok 2 - no kernel file uses a section file"
else
  echo "not ok 2 - kernel files using sections:$bad"
fi

# Acyclic: remove files that use nothing left, repeatedly (Kahn).
cycle=$(awk '
  $1 == "file" { f[$2] = 1 }
  $1 == "edge" { out[$2] = out[$2] " " $3; n[$2]++ }
  END {
    do {
      changed = 0
      for (x in f) {
        left = 0
        m = split(out[x], u, " ")
        for (i = 1; i <= m; i++) if (u[i] in f) left++
        if (left == 0) { delete f[x]; changed = 1 }
      }
    } while (changed)
    for (x in f) printf " %s", x
  }' layers.graph.tmp)
if test -z "$cycle"; then
  echo "ok 3 - the file graph is acyclic"
else
  echo "not ok 3 - files in a cycle:$cycle"
fi

# 4. the engine's uses of the library: public names only
engine=$top_builddir/lib/.libs/libchaplygin-scene-core.a
if test ! -r "$engine"; then
  echo "not ok 4 - $engine is not built"
else
  nm -g --defined-only "$archive" 2>/dev/null | awk 'NF == 3 { print $3 }' \
    | sort -u > layers.core.tmp
  inner=$(nm -u "$engine" 2>/dev/null | awk '{ print $NF }' | sort -u \
    | comm -12 - layers.core.tmp | grep -v '^chaplygin_' | tr '\n' ' ')
  rm -f layers.core.tmp
  if test -z "$inner"; then
    echo "ok 4 - the scene engine uses the library's public functions only"
  else
    echo "not ok 4 - the scene engine uses the library's internals: $inner"
  fi
fi

echo "# the file graph (user: used), from nm of $archive:"
awk '$1 == "edge" { u[$2] = u[$2] " " $3 } $1 == "file" { f[$2] = 1 }
     END { for (x in f) print "# " x ":" u[x] }' layers.graph.tmp | sort
rm -f layers.graph.tmp
