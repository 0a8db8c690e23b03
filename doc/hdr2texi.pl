#!/usr/bin/perl
# hdr2texi.pl -- a library reference chapter (Texinfo) from the doc comments
# of a public C header: the header is the one source of the reference.
#
#   perl doc/hdr2texi.pl [OPTIONS] HEADER > OUT.texi
#
# Options:
#   --chapter=TITLE     write the chapter: @node/@chapter TITLE, the header's
#                       @overview comment, the @menu of all its sections,
#                       then the sections
#   --only=NODE         write only the section NODE (no chapter head)
#   --split=NODE=FILE   write `@include FILE' in place of the section NODE
#                       (which a second run writes with --only=NODE)
#   --concordance=TSV   a function named in TSV's columns `function' or
#                       `printed_function' (comma-separated lists; -, same
#                       and none name none) gets the line @implementsName{}
#                       after its @deftypefun line (the macro that
#                       doc/concordance.awk writes); a name there that the
#                       header does not declare is an error
#   --name=PATH         the header's name in the generated file's comment
#                       (default: HEADER as given)
#   --prefix=P          identifiers starting with P are code by themselves
#                       (repeatable; default chaplygin_ and CHAPLYGIN_)
#   --list              instead of Texinfo, print the documented
#                       declarations, one per line: `function NAME',
#                       `type NAME', `macro NAME' (also when there are
#                       errors, which it reports as below)
# Any error (an undocumented function, an unknown @word, unbalanced markup)
# is reported as HEADER:LINE: message, and the exit status is 1 with
# nothing on standard output.
#
# THE MARKUP (also summarised at the top of lib/chaplygin.h)
#
# A doc comment starts with `/**'; an ordinary `/* */' comment is not
# documentation.  The comment's text starts after `/** ' on its first line
# and, on the lines after it, three columns to the right of the `/**'
# (GNU style); a line indented less is an error.
#
# What a doc comment documents:
#  - the declaration that follows it with nothing but one line break
#    between them (no blank line):
#      function prototype  -> @anchor{NAME}, @deftypefun made from the
#                             prototype itself (parameters as @var), the
#                             @implementsName{} line (--concordance), the
#                             comment's text; every function needs one;
#      typedef struct / typedef enum / enum TAG -> @anchor{NAME} (typedefs),
#                             @deftp {Data type} / {Enumerated type}, the
#                             text, and a table (@table @code) of the
#                             members that carry a doc comment of their own
#                             (`/** ... */' after the member: @item TYPE NAME,
#                             or @item NAME = VALUE for an enum constant),
#                             placed where the text has a line `@fields'
#                             (else after the text);
#      #define NAME ...       -> @defmac NAME; `@expansion' in its text is
#                             the macro's replacement text, as @code;
#      typedef struct TAG NAME; (an opaque type) -> @deftp {Data type};
#      typedef RET (*NAME) (PARAMS); -> @deftp {Function type} NAME, the
#                             typedef in an @example, parameters as @var;
#  - `/** @overview' (once): the chapter's introduction, before its @menu;
#  - `/** @section TITLE' starts a section: @node/@section TITLE; optional
#    lines `@node NAME' (the node's name when it is not the title) and
#    `@brief TEXT' (its line in the chapter's @menu), then the section's
#    introduction;
#  - any other doc comment (followed by a blank line, another comment or a
#    preprocessor line) is text between the entries, in place (e.g. a
#    `@subheading').
#
# Blocks (at the text's left margin unless said otherwise):
#  - a line indented by 2 or more columns: a line of an @example (blank
#    lines between such lines stay in it); written verbatim, braces and @
#    escaped;
#  - `- ' starts an item of an @itemize @bullet; its next lines are
#    indented by 2;
#  - lines that pass through as they are: @noindent, @cindex ...,
#    @subheading ..., @table ..., @item ..., @end table;
#  - `@NAME: (ANNOTATIONS)' annotates parameter NAME for the Python binding
#    (python/gen.py reads it; not written here, but NAME must be a
#    parameter);
#  - a blank line is a blank line; other lines are paragraph text.
# Inline, in paragraph text:
#    $...$            @math{...} in the manual's plain notation, converted
#                     by lib/TexinfoMath.pm (the Conventions chapter):
#                     sqrt(x), 10^(-3), ^iE^+, Omega, <=; inside, {...}
#                     after ^ or _ is a group, other braces are literal,
#                     `x` is @code{x}
#    `x`              @code{x}
#    @NAME            @var{NAME}, NAME a parameter of the function
#    chaplygin_x, CHAPLYGIN_X (an identifier with a prefix of --prefix)
#                     @code{...}
#    @pxref @ref @xref @samp @file @command @option @url{...}: as they are
#    @emph @dfn @strong @var @code{...}: as they are, the argument marked
#                     up in turn;  @dots{} @{ @} @@ @: @. @'e as they are
#    ``...''          Texinfo's quotes, as they are
#    { } elsewhere    escaped (@{ @}); any other @ is an error.

