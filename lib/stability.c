/* stability.c -- Sections 3.1.1, 3.1.2 and 4.1: period-1 fixed points and
   their stability, (3.9)-(3.12), (4.1), (B.14); the spinning equilibrium
   and its linearisation.

   Notation: x = L0/Delta, y = 1/Delta^2 (the axes of the paper's Fig. 2);
   h = H/sqrt(2E); for a segment of the motion between collisions
   l = L0 + D runs over [lo, hi] (the slot, lo = L0, hi = L0 + Delta),
   a = 1 + l^2, g = a - h^2 = a V^2/(2E).  */
#include <config.h>

#include <float.h>
#include <math.h>
#include <stddef.h>

#include "chaplygin.h"
#include "collision.h"
#include "eft.h"
#include "far.h"
#include "motion.h"
#include "quad.h"

static int
check_dir (int dir)
{
  return dir == 1 || dir == -1;
}

/* The sign of 2 + (L0 + Delta)(2 L0 + Delta) (dir = +1) or
   2 + L0 (2 L0 + Delta) (dir = -1), the (3.11)/(3.12) polynomials times
   Delta^2, from error-free products: exact unless the value is below
   ~1e-30 of its terms. */
static double
criterion_value (double L0, double Delta, int dir)
{
  double a, ea, p, ep;
  if (dir > 0)
    chp_two_sum (L0, Delta, &a, &ea);
  else
    {
      a = L0;
      ea = 0.0;
    }
  double b, eb;
  chp_two_sum (2.0 * L0, Delta, &b, &eb);
  chp_two_prod (a, b, &p, &ep);
  double s, es;
  chp_two_sum (2.0, p, &s, &es);
  return s + (es + (ep + (a * eb + ea * b)));
}

/* chaplygin_discrete_sigma4: (3.10) the eigenvalues of the Jacobian (3.9)
   at a period-1 fixed point,
       sigma1 = 0,  sigma2 = sigma3 = 1,
       sigma4 = [1 + L0 (L0 + Delta)]/[1 + (L0 + Delta)^2]  (V* > 0),
       sigma4 = [1 + L0 (L0 + Delta)]/[1 + L0^2]            (V* < 0),
   dir = sign of V*.  sigma4 is the coefficient C2 of (B.3) for the
   direction of travel (the collision at the far end).  sigma may be NULL;
   all four are written to it in the order above.
   Method: chp_collision_ratio (numerator by an error-free sum).
   Accuracy: within 4 ulps of sigma4 (tests: 40-digit references).
   Domain: finite L0, 0 < Delta finite, dir = +-1.
   Errors: CHAPLYGIN_EINVAL (dir, NULL sigma4), CHAPLYGIN_EDOM,
   CHAPLYGIN_ERANGE (|L0|, |L0 + Delta| > 2^500). */
int
chaplygin_discrete_sigma4 (double L0, double Delta, int dir, double *sigma4,
                           double sigma[4])
{
  if (!sigma4 || !check_dir (dir))
    return CHAPLYGIN_EINVAL;
  if (!chp_finite2 (L0, Delta) || !(Delta > 0.0))
    return CHAPLYGIN_EDOM;
  double l1 = L0 + Delta;
  chp_far f;
  CHP_TRY (chp_far_open (L0, Delta, &f));
  if (f.k)      /* far (lib/far.c): sigma4 = C2 is scale-free */
    return chaplygin_discrete_sigma4 (f.sys.L0, f.sys.Delta, dir, sigma4,
                                      sigma);
  /* the collision ends the segment at the far end: b is l there */
  double s = dir > 0 ? chp_collision_ratio (L0, Delta, l1, L0)
    : chp_collision_ratio (L0, Delta, L0, l1);
  if (!isfinite (s))
    return CHAPLYGIN_ERANGE;
  *sigma4 = s;
  if (sigma)
    {
      sigma[0] = 0.0;
      sigma[1] = 1.0;
      sigma[2] = 1.0;
      sigma[3] = s;
    }
  return CHAPLYGIN_SUCCESS;
}

