## bench/local.mk -- `make bench': the work-precision measurement.  Times
## one step of the return map from each of a randomized set of states for
## every method and setting of the library, measures the errors against the
## Arb oracle (verification/oracle --refs) and writes the committed results:
## bench/work-precision.csv, doc/bench-table.texi (the manual's table) and
## doc/figures/work-precision.png (gnuplot).  Where a Python 3 with SciPy is
## found (BENCH_PYTHONS: PYTHON, python3, /usr/bin/python3, the first
## that imports scipy.integrate), bench/scipy-ivp.py adds the rows of
## SciPy's solve_ivp (DOP853) on the same states; without it they are
## skipped, and said so.  Then bench/atlas: the atlas sweep's kernel
## (chaplygin_discrete_fates_phase, and the scalar chaplygin_discrete_basins
## per point) in ns per collision as ratios to the same baseline chain on
## the same step set, and the sweep's parallel efficiency with 2 threads
## (stdout only).
## Not part of `make check'.
noinst_PROGRAMS += bench/work-precision
bench_work_precision_SOURCES = bench/work-precision.c verification/tap.h
bench_work_precision_CPPFLAGS = $(AM_CPPFLAGS) -I$(top_srcdir)/verification \
	-DBENCH_CFLAGS='"$(CFLAGS)"'
bench_work_precision_LDADD = lib/libchaplygin.la $(CODE_COVERAGE_LIBS) -lm

noinst_PROGRAMS += bench/atlas
bench_atlas_SOURCES = bench/atlas.c bench/baseline.h bench/timing.h
bench_atlas_CPPFLAGS = $(AM_CPPFLAGS) -I$(srcdir)/lib/scene
bench_atlas_LDADD = lib/libchaplygin-scene.la lib/libchaplygin.la \
	$(CODE_COVERAGE_LIBS) -lm
bench_work_precision_SOURCES += bench/baseline.h bench/timing.h

EXTRA_DIST += bench/work-precision.gp bench/work-precision.csv \
	bench/scipy-ivp.py

if HAVE_ARB
BENCH_HAVE_ARB = yes
else
BENCH_HAVE_ARB = no
endif
GNUPLOT = gnuplot
BENCH_STATES = bench/work-precision-states.txt
BENCH_REFS = bench/work-precision-refs.txt
BENCH_SCIPY = bench/work-precision-scipy.txt
# the interpreters tried for the SciPy rows, in order (BENCH_PYTHONS=none:
# skip them)
BENCH_PYTHONS = $(PYTHON) python3 /usr/bin/python3
CLEANFILES += $(BENCH_STATES) $(BENCH_REFS) $(BENCH_SCIPY)

bench: bench/work-precision
	@if test $(BENCH_HAVE_ARB) != yes; then \
	  echo "make bench: the reference values need the Arb oracle" \
	    "(verification/oracle), and configure did not find Arb" \
	    "(install libflint-arb-dev and rerun configure)" >&2; \
	  exit 1; \
	fi
	$(MAKE) $(AM_MAKEFLAGS) verification/oracle
	./bench/work-precision --states $(BENCH_STATES)
	./verification/oracle --refs $(BENCH_STATES) $(BENCH_REFS)
	@rm -f $(BENCH_SCIPY); py=; \
	for p in $(BENCH_PYTHONS); do \
	  if "$$p" -c 'import scipy.integrate' >/dev/null 2>&1; then \
	    py=$$p; break; fi; \
	done; \
	if test -n "$$py"; then \
	  echo "$$py $(srcdir)/bench/scipy-ivp.py $(BENCH_STATES) $(BENCH_REFS)" \
	    "$(BENCH_SCIPY)"; \
	  "$$py" $(srcdir)/bench/scipy-ivp.py $(BENCH_STATES) $(BENCH_REFS) \
	    $(BENCH_SCIPY) || exit 1; \
	else \
	  echo "make bench: no Python 3 with SciPy found (Debian:" \
	    "apt-get install python3-scipy): the SciPy solve_ivp rows are" \
	    "skipped"; \
	fi
	./bench/work-precision --states-in $(BENCH_STATES) --refs $(BENCH_REFS) \
	  --csv $(srcdir)/bench/work-precision.csv \
	  --texi $(srcdir)/doc/bench-table.texi \
	  `test -s $(BENCH_SCIPY) && echo --scipy $(BENCH_SCIPY)`
	$(GNUPLOT) -e "csv = '$(srcdir)/bench/work-precision.csv'" \
	  -e "png = '$(srcdir)/doc/figures/work-precision.png'" \
	  $(srcdir)/doc/figures/style.gp $(srcdir)/bench/work-precision.gp
	$(MAKE) $(AM_MAKEFLAGS) bench/atlas
	./bench/atlas --states $(BENCH_STATES)
.PHONY: bench

# `make bench-carlson': the fused Carlson kernel (lib/carlson.c) against
# GSL's R_F + R_D on the triples chp_quartic_interval forms: accuracy
# against Arb, time (min and median of rounds) and instruction counts
# (callgrind, when valgrind is installed), as ratios to GSL in one run;
# writes bench/carlson.csv.  Needs Arb; not part of `make check'.
EXTRA_PROGRAMS += bench/carlson
bench_carlson_SOURCES = bench/carlson.c bench/timing.h
bench_carlson_CFLAGS = $(AM_CFLAGS) $(GSL_CFLAGS)
bench_carlson_LDADD = lib/libchaplygin-core.la $(GSL_LIBS) $(ARB_LIBS) \
	$(CODE_COVERAGE_LIBS) -lm
EXTRA_DIST += bench/carlson.csv

bench-carlson:
	@if test $(BENCH_HAVE_ARB) != yes; then \
	  echo "make bench-carlson: the reference values need Arb, and" \
	    "configure did not find it (install libflint-arb-dev and rerun" \
	    "configure)" >&2; \
	  exit 1; \
	fi
	$(MAKE) $(AM_MAKEFLAGS) bench/carlson
	@if command -v valgrind >/dev/null 2>&1; then cg=; else \
	  echo "make bench-carlson: valgrind not found: no instruction" \
	    "counts" >&2; cg=--no-callgrind; fi; \
	./bench/carlson $$cg --csv $(srcdir)/bench/carlson.csv
.PHONY: bench-carlson
