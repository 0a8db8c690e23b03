#!/bin/sh
# test-plot.sh -- TAP: "chaplygin plot".  A PNG of the size of the style
# (1200 x 760, read from its IHDR chunk) for a run, a massless run and the
# three sweeps; SVG; an atlas's fate map (PNG, SVG: its key's five classes
# and its axes; every point coloured as its class in the key, as gnuplot
# computes it from the script with 'set table', failed points among them,
# on an image and on cells of one x; its row limit); the axis labels per model (in the SVG's text); a
# scene's title or file name that tries to make gnuplot run a command or
# read a file draws as text and runs nothing; the row limit and -o rules
# as for run; a missing gnuplot.  A failed write of the image never
# replaces the previous file: a full disk (a 64 KiB tmpfs, as root; else
# skipped) for PNG, SVG and -o - (exit 1), the file-size limit (ulimit
# -f), and a gnuplot that exits 0 after a truncated image or none (a
# stand-in script); gnuplot's messages shown only when it fails.
# Skipped without gnuplot (pngcairo).
# Run by `make check', or by hand:
#   top_builddir=. top_srcdir=. sh tools/test-plot.sh
# POSIX sh.

set -u
top_builddir=${top_builddir:-.}
top_srcdir=${top_srcdir:-.}
prog=${CHAPLYGIN:-$top_builddir/tools/chaplygin}

. "$top_srcdir/tools/tap-lib.sh"
tap_start test-plot 26

if ! gnuplot -e 'set terminal pngcairo' </dev/null >/dev/null 2>&1; then
  while test "$count" -lt "$plan"; do
    count=$((count + 1))
    echo "ok $count # SKIP gnuplot with pngcairo not found"
  done
  exit 0
fi

say () { echo "# $*" >&2; }
abs_prog=$(cd "$(dirname "$prog")" && pwd)/$(basename "$prog")

# png_size FILE: "WIDTH HEIGHT" from the IHDR chunk (bytes 17-24, big
# endian), or nothing if FILE does not start with the PNG signature.
png_size () {
  test "$(od -An -tx1 -N8 "$1" | tr -d ' \n')" = 89504e470d0a1a0a || return 0
  od -An -tu1 -j16 -N8 "$1" | awk '{ printf "%d %d\n",
    (($1 * 256 + $2) * 256 + $3) * 256 + $4,
    (($5 * 256 + $6) * 256 + $7) * 256 + $8 }'
}

# png_ok FILE MIN-BYTES: a 1200 x 760 PNG of at least MIN-BYTES.
png_ok () {
  test -f "$1" && test "$(png_size "$1")" = "1200 760" \
    && test "$(wc -c <"$1")" -ge "$2"
}

cat >"$tmp/fig6.ini" <<'EOF'
[scene]
model = discrete
compare = smooth
title = Fig. 6
[parameters]
L0 = 1
Delta = 1/3
L = 1
[initial]
V = 1
Omega = 0.5
[run]
collisions = 20
duration = 5.64
EOF

# ---- images -------------------------------------------------------------------
run plot "$tmp/fig6.ini" -o "$tmp/fig6.png"
ok=1
png_ok "$tmp/fig6.png" 40000 && test "$rc" -eq 0 && test ! -s "$tmp/raw" && ok=0
say "fig6.png: $(png_size "$tmp/fig6.png"), $(wc -c <"$tmp/fig6.png") bytes"
result "$ok" "a discrete run with its companion: a 1200 x 760 PNG of > 40 kB"

for f in fig2a fig2b fig3 fig4 fig10; do
  run plot "$top_srcdir/scenes/$f.ini" -o "$tmp/$f.png"
  ok=1
  test "$rc" -eq 0 && png_ok "$tmp/$f.png" 15000 && ok=0
  test "$ok" -eq 0 || sed 's/^/# /' "$tmp/err"
  result "$ok" "scenes/$f.ini: a 1200 x 760 PNG"
done

run plot "$tmp/fig6.ini" -o "$tmp/fig6.svg"
ok=1
test "$rc" -eq 0 && grep -q '<svg' "$tmp/fig6.svg" \
  && grep -q 'width="1200' "$tmp/fig6.svg" && ok=0
