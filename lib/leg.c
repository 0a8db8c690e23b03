/* leg.c -- kernel: the heading and time along one leg of a motion between
   collisions, by the closed form (Carlson integrals, ellint.c) or adaptive
   quadrature (quad.c); the ODE route of a leg is the caller's (ode.c).
   Uses motion.h, ellint.c, quad.c.

   Notation.  l = L0 + D is the signed distance from the peg to the mass
   centre.  Between collisions the energy E (3.3) and the angular momentum
   about the peg H (3.4) are constant, so with h = H/sqrt(2E)

       V^2 = 2E - H^2/(1 + l^2) = 2E g(l)/(1 + l^2),   g(l) = l^2 + 1 - h^2,
       Omega = H/(1 + l^2),
       dtheta/dl = Omega/V,   dtau/dl = 1/V.

   Two regimes (manual, "Closed forms"):
   A.  h^2 <= 1: g > 0 for all l != 0, no turning point.  With t = |l|,
         |dtheta| = |h| dt/sqrt((t^2 + 1)(t^2 + 1 - h^2)),
          dtau    = (1/sqrt(2E)) sqrt((t^2 + 1)/(t^2 + 1 - h^2)) dt,
       i.e. p = 1, q = 1 - h^2, p - q = h^2.
   B.  h^2 > 1: turning points at |l| = c = sqrt(h^2 - 1), motion only where
       |l| >= c.  With w = sqrt(l^2 - c^2) (w = 0 at the turning point),
         |dtheta| = |h| dw/sqrt((w^2 + c^2)(w^2 + h^2)),
          dtau    = (1/sqrt(2E)) sqrt((w^2 + h^2)/(w^2 + c^2)) dw,
       i.e. p = h^2, q = h^2 - 1, p - q = 1.
   The integrals are those of chp_quartic_interval;
   sqrt(p) cancels |h| in B, and dtheta = sign(H) min(|h|, 1) F.  */
#include <config.h>

#include <math.h>
#include <stddef.h>

#include "eft.h"
#include "ellint.h"
#include "leg.h"
#include "motion.h"
#include "quad.h"

/* ---- quadrature integrands (the paper's, in |l|; in u at turning points)

   The integration variable t runs from 0 over an interval whose width is
   known exactly; the physical variable (|l| or u) is A + t, so rounding
   only perturbs where the integrand is evaluated, never the width.  The
   integrands are written with hypot so that they neither overflow nor
   underflow for any |l| the library accepts. */
struct quad_par
{
  const chp_motion *m;
  double A;
  double w;             /* max(|h|, 1): the part of |h| in the integrand */
};

/* Regime A, |l| = A + t: |dtheta/dl| = |h|/sqrt((1 + l^2)(l^2 + q)),
   integrated as w/sqrt(...) times min(|h|, 1) (w = max(|h|, 1) <= sq + 1):
   the integral of 1/sqrt(...) alone underflows for a short leg at large
   |l| where the heading does not, and |h| inside alone would make the
   integrand subnormal for a subnormal H. */
static double
qa_theta (double t, void *p)
{
  const struct quad_par *qp = p;
  double l = qp->A + t;
  return qp->w / (hypot (1.0, l) * hypot (l, qp->m->sqrt_q));
}

/* Regime A: sqrt(2E) dtau/dl = sqrt((1 + l^2)/(l^2 + q)). */
static double
qa_tau (double t, void *p)
{
  const struct quad_par *qp = p;
  double l = qp->A + t;
  return hypot (1.0, l) / hypot (l, qp->m->sqrt_q);
}

/* Regime B, u = A + t with |l| = c + u^2, g = u^2 (|l| + c):
   |dtheta/du| = 2 |h|/sqrt((1 + l^2)(|l| + c)) (w inside, as above). */
static double
qb_theta (double t, void *p)
{
  const struct quad_par *qp = p;
  double u = qp->A + t, c = qp->m->sqrt_q, al = c + u * u;
  return 2.0 * qp->w / (hypot (1.0, al) * sqrt (al + c));
}

/* Regime B: sqrt(2E) dtau/du = 2 sqrt((1 + l^2)/(|l| + c)). */
static double
qb_tau (double t, void *p)
{
  const struct quad_par *qp = p;
  double u = qp->A + t, c = qp->m->sqrt_q, al = c + u * u;
  return 2.0 * hypot (1.0, al) / sqrt (al + c);
}

/* Integrate over t in [0, W] (the variable A + t), in pieces over which
   A + t at most doubles once it exceeds 1: the integrands vary on the
   scale max(A + t, 1), and one Gauss-Kronrod panel cannot span decades
   (a leg may run from |l| ~ 1 to 1e100).  Sums into *th, *ta. */
