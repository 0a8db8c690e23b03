/* motion.c -- kernel: the motion of the discrete skate between collisions
   (motion.h).  Uses eft.h only.

   Between collisions the energy E (3.3) and the angular momentum about the
   peg H (3.4) are constant, so with h = H/sqrt(2E)

       V^2 = 2E - H^2/(1 + l^2) = 2E g(l)/(1 + l^2),   g(l) = l^2 + 1 - h^2,
       Omega = H/(1 + l^2),

   and everything the library computes of a motion derives from E, H and
   1 - h^2, whose sign (exact here) separates the two regimes of the closed
   forms (leg.c): h^2 <= 1, no turning point (p = 1, q = 1 - h^2); h^2 > 1,
   turning points at |l| = sqrt(h^2 - 1) (p = h^2, q = h^2 - 1).  */
#include <config.h>

#include <float.h>
#include <math.h>

#include "eft.h"
#include "motion.h"

/* chp_one_minus_h2: 1 - h^2 = (2E - H^2)/(2E) for E > 0.
   Method: H^2 - 2E by one fma, so that the sign is exact (zero exactly
   when H^2 = 2E, the spinning condition (3.8)) and the value within 2 ulps;
   for |H| > 2^500 on arguments scaled by 2^-2k, 2^-k (exact unless 2E 2^-2k
   underflows, which only happens when H^2 >> 2E and the result overflows).
   Returns -Inf when the result overflows. */
double
chp_one_minus_h2 (double E, double H)
{
  double twoE = 2.0 * E;
  if (fabs (H) <= 0x1p500 && isfinite (twoE))
    return -fma (H, H, -twoE) / twoE;
  int k;
  frexp (H, &k);
  double Hs = ldexp (H, -k), twoEs = ldexp (E, 1 - 2 * k);
  if (!(twoEs > 0.0))
    return -HUGE_VAL;
  return -fma (Hs, Hs, -twoEs) / twoEs;
}

/* chp_motion_init_eh: the part of chp_motion_init that the exact
   classification of a motion and the (E, H) update need: E, H and
   1 - h^2 (see chp_one_minus_h2); the other fields are left unset
   (chp_motion_complete sets them).
   Errors: CHAPLYGIN_EDOM (non-finite, E < 0), CHAPLYGIN_ESTATE (E = 0: at
   rest, no motion), CHAPLYGIN_ERANGE (2E or h^2 overflows). */
int
chp_motion_init_eh (double E, double H, chp_motion *m)
{
  if (!isfinite (E) || !isfinite (H) || E < 0.0)
    return CHAPLYGIN_EDOM;
  if (E == 0.0)
    return CHAPLYGIN_ESTATE;
  double twoE = 2.0 * E;
  double one_minus_h2 = chp_one_minus_h2 (E, H);
  if (!isfinite (twoE) || !isfinite (one_minus_h2))
    return CHAPLYGIN_ERANGE;
  m->E = E;
  m->H = H;
  m->one_minus_h2 = one_minus_h2;
  return CHAPLYGIN_SUCCESS;
}

/* chp_motion_complete: the fields of a motion set by chp_motion_init_eh
   extended by those the heading and time integrals need. */
void
chp_motion_complete (chp_motion *m)
{
  m->sqrt2E = sqrt (2.0 * m->E);
  m->h = m->H / m->sqrt2E;
  chp_motion_set_one_minus_h2 (m, m->one_minus_h2);
}

/* chp_motion_init: the invariants of the motion with energy E > 0 and
   momentum H: chp_motion_init_eh and chp_motion_complete.
   Errors: those of chp_motion_init_eh. */
int
chp_motion_init (double E, double H, chp_motion *m)
{
  CHP_TRY (chp_motion_init_eh (E, H, m));
  chp_motion_complete (m);
  return CHAPLYGIN_SUCCESS;
}

/* chp_motion_set_one_minus_h2: set 1 - h^2 (finite: a non-finite value is
   ignored) and derive sp, sq, pmq and theta_factor from it; used by
   chp_motion_init and to replace its value by a more accurate one. */