result "$ok" "-o FILE.svg: SVG"

# Axis labels per model: lengths in units of rho for the discrete skate,
# of the slot length for the massless one.
run plot "$top_srcdir/scenes/fig10.ini" -o - --format svg
ok=1
grep -q '>x (slot lengths)<' "$tmp/raw" && ! grep -q 'ρ' "$tmp/raw" \
  && grep -q '>x/ρ<' "$tmp/fig6.svg" && ! grep -q 'slot lengths' "$tmp/fig6.svg" \
  && ok=0
result "$ok" "axis labels: x (slot lengths) for the massless skate, x/rho for the discrete one"

(cd "$tmp" && "$abs_prog" plot fig6.ini -o - >stdout.png 2>/dev/null)
ok=1
png_ok "$tmp/stdout.png" 40000 && test ! -e "$tmp/-" && ok=0
result "$ok" "-o -: the PNG on standard output"

# ---- a scene is data, never code ----------------------------------------------
mkdir "$tmp/hostile"
cat >"$tmp/hostile/h.ini" <<'EOF'
[scene]
model = discrete
title = `touch PWNED1` system("touch PWNED2") @cmd '; system("touch PWNED3"); ' " . system("touch PWNED4") . " \n $d {/Symbol a}
[parameters]
L0 = 1
Delta = 1/3
[initial]
V = 1
Omega = 0.5
[run]
collisions = 3
EOF
# the file name as title (a scene without one)
sed '/^title/d' "$tmp/hostile/h.ini" >"$tmp/hostile/n\`touch PWNED5\`'\"@x.ini"
(cd "$tmp/hostile" && "$abs_prog" plot h.ini -o h.png 2>err1 \
   && "$abs_prog" plot "n\`touch PWNED5\`'\"@x.ini" -o n.png 2>err2) && rc=0 || rc=$?
ok=1
test "$rc" -eq 0 && png_ok "$tmp/hostile/h.png" 20000 && png_ok "$tmp/hostile/n.png" 20000 \
  && test -z "$(ls "$tmp/hostile" | grep '^PWNED')" && ok=0
test "$ok" -eq 0 || { ls "$tmp/hostile" | sed 's/^/# /'; cat "$tmp/hostile/err1" "$tmp/hostile/err2" | sed 's/^/# /'; }
result "$ok" "hostile title and file name (backquotes, system(), @macro, quotes): drawn, nothing run"

# The title is drawn as it is: in the SVG's text, with its quotes.
(cd "$tmp/hostile" && "$abs_prog" plot h.ini -o h.svg 2>/dev/null)
ok=1
grep -qF 'system("touch PWNED2") @cmd' "$tmp/hostile/h.svg" \
  && grep -q '`touch PWNED1`' "$tmp/hostile/h.svg" \
  && test -z "$(ls "$tmp/hostile" | grep '^PWNED')" && ok=0
result "$ok" "... the title appears verbatim in the figure"

# ---- an atlas: its fate map ---------------------------------------------------------
# The scene of the example (x = V, y = Omega), a smaller grid; and x = L0,
# y = V on a grid through V = 0 (its row ESTATE: failed) with few
# collisions (some points undecided).
cat >"$tmp/atlas.ini" <<'EOF'
[scene]
model = discrete
title = Fates over (V+, Omega+), L0 = -1/2, Delta = 1
[parameters]
L0 = -0.5
Delta = 1
[run]
collisions = 100000
[sweep]
kind = atlas
x = V
x_min = 0.01
x_max = 0.5
nx = 60
y = Omega
y_min = 0.1
y_max = 2
ny = 40
EOF
cat >"$tmp/atlas-fail.ini" <<'EOF'
[scene]
model = discrete
[parameters]
Delta = 1
[initial]
Omega = 0.8
[run]
collisions = 4
[sweep]
kind = atlas
x = L0
x_min = -3
x_max = 1
nx = 60
y = V
y_min = -1
y_max = 1
ny = 41
EOF
sed 's/^nx = 60$/nx = 1/' "$tmp/atlas-fail.ini" >"$tmp/atlas-col.ini"

