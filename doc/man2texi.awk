# man2texi.awk -- convert a man(7) page into a Texinfo chapter.
#
# Usage:
#   awk -f doc/man2texi.awk tools/chaplygin.1 > doc/program.texi
#   awk -v source=tools/chaplygin.1 -f doc/man2texi.awk $(srcdir)/tools/chaplygin.1
#
# The manual's chapter "Program reference" is generated from the same
# source as the man page, tools/chaplygin.1, so that the two cannot
# drift.  The script is POSIX awk (tested with mawk, gawk --posix, the
# one true awk and busybox awk); it uses no gawk extension.
#
# Variables (-v NAME=VALUE):
#   source      the name of the man page written into the "generated
#               from" comment (default: the input file name; give it in
#               a Makefile rule so the output does not depend on $(srcdir))
#   output      the name of the generated file in that comment
#               (default: program.texi)
#   chapter     the chapter's node name and title (default: Program reference)
#   nodeprefix  prefixed to every section's node name to keep it unique
#               in the manual (default: "Program ")
#
# Output: a comment line, "@node Program reference", "@chapter Program
# reference", "@cindex program reference", "@cindex NAME (program)" (NAME
# from .TH), the NAME line as a short paragraph, a @menu of the sections,
# then every .SH as "@node Program <title in lower case>" and "@section
# <Title in sentence case>".  Each .SH is a node (not a node-less
# @heading) so that each section is an Info node and a page of the split
# HTML manual, index entries lead to the very section, and the rest of
# the manual can @ref{Program scene files}; the menu is generated, so it
# cannot drift either.  .SS becomes a @subsection without a node.  The
# SYNOPSIS section becomes an @example, one line per .br-separated line.
#
# Font mapping (one mapping everywhere, in text, tags and examples):
#   bold         (\fB, .B, .BR, .RB, .BI, .IB, .SB)  -> @code{...}
#                (in this page bold marks commands, options, scene
#                sections, keys, words and CSV columns: literal text)
#   italic       (\fI, .I, .IR, .RI, .BI, .IB)      -> @var{...}
#                (replaceable arguments; Info shows @var in capitals)
#   bold italic  (\f(BI, \f4)                       -> @var{...}
#   constant width (\f(CW, \f(CR, \f(CB, \fC)       -> @code{...}
#   roman        (\fR, \f1, \fP back to roman)      -> plain text
# Spaces at either end of a font run are moved out of the braces.
#
# Supported macros: .TH (its title and section only go into comments and
# the "(program)" index entry), .SH, .SS, .PP, .P, .LP, .HP, .TP, .TQ,
# .IP (a bullet tag such as \(bu, * or - gives an @itemize @bullet item,
# another tag a @table @item; without a tag, a new paragraph of the
# current item, or an @indentedblock outside a list), .RS/.RE (nested
# tables; an .RS outside a table item gives an @indentedblock), .nf/.fi
# and .EX/.EE (@example), .B, .I, .SB, .SM, .BR, .RB, .BI, .IB, .IR, .RI,
# .br, .sp, .ft, .UR/.UE (@uref), .MT/.ME (@email), .SY/.OP/.YS (synopsis
# lines), comments (.\" and .\#), and, ignored as they only tune the
# layout: .PD .ne .ad .na .hy .nh .hw .ns .rs .bp .fl .lf .ll .ta .DT .UC
# .AT .ss .cs .ps .vs.
# Supported escapes: \fX \f(XX \f[X] (the fonts above), \- \e \\ \& \|
# \^ \: (a break point: @/) \~ \0 and "\ " (@tie{}), \% \c \" \# \s (size,
# ignored), \' \` \. \t, \(xx and \[xx] for em en aq dq lq rq oq cq bu co
# rg tm mi hy pl mu eq <= >= +- -> <- de ha ti rs sl at lB rB lC rC ga ul
# and \[uXXXX], \*(lq \*(rq \*R \*(Tm.  The Texinfo specials @ { } are
# escaped, and "--", "``", "''" in roman and italic text are kept from
# becoming dashes and quotes.
#
# Index entries: every .TP/.TQ tag in the sections listed in IDXCMD
# below (SCENE FILES, OUTPUT, EXIT STATUS, ENVIRONMENT) gets an index
# entry, one per comma-separated name of the tag with parenthesised
# remarks dropped: "@vindex collisions (scene key)", "@cindex Dense
# (output)", "@cindex exit status 2", "@vindex OMP_NUM_THREADS".
#
# Errors: any other macro, escape, named glyph or font, and any roff
# request (.de .if .so .ds ...), is reported on standard error as
# FILE:LINE: message; then nothing is printed and the exit status is 1,
# so that a new unsupported construct is noticed.  A Makefile rule should
# write to a temporary file and rename it on success, e.g.
#   $(srcdir)/doc/program.texi: tools/chaplygin.1 doc/man2texi.awk
#   	$(AWK) -v source=tools/chaplygin.1 -f $(srcdir)/doc/man2texi.awk \
#   	  $(srcdir)/tools/chaplygin.1 > $@.tmp && mv $@.tmp $@
#
# Limits: no tbl, eqn or pic; no user macros, strings, registers or
# conditionals; .RS inside a tagged paragraph adds no indentation by
# itself (a nested .TP list does); .in/.ti are not supported; the man
# page's header and footer (.TH date, source, manual) and the word NAME
# are not shown; section titles in capitals are put in sentence case
# ("SEE ALSO" -> "See also", but also "CSV OUTPUT" -> "Csv output").

