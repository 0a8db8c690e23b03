/* far.c -- kernel: the far regime: a slot with an end beyond CHP_L_MAX (2^500
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
   overflows elsewhere: CHAPLYGIN_ERANGE).

   One mechanism.  A routine of the library handles a far slot by opening
   its scaling (chp_far_open), scaling its inputs by their kind of quantity
   (chp_far_in, chp_far_state, chp_far_phase), calling itself on the scaled
   system f.sys, and scaling each output back by its kind (chp_far_out):
   which power of two each kind carries is stated here alone
   (chp_far_exponent).  Uses eft.h and collision.c (the scaled system). */
#include <config.h>

#include <float.h>
#include <math.h>

#include "collision.h"
#include "eft.h"
#include "far.h"
#include "motion.h"

/* The scale exponent k of a path from la to lb: 0 within the cap
   (max |l| <= 2^500); beyond it, for a far path (one strict sign,
   max |l| <= 2^400 min |l|), k = ilogb(min |l|) - 99, which puts the
   scaled min |l| in [2^99, 2^100) and the scaled max below 2^500;
   CHAPLYGIN_ERANGE otherwise (or non-finite). */
static int
far_k (double la, double lb, int *k)
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
  *k = ilogb (lo) - 99;
  return CHAPLYGIN_SUCCESS;
}

int
chp_far_open (double L0, double Delta, chp_far *f)
{
  double Ls, Ds;
  f->k = f->m = f->j = 0;
  if (!chp_finite2 (L0, Delta) || !(Delta > 0.0))
    return CHAPLYGIN_EDOM;
  CHP_TRY (far_k (L0, L0 + Delta, &f->k));
  if (f->k == 0)
    return CHAPLYGIN_SUCCESS;
  if (!chp_exact_ldexp (L0, -f->k, &Ls) || !chp_exact_ldexp (Delta, -f->k, &Ds)
      || !(Ds >= DBL_MIN))
    return CHAPLYGIN_ERANGE;    /* Delta below 2^(k - 1022): subnormal */
  chp_system_fill (&f->sys, Ls, Ds);
  return CHAPLYGIN_SUCCESS;
}

int
chp_far_open_sys (const chaplygin_discrete *sys, chp_far *f)
{
  CHP_TRY (chp_far_open (sys->L0, sys->Delta, f));
  if (f->k == 0 && chp_system_far (sys))
    return CHAPLYGIN_EDOM;
  return CHAPLYGIN_SUCCESS;
}

int
chp_far_open_path (double la, double lb, chp_far *f)
{
  f->k = f->m = f->j = 0;
  return far_k (la, lb, &f->k);
}

int
chp_far_state (chp_far *f, double E, double H, int linear, double *Es,
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
  if (!chp_far_in (f, CHP_Q_ENERGY, E, Es)
      || !chp_far_in (f, CHP_Q_MOMENTUM, H, Hs))
    return CHAPLYGIN_ERANGE;
  return CHAPLYGIN_SUCCESS;
}

int
chp_far_state_of (chp_far *f, const chaplygin_discrete_state *in, int linear,
                  chaplygin_discrete_state *si)
{
  *si = *in;
  CHP_TRY (chp_far_state (f, in->E, in->H, linear, &si->E, &si->H));
  if (!chp_far_in (f, CHP_Q_SPEED, in->V, &si->V))
    si->V = 0.0;
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
  if (!chp_far_in (f, CHP_Q_SPEED, V, Vs)
      || !chp_far_in (f, CHP_Q_RATE, Omega, Omegas))
    return CHAPLYGIN_ERANGE;
  return CHAPLYGIN_SUCCESS;
}

/* Whether the speed of a phase state at l0, sp = max(|V|, sqrt(1 + l0^2)
   |Omega|), is so large or small that E or H (or their products in the
   routines that use them) would overflow or underflow: sp max(1, |l0|) >
   2^450 or sp < 2^-400 (the bounds of chaplygin_discrete_heading's
   time-scaling), or sp overflows.  sp^2/2 <= E <= sp^2 and |H| <= sqrt(2) sp max(1, |l0|),
   so within them E lies in [2^-801, 2^900] and |H| below 2^451.  Once
   scaled by chp_far_speed, sp is in [1, 2): never a second time.  The
   one test of chaplygin_velocity_scaling (units.c),
   chaplygin_discrete_poincare (map.c) and a leg's scaling (flow.c). */