run plot "$tmp/atlas.ini" -o "$tmp/atlas.png"
ok=1
test "$rc" -eq 0 && png_ok "$tmp/atlas.png" 10000 && test ! -s "$tmp/err" && ok=0
test "$ok" -eq 0 || sed 's/^/# /' "$tmp/err"
result "$ok" "an atlas: a 1200 x 760 PNG"

# The SVG's text: the five classes of the key (also those absent from the
# data: this atlas has forward and backward only), the axes named as the
# quantities, the title.
run plot "$tmp/atlas.ini" -o "$tmp/atlas.svg"
ok=1
if test "$rc" -eq 0 && grep -q '</svg>' "$tmp/atlas.svg"; then
  ok=0
  for t in '>forward (V\* > 0)<' '>backward (V\* &lt; 0)<' '>spin<' '>undecided<' \
           '>failed (status not SUCCESS)<' '>initial V</tspan><tspan[^>]*>+<' \
           '>initial Ω</tspan><tspan[^>]*>+<' \
           '>Fates over (V+, Omega+), L0 = -1/2, Delta = 1<'; do
    grep -q "$t" "$tmp/atlas.svg" || { say "not in the SVG: $t"; ok=1; }
  done
fi
result "$ok" "an atlas's SVG: the five classes in the key, the axes initial V+ and Omega+, the title"

# colours_check SCENE: the scene drawn through a gnuplot that keeps its
# script; that script run again with 'set table' before its plot gives
# each point's colour as gnuplot computed it (an image: red green blue;
# boxes: 0xRRGGBB), in the order of the rows of 'chaplygin run'.  Every
# point must have the colour of its class in the key (fate -1 backward,
# 0 spin, 1 forward, 2 undecided, status not SUCCESS failed), the key's
# five colours distinct, and the classes FOUND (a list) all present.
cat >"$tmp/gp-keep" <<EOF
#!/bin/sh
tee "$tmp/kept.gp" | gnuplot "\$@"
EOF
chmod +x "$tmp/gp-keep"
colours_check () {
  rm -f "$tmp/kept.gp" "$tmp/table"
  rc=0
  GNUPLOT=$tmp/gp-keep "$prog" plot "$1" -o "$tmp/c.svg" 2>"$tmp/err" || rc=$?
  test "$rc" -eq 0 || { sed 's/^/# /' "$tmp/err"; return 1; }
  sed "/^plot \\\$d/i set table '$tmp/table'" "$tmp/kept.gp" | gnuplot -d >/dev/null 2>&1
  "$prog" run "$1" 2>/dev/null | grep -v '^#' >"$tmp/rows"
  grep -o "keyentry [^,]*lc rgb '#[0-9a-f]*' title '[a-z]*" "$tmp/kept.gp" \
    | sed "s/.*'#\\([0-9a-f]*\\)' title '\\(.*\\)/\\2 \\1/" >"$tmp/key"
  awk -v found="$2" '
    FILENAME == ARGV[1] { key[$1] = $2; n_key++; next }
    FILENAME == ARGV[2] { if (FNR > 1) { nrow++; split($0, c, ",");
        cls[nrow] = c[9] != "SUCCESS" ? "failed" : c[4] == -1 ? "backward" \
          : c[4] == 0 ? "spin" : c[4] == 1 ? "forward" : c[4] == 2 ? "undecided" : "?" }
      next }
    /^# Curve/ { curve++; next }
    curve == 1 && NF >= 5 && $1 !~ /^#/ {
      np++
      col = $(NF - 1) ~ /^0x/ ? substr($(NF - 1), 3) : sprintf("%02x%02x%02x", $3, $4, $5)
      seen[cls[np]] = 1
      if (col != key[cls[np]]) { bad++; if (bad < 4) printf "# row %d (%s): colour %s, key %s\n", np, cls[np], col, key[cls[np]] }
    }
    END {
      for (a in key) for (b in key) if (a < b && key[a] == key[b]) { print "# same colour: " a ", " b; bad++ }
      if (n_key != 5) { print "# key entries: " n_key; bad++ }
      if (np != nrow || np == 0) { print "# points " np ", rows " nrow; bad++ }
      n = split(found, f, ",")
      for (i = 1; i <= n; i++) if (!seen[f[i]]) { print "# no " f[i] " point"; bad++ }
      exit bad > 0
    }' "$tmp/key" "$tmp/rows" "$tmp/table"
}