/* chaplygin_discrete_stable: (3.11) and (3.12), the stability criteria of
   the straight-line motions, read as
     (3.11) V* > 0:  L0/Delta > -1  and
                     (1/Delta)^2 > -(1/2)(1 + 2 L0/Delta)(1 + L0/Delta),
     (3.12) V* < 0:  L0/Delta < 0   and
                     (1/Delta)^2 > -(1/2)(L0/Delta)(1 + 2 L0/Delta),
   where the printed "> 0" closing each chain only says when the bound is
   active, not a third condition (errata E12: read literally, the chain
   would call every L0/Delta > -1/2 unstable, against (3.10)).  They are
   |sigma4| < 1: sigma4 < 1 iff the first, sigma4 > -1 iff the second.
   *stable = 1 (asymptotically stable in the paper's weak sense) or 0
   (|sigma4| >= 1: unstable, or neutral on the boundary).
   Method: the conditions times Delta^2, L0 + Delta > 0 and
   2 + (L0 + Delta)(2 L0 + Delta) > 0 (dir +1), L0 < 0 and
   2 + L0 (2 L0 + Delta) > 0 (dir -1), the comparisons exact and the
   polynomials by error-free transformations, so points on either side of
   the boundary are classified correctly down to ~1e-30 relative.
   Domain: finite L0, 0 < Delta finite.
   Errors: CHAPLYGIN_EINVAL (NULL, dir), CHAPLYGIN_EDOM,
   CHAPLYGIN_ERANGE (|L0| or |L0 + Delta| above 2^500, as for sigma4). */
int
chaplygin_discrete_stable (double L0, double Delta, int dir, int *stable)
{
  if (!stable || !check_dir (dir))
    return CHAPLYGIN_EINVAL;
  if (!chp_finite2 (L0, Delta) || !(Delta > 0.0))
    return CHAPLYGIN_EDOM;
  chp_far f;
  CHP_TRY (chp_far_open (L0, Delta, &f));
  if (f.k)      /* far (lib/far.c): scale-free */
    return chaplygin_discrete_stable (f.sys.L0, f.sys.Delta, dir, stable);
  int first = dir > 0 ? L0 > -Delta : L0 < 0.0;
  *stable = first && criterion_value (L0, Delta, dir) > 0.0;
  return CHAPLYGIN_SUCCESS;
}

/* chaplygin_discrete_stability_boundary: the boundary of the stable region
   of (3.11) (dir +1) or (3.12) (dir -1) in the plane of Fig. 2(b),
   x = L0/Delta, y = (1/Delta)^2 >= 0: the motion is stable iff
   *stabilizable and y > *ymin, with
     dir +1:  stabilizable iff x > -1,  ymin = max(0, -(1 + 2x)(1 + x)/2),
     dir -1:  stabilizable iff x < 0,   ymin = max(0, -x (1 + 2x)/2).
   The curved parts run over -1 < x < -1/2 (dir +1) and -1/2 < x < 0
   (dir -1), peaking at y = 1/16 (x = -3/4, x = -1/4); elsewhere every
   y > 0 is stable.  *ymin is written only if *stabilizable.
   Errors: CHAPLYGIN_EINVAL (NULL, dir), CHAPLYGIN_EDOM (x not finite). */
int
chaplygin_discrete_stability_boundary (int dir, double x, int *stabilizable,
                                       double *ymin)
{
  if (!stabilizable || !ymin || !check_dir (dir))
    return CHAPLYGIN_EINVAL;
  if (!isfinite (x))
    return CHAPLYGIN_EDOM;
  int ok = dir > 0 ? x > -1.0 : x < 0.0;
  *stabilizable = ok;
  if (ok)
    {
      double b = dir > 0 ? -0.5 * (1.0 + 2.0 * x) * (1.0 + x)
        : -0.5 * x * (1.0 + 2.0 * x);
      *ymin = b > 0.0 ? b : 0.0;
    }
  return CHAPLYGIN_SUCCESS;
}

