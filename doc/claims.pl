#!/usr/bin/perl
# claims.pl -- read the registry of the paper's claims (doc/claims.txt,
# whose header documents its format) and write what is generated from it.
#
#   perl doc/claims.pl [-o OUT] MODE doc/claims.txt FILES...
#
# MODE:
#   texi     doc/claims.texi, the chapter "The paper's claims": a summary
#            table, then one node "Claim ID" a claim;
#   figures  doc/claims-figures.texi: for each figure node of
#            doc/figures.texi a macro named by its first figure,
#            @claimsFigureOne{} ... (the number in words: texinfo.tex
#            takes macro names of letters only), listing the claims about
#            its figures, which the node's section calls (every mode
#            checks that each node of doc/figures.texi does);
#   list     tests/claims-list.h: the macro CLAIM_CHECKS, the checks'
#            names as C strings in the registry's order, which
#            tests/test_claims compares with the checks it registers;
#   check    read and check only.
# FILES (all modes; recognised by their names): lib/labels.txt (the
# labels), doc/errata.texi (the errata's nodes), doc/figures.texi (the
# figures' nodes), and the C files of tests/test_claims (each check must
# be a START_TEST of exactly one of them).  With -o OUT the output is
# written to a temporary file beside OUT and renamed to OUT once complete.
# Any malformed input is an error (exit 1, a message naming the file and
# line).  Perl 5 core only.

use strict;
use warnings;
use File::Basename qw(basename);
use FindBin;
use lib "$FindBin::Bin/../lib";
use Registry qw(read_registry list_names write_output on_error);
use TexinfoMath qw(convert_texinfo);

my $me = 'claims.pl';
on_error($me);
sub fail { die "$_[0]\n" }

my %KIND = (
  title => 'text', where => 'text', verdict => 'text', check => 'text',
  labels => 'list', errata => 'list', figures => 'list',
  claim => 'block', evidence => 'block',
);
my @VERDICTS = ('confirmed', 'refined', 'contradicted', 'not checkable');

my $out;
if (@ARGV >= 2 && $ARGV[0] eq '-o') { $out = $ARGV[1]; splice @ARGV, 0, 2; }
my ($mode, $registry, @files) = @ARGV;
fail("usage: $me [-o OUT] texi|figures|list|check doc/claims.txt FILES...")
  unless defined $registry && $mode =~ /^(?:texi|figures|list|check)\z/;

# ---- the other sources -------------------------------------------------

# The macro of the figure node whose first figure is N (the number in
# words: texinfo.tex takes macro names of letters only).
my @NUMBER_WORD = qw(zero one two three four five six seven eight nine ten);
sub figure_macro {
  my ($n) = @_;
  fail("figure $n: no macro name for it") unless $n >= 1 && $n <= 10;
  return 'claimsFigure' . ucfirst($NUMBER_WORD[$n]);
}

my (%label, %erratum, %figure_node, %node_first, %macro_called, %check_file);
my $figures_texi;
for my $path (@files) {
  my $name = basename($path);
  open my $fh, '<', $path or fail("$path: $!");
  while (my $line = <$fh>) {
    if ($name eq 'labels.txt') {
      $label{$1} = 1 if $line =~ /^@ (\S+)$/;
    } elsif ($name eq 'errata.texi') {
      $erratum{$1} = 1 if $line =~ /^\@node Erratum (E\d+)\s*$/;
    } elsif ($name eq 'figures.texi') {
      $figures_texi = $path;
      if ($line =~ /^\@node (Figures? (\d+)(?: and (\d+))?)\s*$/) {
        $figure_node{$2} = $1;
        $figure_node{$3} = $1 if defined $3;
        $node_first{$1} = $2;
      }
      $macro_called{$1} = 1 if $line =~ /^\@(claimsFigure[A-Za-z]+)\{\}\s*$/;
    } elsif ($name =~ /\.c\z/) {
      if ($line =~ /^START_TEST \((claim_[a-z0-9_]+)\)/) {
        my $check = $1;
        fail("$path:$.: $check is also a test of $check_file{$check}")
          if $check_file{$check};
        $check_file{$check} = $path =~ s{^.*?(tests/[^/]+)\z}{$1}r;
      }
    } else {
      fail("$path: not lib/labels.txt, doc/errata.texi, doc/figures.texi or a C file");
    }
  }
  close $fh;
}
fail("no lib/labels.txt among the files") unless %label;
fail("no doc/errata.texi among the files") unless %erratum;
fail("no doc/figures.texi among the files") unless %figure_node;
for my $node (sort keys %node_first) {
  my $m = figure_macro($node_first{$node});
  fail("$figures_texi: $node does not list its claims (\@$m\{\})")
    unless $macro_called{$m};
}

# ---- the registry ------------------------------------------------------

