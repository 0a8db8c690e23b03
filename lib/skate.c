/* skate.c -- the discrete skate at one point of its motion: the rate
   Omega from the momentum H (3.4 inverted), the positions of the slot
   front and the mass centre in the plane, and (B.1), (B.2) along both
   legs of a segment from its post-collision state.  What a caller
   sampling a motion between collisions needs (the program's dense rows,
   tools/run.c); the massless skate's positions are the same in its
   units, its rate and flow are chaplygin_massless_omega and
   chaplygin_massless_flow. */
#include <config.h>

#include <float.h>
#include <math.h>

#include "chaplygin.h"
#include "eft.h"
#include "leg.h"
#include "motion.h"
#include "status.h"

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

/* ---- the discrete skate between two collisions ------------------------ */

/* Where on its segment a sample lies, from the step's classification. */
typedef struct
{
  double D0;            /* the start end */
  double V0, Omega0;    /* the phase state there (from E, H) */
  int reversal;         /* the segment turns back at ev.Dc */
  int spins;            /* it ends in the spinning equilibrium (3.8) */
  chaplygin_discrete_event ev;  /* the step's (reversal, Dc, V-, ...) */
} segment_place;

/* Relative distance within which a sample is the turning point itself (V =
   0 there): the rounding of D_c = -L0 -+ c and of l = L0 + D, a few ulps
   of |L0| + c; as chaplygin_massless_flow's 8 eps of its unit slot. */
#define TURN_ULPS 8.0

/* Phase 1: the segment of ST: its start as a phase state and the step's
   classification (E, H only, the fast path). */
static int
segment_locate (const chaplygin_discrete *sys,
                const chaplygin_discrete_state *st, segment_place *sp)
{
  double q0[4];
  CHP_TRY (chaplygin_discrete_state_to_phase (sys, st, q0));
  sp->D0 = q0[0];
  sp->V0 = q0[1];
  sp->Omega0 = q0[3];
  chaplygin_discrete_state next;
  /* the classification is exact whatever the method: the closed form's
     E, H alone */
  const int status = chaplygin_discrete_step (sys, st, 0, NULL, &next,
                                              &sp->ev);
  sp->spins = status == CHAPLYGIN_ESPIN;        /* the motion to it exists */
  if (!sp->spins)
    CHP_TRY (status);
  sp->reversal = !sp->spins && sp->ev.reversal;
  return CHAPLYGIN_SUCCESS;
}

/* The step's heading and time (the whole segment), for the ends and the
   return leg. */
static int
segment_totals (const chaplygin_discrete *sys,
                const chaplygin_discrete_state *st,
                const chaplygin_options *opt, unsigned want,
                segment_place *sp)
{
  chaplygin_discrete_state next;
  return chaplygin_discrete_step (sys, st, want, opt, &next, &sp->ev);
}

/* g(l) = (1 + l^2) V^2/(2E) at the start (*g0) and at D (*gl), within
   the cap: from E and H by error-free arithmetic (no cancellation near a
   turning point, where (B.1) from V0 cancels), or, where the state
   knows V+ (a slow start: E and H lose it), g0 from V+ itself and
   gl = g0 + (D - D0)(2 L0 + D + D0) unless that cancels worse than E and
   H are conditioned at l (as the step: lib/map.c). */
static void
segment_g (const chaplygin_discrete *sys, const chaplygin_discrete_state *st,
           const chp_motion *m, double D, double *g0, double *gl)
{
  chp_segment seg;
  chp_segment_init (sys, st->dir, &seg);
  double l, le;
  chp_two_sum (sys->L0, D, &l, &le);
  *g0 = chp_motion_g_exact (m, seg.l0, seg.l0_err);
  *gl = chp_motion_g_exact (m, l, le);
  if (st->V == 0.0)
    return;
  const double V = st->V, D0 = st->dir > 0 ? 0.0 : sys->Delta;
  const double delta = (D - D0) * (2.0 * sys->L0 + D + D0);
  *g0 = chp_one_plus_sq (seg.l0) * (V * (V / (2.0 * st->E)));
  if (fabs (*g0) + fabs (delta)
      <= chp_one_plus_sq (l) + fabs (1.0 - m->one_minus_h2))
    *gl = *g0 + delta;
}

/* V^2 at l = L0 + D: 2E g(l)/(1 + l^2) (segment_g); beyond the cap, (B.1)
   of the scaled problem (chaplygin_discrete_flow). */