/* Phi'(h) = Int_lo^hi sqrt(a) g^(-3/2) dl, the derivative of the heading
   increment Phi(h) = h Int dl/sqrt(a g) of a segment without a turning
   point: the integrand, for the quadrature fallback. */
struct dphi_params
{
  double L0, h2;
};

static double
dphi_integrand (double t, void *p)
{
  /* t = D, the offset from the slot front: l = L0 + t without the
     rounding of L0 + Delta in the limits */
  const struct dphi_params *q = p;
  double a = chp_one_plus_sq (q->L0 + t);
  double g = a - q->h2;
  return sqrt (a) / (g * sqrt (g));
}

/* chaplygin_discrete_jacobian: (3.9) the Jacobian of the return map (B.3)
   in the coordinates p = {D+, E, theta, H} (row-major J[4 i + j] =
   d p'_i / d p_j), at a post-collision state whose segment has no
   velocity reversal:
         ( 0  0           0  0            )
     J = ( 0  1           0  2 C1 H       )
         ( 0  df3/dE      1  df3/dH       )
         ( 0  0           0  C2           )
   with C1, C2 of (B.3) for the direction of travel.  f3 depends on E and H
   only through h = H/sqrt(2E): f3 = Phi(h), so
     df3/dH = Phi'(h)/sqrt(2E),  df3/dE = -h Phi'(h)/(2E),
     Phi'(h) = Int_lo^hi sqrt(1 + l^2) (1 + l^2 - h^2)^(-3/2) dl.
   At a period-1 fixed point (H = 0) this is the paper's (3.9):
   df3/dE = 0 and df3/dH = [atan(L0 + Delta) - atan(L0)]/sqrt(2E*), which
   the paper leaves unevaluated.
   Method: Phi'(h) from the closed-form heading and time of the same
   segment (chaplygin_discrete_step), by the identity (derived in the
   manual, Methods, "Jacobian of the return map")
     (1 - h^2) Phi'(h) = [l sqrt(a/g)]_lo^hi + Theta - T,
     Theta = Int dl/sqrt(a g) = |dtheta|/|h|,  T = Int sqrt(a/g) dl
           = sqrt(2E) dtau;
   when the right side cancels by more than a factor 8 (|l| large beside
   the slot, a short or a long slot, h^2 near 1 away from l = 0) Phi' is
   integrated directly over D in [0, Delta] instead
   (chp_integrate, relative tolerance 64 eps; the integrand is smooth on a
   segment without a turning point).  At H = 0, and for |h| < 2^-500
   where Phi'(h) - Phi'(0) = O(h^2) is below an ulp,
   Phi'(0) = atan2(Delta, 1 + L0 (L0 + Delta)).
   Accuracy: df3/dE, df3/dH within 7 eps of mpmath references on 12
   states (16 eps asserted); Richardson-extrapolated central differences
   of the map agree to ~1e-10 on 300 random states.
   Domain: as chaplygin_discrete_step; the segment from st must not
   reverse (a period-1 orbit never does).
   Errors: those of chaplygin_discrete_step; CHAPLYGIN_ESTATE if the
   segment reverses; CHAPLYGIN_ENOCONV if the fallback quadrature fails. */
