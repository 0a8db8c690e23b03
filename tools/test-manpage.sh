#!/bin/sh
# test-manpage.sh -- TAP: the program's reference (tools/chaplygin.1.in, and
# the manual's chapter generated from it) covers what the program does:
#  1. every scene key of the scene engine (the key table of
#     lib/scene/scene.c) is a tag of SCENE FILES;
#  2. every CSV column the program writes (runs of every model with every
#     output, dense and per collision, the three sweeps, eq) is named in
#     OUTPUT or COMMANDS;
#  3. every status of the library (lib/chaplygin.h) is in STATUS CODES;
#  4. the generated chapter doc/program.texi indexes every scene key;
#  5. every subcommand of --help has its entry in COMMANDS;
#  6. every option of the --help texts (the program's, sweep's, merge's,
#     plot's, eq's) is named in the man page;
#  7. every status the sweeps print (by name) is a tag of STATUS CODES,
#     and every status of the library has its name there.
# POSIX sh.

set -u
top_builddir=${top_builddir:-.}
top_srcdir=${top_srcdir:-.}
prog=$top_builddir/tools/chaplygin
man=$top_srcdir/tools/chaplygin.1.in

. "$top_srcdir/tools/tap-lib.sh"
tap_start test-manpage 7

# section NAME: the lines of the man page's .SH NAME section.
section () {
  awk -v s="$1" '/^\.SH / { on = ($0 == ".SH " s) || ($0 == ".SH \"" s "\"") ; next } on' "$man"
}

# 1: scene keys
keys=$(grep -o '\[K_[A-Z0-9_]*\] = { SEC_[A-Z]*, "[A-Za-z0-9_]*"' "$top_srcdir/lib/scene/scene.c" | sed 's/.*"\(.*\)".*/\1/' | sort -u)
tags=$(section "SCENE FILES" | awk '/^\.TP/ { getline; print }' \
  | sed -e 's/^\.BR* //' -e 's/"//g' -e 's/\\fR//g; s/\\fB//g' | tr ', ' '\n\n')
missing=""
for k in $keys; do
  echo "$tags" | grep -qx "$k" || missing="$missing $k"
done
ok=1; test -n "$keys" && test -z "$missing" && ok=0
result "$ok" "every scene key of lib/scene/scene.c is documented${missing:+ (missing:$missing)}"

# 2: CSV columns of every kind of output
cat > "$tmp/d.ini" <<'EOF'
[scene]
model = discrete
compare = smooth
[parameters]
L0 = 1
Delta = 1/3
L = 1
[initial]
V = 1
Omega = 0.5
[run]
collisions = 2
duration = 1
outputs = E,H,theta,tau,peg,V,Omega,path,G
EOF
sed 's/^duration = 1$/duration = 1\nsamples = 2/' "$tmp/d.ini" > "$tmp/dense.ini"
cat > "$tmp/m.ini" <<'EOF'
[scene]
model = massless
[parameters]
L0 = -1/2
[initial]
V = 1
Omega = 1
[run]
collisions = 2
outputs = E,H,theta,tau,peg,V,Omega,path,G
EOF
cat > "$tmp/s4.ini" <<'EOF'
[scene]
model = discrete
[sweep]
kind = sigma4
x_min = -2
x_max = 1
nx = 3
y = 1
dir = 1
EOF
cat > "$tmp/st.ini" <<'EOF'
[scene]
model = discrete
[sweep]
kind = stability
x_min = -2
x_max = 1
nx = 3
y_min = 0
y_max = 1
ny = 2
EOF
cat > "$tmp/b.ini" <<'EOF'
[scene]
model = discrete
[parameters]
L0 = -1/2
Delta = 1
[initial]
Omega = 4/5
[run]
collisions = 100
[sweep]
kind = basins
x_min = 0.1
x_max = 0.5
nx = 3
EOF
: > "$tmp/headers"
for args in "run $tmp/d.ini" "run $tmp/dense.ini" "run --compare $tmp/d.ini" \
            "run $tmp/m.ini" "run $tmp/s4.ini" "run $tmp/st.ini" "run $tmp/b.ini" \
            "eq 3.10 L0=1 Delta=1 dir=1 --csv" "eq --list --csv"; do
  # shellcheck disable=SC2086
  run $args
  if test "$rc" -ne 0; then echo "# $args: exit $rc" >&2; echo "__failed__" >> "$tmp/headers"; fi
  head -n 1 "$tmp/out" | tr ',' '\n' >> "$tmp/headers"
  case $args in
    "run $tmp/s4.ini"|"run $tmp/b.ini") cut -d, -f5,8 "$tmp/out" \
      | sed 1d | tr ',' '\n' | grep '^[A-Z]' >> "$tmp/statuses" ;;
  esac
