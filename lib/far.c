/* far.c -- the far regime: a slot with an end beyond CHP_L_MAX (2^500
   radii of gyration) from the mass centre, where 1 + l^2 and its products
   overflow.

   There the radius of gyration (the "1" of 1 + l^2) is below every
   rounding: the motion is that of rho = 0 up to a relative O(1/l^2), and
   rho = 0 has the scaling symmetry
       (l, E, H, tau) -> (s l, a E, sqrt(a) s H, s tau/sqrt(a)),
   theta, the number of collisions and the direction unchanged (lengths
   times s; a is the time-scaling, exact for any rho).  With s = 2^-k and
   a = 4^m every scaling is exact in binary floating point.  The routines
   at |l| > 2^500 solve the scaled problem, whose smallest |l| on the path
   lies in [2^99, 2^100) and largest below 2^500 (within the range where
   every routine works), and scale the answer back.  rho = 1 at |l| >=
   2^99 is again rho = 0 up to a relative O(2^-198), so the two problems
   agree far below the rounding of double.  (A larger scaled |l| would
   not do: quantities ~ 1/l^2 of a short leg, such as the heading's
   integrands, underflow at 2^400.)  The energy factor a brings E (or a
   phase state's speed) near 1, so that times, lengths over speeds, stay
   in range as lengths do.  Where sqrt(a) s H would still be below
   2^-570, h = H/sqrt(2E) is below 2^-570 of the smallest |l|: the
   motion is linear in H to far below rounding (no turning point, V^2 =
   2E (1 - h^2/(1 + l^2))), and routines whose results are linear in H
   there (the return map, the collision, the Jacobian) scale H alone by
   a further 2^j, the others raise a instead (chp_far_eh).

   The signs that decide validity and reversal agree too where the slot
   end is a double (L0 itself): H^2 - 2E l^2 is then 0 or a multiple of
   2^(2 ilogb(l) - 156) at least, above the 2^(2 ilogb(l) - 198) by which
   the two problems' terms differ.  At the end L0 + Delta, when not
   representable, they may differ where the turning point lies within a
   relative 2^-198 of that end: the peg then arrives with |V-| below
   2^-98 sqrt(2E), and either outcome is within the rounding of the
   inputs.

   Domain: the path of one strict sign and max |l| <= 2^400 min |l|
   (otherwise it comes near the mass centre, where rho matters, while l^2
   overflows elsewhere: CHAPLYGIN_ERANGE). */
#include <config.h>

#include <float.h>
#include <math.h>

#include "internal.h"

int
chp_exact_ldexp (double x, int e, double *r)
{
  double y = ldexp (x, e);
  if (!isfinite (y) || ldexp (y, -e) != x)
    return 0;
  *r = y;
  return 1;
}

int
chp_far_k (double la, double lb, int *k)
{
  double hi = fmax (fabs (la), fabs (lb)), lo = fmin (fabs (la), fabs (lb));
  *k = 0;
  if (!isfinite (hi))
    return CHAPLYGIN_ERANGE;
  if (hi <= CHP_L_MAX)
    return CHAPLYGIN_SUCCESS;
  /* one strict sign, and far from the mass centre everywhere (2^400 lo
     is exact, or +Inf) */
  if (!((la > 0.0 && lb > 0.0) || (la < 0.0 && lb < 0.0))
      || !(hi <= 0x1p400 * lo))
    return CHAPLYGIN_ERANGE;
  /* the scaled min |l| in [2^99, 2^100), the scaled max below 2^500 */
  *k = ilogb (lo) - 99;
  return CHAPLYGIN_SUCCESS;
}