int
chaplygin_discrete_jacobian (const chaplygin_discrete *sys,
                             const chaplygin_discrete_state *st, double J[16])
{
  if (!sys || !st || !J)
    return CHAPLYGIN_EINVAL;
  chp_far f;
  CHP_TRY (chp_far_open_sys (sys, &f));
  if (f.k)
    {
      /* far (lib/far.c): the Jacobian of the scaled map in the scaled
         coordinates, scaled back (the entries not listed are
         scale-free) */
      chaplygin_discrete_state si;
      double Js[16];
      if (st->dir != 1 && st->dir != -1)
        return CHAPLYGIN_EINVAL;
      if (!chp_finite2 (st->E, st->H) || st->E < 0.0)
        return CHAPLYGIN_EDOM;
      CHP_TRY (chp_far_state_of (&f, st, 1, &si));
      CHP_TRY (chaplygin_discrete_jacobian (&f.sys, &si, Js));
      Js[7] = chp_far_out (&f, CHP_Q_DENERGY_DMOMENTUM, Js[7]);
      Js[9] = chp_far_out (&f, CHP_Q_DHEADING_DENERGY, Js[9]);
      Js[11] = chp_far_out (&f, CHP_Q_DHEADING_DMOMENTUM, Js[11]);
      for (int i = 0; i < 16; i++)
        if (!isfinite (Js[i]))
          return CHAPLYGIN_ERANGE;
      for (int i = 0; i < 16; i++)
        J[i] = Js[i];
      return CHAPLYGIN_SUCCESS;
    }
  chaplygin_discrete_state next;
  chaplygin_discrete_event ev;
  CHP_TRY (chaplygin_discrete_step (sys, st,
                                    CHAPLYGIN_WANT_THETA | CHAPLYGIN_WANT_TAU,
                                    NULL, &next, &ev));
  if (ev.reversal)
    return CHAPLYGIN_ESTATE;
  const int far = st->dir > 0 ? 1 : 0;   /* the end the peg leaves */
  const double C1 = sys->C1[far], C2 = sys->C2[far];
  const double E = st->E, H = st->H, s2E = sqrt (2.0 * E);
  double dphi;
  /* Phi'(h) = Phi'(0) + O(h^2): at |h| < 2^-500 the H = 0 value is exact
     in double (and Theta = |dtheta|/|h| would divide subnormals) */
  if (fabs (H) < 0x1p-500 * sqrt (2.0 * E))
    dphi = atan2 (sys->Delta, chp_one_plus_L0_L0D (sys->L0, sys->Delta));
  else
    {
      chp_motion m;
      CHP_TRY (chp_motion_init (E, H, &m));
      const double h = m.h, one_minus_h2 = m.one_minus_h2;
      const double lo = sys->l_end[0], hi = sys->l_end[1];
      const double glo = chp_motion_g_exact (&m, lo, sys->l_err[0]);
      const double ghi = chp_motion_g_exact (&m, hi, sys->l_err[1]);
      const double Blo = lo * sqrt (chp_one_plus_sq (lo) / glo);
      /* the rounding of hi = L0 + Delta shifts B by ~ulp(hi): below eps
         of the result whenever the identity is used (it is not for
         short slots, where the terms cancel) */
      const double Bhi = hi * sqrt (chp_one_plus_sq (hi) / ghi);
      const double Theta = fabs (ev.dtheta) / fabs (h);
      const double T = s2E * ev.dtau;
      const double num = ((Bhi - Blo) + Theta) - T;
      const double size = fabs (Bhi) + fabs (Blo) + Theta + T;
      if (one_minus_h2 != 0.0 && isfinite (num) && fabs (num) * 8.0 >= size)
        dphi = num / one_minus_h2;
      else
        {
          struct dphi_params p = { sys->L0, h * h };
          CHP_TRY (chp_integrate (dphi_integrand, &p, 0.0, sys->Delta,
                                  64.0 * 0x1p-52, &dphi));
        }
    }
  const double dHdH = C2, dEdH = 2.0 * C1 * H;
  const double df3dH = dphi / s2E;
  const double df3dE = -(H / s2E) * dphi / (2.0 * E);
  const double r[16] = { 0.0, 0.0, 0.0, 0.0,
                         0.0, 1.0, 0.0, dEdH,
                         0.0, df3dE, 1.0, df3dH,
                         0.0, 0.0, 0.0, dHdH };
  for (int i = 0; i < 16; i++)
    if (!isfinite (r[i]))
      return CHAPLYGIN_ERANGE;
  for (int i = 0; i < 16; i++)
    J[i] = r[i];
  return CHAPLYGIN_SUCCESS;
}

