#!/usr/bin/perl
# labels.pl -- read the registry of the paper's equation labels
# (lib/labels.txt, whose header documents its format; its syntax read by
# lib/Registry.pm, as every registry's) and write what is generated from
# it.
#
#   perl lib/labels.pl [-o OUT] MODE lib/labels.txt [FILES...]
#
# MODE:
#   list     the labels, one a line, in the registry's (the paper's) order;
#   tsv      doc/concordance.tsv: the header line
#            equation function unit_test verification erratum
#            printed_function eq (tab-separated), then one row a label,
#            lists comma-separated;
#   entries  the nodes "Concordance of Section 2" ... "Appendix B" of the
#            manual: one entry a label, with an anchor "Equation 3-10" and
#            an index entry "(3.10)";
#   audit    the table of the errata chapter's "Audit of every label";
#   macros   the flag labelcount (@set labelcount N: the number of
#            labels, for the manual's text) and one Texinfo macro a
#            function of the registry, @implementsFunction{} (TexinfoName.pm), which the
#            function's entry in the library reference calls: its index
#            entries "(3.10)" and a reference to the concordance entry;
#   field NAME
#            for a one-line field NAME (any, also an eq.* or tex.* one):
#            LABEL<TAB>VALUE a line, for the labels that have it;
#   check    read and check the registry only (exit status 0 or 1).
# FILES (entries and audit; recognised by their names, in any order):
#   doc/accuracy.texi  the oracle's tables (anchors, ordinary-set rows);
#   doc/errata.texi    the errata menu (one line per erratum);
#   tests/*.c          which file holds each Check test case.
# With -o OUT the output is written to a temporary file beside OUT and
# renamed to OUT once complete: a failure leaves no file behind (and OUT,
# if it exists, untouched).  Any malformed input is an error (exit 1, a
# message on stderr naming the file and line), never a silently
# incomplete output.  Perl 5 core only.

use strict;
use warnings;
use File::Basename qw(basename);
use FindBin;
use lib $FindBin::Bin;
use TexinfoName qw(implements_macro);
use TexinfoMath qw(display_texi display_errors);
use Registry qw(read_registry list_names write_output on_error);

my $me = 'labels.pl';
on_error($me);
sub fail { die "$_[0]\n" }

# ---- the registry --------------------------------------------------------

# The fields lib/labels.pl knows, in the order the records keep them; all
# are required.  The kinds: text (one line), list, block.
my @FIELDS = (
  [ 'title', 'text' ], [ 'functions', 'list' ], [ 'tests', 'list' ],
  [ 'verification', 'list' ], [ 'errata', 'list' ],
  [ 'printed_function', 'text' ], [ 'eq.inputs', 'text' ],
  [ 'eq.outputs', 'text' ], [ 'eq.paper', 'text' ],
  [ 'eq.example', 'text' ], [ 'printed', 'block' ],
  [ 'implemented', 'block' ], [ 'tex.printed', 'block' ],
);
# Required unless the implemented form is 'as printed'.
my %KIND = ((map { $_->[0] => $_->[1] } @FIELDS), 'tex.implemented' => 'block');
# Namespaces of fields other consumers read (see the registry's header).
my $FOREIGN = qr/^(?:eq|tex)\.[a-z0-9_.]+$/;

# Reads the registry FILE (lib/Registry.pm: the syntax) and checks its
# records: a list of records {label, line, fields => {}, at => {}}, in
# the file's order.  Every rule of the header is enforced here.
sub read_labels {
  my ($file) = @_;
  # Registry.pm dies "FILE:LINE: message"; the __DIE__ handler fails so.
  my @recs = read_registry($file, key => 'label',
    id => qr/^(?:[1-9][0-9]*|[A-Z])\.[1-9][0-9]*\z/,
    id_what => 'a label such as 3.10 or B.2', kinds => \%KIND,
    foreign => $FOREIGN);
  check_record($file, $_) for @recs;
  check_tex($file, $_) for @recs;
  return @recs;
}

