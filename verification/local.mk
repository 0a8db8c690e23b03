## verification/local.mk -- checks of invariants by routes independent of
## the library's formulas (issue 4 extends this).  Run by `make check'.
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
