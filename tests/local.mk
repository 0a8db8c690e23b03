## tests/local.mk -- Check unit tests: one suite per source file of lib/,
## one TCase per equation.  Included from the top-level Makefile.am.
TEST_CFLAGS = $(AM_CFLAGS) $(CHECK_CFLAGS) $(GSL_CFLAGS)
TEST_LDADD = tests/libtestutil.a lib/libchaplygin-core.la $(CHECK_LIBS) \
	$(GSL_LIBS) $(CODE_COVERAGE_LIBS) -lm

check_LIBRARIES = tests/libtestutil.a
tests_libtestutil_a_SOURCES = tests/testutil.c tests/testutil.h
tests_libtestutil_a_CFLAGS = $(TEST_CFLAGS)

UNIT_CHECKS = \
	tests/test_status \
	tests/test_units \
	tests/test_smooth \
	tests/test_discrete \
	tests/test_flow \
	tests/test_map \
	tests/test_ellint \
	tests/test_carlson \
	tests/test_quad \
	tests/test_ode \
	tests/test_stability \
	tests/test_fate \
	tests/test_massless \
	tests/test_skate \
	tests/test_reversal \
	tests/test_energy \
	tests/test_threads \
	tests/test_extremes \
	tests/test_far \
	tests/test_alloc \
	tests/test_printed
check_PROGRAMS += $(UNIT_CHECKS)
TESTS += $(UNIT_CHECKS) tests/concordance.sh tests/layers.sh tests/apiref.sh

# The paper's claims beyond its equations (doc/claims.txt): every claim's
# check, and the list of them generated from the registry
# (tests/claims-list.h, doc/local.mk).
check_PROGRAMS += tests/test_claims
TESTS += tests/test_claims tests/claims.sh
EXTRA_DIST += tests/claims.sh
tests_test_claims_SOURCES = tests/test_claims.c tests/claims-motion.c \
	tests/claims.h tests/claims-list.h
tests_test_claims_CFLAGS = $(TEST_CFLAGS)
tests_test_claims_LDADD = $(TEST_LDADD)

# The scene engine (lib/scene/): its reader and numbers against its
# internal structure, its public interface from outside.
SCENE_TEST_CPPFLAGS = $(AM_CPPFLAGS) -I$(srcdir)/lib/scene
SCENE_TEST_LDADD = lib/libchaplygin-scene-core.la $(TEST_LDADD) \
	$(MPFR_LIBS) $(OPENMP_CFLAGS)
SCENE_CHECKS = tests/test_scene tests/test_number tests/test_scene_api \
	tests/test_eq_scaling
check_PROGRAMS += $(SCENE_CHECKS)
TESTS += $(SCENE_CHECKS)
tests_test_scene_SOURCES = tests/test_scene.c
tests_test_scene_CPPFLAGS = $(SCENE_TEST_CPPFLAGS)
tests_test_scene_CFLAGS = $(TEST_CFLAGS)
tests_test_scene_LDADD = $(SCENE_TEST_LDADD)
tests_test_number_SOURCES = tests/test_number.c
tests_test_number_CPPFLAGS = $(SCENE_TEST_CPPFLAGS)
tests_test_number_CFLAGS = $(TEST_CFLAGS)
tests_test_number_LDADD = $(SCENE_TEST_LDADD)
tests_test_eq_scaling_SOURCES = tests/test_eq_scaling.c
tests_test_eq_scaling_CPPFLAGS = $(SCENE_TEST_CPPFLAGS)
tests_test_eq_scaling_CFLAGS = $(TEST_CFLAGS)
tests_test_eq_scaling_LDADD = $(SCENE_TEST_LDADD)
# the public interface only: linked as a program links the installed one
tests_test_scene_api_SOURCES = tests/test_scene_api.c
tests_test_scene_api_CPPFLAGS = $(SCENE_TEST_CPPFLAGS)
tests_test_scene_api_CFLAGS = $(TEST_CFLAGS)
tests_test_scene_api_LDADD = $(SCENE_TEST_LDADD)

