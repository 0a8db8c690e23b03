## doc/local.mk -- the Texinfo manual, the concordance and the errata.
info_TEXINFOS = doc/chaplygin.texi
doc_chaplygin_TEXINFOS = doc/notation.texi doc/conventions.texi \
	doc/methods.texi doc/concordance.texi doc/errata.texi \
	doc/accuracy.texi doc/figures.texi doc/atlas.texi \
	doc/bench.texi doc/bench-table.texi doc/python.texi $(GENERATED_TEXINFOS)

# Images are named by their file name alone (@image{fig6,...}) and found
# in doc/figures: the HTML manual then holds them beside its pages.
AM_MAKEINFOFLAGS = -I $(srcdir)/doc/figures
# The PDF manual (`make pdf', optional: TeX): automake puts the directory
# of TEXINFO_TEX first on TeX's path, so naming one in doc/figures lets
# TeX find the figures (@image) there; no texinfo.tex is there, and TeX
# takes the system's (Debian's texinfo).
TEXINFO_TEX = doc/figures/texinfo.tex
# Without TeX (configure), doc/no-tex.sh stands in for texi2dvi: `make
# pdf' (and `make dvi') stop with one line naming the packages to install.
if !HAVE_TEX
doc/chaplygin.pdf doc/chaplygin.dvi: TEXI2DVI = $(SHELL) $(srcdir)/doc/no-tex.sh
endif
# The HTML pages: formulas typeset by the local MathJax 2 that configure
# found (MATHJAX_SCRIPT, a file: no page loads a remote script); a figure
# (1200 pixels wide) shrinks to the window.
if HAVE_MATHJAX
MATHJAX_HTMLFLAGS = -c HTML_MATH=mathjax -c 'MATHJAX_SCRIPT=$(MATHJAX_SCRIPT)'
endif
AM_MAKEINFOHTMLFLAGS = $(AM_MAKEINFOFLAGS) $(MATHJAX_HTMLFLAGS) \
	-c 'EXTRA_HEAD=<style>img { max-width: 100%; height: auto; }</style>'

# The figures of `make figures' (tools/local.mk) and the work-precision
# diagram of `make bench' (bench/local.mk), committed.
MANUAL_FIGURES = doc/figures/fig2a.png doc/figures/fig2b.png \
	doc/figures/fig3.png doc/figures/fig4.png doc/figures/fig5.png \
	doc/figures/fig6.png doc/figures/fig7.png doc/figures/fig8.png \
	doc/figures/fig9.png doc/figures/fig10.png \
	doc/figures/atlas-omega.png doc/figures/atlas-bistable.png \
	doc/figures/work-precision.png
EXTRA_DIST += $(MANUAL_FIGURES) \
	doc/man2texi.awk doc/check-html.pl doc/check-html.sh doc/hdr2texi.pl \
	doc/check-texi-math.sh \
	doc/texi-math.pl doc/no-tex.sh lib/TexinfoMath.pm \
	doc/check-math.pl
# Generated from lib/labels.txt (below), installed and distributed.
dist_doc_DATA = doc/concordance.tsv

# ---- generated parts of the manual --------------------------------------
# Written into the source tree and distributed (like version.texi), each
# from its one source: from the registry of the paper's labels,
# lib/labels.txt (by lib/labels.pl), the concordance chapter, the errata's
# audit table, the library reference's links back to the concordance and
# doc/concordance.tsv; the program reference from the man page's source
# (doc/man2texi.awk); the library reference from the doc comments of
# lib/chaplygin.h (doc/hdr2texi.pl).  A generator that fails leaves no file
# behind (lib/labels.pl -o renames a complete temporary file).
GENERATED_TEXINFOS = doc/concordance-entries.texi doc/audit-table.texi \
	doc/concordance-macros.texi doc/program.texi doc/api.texi \
	doc/api-printed.texi doc/api-scene.texi doc/math-macros.texi \
	doc/claims.texi doc/claims-figures.texi
LABELS_DEPS = $(srcdir)/lib/labels.txt $(srcdir)/lib/labels.pl \
	$(srcdir)/lib/TexinfoName.pm $(srcdir)/lib/TexinfoMath.pm \
	$(srcdir)/lib/Registry.pm
# The formulas' macros (plain notation in Info, TeX elsewhere), from the
# converter's table (lib/TexinfoMath.pm); doc/texi-math.pl converts a
# chapter's formulas into them.
$(srcdir)/doc/math-macros.texi: $(srcdir)/lib/TexinfoMath.pm \
		$(srcdir)/doc/texi-math.pl
	$(AM_V_GEN)perl $(srcdir)/doc/texi-math.pl --macros > $@.tmp \
	  && mv $@.tmp $@ || { rm -f $@.tmp; exit 1; }