static int
segment_speed2 (const chaplygin_discrete *sys,
                const chaplygin_discrete_state *st, const segment_place *sp,
                double D, double *V2)
{
  const double L0 = sys->L0, l = L0 + D;
  if (fabs (l) > CHP_L_MAX || fabs (L0 + sp->D0) > CHP_L_MAX)
    {
      double om;
      const int status = chaplygin_discrete_flow (L0, sp->D0, sp->V0,
                                                  sp->Omega0, D, V2, &om);
      if (status == CHAPLYGIN_ESTATE)
        *V2 = -1.0;                     /* not reached: the caller decides */
      return status == CHAPLYGIN_ESTATE ? CHAPLYGIN_SUCCESS : status;
    }
  chp_motion m;
  double g0, gl;
  CHP_TRY (chp_motion_init_eh (st->E, st->H, &m));
  segment_g (sys, st, &m, D, &g0, &gl);
  *V2 = 2.0 * (st->E * (gl / chp_one_plus_sq (l)));
  return isfinite (*V2) ? CHAPLYGIN_SUCCESS : CHAPLYGIN_ERANGE;
}

/* The heading and time from the start to D on leg 0: within the cap and
   the range where the motion's fields neither overflow nor underflow (E in
   [2^-800, 2^800], |H| <= 2^450; chaplygin_discrete_heading's time-scaling
   bounds), the map's own leg (chp_leg) from E and H with g at both ends by
   error-free arithmetic: no cancellation near a turning point, where the
   phase state's g0 + (B.1) would lose the condition number of g (measured
   9900 eps at a sample 1e-3 of the leg short of D_c); elsewhere, and for
   the ODE, (B.2) from the start's phase state (scaled as it needs). */
static int
segment_leg (const chaplygin_discrete *sys, const chaplygin_discrete_state *st,
             const segment_place *sp, double D, const chaplygin_options *o,
             double *dtheta, double *dtau)
{
  chp_segment seg;
  chp_segment_init (sys, st->dir, &seg);
  const double l = sys->L0 + D, E = st->E, H = st->H;
  if (o->method == CHAPLYGIN_ODE || fabs (seg.l0) > CHP_L_MAX
      || fabs (l) > CHP_L_MAX || !(E >= 0x1p-800 && E <= 0x1p800)
      || !(fabs (H) <= 0x1p450))
    return chaplygin_discrete_heading (sys->L0, sp->D0, sp->V0, sp->Omega0, D,
                                       o, dtheta, dtau);
  chp_motion m;
  double g0, gl;
  CHP_TRY (chp_motion_init (E, H, &m));
  segment_g (sys, st, &m, D, &g0, &gl);
  return chp_leg (&m, seg.l0, g0, l, fmax (gl, 0.0), fabs (D - sp->D0), o,
                  dtheta, dtau);
}

/* Phase 2: the sample at D on LEG of the located segment SP. */
static int
segment_sample (const chaplygin_discrete *sys,
                const chaplygin_discrete_state *st, segment_place *sp,
                double D, int leg, const chaplygin_options *opt, double *V,
                double *Omega, double *dtheta, double *dtau)
{
  const double L0 = sys->L0, D0 = sp->D0, dir = st->dir;
  const unsigned want = (dtheta ? CHAPLYGIN_WANT_THETA : 0u)
    | (dtau ? CHAPLYGIN_WANT_TAU : 0u);
  if (leg == 1 && !sp->reversal)
    return CHAPLYGIN_ESTATE;
  /* the end of leg 0: D_c, or the far end (where a spinning motion never
     arrives: l = 0 comes first) */
  const double Dc = sp->ev.Dc, Dfar = dir > 0 ? sys->Delta : 0.0;
  const double tol = TURN_ULPS * DBL_EPSILON * (fabs (L0) + fabs (L0 + Dc));
  const int at_turn = sp->reversal && fabs (D - Dc) <= tol;
  if (!at_turn && !(dir * (D - D0) >= 0.0
                    && dir * (D - (sp->reversal ? Dc : Dfar)) <= 0.0))
    return CHAPLYGIN_ESTATE;            /* not on the leg */
  if (sp->spins && (L0 + D == 0.0 || (L0 + D < 0.0) != (L0 + D0 < 0.0)))
    return CHAPLYGIN_ESTATE;            /* at or beyond the spinning point */

  double v, om, th = 0.0, ta = 0.0;
  const double H = st->H;
  if (at_turn || (leg == 1 && D == D0) || (!sp->reversal && !sp->spins
                                           && D == Dfar))
    {
      /* the ends of the legs: the step's values */
      CHP_TRY (segment_totals (sys, st, opt, want, sp));
      const double half = at_turn ? 0.5 : 1.0;
      v = at_turn ? 0.0 : sp->ev.Vminus;
      th = half * sp->ev.dtheta;
      ta = half * sp->ev.dtau;
      /* at D_c, V = 0: E = H Omega/2 exactly, so Omega = 2E/H to an ulp
         (H/(1 + l^2) would carry the rounding of D_c and of L0 + D_c) */
      if (at_turn)
        om = 2.0 * (st->E / H);
      else
        CHP_TRY (chaplygin_discrete_omega (L0, D, H, &om));
      if (!isfinite (om))
        return CHAPLYGIN_ERANGE;
    }
  else if (D == D0)
    {
      v = sp->V0;
      om = sp->Omega0;
    }
  else
    {
      double v2;
      CHP_TRY (segment_speed2 (sys, st, sp, D, &v2));
      if (!(v2 >= 0.0))
        return CHAPLYGIN_ESTATE;        /* beyond a turning point */
      v = (leg ? -dir : dir) * sqrt (v2);
      CHP_TRY (chaplygin_discrete_omega (L0, D, H, &om));
      CHP_TRY (segment_leg (sys, st, sp, D, opt, dtheta ? &th : NULL,
                            dtau ? &ta : NULL));
      if (leg == 1)
        {
          CHP_TRY (segment_totals (sys, st, opt, want, sp));
          th = sp->ev.dtheta - th;
          ta = sp->ev.dtau - ta;
        }
    }
  if (V)
    *V = v;
  if (Omega)
    *Omega = om;
  if (dtheta)
    *dtheta = th;
  if (dtau)
    *dtau = ta;
  return CHAPLYGIN_SUCCESS;
}

