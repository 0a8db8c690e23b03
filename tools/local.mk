## tools/local.mk -- the command-line program, its tests, the scene
## fuzzer, the figures.
bin_PROGRAMS = tools/chaplygin
tools_chaplygin_SOURCES = tools/chaplygin.c tools/scene.c tools/scene.h \
	tools/run.c tools/run.h tools/sweep.c tools/sweep.h tools/progress.c \
	tools/progress.h tools/eq.c tools/eq.h tools/number.c tools/number.h
tools_chaplygin_CFLAGS = $(AM_CFLAGS) $(INIH_CFLAGS) $(OPENMP_CFLAGS)
tools_chaplygin_CPPFLAGS = $(AM_CPPFLAGS) \
	-DCHAPLYGIN_SCENES_DIR='"$(scenesdir)"' 
tools_chaplygin_LDFLAGS = $(OPENMP_CFLAGS)
tools_chaplygin_LDADD = lib/libchaplygin.la $(INIH_LIBS) $(MPFR_LIBS) \
	$(CODE_COVERAGE_LIBS) -lm
# The man page names the installed scenes: @pkgdatadir@ substituted here,
# so that its EXAMPLES work from an installation.  The manual's "Program
# reference" is generated from the same source (doc/local.mk).
man1_MANS = tools/chaplygin.1
tools/chaplygin.1: $(srcdir)/tools/chaplygin.1.in Makefile
	$(AM_V_GEN)$(MKDIR_P) tools && sed -e 's|@pkgdatadir[@]|$(pkgdatadir)|g' \
	  $(srcdir)/tools/chaplygin.1.in > $@.tmp && mv $@.tmp $@
CLEANFILES += tools/chaplygin.1
EXTRA_DIST += tools/chaplygin.1.in

# The scene parser's unit tests, and the fuzz target replaying its corpus
# (the same source as the libFuzzer build of `make fuzz').
check_PROGRAMS += tools/test-scene tools/fuzz-scene tools/test-number
tools_test_number_SOURCES = tools/test-number.c tools/number.c tools/number.h
tools_test_number_CFLAGS = $(AM_CFLAGS) $(CHECK_CFLAGS)
tools_test_number_LDADD = $(CHECK_LIBS) $(MPFR_LIBS) $(CODE_COVERAGE_LIBS) -lm
tools_test_scene_SOURCES = tools/test-scene.c tools/scene.c tools/scene.h \
	tools/number.c tools/number.h
tools_test_scene_CFLAGS = $(AM_CFLAGS) $(CHECK_CFLAGS) $(INIH_CFLAGS)
tools_test_scene_LDADD = lib/libchaplygin-core.la $(CHECK_LIBS) \
	$(INIH_LIBS) $(MPFR_LIBS) $(CODE_COVERAGE_LIBS) -lm
tools_fuzz_scene_SOURCES = tools/fuzz-scene.c tools/scene.c tools/scene.h \
	tools/number.c tools/number.h
tools_fuzz_scene_CFLAGS = $(AM_CFLAGS) $(INIH_CFLAGS)
tools_fuzz_scene_LDADD = lib/libchaplygin-core.la $(INIH_LIBS) \
	$(MPFR_LIBS) $(CODE_COVERAGE_LIBS) -lm

CLI_TESTS = tools/test-cli.sh tools/test-run.sh tools/test-sweep.sh \
	tools/test-scene tools/test-number tools/fuzz-replay.sh \
	tools/test-scenes.sh tools/test-eq.sh tools/test-manpage.sh
TESTS += $(CLI_TESTS)
EXTRA_DIST += tools/tap-lib.sh tools/test-cli.sh tools/test-run.sh tools/test-sweep.sh \
	tools/fuzz-replay.sh tools/test-scenes.sh tools/test-eq.sh \
	tools/test-manpage.sh tools/installcheck-examples.sh tools/fuzz-corpus tools/fuzz-scene.dict doc/figures/figure.sh \
	doc/figures/style.gp tests/ref/eq.tsv tests/ref/make_eq_refs.py

# `make fuzz': the libFuzzer build of the scene parser (clang), run for
# FUZZ_SECONDS on a copy of the corpus; new inputs land in fuzz-work/.
FUZZ_SECONDS = 60
FUZZ_CC = clang
fuzz: $(srcdir)/tools/fuzz-scene.c $(srcdir)/tools/scene.c \
	$(srcdir)/tools/number.c
	$(FUZZ_CC) -g -O1 -fsanitize=fuzzer,address,undefined \
	  -fno-sanitize-recover=undefined \
	  -DCHAPLYGIN_LIBFUZZER -I$(builddir) -I$(srcdir)/lib -I$(srcdir)/tools \
	  $(INIH_CFLAGS) -o fuzz-scene-libfuzzer $(srcdir)/tools/fuzz-scene.c \
	  $(srcdir)/tools/scene.c $(srcdir)/tools/number.c $(INIH_LIBS) \
	  $(MPFR_LIBS)
	mkdir -p fuzz-work && cp $(srcdir)/tools/fuzz-corpus/* fuzz-work/
	./fuzz-scene-libfuzzer -max_total_time=$(FUZZ_SECONDS) -max_len=4096 \
	  -dict=$(srcdir)/tools/fuzz-scene.dict fuzz-work
.PHONY: fuzz
CLEANFILES += fuzz-scene-libfuzzer

# `make figures': every scene of scenes/ run and drawn with gnuplot
# (pngcairo) into doc/figures/ of the source tree (committed, so that the
# manual has them without gnuplot).
FIGURES = fig2a fig2b fig3 fig4 fig5 fig6 fig7 fig8 fig9 fig10
figures: tools/chaplygin
	@for f in $(FIGURES); do \
	  echo "  FIGURE   doc/figures/$$f.png"; \
	  CHAPLYGIN=$(abs_builddir)/tools/chaplygin GNUPLOT=gnuplot \
	    $(SHELL) $(srcdir)/doc/figures/figure.sh $$f $(srcdir)/scenes \
	    $(srcdir)/doc/figures || exit 1; \
	done
.PHONY: figures

# The scenes of the paper's figures, installed as examples (the man page's
# EXAMPLES run them from there).
scenesdir = $(pkgdatadir)/scenes
dist_scenes_DATA = scenes/example.ini scenes/fig2a.ini scenes/fig2b.ini \
	scenes/fig3.ini scenes/fig4.ini scenes/fig5.ini scenes/fig6.ini \
	scenes/fig7.ini scenes/fig8.ini scenes/fig9.ini scenes/fig10.ini
