/* cert-round.h -- correct rounding to binary64 for the certified method
   (issue 28): an exact rational, and a ball of Arb when it decides.
   Internal to libchaplygin. */
#ifndef CHAPLYGIN_CERT_ROUND_H
#define CHAPLYGIN_CERT_ROUND_H

#include <arb.h>
#include <flint/fmpq.h>

/* *X = the double nearest to Q, ties to even (the subnormals included).
   CHAPLYGIN_SUCCESS, or CHAPLYGIN_ERANGE where |Q| rounds beyond DBL_MAX
   (at least DBL_MAX + ulp(DBL_MAX)/2; *X then untouched). */
int chp_cert_round_fmpq (const fmpq_t q, double *x);

/* Nonzero, and *X the double nearest to every point of the ball B (ties
   to even), where they all round to the same finite double; 0 (*X
   untouched) where B does not decide: a ball across a rounding boundary,
   or one with a non-finite end. */
int chp_cert_round_arb (const arb_t b, double *x);

#endif
