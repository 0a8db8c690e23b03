/* series.h -- kernel: a run of collisions without reversal in one direction
   (series.c): the (B.3) coefficients and what the series (B.6), (B.9), (B.10)
   need of them.  Uses eft.h and motion.h. */
#ifndef CHAPLYGIN_SERIES_H
#define CHAPLYGIN_SERIES_H

#include "chaplygin.h"
#include "motion.h"

typedef struct
{
  int dir;
  double Delta;
  chp_segment seg;      /* the segment of every collision of the run: from
                           l_s = seg.l0 to l_f = seg.l1 */
  double s;             /* 2 L0 + Delta = l_s + l_f, rounded once */
  double C1, C2;        /* (B.3): E' = E + C1 H^2, H' = C2 H */
  double c2m1, c2p1;    /* C2 - 1 and C2 + 1, each to a few ulps */
  double omq;           /* 1 - q = 1 - C2^2 = -(C2 - 1)(C2 + 1) */
  double logq;          /* log q = log C2^2: 2 log1p(|C2| - 1) for
                           |C2| > 1/2, 2 log |C2| otherwise; -Inf if
                           C2 = 0 */
  double kappa;         /* 1 + 2 C1 (1 + l_s^2)/(1 - C2^2)
                           = 1 - dir Delta/(l_f (2 + l_f (2 L0 + Delta))) */
} chp_run;

/* The run of direction dir of a valid system.  CHAPLYGIN_EINVAL (dir),
   CHAPLYGIN_EDOM (system), CHAPLYGIN_ERANGE (|l| > CHP_L_MAX). */
int chp_run_init (const chaplygin_discrete *sys, int dir, chp_run *run);

/* (B.9) the state after k collisions of the run, no checks:
   E_k = E + C1 H^2 S_k, S_k = expm1(k log q)/(q - 1) (k if q = 1),
   H_k = C2^k H.  CHAPLYGIN_ERANGE if either is not finite. */
int chp_run_state (const chp_run *run, double E, double H, double k,
                   double *Ek, double *Hk);

/* H_k = C2^k H alone, as chp_run_state forms it (for a far slot, where
   the run is the scaled one and H the unscaled momentum: C2 is
   scale-free). */
int chp_run_momentum (const chp_run *run, double H, double k, double *Hk);

/* (B.10) as E g0/(1 + l_s^2) + kappa H^2/(2 (1 + l_s^2)), g0 = g(l_s)
   (= (1 + l_s^2) V^2/(2E)): V^2/2 + kappa (1 + l_s^2) Omega^2/2, the form
   of (B.12), without the cancellation of E + C1 H^2/(1 - C2^2) when
   kappa >= 0.  Meaningful only for omq > 0. */
double chp_run_final_energy (const chp_run *run, double E, double g0,
                             double H);

#endif /* CHAPLYGIN_SERIES_H */
