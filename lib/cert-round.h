/* cert-round.h -- correct rounding to binary64 for the certified method
   (issue 28): an exact rational, and a ball of Arb when it decides; and
   the exact rational of a ratio of two doubles.
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

/* The outcomes of chp_cert_round_ball. */
enum
{
  CHP_CERT_ROUNDED = 0,         /* decided: *X the nearest double */
  CHP_CERT_UNDECIDED = 1,       /* across a rounding boundary: more
                                   precision */
  CHP_CERT_BEYOND = 2           /* all of the ball rounds beyond DBL_MAX
                                   (|B| >= DBL_MAX + ulp(DBL_MAX)/2) */
};

/* chp_cert_round_arb, with the ball beyond the doubles told apart from
   one that does not decide: a CHP_CERT_ outcome (*X written only for
   CHP_CERT_ROUNDED). */
int chp_cert_round_ball (const arb_t b, double *x);

/* Q = R[0]/R[1] exactly: nonzero, or 0 (Q untouched) where R[0] or R[1] is
   not finite or R[1] = 0. */
int chp_cert_q_of_ratio (fmpq_t q, const double r[2]);

#endif
