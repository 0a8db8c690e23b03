/* cert-eval.h -- the shared mechanisms of the certified closed forms
   (issue 28): exact inputs as FLINT rationals, Ziv's loop on an Arb ball,
   and exact work with square roots.  Used by cert-algebraic.c and the
   other certified evaluators (cert-smooth.c, cert-massless.c,
   cert-series.c, cert-units.c).  Internal to libchaplygin; built only
   with Arb. */
#ifndef CHAPLYGIN_CERT_EVAL_H
#define CHAPLYGIN_CERT_EVAL_H

#include <arb.h>
#include <flint/fmpq.h>

/* Ziv's loop: the first working precision and the cap (bits). */
enum { CHP_CERT_PREC_START = 64, CHP_CERT_PREC_CAP = 1 << 16 };

/* The exact rationals of one call, initialised and cleared together. */
enum { CHP_CERT_NQ = 12 };
typedef struct
{
  fmpq_t q[CHP_CERT_NQ];
} chp_cert_qset;

void chp_cert_qset_init (chp_cert_qset *s);
void chp_cert_qset_clear (chp_cert_qset *s);

/* *Q = R[0]/R[1]: CHAPLYGIN_SUCCESS, or CHAPLYGIN_EDOM (not finite, or
   R[1] = 0). */
int chp_cert_in (fmpq_t q, const double r[2]);

/* The slot's parameters: L0, Delta exact, Delta > 0 (CHAPLYGIN_EDOM
   otherwise). */
int chp_cert_slot_in (fmpq_t L0, fmpq_t Delta, const double L0r[2],
                      const double Deltar[2]);

/* T = 1 + A^2. */
void chp_cert_one_plus_sq (fmpq_t t, const fmpq_t a);

/* C1 of (3.7), (B.3)/(B.4) for the collision that leaves l = B for
   l = B' (the ends of a slot of length DELTA):
     C1 = -Delta^2/(2 (1 + b^2)^2 (1 + b'^2)),
   the energy it takes being -C1 H^2.  C1 may alias an input. */
void chp_cert_c1 (fmpq_t c1, const fmpq_t Delta, const fmpq_t b,
                  const fmpq_t bp);

/* Nonzero, and *R = sqrt(A), where A is the square of a rational; else 0
   (R untouched). */
int chp_cert_sqrt_q (fmpq_t r, const fmpq_t a);

/* Round each of the N rationals Q[i] into X[i]: CHAPLYGIN_SUCCESS, or
   the first failure's status (X then partly written: callers round into a
   copy and write their outputs only on success). */
int chp_cert_round_all (fmpq *const *q, int n, double *x);

/* A value as a ball at the working precision PREC. */
typedef void (*chp_cert_ball_fn) (arb_t r, const void *data, slong prec);

/* *X = the double nearest to the value F encloses (F's balls must shrink
   to it as PREC grows), raising the precision from CHP_CERT_PREC_START
   until a ball decides: CHAPLYGIN_SUCCESS, CHAPLYGIN_ERANGE (the ball lies
   beyond DBL_MAX's rounding boundary), or CHAPLYGIN_ECAP (undecided at
   CHP_CERT_PREC_CAP bits: a value that is a double or a midpoint must be
   recognised exactly before, never left to this loop). */
int chp_cert_ziv_round (chp_cert_ball_fn f, const void *data, double *x);

/* *X = A + S sqrt(R) rounded (R >= 0, S = +-1): exactly where R is the
   square of a rational, else by Ziv's loop (the value is then
   irrational: no double and no midpoint). */
int chp_cert_round_sqrt_expr (const fmpq_t a, const fmpq_t r, int s,
                              double *x);

/* The sign of sqrt(R) - T (R >= 0), exactly: -1, 0 or 1. */
int chp_cert_cmp_sqrt (const fmpq_t r, const fmpq_t t);

/* ---- the discrete skate's exact numbers ------------------------------- */

/* The path of direction DIR (+1 or -1): l = L0 + D at its start LS and its
   far end LF (LS = L0, LF = L0 + Delta for DIR = +1). */
void chp_cert_path_ends (fmpq_t ls, fmpq_t lf, const fmpq_t L0,
                         const fmpq_t Delta, int dir);

/* C = [1 + L0 (L0 + Delta)]/(1 + B^2), the momentum ratio C2 of (3.7) for
   the peg leaving the end B = L0 + D- (T scratch). */
void chp_cert_momentum_ratio (fmpq_t c, const fmpq_t L0, const fmpq_t Delta,
                              const fmpq_t b, fmpq_t t);

/* The (3.7) coefficients of the collision at which the peg leaves the end
   B = L0 + D- (B' = 2 L0 + Delta - B the other end):
   C1 = -Delta^2/(2 (1 + B^2)^2 (1 + B'^2)), C2 of chp_cert_momentum_ratio. */
void chp_cert_coefficients (fmpq_t C1, fmpq_t C2, const fmpq_t L0,
                            const fmpq_t Delta, const fmpq_t b);

/* G = 2E (1 + L^2) - H^2: the sign of V^2 at l = L. */
void chp_cert_g (fmpq_t g, const fmpq_t E, const fmpq_t H, const fmpq_t l);

/* The outcomes of a path (chp_cert_classify). */
enum
{
  CHP_CERT_PASS = 0,            /* reaches the far end: a (B.3) collision */
  CHP_CERT_REVERSE = 1,         /* turns back: (B.4) */
  CHP_CERT_SPIN = 2             /* ends in the spinning state (3.8) */
};

/* The outcome of the path of direction DIR from the state (E > 0, H),
   exactly, and *Q = 1 - H^2/(2E): q = 0 on a path that reaches l = 0
   spins; q < 0 reverses where the path reaches l = 0 or lf^2 + q <= 0 (a
   turning point exactly at the far end is a reversal, the library's
   convention). */
int chp_cert_classify (fmpq_t q, const fmpq_t L0, const fmpq_t Delta,
                       int dir, const fmpq_t E, const fmpq_t H);

/* (B.10): EF = E + C1 H^2/(1 - C2^2) (C2^2 != 1). */
void chp_cert_final_energy (fmpq_t Ef, const fmpq_t E, const fmpq_t H,
                            const fmpq_t C1, const fmpq_t C2);

#endif
