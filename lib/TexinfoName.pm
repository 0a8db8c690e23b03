# TexinfoName.pm -- the name of the Texinfo macro that says which labels a
# function of the library implements: what lib/labels.pl defines (in
# doc/concordance-macros.texi) and doc/hdr2texi.pl calls after the
# function's entry.  texinfo.tex (the PDF manual) takes macro names of
# letters only, so chaplygin_discrete_sigma4 is implementsChaplyginDiscreteSigmaNE:
# each word capitalised, the underscores dropped, a digit d written "N"
# and the d-th capital letter (no name of the header has "_" before a
# digit, so no two names meet).
package TexinfoName;

use strict;
use warnings;

use Exporter qw(import);
our @EXPORT_OK = qw(implements_macro);

sub implements_macro {
  my ($fn) = @_;
  die "TexinfoName: '$fn' is not a C identifier of lower case, digits "
    . "and single underscores\n"
    unless $fn =~ /^[a-z][a-z0-9]*(?:_[a-z][a-z0-9]*)*$/;
  my $name = join '', map { ucfirst } split /_/, $fn;
  $name =~ s/(\d)/'N' . chr (ord ('A') + $1)/ge;
  return "implements$name";
}

1;