static int
quad_geometric (double (*f_th) (double, void *),
                double (*f_ta) (double, void *), const chp_motion *m, double A,
                double W, double tol, double *th, double *ta)
{
  struct quad_par qp = { m, A, chp_max (fabs (m->h), 1.0) };
  double t = 0.0, r;
  while (t < W)
    {
      double next = 2.0 * chp_max (A + t, 1.0) - A;
      double tn = (next > t && next < W) ? next : W;
      if (th)
        {
          CHP_TRY (chp_integrate (f_th, &qp, t, tn, tol, &r));
          *th += r;
        }
      if (ta)
        {
          CHP_TRY (chp_integrate (f_ta, &qp, t, tn, tol, &r));
          *ta += r;
        }
      t = tn;
    }
  return CHAPLYGIN_SUCCESS;
}

/* chp_leg: heading and time along one leg from la to lb.
   Closed form: the reductions of the file comment, with the interval in t
   (regime A; split at t = 0 when la, lb straddle 0) or in w (regime B; the
   width w_b - w_a = (|lb| - |la|)(|la| + |lb|)/(w_a + w_b) is formed from dl,
   not by subtraction).
   Quadrature: the paper's integrands of (B.2)/(B.3) in l (regime A, split
   at 0 where the integrand peaks), or in u = sqrt(|l| - c) (regime B), which
   removes the inverse-square-root singularity at a turning point; adaptive
   Gauss-Kronrod to opt->tol. */
int
chp_leg (const chp_motion *m, double la, double ga, double lb, double gb,
         double dl, const chaplygin_options *opt, double *dtheta,
         double *dtau)
{
  double F = 0.0, T = 0.0;
  double *pF = dtheta ? &F : NULL, *pT = dtau ? &T : NULL;
  double aa = fabs (la), ab = fabs (lb);

  if (dl == 0.0)
    {
      if (dtheta)
        *dtheta = 0.0;
      if (dtau)
        *dtau = 0.0;
      return CHAPLYGIN_SUCCESS;
    }

  if (opt->method == CHAPLYGIN_CLOSED_FORM)
    {
      if (m->H == 0.0)
        {
          /* Straight line: Omega = 0, V^2 = 2E. */
          T = dl;
          F = 0.0;
        }
      else if (m->one_minus_h2 >= 0.0)
        {
          if (la * lb < 0.0)
            {
              double F1 = 0.0, T1 = 0.0, F2 = 0.0, T2 = 0.0;
              CHP_TRY (chp_quartic_interval (
                  m->sqrt_p, m->sqrt_q, m->p_minus_q, 0.0, aa, aa,
                  opt->precision, pF ? &F1 : NULL, pT ? &T1 : NULL));
              CHP_TRY (chp_quartic_interval (
                  m->sqrt_p, m->sqrt_q, m->p_minus_q, 0.0, ab, ab,
                  opt->precision, pF ? &F2 : NULL, pT ? &T2 : NULL));
              F = F1 + F2;
              T = T1 + T2;
            }
          else
            CHP_TRY (chp_quartic_interval (m->sqrt_p, m->sqrt_q, m->p_minus_q,
                                           chp_min (aa, ab), chp_max (aa, ab),
                                           dl, opt->precision, pF, pT));
        }
      else
        {
          double wa = sqrt (ga), wb = sqrt (gb);
          double dw = dl * ((aa + ab) / (wa + wb));
          CHP_TRY (chp_quartic_interval (m->sqrt_p, m->sqrt_q, m->p_minus_q,
                                         chp_min (wa, wb), chp_max (wa, wb),
                                         dw, opt->precision, pF, pT));
        }
      if (dtheta)
        *dtheta = m->theta_factor * F;
      if (dtau)
        *dtau = T / m->sqrt2E;
      return CHAPLYGIN_SUCCESS;
    }

  /* Quadrature, over intervals of exactly known width. */
  double *qF = dtheta ? &F : NULL, *qT = dtau ? &T : NULL;
  if (m->one_minus_h2 >= 0.0)
    {
      /* in |l|: two pieces from 0 if la, lb straddle l = 0 (where the
         integrand peaks), one otherwise */
      if (la * lb < 0.0)
        {
          CHP_TRY (
              quad_geometric (qa_theta, qa_tau, m, 0.0, aa, opt->tol, qF, qT));
          CHP_TRY (
              quad_geometric (qa_theta, qa_tau, m, 0.0, ab, opt->tol, qF, qT));
        }
      else
        CHP_TRY (quad_geometric (qa_theta, qa_tau, m, chp_min (aa, ab), dl,
                                 opt->tol, qF, qT));
    }
  else
    {
      /* in u = sqrt(|l| - c): |l| - c = g/(|l| + c) without cancellation,
         and u_b - u_a = (|lb| - |la|)/(u_a + u_b) = +-dl/(u_a + u_b) */
      double c = m->sqrt_q;
      double ua = sqrt (ga / (aa + c)), ub = sqrt (gb / (ab + c));
      CHP_TRY (quad_geometric (qb_theta, qb_tau, m, chp_min (ua, ub),
                               dl / (ua + ub), opt->tol, qF, qT));
    }
  F *= chp_min (fabs (m->h), 1.0);
  if (dtheta)
    *dtheta = chp_sign (m->H) * F;
  if (dtau)
    *dtau = T / m->sqrt2E;
  return CHAPLYGIN_SUCCESS;
}