# thread safety: several OpenMP threads against a serial run
tests_test_threads_SOURCES = tests/test_threads.c
tests_test_threads_CFLAGS = $(TEST_CFLAGS) $(OPENMP_CFLAGS)
tests_test_threads_LDFLAGS = $(OPENMP_CFLAGS)
tests_test_threads_LDADD = $(TEST_LDADD)
tests_test_status_SOURCES = tests/test_status.c
tests_test_status_CFLAGS = $(TEST_CFLAGS)
tests_test_status_LDADD = $(TEST_LDADD)
tests_test_units_SOURCES = tests/test_units.c
tests_test_units_CFLAGS = $(TEST_CFLAGS)
tests_test_units_LDADD = $(TEST_LDADD)
tests_test_smooth_SOURCES = tests/test_smooth.c tests/ref_smooth.h
tests_test_smooth_CFLAGS = $(TEST_CFLAGS)
tests_test_smooth_LDADD = $(TEST_LDADD)
tests_test_discrete_SOURCES = tests/test_discrete.c
tests_test_discrete_CFLAGS = $(TEST_CFLAGS)
tests_test_discrete_LDADD = $(TEST_LDADD)
tests_test_flow_SOURCES = tests/test_flow.c tests/ref_flow.h
tests_test_flow_CFLAGS = $(TEST_CFLAGS)
tests_test_flow_LDADD = $(TEST_LDADD)
tests_test_map_SOURCES = tests/test_map.c tests/ref_map.h tests/ref_poincare.h \
	tests/ref_slow.h
tests_test_map_CFLAGS = $(TEST_CFLAGS)
tests_test_map_LDADD = $(TEST_LDADD) -lquadmath
tests_test_ellint_SOURCES = tests/test_ellint.c tests/ref_ellint.h
tests_test_ellint_CFLAGS = $(TEST_CFLAGS)
tests_test_ellint_LDADD = $(TEST_LDADD)
# the fused Carlson kernel (lib/carlson.c): closed forms in binary128,
# same bits across requests and entries, GSL, statuses; and, where
# configure found Arb, its accuracy against Arb (tests/test_carlson_arb,
# the same source with -DCHP_TEST_ARB)
tests_test_carlson_SOURCES = tests/test_carlson.c
tests_test_carlson_CFLAGS = $(TEST_CFLAGS)
tests_test_carlson_LDADD = $(TEST_LDADD) -lquadmath
if HAVE_ARB
check_PROGRAMS += tests/test_carlson_arb
TESTS += tests/test_carlson_arb
endif
tests_test_carlson_arb_SOURCES = tests/test_carlson.c
tests_test_carlson_arb_CFLAGS = $(TEST_CFLAGS) -DCHP_TEST_ARB
tests_test_carlson_arb_LDADD = $(TEST_LDADD) -lquadmath $(ARB_LIBS)
# the certified method (issue 28): its correct rounding against MPFR, its
# orbits against Arb's rigorous integration of the integrands and the
# exact model
if HAVE_ARB
check_LIBRARIES += tests/libcertref.a
check_PROGRAMS += tests/test_cert_round tests/test_certified \
	tests/test_cert_algebraic tests/test_cert_smooth tests/test_cert_series \
	tests/test_cert_massless tests/test_cert_units tests/test_cert_sweep
TESTS += tests/test_cert_round tests/test_certified \
	tests/test_cert_algebraic tests/test_cert_smooth tests/test_cert_series \
	tests/test_cert_massless tests/test_cert_units tests/test_cert_sweep