ok=0; colours_check "$tmp/atlas-fail.ini" failed,forward,backward,undecided || ok=1
result "$ok" "an atlas through V = 0 (an image): each point the key's colour of its class, failed (ESTATE) among them; five distinct colours"

ok=0; colours_check "$tmp/atlas-col.ini" failed,backward || ok=1
result "$ok" "... of one x (cells): each point the key's colour of its class, failed among them"

# ... and the cells are drawn (gnuplot's image of one column draws
# nothing, silently): filled shapes of the failed and backward colours
# beyond the key's two swatches.
ok=0
for c in failed backward; do
  fill=$(awk -v c="$c" 'function x(s) { return 16 * (index("0123456789abcdef",
      substr(s, 1, 1)) - 1) + index("0123456789abcdef", substr(s, 2, 1)) - 1 }
    $1 == c { printf "rgb(%3d, %3d, %3d)", x(substr($2, 1, 2)),
      x(substr($2, 3, 2)), x(substr($2, 5, 2)) }' "$tmp/key")
  n=$(grep -c "fill = '$fill'" "$tmp/c.svg")
  test "$n" -ge 2 || { say "$c ($fill): $n filled shapes"; ok=1; }
done
result "$ok" "... its cells drawn in the SVG, not an empty image"

run plot "$tmp/atlas.ini" -o "$tmp/atlas-big.png" --max-rows 2399
ok=1
test "$rc" -eq 2 && test ! -e "$tmp/atlas-big.png" && grep -q 'max_rows' "$tmp/err" && ok=0
result "$ok" "an atlas beyond the row limit (2400 points, --max-rows 2399): refused, no file"

# ---- bounds and files -----------------------------------------------------------
sed 's/^collisions = 20$/collisions = 1e9/' "$tmp/fig6.ini" >"$tmp/big.ini"
run plot "$tmp/big.ini" -o "$tmp/big.png"
ok=1
test "$rc" -eq 2 && test ! -e "$tmp/big.png" && grep -q 'max_rows' "$tmp/err" && ok=0
result "$ok" "a runaway scene: refused before anything is drawn, no file"

cp "$tmp/fig6.ini" "$tmp/keep.ini"
run plot "$tmp/keep.ini" -o "$tmp/keep.ini" --format png
ok=1
test "$rc" -eq 2 && cmp -s "$tmp/keep.ini" "$tmp/fig6.ini" && ok=0
result "$ok" "-o the scene: refused, the scene intact"

rm -f "$tmp/g.png"
rc=0
GNUPLOT=/nonexistent/gnuplot "$prog" plot "$tmp/fig6.ini" -o "$tmp/g.png" \
  2>"$tmp/err" || rc=$?
ok=1
test "$rc" -eq 1 && test ! -e "$tmp/g.png" && grep -q 'cannot run /nonexistent/gnuplot' "$tmp/err" \
  && test -z "$(ls -A "$tmp" | grep '^\.g\.png\.')" && ok=0
result "$ok" "GNUPLOT not a program: exit 1, no file, no temporary left"

run plot "$tmp/fig6.ini" -o "$tmp/x.pdf"
ok=1
test "$rc" -eq 2 && test ! -e "$tmp/x.pdf" && ok=0
result "$ok" "an unknown format (.pdf): exit 2"