# The TeX forms of a record (tex.printed, and tex.implemented unless the
# implemented form is 'as printed'): lib/TexinfoMath.pm's
# display_errors (well-formed, the plain form's symbols).
sub check_tex {
  my ($file, $r) = @_;
  my $f = $r->{fields};
  if ($f->{implemented} eq "as printed\n") {
    fail("$file:$r->{at}{'tex.implemented'}: ($r->{label}) tex.implemented with an implemented form 'as printed'")
      if defined $f->{'tex.implemented'};
  } else {
    fail("$file:$r->{line}: ($r->{label}) no field 'tex.implemented' (its implemented form is not 'as printed')")
      unless defined $f->{'tex.implemented'};
  }
  for my $kind (qw(printed implemented)) {
    my $tex = $f->{"tex.$kind"};
    next unless defined $tex;
    for (display_errors($f->{$kind}, $tex)) {
      my $n = $r->{at}{"tex.$kind"};
      $n += $1 if s/^line ([0-9]+): //;
      fail("$file:$n: ($r->{label}) tex.$kind: " . (s/^symbols: /$kind and tex.$kind differ in their symbols: /r));
    }
  }
}

# A LIST field's names (an empty list for '-').
sub names { return list_names($_[0]); }

sub check_record {
  my ($file, $r) = @_;
  my $f = $r->{fields};
  my $at = "$file:$r->{line}: ($r->{label})";
  for my $spec (@FIELDS) {
    fail("$at: no field '$spec->[0]'") unless exists $f->{$spec->[0]};
  }
  for my $name (grep { $KIND{$_} eq 'list' } keys %KIND) {
    my $v = $f->{$name};
    fail("$at: $name '$v' is not '-' or names separated by ', '")
      unless $v eq '-' || $v =~ /^[A-Za-z0-9_]+(?:, [A-Za-z0-9_]+)*\z/;
    my %dup;
    for (names($v)) { fail("$at: $name lists $_ twice") if $dup{$_}++; }
  }
  my @fn = names($f->{functions});
  fail("$at: functions is empty") unless @fn;
  for (@fn) { fail("$at: function $_ is not chaplygin_*") unless /^chaplygin_/; }
  (my $tcase = "eq_$r->{label}") =~ s/\./_/;
  fail("$at: tests must start with the label's own test case $tcase")
    unless ((names($f->{tests}))[0] // '') eq $tcase;
  for (names($f->{errata})) { fail("$at: erratum '$_' is not E<number>") unless /^E[1-9][0-9]*\z/; }
  my $pf = $f->{printed_function};
  if ($f->{errata} eq '-') {
    fail("$at: printed_function must be '-' when errata is '-'") unless $pf eq '-';
    fail("$at: eq.paper must be 'confirmed as printed' when errata is '-'")
      unless $f->{'eq.paper'} eq 'confirmed as printed';
  } else {
    fail("$at: printed_function '-' with errata $f->{errata}") if $pf eq '-';
    unless ($pf eq 'same' || $pf eq 'none') {
      fail("$at: printed_function '$pf' is not same, none or chaplygin_printed_* names")
        unless $pf =~ /^chaplygin_printed_[a-z0-9_]+(?:, chaplygin_printed_[a-z0-9_]+)*\z/;
    }
    for (names($f->{errata})) {
      fail("$at: eq.paper does not name erratum $_") unless $f->{'eq.paper'} =~ /\b$_\b/;
    }
  }
  for (qw(title eq.inputs eq.outputs eq.paper eq.example)) {
    fail("$at: $_ is empty") if $f->{$_} eq '';
  }
  fail("$at: no eq.certified (every label has a certified evaluation)")
    unless defined $f->{'eq.certified'};
  fail("$at: eq.certified '$f->{'eq.certified'}' is not chaplygin_certified_* names separated by ', '")
    if $f->{'eq.certified'} !~ /^chaplygin_certified_[a-z0-9_]+(?:, chaplygin_certified_[a-z0-9_]+)*\z/;
}

# ---- the other sources -----------------------------------------------------

my (%tcase_file, %erratum_title, @acc, %acc_of, %have);

sub read_other {
  my ($path) = @_;
  my $file = basename($path);
  open my $fh, '<', $path or fail("$path: $!");
  if ($file eq 'accuracy.texi') {
    $have{accuracy} = 1;
    my ($pending, $in) = ('', undef);
    while (<$fh>) {
      chomp;
      if (/^\@anchor\{(Accuracy [^}]*)\}\z/) { $pending = $1; next; }
      if ($pending ne '' && /^\@subheading \((.*?)\): (.*)\z/) {
        my ($lbls, $q) = ($1, $2);
        $q =~ s/, \@code\{.*\z//;
        push @acc, { anchor => $pending, quantity => $q };
        $pending = '';
        $in = $#acc;
        push @{ $acc_of{$_} }, $in for split /\)\/\(/, $lbls;
        next;
      }
      if (defined $in && /^\@item ordinary \@tab /) {
        my @c = split / \@tab /, $_;
        @{ $acc[$in] }{qw(points max mean)} = @c[1 .. 3];
        undef $in;
      }
    }
    for (@acc) { fail("$path: table '$_->{anchor}' has no ordinary row") unless defined $_->{points}; }
  } elsif ($file eq 'errata.texi') {
    $have{errata} = 1;
    while (<$fh>) {
      chomp;
      $erratum_title{$1} = $2 if /^\* Erratum (E[0-9]+):: +(.*)\z/;
    }
  } elsif ($file =~ /\.c\z/) {
    $have{tests} = 1;
    while (<$fh>) {
      if (/tcase_create *\( *"([^"]*)"/ || /add *\( *s *, *"([^"]*)"/) {
        $tcase_file{$1} = $file;
      }
    }
  } else {
    fail("$path: not doc/accuracy.texi, doc/errata.texi or a tests/*.c file");
  }
  close $fh;
}

# ---- Texinfo -----------------------------------------------------------------

sub texi {
  my ($s) = @_;
  $s =~ s/([\@{}])/\@$1/g;
  return $s;
}

# "3.10" -> "Equation 3-10" (anchors avoid periods, which Info reserves).
sub anchor { my $a = shift; $a =~ s/\./-/; return "Equation $a"; }

my %GROUP_TITLE = (
  'Section 2'  => 'Section 2: the smooth sleigh',
  'Section 3'  => 'Section 3: the discrete skate',
  'Section 4'  => 'Section 4: the limit Delta -> 0',
  'Appendix A' => 'Appendix A: the smooth sleigh in closed form',
  'Appendix B' => "Appendix B: the discrete skate's return map",
);

sub group_of {
  my ($label) = @_;
  return "Section $1" if $label =~ /^([234])\./;
  return "Appendix $1" if $label =~ /^([AB])\./;
  fail("no concordance node for label $label (lib/labels.pl's groups)");
}

sub function_refs { join ', ', map { "\@ref{$_,,\@code{$_}}" } @_ }

sub test_refs {
  join ', ', map {
    fail("unit test $_ is in no tests/*.c file") unless exists $tcase_file{$_};
    "\@code{$_} (\@file{tests/$tcase_file{$_}})"
  } @_;
}

sub verification_refs {
  return 'none yet' unless @_;
  return join ', ', map { "\@file{verification/$_.c}" } @_;
}

sub erratum_known {
  fail("erratum $_[0] is not in the errata menu of doc/errata.texi")
    unless exists $erratum_title{ $_[0] };
}

sub errata_refs { join ', ', map { erratum_known($_); "\@ref{Erratum $_}" } @_ }

# An erratum's menu description without its leading "(2.1): " label.
sub erratum_summary {
  my ($id) = @_;
  erratum_known($id);
  (my $t = $erratum_title{$id}) =~ s/^\([^)]*\)(?:, \([^)]*\))*(?:--\([^)]*\))?: //;
  return $t;
}


