/* flow.c -- Appendix B.1: motion of the discrete skate between collisions,
   (B.1) and (B.2) as public functions; the integrals themselves are those
   of a leg (leg.c), the invariants those of motion.c.

   Notation.  l = L0 + D is the signed distance from the peg to the mass
   centre.  Between collisions the energy E (3.3) and the angular momentum
   about the peg H (3.4) are constant, so with h = H/sqrt(2E)

       V^2 = 2E - H^2/(1 + l^2) = 2E g(l)/(1 + l^2),   g(l) = l^2 + 1 - h^2,
       Omega = H/(1 + l^2),
       dtheta/dl = Omega/V,   dtau/dl = 1/V.  */
#include <config.h>

#include <float.h>
#include <math.h>
#include <stddef.h>

#include "chaplygin.h"
#include "eft.h"
#include "far.h"
#include "leg.h"
#include "motion.h"
#include "ode.h"
#include "status.h"

/* Whether a quantity that vanishes at a turning point, computed at D as
   x = a + p (a >= 0 its value at the start, p = k (D - D0)(2 L0 + D +
   D0) = k (l^2 - l0^2), k > 0), lies below 0 only by rounding, so that D
   is the turning point within rounding: -x at most 8 eps (a + |p| +
   k |l D|), the roundings of the terms (a few ulps each) and of D itself
   (two ulps, as the turning point D_c of chaplygin_discrete_step's event
   is rounded: moving D by an ulp moves p by up to 4 eps k |l D|).  Such a
   D is the turning point itself (x = 0).  (A D short of it by rounding is
   taken as given: the leg to it, which differs from the leg to the
   turning point by the square root of that distance.) */
static int
beyond_turning_by_rounding (double x, double a, double p, double klD)
{
  return x < 0.0 && -x <= 8.0 * DBL_EPSILON * (a + fabs (p) + klD);
}

/* chaplygin_discrete_flow: (B.1)
       V(D)^2 = V0^2 + (D - D0)(2 L0 + D + D0)(1 + (L0 + D0)^2) Omega0^2
                       / (1 + (L0 + D)^2),
       Omega(D) = Omega0 (1 + (L0 + D0)^2)/(1 + (L0 + D)^2).
   Domain: all arguments finite.  D need not lie in the slot: (B.1) is the
   conservation of E and H, valid wherever the motion goes.
   Method: as printed; (D - D0)(2 L0 + D + D0) = l^2 - l0^2 is already the
   factored difference of squares, so only V0^2 + (...) can cancel, which is
   the conditioning of V near a turning point, not of the formula.
   Accuracy: a few ulps of the terms (no division by small quantities).
   Reachability: V^2 is smallest at l = 0, so D is reached (before or after
   reversals) iff V(D)^2 >= 0 and, when the path from D0 to D crosses l = 0,
   V^2 > 0 there.  A D beyond a turning point by no more than the rounding
   of V(D)^2 and of D itself (beyond_turning_by_rounding: the event's D_c of
   chaplygin_discrete_step, which is 37% of the time such a double) is the
   turning point: V^2 = 0.
   Errors: CHAPLYGIN_EINVAL for NULL outputs; CHAPLYGIN_EDOM for non-finite
   input; CHAPLYGIN_ESTATE if D is never reached (V(D)^2 < 0, or a turning
   point lies between D0 and D); CHAPLYGIN_ERANGE on overflow. */
