# concordance.awk -- the generated parts of the manual's concordance, from
# one source per fact:
#   doc/concordance.tsv  label -> functions, unit tests, verification
#                        programs, errata, printed-form function, eq call
#   doc/equations.txt    label -> title, printed form, implemented form
#   doc/accuracy.texi    the oracle's tables (anchors, ordinary-set rows)
#   doc/errata.texi      the errata menu (one line per erratum)
#   tests/*.c            which file holds each Check test case
#
#   awk -v part=entries -f doc/concordance.awk FILES > concordance-entries.texi
#   awk -v part=audit   -f doc/concordance.awk FILES > audit.texi
#   awk -v part=macros  -f doc/concordance.awk FILES > concordance-macros.texi
#
# with FILES = doc/concordance.tsv doc/equations.txt doc/accuracy.texi
# doc/errata.texi tests/*.c, in any order (each is recognised by its name).
#   entries  the nodes "Concordance of Section 2" ... "Appendix B": one
#            entry per label, with an anchor "Equation 3-10" and an index
#            entry "(3.10)";
#   audit    the table of the errata chapter's "Audit of every label";
#   macros   one Texinfo macro per function of the concordance,
#            @implements_FUNCTION{}, which the function's entry in the
#            library reference calls: its index entries "(3.10)" and a
#            reference to the concordance entry.
# POSIX awk (mawk, gawk).  Any malformed input is an error (exit 1, a
# message on stderr), never a silently incomplete chapter.

function fail(msg) {
  printf "concordance.awk: %s\n", msg > "/dev/stderr"
  failed = 1
  exit 1
}

# Texinfo specials of plain text.
function texi(s) {
  gsub(/@/, "@@", s)
  gsub(/\{/, "@{", s)
  gsub(/\}/, "@}", s)
  return s
}

function basename(path,    n, parts) {
  n = split(path, parts, "/")
  return parts[n]
}

# "3.10" -> "Equation 3-10" (anchors avoid periods, which Info reserves).
function anchor(label,    a) {
  a = label
  sub(/\./, "-", a)
  return "Equation " a
}

function group_of(label) {
  if (label ~ /^2\./) return "Section 2"
  if (label ~ /^3\./) return "Section 3"
  if (label ~ /^4\./) return "Section 4"
  if (label ~ /^A\./) return "Appendix A"
  if (label ~ /^B\./) return "Appendix B"
  fail("no group for label " label)
}

function group_title(g) {
  if (g == "Section 2") return "Section 2: the smooth sleigh"
  if (g == "Section 3") return "Section 3: the discrete skate"
  if (g == "Section 4") return "Section 4: the limit Delta -> 0"
  if (g == "Appendix A") return "Appendix A: the smooth sleigh in closed form"
  return "Appendix B: the discrete skate's return map"
}

# A comma-separated list of function names as cross-references.
function function_refs(list,    n, f, i, s) {
  n = split(list, f, ",")
  s = ""
  for (i = 1; i <= n; i++)
    s = s (i > 1 ? ", " : "") "@ref{" f[i] ",,@code{" f[i] "}}"
  return s
}

function test_refs(list,    n, t, i, s) {
  n = split(list, t, ",")
  s = ""
  for (i = 1; i <= n; i++) {
    if (!(t[i] in tcase_file))
      fail("unit test " t[i] " is in no tests/*.c file")
    s = s (i > 1 ? ", " : "") "@code{" t[i] "} (@file{tests/" tcase_file[t[i]] "})"
  }
  return s
}

function verification_refs(list,    n, v, i, s) {
  if (list == "-")
    return "none yet"
  n = split(list, v, ",")
  s = ""
  for (i = 1; i <= n; i++)
    s = s (i > 1 ? ", " : "") "@file{verification/" v[i] ".c}"
  return s
}

function errata_refs(list,    n, e, i, s) {
  n = split(list, e, ",")
  s = ""
  for (i = 1; i <= n; i++) {
    if (!(e[i] in erratum_title))
      fail("erratum " e[i] " is not in the errata menu")
    s = s (i > 1 ? ", " : "") "@ref{Erratum " e[i] "}"
  }
  return s
}

function print_block(text) {
  print "@example"
  printf "%s", texi(text)
  print "@end example"
}