/* chaplygin_discrete_fixed_point: (B.14) with H* = 0, the period-1 fixed
   points: the straight-line motion with speed |V*| along the slot,
   E* = V*^2/2, H* = 0, heading theta*, the peg at peg (may be NULL: the
   origin) and time tau; *tau_star (may be NULL) = Delta/|V*|, the time
   between collisions.  Periodic motions need lossless collisions,
   C1 H*^2 = 0 (B.14); for I != 0 and Delta > 0, C1 < 0 and only H* = 0
   remains (see chaplygin_discrete_collision_loss).
   Errors: CHAPLYGIN_EINVAL (NULL sys or st), CHAPLYGIN_EDOM (non-finite),
   CHAPLYGIN_ESTATE (V* = 0), CHAPLYGIN_ERANGE (V*^2/2 overflows or is
   below the normal range, |V*| < ~1.5e-154, or Delta/|V*| overflows). */
int
chaplygin_discrete_fixed_point (const chaplygin_discrete *sys, double Vstar,
                                double theta, double tau, const double peg[2],
                                chaplygin_discrete_state *st,
                                double *tau_star)
{
  if (!sys || !st)
    return CHAPLYGIN_EINVAL;
  if (!chp_finite4 (Vstar, theta, tau, sys->Delta) || !isfinite (sys->L0)
      || !(sys->Delta > 0.0) || (peg && !chp_finite2 (peg[0], peg[1])))
    return CHAPLYGIN_EDOM;
  if (Vstar == 0.0)
    return CHAPLYGIN_ESTATE;
  double E = (0.5 * Vstar) * Vstar, ts = sys->Delta / fabs (Vstar);
  /* E must be a normal number: a subnormal or zero E is a state the map
     rejects or resolves only to a few digits */
  if (!isfinite (E) || !(E >= DBL_MIN) || !isfinite (ts))
    return CHAPLYGIN_ERANGE;
  chaplygin_discrete_state s;
  s.dir = Vstar > 0.0 ? 1 : -1;
  s.E = E;
  s.H = 0.0;
  s.theta = theta;
  s.tau = tau;
  s.peg[0] = peg ? peg[0] : 0.0;
  s.peg[1] = peg ? peg[1] : 0.0;
  s.V = Vstar;
  *st = s;
  if (tau_star)
    *tau_star = ts;
  return CHAPLYGIN_SUCCESS;
}

/* chaplygin_discrete_collision_loss: (B.14) the energy a collision takes,
   -C1 H^2 >= 0, for a post-collision state with direction dir whose
   segment does (reversal = 1) or does not (0) reverse; C1 of (B.3)/(B.4).
   It vanishes iff H = 0 (Delta > 0, rho > 0): the period-1 condition (in
   floating point it also underflows to 0 for very small |H|).
   Errors: CHAPLYGIN_EINVAL (NULL, dir, reversal), CHAPLYGIN_EDOM,
   CHAPLYGIN_ERANGE (overflow). */
int
chaplygin_discrete_collision_loss (const chaplygin_discrete *sys, int dir,
                                   int reversal, double H, double *loss)
{
  if (!sys || !loss || !check_dir (dir) || (reversal != 0 && reversal != 1))
    return CHAPLYGIN_EINVAL;
  if (!chp_finite2 (sys->L0, sys->Delta) || !(sys->Delta > 0.0)
      || !isfinite (H))
    return CHAPLYGIN_EDOM;
  int start = dir > 0 ? 0 : 1;
  int leave = reversal ? start : 1 - start;
  double r = -sys->C1[leave] * H * H;
  if (!isfinite (r))
    return CHAPLYGIN_ERANGE;
  *loss = r;
  return CHAPLYGIN_SUCCESS;
}