BEGIN {
	if (output == "") output = "program.texi"
	if (chapter == "") chapter = "Program reference"
	if (nodeprefix == "") nodeprefix = "Program "
	# index entries for the tags of these sections: command and format
	IDXCMD["SCENE FILES"] = "@vindex"; IDXFMT["SCENE FILES"] = "%s (scene key)"
	IDXCMD["OUTPUT"] = "@cindex"; IDXFMT["OUTPUT"] = "%s (output)"
	IDXCMD["EXIT STATUS"] = "@cindex"; IDXFMT["EXIT STATUS"] = "exit status %s"
	IDXCMD["ENVIRONMENT"] = "@vindex"; IDXFMT["ENVIRONMENT"] = "%s"
	# fonts: the Texinfo command opening a run (roman: none)
	OPEN["B"] = "@code{"; OPEN["I"] = "@var{"; OPEN["BI"] = "@var{"
	OPEN["CW"] = "@code{"
	CODEFONT["B"] = 1; CODEFONT["CW"] = 1
	FONTNAME["R"] = "R"; FONTNAME["1"] = "R"
	FONTNAME["B"] = "B"; FONTNAME["3"] = "B"
	FONTNAME["I"] = "I"; FONTNAME["2"] = "I"
	FONTNAME["BI"] = "BI"; FONTNAME["4"] = "BI"
	FONTNAME["CW"] = "CW"; FONTNAME["CR"] = "CW"; FONTNAME["C"] = "CW"
	FONTNAME["CB"] = "CW"; FONTNAME["CI"] = "I"
	# named glyphs \(xx and \[xx]
	GLYPH["em"] = "---"; GLYPH["en"] = "--"; GLYPH["aq"] = "@U{0027}"
	GLYPH["dq"] = "\""; GLYPH["lq"] = "``"; GLYPH["rq"] = "''"
	GLYPH["oq"] = "`"; GLYPH["cq"] = "'"; GLYPH["bu"] = "@bullet{}"
	GLYPH["co"] = "@copyright{}"; GLYPH["rg"] = "@registeredsymbol{}"
	GLYPH["tm"] = "@U{2122}"; GLYPH["mi"] = "-"; GLYPH["hy"] = "-"
	GLYPH["pl"] = "+"; GLYPH["mu"] = "@U{00D7}"; GLYPH["eq"] = "="
	GLYPH["<="] = "@U{2264}"; GLYPH[">="] = "@U{2265}"
	GLYPH["+-"] = "@U{00B1}"; GLYPH["->"] = "@U{2192}"
	GLYPH["<-"] = "@U{2190}"; GLYPH["de"] = "@U{00B0}"; GLYPH["ha"] = "^"
	GLYPH["ti"] = "~"; GLYPH["rs"] = "\\"; GLYPH["sl"] = "/"
	GLYPH["at"] = "@@"; GLYPH["lB"] = "["; GLYPH["rB"] = "]"
	GLYPH["lC"] = "@{"; GLYPH["rC"] = "@}"; GLYPH["ga"] = "`"
	GLYPH["ul"] = "_"
	STRING["lq"] = "``"; STRING["rq"] = "''"; STRING["R"] = "@registeredsymbol{}"
	STRING["Tm"] = "@U{2122}"
	# requests that only tune the layout
	split("PD ne ad na hy nh hw ns rs bp fl lf ll ta DT UC AT ss cs ps vs", Tmp, " ")
	for (Ti in Tmp) IGNORED[Tmp[Ti]] = 1
	n = 0; nerr = 0; nsec = 0; menuat = 0
	font = "R"; prevfont = "R"
	level = 0; env[0] = ""; rsind[0] = 0
	mode = "fill"; join = ""; trap = ""; trapfont = ""; urmode = ""; urtext = ""
	synbuf = ""; synopen = 0; synjoin = 0; exinsyn = 0; syclose = 0; namebuf = ""
	thtitle = ""; thsec = ""
	joinnext = 0; lasttext = 0; afteritem = 0; sect = ""; started = 0
}

