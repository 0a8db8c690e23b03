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
	tests/test_quad \
	tests/test_ode \
	tests/test_stability \
	tests/test_fate \
	tests/test_massless \
	tests/test_reversal \
	tests/test_energy \
	tests/test_threads
check_PROGRAMS += $(UNIT_CHECKS)
TESTS += $(UNIT_CHECKS) tests/concordance.sh

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
tests_test_map_SOURCES = tests/test_map.c tests/ref_map.h tests/ref_poincare.h
tests_test_map_CFLAGS = $(TEST_CFLAGS)
tests_test_map_LDADD = $(TEST_LDADD)
tests_test_ellint_SOURCES = tests/test_ellint.c tests/ref_ellint.h
tests_test_ellint_CFLAGS = $(TEST_CFLAGS)
tests_test_ellint_LDADD = $(TEST_LDADD)
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
tests_test_massless_LDADD = $(TEST_LDADD)
tests_test_reversal_SOURCES = tests/test_reversal.c
tests_test_reversal_CFLAGS = $(TEST_CFLAGS)
tests_test_reversal_LDADD = $(TEST_LDADD)
tests_test_energy_SOURCES = tests/test_energy.c
tests_test_energy_CFLAGS = $(TEST_CFLAGS)
tests_test_energy_LDADD = $(TEST_LDADD)

EXTRA_DIST += tests/concordance.sh tests/ref/make_refs.py tests/ref/README
