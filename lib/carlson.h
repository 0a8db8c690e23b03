/* carlson.h -- the library's own kernel for Carlson's symmetric elliptic
   integrals R_F and R_D: one duplication loop for both.  Internal (not
   installed, not exported): a leaf of lib/, it uses nothing of the library
   but the status codes and the precision enum of chaplygin.h.  See
   carlson.c for the method, the constants and the measured accuracy. */
#ifndef CHAPLYGIN_CARLSON_H
#define CHAPLYGIN_CARLSON_H

#include "chaplygin.h"

/* chp_carlson_rfrd: R_F(x, y, z) into *rf and R_D(x, y, z) into *rd, where
       R_F(x, y, z) = 1/2 Int_0^inf dt / sqrt((t + x)(t + y)(t + z)),
       R_D(x, y, z) = 3/2 Int_0^inf dt / [sqrt((t + x)(t + y)) (t + z)^(3/2)]
   (DLMF 19.16.5, 19.16.6).  A NULL pointer means "not requested"; each
   value has the same bits whether it is requested alone or with the other.
   prec: CHAPLYGIN_PREC_DOUBLE (a few ulps), CHAPLYGIN_PREC_SINGLE (~1e-12
   relative, one duplication step fewer); any other value means DOUBLE.
   Domain: x, y, z >= 0 and finite; for R_F at most one of them zero; for
   R_D z > 0 and x + y > 0.
   Returns 0 on success, and writes nothing otherwise:
     CHAPLYGIN_EDOM   an argument negative, NaN or infinite; z = 0 with R_D
                      requested;
     CHAPLYGIN_ERANGE the requested integral is infinite (two zero arguments
                      for R_F, x = y = 0 for R_D), or R_D overflows, or (R_D
                      only) max(x, y, z) > 2^500 with z < 2^-600 max(x, y, z),
                      a corner that is not supported (as in chp_rd).
   The checks for a request of both are the union of the checks of each.
   Reentrant, no allocation, no libm call but sqrt on the common path. */
int chp_carlson_rfrd (double x, double y, double z, chaplygin_precision prec,
                      double *rf, double *rd);

/* chp_carlson_rfrd_x1: the same as chp_carlson_rfrd (1.0, y, z, prec, rf,
   rd), bit for bit and status for status, faster: chp_quartic_interval's
   triples (1, 1 + k'^2 tan^2 mu, 1 + tan^2 mu) have x = 1, so the first
   duplication step needs no square root of it, and for y, z in
   [1, 2^100] no sorting, scaling or range test is needed. */
int chp_carlson_rfrd_x1 (double y, double z, chaplygin_precision prec,
                         double *rf, double *rd);

/* The 7th-order series of carlson.c (step 2), 1 + ..., in Carlson's
   elementary symmetric functions: R_F(A(1 - X), A(1 - Y), A(1 - Z)) =
   A^-1/2 chp_carlson_series_rf (E2, E3) + O(t^8) and likewise R_D with
   A^-3/2.  For the tests (tests/test_carlson checks every coefficient
   against the hypergeometric expansion); the kernel inlines its own. */
double chp_carlson_series_rf (double E2, double E3);
double chp_carlson_series_rd (double E2, double E3, double E4, double E5);

#endif