int
chaplygin_discrete_flow (double L0, double D0, double V0, double Omega0,
                         double D, double *V2, double *Omega)
{
  if (!V2 || !Omega)
    return CHAPLYGIN_EINVAL;
  if (!chp_finite4 (L0, D0, V0, Omega0) || !isfinite (D))
    return CHAPLYGIN_EDOM;
  double v2, om;
  if (fabs (L0 + D0) > CHP_L_MAX || fabs (L0 + D) > CHP_L_MAX)
    {
      /* far (lib/far.c): the same leg of the exactly scaled problem */
      chp_far f;
      double L0s, D0s, Ds, V0s, Om0s;
      CHP_TRY (chp_far_open_path (L0 + D0, L0 + D, &f));
      if (!chp_far_in (&f, CHP_Q_LENGTH, L0, &L0s)
          || !chp_far_in (&f, CHP_Q_LENGTH, D0, &D0s)
          || !chp_far_in (&f, CHP_Q_LENGTH, D, &Ds))
        return CHAPLYGIN_ERANGE;
      CHP_TRY (chp_far_phase (&f, L0 + D0, V0, Omega0, &V0s, &Om0s));
      CHP_TRY (chaplygin_discrete_flow (L0s, D0s, V0s, Om0s, Ds, &v2, &om));
      v2 = chp_far_out (&f, CHP_Q_ENERGY, v2);
      om = chp_far_out (&f, CHP_Q_RATE, om);
      if (!isfinite (v2))
        return CHAPLYGIN_ERANGE;
      *V2 = v2;
      *Omega = om;
      return CHAPLYGIN_SUCCESS;
    }
  CHP_TRY (chp_flow_eval (L0, D0, V0, Omega0, D, &v2, &om));
  double l0 = L0 + D0, l = L0 + D, n0 = chp_one_plus_sq (l0);
  if (beyond_turning_by_rounding (v2, V0 * V0, v2 - V0 * V0, fabs (l * D)
                                  * (n0 / chp_one_plus_sq (l))
                                  * Omega0 * Omega0))
    v2 = 0.0;
  if (v2 < 0.0)
    return CHAPLYGIN_ESTATE;
  /* V^2 is smallest where l = 0: a path that crosses l = 0 must have
     V^2 > 0 there, or D lies beyond a turning point (or the spinning
     point) although V(D)^2 >= 0. */
  if (l0 * l < 0.0 && !(V0 * V0 - l0 * l0 * n0 * Omega0 * Omega0 > 0.0))
    return CHAPLYGIN_ESTATE;
  *V2 = v2;
  *Omega = om;
  return CHAPLYGIN_SUCCESS;
}

/* The scaling of a leg of (B.2), the first phase of
   chaplygin_discrete_heading: far (lib/far.c) if |l| leaves the cap on it
   (lengths and speeds scaled); otherwise the time-scaling alone (exact for
   any rho: the heading unchanged, the time times 2^-m) where the speed
   sqrt(2E) ~ max(|V0|, |l0 Omega0|) would make H = (1 + l0^2) Omega0
   exceed 2^450 or E fall below 2^-800 (H^2 and the motion's fields would
   overflow or underflow: a heading and time of 0 were returned at
   |l0| ~ 1e150, H ~ 1e198 before, found by tests/test_far).  Once scaled,
   the speed is in [1, 2): the scaled leg needs no second scaling.
   *scaled = 1 if the caller must solve the scaled leg. */
static int
leg_scaling (double L0, double D0, double V0, double Omega0, double D,
             chp_far *f, int *scaled)
{
  const double l0 = L0 + D0, l = L0 + D;
  *scaled = 0;
  if (fabs (l0) > CHP_L_MAX || fabs (l) > CHP_L_MAX)
    {
      CHP_TRY (chp_far_open_path (l0, l, f));
      *scaled = 1;
      return CHAPLYGIN_SUCCESS;
    }
  CHP_TRY (chp_far_open_path (l0, l, f));       /* k = 0 */
  *scaled = chp_far_speed_needed (l0, V0, Omega0);
  return CHAPLYGIN_SUCCESS;
}

/* The heading and time of a leg through its scaling F (leg_scaling):
   lengths, V0 and Omega0 scaled, the scaled leg solved, the time scaled
   back (CHAPLYGIN_ERANGE where the scaled time is not a normal double, its
   digits lost); the heading is scale-free. */