LABELS_GEN = $(PERL) $(srcdir)/lib/labels.pl
CONCORDANCE_INPUTS = $(srcdir)/doc/accuracy.texi $(srcdir)/doc/errata.texi \
	$(wildcard $(srcdir)/tests/*.c)

$(srcdir)/doc/concordance-entries.texi: $(LABELS_DEPS) $(CONCORDANCE_INPUTS)
	$(AM_V_GEN)$(LABELS_GEN) -o $@ entries $(srcdir)/lib/labels.txt \
	  $(CONCORDANCE_INPUTS)
$(srcdir)/doc/audit-table.texi: $(LABELS_DEPS) $(srcdir)/doc/errata.texi
	$(AM_V_GEN)$(LABELS_GEN) -o $@ audit $(srcdir)/lib/labels.txt \
	  $(srcdir)/doc/errata.texi
$(srcdir)/doc/concordance-macros.texi: $(LABELS_DEPS)
	$(AM_V_GEN)$(LABELS_GEN) -o $@ macros $(srcdir)/lib/labels.txt
$(srcdir)/doc/concordance.tsv: $(LABELS_DEPS)
	$(AM_V_GEN)$(LABELS_GEN) -o $@ tsv $(srcdir)/lib/labels.txt
# The chapter "Library reference", and its section of the paper's printed
# forms in a file of its own; @implementsFunction{} (lib/TexinfoName.pm) after the entry of
# every function of the concordance.  (tests/apiref.sh runs the same
# invocations and checks the files against them.)
HDR2TEXI = perl $(srcdir)/doc/hdr2texi.pl --name=lib/chaplygin.h \
	--concordance=$(srcdir)/doc/concordance.tsv
APIREF_INPUTS = $(srcdir)/lib/chaplygin.h $(srcdir)/doc/hdr2texi.pl \
	$(srcdir)/lib/TexinfoName.pm $(srcdir)/lib/TexinfoMath.pm \
	$(srcdir)/doc/concordance.tsv
$(srcdir)/doc/api.texi: $(APIREF_INPUTS)
	$(AM_V_GEN)$(HDR2TEXI) --chapter='Library reference' \
	  --split='Printed forms=api-printed.texi' $(srcdir)/lib/chaplygin.h \
	  > $@.tmp && mv $@.tmp $@ || { rm -f $@.tmp; exit 1; }
# The chapter "Scene engine reference" from lib/scene/chaplygin-scene.h.
$(srcdir)/doc/api-scene.texi: $(srcdir)/lib/scene/chaplygin-scene.h \
		$(srcdir)/doc/hdr2texi.pl $(srcdir)/lib/TexinfoMath.pm
	$(AM_V_GEN)perl $(srcdir)/doc/hdr2texi.pl \
	  --name=lib/scene/chaplygin-scene.h --chapter='Scene engine reference' \
	  $(srcdir)/lib/scene/chaplygin-scene.h \
	  > $@.tmp && mv $@.tmp $@ || { rm -f $@.tmp; exit 1; }
$(srcdir)/doc/api-printed.texi: $(APIREF_INPUTS)
	$(AM_V_GEN)$(HDR2TEXI) --only='Printed forms' \
	  $(srcdir)/lib/chaplygin.h \
	  > $@.tmp && mv $@.tmp $@ || { rm -f $@.tmp; exit 1; }
# @pkgdatadir@ reads "pkgdatadir" in the manual (the man page gets the
# configured directory).
$(srcdir)/doc/program.texi: $(srcdir)/tools/chaplygin.1.in \
		$(srcdir)/doc/man2texi.awk
	$(AM_V_GEN)sed -e 's/@pkgdatadir@/\\fIpkgdatadir\\fP/g' \
	  $(srcdir)/tools/chaplygin.1.in | $(AWK) -v source=tools/chaplygin.1.in \
	  -f $(srcdir)/doc/man2texi.awk \
	  > $@.tmp && mv $@.tmp $@

# ---- the HTML manual ------------------------------------------------------
# `make html' builds the split manual doc/chaplygin.html/ (automake's
# rule); doc/html.stamp then puts the figures and a single-page edition,
# one-page.html, into that directory, so that every image and link
# resolves there, in the build tree as once installed (automake's
# install-html installs every file of the directory).
doc/one-page.html: $(srcdir)/doc/chaplygin.texi $(srcdir)/doc/version.texi \
		$(doc_chaplygin_TEXINFOS)
	$(AM_V_MAKEINFO)$(MKDIR_P) doc && $(MAKEINFOHTML) \
	  $(AM_MAKEINFOHTMLFLAGS) $(MAKEINFOFLAGS) --no-split -I doc \
	  -I $(srcdir)/doc -o $@.tmp $(srcdir)/doc/chaplygin.texi \
	  && mv $@.tmp $@
doc/html.stamp: $(HTMLS) doc/one-page.html $(MANUAL_FIGURES)
	$(AM_V_GEN)for f in $(MANUAL_FIGURES); do \
	  cp "$(srcdir)/$$f" doc/chaplygin.html/ || exit 1; \
	done && cp doc/one-page.html doc/chaplygin.html/ && touch $@
html-local: doc/html.stamp
install-html-local: doc/html.stamp
	@$(NORMAL_INSTALL)
	$(MKDIR_P) "$(DESTDIR)$(htmldir)/chaplygin.html"
	$(INSTALL_DATA) doc/chaplygin.html/one-page.html \
	  "$(DESTDIR)$(htmldir)/chaplygin.html"
	for f in $(MANUAL_FIGURES); do \
	  $(INSTALL_DATA) "$(srcdir)/$$f" "$(DESTDIR)$(htmldir)/chaplygin.html" \
	    || exit 1; \
	done
# `make install' installs the HTML manual too: it is the edition most
# readers open (figures, links), not only the Info one.
install-data-local: install-html
# With MathJax, texi2any writes the pages' JavaScript licences beside its
# output: doc/js_licenses.html beside one-page.html (the split manual's own
# copy, which one-page.html links once copied, is in its directory).
CLEANFILES += doc/one-page.html doc/html.stamp doc/js_licenses.html

# `make check' builds the HTML manual and checks that every image and
# every internal link of both editions resolves (doc/check-html.sh);
# `make installcheck' checks the installed one.
check_DATA = doc/html.stamp
TESTS += doc/check-html.sh
# Every formula of the hand-written chapters is in the manual's form
# (doc/texi-math.pl --check).
TESTS += doc/check-texi-math.sh
# `make installcheck' also runs the installed man page's EXAMPLES with the
# installed program and scenes (tools/installcheck-examples.sh).
installcheck-local: installcheck-html installcheck-examples
installcheck-html:
	CHAPLYGIN_HTML_DIR="$(DESTDIR)$(htmldir)/chaplygin.html" \
	  top_srcdir="$(srcdir)" $(SHELL) $(srcdir)/doc/check-html.sh \
	  | tee installcheck-html.log; ! grep -q '^not ok\|^Bail out' \
	  installcheck-html.log
installcheck-examples:
	CHAPLYGIN_MAN="$(DESTDIR)$(man1dir)/chaplygin.1" \
	  CHAPLYGIN_BINDIR="$(bindir)" CHAPLYGIN_LIBDIR="$(libdir)" \
	  CHAPLYGIN_DATADIR="$(pkgdatadir)" CHAPLYGIN_DESTDIR="$(DESTDIR)" \
	  $(SHELL) $(srcdir)/tools/installcheck-examples.sh \
	  | tee installcheck-examples.log; ! grep -q '^not ok' \
	  installcheck-examples.log
.PHONY: installcheck-html installcheck-examples
CLEANFILES += installcheck-html.log installcheck-examples.log

# The chapter "The paper's claims", the claims listed under each figure
# and the list of checks tests/test_claims compares with its own, from the
# registry of claims (doc/claims.txt, by doc/claims.pl).
CLAIMS_DEPS = $(srcdir)/doc/claims.txt $(srcdir)/doc/claims.pl \
	$(srcdir)/lib/Registry.pm $(srcdir)/lib/TexinfoMath.pm
CLAIMS_INPUTS = $(srcdir)/lib/labels.txt $(srcdir)/doc/errata.texi \
	$(srcdir)/doc/figures.texi $(srcdir)/tests/test_claims.c \
	$(srcdir)/tests/claims-motion.c
CLAIMS_GEN = $(PERL) $(srcdir)/doc/claims.pl
$(srcdir)/doc/claims.texi: $(CLAIMS_DEPS) $(CLAIMS_INPUTS)
	$(AM_V_GEN)$(CLAIMS_GEN) -o $@ texi $(srcdir)/doc/claims.txt \
	  $(CLAIMS_INPUTS)
$(srcdir)/doc/claims-figures.texi: $(CLAIMS_DEPS) $(CLAIMS_INPUTS)
	$(AM_V_GEN)$(CLAIMS_GEN) -o $@ figures $(srcdir)/doc/claims.txt \
	  $(CLAIMS_INPUTS)
$(srcdir)/tests/claims-list.h: $(CLAIMS_DEPS) $(CLAIMS_INPUTS)
	$(AM_V_GEN)$(CLAIMS_GEN) -o $@ list $(srcdir)/doc/claims.txt \
	  $(CLAIMS_INPUTS)
BUILT_SOURCES += $(srcdir)/tests/claims-list.h
EXTRA_DIST += doc/claims.txt doc/claims.pl