# A form of the equation: its plain form, and its TeX form displayed
# (lib/TexinfoMath.pm's display_texi).
sub form_block { return display_texi($_[0], $_[1]); }

sub entry {
  my ($r) = @_;
  my ($l, $f) = ($r->{label}, $r->{fields});
  my $s = '';
  $s .= "\@anchor{" . anchor($l) . "}\n";
  $s .= "\@subheading ($l) " . texi($f->{title}) . "\n";
  $s .= "\@cindex ($l)\n\n";
  $s .= "\@noindent\n\@strong{Paper} (as transcribed):\n" . form_block($f->{printed}, $f->{'tex.printed'});
  $s .= "\@noindent\n";
  if ($f->{implemented} eq "as printed\n") {
    $s .= "\@strong{Implemented}: as printed.\n";
  } else {
    $s .= "\@strong{Implemented}:\n" . form_block($f->{implemented}, $f->{'tex.implemented'});
  }
  $s .= "\n\@noindent\n";
  $s .= "\@strong{Functions}: " . function_refs(names($f->{functions})) . ".\n";
  $s .= "\@strong{Unit test}: " . test_refs(names($f->{tests})) . ".\n";
  $s .= "\@strong{Verification}: " . verification_refs(names($f->{verification})) . ".\n";
  $s .= "\n\@noindent\n\@strong{Errata}: ";
  if ($f->{errata} eq '-') {
    $s .= "none; confirmed as printed.\n";
  } else {
    $s .= errata_refs(names($f->{errata}));
    my $pf = $f->{printed_function};
    if ($pf eq 'same') {
      $s .= "; the printed form has the same value wherever the equation applies";
    } elsif ($pf eq 'none') {
      $s .= "; the printed form cannot be evaluated (garbled, or not given)";
    } else {
      $s .= "; the printed form is evaluated by " . function_refs(names($pf));
    }
    $s .= ".\n";
  }
  $s .= "\n\@noindent\n";
  my @t = @{ $acc_of{$l} // [] };
  if (!@t) {
    $s .= "\@strong{Accuracy}: not in the accuracy tables; the unit test compares with a reference computed by another route.\n";
  } else {
    $s .= "\@strong{Accuracy}, against the Arb oracle on its ordinary data set:";
    $s .= join ';', map {
      my $a = $acc[$_];
      " $a->{quantity} at most $a->{max} ulps, mean $a->{mean}, $a->{points} points (\@pxref{$a->{anchor}})"
    } @t;
    $s .= ".\n";
  }
  $s .= "\n\@noindent\n\@strong{Evaluate}:\n\@example\n";
  $s .= "chaplygin eq $l " . texi($f->{'eq.example'}) . "\n\@end example\n\n";
  return $s;
}

sub printed_functions {
  my ($pf) = @_;
  return () if $pf eq '-' || $pf eq 'same' || $pf eq 'none';
  return names($pf);
}

# The macro of function FN for the labels LABELS.
sub macro {
  my ($fn, $verb, @labels) = @_;
  my $s = "\@macro " . implements_macro ($fn) . "\n";
  $s .= "\@cindex ($_)\n" for @labels;
  my $n = @labels;
  $s .= $verb;
  for my $k (0 .. $n - 1) {
    $s .= ($k == 0 ? ' ' : $k == $n - 1 ? ' and ' : ', ')
      . "($labels[$k]) (\@pxref{" . anchor($labels[$k]) . "})";
  }
  return "$s.\n\@end macro\n\n";
}

# ---- the evaluators of `chaplygin eq' (modes c and h) ----------------------------

# The C string literal of TEXT.
sub cstr { my $t = shift; $t =~ s/([\\"])/\\$1/g; return "\"$t\""; }

# The C name of a label's evaluator: eq_3_10; of its certified one
# (eq.certified, lib/scene/eq-certified.c): eq_cert_3_10.
sub evaluator { my $l = shift; $l =~ tr/./_/; return "eq_$l"; }
sub cert_evaluator { my $l = shift; $l =~ tr/./_/; return "eq_cert_$l"; }

# The call of an eq.eval or eq.printed field VALUE of REC: (function,
# [args]), each arg a hash {kind, name, default, lo, hi, literal}.  The
# forms (lib/labels.txt's header): real NAME, real NAME=DEFAULT, dir NAME,
# dir NAME=DEFAULT, count NAME, out real NAME, out int NAME, and a literal
# (a number or NULL); in eq.printed, NAME (an input of eq.eval) and out
# NAME (the output whose printed value it gives).
sub parse_call {
  my ($rec, $name, $value) = @_;
  my $where = "($rec->{label}) $name";
  $value =~ /^(chaplygin_[a-z0-9_]+) \((.*)\)\z/
    or fail("$where: not 'chaplygin_FUNCTION (ARG, ...)': $value");
  my ($fn, @args) = ($1, split /, /, $2);
  my @out;
  for (@args) {
    if (/^(real|dir) ([A-Za-z][A-Za-z0-9_]*)(?:=(-?[0-9.]+))?\z/) {
      push @out, { kind => $1, name => $2, default => $3 };
    } elsif (/^count ([A-Za-z][A-Za-z0-9_]*)\z/) {
      push @out, { kind => 'count', name => $1 };
    } elsif (/^out (real|int) ([A-Za-z][A-Za-z0-9_]*)\z/) {
      push @out, { kind => "out_$1", name => $2 };
    } elsif (/^out ([A-Za-z][A-Za-z0-9_]*)\z/) {
      push @out, { kind => 'printed', name => $1 };
    } elsif (/^(?:[-+]?[0-9]+|NULL)\z/) {
      push @out, { kind => 'literal', literal => $_ };
    } elsif (/^([A-Za-z][A-Za-z0-9_]*)\z/ && $name eq 'eq.printed') {
      push @out, { kind => 'name', name => $1 };
    } else {
      fail("$where: argument '$_' is not one of the forms of lib/labels.txt");
    }
  }
  return ($fn, \@out);
}

# The evaluator of REC generated from its eq.eval (and eq.printed).
sub c_evaluator {
  my ($rec) = @_;
  my $f = $rec->{fields};
  my ($fn, $args) = parse_call($rec, 'eq.eval', $f->{'eq.eval'});
  my (@decl, @read, @call, @put, %seen);
  for my $a (@$args) {
    my $n = $a->{name};
    if (defined $n) {
      fail("($rec->{label}) eq.eval: '$n' twice") if $seen{$n}++;
      fail("($rec->{label}) eq.eval: '$n' is not among eq.inputs or eq.outputs")
        unless index(" $f->{'eq.inputs'} $f->{'eq.outputs'} ", $n) >= 0;
    }
    my $k = $a->{kind};
    if ($k eq 'literal') { push @call, $a->{literal}; next; }
    if ($k eq 'real') {
      push @decl, "double $n;";
      push @read, defined $a->{default}
        ? "eq_real_opt (c, \"$n\", $a->{default}, &$n)" : "eq_real_in (c, \"$n\", &$n)";
      push @call, $n;
    } elsif ($k eq 'dir') {
      push @decl, "int $n;";
      push @read, defined $a->{default}
        ? "eq_dir_opt (c, \"$n\", $a->{default}, &$n)" : "eq_dir_in (c, \"$n\", &$n)";
      push @call, $n;
    } elsif ($k eq 'count') {
      push @decl, "long $n;";
      push @read, "eq_int_in (c, \"$n\", 0, LONG_MAX, &$n)";
      push @call, "(unsigned long) $n";
    } elsif ($k eq 'out_real') {
      push @decl, "double $n;";
      push @call, "&$n";
      push @put, "eq_put_real (c, \"$n\", $n, fn, EQ_FORMULA);";
    } elsif ($k eq 'out_int') {
      push @decl, "int $n;";
      push @call, "&$n";
      push @put, "eq_put_int (c, \"$n\", $n, fn, \"exact\");";
    } else {
      fail("($rec->{label}) eq.eval: 'out $n' belongs in eq.printed");
    }
  }
  my $c = "/* ($rec->{label}) " . $f->{title} . " */\nstatic int\n"
    . evaluator($rec->{label}) . " (eq_ctx *c)\n{\n"
    . "  static const char fn[] = \"$fn\";\n";
  $c .= "  $_\n" for @decl;
  $c .= "\n  if (" . join ("\n      || ", @read,
                           "eq_lib (c, fn, $fn (" . join(', ', @call) . "))")
    . ")\n    return -1;\n";
  $c .= "  $_\n" for @put;
  $c .= printed_call($rec, $args) if defined $f->{'eq.printed'};
  return $c . "  return 0;\n}\n\n";
}

# The call of REC's printed form (eq.printed) after its evaluation ARGS:
# the inputs as read, its output into a variable of its own, recorded as
# the printed value of the output it names, with the label's erratum.
sub printed_call {
  my ($rec, $args) = @_;
  my $f = $rec->{fields};
  my ($pfn, $pargs) = parse_call($rec, 'eq.printed', $f->{'eq.printed'});
  my %type = map { defined $_->{name} ? ($_->{name} => $_->{kind}) : () } @$args;
  my @errata = names($f->{errata});
  fail("($rec->{label}) eq.printed without one erratum") unless @errata == 1;
  fail("($rec->{label}) eq.printed: $pfn is not its printed_function")
    unless grep { $_ eq $pfn } printed_functions($f->{printed_function});
  my (@call, $out, $ctype);
  for my $a (@$pargs) {
    if ($a->{kind} eq 'literal') { push @call, $a->{literal}; next; }
    my $t = $type{$a->{name} // ''} // '';
    if ($a->{kind} eq 'printed' && $t =~ /^out_(real|int)\z/ && !defined $out) {
      ($out, $ctype) = ($a->{name}, $1);
      push @call, "&printed";
    } elsif ($a->{kind} eq 'name' && $t =~ /^(?:real|dir)\z/) {
      push @call, $a->{name};
    } else {
      fail("($rec->{label}) eq.printed: argument '" . ($a->{name} // '?')
           . "' is not an input or an output of eq.eval");
    }
  }
  fail("($rec->{label}) eq.printed: no 'out NAME'") unless defined $out;
  return "  " . ($ctype eq 'real' ? 'double' : 'int') . " printed;\n"
    . "  int st = $pfn (" . join(', ', @call) . ");\n"
    . "  eq_printed_$ctype (c, \"$out\", st, printed, \"$errata[0]\",\n"
    . "                   \"$pfn\");\n";
}

# ---- main ----------------------------------------------------------------------

my $out;
if (@ARGV >= 2 && $ARGV[0] eq '-o') { (undef, $out) = splice @ARGV, 0, 2; }
my $mode = shift @ARGV // '';
my $field;
$field = shift @ARGV if $mode eq 'field';
my $registry = shift @ARGV;
fail("usage: $me [-o OUT] list|tsv|entries|audit|macros|c|h|check|field NAME REGISTRY [FILES...]")
  unless defined $registry && $mode =~ /^(?:list|tsv|entries|audit|macros|c|h|check|field)\z/;
my @recs = read_labels($registry);
read_other($_) for @ARGV;
if ($mode eq 'entries') {
  for (qw(accuracy errata tests)) { fail("entries: give doc/accuracy.texi, doc/errata.texi and tests/*.c") unless $have{$_}; }
} elsif ($mode eq 'audit') {
  fail("audit: give doc/errata.texi") unless $have{errata};
} elsif (@ARGV) {
  fail("$mode reads the registry only");
}

my $text = '';
my $gen = "Generated by lib/labels.pl (mode $mode) from lib/labels.txt";
my $texi_head = sub {
  my ($from) = @_;
  return "\@c $gen" . ($from ? ",\n\@c $from" : '') . ": do not edit.\n\n";
};
if ($mode eq 'list') {
  $text = join '', map { "$_->{label}\n" } @recs;
} elsif ($mode eq 'check') {
  $text = '';
} elsif ($mode eq 'field') {
  fail("field $field is a block, not one line") if ($KIND{$field} // '') eq 'block';
  for (@recs) {
    my $v = $_->{fields}{$field};
    next unless defined $v;
    fail("field $field of ($_->{label}) is a block, not one line") if $v =~ /\n/;
    $text .= "$_->{label}\t$v\n";
  }
} elsif ($mode eq 'tsv') {
  $text = "equation\tfunction\tunit_test\tverification\terratum\tprinted_function\teq\n";
  for (@recs) {
    my $f = $_->{fields};
    $text .= join("\t", $_->{label},
                  map({ my @n = names($f->{$_}); @n ? join(',', @n) : '-' }
                      qw(functions tests verification errata)),
                  join(',', split /, /, $f->{printed_function}), $f->{'eq.example'}) . "\n";
  }
} elsif ($mode eq 'entries') {
  $text = $texi_head->('doc/accuracy.texi, doc/errata.texi, tests/*.c');
  my ($g, %done) = ('');
  for (@recs) {
    my $h = group_of($_->{label});
    if ($h ne $g) {
      fail("($_->{label}): the labels of $h are not together") if $done{$h}++;
      $g = $h;
      $text .= "\@node Concordance of $g\n\@section " . texi($GROUP_TITLE{$g}) . "\n\n";
    }
    $text .= entry($_);
  }
} elsif ($mode eq 'audit') {
  $text = $texi_head->('doc/errata.texi');
  $text .= "\@multitable \@columnfractions .1 .45 .45\n\@headitem Label \@tab Outcome \@tab Functions\n";
  for (@recs) {
    my ($l, $f) = ($_->{label}, $_->{fields});
    my $o = $f->{errata} eq '-' ? 'confirmed'
      : join '; ', map { "\@ref{Erratum $_}: " . texi(erratum_summary($_)) } names($f->{errata});
    $text .= "\@item \@ref{" . anchor($l) . ",,($l)} \@tab $o \@tab "
      . join(', ', map { "\@code{$_}" } names($f->{functions})) . "\n";
  }
  $text .= "\@end multitable\n";
} elsif ($mode eq 'c') {
  $text = "/* eq-table.c -- $gen: do not edit.\n"
    . "   The paper's labels as `chaplygin eq' and chaplygin.eq show them, each\n"
    . "   with its evaluator: generated here from its eq.eval (a label whose\n"
    . "   inputs map to one call), else lib/scene/eq-eval.c's; and the\n"
    . "   certified one of a label with eq.certified (lib/scene/eq-certified.c,\n"
    . "   where the library has the certified method: HAVE_ARB). */\n"
    . "#include <config.h>\n\n#include <limits.h>\n#include <stddef.h>\n\n"
    . "#include \"chaplygin.h\"\n#include \"eq.h\"\n"
    . "#include \"eq-evaluators.h\"\n\n";
  for (@recs) { $text .= c_evaluator($_) if defined $_->{fields}{'eq.eval'}; }
  $text .= "const eq_label eq_labels[] = {\n";
  for (@recs) {
    my ($l, $f) = ($_->{label}, $_->{fields});
    my @e = names($f->{errata});
    $text .= "  { { " . join(",\n      ", map { cstr($_) }
        $l, $f->{title}, $f->{'eq.inputs'}, $f->{'eq.outputs'},
        join(', ', names($f->{functions})), @e ? join(' ', @e) : '-',
        $f->{'eq.paper'}, $f->{'eq.example'})
        . ",\n      " . (defined $f->{'eq.certified'} ? cstr($f->{'eq.certified'}) : 'NULL')
        . " },\n    " . evaluator($l) . ",\n    "
        . (defined $f->{'eq.degrees'} ? cstr($f->{'eq.degrees'}) : 'NULL') . ",\n    "
        . (defined $f->{'eq.certified'}
           ? "\n#if HAVE_ARB\n    " . cert_evaluator($l) . "\n#else\n    NULL\n#endif\n"
           : 'NULL') . " },\n";
  }
  $text .= "};\n\nconst size_t eq_n_labels = sizeof eq_labels / sizeof eq_labels[0];\n";
} elsif ($mode eq 'h') {
  $text = "/* eq-evaluators.h -- $gen: do not edit.\n"
    . "   The evaluators of the labels without an eq.eval field, written by\n"
    . "   hand in lib/scene/eq-eval.c, and the certified evaluators of the\n"
    . "   labels with an eq.certified field, lib/scene/eq-certified.c. */\n"
    . "#ifndef CHAPLYGIN_SCENE_EQ_EVALUATORS_H\n#define CHAPLYGIN_SCENE_EQ_EVALUATORS_H\n\n"
    . "#include \"eq.h\"\n\n";
  for (@recs) {
    $text .= "int " . evaluator($_->{label}) . " (eq_ctx *c);\n"
      unless defined $_->{fields}{'eq.eval'};
  }
  $text .= "\n#if HAVE_ARB\n";
  for (@recs) {
    $text .= "int " . cert_evaluator($_->{label}) . " (eq_ctx *c);\n"
      if defined $_->{fields}{'eq.certified'};
  }
  $text .= "#endif\n";
  $text .= "\n#endif\n";
} elsif ($mode eq 'macros') {
  $text = $texi_head->('');
  $text .= "\@c The number of labels, for the text of the manual.\n\@set labelcount "
    . scalar(@recs) . "\n\n";
  my (%impl, %prints, %done);
  for my $r (@recs) {
    push @{ $impl{$_} }, $r->{label} for names($r->{fields}{functions});
    push @{ $prints{$_} }, $r->{label} for printed_functions($r->{fields}{printed_function});
  }
  # In the order of first appearance (a reproducible file).
  for my $r (@recs) {
    for (names($r->{fields}{functions})) {
      $text .= macro($_, 'Implements', @{ $impl{$_} }) unless $done{$_}++;
    }
    for (printed_functions($r->{fields}{printed_function})) {
      $text .= macro($_, "Evaluates the paper's printed form of", @{ $prints{$_} }) unless $done{$_}++;
    }
  }
}

write_output($out, $text);
exit 0;