static int
scaled_heading (chp_far *f, double L0, double D0, double V0, double Omega0,
                double D, const chaplygin_options *opt, double *dtheta,
                double *dtau)
{
  double L0s, D0s, Ds, V0s, Om0s, ths = 0.0, tas = 0.0, ta = 0.0;
  if (!chp_far_in (f, CHP_Q_LENGTH, L0, &L0s)
      || !chp_far_in (f, CHP_Q_LENGTH, D0, &D0s)
      || !chp_far_in (f, CHP_Q_LENGTH, D, &Ds))
    return CHAPLYGIN_ERANGE;
  if (f->k > 0)
    CHP_TRY (chp_far_phase (f, L0 + D0, V0, Omega0, &V0s, &Om0s));
  else
    CHP_TRY (chp_far_speed (f, L0 + D0, V0, Omega0, &V0s, &Om0s));
  CHP_TRY (chaplygin_discrete_heading (L0s, D0s, V0s, Om0s, Ds, opt,
                                       dtheta ? &ths : NULL,
                                       dtau ? &tas : NULL));
  if ((f->k > 0 && dtau && D != D0 && !(tas >= DBL_MIN))
      || !chp_far_out_exact (f, CHP_Q_TIME, tas, &ta))
    return CHAPLYGIN_ERANGE;
  if (dtheta)
    *dtheta = ths;
  if (dtau)
    *dtau = ta;
  return CHAPLYGIN_SUCCESS;
}

/* E (3.3) and H (3.4) of the phase state (V0, Omega0) at l0
   (CHAPLYGIN_ERANGE where they overflow). */
static int
leg_invariants (double l0, double V0, double Omega0, double *E, double *H)
{
  const double n0 = chp_one_plus_sq (l0);
  *E = 0.5 * (V0 * V0 + n0 * Omega0 * Omega0);
  *H = n0 * Omega0;
  if (!isfinite (*E) || !isfinite (*H))
    return CHAPLYGIN_ERANGE;
  return CHAPLYGIN_SUCCESS;
}

/* The motion of a leg from (D0, V0, Omega0) to D != D0, and g = (1 + l^2)
   V^2/(2E) at both ends, after the checks that D is reached: on the side
   V0 points to (or, for V0 = 0, the side the acceleration l0 Omega0^2
   points to), before any turning point or the spinning point.  1 - h^2
   from the phase inputs themselves, not from the rounded E and H, whose
   roundings it would amplify by 1/|1 - h^2| near the spinning ratio
   2E = H^2 (found by the Arb oracle: 282 ulps); g from V0 and the
   factored (B.1), g(l) = g(l0) + (D - D0)(2 L0 + D + D0), with no
   cancellation but that of V^2 itself near a turning point (g from
   1 - h^2 would lose log10(l^2/g) digits for large |l|). */
static int
leg_motion (double L0, double D0, double V0, double Omega0, double D,
            chp_motion *m, double *g0, double *gl)
{
  const double l0 = L0 + D0, l = L0 + D;
  double E, H;
  CHP_TRY (leg_invariants (l0, V0, Omega0, &E, &H));
  if (E == 0.0)
    return CHAPLYGIN_ESTATE;
  const double dirD = chp_sign (D - D0);
  if (V0 != 0.0 && chp_sign (V0) != dirD)
    return CHAPLYGIN_ESTATE;
  if (V0 == 0.0)
    {
      if (l0 == 0.0)
        return CHAPLYGIN_ESPIN;         /* the spinning equilibrium itself */
      if (chp_sign (l0) != dirD)
        return CHAPLYGIN_ESTATE;
    }
  CHP_TRY (chp_motion_init (E, H, m));
  chp_motion_set_one_minus_h2 (m, chp_phase_one_minus_h2 (l0, V0, Omega0,
                                                           2.0 * E));
  *g0 = chp_one_plus_sq (l0) * V0 * (V0 / (2.0 * E));
  const double p = (D - D0) * (2.0 * L0 + D + D0);
  *gl = *g0 + p;
  /* D beyond a turning point by rounding (the event's D_c) is the turning
     point, the end of the leg's integrals */
  if (m->one_minus_h2 < 0.0
      && beyond_turning_by_rounding (*gl, *g0, p, fabs (l * D)))
    *gl = 0.0;
  if (m->one_minus_h2 >= 0.0)
    {
      if (m->one_minus_h2 == 0.0 && l0 * l <= 0.0)
        return l == 0.0 ? CHAPLYGIN_ESPIN : CHAPLYGIN_ESTATE;
    }
  else if (*gl < 0.0 || (l0 * l < 0.0) || (l == 0.0))
    return CHAPLYGIN_ESTATE;
  return CHAPLYGIN_SUCCESS;
}