/* chaplygin_discrete_xi4: (4.1) the discrete stability exponent per unit
   time, xi4 = log(sigma4)/tau* with tau* = Delta/|V*|:
       xi4 = (|V*|/Delta) log sigma4,
   sigma4 of (3.10) for the direction sign(V*) (the paper writes V* for
   V* > 0).  As Delta -> 0 it tends to the smooth sleigh's -L0 V* / (1 + L0^2)
   (chaplygin_smooth_eigenvalue) for either sign of V*.
   Method: without cancellation for small Delta:
       sigma4 - 1 = -Delta b/(1 + b^2),  b = L0 + Delta   (V* > 0),
       sigma4 - 1 =  Delta L0/(1 + L0^2)                 (V* < 0),
   b/(1 + b^2) formed without overflow, then log1p; below 2^-500,
   xi4 = -|V*| b/(1 + b^2) (resp. |V*| L0/(1 + L0^2)) directly; for
   sigma4 < 1/2, log of sigma4 itself (formed as in
   chaplygin_discrete_sigma4), since sigma4 - 1 has then cancelled.
   Unlike sigma4, no range test: for |L0|, |L0 + Delta| beyond 2^500 the
   ratios are formed scaled, and xi4 is returned wherever it is finite.
   Accuracy: within ~4 ulps (tests: series and 40-digit references),
   down to Delta = 1e-300.
   Errors: CHAPLYGIN_EINVAL (NULL), CHAPLYGIN_EDOM (non-finite,
   Delta <= 0, sigma4 <= 0: the logarithm is not real),
   CHAPLYGIN_ESTATE (V* = 0), CHAPLYGIN_ERANGE (overflow). */
int
chaplygin_discrete_xi4 (double L0, double Delta, double Vstar, double *xi4)
{
  if (!xi4)
    return CHAPLYGIN_EINVAL;
  if (!chp_finite4 (L0, Delta, Vstar, 0.0) || !(Delta > 0.0))
    return CHAPLYGIN_EDOM;
  if (Vstar == 0.0)
    return CHAPLYGIN_ESTATE;
  const int dir = Vstar > 0.0 ? 1 : -1;
  /* u = sigma4 - 1 = -Delta b/(1 + b^2), b = L0 + Delta (V* > 0), or
     Delta L0/(1 + L0^2) (V* < 0); b rounded once, within half an ulp */
  const double f = dir > 0 ? chp_L_over_one_plus_sq (L0 + Delta)
    : -chp_L_over_one_plus_sq (L0);
  const double u = -Delta * f;
  double q;                     /* log(sigma4)/Delta */
  if (fabs (u) < 0x1p-500)
    /* log1p(u)/Delta = -f (1 - u/2 + ...): exact to below an ulp, and
       u itself may be subnormal */
    q = -f;
  else if (u < -0.5)
    {
      /* sigma4 near 0: u has cancelled; log of sigma4 itself, whose
         numerator 1 + L0 (L0 + Delta) is formed without cancellation (as
         chaplygin_discrete_sigma4, without its 2^500 range test: beyond
         it chp_collision_ratio scales, and the result is representable) */
      const double l1 = L0 + Delta;
      const double s4 = dir > 0 ? chp_collision_ratio (L0, Delta, l1, L0)
        : chp_collision_ratio (L0, Delta, L0, l1);
      if (!(s4 > 0.0))
        return CHAPLYGIN_EDOM;
      q = log (s4) / Delta;
    }
  else
    q = log1p (u) / Delta;
  double r = fabs (Vstar) * q;
  if (!isfinite (r))
    return CHAPLYGIN_ERANGE;
  *xi4 = r;
  return CHAPLYGIN_SUCCESS;
}

