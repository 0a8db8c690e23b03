# Registry.pm -- the reader of the project's registries, and the writer
# of what their generators make of them: lib/labels.txt
# (the paper's equation labels, read by lib/labels.pl) and doc/claims.txt
# (the paper's claims, read by doc/claims.pl).  Both have the same syntax,
# documented in their headers: records that start with a line '@ ID', then
# fields 'NAME: VALUE' (one line) or 'NAME:' followed by a block of lines
# indented by four spaces; '#' comments and blank lines between them.
# Every rule of the syntax is enforced here; a violation dies with
# "FILE:LINE: message" (the callers turn that into their error exit).
# Perl 5 core only.
package Registry;

use strict;
use warnings;

use Exporter qw(import);
use File::Basename qw(basename dirname);
our @EXPORT_OK = qw(read_registry list_names write_output on_error);

# read_registry(FILE, %opt) -> list of records { KEY => ID, line => N,
# fields => { NAME => VALUE }, at => { NAME => its line } }, in the
# file's order.  Options:
#   key      the name of the record's identifier ('label', 'id');
#   id       a regex an identifier must match;
#   id_what  how to describe a good identifier in a message;
#   kinds    { NAME => 'text' | 'list' | 'block' }: the known fields;
#   foreign  a regex of further field names accepted as they come (one
#            line or block), for other consumers; undef for none.
# Duplicate identifiers and fields, unknown fields, a one-line field
# written as a block or the reverse, empty blocks, tabs, carriage returns,
# trailing spaces and a missing final newline are errors.
sub read_registry {
  my ($file, %opt) = @_;
  my ($key, $kinds, $foreign) = @opt{qw(key kinds foreign)};
  open my $fh, '<', $file or die "$file: $!\n";
  my (@recs, %seen, $rec, $block, $blockname);
  my $n = 0;
  my $fail = sub { die "$file:$n: $_[0]\n" };
  my $end_block = sub {
    return unless defined $block;
    $fail->("field '$blockname' of $rec->{$key} is an empty block")
      if $block eq '';
    $rec->{fields}{$blockname} = $block;
    undef $block;
  };
  while (my $line = <$fh>) {
    $n++;
    $fail->("no newline at the end of the file") unless $line =~ s/\n\z//;
    $fail->("a tab or carriage return") if $line =~ /[\t\r]/;
    $fail->("trailing space") if $line =~ / \z/;
    if (defined $block && $line =~ /^    (.*)\z/s) {
      $block .= "$1\n";
      next;
    }
    $end_block->();
    next if $line =~ /^#/ || $line eq '';
    if ($line =~ /^@ (.*)\z/) {
      my $id = $1;
      $fail->("'$id' is not $opt{id_what}") unless $id =~ $opt{id};
      $fail->("$id again (first at line $seen{$id})") if $seen{$id};
      $seen{$id} = $n;
      $rec = { $key => $id, line => $n, fields => {} };
      push @recs, $rec;
      next;
    }
    $fail->("a line outside a record: $line") unless $rec;
    my ($name, $value) = $line =~ /^([a-z][a-z0-9_.]*):(?: (.*))?\z/
      or $fail->("not a field (NAME: VALUE, or NAME: then a block): $line");
    $fail->("unknown field '$name' in $rec->{$key} (the fields are listed "
            . "in the header)")
      unless exists $kinds->{$name} || (defined $foreign && $name =~ $foreign);
    $fail->("field '$name' again in $rec->{$key}")
      if exists $rec->{fields}{$name};
    if (defined $value) {
      $fail->("field '$name' is a block (its lines indented by four spaces "
              . "below '$name:')")
        if ($kinds->{$name} // '') eq 'block';
      $rec->{fields}{$name} = $value;
    } else {
      $fail->("field '$name' is one line ('$name: VALUE')")
        if exists $kinds->{$name} && $kinds->{$name} ne 'block';
      ($block, $blockname) = ('', $name);
    }
    $rec->{at}{$name} = $n;
  }
  $end_block->();
  close $fh;
  die "$file: no record\n" unless @recs;
  return @recs;
}

# The names of a LIST field's VALUE: an empty list for '-'.
sub list_names {
  my ($v) = @_;
  return () if $v eq '-';
  return split /, /, $v;
}

# write_output(OUT, TEXT): TEXT to the file OUT, or to standard output if
# OUT is undef.  A file is written beside OUT under a temporary name and
# renamed to OUT once complete, so that a failure (a full disk) leaves OUT
# as it was and no temporary file; dies with the reason.
sub write_output {
  my ($out, $text) = @_;
  if (!defined $out) {
    print $text or die "standard output: $!\n";
    close STDOUT or die "standard output: $!\n";
    return;
  }
  my $tmp = dirname($out) . '/.' . basename($out) . ".tmp$$";
  my $fh;
  my $ok = open($fh, '>', $tmp) && (print {$fh} $text) && close($fh)
    && rename($tmp, $out);
  return if $ok;
  my $why = $!;
  unlink $tmp;
  die "$out: $why\n";
}

# on_error(NAME): every error of the generator NAME (a die outside an
# eval, or a warning) printed as "NAME: message" on standard error, then
# exit status 1: a generator's one way to fail.
sub on_error {
  my ($me) = @_;
  my $say = sub { print STDERR "$me: $_[0]" . ($_[1] =~ s/\n\z//r) . "\n"; exit 1; };
  $SIG{__DIE__} = sub { return if $^S; $say->('', $_[0]) };
  $SIG{__WARN__} = sub { $say->('warning: ', $_[0]) };
}

1;