endif
tests_libcertref_a_SOURCES = tests/certref.c tests/certref.h
tests_libcertref_a_CFLAGS = $(TEST_CFLAGS)
CERT_LDADD = tests/libcertref.a $(TEST_LDADD) $(ARB_LIBS) $(MPFR_LIBS)
tests_test_cert_round_SOURCES = tests/test_cert_round.c
tests_test_cert_round_CFLAGS = $(TEST_CFLAGS)
tests_test_cert_round_LDADD = $(TEST_LDADD) $(ARB_LIBS) $(MPFR_LIBS)
tests_test_certified_SOURCES = tests/test_certified.c
tests_test_certified_CFLAGS = $(TEST_CFLAGS)
tests_test_certified_LDADD = $(CERT_LDADD)
# the certified closed forms against GMP's exact rationals and MPFR
tests_test_cert_algebraic_SOURCES = tests/test_cert_algebraic.c
tests_test_cert_algebraic_CFLAGS = $(TEST_CFLAGS)
tests_test_cert_algebraic_LDADD = $(CERT_LDADD)
# the certified smooth sleigh (2.1), (2.4), (A.1)-(A.6)
tests_test_cert_smooth_SOURCES = tests/test_cert_smooth.c
tests_test_cert_smooth_CFLAGS = $(TEST_CFLAGS)
tests_test_cert_smooth_LDADD = $(CERT_LDADD)
# the certified series (B.2), (B.6), (B.8)-(B.13)
tests_test_cert_series_SOURCES = tests/test_cert_series.c
tests_test_cert_series_CFLAGS = $(TEST_CFLAGS)
tests_test_cert_series_LDADD = $(CERT_LDADD)
# the certified massless skate (B.14)-(B.17)
tests_test_cert_massless_SOURCES = tests/test_cert_massless.c
tests_test_cert_massless_CFLAGS = $(TEST_CFLAGS)
tests_test_cert_massless_LDADD = $(CERT_LDADD)
# the certified units and fields (2.2), (2.3), (3.1), (3.2)
tests_test_cert_units_SOURCES = tests/test_cert_units.c
tests_test_cert_units_CFLAGS = $(TEST_CFLAGS)
tests_test_cert_units_LDADD = $(CERT_LDADD)
# the certified sweeps of Figure 2
tests_test_cert_sweep_SOURCES = tests/test_cert_sweep.c
tests_test_cert_sweep_CFLAGS = $(TEST_CFLAGS)
tests_test_cert_sweep_LDADD = $(CERT_LDADD)
tests_test_quad_SOURCES = tests/test_quad.c
tests_test_quad_CFLAGS = $(TEST_CFLAGS)
tests_test_quad_LDADD = $(TEST_LDADD)
tests_test_ode_SOURCES = tests/test_ode.c
tests_test_ode_CFLAGS = $(TEST_CFLAGS)
tests_test_ode_LDADD = $(TEST_LDADD)
tests_test_stability_SOURCES = tests/test_stability.c tests/ref_stability.h
tests_test_stability_CFLAGS = $(TEST_CFLAGS)
tests_test_stability_LDADD = $(TEST_LDADD) -lquadmath
tests_test_fate_SOURCES = tests/test_fate.c
tests_test_fate_CFLAGS = $(TEST_CFLAGS)
tests_test_fate_LDADD = $(TEST_LDADD)
tests_test_massless_SOURCES = tests/test_massless.c
tests_test_massless_CFLAGS = $(TEST_CFLAGS)
tests_test_massless_LDADD = $(TEST_LDADD) -lquadmath
tests_test_skate_SOURCES = tests/test_skate.c tests/ref_segment.h
tests_test_skate_CFLAGS = $(TEST_CFLAGS)
tests_test_skate_LDADD = $(TEST_LDADD) -lquadmath
tests_test_reversal_SOURCES = tests/test_reversal.c
tests_test_reversal_CFLAGS = $(TEST_CFLAGS)
tests_test_reversal_LDADD = $(TEST_LDADD)
tests_test_energy_SOURCES = tests/test_energy.c
tests_test_energy_CFLAGS = $(TEST_CFLAGS)
tests_test_energy_LDADD = $(TEST_LDADD)

EXTRA_DIST += tests/concordance.sh tests/layers.sh tests/apiref.sh tests/fp-digest.sh tests/ref/make_refs.py tests/ref/README

# the extremes of issue 6: every entry point, each method, at the edges of
# its domain (documented result with its accuracy, or a documented status)
tests_test_extremes_SOURCES = tests/test_extremes.c
tests_test_extremes_CFLAGS = $(TEST_CFLAGS)
tests_test_extremes_LDADD = $(TEST_LDADD) -lquadmath
# the far slot (lib/far.c): beyond the cap 2^500, values against the
# rho = 0 closed forms in binary128
tests_test_far_SOURCES = tests/test_far.c
tests_test_far_CFLAGS = $(TEST_CFLAGS)
tests_test_far_LDADD = $(TEST_LDADD) -lquadmath
# the hot path allocates nothing (a counting malloc interposed in the test)
tests_test_alloc_SOURCES = tests/test_alloc.c
tests_test_alloc_CFLAGS = $(TEST_CFLAGS)
tests_test_alloc_LDADD = $(TEST_LDADD)
# the paper's printed forms (lib/printed.c): values against the printed
# formulas written out in binary128, the errata's numbers, statuses
tests_test_printed_SOURCES = tests/test_printed.c
tests_test_printed_CFLAGS = $(TEST_CFLAGS)
tests_test_printed_LDADD = $(TEST_LDADD) -lquadmath

# ---- robustness: the tests under sanitizers and valgrind ----------------
# Each builds the distribution directory in a directory of its own (as
# `make distcheck' does), so that it works next to an in-tree build.