/* chaplygin_discrete_xi4_taylor: (4.1) the coefficients of
       xi4 = V* [c0 + c1 Delta + c2 Delta^2 + O(Delta^3)],  a = 1 + L0^2,
   V* > 0 (dir +1):  c0 = -L0/a,  c1 = (L0^2 - 2)/(2 a^2),
                     c2 = L0 (6 - L0^2)/(3 a^3);
   V* < 0 (dir -1):  c0 = -L0/a,  c1 = L0^2/(2 a^2),  c2 = -L0^3/(3 a^3).
   The paper's c0 and c1 are right; its c2 = -L0 (L0^2 - 2)/(3 a^3) is
   wrong (errata E13).  Derivation: log sigma4 = log1p(u), u = -Delta
   f(L0 + Delta), f(b) = b/(1 + b^2), expanded to third order in Delta.
   Errors: CHAPLYGIN_EINVAL (NULL, dir), CHAPLYGIN_EDOM (L0 non-finite),
   CHAPLYGIN_ERANGE (|L0| > 2^500). */
int
chaplygin_discrete_xi4_taylor (double L0, int dir, double c[3])
{
  if (!c || !check_dir (dir))
    return CHAPLYGIN_EINVAL;
  if (!isfinite (L0))
    return CHAPLYGIN_EDOM;
  /* with f = L0/a and 1/a = f/L0 (no overflow for large L0):
     dir +1:  c1 = (1 - 3/a)/(2a),     c2 = f (7/a - 1)/(3a);
     dir -1:  c1 = f^2/2,              c2 = -f^3/3.
     1 - 3/a = (L0^2 - 2)/a and 7/a - 1 = (6 - L0^2)/a vanish at L0^2 = 2
     and 6: formed from L0^2 - 2 and 6 - L0^2 by one fma each, c1 and c2
     keep their relative accuracy there (the differences cancelled: 67 ulps
     in c2 at L0 = 2.449..., tests/test_cert_algebraic.c); beyond 2^500,
     where L0^2 would overflow, 3/a and 7/a are negligible. */
  double f = chp_L_over_one_plus_sq (L0);
  double inva = L0 != 0.0 ? f / L0 : 1.0;
  double r0 = -f, r1, r2;
  if (dir > 0 && fabs (L0) <= 0x1p500)
    {
      r1 = 0.5 * inva * (fma (L0, L0, -2.0) * inva);
      r2 = f * inva * (fma (-L0, L0, 6.0) * inva) / 3.0;
    }
  else if (dir > 0)
    {
      r1 = 0.5 * inva * (1.0 - 3.0 * inva);
      r2 = f * inva * (7.0 * inva - 1.0) / 3.0;
    }
  else
    {
      r1 = 0.5 * f * f;
      r2 = -f * f * f / 3.0;
    }
  c[0] = r0;
  c[1] = r1;
  c[2] = r2;
  return CHAPLYGIN_SUCCESS;
}

/* chaplygin_discrete_field_jacobian: the linearisation of (3.1),
   A[4 i + j] = d(dq_i/dtau)/dq_j at q = {D, V, theta, Omega}, l = L0 + D:
     ( 0                          1                 0  0              )
     ( Omega^2                    0                 0  2 l Omega      )
     ( 0                          0                 0  1              )
     ( -2 V Omega (1-l^2)/(1+l^2)^2  -2 l Omega/(1+l^2)  0  -2 l V/(1+l^2) )
   Errors: CHAPLYGIN_EINVAL (NULL), CHAPLYGIN_EDOM, CHAPLYGIN_ERANGE. */