/* chaplygin_discrete_segment_flow: the motion between collisions, (B.1)
   and (B.2) along the segment that starts at the post-collision state st
   (the discrete analogue of chaplygin_massless_flow).  At D on
     leg 0 (from the start D0 towards the far end or the turning point
       D_c):  V = dir sqrt(V(D)^2), theta - theta0 and tau - tau0 by (B.2)
       (chaplygin_discrete_heading from the start's phase state);
     leg 1 (a reversing segment, from D_c back to D0): by the time
       reversal about D_c, V = -dir sqrt(V(D)^2) and the increments are
       the whole segment's (chaplygin_discrete_step's) less leg 0's at D;
   Omega = H/(1 + (L0 + D)^2) (chaplygin_discrete_omega) on both, and
   2E/H at D_c (V = 0 there: exact for E and H, where the first would
   carry the rounding of D_c).
   V(D)^2 = 2E g(l)/(1 + l^2), g = l^2 + 1 - H^2/(2E) by error-free
   arithmetic.  At the far end, at D_c (V = 0, half the segment's heading
   and time: the motion is symmetric about it) and back at D0 the values
   are chaplygin_discrete_step's bit for bit.  A D within 8 ulps of
   |L0| + |L0 + D_c| of D_c (either side) is taken as D_c.
   Domain: sys and st as chaplygin_discrete_step; D on the part of the
   slot the leg covers (leg 1 only for a reversing segment); also the
   segment of a state whose motion ends in the spinning equilibrium (3.8)
   (CHAPLYGIN_ESPIN from the step), leg 0 short of l = 0.
   Cost: one E, H step to classify, one leg integral (segment_leg), and
   one full step on leg 1 and at the ends.
   Accuracy: against 40-digit quadrature in D (tests/test_skate.c,
   84 samples on both legs of 14 segments): V within 0.93 eps, Omega 1.0,
   dtheta 2.9, dtau 3.7 eps relative, also a thousandth of the leg short
   of D_c; the scaled route (segment_leg) as chaplygin_discrete_heading.
   Errors: CHAPLYGIN_EINVAL (NULL sys or st, leg not 0 or 1, bad
   options), CHAPLYGIN_EDOM
   (non-finite D), CHAPLYGIN_ESTATE (D not on the leg), and those of the
   step and heading. */
int
chaplygin_discrete_segment_flow (const chaplygin_discrete *sys,
                                 const chaplygin_discrete_state *st,
                                 double D, int leg,
                                 const chaplygin_options *opt, double *V,
                                 double *Omega, double *dtheta, double *dtau)
{
  if (!sys || !st || (leg != 0 && leg != 1))
    return CHAPLYGIN_EINVAL;
  chaplygin_options o;
  CHP_TRY (chp_options_resolve (opt, &o));
  if (!isfinite (D))
    return CHAPLYGIN_EDOM;
  segment_place sp;
  CHP_TRY (segment_locate (sys, st, &sp));
  return segment_sample (sys, st, &sp, D, leg, &o, V, Omega, dtheta, dtau);
}