# ---- output buffer -------------------------------------------------------

function emit(s) { OUT[++n] = s; lasttext = 0; joinnext = 0; afteritem = 0 }

function emit_text(t) {
	if (joinnext && lasttext && n > 0) OUT[n] = OUT[n] t
	else OUT[++n] = t
	lasttext = 1; joinnext = CONT; afteritem = 0
}

function err(msg) {
	print FILENAME ":" FNR ": " msg | "cat 1>&2"
	nerr++
}

# ---- inline text: escapes and fonts --------------------------------------

# close the current font run into RES
function flushrun(   lead, trail, core) {
	if (GBUF == "") return
	if (font == "R" || !(font in OPEN)) { RES = RES GBUF; GBUF = ""; return }
	core = GBUF; lead = ""; trail = ""
	while (substr(core, 1, 1) == " ") { lead = lead " "; core = substr(core, 2) }
	while (core != "" && substr(core, length(core)) == " ") {
		trail = trail " "; core = substr(core, 1, length(core) - 1)
	}
	if (core == "") RES = RES GBUF
	else RES = RES lead OPEN[font] core "}" trail
	GBUF = ""
}

function setfont(f) {
	if (f == "P") f = prevfont
	if (f == font) return
	flushrun()
	prevfont = font; font = f; LASTCH = ""
}

# append Texinfo text T (already escaped) to the current run; C is the
# source character for the ligature check ("" for none)
function add(t, c) {
	if (c != "" && c == LASTCH && index("-`'", c) && !(font in CODEFONT) && mode != "example")
		t = "@w{}" t
	GBUF = GBUF t; PLAIN = PLAIN t; LASTCH = c
}

