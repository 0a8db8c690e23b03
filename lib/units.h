/* units.h -- the start of a run in the units of its velocity scaling, the
   one sequence behind chaplygin_discrete_scaled_state (units.c) and
   chaplygin_massless_scaled_state (massless.c).  Internal to lib/. */
#ifndef CHAPLYGIN_UNITS_H
#define CHAPLYGIN_UNITS_H

#include "chaplygin.h"

/* The velocity scaling of the start q = {D+, V+, theta+, Omega+} at l0
   (chaplygin_velocity_scaling), and tau: *m, s = q with V+, Omega+ times
   2^m, *taus = tau 2^-m (a time in the scaled units).  The statuses of
   the two functions. */
int chp_scaled_start (double l0, const double q[4], double tau, double s[4],
                      double *taus, int *m);

/* The outputs of a scaled start: *st = *out, *mo = m, s into qs (may be
   NULL). */
void chp_scaled_out (const chaplygin_discrete_state *out, int m,
                     const double s[4], chaplygin_discrete_state *st,
                     int *mo, double qs[4]);

#endif /* CHAPLYGIN_UNITS_H */