my @claims = read_registry($registry, key => 'id', id => qr/^C[1-9][0-9]*\z/,
                           id_what => 'a claim such as C7', kinds => \%KIND);
my (%by_id, %by_check);
for my $i (0 .. $#claims) {
  my $c = $claims[$i];
  my $at = "$registry:$c->{line}: $c->{id}";
  fail("$at: the claims are numbered C1, C2, ... in order (this is claim "
       . ($i + 1) . ")") unless $c->{id} eq 'C' . ($i + 1);
  for my $f (sort keys %KIND) {
    fail("$at: no field '$f'") unless defined $c->{fields}{$f};
  }
  my $f = $c->{fields};
  fail("$at: verdict '$f->{verdict}' is not one of " . join(', ', @VERDICTS))
    unless grep { $_ eq $f->{verdict} } @VERDICTS;
  fail("$at: check '$f->{check}' is not claim_NAME")
    unless $f->{check} =~ /^claim_[a-z0-9_]+\z/;
  fail("$at: check $f->{check} is also that of $by_check{$f->{check}}")
    if $by_check{$f->{check}};
  $by_check{$f->{check}} = $c->{id};
  if (grep { /\.c\z/ } @files) {
    fail("$at: check $f->{check} is no START_TEST of the C files given")
      unless $check_file{$f->{check}};
  }
  for (list_names($f->{labels})) {
    fail("$at: label $_ is not in lib/labels.txt") unless $label{$_};
  }
  for (list_names($f->{errata})) {
    fail("$at: erratum $_ is not a node of doc/errata.texi") unless $erratum{$_};
  }
  for (list_names($f->{figures})) {
    fail("$at: figure $_ has no node in doc/figures.texi") unless $figure_node{$_};
  }
  $by_id{$c->{id}} = $c;
}
for my $c (@claims) {
  for my $b (qw(claim evidence)) {
    for my $ref ($c->{fields}{$b} =~ /\[(C\d+)\]/g) {
      fail("$registry:$c->{line}: $c->{id} refers to [$ref], which is not a claim")
        unless $by_id{$ref};
    }
  }
}

# ---- output ------------------------------------------------------------

sub texi { my $s = shift; $s =~ s/([\@{}])/\@$1/g; return $s; }
# A title of the registry in the manual's form.
sub title { return convert_texinfo(shift); }
sub claim_ref { "\@ref{Claim $_[0],,$_[0]}" }
# A Texinfo block of the registry: claim references made links, formulas
# in the manual's math macros (written in the plain notation there).
sub block {
  my $s = convert_texinfo(shift);
  $s =~ s/\[(C\d+)\]/claim_ref($1)/ge;
  return $s;
}
sub label_ref { my $l = shift; (my $a = $l) =~ s/\./-/; "\@ref{Equation $a,,($l)}" }

sub entry {
  my ($c) = @_;
  my $f = $c->{fields};
  my $s = "\@node Claim $c->{id}\n\@section $c->{id}: " . title($f->{title})
    . "\n\@cindex claim $c->{id}\n\n\@table \@asis\n";
  $s .= "\@item Where\n" . texi($f->{where}) . "\n";
  $s .= "\@item Claim\n" . block($f->{claim});
  $s .= "\@item Verdict\n\@strong{$f->{verdict}}\n";
  $s .= "\@item Evidence\n" . block($f->{evidence});
  $s .= "\@item Check\n\@code{$f->{check}}";
  $s .= " (\@file{$check_file{$f->{check}}})" if $check_file{$f->{check}};
  $s .= ", run by \@file{tests/test_claims} in \@code{make check}\n";
  my @see;
  my $see = sub {
    my ($one, $many, @refs) = @_;
    push @see, (@refs > 1 ? $many : $one) . ' ' . join(', ', @refs) if @refs;
  };
  $see->('equation', 'equations', map { label_ref($_) } list_names($f->{labels}));
  $see->('erratum', 'errata', map { "\@ref{Erratum $_,,$_}" } list_names($f->{errata}));
  $see->('figure', 'figures',
         map { "\@ref{$figure_node{$_},,$_}" } list_names($f->{figures}));
  $s .= "\@item See\n" . join('; ', @see) . "\n" if @see;
  return $s . "\@end table\n\n";
}

