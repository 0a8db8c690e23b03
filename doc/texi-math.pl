#!/usr/bin/perl
# texi-math.pl -- convert the formulas of Texinfo files from the plain
# notation into the manual's math macros (lib/TexinfoMath.pm, the
# Conventions chapter), or write the macros' file.
#
#   perl doc/texi-math.pl FILE...     rewrite every @math{} of each FILE
#                                     in place (a formula already
#                                     converted is left as it is)
#   perl doc/texi-math.pl --macros    doc/math-macros.texi on stdout
#
# A formula the converter cannot write so that Info shows it exactly as
# before, or whose TeX is malformed, is an error naming the file: no file
# is changed then.
use strict;
use warnings;
use FindBin;
use lib "$FindBin::Bin/../lib";
use TexinfoMath qw(convert_texinfo macros_texi);

if (@ARGV == 1 && $ARGV[0] eq '--macros') {
  print macros_texi() or die "texi-math.pl: standard output: $!\n";
  close STDOUT or die "texi-math.pl: standard output: $!\n";
  exit 0;
}
die "usage: texi-math.pl FILE... | --macros\n" unless @ARGV;
my %new;
for my $f (@ARGV) {
  open my $fh, '<', $f or die "texi-math.pl: $f: $!\n";
  my $t = do { local $/; <$fh> };
  close $fh;
  $new{$f} = eval { convert_texinfo($t) } // die "texi-math.pl: $f: $@";
}
for my $f (@ARGV) {
  open my $fh, '>', "$f.tmp" or die "texi-math.pl: $f.tmp: $!\n";
  print {$fh} $new{$f} or die "texi-math.pl: $f.tmp: $!\n";
  close $fh or die "texi-math.pl: $f.tmp: $!\n";
  rename "$f.tmp", $f or die "texi-math.pl: $f: $!\n";
}