done
text=$( (section OUTPUT; section COMMANDS) | sed -e 's/\\://g' -e 's/\\f[BIRP]//g' -e 's/\\-/-/g')
missing=""
for col in $(sort -u "$tmp/headers"); do
  echo "$text" | grep -q -- "$col" || missing="$missing $col"
done
ok=1; test -z "$missing" && ok=0
result "$ok" "every CSV column the program writes is named in OUTPUT or COMMANDS${missing:+ (missing:$missing)}"

# 3: statuses
statuses=$(sed -n '/^enum chaplygin_status/,/^};/s/^ *\(CHAPLYGIN_[A-Z]*\) = [0-9]*.*/\1/p' "$top_srcdir/lib/chaplygin.h")
text=$(section "STATUS CODES")
missing=""
for s in $statuses; do
  echo "$text" | grep -q "^$s:" || missing="$missing $s"
done
ok=1; test -n "$statuses" && test -z "$missing" && ok=0
result "$ok" "every library status is in STATUS CODES${missing:+ (missing:$missing)}"

# 4: the generated chapter indexes every scene key
missing=""
for k in $keys; do
  grep -q "^@vindex $k (scene key)" "$top_srcdir/doc/program.texi" || missing="$missing $k"
done
ok=1; test -z "$missing" && ok=0
result "$ok" "doc/program.texi has an index entry for every scene key${missing:+ (missing:$missing)}"

# 5: subcommands
run --help
subs=$(sed -n '/^Subcommands:/,/^$/s/^  \([a-z]*\)  .*/\1/p' "$tmp/out")
text=$(section COMMANDS)
missing=""
for s in $subs; do
  echo "$text" | grep -q "^\.B $s\( \|$\)" || missing="$missing $s"
done
ok=1; test -n "$subs" && test -z "$missing" && ok=0
result "$ok" "every subcommand of --help ($(echo $subs)) has its entry in COMMANDS${missing:+ (missing:$missing)}"

# 6: options
: > "$tmp/options"
for args in "--help" "sweep --help" "merge --help" "plot --help" "eq --help"; do
  # shellcheck disable=SC2086
  run $args
  grep -o -- '--[a-zA-Z][a-zA-Z0-9-]*' "$tmp/out" | grep -vx -- '--name' >> "$tmp/options"
done
man_text=$(sed -e 's/\\-/-/g' "$man")
missing=""
for o in $(sort -u "$tmp/options"); do
  echo "$man_text" | grep -q -- "$o" || missing="$missing $o"
done
ok=1; test -s "$tmp/options" && test -z "$missing" && ok=0
result "$ok" "every option of the --help texts is in the man page${missing:+ (missing:$missing)}"

# 7: status names
tags=$(section "STATUS CODES" | awk '/^\.TP/ { getline; print $2 }')
missing=""
for st in $(sort -u "$tmp/statuses") $(echo "$statuses" | sed 's/CHAPLYGIN_//'); do
  echo "$tags" | grep -qx "$st" || missing="$missing $st"
done
ok=1; test -s "$tmp/statuses" && test -z "$missing" && ok=0
result "$ok" "every status name (the sweeps' $(sort -u "$tmp/statuses" | tr '\n' ' ')and the library's) is a tag of STATUS CODES${missing:+ (missing:$missing)}"