sub chapter {
  my %count;
  $count{$_->{fields}{verdict}}++ for @claims;
  my $n = @claims;
  my $counts = join ', ', map { ($count{$_} // 0) . " $_" } @VERDICTS;
  my $s = convert_texinfo(<<"EOT");
\@c Generated from doc/claims.txt by doc/claims.pl: do not edit.
\@node The paper's claims
\@chapter The paper's claims
\@cindex claims of the paper
\@cindex audit of the paper's text

Beyond its numbered equations (\@pxref{Concordance}), the paper's text and
captions make statements that can be checked: stability ranges, the modes
of motion, the basins of attraction, the limits \@math{Delta -> 0} and
\@math{rho -> 0}.  This chapter lists $n of them, in the paper's order,
each with where it stands, the claim in brief, a verdict and the
evidence; the figures' claims are also listed under each figure
(\@pxref{Scenes and figures}).  The verdicts: $counts.

\@table \@asis
\@item confirmed
the claim holds as stated, where the paper states it;
\@item refined
it holds under a condition the paper does not state, or with other
numbers: the entry says which;
\@item contradicted
it is false, and the entry gives the counterexample;
\@item not checkable
it is not a statement about the motion, or no computation can decide it.
\@end table

Each claim is decided by a Check test of \@file{tests/test_claims}, which
\@code{make check} runs.  The test fails unless the checks it runs are
exactly those of the registry \@file{doc/claims.txt}, the one source of
this chapter, of the lists under the figures and of the test's list
(\@file{doc/claims.pl} writes all three).  Each test checks the claim
against a route other than the function that computes it (an identity,
a limit, plain iteration of the map, finite differences, a Runge-Kutta
integration, the other skate) and states its tolerances; the evidence
below gives the numbers.  Where a claim meets an erratum, the entry
refers to it.

\@multitable \@columnfractions .07 .43 .33 .17
\@headitem Claim \@tab In brief \@tab Where \@tab Verdict
EOT
  for my $c (@claims) {
    my $f = $c->{fields};
    # The identifier as text: a cross-reference in a table cell is a
    # whole "Section 11.1 [C1], page 185" in the PDF; the menu below
    # links every entry.
    $s .= "\@item $c->{id} \@tab " . title($f->{title})
      . " \@tab " . texi($f->{where}) . " \@tab $f->{verdict}\n";
  }
  $s .= "\@end multitable\n\n";
  $s .= errata_table();
  $s .= "\@menu\n";
  $s .= "* Claim $_->{id}::" . (' ' x (10 - length $_->{id}))
    . title($_->{fields}{title}) . ".\n" for @claims;
  $s .= "\@end menu\n\n";
  $s .= entry($_) for @claims;
  return $s;
}

# The errata the claims meet, each with its claims, in the errata's order.
sub errata_table {
  my %claims_of;
  for my $c (@claims) {
    push @{$claims_of{$_}}, $c->{id} for list_names($c->{fields}{errata});
  }
  my @e = sort { substr($a, 1) <=> substr($b, 1) } keys %claims_of;
  return '' unless @e;
  my $s = "\@noindent\nThe errata the claims meet, and their claims:\n\n"
    . "\@multitable \@columnfractions .15 .85\n\@headitem Erratum \@tab Claims\n";
  $s .= "\@item $_ \@tab " . join(', ', @{$claims_of{$_}}) . "\n"
    for @e;
  return $s . "\@end multitable\n\n";
}

sub figure_macros {
  my $s = "\@c Generated from doc/claims.txt by doc/claims.pl: do not edit.\n"
    . "\@c The claims about the figures of each node of figures.texi.\n";
  my %numbers;   # node -> its figures
  push @{$numbers{$figure_node{$_}}}, $_ for sort { $a <=> $b } keys %figure_node;
  for my $node (sort { $numbers{$a}[0] <=> $numbers{$b}[0] } keys %numbers) {
    my @n = @{$numbers{$node}};
    my %in = map { $_ => 1 } @n;
    my @about = grep { grep { $in{$_} } list_names($_->{fields}{figures}) } @claims;
    my $what = @n > 1 ? 'Figures ' . join(' and ', @n) : "Figure $n[0]";
    $s .= "\n\@macro " . figure_macro($n[0]) . "\n";
    if (@about) {
      $s .= "\@noindent\nThe paper's claims about $what "
        . "(\@pxref{The paper's claims}):\n\n\@itemize \@bullet\n";
      for my $c (@about) {
        $s .= "\@item\n" . claim_ref($c->{id}) . ", $c->{fields}{verdict}: "
          . title($c->{fields}{title}) . ".\n";
      }
      $s .= "\@end itemize\n";
    } else {
      $s .= "\@noindent\nNo claim of the registry is about $what.\n";
    }
    $s .= "\@end macro\n";
  }
  return $s;
}

sub check_list {
  my $s = "/* claims-list.h -- generated from doc/claims.txt by doc/claims.pl:\n"
    . "   do not edit.  The checks of the paper's claims, in the registry's\n"
    . "   order (tests/test_claims.c). */\n#define CLAIM_CHECKS \\\n";
  $s .= join(", \\\n", map { "  \"$_->{fields}{check}\"" } @claims) . "\n";
  return $s;
}

my $text = $mode eq 'texi' ? chapter()
  : $mode eq 'figures' ? figure_macros()
  : $mode eq 'list' ? check_list() : '';
exit 0 if $mode eq 'check';
write_output($out, $text);
