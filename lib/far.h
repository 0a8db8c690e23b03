/* far.h -- kernel: the exact power-of-two scaling of the far regime,
   |l| > CHP_L_MAX (far.c; its file comment states the physics and the
   domain).  Uses eft.h, collision.h and motion.h. */
#ifndef CHAPLYGIN_FAR_H
#define CHAPLYGIN_FAR_H

#include <math.h>

#include "chaplygin.h"
#include "motion.h"

/* Whether the slot of SYS reaches the far regime: |l| > CHP_L_MAX at
   either end (the test every caller that goes by l_end makes). */
static inline int
chp_system_far (const chaplygin_discrete *sys)
{
  return fabs (sys->l_end[0]) > CHP_L_MAX || fabs (sys->l_end[1]) > CHP_L_MAX;
}

/* The scaling of one problem: lengths times 2^-k, energies times 4^m,
   quantities linear in H (where the motion is) by a further 2^j; k = 0
   within the cap (nothing to scale: the caller computes unscaled). */
typedef struct
{
  int k, m, j;
  chaplygin_discrete sys;       /* the scaled system (chp_far_open, k > 0) */
} chp_far;

/* The kinds of quantity, each with its power of two (chp_far_exponent). */
typedef enum
{
  CHP_Q_LENGTH,                 /* l, D, Delta, turning points: 2^-k */
  CHP_Q_ENERGY,                 /* E, V^2: 4^m */
  CHP_Q_SPEED,                  /* V: 2^m */
  CHP_Q_MOMENTUM,               /* H: 2^(m-k+j) */
  CHP_Q_RATE,                   /* Omega: 2^(m+k+j) */
  CHP_Q_TIME,                   /* tau: 2^-(k+m) */
  CHP_Q_HEADING,                /* theta increments: 2^j */
  CHP_Q_INVERSE_AREA,           /* 1/(1 + l^2), 2E/H^2: 2^2k */
  CHP_Q_DENERGY_DMOMENTUM,      /* dE'/dH of the Jacobian: 2^(m+k+j) */
  CHP_Q_DHEADING_DENERGY,       /* dtheta'/dE: 2^(j-2m) */
  CHP_Q_DHEADING_DMOMENTUM      /* dtheta'/dH: 2^(k-m) */
} chp_quantity;

/* The scaling of the slot (L0, Delta): CHAPLYGIN_EDOM unless both are
   finite and Delta > 0; k = 0 within the cap; for a far slot k > 0 and
   f->sys the scaled system (min |l| in [2^99, 2^100), max below 2^500);
   CHAPLYGIN_ERANGE elsewhere beyond the cap or where 2^-k Delta is not a
   normal double.  m = j = 0 until a state is scaled. */
int chp_far_open (double L0, double Delta, chp_far *f);

/* The same for a system made by chaplygin_discrete_init (or any with its
   L0 and Delta: validated), and CHAPLYGIN_EDOM where its ends l_end lie
   beyond the cap although L0 and Delta do not (a struct not made by
   chaplygin_discrete_init: callers that go by l_end would use f->sys,
   which is then not set). */
int chp_far_open_sys (const chaplygin_discrete *sys, chp_far *f);

/* The scaling of a path from la to lb (a leg of (B.1), (B.2)): k only,
   f->sys not set.  CHAPLYGIN_ERANGE as chp_far_open. */
int chp_far_open_path (double la, double lb, chp_far *f);

/* m (E scaled into [1/2, 2)), j and the scaled E, H of a state; where
   2^(m-k) H would be below 2^-570: j > 0 if LINEAR (the caller's results
   are linear in H there), else m raised while 4^m E <= 2^1000, else
   CHAPLYGIN_ERANGE.  k = 0: E unchanged, H as is. */
int chp_far_state (chp_far *f, double E, double H, int linear, double *Es,
                   double *Hs);

/* A discrete-skate state IN in the scaled problem: E, H by chp_far_state
   (LINEAR as there), the rest copied, and the V^+ IN keeps scaled with
   them (0 where it has none or its scaling is not exact): E and H cannot
   hold a V^+ below about 2^-26 sqrt(2E) (V = Omega = 1 at L0 = 1e200),
   which the state then carries alone. */
int chp_far_state_of (chp_far *f, const chaplygin_discrete_state *in,
                      int linear, chaplygin_discrete_state *si);

/* m (the speed max(|V|, |l0 Omega|) scaled near 1 when k > 0; j = 0) and
   the scaled V, Omega of a phase state at l0.  CHAPLYGIN_ERANGE where a
   scaling is not exact. */
int chp_far_phase (chp_far *f, double l0, double V, double Omega,
                   double *Vs, double *Omegas);

/* 1 if the phase state (V, Omega) at l0 must be time-scaled by
   chp_far_speed before E and H are formed (its speed max(|V|, sqrt(1 +
   l0^2) |Omega|) times max(1, |l0|) above 2^450 or beyond DBL_MAX, or
   the speed below 2^-400), 0 if not (also for a zero speed or non-finite
   inputs). */
int chp_far_speed_needed (double l0, double V, double Omega);

/* m alone (the time-scaling, exact for any rho: also within the cap, k =
   0): the speed max(|V|, sqrt(1 + l0^2) |Omega|) scaled into [1, 2) (also
   where it overflows), and the scaled V, Omega.  CHAPLYGIN_ERANGE where a
   scaling is not exact. */
int chp_far_speed (chp_far *f, double l0, double V, double Omega,
                   double *Vs, double *Omegas);

/* e: a quantity of kind q is scaled as x 2^e. */
int chp_far_exponent (const chp_far *f, chp_quantity q);

/* The true value of a scaled quantity of kind q (may underflow or
   overflow: the caller checks what it returns). */
double chp_far_out (const chp_far *f, chp_quantity q, double scaled);

/* The same, 1 if exact and finite (*x written), 0 if not. */
int chp_far_out_exact (const chp_far *f, chp_quantity q, double scaled,
                       double *x);

/* The scaled value of a quantity of kind q: 1 if exact and finite
   (*scaled written), 0 if not. */
int chp_far_in (const chp_far *f, chp_quantity q, double x, double *scaled);

#endif /* CHAPLYGIN_FAR_H */