# convert a line of roff text S to Texinfo; sets PLAIN (the text without
# font commands) and CONT (the line ended with \c)
function inline(s,   i, L, c, d, name, j, f) {
	RES = ""; GBUF = ""; PLAIN = ""; CONT = 0; LASTCH = ""
	L = length(s)
	for (i = 1; i <= L; i++) {
		c = substr(s, i, 1)
		if (c != "\\") {
			if (c == "@" || c == "{" || c == "}") add("@" c, c)
			else if (c == "\t" && mode != "example") add(" ", " ")
			else add(c, c)
			continue
		}
		i++; d = substr(s, i, 1)
		if (d == "f") {
			i++; c = substr(s, i, 1)
			if (c == "(") { name = substr(s, i + 1, 2); i += 2 }
			else if (c == "[") {
				j = index(substr(s, i + 1), "]")
				if (j == 0) { err("unterminated \\f["); break }
				name = substr(s, i + 1, j - 1); i += j
				if (name == "") name = "P"
			} else name = c
			if (name == "P") f = "P"
			else if (name in FONTNAME) f = FONTNAME[name]
			else { err("unsupported font \\f" (c == "(" || c == "[" ? c : "") name (c == "[" ? "]" : "")); continue }
			setfont(f)
		} else if (d == "-") add("-", "-")
		else if (d == "(" || d == "[") {
			if (d == "(") { name = substr(s, i + 1, 2); i += 2 }
			else {
				j = index(substr(s, i + 1), "]")
				if (j == 0) { err("unterminated \\["); break }
				name = substr(s, i + 1, j - 1); i += j
			}
			if (name in GLYPH) add(GLYPH[name], name == "mi" || name == "hy" ? "-" : "")
			else if (d == "[" && name ~ /^u[0-9A-F][0-9A-F][0-9A-F][0-9A-F]$/)
				add("@U{" substr(name, 2) "}", "")
			else err("unsupported glyph \\" d name (d == "[" ? "]" : ""))
		} else if (d == "*") {
			i++; c = substr(s, i, 1)
			if (c == "(") { name = substr(s, i + 1, 2); i += 2 }
			else if (c == "[") {
				j = index(substr(s, i + 1), "]")
				if (j == 0) { err("unterminated \\*["); break }
				name = substr(s, i + 1, j - 1); i += j
			} else name = c
			if (name in STRING) add(STRING[name], "")
			else err("unsupported string \\*" (c == "(" || c == "[" ? c : "") name (c == "[" ? "]" : ""))
		} else if (d == "e" || d == "E" || d == "\\") add("\\", "\\")
		else if (d == "&" || d == "|" || d == "^" || d == "%" || d == ")") ;
		else if (d == ":") add("@/", "")
		else if (d == "~" || d == " " || d == "0") add("@tie{}", "")
		else if (d == "\"") break
		else if (d == "#") { CONT = 1; break }
		else if (d == "c") { CONT = 1; break }
		else if (d == "s") {
			# \sN \s+N \s-N \s(NN \s[N] \s'N'
			c = substr(s, i + 1, 1)
			if (c == "+" || c == "-") { i++; c = substr(s, i + 1, 1) }
			if (c == "(") i += 3
			else if (c == "[" || c == "'") {
				j = index(substr(s, i + 2), c == "[" ? "]" : "'")
				i += j + 1
			} else if (c ~ /[0-9]/) i++
			else err("bad size escape \\s" c)
		}
		else if (d == "'") add("'", "'")
		else if (d == "`") add("`", "`")
		else if (d == ".") add(".", ".")
		else if (d == "t") add(" ", " ")
		else if (d == "") add("\\", "\\")	# a lone backslash at the end
		else err("unsupported escape \\" d)
	}
	flushrun()
	return RES
}

# ---- block structure -----------------------------------------------------

function close_env(l) {
	if (env[l] == "table") emit("@end table")
	else if (env[l] == "itemize") emit("@end itemize")
	else if (env[l] == "indent") emit("@end indentedblock")
	env[l] = ""
}

# make the environment of the current level a table or a bullet list
function open_env(kind) {
	if (env[level] == kind) return
	close_env(level)
	emit(kind == "table" ? "@table @asis" : "@itemize @bullet")
	env[level] = kind
}

function pop_level() {
	close_env(level)
	if (rsind[level]) emit("@end indentedblock")
	rsind[level] = 0
	level--
}

function end_example() {
	if (mode == "example") {
		if (!exinsyn) emit("@end example")
		mode = "fill"; exinsyn = 0
	}
}

function syn_flush() {
	if (synbuf != "") { emit(synbuf); synbuf = "" }
}

# end the synopsis block (at a section end, .YS or a structural macro)
function end_join(   p, names, desc, t) {
	if (join == "synopsis") {
		syn_flush()
		if (mode == "example" && exinsyn) { mode = "fill"; exinsyn = 0 }
		if (synopen) emit("@end example")
		synopen = 0
	} else if (join == "name") {
		p = index(namebuf, "\\-")
		if (p) {
			names = substr(namebuf, 1, p - 1); desc = substr(namebuf, p + 2)
			sub(/^[ \t]+/, "", names); sub(/[ \t]+$/, "", names)
			sub(/^[ \t]+/, "", desc)
			t = "@command{" inline(names) "} --- " inline(desc)
		} else t = inline(namebuf)
		if (namebuf != "") { emit(""); emit_text(t); emit("") }
		namebuf = ""
	}
	join = ""
}

function close_all() {
	end_join()
	end_example()
	if (urmode != "") end_ur("")
	while (level > 0) pop_level()
	close_env(0)
	trap = ""; trapfont = ""
	font = "R"; prevfont = "R"
}

