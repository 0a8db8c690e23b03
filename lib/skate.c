/* skate.c -- the discrete skate at one point of its motion: the rate
   Omega from the momentum H (3.4 inverted) and the positions of the slot
   front and the mass centre in the plane.  What a caller sampling a
   motion between collisions needs beside (B.1), (B.2) (the program's
   dense rows, tools/run.c); the massless skate's positions are the same
   in its units, its rate is chaplygin_massless_omega. */
#include <config.h>

#include <math.h>

#include "chaplygin.h"
#include "eft.h"

/* chaplygin_discrete_omega: Omega = H/(1 + l^2), l = L0 + D, the momentum
   (3.4) H = (1 + l^2) Omega inverted.
   Method: l = L0 + D with its rounding error le (TwoSum); 1 + l^2 by one
   fma, as chp_one_plus_sq (chaplygin_discrete_state_to_phase), with
   1 + 2 l le in place of 1;
   where it overflows (|l| > 2^511), (H/l)/l: 1 + l^2 = l^2 there to
   within 2^-1022 (the rounding of l then costs up to 1 ulp more).
   Accuracy: within 1.5 ulps of H/(1 + (L0 + D)^2) (measured against
   binary128 on 20000 random points, test discrete_omega: 1.0), 2.5 where
   |l| > 2^511 or the result is subnormal.
   Never overflows (|Omega| <= |H|).
   Errors: CHAPLYGIN_EINVAL (NULL), CHAPLYGIN_EDOM (non-finite, or
   L0 + D overflows). */
int
chaplygin_discrete_omega (double L0, double D, double H, double *Omega)
{
  if (!Omega)
    return CHAPLYGIN_EINVAL;
  double l, le;
  chp_two_sum (L0, D, &l, &le);         /* L0 + D = l + le exactly */
  if (!isfinite (l) || !isfinite (H))
    return CHAPLYGIN_EDOM;
  /* 1 + (l + le)^2 = l^2 + (1 + 2 l le) to first order, rounded once but
     for the rounding of 1 + 2 l le (|2 l le| <= eps l^2: below an ulp of
     the sum) */
  const double n = fma (l, l, fma (2.0 * l, le, 1.0));
  *Omega = isfinite (n) ? H / n : (H / l) / l;
  return CHAPLYGIN_SUCCESS;
}

/* chaplygin_discrete_positions: the slot front F = P + D e and the mass
   centre G = P + (L0 + D) e, e = (cos theta, sin theta), of the skate whose
   peg P is at slot position D (the front is D ahead of the peg, the mass
   centre L0 ahead of the front).  Either output may be NULL.  The massless
   skate's, in its units (Delta = 1): G as chaplygin_massless_mass_centre
   bit for bit at D = D+.
   Method: one fma per coordinate.
   Accuracy: within 1 ulp of max(|P|, |l|) plus that of sincos.
   Errors: CHAPLYGIN_EINVAL (NULL peg), CHAPLYGIN_EDOM (non-finite),
   CHAPLYGIN_ERANGE (a coordinate overflows). */
int
chaplygin_discrete_positions (double L0, double D, double theta,
                              const double peg[2], double front[2],
                              double G[2])
{
  if (!peg)
    return CHAPLYGIN_EINVAL;
  if (!chp_finite4 (L0, D, theta, peg[0]) || !isfinite (peg[1]))
    return CHAPLYGIN_EDOM;
  double sn, cs;
  sincos (theta, &sn, &cs);
  const double l = L0 + D;
  const double f0 = fma (D, cs, peg[0]), f1 = fma (D, sn, peg[1]);
  const double g0 = fma (l, cs, peg[0]), g1 = fma (l, sn, peg[1]);
  if (!chp_finite4 (f0, f1, g0, g1))
    return CHAPLYGIN_ERANGE;
  if (front)
    {
      front[0] = f0;
      front[1] = f1;
    }
  if (G)
    {
      G[0] = g0;
      G[1] = g1;
    }
  return CHAPLYGIN_SUCCESS;
}