# ---- a failed write never replaces the image ----------------------------------------
# no_temp NAME: no temporary file .NAME.XXXXXX left in $tmp/full.
no_temp () {
  test -z "$(ls -A "$tmp/full" | grep "^\.$1\.")"
}
mkdir "$tmp/full"
if mount -t tmpfs -o size=64k tmpfs "$tmp/full" 2>/dev/null; then
  trap 'umount "$tmp/full" 2>/dev/null; rm -rf "$tmp"' 0
  dd if=/dev/zero of="$tmp/full/fill" bs=1024 count=40 2>/dev/null
  ok=0
  for f in f.png f.svg; do
    echo previous >"$tmp/full/$f"
    run plot "$tmp/fig6.ini" -o "$tmp/full/$f"
    if test "$rc" -ne 1 || test "$(cat "$tmp/full/$f")" != previous || ! no_temp "$f" \
       || ! grep -q "error writing to .*$f: No space left on device" "$tmp/err"; then
      say "$f: exit $rc: $(cat "$tmp/err")"; ok=1
    fi
  done
  rc=0
  "$prog" plot "$tmp/fig6.ini" -o - >"$tmp/full/g.png" 2>"$tmp/err" || rc=$?
  test "$rc" -eq 1 && grep -q 'error writing to standard output' "$tmp/err" || ok=1
  result "$ok" "a full disk: PNG and SVG exit 1, the previous file intact, no temporary; -o - exit 1"
  umount "$tmp/full"
else
  count=$((count + 1))
  echo "ok $count # SKIP a full disk: cannot mount a tmpfs (needs root)"
fi

echo previous >"$tmp/full/l.png"
(ulimit -f 40 && "$prog" plot "$tmp/fig6.ini" -o "$tmp/full/l.png") 2>"$tmp/err" && rc=0 || rc=$?
ok=1
test "$rc" -eq 1 && test "$(cat "$tmp/full/l.png")" = previous && no_temp l.png \
  && grep -q 'File too large' "$tmp/err" && ok=0
result "$ok" "ulimit -f below the image's size: exit 1, the previous file intact, no temporary"

# Stand-ins for gnuplot that read the script and exit 0: one writes the
# first 1000 bytes of a PNG (as gnuplot does when its write fails half
# way), one nothing; one fails with a message.
cat >"$tmp/gp-cut" <<EOF
#!/bin/sh
cat >/dev/null
head -c 1000 "$tmp/fig6.png"
EOF
printf '#!/bin/sh\ncat >/dev/null\n' >"$tmp/gp-none"
printf '#!/bin/sh\ncat >/dev/null\necho "line 7: something odd" >&2\nexit 1\n' >"$tmp/gp-fail"
chmod +x "$tmp/gp-cut" "$tmp/gp-none" "$tmp/gp-fail"
for f in c1 c2 c3; do echo previous >"$tmp/full/$f.png"; done
rc=0
GNUPLOT=$tmp/gp-cut "$prog" plot "$tmp/fig6.ini" -o "$tmp/full/c1.png" 2>"$tmp/err" || rc=$?
ok=1
test "$rc" -eq 1 && test "$(cat "$tmp/full/c1.png")" = previous && no_temp c1.png \
  && grep -q "gnuplot's image is incomplete (1000 bytes" "$tmp/err" && ok=0
result "$ok" "gnuplot exits 0 after a truncated PNG: exit 1, the previous file intact"

rc=0
GNUPLOT=$tmp/gp-none "$prog" plot "$tmp/fig6.ini" -o "$tmp/full/c2.png" 2>"$tmp/err" || rc=$?
ok=1
test "$rc" -eq 1 && test "$(cat "$tmp/full/c2.png")" = previous \
  && grep -q 'gnuplot wrote no image' "$tmp/err" && ok=0
result "$ok" "gnuplot exits 0 without an image: exit 1, the previous file intact"

rc=0
GNUPLOT=$tmp/gp-fail "$prog" plot "$tmp/fig6.ini" -o "$tmp/full/c3.png" 2>"$tmp/err" || rc=$?
ok=1
test "$rc" -eq 1 && test "$(cat "$tmp/full/c3.png")" = previous \
  && grep -q '^chaplygin: plot: gnuplot failed (exit status 1); it said:$' "$tmp/err" \
  && grep -qx 'chaplygin: plot: gnuplot: line 7: something odd' "$tmp/err" && ok=0
result "$ok" "gnuplot fails: exit 1, its messages shown after the program's"

test "$count" -eq "$plan" || echo "Bail out! ran $count tests, planned $plan"
