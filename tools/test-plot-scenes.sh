#!/bin/sh
# test-plot-scenes.sh -- TAP: "chaplygin plot" draws every scene that
# "chaplygin run" accepts, or refuses it (exit 2) with a message saying
# why, before gnuplot runs: never a raw gnuplot error.  Scenes at the
# edges: each model and view, collisions = 0 and 1, stop conditions that
# end a run at once, tiny and huge states, far slots, a straight line
# (H = 0), sweeps of one point, of one y, of points that all fail or lie
# beyond what gnuplot draws; atlases of one point, one x, one y, y_min =
# y_max, a 2 x 2 grid.  Each case says which it must be: "draw"
# (exit 0, a whole SVG, nothing from gnuplot on stderr) or "refuse TEXT"
# (exit 2, no file, TEXT in the message); and run accepts every scene.
# A run of one row is drawn as points.  Skipped without gnuplot.
# Run by `make check', or by hand:
#   top_builddir=. top_srcdir=. sh tools/test-plot-scenes.sh
# POSIX sh.

set -u
top_builddir=${top_builddir:-.}
top_srcdir=${top_srcdir:-.}
prog=${CHAPLYGIN:-$top_builddir/tools/chaplygin}

# The cases: "EXPECT | NAME | scene lines separated by ';'".
cases=$(cat <<'EOF'
draw | discrete, collisions = 0 | [scene];model = discrete;[parameters];L0 = 1;Delta = 1/3;[initial];V = 1;Omega = 0.5;[run];collisions = 0
draw | discrete phase-space, collisions = 0 | [scene];model = discrete;[parameters];L0 = 1;Delta = 1/3;[initial];V = 1;Omega = 0.5;[run];collisions = 0;[plot];view = phase-space
draw | discrete and companion, collisions = 0 | [scene];model = discrete;compare = smooth;[parameters];L0 = 1;Delta = 1/3;L = 1;[initial];V = 1;Omega = 0.5;[run];collisions = 0;duration = 1
draw | ... phase-space, collisions = 0 | [scene];model = discrete;compare = smooth;[parameters];L0 = 1;Delta = 1/3;L = 1;[initial];V = 1;Omega = 0.5;[run];collisions = 0;duration = 1;[plot];view = phase-space
draw | massless, collisions = 0 | [scene];model = massless;[parameters];L0 = -0.5;[initial];V = 1;Omega = 0.5;[run];collisions = 0
draw | discrete, collisions = 1 | [scene];model = discrete;[parameters];L0 = 1;Delta = 1/3;[initial];V = -1;Omega = 0.5;[run];collisions = 1
draw | discrete phase-space, collisions = 1 | [scene];model = discrete;[parameters];L0 = 1;Delta = 1/3;[initial];V = 1;Omega = 0.5;[run];collisions = 1;[plot];view = phase-space
draw | massless, collisions = 1, per collision | [scene];model = massless;[parameters];L0 = -0.5;[initial];V = 1;Omega = 0.5;[run];collisions = 1;samples = 0
draw | discrete, stop_H ends it at collision 0 | [scene];model = discrete;[parameters];L0 = 1;Delta = 1/3;[initial];V = 1;Omega = 0.5;[run];collisions = 3;stop_H = 1e300
draw | discrete phase-space, stop_fate at collision 0 | [scene];model = discrete;[parameters];L0 = 1;Delta = 1/3;[initial];V = 1;Omega = 0.5;[run];collisions = 3;stop_fate = yes;[plot];view = phase-space
draw | massless, stop_H at collision 0 | [scene];model = massless;[parameters];L0 = -0.5;[initial];V = 1;Omega = 0.5;[run];collisions = 3;stop_H = 1e300
draw | discrete, stop_tau after the first segment | [scene];model = discrete;[parameters];L0 = 1;Delta = 1/3;[initial];V = 1;Omega = 0.5;[run];collisions = 3;stop_tau = 1e-300
draw | discrete, a straight line (Omega = 0) | [scene];model = discrete;[parameters];L0 = 1;Delta = 1/3;[initial];V = 1;Omega = 0;[run];collisions = 3
draw | smooth, a straight line, one sample | [scene];model = smooth;[parameters];L = 1;[initial];V = 1;Omega = 0;[run];duration = 1e-300;samples = 1
draw | discrete, a tiny state within the doubles (1e-100) | [scene];model = discrete;[parameters];L0 = 1;Delta = 1/3;[initial];V = 1e-100;Omega = 1e-100;[run];collisions = 3
draw | sigma4, one x | [scene];model = discrete;[sweep];kind = sigma4;x_min = -4;x_max = 2;nx = 1;y = 0.5;dir = 1
draw | stability, one point | [scene];model = discrete;[sweep];kind = stability;x_min = -4;x_max = 2;nx = 1;y_min = 0;y_max = 1;ny = 1
draw | stability, one y on a 3 x 3 grid | [scene];model = discrete;[sweep];kind = stability;x_min = -4;x_max = 2;nx = 3;y_min = 0.5;y_max = 0.5;ny = 3
draw | basins, one point | [scene];model = discrete;[parameters];L0 = -0.5;Delta = 1;[initial];Omega = 0.8;[run];collisions = 10;[sweep];kind = basins;x_min = 0.0005;x_max = 0.5;nx = 1
draw | discrete, a far slot (L0 = 1e200, V = 1, Omega = 1e-100) | [scene];model = discrete;[parameters];L0 = 1e200;Delta = 1/3;[initial];V = 1;Omega = 1e-100;[run];collisions = 3
refuse beyond the doubles | discrete, a far slot (L0 = 1e300, V = Omega = 1: E = 5e599) | [scene];model = discrete;[parameters];L0 = 1e300;Delta = 1/3;[initial];V = 1;Omega = 1;[run];collisions = 3
refuse beyond the doubles | discrete, V = Omega = 1e300 | [scene];model = discrete;[parameters];L0 = 1;Delta = 1/3;[initial];V = 1e300;Omega = 1e300;[run];collisions = 3
refuse beyond the doubles | discrete phase-space, V = Omega = 1e-300 | [scene];model = discrete;[parameters];L0 = 1;Delta = 1/3;[initial];V = 1e-300;Omega = 1e-300;[run];collisions = 3;[plot];view = phase-space
refuse beyond the doubles | massless, Omega = 1e300 | [scene];model = massless;[parameters];L0 = -0.5;[initial];V = 1;Omega = 1e300;[run];collisions = 3
refuse beyond the doubles | smooth, V = Omega = 1e300 | [scene];model = smooth;[parameters];L = 1;[initial];V = 1e300;Omega = 1e300;[run];duration = 3
refuse up to 1e300 | discrete, V = Omega = 1e150 (E = 1.5e300) | [scene];model = discrete;[parameters];L0 = 1;Delta = 1/3;[initial];V = 1e150;Omega = 1e150;[run];collisions = 3
refuse subnormal | smooth, Omega = 4.9e-324 | [scene];model = smooth;[parameters];L = 1;[initial];V = 1;Omega = 4.9e-324;[run];duration = 3
refuse up to 1e300 | basins over V0 = -1.7e308 .. 1.7e308 | [scene];model = discrete;[parameters];L0 = -0.5;Delta = 1;[initial];Omega = 1e-300;[run];collisions = 3;[sweep];kind = basins;x_min = -1.7e308;x_max = 1.7e308;nx = 4
draw | atlas, one point | [scene];model = discrete;[parameters];L0 = -0.5;Delta = 1;[run];collisions = 10;[sweep];kind = atlas;x = V;x_min = 0.1;x_max = 0.5;nx = 1;y = Omega;y_min = 0.1;y_max = 2;ny = 1
draw | atlas, one y | [scene];model = discrete;[parameters];L0 = -0.5;Delta = 1;[run];collisions = 10;[sweep];kind = atlas;x = V;x_min = 0.1;x_max = 0.5;nx = 5;y = Omega;y_min = 0.1;y_max = 2;ny = 1
draw | atlas, y_min = y_max on a 3 x 3 grid | [scene];model = discrete;[parameters];L0 = -0.5;Delta = 1;[run];collisions = 10;[sweep];kind = atlas;x = V;x_min = 0.1;x_max = 0.5;nx = 3;y = Omega;y_min = 0.8;y_max = 0.8;ny = 3
draw | atlas over (Delta, L0), 2 x 2 | [scene];model = discrete;[initial];V = 0.3;Omega = 0.8;[run];collisions = 10;[sweep];kind = atlas;x = Delta;x_min = 0.5;x_max = 2;nx = 2;y = L0;y_min = -1;y_max = 1;ny = 2
draw | atlas, one x through V = 0 | [scene];model = discrete;[parameters];Delta = 1;[initial];Omega = 0.8;[run];collisions = 10;[sweep];kind = atlas;x = L0;x_min = -1;x_max = 1;nx = 1;y = V;y_min = -1;y_max = 1;ny = 3
refuse up to 1e300 | atlas over L0 = -1.7e308 .. 1.7e308 | [scene];model = discrete;[parameters];Delta = 1;[initial];Omega = 0.8;[run];collisions = 3;[sweep];kind = atlas;x = L0;x_min = -1.7e308;x_max = 1.7e308;nx = 3;y = V;y_min = 0.1;y_max = 1;ny = 2
refuse no row to draw | atlas whose every point fails (V = 0) | [scene];model = discrete;[parameters];Delta = 1;[initial];Omega = 0.8;[run];collisions = 10;[sweep];kind = atlas;x = L0;x_min = -1;x_max = 1;nx = 3;y = V;y_min = 0;y_max = 0;ny = 2
refuse no row to draw | basins whose one point fails (V0 = 0) | [scene];model = discrete;[parameters];L0 = -0.5;Delta = 1;[initial];Omega = 0.8;[run];collisions = 10;[sweep];kind = basins;x_min = 0;x_max = 1;nx = 1
EOF
)

