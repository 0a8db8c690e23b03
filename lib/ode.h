/* ode.h -- kernel: event-located integration of (3.1) (ode.c).  Uses GSL
   and motion.h. */
#ifndef CHAPLYGIN_ODE_H
#define CHAPLYGIN_ODE_H

#include "chaplygin.h"

/* Integrate (3.1) from q0 (tau = 0) until D leaves the open interval
   (Dlo, Dhi), landing exactly on the bound it crosses, or, if stop_at_turn,
   until V reaches 0, landing exactly there.  q1 and *tau receive the state
   and time of the event; *turned = 1 if it was V = 0.  Runge-Kutta-Prince-
   Dormand 8(9) with relative tolerance tol; see ode.c.  The theta and
   Omega of q0 and q1 are 2^k times the true ones (k = 0: unscaled; a
   caller with a tiny H passes it scaled, to keep its relative precision
   through the subnormal range). */
int chp_ode_until (double L0, const double q0[4], int k, double Dlo,
                   double Dhi, int stop_at_turn, double tol, double q1[4],
                   double *tau, int *turned);

#endif /* CHAPLYGIN_ODE_H */
