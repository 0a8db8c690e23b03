/* internal.h -- helpers shared by the sources of libchaplygin; not
   installed, not exported (the shared library exports only chaplygin_*).  */
#ifndef CHAPLYGIN_INTERNAL_H
#define CHAPLYGIN_INTERNAL_H

#include <math.h>
#include "chaplygin.h"

#include "eft.h"
#include "status.h"
#include "collision.h"

/* ---- ellint.c: Carlson integrals and the quartic reduction ---------- */

/* Carlson's R_F(x, y, z) and R_D(x, y, z) for x, y, z >= 0 (at most one
   zero for R_F; x + y > 0 for R_D), through GSL within its domain, by exact
   power-of-two scaling outside it, and by the leading asymptotic term when
   two arguments are below 2^-100 times the third.  Never invokes GSL's
   error handler.  CHAPLYGIN_ERANGE if the integral is infinite. */
int chp_rf (double x, double y, double z, chaplygin_precision prec,
            double *r);
int chp_rd (double x, double y, double z, chaplygin_precision prec,
            double *r);

/* The two integrals every closed form of Appendix B reduces to, with
   P(t) = (t^2 + p)(t^2 + q), p = sp^2, q = sq^2, pmq = p - q > 0,
   0 <= y <= x, dxy = x - y given separately (exactly):
     *F = sqrt(p) * Int_y^x dt/sqrt(P(t))   = F(mu, k), k^2 = (p - q)/p,
     *T = Int_y^x sqrt((t^2 + p)/(t^2 + q)) dt.
   Either output may be NULL.  See ellint.c for the method. */
int chp_quartic_interval (double sp, double sq, double pmq, double y,
                          double x, double dxy, chaplygin_precision prec,
                          double *F, double *T);

/* ---- quad.c: adaptive Gauss-Kronrod quadrature ---------------------- */

/* Int_a^b f(t) dt to relative tolerance epsrel (raised to 64 eps at least),
   globally adaptive bisection with GSL's 21-point Kronrod rule, at most
   CHP_QUAD_LIMIT subintervals, no allocation, no GSL error handler.
   CHAPLYGIN_ENOCONV if the tolerance is not met; CHAPLYGIN_ERANGE if f
   returns a non-finite value. */
#define CHP_QUAD_LIMIT 256
int chp_integrate (double (*f) (double, void *), void *params, double a,
                   double b, double epsrel, double *result);

/* ---- ode.c: event-located integration of (3.1) ----------------------- */

/* Integrate (3.1) from q0 (tau = 0) until D leaves the open interval
   (Dlo, Dhi), landing exactly on the bound it crosses, or, if stop_at_turn,
   until V reaches 0, landing exactly there.  q1 and *tau receive the state
   and time of the event; *turned = 1 if it was V = 0.  Runge-Kutta-Prince-
   Dormand 8(9) with relative tolerance tol; see ode.c.  The theta and
   Omega of q0 and q1 are 2^k times the true ones (k = 0: unscaled; a
   caller with a tiny H passes it scaled, to keep its relative precision
   through the subnormal range). */
int chp_ode_until (double L0, const double q0[4], int k, double Dlo, double Dhi,
                   int stop_at_turn, double tol, double q1[4], double *tau,
                   int *turned);

#include "motion.h"

#include "far.h"

/* The largest |L0| the massless skate (rho = 0, lengths in units of the
   slot) accepts: 2 L0 + 1 must be finite. */
#define CHP_MASSLESS_L_MAX 0x1p1020

/* Heading and time along one leg from la to lb (no turning point strictly
   between them; lb may be one), ga = g(la), gb = g(lb), dl = |lb - la|. */
int chp_leg (const chp_motion *m, double la, double ga, double lb, double gb,
             double dl, const chaplygin_options *opt, double *dtheta,
             double *dtau);

#include "run.h"

#endif /* CHAPLYGIN_INTERNAL_H */