int
chp_far_init (double L0, double Delta, chp_far *f)
{
  f->m = 0;
  f->L0 = L0;
  f->Delta = Delta;
  CHP_TRY (chp_far_k (L0, L0 + Delta, &f->k));
  if (f->k == 0)
    return CHAPLYGIN_SUCCESS;
  if (!chp_exact_ldexp (L0, -f->k, &f->L0)
      || !chp_exact_ldexp (Delta, -f->k, &f->Delta)
      || !(f->Delta >= DBL_MIN))
    return CHAPLYGIN_ERANGE;    /* Delta below 2^(k - 1022): subnormal */
  return CHAPLYGIN_SUCCESS;
}

int
chp_far_eh (chp_far *f, double E, double H, int linear, double *Es,
            double *Hs)
{
  f->m = 0;
  f->j = 0;
  if (f->k == 0 || !(E > 0.0))
    {
      /* nothing to scale but lengths (E = 0 or invalid: refused by the
         caller's own checks, in the scaled problem) */
      *Es = E;
      *Hs = ldexp (H, -f->k);
      return CHAPLYGIN_SUCCESS;
    }
  /* E in [1/2, 2): speeds near 1, so that times (lengths over speeds)
     stay in range as lengths do */
  f->m = -(ilogb (E) / 2);
  if (H == 0.0)
    {
      if (!chp_exact_ldexp (E, 2 * f->m, Es))
        return CHAPLYGIN_ERANGE;
      *Hs = H;
      return CHAPLYGIN_SUCCESS;
    }
  /* 2^(m-k) H must be exact, and C2 times it (C2 >= 2^-400 in a far
     slot) normal too: where it would be below 2^-570, h is below
     2^-570 of the smallest |l| and the motion is linear in H to far
     below rounding (V^2 = 2E (1 - h^2/(1 + l^2)), no turning point):
     scale H alone by 2^j to near 2^-100 (LINEAR); otherwise raise the
     energy further (time-scaling, exact) while it stays below 2^1000 */
  const int eh = ilogb (H) + f->m - f->k;
  if (eh < -570)
    {
      if (linear)
        f->j = -100 - eh;
      else if (ilogb (E) + 2 * (f->m - 570 - eh) <= 1000)
        f->m += -570 - eh;
      else
        return CHAPLYGIN_ERANGE;
    }
  if (!chp_exact_ldexp (E, 2 * f->m, Es)
      || !chp_exact_ldexp (H, f->m - f->k + f->j, Hs))
    return CHAPLYGIN_ERANGE;
  return CHAPLYGIN_SUCCESS;
}

int
chp_far_phase (chp_far *f, double l0, double V, double Omega, double *Vs,
               double *Omegas)
{
  f->m = 0;
  f->j = 0;
  /* the speed sqrt(V^2 + l0^2 Omega^2) (for |l0| >> 1) near 1 */
  const double sp = fmax (fabs (V), fabs (l0) * fabs (Omega));
  if (f->k > 0 && sp > 0.0 && isfinite (sp))
    f->m = -ilogb (sp);
  if (!chp_exact_ldexp (V, f->m, Vs)
      || !chp_exact_ldexp (Omega, f->k + f->m, Omegas))
    return CHAPLYGIN_ERANGE;
  return CHAPLYGIN_SUCCESS;
}

int
chp_far_params (double L0, double Delta, int dir, chp_far *f)
{
  if (dir != 1 && dir != -1)
    return CHAPLYGIN_EINVAL;
  if (!chp_finite2 (L0, Delta) || !(Delta > 0.0))
    return CHAPLYGIN_EDOM;
  return chp_far_init (L0, Delta, f);
}

int
chp_far_sys (const chaplygin_discrete *sys, chp_far *f,
             chaplygin_discrete *scaled)
{
  if (!chp_finite2 (sys->L0, sys->Delta) || !(sys->Delta > 0.0))
    return CHAPLYGIN_EDOM;
  CHP_TRY (chp_far_init (sys->L0, sys->Delta, f));
  if (f->k == 0)
    return CHAPLYGIN_SUCCESS;
  return chaplygin_discrete_init (scaled, f->L0, f->Delta);
}