. "$top_srcdir/tools/tap-lib.sh"
n_cases=$(echo "$cases" | wc -l)
tap_start test-plot-scenes $((n_cases + 1))

if ! gnuplot -e 'set terminal svg' </dev/null >/dev/null 2>&1; then
  while test "$count" -lt "$plan"; do
    count=$((count + 1))
    echo "ok $count # SKIP gnuplot not found"
  done
  exit 0
fi

i=0
echo "$cases" | while IFS='|' read -r expect name lines; do
  i=$((i + 1))
  expect=$(echo $expect)
  name=$(echo $name)
  echo "$lines" | sed 's/^ *//' | tr ';' '\n' >"$tmp/c$i.ini"
  ok=1
  if "$prog" run "$tmp/c$i.ini" -o /dev/null 2>"$tmp/run.err"; then
    rc=0
    "$prog" plot "$tmp/c$i.ini" -o "$tmp/c$i.svg" 2>"$tmp/err" || rc=$?
    # every line of stderr the program's, none relaying gnuplot
    quiet=1
    grep -v '^chaplygin: ' "$tmp/err" >/dev/null \
      || grep '^chaplygin: plot: gnuplot' "$tmp/err" >/dev/null || quiet=0
    case $expect in
      draw)
        test "$rc" -eq 0 && test "$quiet" -eq 0 \
          && test "$(tail -c 8 "$tmp/c$i.svg" | tr -d '\n')" = "</svg>" && ok=0 ;;
      refuse*)
        test "$rc" -eq 2 && test "$quiet" -eq 0 && test ! -e "$tmp/c$i.svg" \
          && grep -q "^chaplygin: plot: .*${expect#refuse }" "$tmp/err" && ok=0 ;;
    esac
    test "$ok" -eq 0 || { echo "# exit $rc"; sed 's/^/# /' "$tmp/err"; } >&2
  else
    sed 's/^/# run: /' "$tmp/run.err" >&2
  fi
  result "$ok" "$name: $expect"
done

# The cases ran in a subshell (the pipe): go on counting after them.
count=$n_cases
# A run of one row (case 1: collisions = 0) is drawn as points (pt 7,
# gnuplot's SVG marker gpPt6), not as a line of one point, which draws
# nothing and says nothing.
ok=1
test -f "$tmp/c1.svg" && grep -q "xlink:href='#gpPt6'" "$tmp/c1.svg" && ok=0
result "$ok" "a run of one row (collisions = 0) is drawn as points, not as an invisible line"