function in_syn() {
	if (join != "synopsis") return 0
	if (!synopen) { emit("@example"); synopen = 1 }
	return 1
}

# a structural macro inside the synopsis ends its @example
function structural() { if (join == "synopsis") end_join() }

# ---- text ----------------------------------------------------------------

function sentence_case(s) {
	if (s ~ /[a-z]/) return s
	return toupper(substr(s, 1, 1)) tolower(substr(s, 2))
}

function heading(raw,   t, p, title, node, base, k) {
	t = inline(raw); p = PLAIN
	sub(/^[ \t]+/, "", p); sub(/[ \t]+$/, "", p)
	sect = toupper(p)
	if (sect == "NAME" && !started) { join = "name"; namebuf = ""; return }
	title = (p ~ /[a-z]/) ? t : sentence_case(p)
	node = (p ~ /[a-z]/) ? p : tolower(p)
	gsub(/@[a-zA-Z]+\{[^}]*\}/, "", node)
	gsub(/[@{}.,:()]/, "", node)
	gsub(/[ \t]+/, " ", node); sub(/^ /, "", node); sub(/ $/, "", node)
	base = nodeprefix node; node = base
	for (k = 2; node in NODEUSED; k++) node = base " " k
	NODEUSED[node] = 1
	if (!menuat) menuat = n
	started = 1
	SECNODE[++nsec] = node
	emit(""); emit("@node " node); emit("@section " title)
	emit("")
	if (sect == "SYNOPSIS") { join = "synopsis"; synbuf = ""; synopen = 0 }
}

