/* certref.h -- the reference route's instruments shared by the tests of
   the certified method (tests/test_cert_*.c): exact rationals in GMP (the
   library uses FLINT's), rounding to binary64 by MPFR (the library:
   cert-round.c's exact comparisons with midpoints), an Arb ball's
   rounding decided by MPFR at both ends, and random exact inputs. */
#ifndef CHAPLYGIN_TESTS_CERTREF_H
#define CHAPLYGIN_TESTS_CERTREF_H

#include <math.h>

#include <arb.h>
#include <gmp.h>
#include <mpfr.h>

#include "testutil.h"

/* Q = R[0]/R[1] (GMP converts doubles exactly). */
void cr_q_of (mpq_t q, const double r[2]);

/* The double nearest to X (any precision) or Q, ties to even, subnormals
   included: binary64 emulated as MPFR's manual says. */
double cr_round_fr (const mpfr_t x);
double cr_round_q (const mpq_t q);

/* SGN sqrt(Q) rounded (Q >= 0): exactly where Q is the square of a
   rational (GMP's mpz_perfect_square_p), else from MPFR at 3000 bits
   (an irrational number: no double and no midpoint, and 3000 bits far
   from both). */
double cr_round_sqrt_q (const mpq_t q, int sgn);

/* *X = the double nearest to every point of the ball B (both its ends,
   rounded by MPFR, the same double): 1, else 0. */
int cr_round_ball (const arb_t b, double *x);

/* The same doubles, signed zeros told apart. */
int cr_same (double a, double b);

/* |A - B| in units of the last place of B. */
double cr_ulps (double a, double b);

#define ck_assert_same(got, want)                                           \
  do                                                                        \
    {                                                                       \
      double g_ = (got), w_ = (want);                                       \
      ck_assert_msg (cr_same (g_, w_), "%s = %a (%.17g), want %a (%.17g)",  \
                     #got, g_, g_, w_, w_);                                 \
    }                                                                       \
  while (0)

#define ck_assert_ulps(got, want, n)                                        \
  do                                                                        \
    {                                                                       \
      double g_ = (got), w_ = (want);                                       \
      ck_assert_msg (cr_ulps (g_, w_) <= (n), "%s = %.17g, want %.17g "     \
                     "within %g ulps: %g", #got, g_, w_, (double) (n),      \
                     cr_ulps (g_, w_));                                     \
    }                                                                       \
  while (0)

/* A random exact input near X: P/(Q 2^k) with Q up to 2^20, up to
   2^53 - 1, or the double X itself (each a third of the time); 2^k brings
   a small X's significand into P. */
void cr_ratio_near (tu_rng *g, double x, double r[2]);

/* A random exact input in [A, B). */
void cr_ratio_in (tu_rng *g, double a, double b, double r[2]);

/* The reference route's leg integrals (Arb's rigorous integration,
   acb_calc_integrate, of the paper's integrands): on a leg without a
   turning point nearby (REV = 0) in D, l = L0 + D (L0 = 0: in l); with
   one (REV = 1) in w, |l| = LT + w^2, LT the turning point, with no
   singularity at it nor beside it.  KIND 0: the heading |H|/sqrt((1 +
   l^2) g), 1: the time sqrt(1 + l^2)/sqrt(g), g = 2E (1 + l^2) - H^2
   (TWOE = 2E, H2 = H^2, ABSH = |H|). */
typedef struct
{
  arb_t L0, twoE, H2, absH;
  int kind;                     /* 0 heading, 1 time */
  int rev;                      /* a leg to a turning point: in w */
  arb_t la, lt;                 /* leg start, turning point (rev) */
} cr_leg;

/* R = |the integral of P's integrand from A to B| (real ends), at PREC
   bits (tolerance 2^(20 - PREC)). */
void cr_leg_integrate (arb_t r, cr_leg *p, const arb_t A,
                       const arb_t B, slong prec);

/* A double input X taken as the ratio {X, 1}. */
#define AS_RATIO(x) ((const double[2]) { (x), 1.0 })

#endif