use strict;
use warnings;
use FindBin;
use lib "$FindBin::Bin/../lib";
use TexinfoName qw(implements_macro);
use TexinfoMath qw(convert_math);

my @PREFIXES;
my %RAW_ARG = map { $_ => 1 } qw(pxref ref xref samp file command option url);
my %TEXT_ARG = map { $_ => 1 } qw(emph dfn strong var code);
my %LINE_CMD = map { $_ => 1 } qw(noindent cindex subheading table item end);

my (%opt, @only, %split);
for my $a (@ARGV) {
  if ($a =~ /^--(chapter|concordance|name)=(.*)$/s) { $opt{$1} = $2 }
  elsif ($a =~ /^--only=(.+)$/s) { push @only, $1 }
  elsif ($a =~ /^--prefix=(\w+)$/s) { push @PREFIXES, $1 }
  elsif ($a =~ /^--split=([^=]+)=(.+)$/s) { $split{$1} = $2 }
  elsif ($a eq '--list') { $opt{list} = 1 }
  elsif ($a =~ /^--/) { die "hdr2texi.pl: unknown option $a\n" }
  elsif (!defined $opt{header}) { $opt{header} = $a }
  else { die "hdr2texi.pl: one header only\n" }
}
@PREFIXES = ('chaplygin_', 'CHAPLYGIN_') unless @PREFIXES;
defined $opt{header} or die "usage: hdr2texi.pl [OPTIONS] HEADER > OUT.texi\n";
my $HDR = $opt{header};
my $NAME = defined $opt{name} ? $opt{name} : $HDR;
my $id_re = join '|', map { quotemeta } @PREFIXES;

open my $fh, '<', $HDR or die "hdr2texi.pl: $HDR: $!\n";
my $text = do { local $/; <$fh> };
close $fh;

