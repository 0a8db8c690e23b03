#!/usr/bin/perl
# certified-none.pl -- writes lib/certified-none.c from lib/chaplygin.h:
# every public chaplygin_certified_* function declared there, as a stub
# for a library built without Arb (configure --without-arb, or Arb not
# found), so that programs and bindings link against either build with
# the same interface.  A stub refuses with CHAPLYGIN_EINVAL, sets each
# `T **' output to NULL, and uses nothing else; an orbit's release
# (_free) succeeds (there is nothing to release).  The header is the one
# source: a certified function declared there has its stub by
# construction.
# Usage: perl lib/certified-none.pl lib/chaplygin.h > lib/certified-none.c
use strict;
use warnings;

my $header = shift @ARGV or die "usage: $0 chaplygin.h\n";
open my $fh, '<', $header or die "$header: $!\n";
my $text = do { local $/; <$fh> };
close $fh;
$text =~ s{/\*.*?\*/}{}gs;                     # comments (the doc comments)

print <<'HEAD';
/* certified-none.c -- every public chaplygin_certified_* function in a
   build without Arb, each refusing with CHAPLYGIN_EINVAL (an orbit's
   release succeeds: there is none), so that programs and bindings link
   against either build (chaplygin_method_available tells them apart).
   Generated from lib/chaplygin.h by lib/certified-none.pl: do not
   edit. */
#include <config.h>

#include <stddef.h>

#include "chaplygin.h"
HEAD

my $n = 0;
while ($text =~ /\bint\s+(chaplygin_certified_\w+)\s*\(([^;]*?)\)\s*;/gs) {
  my ($name, $params) = ($1, $2);
  my @params = map { my $p = $_; $p =~ s/\s+/ /g; $p =~ s/^ | $//g;
                     $p =~ s/\* /*/g; $p } split /,/, $params;
  my $indent = ' ' x (length($name) + 2);
  print "\nint\n$name (", join(",\n$indent", @params), ")\n{\n";
  for my $p (@params) {
    $p =~ /(\**)(\w+)(?:\[\d+\])?$/ or die "$name: cannot read '$p'\n";
    my ($stars, $var) = ($1, $2);
    if (length $stars == 2) {
      print "  if ($var)\n    *$var = NULL;\n";
    } else {
      print "  (void) $var;\n";
    }
  }
  print "  return ", ($name =~ /_free$/ ? 'CHAPLYGIN_SUCCESS' : 'CHAPLYGIN_EINVAL'),
    ";\n}\n";
  $n++;
}
die "$header: no chaplygin_certified_* declarations\n" unless $n;