# `make check-sanitizers': the whole of `make check' (unit tests,
# verification at level 1, the program's tests) in a build with
# AddressSanitizer and UndefinedBehaviorSanitizer, any finding fatal; then
# `make check-tsan'.
SAN_DIR = $(distdir)-asan
check-sanitizers: distdir
	rm -rf $(SAN_DIR) && mv $(distdir) $(SAN_DIR)
	cd $(SAN_DIR) && ./configure --enable-sanitizers --disable-shared \
	  --without-arb --enable-werror --disable-fma CFLAGS="-O1 -g" \
	  >/dev/null \
	  && $(MAKE) $(AM_MAKEFLAGS) \
	  && { nm tools/chaplygin | grep __asan_init >/dev/null \
	       && nm tools/chaplygin | grep __ubsan_handle >/dev/null \
	       && nm lib/.libs/libchaplygin-core.a | grep __asan_report >/dev/null \
	       || { echo "check-sanitizers: the build is not instrumented" >&2; \
	            exit 1; }; } \
	  && ASAN_OPTIONS=detect_leaks=1:abort_on_error=0 \
	     UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
	     $(MAKE) $(AM_MAKEFLAGS) check
	@# the same bits with and without the FMA instruction (this build may
	@# use -mfma; the sanitizer build above does not)
	$(SHELL) $(srcdir)/tests/fp-digest.sh ./tools/chaplygin $(srcdir) \
	  > fp-digest.main
	cd $(SAN_DIR) && $(SHELL) tests/fp-digest.sh ./tools/chaplygin . \
	  > ../fp-digest.portable
	cmp fp-digest.main fp-digest.portable \
	  && echo "check-sanitizers: the portable build prints the same bits"
	rm -f fp-digest.main fp-digest.portable
	rm -rf $(SAN_DIR)
	$(MAKE) $(AM_MAKEFLAGS) check-tsan
.PHONY: check-sanitizers

# `make check-tsan': tests/test_threads (the map, fates and sweeps from
# several OpenMP threads against a serial run) under ThreadSanitizer.
# GCC's libgomp is not instrumented and makes TSan report its own
# synchronisation as races, so this build uses clang with LLVM's libomp
# and its TSan tool Archer (Debian: clang, libomp-14-dev).
TSAN_CC = clang
TSAN_DIR = $(distdir)-tsan
check-tsan: distdir
	rm -rf $(TSAN_DIR) && mv $(distdir) $(TSAN_DIR)
	archer=`$(TSAN_CC) -print-resource-dir`/../../libarcher.so; \
	test -f "$$archer" || { echo "check-tsan: Archer ($$archer) not" \
	  "found: install libomp-14-dev" >&2; exit 1; }; \
	cd $(TSAN_DIR) && ./configure CC=$(TSAN_CC) --disable-shared \
	  --without-arb --disable-werror \
	  CFLAGS="-O1 -g -fsanitize=thread" LDFLAGS="-fsanitize=thread" \
	  >/dev/null \
	  && grep '^OPENMP_CFLAGS = -fopenmp' Makefile >/dev/null \
	  && { $(MAKE) $(AM_MAKEFLAGS) tests/test_threads >build.log 2>&1 \
	       || { cat build.log; exit 1; }; } \
	  && nm tests/test_threads | grep __tsan_init >/dev/null \
	  && OMP_NUM_THREADS=4 OMP_TOOL_LIBRARIES=$$archer CK_FORK=no \
	     TSAN_OPTIONS="ignore_noninstrumented_modules=1 halt_on_error=1 exitcode=66" \
	     ./tests/test_threads
	rm -rf $(TSAN_DIR)
.PHONY: check-tsan

# `make check-valgrind': a subset of the unit tests under valgrind's
# memcheck (in-process: CK_FORK=no), any error or definite leak fatal.
# tests/test_alloc replaces malloc itself and is left out; the slowest
# suites are left out to keep the run short (they run under ASan).  The
# scene engine's suites too (their sweeps' OpenMP threads: libgomp's
# thread stacks are "possibly lost", not definite).
VALGRIND_CHECKS = tests/test_status tests/test_units tests/test_smooth \
	tests/test_discrete tests/test_flow tests/test_map tests/test_ellint \
	tests/test_quad tests/test_ode tests/test_stability $(SCENE_CHECKS)
VALGRIND_DIR = $(distdir)-valgrind
check-valgrind: distdir
	rm -rf $(VALGRIND_DIR) && mv $(distdir) $(VALGRIND_DIR)
	cd $(VALGRIND_DIR) && ./configure --disable-shared --without-arb \
	  --enable-werror CFLAGS="-O1 -g" >/dev/null \
	  && $(MAKE) $(AM_MAKEFLAGS) $(VALGRIND_CHECKS) \
	  && for t in $(VALGRIND_CHECKS); do \
	    echo "  VALGRIND $$t"; \
	    CK_FORK=no CK_DEFAULT_TIMEOUT=0 valgrind --tool=memcheck -q \
	      --error-exitcode=1 --leak-check=full \
	      --errors-for-leak-kinds=definite ./$$t >$$t.vg.log 2>&1 \
	      || { cat $$t.vg.log; exit 1; }; \
	  done
	rm -rf $(VALGRIND_DIR)
.PHONY: check-valgrind