/* The speed sp = max(|V|, sqrt(1 + l0^2) |Omega|) of a phase state and
   *e = ilogb(sp) (0 for sp = 0 or non-finite inputs).  Where the product
   overflows (finite inputs: |Omega| > 1 there, up to V = Omega = DBL_MAX),
   sp = +Inf and *e the exponent an unbounded format would give. */
static double
speed (double l0, double V, double Omega, int *e)
{
  const double sp = fmax (fabs (V), hypot (1.0, l0) * fabs (Omega));
  *e = 0;
  if (sp > 0.0 && isfinite (sp))
    *e = ilogb (sp);
  else if (isinf (sp) && isfinite (V) && isfinite (Omega) && isfinite (l0))
    {
      /* the product's exponent from its factors' (each below 1024, so no
         int overflow: 2^-64 lower was still infinite for l0 = 1e300,
         Omega = 1e100) and the product of their significands in [1, 4),
         rounded as an unbounded format would */
      const double h = hypot (1.0, l0), w = fabs (Omega);
      const int eh = ilogb (h), ew = ilogb (w);
      const int ep = eh + ew + ilogb (scalbn (h, -eh) * scalbn (w, -ew));
      *e = V != 0.0 && ilogb (fabs (V)) > ep ? ilogb (fabs (V)) : ep;
    }
  return sp;
}

int
chp_far_speed_needed (double l0, double V, double Omega)
{
  int e;
  const double sp = speed (l0, V, Omega, &e);
  return e != 0
    && (!isfinite (sp) || sp * fmax (1.0, fabs (l0)) > 0x1p450
        || sp < 0x1p-400);
}

int
chp_far_speed (chp_far *f, double l0, double V, double Omega, double *Vs,
               double *Omegas)
{
  int e;
  f->j = 0;
  (void) speed (l0, V, Omega, &e);
  f->m = -e;
  if (!chp_far_in (f, CHP_Q_SPEED, V, Vs)
      || !chp_far_in (f, CHP_Q_RATE, Omega, Omegas))
    return CHAPLYGIN_ERANGE;
  return CHAPLYGIN_SUCCESS;
}

/* The exponent of each kind of quantity: its scaled value is the true one
   times 2^e.  Lengths by s = 2^-k, energies by a = 4^m (the time-scaling
   of every speed by 2^m), so that H = (1 + l^2) Omega ~ l^2 Omega and
   Omega = V/l-like rates follow; j is the extra factor of the quantities
   linear in H where the motion is (chp_far_state, LINEAR). */
int
chp_far_exponent (const chp_far *f, chp_quantity q)
{
  switch (q)
    {
    case CHP_Q_LENGTH:
      return -f->k;
    case CHP_Q_ENERGY:
      return 2 * f->m;
    case CHP_Q_SPEED:
      return f->m;
    case CHP_Q_MOMENTUM:
      return f->m - f->k + f->j;
    case CHP_Q_RATE:
      return f->m + f->k + f->j;
    case CHP_Q_TIME:
      return -(f->k + f->m);
    case CHP_Q_HEADING:
      return f->j;
    case CHP_Q_INVERSE_AREA:
      return 2 * f->k;
    case CHP_Q_DENERGY_DMOMENTUM:
      /* dE'/dH = 2 C1 H: C1 ~ Delta^2/l^4 (2^2k) times H */
      return f->m + f->k + f->j;
    case CHP_Q_DHEADING_DENERGY:
      return f->j - 2 * f->m;
    case CHP_Q_DHEADING_DMOMENTUM:
    default:
      /* the heading is linear in H where j > 0: j cancels */
      return f->k - f->m;
    }
}

double
chp_far_out (const chp_far *f, chp_quantity q, double scaled)
{
  return ldexp (scaled, -chp_far_exponent (f, q));
}

int
chp_far_in (const chp_far *f, chp_quantity q, double x, double *scaled)
{
  return chp_exact_ldexp (x, chp_far_exponent (f, q), scaled);
}

int
chp_far_out_exact (const chp_far *f, chp_quantity q, double scaled,
                   double *x)
{
  return chp_exact_ldexp (scaled, -chp_far_exponent (f, q), x);
}