int
chaplygin_discrete_field_jacobian (double L0, const double q[4],
                                   double A[16])
{
  if (!q || !A)
    return CHAPLYGIN_EINVAL;
  if (!chp_finite4 (q[0], q[1], q[2], q[3]) || !isfinite (L0))
    return CHAPLYGIN_EDOM;
  double l = L0 + q[CHAPLYGIN_D], V = q[CHAPLYGIN_V], Om = q[CHAPLYGIN_OMEGA];
  double f = chp_L_over_one_plus_sq (l);     /* l/(1 + l^2) */
  double n = chp_one_plus_sq (l);
  /* (1 - l^2)/(1 + l^2)^2 = (2/(1 + l^2) - 1)/(1 + l^2) */
  double df = isfinite (n) ? (2.0 / n - 1.0) / n : 0.0;
  const double r[16] = { 0.0, 1.0, 0.0, 0.0,
                         Om * Om, 0.0, 0.0, 2.0 * l * Om,
                         0.0, 0.0, 0.0, 1.0,
                         -2.0 * V * Om * df, -2.0 * f * Om, 0.0, -2.0 * f * V };
  for (int i = 0; i < 16; i++)
    if (!isfinite (r[i]))
      return CHAPLYGIN_ERANGE;
  for (int i = 0; i < 16; i++)
    A[i] = r[i];
  return CHAPLYGIN_SUCCESS;
}

/* chaplygin_discrete_spin_equilibrium: the spinning solution of Section
   3.1.1, q_eq(tau) = {-L0, 0, theta0 + Omega tau, Omega}: the mass centre
   on the peg, which exists iff it lies within the slot, -Delta < L0 < 0
   (D_eq = -L0 in (0, Delta)).  Its energy and momentum satisfy (3.8),
   2E/H^2 = 1.  Errors: CHAPLYGIN_EINVAL (NULL), CHAPLYGIN_EDOM
   (non-finite, Delta <= 0, L0 outside (-Delta, 0)), CHAPLYGIN_ESTATE
   (Omega = 0: the skate at rest, as for V* = 0 elsewhere),
   CHAPLYGIN_ERANGE. */
int
chaplygin_discrete_spin_equilibrium (double L0, double Delta, double Omega,
                                     double theta0, double tau, double q[4])
{
  if (!q)
    return CHAPLYGIN_EINVAL;
  if (!chp_finite4 (L0, Delta, Omega, theta0) || !isfinite (tau)
      || !(Delta > 0.0) || !(L0 < 0.0 && L0 > -Delta))
    return CHAPLYGIN_EDOM;
  if (Omega == 0.0)
    return CHAPLYGIN_ESTATE;
  double th = fma (Omega, tau, theta0);
  if (!isfinite (th))
    return CHAPLYGIN_ERANGE;
  q[CHAPLYGIN_D] = -L0;
  q[CHAPLYGIN_V] = 0.0;
  q[CHAPLYGIN_THETA] = th;
  q[CHAPLYGIN_OMEGA] = Omega;
  return CHAPLYGIN_SUCCESS;
}

/* chaplygin_discrete_spin_eigenvalues: the eigenvalues of (3.1)
   linearised about the spinning solution (chaplygin_discrete_field_jacobian
   at l = 0, V = 0): the (D, V) block [[0, 1], [Omega^2, 0]] gives
   +-|Omega|, the (theta, Omega) block a double 0 (a Jordan block: the
   heading drifts linearly under a change of Omega).  Written in ascending
   order: lambda = {-|Omega|, 0, 0, |Omega|}: a saddle, always unstable.
   Errors: as chaplygin_discrete_spin_equilibrium. */
int
chaplygin_discrete_spin_eigenvalues (double L0, double Delta, double Omega,
                                     double lambda[4])
{
  double q[4];
  if (!lambda)
    return CHAPLYGIN_EINVAL;
  CHP_TRY (chaplygin_discrete_spin_equilibrium (L0, Delta, Omega, 0.0, 0.0,
                                                q));
  double w = fabs (Omega);
  lambda[0] = -w;
  lambda[1] = 0.0;
  lambda[2] = 0.0;
  lambda[3] = w;
  return CHAPLYGIN_SUCCESS;
}