function print_entry(label,    impl, i, n, k) {
  if (!(label in title))
    fail("label " label " has no record in doc/equations.txt")
  print "@anchor{" anchor(label) "}"
  print "@subheading (" label ") " texi(title[label])
  print "@cindex (" label ")"
  print ""
  print "@noindent"
  print "@strong{Paper} (as transcribed):"
  print_block(printed[label])
  impl = implemented[label]
  print "@noindent"
  if (impl == "as printed\n")
    print "@strong{Implemented}: as printed."
  else {
    print "@strong{Implemented}:"
    print_block(impl)
  }
  print ""
  print "@noindent"
  print "@strong{Functions}: " function_refs(col_function[label]) "."
  print "@strong{Unit test}: " test_refs(col_test[label]) "."
  print "@strong{Verification}: " verification_refs(col_verification[label]) "."
  print ""
  print "@noindent"
  printf "@strong{Errata}: "
  if (col_erratum[label] == "-")
    print "none; confirmed as printed."
  else {
    printf "%s", errata_refs(col_erratum[label])
    if (col_printed[label] == "same")
      printf "; the printed form has the same value wherever the equation applies"
    else if (col_printed[label] == "none")
      printf "; the printed form cannot be evaluated (garbled, or not given)"
    else
      printf "; the printed form is evaluated by %s", function_refs(col_printed[label])
    print "."
  }
  print ""
  print "@noindent"
  n = n_acc[label]
  if (n == 0)
    print "@strong{Accuracy}: not in the accuracy tables; the unit test compares with a reference computed by another route."
  else {
    printf "@strong{Accuracy}, against the Arb oracle on its ordinary data set:"
    for (k = 1; k <= n; k++) {
      i = acc_of[label, k]
      printf " %s at most %s ulps, mean %s, %s points (@pxref{%s})%s", acc_quantity[i], \
        acc_max[i], acc_mean[i], acc_points[i], acc_anchor[i], (k < n ? ";" : ".\n")
    }
  }
  print ""
  print "@noindent"
  print "@strong{Evaluate}:"
  print "@example"
  print "chaplygin eq " label " " texi(col_eq[label])
  print "@end example"
  print ""
}

# ---- reading ------------------------------------------------------------

FNR == 1 { file = basename(FILENAME); eqs_state = "" }

file == "concordance.tsv" {
  if (FNR == 1) {
    if ($0 != "equation\tfunction\tunit_test\tverification\terratum\tprinted_function\teq")
      fail("concordance.tsv: unexpected header " $0)
    next
  }
  if (split($0, c, "\t") != 7)
    fail("concordance.tsv line " FNR ": not 7 fields")
  n_labels++
  labels[n_labels] = c[1]
  col_function[c[1]] = c[2]
  col_test[c[1]] = c[3]
  col_verification[c[1]] = c[4]
  col_erratum[c[1]] = c[5]
  col_printed[c[1]] = c[6]
  if ((c[5] == "-") != (c[6] == "-"))
    fail("concordance.tsv line " FNR ": printed_function must be - exactly when erratum is -")
  col_eq[c[1]] = c[7]
  next
}