function item(t, p, kind, index_it,   terms, k, m, e) {
	sub(/^[ \t]+/, "", t); sub(/[ \t]+$/, "", t)
	emit((kind == "TQ" ? "@itemx" : "@item") (t == "" ? "" : " " t))
	afteritem = 1
	if (!index_it || !(sect in IDXCMD)) return
	gsub(/\([^()]*\)/, "", p)
	m = split(p, terms, ",")
	for (k = 1; k <= m; k++) {
		e = terms[k]
		gsub(/@tie\{\}/, " ", e); gsub(/@\//, "", e)
		sub(/^[ \t]+/, "", e); sub(/[ \t]+$/, "", e)
		if (e != "") emit(IDXCMD[sect] " " sprintf(IDXFMT[sect], e))
	}
	afteritem = 1
}

# every piece of text, from a text line or a font macro, comes here
function text(s,   t, k) {
	if (trapfont != "") { s = "\\f[" trapfont "]" s "\\f[" font "]"; trapfont = "" }
	if (trap == "SH") { trap = ""; heading(s); return }
	if (trap == "SS") { trap = ""; subheading(s); return }
	if (join == "name") { namebuf = namebuf (namebuf == "" ? "" : " ") s; return }
	t = inline(s)
	if (trap == "TP" || trap == "TQ") { k = trap; trap = ""; item(t, PLAIN, k, 1); return }
	if (urmode != "") { urtext = urtext (urtext == "" ? "" : " ") t; return }
	if (in_syn() && mode != "example") {
		if (synbuf != "" && !synjoin) synbuf = synbuf " "
		synbuf = synbuf t; synjoin = CONT
		return
	}
	if (mode == "example") { emit(t); return }
	sub(/^ +/, "", t); sub(/ +$/, "", t)
	emit_text(t)
}

function subheading(raw,   t) {
	t = inline(raw)
	sub(/^[ \t]+/, "", t)
	emit(""); emit("@subsection " t); emit("")
}

function br() {
	if (join == "synopsis") { syn_flush(); synjoin = 0; return }
	if (mode == "example") return
	if (lasttext && n > 0 && OUT[n] !~ /@\*$/) OUT[n] = OUT[n] "@*"
}

function para() {
	if (join == "synopsis") { syn_flush(); if (synopen) emit(""); return }
	if (mode == "example") { emit(""); return }
	if (urmode != "") end_ur("")
	close_env(level)
	emit("")
}

function end_ur(trail,   t, u) {
	u = inline(urarg); gsub(/,/, "@comma{}", u)
	t = urtext; gsub(/,/, "@comma{}", t)
	if (urmode == "UR") t = (t == "" ? "@uref{" u "}" : "@uref{" u ", " t "}")
	else t = (t == "" ? "@email{" u "}" : "@email{" u ", " t "}")
	urmode = ""; urtext = ""
	emit_text(t inline(trail))
}

# ---- macros --------------------------------------------------------------

# split the arguments of a macro line into A[1..NA] (roff quoting rules)
function parseargs(s,   i, L, c, a, q) {
	NA = 0; L = length(s); i = 1
	while (i <= L) {
		while (i <= L && (substr(s, i, 1) == " " || substr(s, i, 1) == "\t")) i++
		if (i > L) break
		if (substr(s, i, 2) == "\\\"") break
		a = ""
		if (substr(s, i, 1) == "\"") {
			i++
			while (i <= L) {
				c = substr(s, i, 1)
				if (c == "\"") {
					if (substr(s, i + 1, 1) == "\"") { a = a "\""; i += 2; continue }
					i++; break
				}
				if (c == "\\") { a = a substr(s, i, 2); i += 2; continue }
				a = a c; i++
			}
		} else {
			while (i <= L) {
				c = substr(s, i, 1)
				if (c == " " || c == "\t") break
				if (c == "\\") {
					if (substr(s, i + 1, 1) == "\"") { i = L + 1; break }
					a = a substr(s, i, 2); i += 2; continue
				}
				a = a c; i++
			}
		}
		A[++NA] = a
	}
}

function joinargs(   k, s) {
	s = ""
	for (k = 1; k <= NA; k++) s = s (k > 1 ? " " : "") A[k]
	return s
}

function alternate(f1, f2,   k, s, cur) {
	if (NA == 0) return
	cur = font; s = ""
	for (k = 1; k <= NA; k++) s = s "\\f[" (k % 2 ? f1 : f2) "]" A[k]
	text(s "\\f[" cur "]")
}

function macro(line,   name, rest, k, target) {
	sub(/^[.'][ \t]*/, "", line)
	name = line; sub(/[ \t].*/, "", name)
	rest = substr(line, length(name) + 1)
	parseargs(rest)
	if (name == "TH") {
		thtitle = A[1]; thsec = A[2]
		return
	}
	if (name == "SH" || name == "SS") {
		close_all()
		if (NA == 0) { trap = name; return }
		if (name == "SH") heading(joinargs()); else subheading(joinargs())
		return
	}
	if (name == "PP" || name == "P" || name == "LP" || name == "HP") {
		para(); font = "R"; prevfont = "R"
		return
	}
	if (name == "TP" || name == "TQ") {
		structural()
		if (mode == "example") { err("." name " inside .nf/.EX"); return }
		# .TQ: a further tag of the same item (after body text, a new item)
		if (name == "TQ" && env[level] == "table" && afteritem) { trap = "TQ"; return }
		open_env("table")
		trap = "TP"
		return
	}
	if (name == "IP") {
		structural()
		if (mode == "example") { err(".IP inside .nf/.EX"); return }
		if (NA >= 1 && A[1] ~ /^(\\\(bu|\\\[bu\]|\*|-|\\-|\\\(em|\\\[em\]|o|\\\(ci)$/) {
			# a bullet: @itemize
			open_env("itemize"); emit("@item")
		} else if (NA >= 1 && A[1] != "") {
			open_env("table")
			item(inline(A[1]), PLAIN, "TP", 0)
		} else if (env[level] == "") { emit("@indentedblock"); env[level] = "indent" }
		else emit("")
		return
	}
	if (name == "RS") {
		structural()
		if (mode == "example") { err(".RS inside .nf/.EX"); return }
		k = level + 1
		rsind[k] = (env[level] != "table" && env[level] != "itemize")
		if (rsind[k]) emit("@indentedblock")
		env[k] = ""
		level = k
		return
	}
	if (name == "RE") {
		if (mode == "example") { err(".RE inside .nf/.EX"); return }
		target = (NA >= 1 && A[1] ~ /^[0-9]+$/) ? A[1] - 1 : level - 1
		if (target < 0) target = 0
		while (level > target) pop_level()
		return
	}
	if (name == "nf" || name == "EX") {
		if (mode == "example") return
		if (join == "synopsis") { in_syn(); syn_flush(); exinsyn = 1 }
		else { emit("@example"); exinsyn = 0 }
		mode = "example"
		return
	}
	if (name == "fi" || name == "EE") { end_example(); return }
	if (name == "br") { br(); return }
	if (name == "sp") { para(); return }
	if (name == "B" || name == "SB") {
		if (NA == 0) trapfont = "B"
		else text("\\f[B]" joinargs() "\\f[" font "]")
		return
	}
	if (name == "I") {
		if (NA == 0) trapfont = "I"
		else text("\\f[I]" joinargs() "\\f[" font "]")
		return
	}
	if (name == "SM") { if (NA > 0) text(joinargs()); return }
	if (name == "BR") { alternate("B", "R"); return }
	if (name == "RB") { alternate("R", "B"); return }
	if (name == "BI") { alternate("B", "I"); return }
	if (name == "IB") { alternate("I", "B"); return }
	if (name == "IR") { alternate("I", "R"); return }
	if (name == "RI") { alternate("R", "I"); return }
	if (name == "ft") {
		k = (NA == 0) ? "P" : A[1]
		if (k == "P" || k in FONTNAME) {
			if (k != "P") k = FONTNAME[k]
			if (k == "P") k = prevfont
			prevfont = font; font = k
		} else err("unsupported font .ft " k)
		return
	}
	if (name == "UR" || name == "MT") {
		if (urmode != "") end_ur("")
		urmode = (name == "UR") ? "UR" : "MT"; urarg = A[1]; urtext = ""
		return
	}
	if (name == "UE" || name == "ME") {
		if (urmode != "") end_ur(joinargs())
		return
	}
	if (name == "SY") {
		if (join != "synopsis") { close_env(level); join = "synopsis"; synopen = 0; syclose = 1 }
		in_syn(); syn_flush()
		synbuf = inline("\\fB" joinargs() "\\fR"); synjoin = 0
		return
	}
	if (name == "OP") {
		in_syn()
		k = "[\\fB" A[1] "\\fR"
		if (NA >= 2) k = k " \\fI" A[2] "\\fR"
		synbuf = synbuf (synbuf == "" ? "" : " ") inline(k "]")
		return
	}
	if (name == "YS") {
		if (join == "synopsis") { syn_flush(); if (syclose) { end_join(); syclose = 0 } }
		return
	}
	if (name in IGNORED) return
	err("unsupported macro ." name)
}

# ---- main loop -----------------------------------------------------------

{
	Ln = $0
	sub(/\r$/, "", Ln)
	if (Ln ~ /^[.'][ \t]*\\["#]/) next		# comment line
	if (Ln ~ /^[.'][ \t]*$/) next			# empty request
	if (Ln ~ /^[.'][ \t]*[A-Za-z]/) { macro(Ln); next }
	if (Ln ~ /^[.']/) { err("unsupported control line " Ln); next }
	if (Ln ~ /^[ \t]*$/ && mode != "example") {
		if (trap == "" && join != "name") para()
		next
	}
	if (Ln ~ /^[ \t]/ && mode != "example" && join == "") br()
	text(Ln)
}

END {
	close_all()
	if (nerr) {
		print "man2texi.awk: " nerr " error(s); no output written" | "cat 1>&2"
		close("cat 1>&2")
		exit 1
	}
	if (source == "") source = FILENAME
	Prog = tolower(thtitle)
	print "@c " output " -- generated from " source " by doc/man2texi.awk: do not edit."
	if (thtitle != "") print "@c " thtitle "(" thsec ")"
	print "@node " chapter
	print "@chapter " chapter
	print "@cindex " tolower(chapter)
	if (Prog != "") print "@cindex " Prog " (program)"
	if (!menuat) menuat = n
	# the menu goes before the first section; runs of blank lines are
	# printed as one
	Blank = 0
	for (Ek = 1; Ek <= n; Ek++) {
		if (Ek == menuat + 1 && nsec) {
			if (!Blank) print ""
			print "@menu"
			for (Ej = 1; Ej <= nsec; Ej++) print "* " SECNODE[Ej] "::"
			print "@end menu"
			Blank = 0
		}
		if (OUT[Ek] == "") { if (!Blank) print ""; Blank = 1 }
		else { print OUT[Ek]; Blank = 0 }
	}
}
