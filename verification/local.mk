## verification/local.mk -- checks of the library by routes independent of
## its formulas.  `make check' runs them at level 1 (fast); `make
## verify-long' runs them again at level 2 (more samples, longer runs),
## through the environment variable CHAPLYGIN_VERIFY_LEVEL.
VERIFICATION_CHECKS = verification/conservation verification/reflection
check_PROGRAMS += $(VERIFICATION_CHECKS)
TESTS += $(VERIFICATION_CHECKS)
VERIFICATION_LDADD = lib/libchaplygin.la $(GSL_LIBS) $(CODE_COVERAGE_LIBS) -lm
verification_conservation_SOURCES = verification/conservation.c verification/tap.h
verification_conservation_CFLAGS = $(AM_CFLAGS) $(GSL_CFLAGS)
verification_conservation_LDADD = $(VERIFICATION_LDADD)
verification_reflection_SOURCES = verification/reflection.c verification/tap.h
verification_reflection_CFLAGS = $(AM_CFLAGS) $(GSL_CFLAGS)
verification_reflection_LDADD = $(VERIFICATION_LDADD)

# The deep tier: the same programs with more samples.
verify-long: $(VERIFICATION_CHECKS)
	@fail=0; for p in $(VERIFICATION_CHECKS); do \
	  echo "== $$p (level 2)"; \
	  CHAPLYGIN_VERIFY_LEVEL=2 ./$$p || fail=1; \
	done; test $$fail = 0
.PHONY: verify-long

# Independent routes (each program's header comment says which).
VERIFICATION_CHECKS += verification/hybrid verification/rigid_body
verification_hybrid_SOURCES = verification/hybrid.c verification/tap.h
verification_hybrid_CFLAGS = $(AM_CFLAGS) $(GSL_CFLAGS)
verification_hybrid_LDADD = $(VERIFICATION_LDADD)
verification_rigid_body_SOURCES = verification/rigid_body.c verification/tap.h
verification_rigid_body_CFLAGS = $(AM_CFLAGS) $(GSL_CFLAGS)
verification_rigid_body_LDADD = $(VERIFICATION_LDADD)
VERIFICATION_CHECKS += verification/smooth verification/limits
verification_smooth_SOURCES = verification/smooth.c verification/tap.h
verification_smooth_CFLAGS = $(AM_CFLAGS) $(GSL_CFLAGS)
verification_smooth_LDADD = $(VERIFICATION_LDADD)
verification_limits_SOURCES = verification/limits.c verification/tap.h
verification_limits_CFLAGS = $(AM_CFLAGS) $(GSL_CFLAGS)
verification_limits_LDADD = $(VERIFICATION_LDADD)
VERIFICATION_CHECKS += verification/stability
verification_stability_SOURCES = verification/stability.c verification/tap.h
verification_stability_CFLAGS = $(AM_CFLAGS) $(GSL_CFLAGS)
verification_stability_LDADD = $(VERIFICATION_LDADD)

# The Arb oracle (route 3), built where configure found Arb.  It also
# writes the manual's accuracy tables: `make accuracy-tables'.
if HAVE_ARB
VERIFICATION_CHECKS += verification/oracle
endif
EXTRA_PROGRAMS = verification/oracle
verification_oracle_SOURCES = verification/oracle.c verification/tap.h
verification_oracle_CFLAGS = $(AM_CFLAGS) $(GSL_CFLAGS)
verification_oracle_LDADD = $(VERIFICATION_LDADD) $(ARB_LIBS) $(MPFR_LIBS)

accuracy-tables: verification/oracle
	CHAPLYGIN_VERIFY_LEVEL=2 ./verification/oracle --table $(srcdir)/doc/accuracy.texi
.PHONY: accuracy-tables

# The extremes of issue 6 over long runs (10^6 collisions, 10^7 at level
# 2), the massless limit, the spinning state and Delta's extremes, against
# a binary128 model (libquadmath): see its header comment.
VERIFICATION_CHECKS += verification/extremes
verification_extremes_SOURCES = verification/extremes.c verification/tap.h
verification_extremes_CFLAGS = $(AM_CFLAGS) $(GSL_CFLAGS)
verification_extremes_LDADD = $(VERIFICATION_LDADD) -lquadmath
