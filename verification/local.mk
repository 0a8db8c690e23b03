## verification/local.mk -- checks of invariants by routes independent of
## the library's formulas.  Run by `make check' (fast tier).
VERIFICATION_CHECKS = verification/conservation
check_PROGRAMS += $(VERIFICATION_CHECKS)
TESTS += $(VERIFICATION_CHECKS)
verification_conservation_SOURCES = verification/conservation.c verification/tap.h
verification_conservation_CFLAGS = $(AM_CFLAGS) $(GSL_CFLAGS)
verification_conservation_LDADD = lib/libchaplygin.la $(GSL_LIBS) $(CODE_COVERAGE_LIBS) -lm
