#!/bin/sh
# fuzz-replay.sh -- TAP: replay the scene fuzzer's corpus
# (tools/fuzz-corpus/, kept from libFuzzer runs of `make fuzz') through
# the fuzz target built with the project's compiler: every input must be
# parsed (accepted or rejected with a message) without a crash, and, in
# the build of `make check-sanitizers', without a sanitizer finding.
set -u
top_builddir=${top_builddir:-.}
top_srcdir=${top_srcdir:-.}
target=$top_builddir/tools/fuzz-scene
corpus=$top_srcdir/tools/fuzz-corpus
echo "1..1"
test -x "$target" || { echo "Bail out! $target is not built"; exit 1; }
n=$(ls "$corpus" | wc -l)
if "$target" "$corpus"; then
  echo "ok 1 - the fuzz target parses all $n corpus inputs"
else
  echo "not ok 1 - the fuzz target failed on the corpus ($n inputs)"
fi