/* chaplygin_discrete_heading: (B.2)
       theta(D) = theta0 + Int_D0^D dD' / sqrt( [1 + (L0+D')^2]/[1 + (L0+D0)^2]
                  * [ (V0/Omega0)^2 [1 + (L0+D')^2]/[1 + (L0+D0)^2]
                      + (D' - D0)(2 L0 + D' + D0) ] )
   times sign(V0 Omega0) (the printed integral has the sign of D - D0, the
   heading has the sign of Omega: see the errata), and the elapsed time
   tau(D) - tau0 = Int_D0^D dD'/|V(D')|.
   Domain: finite arguments; D on the side of D0 that V0 points to (if
   V0 = 0, the side (L0 + D0) Omega0^2 accelerates towards), and not beyond
   the first turning point (D may be the turning point itself).
   Method: opt->method.  Closed form: the reduction to chp_quartic_interval
   described at the top of this file (Legendre F and E through Carlson R_F,
   R_D); quadrature: adaptive Gauss-Kronrod on the integrand above (in
   u = sqrt(|l| - c) in regime B); ODE: (3.1) integrated to D exactly
   (chp_ode_until).  g(l0) is formed from V0 directly, so the start of the
   leg carries no cancellation, and g(l) at D from the factored (B.1).
   Special cases: D = D0 gives 0, 0; Omega0 = 0 gives dtheta = 0 and
   dtau = |D - D0|/|V0|.
   Errors: CHAPLYGIN_EINVAL (both outputs NULL, bad options), CHAPLYGIN_EDOM
   (non-finite input), CHAPLYGIN_ESTATE (D on the wrong side, beyond a
   turning point or beyond the spinning point, or the skate at rest),
   CHAPLYGIN_ESPIN (D is the spinning point l = 0 with 2E = H^2, reached
   only as tau -> inf, or the start is the spinning equilibrium),
   CHAPLYGIN_ERANGE (|L0 + D| or |L0 + D0| above 2^500, overflow),
   CHAPLYGIN_ENOCONV (quadrature/ODE). */
int
chaplygin_discrete_heading (double L0, double D0, double V0, double Omega0,
                            double D, const chaplygin_options *opt,
                            double *dtheta, double *dtau)
{
  chaplygin_options o;
  if (!dtheta && !dtau)
    return CHAPLYGIN_EINVAL;
  CHP_TRY (chp_options_resolve (opt, &o));
  if (!chp_finite4 (L0, D0, V0, Omega0) || !isfinite (D))
    return CHAPLYGIN_EDOM;

  chp_far f;
  int scaled;
  CHP_TRY (leg_scaling (L0, D0, V0, Omega0, D, &f, &scaled));
  if (scaled)
    return scaled_heading (&f, L0, D0, V0, Omega0, D, opt, dtheta, dtau);
  if (D == D0)
    {
      double E = 0.0, H = 0.0;
      CHP_TRY (leg_invariants (L0 + D0, V0, Omega0, &E, &H));
      if (dtheta)
        *dtheta = 0.0;
      if (dtau)
        *dtau = 0.0;
      return CHAPLYGIN_SUCCESS;
    }
  chp_motion m;
  double g0, gl, th = 0.0, ta = 0.0;
  CHP_TRY (leg_motion (L0, D0, V0, Omega0, D, &m, &g0, &gl));
  if (o.method != CHAPLYGIN_ODE)
    CHP_TRY (chp_leg (&m, L0 + D0, g0, L0 + D, gl, fabs (D - D0), &o,
                      dtheta ? &th : NULL, dtau ? &ta : NULL));
  else
    {
      double q0[4] = { D0, V0, 0.0, Omega0 }, q1[4];
      int turned;
      double Dlo = D > D0 ? -HUGE_VAL : D, Dhi = D > D0 ? D : HUGE_VAL;
      CHP_TRY (
          chp_ode_until (L0, q0, 0, Dlo, Dhi, 1, o.tol, q1, &ta, &turned));
      if (turned && gl != 0.0)
        return CHAPLYGIN_ENOCONV;       /* turned back short of D: D is within
                                           the integration error of the
                                           turning point */
      th = q1[CHAPLYGIN_THETA];
    }
  if (!isfinite (th) || !isfinite (ta))
    return CHAPLYGIN_ERANGE;
  if (dtheta)
    *dtheta = th;
  if (dtau)
    *dtau = ta;
  return CHAPLYGIN_SUCCESS;
}