my @errors;
sub line_of { my ($off) = @_; return 1 + (substr($text, 0, $off) =~ tr/\n//) }
sub err { my ($off, $msg) = @_; push @errors, "$HDR:" . line_of($off) . ": $msg"; }

# ---------------------------------------------------------------------
# The header's top-level items: comments, #define lines, declarations.

# The C++ guards (extern "C" {, }) are blanked, line breaks kept.
(my $src = $text) =~ s{(#ifdef __cplusplus.*?#endif)}{ (my $x = $1) =~ tr/\n/ /c; $x }gse;

my @items;
{
  my ($i, $n, $depth, $dstart, $bol) = (0, length $src, 0, undef, 1);
  while ($i < $n) {
    my $c = substr $src, $i, 1;
    if (substr($src, $i, 2) eq '/*') {
      my $j = index $src, '*/', $i + 2;
      if ($j < 0) { err($i, 'unterminated comment'); last }
      if (!defined $dstart) {
        my $body = substr $src, $i + 2, $j - $i - 2;
        my $col = $i - (rindex($src, "\n", $i - 1) + 1);
        push @items, { kind => 'comment', start => $i, end => $j + 2,
                       doc => ($body =~ /^\*(?!\*)/ ? 1 : 0),
                       body => $body, col => $col };
      }
      $i = $j + 2;
      $bol = 0;
      next;
    }
    if ($bol && $c eq '#' && !defined $dstart) {
      my $j = $i;
      while (1) {
        my $k = index $src, "\n", $j;
        $k = $n if $k < 0;
        if ($k > 0 && substr($src, $k - 1, 1) eq '\\') { $j = $k + 1; next }
        $j = $k;
        last;
      }
      my $line = substr $src, $i, $j - $i;
      if ($line =~ /^#\s*define\s+(\w+)(\([^)]*\))?\s*(.*?)\s*$/s) {
        push @items, { kind => 'define', start => $i, end => $j,
                       name => $1, value => $3 };
      }
      $i = $j;
      next;
    }
    if ($c eq "\n") { $bol = 1 } elsif ($c !~ /\s/) { $bol = 0 }
    if (!defined $dstart && $c !~ /\s/) { $dstart = $i }
    if ($c eq '{') { $depth++ }
    elsif ($c eq '}') { $depth-- }
    elsif ($c eq ';' && $depth == 0 && defined $dstart) {
      push @items, { kind => 'decl', start => $dstart, end => $i + 1,
                     raw => substr($src, $dstart, $i + 1 - $dstart) };
      undef $dstart;
    }
    $i++;
  }
  err($dstart, 'declaration without ;') if defined $dstart;
}

# The declarations: what they declare.
for my $it (grep { $_->{kind} eq 'decl' } @items) {
  (my $d = $it->{raw}) =~ s{/\*.*?\*/}{ }gs;
  $d =~ s/\s+/ /g;
  $d =~ s/^ | $//g;
  if ($d =~ /^typedef (struct|enum)\b[^{]*\{(.*)\}\s*(\w+)\s*;$/s) {
    @$it{qw(what tag name body)} = ('type', $1, $3, $2);
  } elsif ($d =~ /^enum (\w+)\s*\{(.*)\}\s*;$/s) {
    @$it{qw(what tag name body)} = ('type', 'enum', "enum $1", $2);
  } elsif ($d =~ /^typedef struct (\w+) (\w+) ?;$/) {
    @$it{qw(what tag name body)} = ('type', 'struct', $2, '');
  } elsif ($d =~ /^typedef (.*?) ?\( ?\* ?(\w+) ?\) ?\((.*)\) ?;$/s) {
    my ($ret, $name, $plist) = ($1, $2, $3);
    my @params;
    for my $p (split_commas($plist)) {
      next if $p eq 'void';
      if ($p =~ /^(.*?)(\w+)((?: ?\[[^\]]*\])*)$/) {
        push @params, { text => $p, type => $1, name => $2, suffix => $3 };
      } else {
        err($it->{start}, "$name: cannot read the parameter `$p'");
      }
    }
    @$it{qw(what name ret params decl)} = ('fntype', $name, $ret, \@params, $d);
  } elsif ($d !~ /[{}]/ && $d =~ /^(?:extern )?(.*?)\b(\w+) ?\((.*)\) ?;$/s) {
    my ($ret, $name, $plist) = ($1, $2, $3);
    $ret =~ s/ $//;
    my @params;
    for my $p (split_commas($plist)) {
      next if $p eq 'void';
      if ($p =~ /^(.*?)(\w+)((?: ?\[[^\]]*\])*)$/) {
        push @params, { text => $p, type => $1, name => $2, suffix => $3 };
      } else {
        err($it->{start}, "$name: cannot read the parameter `$p'");
      }
    }
    @$it{qw(what name ret params)} = ('function', $name, $ret, \@params);
  } else {
    $it->{what} = 'other';
  }
}

sub split_commas {
  my ($s) = @_;
  my @out;
  my ($cur, $depth) = ('', 0);
  for my $c (split //, $s) {
    if ($c eq ',' && $depth == 0) { push @out, $cur; $cur = ''; next }
    $depth++ if $c =~ /[(\[]/;
    $depth-- if $c =~ /[)\]]/;
    $cur .= $c;
  }
  push @out, $cur if $cur =~ /\S/;
  s/^\s+|\s+$//g for @out;
  return @out;
}

# What each doc comment documents: the next item, when only one line
# break lies between them and it is a declaration or a #define.
for my $k (0 .. $#items) {
  my $c = $items[$k];
  next unless $c->{kind} eq 'comment' && $c->{doc};
  my $next = $items[$k + 1];
  my $gap = $next ? substr($src, $c->{end}, $next->{start} - $c->{end}) : "\n\n";
  my $body = $c->{body};
  if ($body =~ /^\*\s*\@overview\b/) { $c->{role} = 'overview' }
  elsif ($body =~ /^\*\s*\@section\b/) { $c->{role} = 'section' }
  elsif ($gap !~ /\n[ \t]*\n/ && $next && ($next->{kind} eq 'define'
         || ($next->{kind} eq 'decl' && $next->{what} ne 'other'))) {
    $c->{role} = 'entry';
    $next->{doc} = $c;
  } else {
    $c->{role} = 'text';
  }
}
for my $it (@items) {
  next unless $it->{kind} eq 'decl' && $it->{what} eq 'function';
  err($it->{start}, "$it->{name}: no doc comment (/** ... */ right above it)")
    unless $it->{doc};
}

# ---------------------------------------------------------------------
# The concordance: the functions that get @implements_NAME{}.

my %implements;
if (defined $opt{concordance}) {
  open my $t, '<', $opt{concordance}
    or die "hdr2texi.pl: $opt{concordance}: $!\n";
  my $head = <$t>;
  defined $head or die "hdr2texi.pl: $opt{concordance}: empty\n";
  chomp $head;
  my @cols = split /\t/, $head;
  my @want = grep { $cols[$_] eq 'function' || $cols[$_] eq 'printed_function' } 0 .. $#cols;
  @want == 2 or die "hdr2texi.pl: $opt{concordance}: no columns function and printed_function\n";
  while (my $l = <$t>) {
    chomp $l;
    my @f = split /\t/, $l, -1;
    for my $k (@want) {
      next unless defined $f[$k];
      for my $fn (split /,/, $f[$k]) {
        $implements{$fn} = 1 unless $fn =~ /^(-|same|none|)$/;
      }
    }
  }
  close $t;
  my %declared = map { $_->{name} => 1 }
    grep { $_->{kind} eq 'decl' && $_->{what} eq 'function' } @items;
  for my $fn (sort keys %implements) {
    push @errors, "$opt{concordance}: $fn is not declared in $HDR"
      unless $declared{$fn};
  }
}

# ---------------------------------------------------------------------
# Doc comment text -> Texinfo.

# The lines of a doc comment, as [indent, text]: indent counted from the
# comment's left margin (three columns right of its `/**').
sub comment_lines {
  my ($c) = @_;
  my $base = $c->{col} + 3;
  my @raw = split /\n/, substr($c->{body}, 1), -1;
  my @lines;
  my $off = $c->{start};
  for my $k (0 .. $#raw) {
    my $l = $raw[$k];
    $l =~ s/\s+$//;
    if ($l =~ /\t/) { err($off, 'a tab in a doc comment'); $l =~ s/\t/        /g }
    if ($k == 0) { $l =~ s/^\s+//; push @lines, [0, $l]; next }
    if ($l !~ /\S/) { push @lines, [0, '']; next }
    $l =~ /^( *)/;
    my $ind = length($1) - $base;
    if ($ind < 0) {
      err($off + 1, "a doc comment's line left of its margin (column $base): `$l'");
      $ind = 0;
    }
    push @lines, [$ind, substr($l, length($1))];
  }
  shift @lines while @lines && $lines[0][1] eq '';
  pop @lines while @lines && $lines[-1][1] eq '';
  return @lines;
}

# Texinfo of the body of doc comment C; CX: {params => {name => 1},
# off => offset for messages, item => the declaration}.
sub body_texi {
  my ($c, $cx, $lines) = @_;
  my @lines = $lines ? @$lines : comment_lines($c);
  my @out;
  my @para;
  my $flush = sub {
    return unless @para;
    push @out, split /\n/, inline(join("\n", @para), $cx, 'text'), -1;
    @para = ();
  };
  my $k = 0;
  while ($k < @lines) {
    my ($ind, $l) = @{$lines[$k]};
    if ($l eq '') { $flush->(); push @out, ''; $k++; next }
    if ($ind >= 2) {                                  # an example
      $flush->();
      my @ex;
      while ($k < @lines) {
        my ($i2, $l2) = @{$lines[$k]};
        if ($l2 eq '') {
          my $m = $k;
          $m++ while $m < @lines && $lines[$m][1] eq '';
          last unless $m < @lines && $lines[$m][0] >= 2;
          push @ex, ('') x ($m - $k);
          $k = $m;
          next;
        }
        last if $i2 < 2;
        push @ex, (' ' x ($i2 - 2)) . $l2;
        $k++;
      }
      push @out, '@example', (map { texi_escape($_) } @ex), '@end example';
      next;
    }
    if ($l =~ /^- (.*)$/) {                           # a list
      $flush->();
      push @out, '@itemize @bullet';
      while ($k < @lines && $lines[$k][1] =~ /^- (.*)$/ && $lines[$k][0] == 0) {
        my @it = ($1);
        $k++;
        while ($k < @lines && $lines[$k][1] ne '' && $lines[$k][0] == 2) {
          push @it, $lines[$k][1];
          $k++;
        }
        if ($k < @lines && $lines[$k][1] ne '' && $lines[$k][0] > 0) {
          err($cx->{off}, "a list item's line indented by $lines[$k][0] (2 continues the item)");
        }
        push @out, '@item', split /\n/, inline(join("\n", @it), $cx, 'text'), -1;
      }
      push @out, '@end itemize';
      next;
    }
    if ($l =~ /^\@(\w+)(?:\s+(.*))?$/ && $LINE_CMD{$1}) {
      my ($cmd, $rest) = ($1, $2);
      $flush->();
      if ($cmd eq 'item') { push @out, '@item ' . inline($rest, $cx, 'text') }
      elsif ($cmd eq 'end' && (!defined $rest || $rest ne 'table')) {
        err($cx->{off}, "\@end $rest: only \@end table passes through");
      }
      else { push @out, $l }
      $k++;
      next;
    }
    if ($l =~ /^\@(\w+):\s*\((.*)\)\s*$/) {          # a Python annotation
      $flush->();
      err($cx->{off}, "annotation of \@$1, which is not a parameter")
        unless $cx->{params} && $cx->{params}{$1};
      $k++;
      next;
    }
    push @para, $l;
    $k++;
  }
  $flush->();
  # collapse runs of blank lines
  my @o2;
  for (@out) { push @o2, $_ unless $_ eq '' && @o2 && $o2[-1] eq '' }
  shift @o2 while @o2 && $o2[0] eq '';
  pop @o2 while @o2 && $o2[-1] eq '';
  return @o2;
}

sub texi_escape { my ($s) = @_; $s =~ s/([\@{}])/\@$1/g; return $s }

# The argument of a brace command: from pos($$sr) (after the `{') to the
# matching `}', which is consumed.
sub brace_arg {
  my ($sr, $cx) = @_;
  my ($start, $depth) = (pos($$sr), 1);
  while ($$sr =~ /\G(?:\@[{}\@]|[^{}\@]+|\@|([{}]))/gc) {
    next unless defined $1;
    $depth += $1 eq '{' ? 1 : -1;
    return substr($$sr, $start, pos($$sr) - 1 - $start) if $depth == 0;
  }
  err($cx->{off}, 'unbalanced braces: ' . substr($$sr, $start - 1, 40));
  pos($$sr) = length $$sr;
  return substr($$sr, $start);
}

# Inline markup of S (mode 'text' or 'code': inside `...`).
sub inline {
  my ($s, $cx, $mode) = @_;
  my $o = '';
  pos($s) = 0;
  my $text = $mode eq 'text';
  while (pos($s) < length $s) {
    if ($text && $s =~ /\G\$([^\$]*)\$/gc) {
      my $m = math($1, $cx);
      # TeX would reach Info as it is: the plain notation only.
      err($cx->{off}, "a backslash in \$$m\$ (write the plain notation: (V^+)', not V^{+\\prime})")
        if $m =~ /\\/;
      $o .= '@math{' . (eval { convert_math($m) } // err($cx->{off}, $@ =~ s/\n\z//r)) . '}';
    } elsif ($text && $s =~ /\G\$/gc) {
      err($cx->{off}, 'unterminated $: ' . substr($s, pos($s) - 1, 40));
    } elsif ($text && $s =~ /\G``/gc) {
      $o .= '``';
    } elsif ($text && $s =~ /\G`([^`]*)`/gc) {
      $o .= '@code{' . inline($1, $cx, 'code') . '}';
    } elsif ($text && $s =~ /\G`/gc) {
      err($cx->{off}, 'unterminated `: ' . substr($s, pos($s) - 1, 40));
    } elsif ($s =~ /\G\@([{}\@:.])/gc) {
      $o .= "\@$1";
    } elsif ($s =~ /\G\@'([A-Za-z])/gc) {
      $o .= "\@'$1";
    } elsif ($s =~ /\G\@(\w+)\{/gc) {
      my $cmd = $1;
      my $arg = brace_arg(\$s, $cx);
      if ($cmd eq 'dots' && $arg eq '') { $o .= '@dots{}' }
      elsif ($RAW_ARG{$cmd}) { $o .= "\@$cmd\{$arg\}" }
      elsif ($TEXT_ARG{$cmd}) {
        $o .= "\@$cmd\{" . inline($arg, $cx, $cmd eq 'code' ? 'code' : $mode) . '}';
      } else { err($cx->{off}, "unknown command \@$cmd\{...\}") }
    } elsif ($s =~ /\G\@(\w+)/gc) {
      if ($cx->{params} && $cx->{params}{$1}) { $o .= "\@var{$1}" }
      elsif (defined $cx->{expansion} && $1 eq 'expansion') {
        $o .= '@code{' . texi_escape($cx->{expansion}) . '}';
      } else {
        err($cx->{off}, "unknown \@$1 (not a parameter of "
            . ($cx->{what} || 'this comment') . ', nor a command)');
      }
    } elsif ($s =~ /\G\@/gc) {
      err($cx->{off}, 'a lone @ (write @@)');
    } elsif ($s =~ /\G([{}])/gc) {
      $o .= "\@$1";
    } elsif ($text && $s =~ /\G((?:$id_re)\w*)/gc) {
      $o .= "\@code{$1}";
    } elsif ($s =~ /\G(\w+|.)/gcs) {
      $o .= $1;
    }
  }
  return $o;
}

# The inside of $...$.
sub math {
  my ($m, $cx) = @_;
  my $o = '';
  pos($m) = 0;
  while (pos($m) < length $m) {
    if ($m =~ /\G([\^_])\{/gc) {
      my $op = $1;
      my $g = brace_arg(\$m, $cx);
      $o .= "$op\{$g\}";
    } elsif ($m =~ /\G`([^`]*)`/gc) {
      $o .= '@code{' . inline($1, $cx, 'code') . '}';
    } elsif ($m =~ /\G([{}])/gc) {
      $o .= "\@$1";
    } elsif ($m =~ /\G\@/gc) {
      err($cx->{off}, 'an @ in $...$');
    } elsif ($m =~ /\G([^\^_`{}\@]+|.)/gcs) {
      $o .= $1;
    }
  }
  return $o;
}

# The members of a struct or enum body and their doc comments: a doc
# comment documents the member it follows (the one being written, as an
# enum's last constant without its comma, else the last one ended).
# [[declaration, doc or undef], ...].
sub members {
  my ($it) = @_;
  my $raw = $it->{raw};
  my $open = index $raw, '{';
  my $body = substr $raw, $open + 1, rindex($raw, '}') - $open - 1;
  my $sep = $it->{tag} eq 'enum' ? ',' : ';';
  my (@m, @docs);
  my $cur = '';
  pos($body) = 0;
  while (pos($body) < length $body) {
    if ($body =~ m{\G/\*(.*?)\*/}gcs) {
      my $c = $1;
      next unless $c =~ s/^\*(?!\*)//;
      my $k = $cur =~ /\S/ ? scalar(@m) : $#m;
      if ($k < 0) { err($it->{start}, "$it->{name}: a doc comment before its first member"); next }
      push @docs, [$k, join "\n", grep { $_ ne '' } map { s/^\s+|\s+$//gr } split /\n/, $c];
    } elsif ($body =~ m{\G([^/$sep]+|/)}gc) {
      $cur .= $1;
    } else {
      $body =~ m{\G.}gcs;
      push @m, $cur;
      $cur = '';
    }
  }
  push @m, $cur if $cur =~ /\S/;
  my @out = map { [s/\s+/ /gr =~ s/^ | $//gr, undef] } @m;
  for my $d (@docs) {
    my $o = $out[$d->[0]];
    err($it->{start}, "$it->{name}: two doc comments for the member $o->[0]") if defined $o->[1];
    $o->[1] = $d->[1];
  }
  return @out;
}

# ---------------------------------------------------------------------
# The entries.

sub entry_texi {
  my ($it) = @_;
  my $c = $it->{doc};
  my @out;
  if ($it->{kind} eq 'define') {
    my $cx = { off => $c->{start}, what => $it->{name}, expansion => $it->{value} };
    push @out, "\@defmac $it->{name}", body_texi($c, $cx), '@end defmac';
  } elsif ($it->{what} eq 'function') {
    my %p = map { $_->{name} => 1 } @{$it->{params}};
    my $cx = { off => $c->{start}, params => \%p, what => $it->{name} };
    my $ret = $it->{ret} =~ / / ? "{$it->{ret}}" : $it->{ret};
    my $args = join ', ', map { "$_->{type}\@var{$_->{name}}$_->{suffix}" } @{$it->{params}};
    $args = 'void' unless @{$it->{params}};
    push @out, "\@anchor{$it->{name}}", "\@deftypefun $ret $it->{name} ($args)";
    push @out, "\@" . implements_macro ($it->{name}) . "\{\}"
      if $implements{$it->{name}};
    push @out, body_texi($c, $cx), '@end deftypefun';
  } elsif ($it->{what} eq 'fntype') {
    my %p = map { $_->{name} => 1 } @{$it->{params}};
    my $cx = { off => $c->{start}, params => \%p, what => $it->{name} };
    (my $decl = $it->{decl}) =~ s/([\@{}])/\@$1/g;
    push @out, "\@anchor{$it->{name}}", "\@deftp {Function type} $it->{name}",
      '@example', $decl, '@end example', body_texi($c, $cx), '@end deftp';
  } else {
    my $cx = { off => $c->{start}, what => $it->{name} };
    my $kind = $it->{tag} eq 'enum' ? 'Enumerated type' : 'Data type';
    my $name = $it->{name} =~ / / ? "{$it->{name}}" : $it->{name};
    push @out, "\@anchor{$it->{name}}" unless $it->{name} =~ / /;
    push @out, "\@deftp {$kind} $name";
    my @table;
    for my $m (members($it)) {
      next unless defined $m->[1];
      push @table, "\@item $m->[0]", split /\n/, inline($m->[1], $cx, 'text');
    }
    my @lines = comment_lines($c);
    my @before = @lines;
    my @after;
    for my $k (0 .. $#lines) {
      if ($lines[$k][1] eq '@fields' && $lines[$k][0] == 0) {
        @before = @lines[0 .. $k - 1];
        @after = @lines[$k + 1 .. $#lines];
        last;
      }
    }
    push @out, body_texi($c, $cx, \@before) if @before;
    push @out, '@table @code', @table, '@end table' if @table;
    push @out, body_texi($c, $cx, \@after) if @after;
    push @out, '@end deftp';
  }
  return @out;
}

# Sections: [{node, title, brief, intro => [...], chunks => [[lines]...]}].
my (@overview, @sections);
for my $it (@items) {
  if ($it->{kind} eq 'comment' && $it->{doc}) {
    my $role = $it->{role};
    next if $role eq 'entry';
    my @lines = comment_lines($it);
    my $cx = { off => $it->{start}, what => "the comment at line " . line_of($it->{start}) };
    if ($role eq 'overview') {
      shift @lines;
      err($it->{start}, 'two @overview comments') if @overview;
      @overview = body_texi($it, $cx, \@lines);
      next;
    }
    if ($role eq 'section') {
      my $first = shift @lines;
      my ($title) = $first->[1] =~ /^\@section\s+(.*\S)/;
      err($it->{start}, '@section without a title') unless defined $title;
      my %s = (title => $title, node => $title, chunks => [], off => $it->{start});
      while (@lines && $lines[0][1] =~ /^\@(node|brief)\s+(.*\S)/) {
        $s{$1} = $2;
        shift @lines;
      }
      $s{intro} = [body_texi($it, $cx, \@lines)];
      push @sections, \%s;
      next;
    }
    # free text
    if (!@sections) { err($it->{start}, 'a doc comment before the first @section'); next }
    push @{$sections[-1]{chunks}}, [body_texi($it, $cx)];
    next;
  }
  next unless $it->{doc};
  if (!@sections) { err($it->{start}, "$it->{name}: documented before the first \@section"); next }
  push @{$sections[-1]{chunks}}, [entry_texi($it)];
  push @{$sections[-1]{names}}, [($it->{kind} eq 'define' ? 'macro'
                                   : $it->{what}), $it->{name}];
}

my %node_seen;
for my $s (@sections) {
  err($s->{off}, "two sections with the node name $s->{node}") if $node_seen{$s->{node}}++;
}
for my $n (@only, keys %split) {
  push @errors, "$HDR: no section with the node name `$n'" unless $node_seen{$n};
}
@overview or !defined $opt{chapter}
  or push @errors, "$HDR: --chapter needs an \@overview doc comment";

# ---------------------------------------------------------------------
# Output.

my @out;
if ($opt{list}) {          # (what is documented, even when there are errors)
  for my $s (@sections) { push @out, "$_->[0] $_->[1]" for @{$s->{names} || []} }
  print "$_\n" for @out;
}
if (@errors) {
  print STDERR "$_\n" for @errors;
  print STDERR "hdr2texi.pl: " . scalar(@errors) . " error(s)"
    . ($opt{list} ? "\n" : "; no output\n");
  exit 1;
}
exit 0 if $opt{list};

push @out, "\@c Generated by doc/hdr2texi.pl from the doc comments of $NAME:",
  "\@c do not edit; edit the header.", '';
my %only = map { $_ => 1 } @only;
if (defined $opt{chapter}) {
  push @out, "\@node $opt{chapter}", "\@chapter $opt{chapter}", @overview, '',
    '@menu';
  for my $s (@sections) {
    my $m = "* $s->{node}::";
    push @out, defined $s->{brief} ? sprintf('%-31s %s', $m, $s->{brief}) : $m;
  }
  push @out, '@end menu', '';
}
for my $s (@sections) {
  next if @only && !$only{$s->{node}};
  if (!@only && $split{$s->{node}}) { push @out, "\@include $split{$s->{node}}", ''; next }
  push @out, "\@node $s->{node}", "\@section $s->{title}", @{$s->{intro}};
  push @out, '' if @{$s->{intro}};
  push @out, @$_, '' for @{$s->{chunks}};
}
pop @out while @out && $out[-1] eq '';
print "$_\n" for @out;
exit 0;
