#!/bin/sh
# fp-digest.sh PROG SRCDIR: one digest of the numbers the program prints
# for every scene of SRCDIR/scenes (and its smooth companion), every
# evaluation of SRCDIR/tests/ref/eq.tsv, and skate runs by every method,
# near and far.  Two builds whose digests agree compute the same bits
# there: `make check-sanitizers' compares its portable build (configure
# --disable-fma) with the main one (-mfma where the machine has it).
# The numbers only: no provenance lines (they name the scene's path).
set -u
prog=$1
src=$2
{
  for f in "$src"/scenes/*.ini; do
    "$prog" run --no-provenance "$f" 2>/dev/null
    "$prog" run --no-provenance --compare "$f" 2>/dev/null
  done
  tail -n +2 "$src/tests/ref/eq.tsv" | cut -f1,2 | sort -u \
    | while IFS="$(printf '\t')" read -r label args; do
        # shellcheck disable=SC2086
        "$prog" eq "$label" $args --csv 2>/dev/null
      done
  for m in closed-form quadrature ode; do
    "$prog" skate --L0 -1/2 --Delta 1 --V 0.3 --Omega 0.8 --collisions 40 \
      --method $m --no-provenance 2>/dev/null
    "$prog" skate --L0 1e200 --Delta 3e199 --V 0.3 --Omega 1e-200 \
      --collisions 20 --method $m --no-provenance 2>/dev/null
  done
} | cksum
