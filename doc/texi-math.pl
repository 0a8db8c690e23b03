#!/usr/bin/perl
# texi-math.pl -- convert the formulas of Texinfo files from the plain
# notation into the manual's math macros (lib/TexinfoMath.pm, the
# Conventions chapter), check them, or write the macros' file.
#
#   perl doc/texi-math.pl FILE...     rewrite each FILE in place: every
#                                     @math{} converted (a formula already
#                                     converted is left as it is), every
#                                     displayed formula (a plain @example
#                                     for Info, a @displaymath a TeX line
#                                     for HTML and TeX: TexinfoMath's
#                                     display_texi) checked and written
#                                     again in its one form
#   perl doc/texi-math.pl --check FILE...
#                                     change nothing; fail (exit 1, naming
#                                     each FILE) if the rewrite would
#                                     change a FILE: a formula not
#                                     converted, or a displayed formula
#                                     edited out of its form
#   perl doc/texi-math.pl --macros    doc/math-macros.texi on stdout
#
# A formula the converter cannot write so that Info shows it exactly as
# before, whose TeX is malformed, or a displayed formula whose two forms
# differ in their symbols, is an error naming the file and line: no file
# is changed then.
use strict;
use warnings;
use FindBin;
use lib "$FindBin::Bin/../lib";
use TexinfoMath qw(convert_texinfo normalize_displays macros_texi);

if (@ARGV == 1 && $ARGV[0] eq '--macros') {
  print macros_texi() or die "texi-math.pl: standard output: $!\n";
  close STDOUT or die "texi-math.pl: standard output: $!\n";
  exit 0;
}
my $check = @ARGV && $ARGV[0] eq '--check' ? shift @ARGV : undef;
die "usage: texi-math.pl [--check] FILE... | --macros\n" unless @ARGV;
my (%old, %new);
for my $f (@ARGV) {
  open my $fh, '<', $f or die "texi-math.pl: $f: $!\n";
  $old{$f} = do { local $/; <$fh> };
  close $fh;
  $new{$f} = eval { normalize_displays(convert_texinfo($old{$f})) }
    // die "texi-math.pl: " . ($@ =~ /^line ([0-9]+): (.*)/s ? "$f:$1: $2" : "$f: $@");
}
if ($check) {
  my @changed = grep { $new{$_} ne $old{$_} } @ARGV;
  print STDERR "texi-math.pl: $_: a formula not in the manual's form "
    . "(run doc/texi-math.pl $_ and review the change)\n" for @changed;
  exit(@changed ? 1 : 0);
}
for my $f (@ARGV) {
  next if $new{$f} eq $old{$f};
  open my $fh, '>', "$f.tmp" or die "texi-math.pl: $f.tmp: $!\n";
  print {$fh} $new{$f} or die "texi-math.pl: $f.tmp: $!\n";
  close $fh or die "texi-math.pl: $f.tmp: $!\n";
  rename "$f.tmp", $f or die "texi-math.pl: $f: $!\n";
}
