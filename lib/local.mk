## lib/local.mk -- the library.
# All code goes into a convenience library that the tests link statically
# (so they can test internal helpers); the installed shared library exports
# only the public chaplygin_* symbols.
noinst_LTLIBRARIES = lib/libchaplygin-core.la
lib_libchaplygin_core_la_SOURCES = \
	lib/internal.h \
	lib/eft.h \
	lib/eft.c \
	lib/status.h \
	lib/collision.h \
	lib/collision.c \
	lib/motion.h \
	lib/motion.c \
	lib/status.c \
	lib/units.h \
	lib/units.c \
	lib/smooth.c \
	lib/discrete.c \
	lib/flow.c \
	lib/map.c \
	lib/ellint.c \
	lib/carlson.h \
	lib/carlson.c \
	lib/quad.c \
	lib/ode.c \
	lib/stability.c \
	lib/sweep.c \
	lib/fate.c \
	lib/massless.c \
	lib/skate.c \
	lib/reversal.c \
	lib/energy.c \
	lib/far.h \
	lib/far.c \
	lib/series.h \
	lib/series.c \
	lib/ellint.h \
	lib/quad.h \
	lib/ode.h \
	lib/leg.h \
	lib/leg.c \
	lib/printed.c
# the certified method (issue 28): built where configure finds Arb
if HAVE_ARB
lib_libchaplygin_core_la_SOURCES += \
	lib/cert-round.h \
	lib/cert-round.c \
	lib/cert-leg.h \
	lib/cert-leg.c \
	lib/certified.c \
	lib/cert-eval.h \
	lib/cert-eval.c \
	lib/cert-algebraic.c \
	lib/cert-smooth.c \
	lib/cert-series.c \
	lib/cert-massless.c \
	lib/cert-units.c \
	lib/cert-sweep.c
else
lib_libchaplygin_core_la_SOURCES += lib/certified-none.c
endif
EXTRA_DIST += lib/certified.h lib/certified-none.c lib/certified-none.pl
# the refusals of a build without Arb, one per certified function that
# lib/chaplygin.h declares (written in the source tree, distributed)
$(srcdir)/lib/certified-none.c: $(srcdir)/lib/chaplygin.h \
		$(srcdir)/lib/certified-none.pl
	$(AM_V_GEN)$(PERL) $(srcdir)/lib/certified-none.pl \
	  $(srcdir)/lib/chaplygin.h > $@.tmp && mv $@.tmp $@
lib_libchaplygin_core_la_CFLAGS = $(AM_CFLAGS) $(FP_CFLAGS) \
	$(CODEGEN_CFLAGS) $(GSL_CFLAGS)
lib_libchaplygin_core_la_LIBADD = $(GSL_LIBS) $(ARB_LIBS) $(CODE_COVERAGE_LIBS)

lib_LTLIBRARIES = lib/libchaplygin.la
lib_libchaplygin_la_SOURCES =
lib_libchaplygin_la_LIBADD = lib/libchaplygin-core.la $(GSL_LIBS) $(ARB_LIBS) $(CODE_COVERAGE_LIBS)
lib_libchaplygin_la_LDFLAGS = -version-info 2:0:0 -export-symbols-regex '^chaplygin_'
include_HEADERS = lib/chaplygin.h

# The registry of the paper's equation labels, its reader/generator and
# the reader of every registry, lib/Registry.pm (doc/claims.pl's too):
# doc/local.mk's generated files, tests/concordance.sh.
EXTRA_DIST += lib/labels.txt lib/labels.pl lib/TexinfoName.pm lib/Registry.pm
pkgconfig_DATA = chaplygin.pc


## The scene engine (lib/scene/): scenes read, checked and run, the
## paper's equations by label, the numbers a user writes.  A second
## installed library, a client of libchaplygin's public interface only,
## so that the numerical library keeps GSL as its one dependency (the
## engine needs GMP and MPFR, and OpenMP for sweeps; it reads inih's INI
## syntax itself: Debian's libinih cuts lines at 198 bytes).  The tests
## link the convenience library (internal helpers); the installed one
## exports the engine's public names.
noinst_LTLIBRARIES += lib/libchaplygin-scene-core.la
lib_libchaplygin_scene_core_la_SOURCES = \
	lib/scene/chaplygin-scene.h \
	lib/scene/engine.h \
	lib/scene/run.h \
	lib/scene/report.c \
	lib/scene/number.c \
	lib/scene/scene.c \
	lib/scene/run.c \
	lib/scene/grid.c \
	lib/scene/eq.h \
	lib/scene/eq.c \
	lib/scene/eq-eval.c \
	lib/scene/eq-certified.c \
	lib/scene/eq-evaluators.h \
	lib/scene/eq-table.c
# The table of labels and the evaluators that map inputs to one call,
# generated from the registry (lib/labels.pl), written into the source
# tree and distributed like the manual's generated parts.
$(srcdir)/lib/scene/eq-table.c: $(srcdir)/lib/labels.txt $(srcdir)/lib/labels.pl \
		$(srcdir)/lib/Registry.pm
	$(AM_V_GEN)$(PERL) $(srcdir)/lib/labels.pl -o $@ c $(srcdir)/lib/labels.txt
$(srcdir)/lib/scene/eq-evaluators.h: $(srcdir)/lib/labels.txt \
		$(srcdir)/lib/labels.pl $(srcdir)/lib/Registry.pm
	$(AM_V_GEN)$(PERL) $(srcdir)/lib/labels.pl -o $@ h $(srcdir)/lib/labels.txt
BUILT_SOURCES += $(srcdir)/lib/scene/eq-evaluators.h
lib_libchaplygin_scene_core_la_CPPFLAGS = $(AM_CPPFLAGS) -I$(srcdir)/lib/scene
lib_libchaplygin_scene_core_la_CFLAGS = $(AM_CFLAGS) $(OPENMP_CFLAGS)
lib_libchaplygin_scene_core_la_LIBADD = $(MPFR_LIBS) $(CODE_COVERAGE_LIBS)

lib_LTLIBRARIES += lib/libchaplygin-scene.la
lib_libchaplygin_scene_la_SOURCES =
lib_libchaplygin_scene_la_LIBADD = lib/libchaplygin-scene-core.la \
	lib/libchaplygin.la $(MPFR_LIBS) $(CODE_COVERAGE_LIBS)
lib_libchaplygin_scene_la_LDFLAGS = -version-info 0:0:0 $(OPENMP_CFLAGS) \
	-export-symbols-regex '^chaplygin_(scene|number|cell|row|text|eq)_'
include_HEADERS += lib/scene/chaplygin-scene.h
pkgconfig_DATA += chaplygin-scene.pc