file == "equations.txt" {
  if ($0 ~ /^#/ || $0 ~ /^[ \t]*$/)
    next
  if ($0 ~ /^@ /) { cur = substr($0, 3); eqs_state = ""; next }
  if ($0 ~ /^title: /) { title[cur] = substr($0, 8); next }
  if ($0 == "printed:") { eqs_state = "printed"; printed[cur] = ""; next }
  if ($0 == "implemented:") { eqs_state = "implemented"; implemented[cur] = ""; next }
  if ($0 ~ /^    / && eqs_state == "printed") { printed[cur] = printed[cur] substr($0, 5) "\n"; next }
  if ($0 ~ /^    / && eqs_state == "implemented") { implemented[cur] = implemented[cur] substr($0, 5) "\n"; next }
  fail("equations.txt line " FNR ": unexpected: " $0)
}

file == "accuracy.texi" {
  if ($0 ~ /^@anchor\{Accuracy /) {
    acc_pending = substr($0, 9, length($0) - 9)
    next
  }
  if ($0 ~ /^@subheading \(/ && acc_pending != "") {
    n_acc_tables++
    acc_anchor[n_acc_tables] = acc_pending
    acc_pending = ""
    head = substr($0, 13)
    split(head, hp, "): ")
    lbls = substr(hp[1], 2)
    q = substr(head, length(hp[1]) + 4)
    sub(/, @code\{.*$/, "", q)
    acc_quantity[n_acc_tables] = q
    nl = split(lbls, ll, "\\)/\\(")
    for (k = 1; k <= nl; k++)
      acc_of[ll[k], ++n_acc[ll[k]]] = n_acc_tables
    in_table = n_acc_tables
    next
  }
  if (in_table && $0 ~ /^@item ordinary @tab /) {
    split($0, cells, " @tab ")
    acc_points[in_table] = cells[2]
    acc_max[in_table] = cells[3]
    acc_mean[in_table] = cells[4]
    in_table = 0
    next
  }
  next
}

file == "errata.texi" {
  if ($0 ~ /^\* Erratum E[0-9]+:: /) {
    id = $3
    sub(/::$/, "", id)
    t = $0
    sub(/^\* Erratum E[0-9]+:: +/, "", t)
    erratum_title[id] = t
  }
  next
}

file ~ /\.c$/ {
  line = $0
  if (match(line, /tcase_create *\( *"[^"]*"/) || match(line, /add *\( *s *, *"[^"]*"/)) {
    s = substr(line, RSTART, RLENGTH)
    sub(/^[^"]*"/, "", s)
    sub(/"$/, "", s)
    tcase_file[s] = file
  }
  next
}

# ---- writing ------------------------------------------------------------

END {
  if (failed)
    exit 1
  if (n_labels != 43)
    fail("concordance.tsv has " n_labels " labels, not 43")
  print "@c Generated by doc/concordance.awk (part " part ") from doc/concordance.tsv,"
  print "@c doc/equations.txt, doc/accuracy.texi, doc/errata.texi, tests/*.c: do not edit."
  print ""
  if (part == "entries") {
    g = ""
    for (i = 1; i <= n_labels; i++) {
      if (group_of(labels[i]) != g) {
        g = group_of(labels[i])
        print "@node Concordance of " g
        print "@section " texi(group_title(g))
        print ""
      }
      print_entry(labels[i])
    }
  } else if (part == "audit") {
    print "@multitable @columnfractions .1 .45 .45"
    print "@headitem Label @tab Outcome @tab Functions"
    for (i = 1; i <= n_labels; i++) {
      l = labels[i]
      out = "confirmed"
      if (col_erratum[l] != "-") {
        n = split(col_erratum[l], e, ",")
        out = ""
        for (k = 1; k <= n; k++)
          out = out (k > 1 ? "; " : "") "@ref{Erratum " e[k] "}: " texi(erratum_summary(e[k]))
      }
      nf = split(col_function[l], f, ",")
      fs = ""
      for (k = 1; k <= nf; k++)
        fs = fs (k > 1 ? ", " : "") "@code{" f[k] "}"
      print "@item @ref{" anchor(l) ",,(" l ")} @tab " out " @tab " fs
    }
    print "@end multitable"
  } else if (part == "macros") {
    for (i = 1; i <= n_labels; i++) {
      l = labels[i]
      nf = split(col_function[l], f, ",")
      for (k = 1; k <= nf; k++)
        implements[f[k]] = implements[f[k]] " " l
      if (col_printed[l] != "-" && col_printed[l] != "same" && col_printed[l] != "none") {
        nf = split(col_printed[l], f, ",")
        for (k = 1; k <= nf; k++)
          prints[f[k]] = prints[f[k]] " " l
      }
    }
    # In the order of first appearance (a reproducible file).
    for (i = 1; i <= n_labels; i++) {
      l = labels[i]
      nf = split(col_function[l], f, ",")
      for (k = 1; k <= nf; k++)
        if (!(f[k] in done)) { done[f[k]] = 1; macro(f[k], implements[f[k]], "Implements") }
      if (l in col_printed && col_printed[l] != "-" && col_printed[l] != "same" && col_printed[l] != "none") {
        nf = split(col_printed[l], f, ",")
        for (k = 1; k <= nf; k++)
          if (!(f[k] in done)) { done[f[k]] = 1; macro(f[k], prints[f[k]], "Evaluates the paper's printed form of") }
      }
    }
  } else
    fail("part must be entries, audit or macros, not '" part "'")
}

# An erratum's menu description without its leading "(2.1): " label.
function erratum_summary(id,    t) {
  t = erratum_title[id]
  sub(/^\([^)]*\)(, \([^)]*\))*(--\([^)]*\))?: /, "", t)
  return t
}

# The macro of function FN for the labels LIST (" 3.11 3.12").
function macro(fn, list, verb,    n, l, k, s) {
  n = split(list, l, " ")
  print "@macro implements_" fn
  for (k = 1; k <= n; k++)
    print "@cindex (" l[k] ")"
  s = verb
  for (k = 1; k <= n; k++)
    s = s (k == 1 ? " " : (k == n ? " and " : ", ")) "(" l[k] ") (@pxref{" anchor(l[k]) "})"
  print s "."
  print "@end macro"
  print ""
}
