/* discrete.c -- Section 3 up to the collision rule: the vector field (3.1),
   the invariants (3.3), (3.4), the collision rule (3.6), (3.7) and the
   spinning condition (3.8).

   l = L0 + D is the signed distance from the peg to the mass centre G:
   G = P + l e_lambda, with P the peg and e_lambda = (cos theta, sin theta)
   the slot axis (manual, "Conventions").  */
#include <config.h>

#include <math.h>

#include "chaplygin.h"
#include "collision.h"
#include "eft.h"
#include "far.h"
#include "motion.h"

/* chaplygin_discrete_field: (3.1)
       dD/dtau = V,  dV/dtau = (L0 + D) Omega^2,  dtheta/dtau = Omega,
       dOmega/dtau = -2 (L0 + D) V Omega / (1 + (L0 + D)^2).
   Derivation (verified by the test eq_3_1 against Newton-Euler equations of
   a rigid body with the pin-in-slot constraint): no force along the slot
   gives dv/dt = l omega^2; the angular momentum about the fixed peg,
   (I + m l^2) omega, is conserved, whence d omega/dt = -2 l v omega/
   (rho^2 + l^2).
   Method: 2l/(1 + l^2) as 2/(l + 1/l) for |l| > 1 (no overflow).
   Domain: finite L0 and q.  Errors: CHAPLYGIN_EINVAL (NULL),
   CHAPLYGIN_EDOM (non-finite input), CHAPLYGIN_ERANGE (overflow). */
int
chaplygin_discrete_field (double L0, const double q[4], double dq[4])
{
  if (!q || !dq)
    return CHAPLYGIN_EINVAL;
  return chp_field (L0, q, dq);
}

/* chaplygin_discrete_energy: (3.3)
       E = [V^2 + (1 + (L0 + D)^2) Omega^2]/2,
   the kinetic energy T/(m v0^2): (1/2) m |v_G|^2 + (1/2) I omega^2 with
   v_G = v e_lambda + l omega e_n.
   Accuracy: within 3 ulps (sum of two nonnegative terms).
   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM, CHAPLYGIN_ERANGE (overflow). */
int
chaplygin_discrete_energy (double L0, double D, double V, double Omega,
                           double *E)
{
  if (!E)
    return CHAPLYGIN_EINVAL;
  if (!chp_finite4 (L0, D, V, Omega))
    return CHAPLYGIN_EDOM;
  /* halved before squaring: E may be representable where V^2 is not;
     beyond 2^500, where 1 + l^2 overflows, (1 + l^2) Omega^2 is
     (l Omega)^2 (Omega^2 is below its rounding) */
  double l = L0 + D, r;
  if (fabs (l) <= CHP_L_MAX)
    r = (0.5 * V) * V + (0.5 * chp_one_plus_sq (l) * Omega) * Omega;
  else
    {
      double lw = l * Omega;
      r = fma (0.5 * lw, lw, (0.5 * V) * V);
    }
  if (!isfinite (r))
    return CHAPLYGIN_ERANGE;
  *E = r;
  return CHAPLYGIN_SUCCESS;
}

/* chaplygin_discrete_momentum: (3.4)
       H_P = [1 + (L0 + D)^2] Omega,
   the angular momentum about the peg (I + m l^2) omega over m rho v0.
   Accuracy: within 2 ulps.
   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM, CHAPLYGIN_ERANGE. */
int
chaplygin_discrete_momentum (double L0, double D, double Omega, double *H)
{
  if (!H)
    return CHAPLYGIN_EINVAL;
  if (!chp_finite2 (L0, D) || !isfinite (Omega))
    return CHAPLYGIN_EDOM;
  /* beyond 2^500 as l (l Omega): 1 + l^2 overflows, the 1 is below the
     rounding */
  double l = L0 + D;
  double r = fabs (l) <= CHP_L_MAX ? chp_one_plus_sq (l) * Omega
    : l * (l * Omega);
  if (!isfinite (r))
    return CHAPLYGIN_ERANGE;
  *H = r;
  return CHAPLYGIN_SUCCESS;
}

/* Check that a pre-collision peg position Dminus is the slot end that the
   sign of the velocity implies (sgn = +1: Delta, -1: 0). */
static int
check_end (double Delta, double Dminus, double sgn)
{
  if (sgn > 0.0 && Dminus == Delta)
    return CHAPLYGIN_SUCCESS;
  if (sgn < 0.0 && Dminus == 0.0)
    return CHAPLYGIN_SUCCESS;
  return CHAPLYGIN_ESTATE;
}