void
chp_motion_set_one_minus_h2 (chp_motion *m, double one_minus_h2)
{
  if (!isfinite (one_minus_h2))
    return;
  m->one_minus_h2 = one_minus_h2;
  if (one_minus_h2 >= 0.0)
    {
      m->sqrt_p = 1.0;
      m->sqrt_q = sqrt (one_minus_h2);
      m->p_minus_q = m->h * m->h;
      m->theta_factor = m->h;
    }
  else
    {
      m->sqrt_p = fabs (m->h);
      m->sqrt_q = sqrt (-one_minus_h2);
      m->p_minus_q = 1.0;
      m->theta_factor = chp_sign (m->H);
    }
}

/* chp_phase_one_minus_h2: 1 - h^2 = (2E - H^2)/(2E) of the phase state
   (l0, V0,
   Omega0), 2E - H^2 = V0^2 - l0^2 (1 + l0^2) Omega0^2 = V0^2 - w^2 -
   (w l0)^2 with w = l0 Omega0, by error-free products and sums: accurate
   relative to the exact inputs however much the terms cancel.  twoE is
   2E (rounded).  Non-finite (NaN or Inf) where a term overflows. */
double
chp_phase_one_minus_h2 (double l0, double V0, double Omega0, double twoE)
{
  double wh, wl, a, ea, uh, eu, b, eb, c, ec, s1, e1, s2, e2;
  chp_two_prod (l0, Omega0, &wh, &wl);
  chp_two_prod (wh, wh, &a, &ea);
  chp_two_prod (wh, l0, &uh, &eu);
  double ul = eu + wl * l0;
  chp_two_prod (uh, uh, &b, &eb);
  chp_two_prod (V0, V0, &c, &ec);
  chp_two_sum (c, -a, &s1, &e1);
  chp_two_sum (s1, -b, &s2, &e2);
  double N = s2 + ((e1 + e2) + ((ec - ea - eb) - 2.0 * (wh * wl + uh * ul)));
  return N / twoE;
}

double
chp_motion_g (const chp_motion *m, double l)
{
  return fma (l, l, m->one_minus_h2);
}

/* chp_motion_g_exact: chp_g_exact for the motion's E and H; chp_motion_g
   where an intermediate overflows (an overflowed 2E l^2 or H^2 makes the
   numerator infinite or NaN). */
double
chp_motion_g_exact (const chp_motion *m, double l, double el)
{
  const double g = chp_g_exact (m->E, m->H, l, el);
  return isfinite (g) ? g : chp_motion_g (m, l);
}


/* (B.1) evaluated as printed, without the reachability checks of
   chaplygin_discrete_flow (for callers that have classified the motion
   already); V^2 may come out slightly negative near a turning point.
   CHAPLYGIN_ERANGE on overflow. */
int
chp_flow_eval (double L0, double D0, double V0, double Omega0, double D,
               double *V2, double *Omega)
{
  double l0 = L0 + D0, l = L0 + D;
  double n0 = chp_one_plus_sq (l0), n = chp_one_plus_sq (l);
  double ratio = n0 / n;
  double om = Omega0 * ratio;
  double v2 = V0 * V0 + (D - D0) * (2.0 * L0 + D + D0) * ratio
    * Omega0 * Omega0;
  if (!isfinite (v2) || !isfinite (om))
    return CHAPLYGIN_ERANGE;
  *V2 = v2;
  *Omega = om;
  return CHAPLYGIN_SUCCESS;
}


int
chp_segment_classify (const chp_segment *seg, const chp_motion *m,
                      const double *g_far)
{
  double least = 1.0;
  if (seg->crosses)
    least = m->one_minus_h2;
  else if (seg->toward && m->one_minus_h2 < 0.0)
    least = g_far ? *g_far : chp_motion_g_exact (m, seg->l1, seg->l1_err);
  return chp_segment_rule (seg->crosses, least);
}
