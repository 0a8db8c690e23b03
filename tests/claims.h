/* claims.h -- the checks of the paper's claims (doc/claims.txt): each is a
   Check test registered under the name the registry's `check:' field gives
   it.  tests/test_claims.c holds the claims about stability, basins and
   the massless skate and the program's main; tests/claims-motion.c the
   claims about motions (Section 4 and the figures). */
#ifndef CHAPLYGIN_CLAIMS_H
#define CHAPLYGIN_CLAIMS_H

#include <check.h>

/* Register TEST as the TCase NAME of S and note NAME, so that main can
   compare the registered checks with the registry's list. */
void claim_case (Suite *s, const char *name, const TTest *test);

/* The motion claims' checks (tests/claims-motion.c). */
void claims_motion_cases (Suite *s);

#endif