/* chaplygin_discrete_collide: (3.6)
       D+ = Delta - D-,  V+ = V-,  theta+ = theta-,
       Omega+ = [1 + L0 (L0 + Delta)] / [1 + (L0 + (Delta - D-))^2] Omega-,
   with D- = Delta for V- > 0 and D- = 0 for V- < 0.
   Derivation: the impulse at the new peg P' acts along e_n, so v (along the
   slot) is unchanged and the angular momentum about P' is conserved:
   (rho^2 + l+ l-) omega- = (rho^2 + l+^2) omega+, l-+ = L0 + D-+, and
   l+ l- = L0 (L0 + Delta) because {D-, D+} = {0, Delta}.
   Method: the ratio through chp_collision_ratio (accurate numerator).
   Domain: finite; Delta > 0; qminus[D] exactly Delta (V- > 0) or 0 (V- < 0).
   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM (non-finite, Delta <= 0),
   CHAPLYGIN_ESTATE (peg not at the end V- implies, or V- = 0). */
int
chaplygin_discrete_collide (double L0, double Delta, const double qminus[4],
                            double qplus[4])
{
  if (!qminus || !qplus)
    return CHAPLYGIN_EINVAL;
  if (!chp_finite2 (L0, Delta) || !(Delta > 0.0)
      || !chp_finite4 (qminus[0], qminus[1], qminus[2], qminus[3]))
    return CHAPLYGIN_EDOM;
  double V = qminus[CHAPLYGIN_V];
  if (V == 0.0)
    return CHAPLYGIN_ESTATE;
  CHP_TRY (check_end (Delta, qminus[CHAPLYGIN_D], V));
  double Dplus = Delta - qminus[CHAPLYGIN_D];   /* exactly 0 or Delta */
  double r = chp_collision_ratio (L0, Delta, L0 + Dplus,
                                  L0 + qminus[CHAPLYGIN_D]);
  double th = qminus[CHAPLYGIN_THETA];
  double om = r * qminus[CHAPLYGIN_OMEGA];
  if (!isfinite (om))
    return CHAPLYGIN_ERANGE;
  qplus[CHAPLYGIN_D] = Dplus;
  qplus[CHAPLYGIN_V] = V;
  qplus[CHAPLYGIN_THETA] = th;
  qplus[CHAPLYGIN_OMEGA] = om;
  return CHAPLYGIN_SUCCESS;
}

/* chaplygin_discrete_collide_eh: (3.7)
       D+ = Delta - D-,
       E+ = E- - Delta^2 H-^2 / (2 [1 + (L0 + D-)^2]^2 [1 + (L0 + Delta - D-)^2]),
       theta+ = theta-,
       H+ = [1 + L0 (L0 + Delta)] / [1 + (L0 + D-)^2] H-.
   Derivation: (3.6) with Omega = H/(1 + l^2) and E from (3.3):
   E+ - E- = Omega-^2 [(1 + l+ l-)^2/(1 + l+^2) - (1 + l-^2)]/2
           = -Omega-^2 (l+ - l-)^2 / (2 (1 + l+^2)), (l+ - l-)^2 = Delta^2.
   (The transcription misplaces a parenthesis in the last factor of the
   denominator; see the errata.)
   Method: E+ is formed as the energy of the state after the collision,
   V-^2/2 + H+^2/(2 (1 + l+^2)), with V-^2 = 2E- g/(1 + l-^2) and
   g = [2E- (1 + l-^2) - H-^2]/(2E-) by error-free arithmetic: equal to
   E- + C1 H-^2 of (3.7) but a sum of nonnegative terms, so that E+ keeps
   its relative accuracy when the collision removes nearly all the energy
   (E- + C1 H-^2 would lose log10(E-/E+) digits).
   Domain: finite; Delta > 0; pminus[D] exactly 0 or Delta; E- >= 0 with
   V-^2 = 2E- - H-^2/(1 + (L0 + D-)^2) > 0; |L0|, |L0 + Delta| <= 2^500.
   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM, CHAPLYGIN_ESTATE (D- not an
   end, or V-^2 <= 0, or E- = 0), CHAPLYGIN_ERANGE. */
