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

/* ---- reversal.c: a run of collisions without reversal ------------- */

/* A run of collisions without reversal in direction dir: the (B.3)
   coefficients and what the series (B.6), (B.9), (B.10) need of them. */
typedef struct
{
  int dir;
  double Delta;
  double s;             /* 2 L0 + Delta = l_s + l_f, rounded once */
  double ls, ls_err;    /* l at the starting end (+ its rounding error) */
  double lf, lf_err;    /* l at the far end */
  int toward;           /* the path moves towards l = 0: dir ls < 0 */
  int crosses;          /* the path reaches l = 0 (ls, lf not of one
                           strict sign; by signs, not by ls lf <= 0) */
  double C1, C2;        /* (B.3): E' = E + C1 H^2, H' = C2 H */
  double c2m1, c2p1;    /* C2 - 1 and C2 + 1, each to a few ulps */
  double omq;           /* 1 - C2^2 = -(C2 - 1)(C2 + 1) */
  double logq;          /* log C2^2: 2 log1p(|C2| - 1) for |C2| > 1/2,
                           2 log |C2| otherwise; -Inf if C2 = 0 */
  double kappa;         /* 1 + 2 C1 (1 + ls^2)/(1 - C2^2)
                           = 1 - dir Delta/(lf (2 + lf (2 L0 + Delta))) */
} chp_run;

/* The run of direction dir of a valid system.  CHAPLYGIN_EINVAL (dir),
   CHAPLYGIN_EDOM (system), CHAPLYGIN_ERANGE (|l| > CHP_L_MAX). */
int chp_run_init (const chaplygin_discrete *sys, int dir, chp_run *run);

/* What the path of a post-collision state of the run does: exactly the
   classification of chaplygin_discrete_step (m: the motion, valid). */
enum
{
  CHP_FATE_PASS = 0,      /* reaches the far end: a (B.3) collision */
  CHP_FATE_REVERSE = 1,   /* turns (B.5) and returns: a (B.4) collision */
  CHP_FATE_SPIN = 2       /* 2E = H^2 and reaches l = 0: no collision */
};
int chp_run_fate (const chp_run *run, const chp_motion *m);

/* (B.9) the state after k collisions of the run, no checks:
   E_k = E + C1 H^2 S_k, S_k = expm1(k log q)/(q - 1) (k if q = 1),
   H_k = C2^k H.  CHAPLYGIN_ERANGE if either is not finite. */
int chp_run_state (const chp_run *run, double E, double H, double k,
                   double *Ek, double *Hk);

/* (B.10) as E g0/(1 + ls^2) + kappa H^2/(2 (1 + ls^2)), g0 = g(ls)
   (= (1 + ls^2) V^2/(2E)): V^2/2 + kappa (1 + ls^2) Omega^2/2, the form
   of (B.12), without the cancellation of E + C1 H^2/(1 - C2^2) when
   kappa >= 0.  Meaningful only for omq > 0. */
double chp_run_final_energy (const chp_run *run, double E, double g0,
                             double H);

#endif /* CHAPLYGIN_INTERNAL_H */
