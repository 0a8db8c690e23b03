#!/usr/bin/perl
# check-math.pl -- the HTML manual loads nothing from the network, and its
# formulas are well-formed TeX.
#
#   perl doc/check-math.pl DIR [PAGE-PATTERN]
#
# Every .html page of DIR: no <script src=...> or <link href=...> names a
# remote resource (a URL with a scheme other than file:, or //host).
# Every page whose file name matches PAGE-PATTERN (a Perl regular
# expression; default: every page): every formula MathJax
# typesets, \(...\) or \[...\], is well-formed TeX by
# lib/TexinfoMath.pm's tex_errors (braces balanced, \left/\right paired,
# control sequences MathJax 2 and plain TeX know, an argument after ^
# and _).  Failures are printed as FILE: MESSAGE, exit status 1; on
# success one summary line, exit status 0.
use strict;
use warnings;
use FindBin;
use lib "$FindBin::Bin/../lib";
use TexinfoMath qw(tex_errors);

my ($dir, $pat) = @ARGV;
die "usage: check-math.pl DIR [PAGE-PATTERN]\n" unless defined $dir && -d $dir;
$pat //= '.';
$pat = qr/$pat/;
my (@bad, $pages, $formulas);
opendir my $dh, $dir or die "check-math.pl: $dir: $!\n";
for my $f (sort grep { /\.html\z/ } readdir $dh) {
  open my $fh, '<', "$dir/$f" or die "check-math.pl: $dir/$f: $!\n";
  my $t = do { local $/; <$fh> };
  close $fh;
  $pages++;
  while ($t =~ /<(script|link)\b([^>]*)>/gi) {
    my ($tag, $attrs) = (lc $1, $2);
    my $attr = $tag eq 'script' ? 'src' : 'href';
    next unless $attrs =~ /\b$attr\s*=\s*(?:"([^"]*)"|'([^']*)'|([^\s>]+))/i;
    my $url = $1 // $2 // $3;
    push @bad, "$f: <$tag> loads a remote resource: $url"
      if $url =~ m{^(?://|(?!file:)[A-Za-z][A-Za-z0-9+.-]*:)};
  }
  next unless $f =~ $pat;
  while ($t =~ /\\\((.*?)\\\)|\\\[(.*?)\\\]/gs) {
    my $m = $1 // $2;
    $m =~ s/&lt;/</g; $m =~ s/&gt;/>/g; $m =~ s/&quot;/"/g;
    $m =~ s/&#(\d+);/chr $1/ge; $m =~ s/&amp;/&/g;
    $formulas++;
    push @bad, "$f: \\($m\\): $_" for tex_errors($m);
  }
}
closedir $dh;
if (@bad) { print "$_\n" for @bad; exit 1; }
print "$pages pages, no remote script or style, " . ($formulas // 0)
  . " formulas well-formed\n";