int
chaplygin_discrete_collide_eh (double L0, double Delta,
                               const double pminus[4], double pplus[4])
{
  if (!pminus || !pplus)
    return CHAPLYGIN_EINVAL;
  if (!chp_finite2 (L0, Delta) || !(Delta > 0.0)
      || !chp_finite4 (pminus[0], pminus[1], pminus[2], pminus[3]))
    return CHAPLYGIN_EDOM;
  double Dm = pminus[CHAPLYGIN_D], E = pminus[CHAPLYGIN_E];
  double H = pminus[CHAPLYGIN_H];
  if (Dm != 0.0 && Dm != Delta)
    return CHAPLYGIN_ESTATE;
  double b, eb, bp = L0 + (Delta - Dm);
  chp_two_sum (L0, Dm, &b, &eb);        /* b + eb = L0 + D- exactly */
  double Ep, Hp;
  if (fabs (b) > CHP_L_MAX || fabs (bp) > CHP_L_MAX)
    {
      /* far (lib/far.c): the collision of the exactly scaled system */
      chp_far f;
      double ps[4], qs[4];
      CHP_TRY (chp_far_open (L0, Delta, &f));
      ps[CHAPLYGIN_D] = Dm == 0.0 ? 0.0 : f.sys.Delta;
      ps[CHAPLYGIN_THETA] = pminus[CHAPLYGIN_THETA];
      CHP_TRY (chp_far_state (&f, E, H, 1, &ps[CHAPLYGIN_E],
                              &ps[CHAPLYGIN_H]));
      CHP_TRY (chaplygin_discrete_collide_eh (f.sys.L0, f.sys.Delta, ps, qs));
      Ep = chp_far_out (&f, CHP_Q_ENERGY, qs[CHAPLYGIN_E]);
      Hp = chp_far_out (&f, CHP_Q_MOMENTUM, qs[CHAPLYGIN_H]);
    }
  else
    {
      /* g = (1 + b^2) V-^2/(2E), error-free (b's own rounding included) */
      chp_motion m;
      CHP_TRY (chp_motion_init (E, H, &m));
      double g = chp_motion_g_exact (&m, b, eb);
      if (!(g > 0.0))
        return CHAPLYGIN_ESTATE;
      double C1, C2;
      chp_collision_coefficients (L0, Delta, Dm, &C1, &C2);
      Hp = C2 * H;
      Ep = chp_post_collision_energy (E, g, b, Hp, bp);
    }
  if (!isfinite (Ep) || !isfinite (Hp))
    return CHAPLYGIN_ERANGE;
  pplus[CHAPLYGIN_D] = Delta - Dm;
  pplus[CHAPLYGIN_E] = Ep;
  pplus[CHAPLYGIN_THETA] = pminus[CHAPLYGIN_THETA];
  pplus[CHAPLYGIN_H] = Hp;
  return CHAPLYGIN_SUCCESS;
}

/* chaplygin_discrete_spin_ratio: (3.8) the energy/momentum ratio 2E/H^2.
   Spinning about the peg with the peg at the mass centre (D = -L0, V = 0)
   has E = Omega^2/2 and H = Omega, so 2E/H^2 = 1.
   Domain: E >= 0, H finite.  Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM,
   CHAPLYGIN_ERANGE (H = 0 or overflow: the ratio is infinite). */
int
chaplygin_discrete_spin_ratio (double E, double H, double *ratio)
{
  if (!ratio)
    return CHAPLYGIN_EINVAL;
  if (!chp_finite2 (E, H) || !(E >= 0.0))
    return CHAPLYGIN_EDOM;
  double r = (2.0 * E / H) / H;
  if (!isfinite (r))
    return CHAPLYGIN_ERANGE;
  *ratio = r;
  return CHAPLYGIN_SUCCESS;
}

/* chaplygin_discrete_spins: whether the motion that starts just after a
   collision in direction dir ends in the spinning equilibrium of (3.8):
   2E = H^2 exactly (chp_one_minus_h2, exact) and the path from the
   starting end reaches l = 0, i.e. D = -L0 lies in [0, Delta] on the far
   side of the start: dir = +1 needs L0 < 0 <= L0 + Delta (the peg at the
   front, D = 0, moving back towards -L0), dir = -1 needs L0 <= 0 < L0 + Delta.
   (The comparison -L0 <= Delta is made without rounding L0 + Delta.)
   Domain: finite; Delta > 0; dir = +-1; E > 0.
   Errors: CHAPLYGIN_EINVAL (NULL, dir), CHAPLYGIN_EDOM. */
int
chaplygin_discrete_spins (double L0, double Delta, int dir, double E,
                          double H, int *spins)
{
  if (!spins || (dir != 1 && dir != -1))
    return CHAPLYGIN_EINVAL;
  if (!chp_finite4 (L0, Delta, E, H) || !(Delta > 0.0) || !(E > 0.0))
    return CHAPLYGIN_EDOM;
  int ratio_one = chp_one_minus_h2 (E, H) == 0.0;
  int reaches = dir > 0 ? (L0 < 0.0 && -L0 <= Delta)
    : (L0 <= 0.0 && -L0 < Delta);
  *spins = ratio_one && reaches;
  return CHAPLYGIN_SUCCESS;
}
