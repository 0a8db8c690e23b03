#!/usr/bin/perl
# check-html.pl -- check the relative links and images of an HTML manual.
#
# Usage:
#   perl doc/check-html.pl DIR_OR_FILE...
#   perl doc/check-html.pl doc/chaplygin.html          (the split manual)
#   perl doc/check-html.pl /tmp/one.html               (a single page)
#
# Every .html/.htm file given, or found directly (not recursively) in a
# directory given, is read, and every href="..." and src="..." attribute
# of its tags (double-quoted, single-quoted or unquoted; HTML comments
# are skipped) is checked:
#   - an absolute URL with a scheme (http:, https:, mailto:, file:, ...)
#     or a network path (//host/...) is skipped;
#   - otherwise the path part (without ?query and #fragment, %xx decoded,
#     entities such as &amp; decoded) must name an existing file or
#     directory, relative to the directory of the HTML file ("" and
#     "#frag" refer to the file itself; /path is taken on this machine);
#   - a #fragment must be the id="..." of an element, or the name="..."
#     of an <a>, in the target file, when the target is an HTML file
#     (a directory's fragment is looked up in its index.html).
# Each failure is printed once per file and target, as
#   FILE: broken link TARGET
#   FILE: missing anchor TARGET
# (TARGET as written in the attribute, entities decoded) and the exit
# status is then 1.  On success a one-line summary (files, links and
# images checked, external URLs skipped) is printed and the exit status
# is 0.  A usage error or an unreadable file gives exit status 2.
#
# Limits: a regular-expression scan, not an HTML parser (enough for the
# HTML that makeinfo writes; a '>' inside a quoted attribute value ends
# the tag early); <base href>, srcset, CSS url(...) and links built by
# scripts are not followed; external URLs are not fetched; file names are
# compared as the file system does (case-sensitively on most systems).
# Core Perl 5 modules only.

use strict;
use warnings;
use File::Spec;
use File::Basename qw(dirname basename);

my $prog = basename($0);

if (!@ARGV || $ARGV[0] eq '-h' || $ARGV[0] eq '--help') {
    print STDERR "usage: perl $prog DIR_OR_FILE...\n";
    exit(@ARGV ? 0 : 2);
}

my %ENT = (amp => '&', lt => '<', gt => '>', quot => '"', apos => "'",
           nbsp => "\xa0");

# decode the character references of an attribute value
sub decode_entities {
    my ($s) = @_;
    $s =~ s{&(?:#[xX]([0-9A-Fa-f]+)|#([0-9]+)|([A-Za-z][A-Za-z0-9]*));}{
        defined $1 ? chr(hex $1)
        : defined $2 ? chr($2)
        : exists $ENT{$3} ? $ENT{$3} : "&$3;"
    }ge;
    return $s;
}

sub url_decode {
    my ($s) = @_;
    $s =~ s/%([0-9A-Fa-f]{2})/chr(hex $1)/ge;
    return $s;
}

sub read_file {
    my ($file) = @_;
    open(my $fh, '<:raw', $file) or return undef;
    local $/;
    my $text = <$fh>;
    close $fh;
    return $text;
}

# the tags of an HTML text: a list of [name, {attribute => value}]
sub tags {
    my ($text) = @_;
    $text =~ s/<!--.*?-->//gs;
    my @tags;
    while ($text =~ /<([A-Za-z][A-Za-z0-9:-]*)((?:[^>"']|"[^"]*"|'[^']*')*)>/g) {
        my ($name, $rest) = (lc $1, $2);
        my %attr;
        while ($rest =~ /([A-Za-z_:][-A-Za-z0-9_:.]*)\s*=\s*(?:"([^"]*)"|'([^']*)'|([^\s"'=<>`]+))/g) {
            my $v = defined $2 ? $2 : defined $3 ? $3 : $4;
            $attr{lc $1} = decode_entities($v);
        }
        push @tags, [$name, \%attr];
    }
    return @tags;
}

my %anchors_of;    # file => {anchor => 1}, or undef if unreadable

sub anchors {
    my ($file) = @_;
    return $anchors_of{$file} if exists $anchors_of{$file};
    my $text = read_file($file);
    my %a;
    if (defined $text) {
        for my $t (tags($text)) {
            my ($name, $attr) = @$t;
            $a{$attr->{id}} = 1 if defined $attr->{id};
            $a{$attr->{name}} = 1 if $name eq 'a' && defined $attr->{name};
        }
    }
    return $anchors_of{$file} = defined $text ? \%a : undef;
}

sub is_html { return $_[0] =~ /\.x?html?$/i }

# the files to check
my @files;
for my $arg (@ARGV) {
    if (-d $arg) {
        opendir(my $dh, $arg) or do { print STDERR "$prog: $arg: $!\n"; exit 2 };
        push @files, map { File::Spec->catfile($arg, $_) }
            sort grep { is_html($_) && -f File::Spec->catfile($arg, $_) } readdir $dh;
        closedir $dh;
    } elsif (-f $arg) {
        push @files, $arg;
    } else {
        print STDERR "$prog: $arg: no such file or directory\n";
        exit 2;
    }
}

my ($nlinks, $nimages, $nexternal, $nfail) = (0, 0, 0, 0);
for my $file (@files) {
    my $text = read_file($file);
    if (!defined $text) { print STDERR "$prog: $file: $!\n"; exit 2 }
    my $dir = dirname($file);
    my %seen;
    for my $t (tags($text)) {
        my ($tag, $attr) = @$t;
        for my $which ('href', 'src') {
            next unless defined $attr->{$which};
            my $target = $attr->{$which};
            $target =~ s/^\s+|\s+$//g;
            if ($target =~ m{^[A-Za-z][A-Za-z0-9+.-]*:} || $target =~ m{^//}) {
                $nexternal++;
                next;
            }
            if ($tag eq 'img' && $which eq 'src') { $nimages++ } else { $nlinks++ }
            my ($path, $frag) = ($target, undef);
            ($path, $frag) = ($1, $2) if $target =~ /^([^#]*)#(.*)$/s;
            $path =~ s/\?.*//s;
            $path = url_decode($path);
            my $dest;
            if ($path eq '') {
                $dest = $file;
            } else {
                $dest = File::Spec->file_name_is_absolute($path)
                    ? $path : File::Spec->catfile($dir, $path);
                if (!-e $dest) {
                    if (!$seen{"b $target"}++) {
                        print "$file: broken link $target\n";
                        $nfail++;
                    }
                    next;
                }
            }
            next if !defined $frag || $frag eq '';
            $dest = File::Spec->catfile($dest, 'index.html') if -d $dest;
            next unless is_html($dest);
            my $a = anchors($dest);
            if (!$a || !($a->{$frag} || $a->{url_decode($frag)})) {
                if (!$seen{"a $target"}++) {
                    print "$file: missing anchor $target\n";
                    $nfail++;
                }
            }
        }
    }
}

if ($nfail) {
    print STDERR "$prog: $nfail broken link(s) or missing anchor(s) in "
        . scalar(@files) . " file(s)\n";
    exit 1;
}
print "$prog: " . scalar(@files) . " file(s), $nlinks link(s), $nimages image(s) "
    . "checked, all good ($nexternal external URL(s) not checked)\n";
exit 0;
