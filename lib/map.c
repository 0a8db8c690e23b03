/* map.c -- Section 3.1 and Appendix B.2: the Poincare map (3.5) and the
   return map (B.3), (B.4), with the turning points (B.5).

   A post-collision state has its peg at the slot front (D = 0) if V > 0 and
   at the rear (D = Delta) if V < 0.  Between collisions E and H are
   constant; the motion either reaches the far end (no reversal, (B.3)) or
   turns at D_c and returns to the end it started from (reversal, (B.4)).
   Either way the next peg goes in at the other end, and the collision is
   that of (3.7) at the end the peg leaves, D-.  */
#include <config.h>

#include <float.h>
#include <math.h>
#include <stddef.h>

#include "chaplygin.h"
#include "certified.h"
#include "collision.h"
#include "eft.h"
#include "far.h"
#include "leg.h"
#include "motion.h"
#include "ode.h"
#include "status.h"

/* chaplygin_discrete_init: a discrete skate with mass centre L0 ahead of the
   slot front and slot length Delta (units of rho), with the (3.7)
   coefficients C1, C2 for a collision at either end, computed once.
   Domain: L0 finite, 0 < Delta finite.
   Errors: CHAPLYGIN_EINVAL (NULL), CHAPLYGIN_EDOM. */
int
chaplygin_discrete_init (chaplygin_discrete *sys, double L0, double Delta)
{
  if (!sys)
    return CHAPLYGIN_EINVAL;
  if (!chp_finite2 (L0, Delta) || !(Delta > 0.0))
    return CHAPLYGIN_EDOM;
  chp_system_fill (sys, L0, Delta);
  return CHAPLYGIN_SUCCESS;
}

/* chaplygin_discrete_coefficients: (B.3), (B.4)
     (B.3) no reversal:  C1 = -Delta^2 / (2 [1 + (L0 + Delta - D+)^2]^2
                                           [1 + (L0 + D+)^2]),
                         C2 = [1 + L0 (L0 + Delta)] / [1 + (L0 + Delta - D+)^2];
     (B.4) reversal:     C1 = -Delta^2 / (2 [1 + (L0 + D+)^2]^2
                                           [1 + (L0 + Delta - D+)^2]),
                         C2 = [1 + L0 (L0 + Delta)] / [1 + (L0 + D+)^2],
   D+ = 0 for V+ > 0 and Delta for V+ < 0.  Both are (3.7) at the end the
   peg leaves: D- = Delta - D+ without reversal, D- = D+ with one.
   Domain: finite; Delta > 0; Dplus exactly 0 or Delta; reversal 0 or 1.
   Errors: CHAPLYGIN_EINVAL (NULL, reversal), CHAPLYGIN_EDOM,
   CHAPLYGIN_ESTATE (Dplus not an end). */
int
chaplygin_discrete_coefficients (double L0, double Delta, double Dplus,
                                 int reversal, double *C1, double *C2)
{
  if (!C1 || !C2 || (reversal != 0 && reversal != 1))
    return CHAPLYGIN_EINVAL;
  if (!chp_finite2 (L0, Delta) || !(Delta > 0.0) || !isfinite (Dplus))
    return CHAPLYGIN_EDOM;
  if (Dplus != 0.0 && Dplus != Delta)
    return CHAPLYGIN_ESTATE;
  double Dminus = reversal ? Dplus : Delta - Dplus;
  chp_collision_coefficients (L0, Delta, Dminus, C1, C2);
  return CHAPLYGIN_SUCCESS;
}

/* chaplygin_discrete_turning_points: (B.5)
       D_c = -L0 -+ sqrt(H^2/(2E) - 1),
   the points where V = 0 for the energy E and momentum H.
   Method: H^2/(2E) - 1 by chp_one_minus_h2 (one fma), so the radicand is
   within two roundings and its sign exact; n_real = 2 (> 0), 1 (= 0: the
   double root D = -L0, the spinning point) or 0 (< 0: V never vanishes).
   Where H^2 overflows, from E and H scaled exactly by 4^-q, 2^-q, or as
   c = |H|/sqrt(2E) where h^2 exceeds the range of double (c = |h| to far
   below rounding there).
   Domain: finite; Delta > 0; E > 0.
   Errors: CHAPLYGIN_EINVAL (NULL), CHAPLYGIN_EDOM (non-finite, Delta <= 0,
   E < 0), CHAPLYGIN_ESTATE (E = 0: at rest), CHAPLYGIN_ERANGE (a turning
   point beyond the range of double). */
int
chaplygin_discrete_turning_points (double L0, double Delta, double E,
                                   double H, int *n_real, double Dc[2],
                                   int *n_in_slot)
{
  if (!n_real || !Dc || !n_in_slot)
    return CHAPLYGIN_EINVAL;
  if (!chp_finite4 (L0, Delta, E, H) || !(Delta > 0.0) || E < 0.0)
    return CHAPLYGIN_EDOM;
  if (E == 0.0)
    return CHAPLYGIN_ESTATE;
  double one_minus_h2 = chp_one_minus_h2 (E, H), c = 0.0;
  if (!isfinite (one_minus_h2))
    {
      /* H^2 overflows: the same ratio h^2 = H^2/(2E) from E, H scaled by
         4^-q, 2^-q (exact); where E 4^-q underflows, h^2 > 2^500 and
         c = sqrt(h^2 - 1) is |h| to far below rounding */
      const int q = ilogb (H) - 256;
      double Es = E, Hs = H;
      if (chp_exact_ldexp (E, -2 * q, &Es) && chp_exact_ldexp (H, -q, &Hs))
        one_minus_h2 = chp_one_minus_h2 (Es, Hs);
      else
        Es = E, Hs = H;
      if (!isfinite (one_minus_h2))
        c = fabs (Hs) / sqrt (2.0 * Es);      /* E (Es) tiny: no overflow */
    }
  int n = 0;
  double r[2] = { 0.0, 0.0 };
  if (c == 0.0 && one_minus_h2 == 0.0)
    {
      n = 1;
      r[0] = -L0;
    }
  else if (c > 0.0 || one_minus_h2 < 0.0)
    {
      if (c == 0.0)
        c = sqrt (-one_minus_h2);
      n = 2;
      r[0] = -L0 - c;
      r[1] = -L0 + c;
      if (!isfinite (r[0]) || !isfinite (r[1]))
        return CHAPLYGIN_ERANGE;
    }
  int in = 0;
  for (int i = 0; i < n; i++)
    if (r[i] >= 0.0 && r[i] <= Delta)
      in++;
  for (int i = 0; i < n; i++)
    Dc[i] = r[i];
  *n_real = n;
  *n_in_slot = in;
  return CHAPLYGIN_SUCCESS;
}

/* The system and the state: x - x is 0 for a finite x and NaN otherwise,
   so that one comparison tests every field (the step's hot path). */
static inline int
check_state (const chaplygin_discrete *sys, const chaplygin_discrete_state *s)
{
  const double zs = (sys->L0 - sys->L0) + (sys->Delta - sys->Delta);
  if (!(zs == 0.0 && sys->Delta > 0.0))
    return CHAPLYGIN_EDOM;
  if (s->dir != 1 && s->dir != -1)
    return CHAPLYGIN_EINVAL;
  const double zf = ((s->E - s->E) + (s->H - s->H))
    + ((s->theta - s->theta) + (s->tau - s->tau))
    + ((s->peg[0] - s->peg[0]) + (s->peg[1] - s->peg[1])) + (s->V - s->V);
  if (!(zf == 0.0))
    return CHAPLYGIN_EDOM;
  if (s->dir * s->V < 0.0)
    return CHAPLYGIN_ESTATE;            /* V+ against the direction */
  return CHAPLYGIN_SUCCESS;
}

/* check_state's test for the lean (E, H) entry: the system, dir, and the
   fields it only copies (theta, tau, peg); E and H are tested by
   eh_energy_ok and eh_outcome's range tests and V = 0 by the caller (a
   state that fails any takes step_core, whose check_state reports it);
   and the slot cap
   |l| <= CHP_L_MAX at both ends.  Conservative, and so one addition a
   field and one comparison for all of them: the sum z of the fields is
   finite only if every field is (and finite fields whose sum overflows
   get a false no; z - z is 0 for a finite z and NaN otherwise), and
   |l0| + |l1| <= CHP_L_MAX bounds each end; a false no takes the general
   route (step_core, or step_eh_n_rest), which tests each. */
static inline int
lean_state_ok (const chaplygin_discrete *sys,
               const chaplygin_discrete_state *s)
{
  const double z = ((sys->L0 + sys->Delta) + (s->theta + s->tau))
    + (s->peg[0] + s->peg[1]);
  const double ends = fabs (sys->l_end[0]) + fabs (sys->l_end[1]);
  return (z - z) + ends <= CHP_L_MAX && sys->Delta > 0.0
    && (s->dir == 1 || s->dir == -1);
}

/* The ODE route for one step: integrate (3.1) from the post-collision phase
   state to the slot end it leaves, then apply (3.6) and (3.3), (3.4).
   *drift: the relative change of h^2 = H^2/(2E) over the integrated segment
   (E and H are exact invariants of (3.1): the integration's own error in
   them, at the end the peg leaves). */
static int
step_ode (const chaplygin_discrete *sys, const chaplygin_discrete_state *in,
          const chp_motion *m, double l0, double g0, double tol, int *iminus,
          double *Vminus, double *E1, double *H1, double *dtheta,
          double *dtau, double *drift)
{
  double L0 = sys->L0, Delta = sys->Delta;
  double n0 = chp_one_plus_sq (l0);
  /* Omega0 = H/n0 below 2^-900 (near or in the subnormals): the route
     works with Omega and theta times 2^k, bringing Omega0 to about 2^-900
     (exact; (3.6) and (3.4) are linear in them), so that a tiny or
     subnormal H keeps its relative precision up to the final rounding of
     H' and dtheta (chp_ode_until scales further for its integration) */
  int k = 0;
  if (m->H != 0.0 && ilogb (m->H) - ilogb (n0) < -900)
    k = -900 - (ilogb (m->H) - ilogb (n0));
  double q0[4] = { in->dir > 0 ? 0.0 : Delta,
                   in->dir * sqrt (2.0 * m->E * (g0 / n0)), 0.0,
                   ldexp (m->H, k) / n0 };
  double q1[4], qp[4], t;
  int turned;
  CHP_TRY (chp_ode_until (L0, q0, k, 0.0, Delta, 0, tol, q1, &t, &turned));
  double Em, Hm, Hs = ldexp (m->H, k);
  CHP_TRY (chaplygin_discrete_energy (L0, q1[CHAPLYGIN_D], q1[CHAPLYGIN_V],
                                      ldexp (q1[CHAPLYGIN_OMEGA], -k), &Em));
  CHP_TRY (chaplygin_discrete_momentum (L0, q1[CHAPLYGIN_D],
                                        q1[CHAPLYGIN_OMEGA], &Hm));
  *drift = Hs != 0.0 && Em > 0.0
    ? fabs ((Hm / Hs) * (Hm / Hs) * (m->E / Em) - 1.0) : 0.0;
  /* the integrated state at the end the peg leaves is one the collision
     rule refuses (V- = 0 or V-^2 < 0 by the integration's error: a
     turning point within that error of the end): the integration cannot
     be trusted there, as when it reaches the wrong end */
  int st = chaplygin_discrete_collide (L0, Delta, q1, qp);
  if (st == CHAPLYGIN_ESTATE)
    return CHAPLYGIN_ENOCONV;
  CHP_TRY (st);
  CHP_TRY (chaplygin_discrete_energy (L0, qp[CHAPLYGIN_D], qp[CHAPLYGIN_V],
                                      ldexp (qp[CHAPLYGIN_OMEGA], -k), E1));
  CHP_TRY (chaplygin_discrete_momentum (L0, qp[CHAPLYGIN_D],
                                        qp[CHAPLYGIN_OMEGA], H1));
  *H1 = ldexp (*H1, -k);
  *iminus = q1[CHAPLYGIN_D] == Delta ? 1 : 0;
  *Vminus = q1[CHAPLYGIN_V];
  *dtheta = ldexp (q1[CHAPLYGIN_THETA], -k);
  *dtau = t;
  return CHAPLYGIN_SUCCESS;
}

/* The (E, H) update where the classification is certain from H^2 and
   2E (1 + l^2) rounded, without the frame of step_core: H' = C2 H with C2
   of the end the peg leaves, and E' by one of two routes.  Where the
   collision takes at most half the energy, |C1| H^2 <= E/2, E' = E + C1 H^2
   by one fma from C1 H, without a division or a square root: then
   E' >= E/2 and the fma loses nothing to cancellation (C1's few ulps weigh
   at most as much as E' itself: about 3 ulps in all, as the sum of
   nonnegative terms of step_core; the oracle measures it).  Where it takes
   more, E' is step_by_integrals' sum of nonnegative terms
   with the same g (bit for bit the general path's E'), unless g at the
   end the peg leaves is so small that the general path would raise E' by
   ulps (valid_energy).  The classification:
     H^2 <= E: 2E > H^2 (H*H rounded is at most E (1 + eps)), so no
       turning point exists and V+^2 >= E > 0: the motion reaches the far
       end (B.3);
     H^2 > E (then H^2 is normal: E >= 2^-900 is required): the start
       state must be valid with a margin, H^2 < 2E (1 + l0^2) (1 - m); a
       motion away from l = 0 (dir l0 > 0) reaches the far end; one
       towards it reverses iff H^2 > 2E (when the path reaches l = 0,
       l0, l1 not of one strict sign) or H^2 >= 2E (1 + l1^2) (when not),
       and the case applies only where H^2 is outside [1 - m, 1 + m] times
       that bound: the sign of the least V^2 is then certain, and the
       segment rule of motion.h decides as for the exact classification.
   m = 2^-40 exceeds by far the relative rounding errors of H*H, 1 + l^2
   (with l's own rounding, l_err) and their products (< 8 eps); an
   overflowed 2E (1 + l^2) is larger than any H^2 <= 2^1000, which the
   comparisons respect.  eh_outcome (the classification and H', E' but
   for the second route) and eh_fast (both routes) below; eh_fast returns
   0 where the case does not apply (the caller takes the general path,
   whose validation and classification cover everything excluded here;
   H' and the reversal flag may have been written), 1 with E', H' and the
   reversal flag written. */
#define EH_MARGIN 0x1p-40

/* eh_fast's E' for a collision at end K that takes more than half the
   energy: step_by_integrals' sum of nonnegative terms, with g at that end
   from E and H as there (the same bits), where it needs no raising
   (valid_energy: g > 2^-40 (1 + l^2)); 0 (the general path) otherwise.
   It makes no call where fma is an instruction (configure's -mfma;
   chp_g_exact and chp_post_collision_energy are inline), so that
   chaplygin_discrete_step_eh_n's loop makes none. */
static CHP_ALWAYS_INLINE int
eh_large (const chaplygin_discrete *sys, size_t k, double E, double H,
          double H1, double *E1)
{
  const double lm = sys->l_end[k];
  const double gm = chp_g_exact (E, H, lm, sys->l_err[k]);
  if (!(gm > 0x1p-40 * chp_one_plus_sq (lm)) || !isfinite (gm))
    return 0;
  *E1 = chp_post_collision_energy (E, gm, lm, H1, sys->l_end[k ^ 1]);
  return 1;
}

/* eh_outcome's outcomes: the step declined (the general path decides),
   made, or made but for E' of a collision that takes more than half the
   energy (eh_large's: the caller calls it, so that chaplygin_discrete_step's
   lean path calls it last and needs no frame) */
enum
{ EH_DECLINED = 0, EH_DONE = 1, EH_LARGE = 2 };

/* The index of the slot end the peg starts from: 0 (the front) for
   dir > 0, 1 for dir < 0. */
static inline size_t
start_end (int dir)
{
  return dir > 0 ? 0 : 1;
}

/* The slot end the peg leaves: the start on a reversal, the far end
   otherwise. */
static inline size_t
leaving_end (size_t start, int reversal)
{
  return reversal ? start : start ^ 1;
}

/* The bound on E that eh_outcome requires and the caller tests (once for
   a run of steps: each step made has E' <= E, since C1 <= 0 as
   chaplygin_discrete_init makes it and eh_large's E' is at most E). */
static inline int
eh_energy_ok (double E)
{
  return E <= 0.25 * DBL_MAX;
}

/* The (E, H) step from the end START (start_end) where its classification
   is certain from E and H with the margin EH_MARGIN, for E with
   eh_energy_ok: nothing written for EH_DECLINED; *H1 and *reversal for
   EH_LARGE; *H1, *reversal and *E1 for EH_DONE. */
static CHP_ALWAYS_INLINE int
eh_outcome (const chaplygin_discrete *sys, size_t start, double E, double H,
            double *E1, double *H1, int *reversal)
{
  /* |H| <= 2^500 iff H*H rounded is at most 2^1000 (rounding is monotonic
     and 2^1000 exact; the next double above 2^500 squares to
     2^1000 (1 + 2^-51) at least) */
  const double H2 = H * H;
  if (!(H2 <= 0x1p1000))
    return EH_DECLINED;
  /* H^2 <= E and E > 0 in one comparison (E >= the least subnormal iff
     E > 0); E = 0 and E < 0 fail the test E >= 2^-900 below */
  const double H2_or_tiny = H2 > 0x1p-1074 ? H2 : 0x1p-1074;
  /* the sign of the least V^2 on the segment, where it is certain: the
     input of the segment rule (motion.h); negative only moving towards
     l = 0 */
  double least = 1.0;
  if (!(H2_or_tiny <= E))
    {
      const double l0 = sys->l_end[start], l1 = sys->l_end[start ^ 1];
      const double twoE = 2.0 * E;
      if (!(E >= 0x1p-900
            && H2 < twoE * fma (l0, l0, 1.0) * (1.0 - EH_MARGIN)))
        return EH_DECLINED;
      /* dir l0 and dir l1 (exact): towards l = 0 iff dir l0 < 0, and
         then the path reaches l = 0 iff dir l1 >= 0 */
      const double d0 = start ? -l0 : l0, d1 = start ? -l1 : l1;
      if (d0 < 0.0)
        {
          /* V^2 least at l = 0 (2E - H^2) or at l1 */
          const double b = d1 >= 0.0 ? twoE : twoE * fma (l1, l1, 1.0);
          if (H2 > b * (1.0 + EH_MARGIN))
            least = -1.0;
          else if (!(H2 < b * (1.0 - EH_MARGIN)))
            return EH_DECLINED;
        }
      else if (!(d0 > 0.0))
        return EH_DECLINED;     /* from l = 0 exactly: the spinning test */
    }
  /* the rule's "crosses" decides only a least V^2 of 0, which the margin
     excludes */
  const int rev = chp_segment_rule (0, least) == CHP_SEGMENT_REVERSE;
  const size_t k = leaving_end (start, rev);
  const double c1h = sys->C1[k] * H;
  *H1 = sys->C2[k] * H;
  *reversal = rev;
  /* C1 <= 0 (-t^2/2 in chp_collision_coefficients), so C1 H^2 <= 0, and
     the collision takes at most half the energy iff C1 H^2 >= -E/2
     (-0.5 E is -(0.5 E) in the default rounding mode) */
  if (!(c1h * H >= -0.5 * E))
    return EH_LARGE;
  *E1 = fma (c1h, H, E);
  return EH_DONE;
}

/* eh_outcome with eh_large's E': 1 if the step is made, 0 if the general
   path must make it. */
static CHP_ALWAYS_INLINE int
eh_fast (const chaplygin_discrete *sys, size_t start, double E, double H,
         double *E1, double *H1, int *reversal)
{
  const int r = eh_outcome (sys, start, E, H, E1, H1, reversal);
  return r == EH_DONE
    || (r == EH_LARGE
        && eh_large (sys, leaving_end (start, *reversal), E, H, *H1, E1));
}

/* E1, raised by at most 8 ulps until the state (E1, H1) with the peg at
   end iplus has g(l+) > 0 (exactly, for the rounded E1 and H1); E1
   unchanged if that does not suffice or E1 is not finite. */
static double
valid_energy (const chaplygin_discrete *sys, int iplus, double E1, double H1)
{
  double E = E1;
  for (int k = 0; k <= 8 && isfinite (E); k++)
    {
      chp_motion m;
      if (chp_motion_init_eh (E, H1, &m) == CHAPLYGIN_SUCCESS
          && chp_motion_g_exact (&m, sys->l_end[iplus], sys->l_err[iplus])
          > 0.0)
        return E;
      E = nextafter (E, INFINITY);
    }
  return E1;
}

/* The new peg P' = P + shift (cos theta', sin theta'), shift = D- - D+'. */
static void
move_peg (const double peg[2], double shift, double theta1, double out[2])
{
  double sn, cs;
  sincos (theta1, &sn, &cs);
  out[0] = peg[0] + shift * cs;
  out[1] = peg[1] + shift * sn;
}

static int step_core (const chaplygin_discrete *sys,
                      const chaplygin_discrete_state *in,
                      unsigned request,
                      const chaplygin_options *opt,
                      chaplygin_discrete_state *out,
                      chaplygin_discrete_event *ev);

/* The map of a far slot (|l| > CHP_L_MAX, lib/far.c): the same step of the
   exactly scaled system and state, scaled back (E by 4^-m, H by
   2^(k-m-j), lengths by 2^k, times by 2^(k+m), V by 2^-m, the heading
   increment by 2^-j; dir, reversal unchanged); the peg moves by the
   unscaled slot length.  CHAPLYGIN_ERANGE where the scaled time is not
   a normal double (its digits would be lost). */
static int
step_far (const chaplygin_discrete *sys, const chaplygin_discrete_state *in,
          unsigned request, const chaplygin_options *opt,
          chaplygin_discrete_state *out, chaplygin_discrete_event *ev)
{
  chp_far f;
  chaplygin_discrete_state si, so;
  chaplygin_discrete_event se;
  CHP_TRY (chp_far_open_sys (sys, &f));
  CHP_TRY (chp_far_state_of (&f, in, 1, &si));
  si.tau = 0.0;
  si.theta = 0.0;
  unsigned req = request & (CHAPLYGIN_WANT_THETA | CHAPLYGIN_WANT_TAU);
  if (request & CHAPLYGIN_WANT_PEG)
    req |= CHAPLYGIN_WANT_THETA;
  CHP_TRY (step_core (&f.sys, &si, req, opt, &so, &se));
  if ((req & CHAPLYGIN_WANT_TAU) && !(se.dtau >= DBL_MIN))
    return CHAPLYGIN_ERANGE;
  chaplygin_discrete_state r = *in;
  r.dir = so.dir;
  r.E = chp_far_out (&f, CHP_Q_ENERGY, so.E);
  r.H = chp_far_out (&f, CHP_Q_MOMENTUM, so.H);
  const double dtau = chp_far_out (&f, CHP_Q_TIME, se.dtau);
  const double dtheta = chp_far_out (&f, CHP_Q_HEADING, se.dtheta);
  const double theta1 = in->theta + dtheta;
  if (request & CHAPLYGIN_WANT_THETA)
    r.theta = theta1;
  if (request & CHAPLYGIN_WANT_TAU)
    r.tau = in->tau + dtau;
  const double Dminus = se.Dminus == 0.0 ? 0.0 : sys->Delta;
  if (request & CHAPLYGIN_WANT_PEG)
    move_peg (in->peg, Dminus != 0.0 ? sys->Delta : -sys->Delta, theta1,
              r.peg);
  const double Vminus = chp_far_out (&f, CHP_Q_SPEED, se.Vminus);
  r.V = so.V != 0.0 ? Vminus : 0.0;
  const double Dc = se.reversal ? chp_far_out (&f, CHP_Q_LENGTH, se.Dc) : 0.0;
  if (!chp_finite4 (r.E, r.H, r.theta, r.tau)
      || !chp_finite4 (r.peg[0], r.peg[1], dtau, Dc))
    return CHAPLYGIN_ERANGE;
  if (ev)
    {
      ev->reversal = se.reversal;
      ev->Dc = Dc;
      ev->Dminus = Dminus;
      ev->Dplus = sys->Delta - Dminus;
      ev->Vminus = Vminus;
      ev->dtheta = dtheta;
      ev->dtau = dtau;
    }
  *out = r;
  return CHAPLYGIN_SUCCESS;
}

/* The work of one step of the return map, filled phase by phase by
   step_core. */
typedef struct
{
  const chaplygin_discrete *sys;
  const chaplygin_discrete_state *in;
  chaplygin_options o;
  unsigned request;
  chp_segment seg;
  chp_motion m;
  double g0, g1;        /* g = (1 + l^2) V^2/(2E) at the two ends */
  int have_g1;          /* g1 formed (step_g1: only where needed) */
  /* The motion's own g at the ends, for the integrals and V-: g0 and g1,
     or from the state's V+ where it is known (v_known: in->V != 0), which
     keeps the digits E and H lose in a slow start, and where it is the
     more accurate decides the classification (step_classify).  The (E, H)
     update uses g0, g1 alone: E' and H' depend on whether V+ is known
     only through the end the peg leaves, where the phase state decides it
     otherwise than E and H (within their rounding of a boundary). */
  int v_known;
  double gv0, gv1;
  int have_gv1;
  int fast;             /* E1, H1 (and reversal) from eh_fast */
  int want_event;       /* the caller asked for the event (V- in it) */
  int reversal;
  int iminus;           /* the end the peg leaves: 0 front, 1 rear */
  double E1, H1, Vminus, dtheta, dtau;
} step_work;

/* Phase 1: the arguments, the options (NULL: the defaults), the state;
   peg implies theta. */
static int
step_begin (step_work *w, const chaplygin_discrete *sys,
            const chaplygin_discrete_state *in, unsigned request,
            const chaplygin_options *opt, const chaplygin_discrete_state *out)
{
  if (!sys || !in || !out || (request & ~(unsigned) CHAPLYGIN_WANT_ALL))
    return CHAPLYGIN_EINVAL;
  if (opt)
    CHP_TRY (chp_options_resolve (opt, &w->o));
  else
    w->o = (chaplygin_options) CHAPLYGIN_OPTIONS_DEFAULT;
  CHP_TRY (check_state (sys, in));
  w->sys = sys;
  w->in = in;
  w->request = request & CHAPLYGIN_WANT_PEG ? request | CHAPLYGIN_WANT_THETA
    : request;
  w->fast = 0;
  w->want_event = 0;
  w->have_g1 = 0;
  w->have_gv1 = 0;
  w->v_known = 0;
  w->E1 = w->H1 = w->Vminus = w->dtheta = w->dtau = 0.0;
  return CHAPLYGIN_SUCCESS;
}

/* g at the far end from g at the start of a phase state: g0 + (l1 -
   l0)(l1 + l0), l1 - l0 = dir Delta exactly, unless that cancels worse
   than E and H (rounded from the phase state) are conditioned there; then
   from E and H by error-free arithmetic. */
static double
g_far_from_start (const step_work *w, double g0)
{
  const chaplygin_discrete *sys = w->sys;
  const chp_segment *seg = &w->seg;
  const double delta = w->in->dir * sys->Delta * (2.0 * sys->L0 + sys->Delta);
  return g0 + fabs (delta)
    <= chp_one_plus_sq (seg->l1) + fabs (1.0 - w->m.one_minus_h2)
    ? g0 + delta : chp_motion_g_exact (&w->m, seg->l1, seg->l1_err);
}

/* g at the far end from (E, H) by error-free arithmetic, exact for them,
   formed once when first needed. */
static const double *
step_g1 (step_work *w)
{
  if (!w->have_g1)
    {
      const chp_segment *seg = &w->seg;
      w->g1 = chp_motion_g_exact (&w->m, seg->l1, seg->l1_err);
      w->have_g1 = 1;
    }
  return &w->g1;
}

/* The motion's g at the far end (see step_work), formed once. */
static const double *
step_gv1 (step_work *w)
{
  if (!w->v_known)
    return step_g1 (w);
  if (!w->have_gv1)
    {
      w->gv1 = g_far_from_start (w, w->gv0);
      w->have_gv1 = 1;
    }
  return &w->gv1;
}

/* The scale of the terms of g(l) = l^2 + 1 - h^2 from E and H: the
   rounding of E and H moves g by a few ulps of it. */
static double
g_scale (const step_work *w, double l)
{
  return chp_one_plus_sq (l) + fabs (1.0 - w->m.one_minus_h2);
}

/* g at the start from the state's V+: (1 + l0^2) V+^2/(2E), with V+'s
   own digits.  CHAPLYGIN_ESTATE where it is not this state's V+: it
   differs from g from E and H by more than 2^-20 of g_scale (E, H and V+
   carried along a run agree to a few ulps a collision, so far below that
   after any run; a V+ left from another state does not).  It may
   underflow to 0 (V+ below ~1e-154 sqrt(2E)): a start at rest along the
   slot to within 2^-1000. */
static int
step_g0_from_V (const step_work *w, double *gv0)
{
  const double V = w->in->V, l0 = w->seg.l0, n0 = chp_one_plus_sq (l0);
  const double gv = n0 * (V * (V / (2.0 * w->in->E)));
  if (!(fabs (gv - w->g0) <= 0x1p-20 * g_scale (w, l0)))
    return CHAPLYGIN_ESTATE;
  *gv0 = gv;
  return CHAPLYGIN_SUCCESS;
}

/* Nonzero where g at the far end from V+ (g_far_from_start) is the more
   accurate: its terms g0 and |l0^2 - l1^2| below E and H's h^2. */
static int
gv_far_better (const step_work *w)
{
  const chaplygin_discrete *sys = w->sys;
  const double delta = sys->Delta * fabs (2.0 * sys->L0 + sys->Delta);
  return w->gv0 + delta < 1.0 - w->m.one_minus_h2;
}

/* Phase 3: the motion and its exact classification.  The classification
   and the (E, H) update need only E, H and 1 - h^2 (and g0 from V+ where
   the state knows it: from (E, H) alone g(l0) loses V+ when V+^2 << (1 +
   l0^2) Omega+^2): the square roots the integrals need are taken only
   for them. */
static int
step_classify (step_work *w)
{
  const chp_segment *seg = &w->seg;
  CHP_TRY (chp_motion_init_eh (w->in->E, w->in->H, &w->m));
  const int complete = (w->request & (CHAPLYGIN_WANT_THETA
                                      | CHAPLYGIN_WANT_TAU))
    || w->o.method == CHAPLYGIN_ODE;
  if (complete)
    chp_motion_complete (&w->m);
  /* g at the start: with error-free arithmetic from (E, H), accurate for
     them even when V+ is small beside Omega+, or as given from V+ */
  w->g0 = chp_motion_g_exact (&w->m, seg->l0, seg->l0_err);
  w->gv0 = w->g0;
  w->v_known = w->in->V != 0.0;
  if (w->v_known)
    CHP_TRY (step_g0_from_V (w, &w->gv0));
  /* a motion: V+^2 > 0 (E and H may hold a slow V+ as 0 or below: a
     known V+ decides, and may underflow g) */
  if (!(w->gv0 > 0.0) && !(w->v_known && w->gv0 == 0.0))
    return CHAPLYGIN_ESTATE;
  /* a known V+: 1 - h^2 = g0 - l0^2 from it, whose absolute error (the
     roundings of V+^2/(2E), of E itself and of l0^2) is below 2^-50 (g0 +
     l0^2), against E and H's few eps h^2 (their own roundings, through
     H^2/(2E)).  V+'s is taken where it is the more accurate (g0 + l0^2 <
     h^2), and decides where it is beyond its error: near l = 0 (g0 + l0^2
     ~ 2 l0^2 << h^2 ~ 1), where E and H hold neither the sign of 1 - h^2
     ~ -l0^2 (a slow start within their rounding of the boundary between
     turning and passing) nor the turning point c = sqrt(h^2 - 1).  Far
     from l = 0 with 2E near H^2, E and H's (g0 - l0^2 cancels there: c,
     and D_c from the rear end, came out 290 ulps off from V+ in one
     measured state).  Within the error of the better one the state does
     not determine the outcome: E and H's sign decides (a state within
     rounding of the spinning state (3.8) spins where 2E = H^2, as for the
     fates), and V+'s value is kept where the signs agree. */
  int v_decides = 0;
  if (w->v_known)
    {
      const double l0sq = chp_sq_exact (seg->l0, seg->l0_err);
      const double omh2 = w->gv0 - l0sq;
      const int v_better = w->gv0 + l0sq < 1.0 - w->m.one_minus_h2;
      v_decides = v_better && fabs (omh2) > 0x1p-50 * (w->gv0 + l0sq);
      if (v_better && omh2 != 0.0
          && (v_decides || (omh2 < 0.0) == (w->m.one_minus_h2 < 0.0)))
        {
          if (complete)                 /* and the fields derived from it */
            chp_motion_set_one_minus_h2 (&w->m, omh2);
          else
            w->m.one_minus_h2 = omh2;
        }
    }
  /* g at the far end matters to the classification only for a motion
     towards l = 0 with turning points that does not cross it: from the
     state that decides, or from V+ where that is the more accurate there:
     g1 = g0 - |l0^2 - l1^2| from V+ is off by a few ulps of g0 + |l0^2 -
     l1^2|, from E and H by a few ulps of h^2 (l1^2 + 1 - h^2 cancels:
     V+ = -1, Omega+ = 1 at L0 = 10^40 has g0 = 1, h^2 = 10^80, and E and
     H's g1 of +-10^64 missed the turning point 1/(2 L0) from the start) */
  const double *g_far = NULL;
  if (!seg->crosses && seg->toward && w->m.one_minus_h2 < 0.0)
    g_far = v_decides || (w->v_known && gv_far_better (w))
      ? step_gv1 (w) : step_g1 (w);
  const int outcome = chp_segment_classify (seg, &w->m, g_far);
  if (outcome == CHP_SEGMENT_SPIN)
    return CHAPLYGIN_ESPIN;
  w->reversal = outcome == CHP_SEGMENT_REVERSE;
  w->iminus = w->reversal ? seg->start : seg->far;
  return CHAPLYGIN_SUCCESS;
}

/* A reversal within a hair of the start (the known V+ so slow that g0 <=
   2^-60 l0^2, down to V+ = DBL_MIN where g0 underflows): the motion to
   the turning point is uniformly decelerated to relative O(g0/l0^2),
   below 2^-60 (the s^2 of g and the change of 1 + l^2 over the
   distance s_c = g0/(2 |l0|) to it: g0/(4 l0^2) and g0/n0 <= g0/l0^2):
   with V^2 = (2E/n0)(g0 - 2 |l0| s) to that order, s =
   |l0| - |l| (n0 = 1 + l0^2), the time out and back is
   2 sqrt(n0/(2E)) sqrt(g0)/|l0| = n0 |V+|/(E |l0|) and the heading
   Omega+ times it, Omega+ = H/n0.  Every method takes it: an integration
   over that distance does not resolve it (the ODE method was 3e-10
   relative off at |V+|/|l0 Omega+| = 1e-12, and returned |V-| ~ 4e-34
   whatever V+ below ~1e-33). */
static int
turns_at_start (const step_work *w)
{
  return w->reversal && w->v_known
    && w->gv0 <= 0x1p-60 * w->seg.l0 * w->seg.l0;
}

static int
step_turn_at_start (step_work *w)
{
  const double l0 = fabs (w->seg.l0), E = w->in->E;
  const double n0 = chp_one_plus_sq (l0), V = fabs (w->in->V);
  /* V/(E l0) on V 2^k ~ E (exact), so that no intermediate leaves the
     normal doubles; each result rounds once more at the end */
  const int k = ilogb (E) - ilogb (V);
  const double r = (ldexp (V, k) / E) / l0;
  w->dtau = ldexp (n0 * r, -k);
  w->dtheta = ldexp (w->in->H * r, -k);
  return CHAPLYGIN_SUCCESS;
}

/* Phase 4, closed form and quadrature: the (E, H) update of (3.7) (unless
   eh_fast made it), V- for the event, and the heading and time of the
   legs by chp_leg. */
static int
step_by_integrals (step_work *w)
{
  const chaplygin_discrete *sys = w->sys;
  const chaplygin_discrete_state *in = w->in;
  const chp_segment *seg = &w->seg;
  const double lm = w->reversal ? seg->l0 : seg->l1;
  if (!w->fast)
    {
      const double gm = w->reversal ? w->g0 : *step_g1 (w);
      w->H1 = sys->C2[w->iminus] * in->H;
      /* E + C1 H^2 of (3.7), as a sum of nonnegative terms (accurate also
         when the collision takes nearly all the energy) */
      w->E1 = chp_post_collision_energy (in->E, gm, lm, w->H1,
                                         sys->l_end[1 - w->iminus]);
      /* V- nearly 0 (a turning point within rounding of the end): E1 may
         round below H1^2/(2 (1 + l+^2)), which would make the output an
         invalid state (V+'^2 < 0); the true E' is above it, so raise E1
         by ulps (at most 8, within its error bound) until the output is
         valid */
      if (gm <= 0x1p-40 * chp_one_plus_sq (lm))
        w->E1 = valid_energy (sys, 1 - w->iminus, w->E1, w->H1);
    }
  /* V- = +-sqrt(2E g/(1 + l^2)) from the motion's g, with the sign of the
     new direction; a reversal returns with -V+ exactly where V+ is known;
     only for the event or the state's V+' (never infinite: 2E is finite,
     chp_motion_init_eh, and g/(1 + l^2) <= 1) */
  if (w->reversal && w->v_known)
    w->Vminus = -in->V;
  else if (w->want_event || w->v_known)
    {
      /* on a pass that E and H decided (g1 > 0) while g from V+ rounds
         to 0 or below at that end (a turning point within rounding of
         it), E and H's g */
      double gvm = w->reversal ? w->gv0 : *step_gv1 (w);
      if (!w->reversal && !(gvm > 0.0))
        gvm = chp_max (*step_g1 (w), 0.0);
      w->Vminus = (w->reversal ? -in->dir : in->dir)
        * sqrt (2.0 * in->E * (gvm / chp_one_plus_sq (lm)));
    }
  const int want_theta = (w->request & CHAPLYGIN_WANT_THETA) != 0;
  const int want_tau = (w->request & CHAPLYGIN_WANT_TAU) != 0;
  if (!want_theta && !want_tau)
    return CHAPLYGIN_SUCCESS;
  double *pth = want_theta ? &w->dtheta : NULL;
  double *pta = want_tau ? &w->dtau : NULL;
  if (!w->reversal)
    {
      /* g at the ends matters to the legs only with turning points */
      const double g1 = w->m.one_minus_h2 < 0.0 ? *step_gv1 (w) : 0.0;
      return chp_leg (&w->m, seg->l0, w->gv0, seg->l1, g1, sys->Delta, &w->o,
                      pth, pta);
    }
  if (turns_at_start (w))
    return step_turn_at_start (w);
  /* Out to the turning point and back: twice one leg.  |l0| - c =
     g0/(|l0| + c) without cancellation. */
  const double c = w->m.sqrt_q, lc = copysign (c, seg->l0);
  const double dl = w->gv0 / (fabs (seg->l0) + c);
  CHP_TRY (chp_leg (&w->m, seg->l0, w->gv0, lc, 0.0, dl, &w->o, pth, pta));
  w->dtheta *= 2.0;
  w->dtau *= 2.0;
  return CHAPLYGIN_SUCCESS;
}

/* Phase 4, ODE: every output from the integration (step_ode); where the
   end it reaches contradicts the exact classification, the motion passes
   within the integration error of a turning point or of the spinning
   state and the integration cannot be trusted.  So too, on a segment
   through l = 0, where the integration's own drift of h^2 (step_ode)
   reaches the distance |1 - h^2| to the spinning state (3.8): it may then
   have passed where the motion turns or turned where it passes, and it
   resolves neither that nor the time, which grows like
   log(1/|1 - h^2|). */
static int
step_by_ode (step_work *w)
{
  int iminus;
  double drift;
  CHP_TRY (step_ode (w->sys, w->in, &w->m, w->seg.l0, w->gv0, w->o.tol,
                     &iminus, &w->Vminus, &w->E1, &w->H1, &w->dtheta,
                     &w->dtau, &drift));
  if ((iminus == w->seg.start) != w->reversal
      || (w->seg.crosses && drift >= fabs (w->m.one_minus_h2)))
    return CHAPLYGIN_ENOCONV;
  w->iminus = iminus;
  return CHAPLYGIN_SUCCESS;
}

/* D_c of a reversal (B.5), in the form without cancellation: from the
   start, D+ + dir (|l0| - c) with |l0| - c = g0/(|l0| + c) (g0 =
   l0^2 - c^2), c = sqrt(h^2 - 1), relative to its distance from the
   start however close (sgn(l0) c - L0 lost it: D_c = 0 for a true
   3e-19); from the rear end (D+ = Delta) that sum cancels where D_c <<
   Delta, so there sgn(l0) c - L0 where its terms are the smaller
   (27 ulps of D_c = 783 at Delta = 13687 otherwise). */
static double
step_turning_point (const step_work *w)
{
  const double c = sqrt (-w->m.one_minus_h2), l0 = fabs (w->seg.l0);
  const double dl = w->gv0 / (l0 + c), L0 = w->sys->L0;
  if (w->in->dir > 0)
    return dl;
  const double Delta = w->sys->Delta;
  return Delta + dl <= c + fabs (L0) ? Delta - dl
    : copysign (c, w->seg.l0) - L0;
}

/* Phase 5: the state after the collision and the event.  The direction
   after the collision is that of V-: the same as before without a
   reversal, the opposite with one (by the classification, not by the sign
   of a computed V-, which may be 0). */
static int
step_finish (step_work *w, chaplygin_discrete_state *out,
             chaplygin_discrete_event *ev)
{
  const chaplygin_discrete_state *in = w->in;
  const double Delta = w->sys->Delta;
  if (!isfinite (w->E1) || !isfinite (w->H1) || !isfinite (w->Vminus))
    return CHAPLYGIN_ERANGE;
  const double Dminus = w->iminus ? Delta : 0.0;
  const double theta1 = in->theta + w->dtheta;
  chaplygin_discrete_state r = *in;
  r.dir = w->reversal ? -in->dir : in->dir;
  r.E = w->E1;
  r.H = w->H1;
  /* V+' = V- ((3.6) keeps V), carried while E' and H' would not hold it:
     g at the collision from E and H below a quarter of its scale (then
     their roundings cost V-^2 more than 4 ulps); dropped otherwise, so
     that carried and (E, H) values cannot drift apart over a run, and the
     next step may take the (E, H) fast path */
  r.V = 0.0;
  if (w->v_known)
    {
      const double lm = w->reversal ? w->seg.l0 : w->seg.l1;
      const double gm = w->reversal ? w->g0 : *step_g1 (w);
      if (gm < 0.25 * g_scale (w, lm))
        r.V = w->Vminus;
    }
  if (w->request & CHAPLYGIN_WANT_THETA)
    r.theta = theta1;
  if (w->request & CHAPLYGIN_WANT_TAU)
    r.tau = in->tau + w->dtau;
  if (w->request & CHAPLYGIN_WANT_PEG)
    move_peg (in->peg, w->iminus ? Delta : -Delta, theta1, r.peg);
  if (!chp_finite4 (r.theta, r.tau, r.peg[0], r.peg[1])
      || !isfinite (w->dtheta) || !isfinite (w->dtau))
    return CHAPLYGIN_ERANGE;
  if (ev)
    {
      ev->reversal = w->reversal;
      ev->Dc = w->reversal ? step_turning_point (w) : 0.0;
      ev->Dminus = Dminus;
      ev->Dplus = Delta - Dminus;
      ev->Vminus = w->Vminus;
      ev->dtheta = w->dtheta;
      ev->dtau = w->dtau;
    }
  *out = r;
  return CHAPLYGIN_SUCCESS;
}

/* The return map proper, in phases: (1) arguments, (2) a far slot
   (step_far), (3) the (E, H) update of the common case (eh_fast), kept
   whatever else is requested, so that E and H never depend on it (E and
   H alone end in chaplygin_discrete_step's lean entry or in
   chaplygin_discrete_step_eh_n, never here), (4) the motion and its exact
   classification, (5) the route of opt->method, (6) the outputs. */
static int
step_core (const chaplygin_discrete *sys, const chaplygin_discrete_state *in,
           unsigned request,
           const chaplygin_options *opt, chaplygin_discrete_state *out,
           chaplygin_discrete_event *ev)
{
  step_work w;
  CHP_TRY (step_begin (&w, sys, in, request, opt, out));
  w.want_event = ev != NULL;
  if (chp_system_far (sys))
    return step_far (sys, in, w.request, opt, out, ev);
  int fast_reversal = 0;
  w.fast = w.o.method != CHAPLYGIN_ODE && eh_energy_ok (in->E)
    && eh_fast (sys, start_end (in->dir), in->E, in->H, &w.E1, &w.H1,
                &fast_reversal);
  chp_segment_init (sys, in->dir, &w.seg);
  CHP_TRY (step_classify (&w));
  /* a known V+ may decide otherwise than E and H within 2^-20 of their
     scale (step_g0_from_V): eh_fast's margin 2^-40 is theirs */
  if (w.fast && fast_reversal != w.reversal)
    w.fast = 0;
  /* a reversal within 2^-60 l0^2 of the start: its closed form, exact to
     that order, also for the ODE method (no integration resolves it) */
  if (w.o.method == CHAPLYGIN_ODE && !turns_at_start (&w))
    CHP_TRY (step_by_ode (&w));
  else
    CHP_TRY (step_by_integrals (&w));
  return step_finish (&w, out, ev);
}

/* step_core from an (E, H) state: chaplygin_discrete_step's slow path,
   kept out of line so that its fast path needs no frame. */
static int __attribute__ ((noinline))
step_general (const chaplygin_discrete *sys,
              const chaplygin_discrete_state *in, unsigned request,
              const chaplygin_options *opt, chaplygin_discrete_state *out,
              chaplygin_discrete_event *ev)
{
#if HAVE_ARB
  /* exact decisions and balls (certified.c); tol and precision unused
     (a precision of neither kind is refused, as for the others) */
  if (opt && opt->method == CHAPLYGIN_CERTIFIED)
    return opt->precision == CHAPLYGIN_PREC_DOUBLE
      || opt->precision == CHAPLYGIN_PREC_SINGLE
      ? chp_certified_step (sys, in, request, out, ev) : CHAPLYGIN_EINVAL;
#endif
  return step_core (sys, in, request, opt, out, ev);
}

/* The lean path's output: *in with the new dir, E and H (V+ unknown). */
static inline int
lean_output (const chaplygin_discrete_state *in, int rev, double E1,
             double H1, chaplygin_discrete_state *out)
{
  const int dir = rev ? -in->dir : in->dir;
  if (out != in)
    *out = *in;
  out->dir = dir;
  out->E = E1;
  out->H = H1;
  out->V = 0.0;
  return CHAPLYGIN_SUCCESS;
}

/* chaplygin_discrete_step's lean path for a collision that takes more than
   half the energy (eh_outcome: EH_LARGE, reversal REV, H' = H1): E' by
   eh_large, or the general path.  Out of line and called last, so that
   the lean path makes no call that needs a frame. */
static int __attribute__ ((noinline))
step_lean_large (const chaplygin_discrete *sys,
                 const chaplygin_discrete_state *in, int rev, double H1,
                 const chaplygin_options *opt, chaplygin_discrete_state *out)
{
  double E1;
  if (!eh_large (sys, leaving_end (start_end (in->dir), rev), in->E, in->H,
                 H1, &E1))
    return step_general (sys, in, 0, opt, out, NULL);
  return lean_output (in, rev, E1, H1, out);
}

/* chaplygin_discrete_step: (B.3) and (B.4), the return map on post-collision
   states p = {D+, E, theta, H} (D+ carried as dir):
     (B.3) no reversal:  D+' = D+, E' = E + C1 H^2, H' = C2 H,
           theta' = theta + sgn(Omega) |Int_{D+}^{Delta - D+} dD/sqrt(Q(D))|,
     (B.4) reversal:     D+' = Delta - D+, E', H' likewise (other C1, C2),
           theta' = theta + 2 sgn(Omega) |Int_{D+}^{D_c} dD/sqrt(Q(D))|,
   Q(D) = (1 + (L0 + D)^2) [2E (1 + (L0 + D)^2)/H^2 - 1]; also the elapsed
   time (twice the time to D_c on reversal) and the new peg position
   P' = P + (D- - D+')(cos theta', sin theta').
   Method: the motion is classified exactly (the sign of 2E - H^2 is exact,
   V^2 at the far end is 2E g(l)/(1 + l^2) with g from one fma):
     2E > H^2, or moving away from l = 0: no turning point is met;
     2E < H^2 and moving towards l = 0: a reversal iff the path reaches
       |l| = c = sqrt(h^2 - 1) (g(far end) <= 0 or the far end beyond 0).
   A turning point exactly at the far end counts as a reversal (the peg
   touches the end with zero speed and does not leave it).  E and H are
   updated by the (3.7) coefficients of the end the peg leaves: where the
   classification is certain from H^2 and 2E (1 + l^2) with a relative
   margin of 2^-40 and the collision takes at most half the energy
   (eh_fast) as E + C1 H^2 by one fma, without a division; elsewhere as
   the sum of
   nonnegative terms V-^2/2 + H'^2/(2 (1 + l+^2)); the same way whatever
   else is requested, so E and H never depend on REQUEST.  Heading and
   time by opt->method (closed form, quadrature: chp_leg; ODE: (3.1)
   integrated to the collision, then (3.6), (3.3), (3.4): every output of
   that route comes from the integration, and an integration that reaches
   the other end than the exact classification says is reported as
   CHAPLYGIN_ENOCONV).  Only what REQUEST asks for is
   computed (E, H, dir always).
   Representation: E and H hold V+ only to absolute precision
   ~eps sqrt(2E): when V+^2 << (1 + l0^2) Omega+^2 the map from (E, H)
   alone is ill-conditioned in V+.  The state's V (V+ where known) removes
   that: the classification, the heading, time and V- from it
   (step_g0_from_V: a slow start near l = 0 turns or passes as the phase
   state does, which E and H may not tell), E' and H' from E and H at the
   end it decides; V+' passed on while E' and H' would not hold it
   (step_finish).
   Domain: a valid system; in->dir = +-1; finite fields; E > 0 and
   V+^2 = 2E - H^2/(1 + l0^2) > 0 (or V+ known); |L0|, |L0 + Delta| <=
   2^500.
   Errors: CHAPLYGIN_EINVAL (NULL, dir, request bits, options),
   CHAPLYGIN_EDOM (non-finite, E < 0), CHAPLYGIN_ESTATE (E = 0, V+^2 <= 0),
   CHAPLYGIN_ESPIN (2E = H^2 and the path reaches l = 0: no next
   collision), CHAPLYGIN_ERANGE (|L0 + D| above 2^500, overflow),
   CHAPLYGIN_ENOCONV. */
int
chaplygin_discrete_step (const chaplygin_discrete *sys,
                         const chaplygin_discrete_state *in,
                         unsigned request, const chaplygin_options *opt,
                         chaplygin_discrete_state *out,
                         chaplygin_discrete_event *ev)
{
  /* E and H only, options that do not integrate (E and H do not depend
     on the method otherwise), the common case: the same validation and
     eh_fast as step_core, without its frame and, but for eh_large's
     collisions (step_lean_large, called last), without a call (a third
     of the cost of such a step); anything else goes through step_core */
  if (request == 0 && !ev && sys && in && out && in->V == 0.0
      /* options that do not integrate, the closed form's tested first
         (the common case: two instructions fewer) */
      && (!opt || (opt->method == CHAPLYGIN_CLOSED_FORM
                   ? chp_options_valid (opt)
                   : opt->method != CHAPLYGIN_ODE && chp_options_valid (opt)))
      && lean_state_ok (sys, in) && eh_energy_ok (in->E))
    {
      double E1, H1;
      int rev;
      const int r = eh_outcome (sys, start_end (in->dir), in->E, in->H,
                               &E1, &H1, &rev);
      if (r == EH_DONE)
        return lean_output (in, rev, E1, H1, out);
      if (r == EH_LARGE)
        return step_lean_large (sys, in, rev, H1, opt, out);
    }
  return step_general (sys, in, request, opt, out, ev);
}

/* eh_fast's steps I .. N - 1 of (dir, E, H), in place, while it takes
   them (for a system from chaplygin_discrete_init its outputs are
   finite and E' <= E: the state stays valid for it): the index of the
   first step it declines, N if none. */
static CHP_ALWAYS_INLINE unsigned long
eh_run (const chaplygin_discrete *sys, int *dir, double *E, double *H,
        unsigned long i, unsigned long n)
{
  if (!eh_energy_ok (*E))
    return i;
  size_t start = start_end (*dir);
  for (; i < n; i++)
    {
      double E1, H1;
      int rev;
      if (!eh_fast (sys, start, *E, *H, &E1, &H1, &rev))
        break;
      start ^= (size_t) rev;
      *E = E1;
      *H = H1;
    }
  *dir = start ? -1 : 1;
  return i;
}

/* chaplygin_discrete_step_eh_n's steps I .. N - 1 from *st, the first I
   made (by eh_fast): eh_fast where it applies, step_core where not. */
static int __attribute__ ((noinline))
step_eh_n_rest (const chaplygin_discrete *sys, chaplygin_discrete_state *st,
                unsigned long n, unsigned long i, unsigned long *done)
{
  /* after I > 0 steps the caller's lean_state_ok passed and eh_fast made
     E and H; else, with n > 0, what lean_state_ok does not test is tested
     by the first step (eh_fast, or step_core's check_state) */
  int status = i > 0 || (n > 0 && lean_state_ok (sys, st))
    ? CHAPLYGIN_SUCCESS : check_state (sys, st);
  /* not !chp_system_far: NaN ends are not within the cap here (as for
     lean_state_ok), so that eh_fast never steps them */
  const int in_cap = fabs (sys->l_end[0]) <= CHP_L_MAX
    && fabs (sys->l_end[1]) <= CHP_L_MAX;
  /* the state in registers: dir, E, H, V (V = 0 on the fast path),
     written back to *st for step_core (which updates *st only when it
     succeeds) and at the end */
  int dir = st->dir;
  double E = st->E, H = st->H, V = st->V;
  while (status == CHAPLYGIN_SUCCESS && i < n)
    {
      if (in_cap && V == 0.0)
        {
          const unsigned long i0 = i;
          i = eh_run (sys, &dir, &E, &H, i, n);
          if (i > i0)
            V = 0.0;            /* as the lean step writes it: +0 */
        }
      if (i == n)
        break;
      /* a step eh_fast declines */
      st->dir = dir;
      st->E = E;
      st->H = H;
      st->V = V;
      status = step_core (sys, st, 0, NULL, st, NULL);
      dir = st->dir;
      E = st->E;
      H = st->H;
      V = st->V;
      i += status == CHAPLYGIN_SUCCESS;
    }
  st->dir = dir;
  st->E = E;
  st->H = H;
  st->V = V;
  if (done)
    *done = i;
  return status;
}

/* chaplygin_discrete_step_eh_n: (B.3)/(B.4), n steps of the return map
   for E and H only (default options), in place: the same as n calls of
   chaplygin_discrete_step (sys, st, 0, NULL, st, NULL), bit for bit, with
   the system validated once and the state kept in registers between
   collisions.  *done (may be NULL) receives the number of steps made; on
   a failure *st is the state after the last successful step and the
   status is that step's.  n = 0 validates and returns.
   Method: eh_fast's steps in a loop that makes no call where fma is an
   instruction (and so sets up no frame), while it takes every step (as
   along the scenes' orbits); step_eh_n_rest from the first step it
   declines.
   Errors: CHAPLYGIN_EINVAL (NULL sys or st), and those of
   chaplygin_discrete_step. */
int
chaplygin_discrete_step_eh_n (const chaplygin_discrete *sys,
                              chaplygin_discrete_state *st, unsigned long n,
                              unsigned long *done)
{
  if (!sys || !st)
    return CHAPLYGIN_EINVAL;
  unsigned long i = 0;
  /* as chaplygin_discrete_step's lean path (a false no of lean_state_ok
     means step_eh_n_rest, which tests each field and end) */
  if (n > 0 && st->V == 0.0 && lean_state_ok (sys, st))
    {
      int dir = st->dir;
      double E = st->E, H = st->H;
      i = eh_run (sys, &dir, &E, &H, 0, n);
      st->dir = dir;
      st->E = E;
      st->H = H;
      if (i > 0)
        st->V = 0.0;            /* as the lean step writes it: +0 */
      if (i == n)
        {
          if (done)
            *done = n;
          return CHAPLYGIN_SUCCESS;
        }
    }
  return step_eh_n_rest (sys, st, n, i, done);
}

/* chaplygin_discrete_state_from_phase: {D+, V+, theta+, Omega+} -> map
   state: dir = sgn V+, E by (3.3), H by (3.4), and V+ itself.  D+ must be 0 for V+ > 0
   and Delta for V+ < 0 exactly.  Errors: CHAPLYGIN_EINVAL (NULL),
   CHAPLYGIN_EDOM, CHAPLYGIN_ESTATE (V+ = 0 or D+ not the matching end). */
int
chaplygin_discrete_state_from_phase (const chaplygin_discrete *sys,
                                     const double q[4], double tau,
                                     const double peg[2],
                                     chaplygin_discrete_state *st)
{
  if (!sys || !q || !st)
    return CHAPLYGIN_EINVAL;
  if (!chp_finite4 (q[0], q[1], q[2], q[3]) || !isfinite (tau)
      || (peg && !chp_finite2 (peg[0], peg[1])))
    return CHAPLYGIN_EDOM;
  double V = q[CHAPLYGIN_V], D = q[CHAPLYGIN_D];
  if (V == 0.0 || (V > 0.0 && D != 0.0) || (V < 0.0 && D != sys->Delta))
    return CHAPLYGIN_ESTATE;
  chaplygin_discrete_state s;
  s.dir = V > 0.0 ? 1 : -1;
  CHP_TRY (chaplygin_discrete_energy (sys->L0, D, V, q[CHAPLYGIN_OMEGA],
                                      &s.E));
  CHP_TRY (chaplygin_discrete_momentum (sys->L0, D, q[CHAPLYGIN_OMEGA],
                                        &s.H));
  if (!(s.E >= DBL_MIN))
    return CHAPLYGIN_ERANGE;    /* E below the normal doubles: the state
                                   cannot hold this motion (its phase
                                   state can: chaplygin_discrete_poincare
                                   scales the speed) */
  s.theta = q[CHAPLYGIN_THETA];
  s.tau = tau;
  s.peg[0] = peg ? peg[0] : 0.0;
  s.peg[1] = peg ? peg[1] : 0.0;
  s.V = V;
  *st = s;
  return CHAPLYGIN_SUCCESS;
}

/* chaplygin_discrete_state_to_phase: the inverse: D+ from dir,
   Omega = H/(1 + l^2), V = dir sqrt(2E - H Omega), or the state's own V+
   where it is known.  Errors: as
   chaplygin_discrete_step's validation; CHAPLYGIN_ESTATE if V^2 <= 0. */
int
chaplygin_discrete_state_to_phase (const chaplygin_discrete *sys,
                                   const chaplygin_discrete_state *st,
                                   double q[4])
{
  if (!sys || !st || !q)
    return CHAPLYGIN_EINVAL;
  CHP_TRY (check_state (sys, st));
  double D = st->dir > 0 ? 0.0 : sys->Delta, l = sys->L0 + D;
  if (chp_system_far (sys))
    {
      /* far (lib/far.c): the scaled state; V times 2^-m, Omega times
         2^-(k+m+j) */
      chp_far f;
      chaplygin_discrete_state si;
      double qs[4];
      CHP_TRY (chp_far_open_sys (sys, &f));
      CHP_TRY (chp_far_state_of (&f, st, 1, &si));
      CHP_TRY (chaplygin_discrete_state_to_phase (&f.sys, &si, qs));
      q[CHAPLYGIN_D] = D;
      q[CHAPLYGIN_V] = st->V != 0.0 ? st->V
        : chp_far_out (&f, CHP_Q_SPEED, qs[CHAPLYGIN_V]);
      q[CHAPLYGIN_THETA] = st->theta;
      q[CHAPLYGIN_OMEGA] = chp_far_out (&f, CHP_Q_RATE, qs[CHAPLYGIN_OMEGA]);
      return CHAPLYGIN_SUCCESS;
    }
  double Om = st->H / chp_one_plus_sq (l);
  double v2 = 2.0 * st->E - st->H * Om;
  if (!(v2 > 0.0) && st->V == 0.0)
    return CHAPLYGIN_ESTATE;
  q[CHAPLYGIN_D] = D;
  q[CHAPLYGIN_V] = st->V != 0.0 ? st->V : st->dir * sqrt (v2);
  q[CHAPLYGIN_THETA] = st->theta;
  q[CHAPLYGIN_OMEGA] = Om;
  return CHAPLYGIN_SUCCESS;
}

/* chaplygin_discrete_poincare of an exactly scaled problem (lib/far.c):
   a far slot (FAR: D times 2^-k, V times 2^m, Omega times 2^(k+m)) or,
   within the cap, the time-scaling alone (V, Omega times 2^m, chp_far_speed:
   the motion is homogeneous in velocity); theta unchanged, the time times
   2^-(k+m).  CHAPLYGIN_ERANGE where the scaled time is not a normal double
   or a result leaves the doubles. */
static int
poincare_scaled (const chaplygin_discrete *sys, int far, const double qplus[4],
                 const chaplygin_options *opt, double qnext[4], double *dtau)
{
  const double V = qplus[CHAPLYGIN_V], D = qplus[CHAPLYGIN_D];
  if (V == 0.0 || (V > 0.0 && D != 0.0) || (V < 0.0 && D != sys->Delta))
    return CHAPLYGIN_ESTATE;            /* as state_from_phase */
  chp_far f;
  double qs[4], qn[4], dts = 0.0, dt = 0.0;
  CHP_TRY (chp_far_open_sys (sys, &f));
  const double l0 = sys->L0 + D;
  if (far)
    CHP_TRY (chp_far_phase (&f, l0, qplus[CHAPLYGIN_V], qplus[CHAPLYGIN_OMEGA],
                            &qs[CHAPLYGIN_V], &qs[CHAPLYGIN_OMEGA]));
  else
    CHP_TRY (chp_far_speed (&f, l0, qplus[CHAPLYGIN_V], qplus[CHAPLYGIN_OMEGA],
                            &qs[CHAPLYGIN_V], &qs[CHAPLYGIN_OMEGA]));
  const chaplygin_discrete *ss = far ? &f.sys : sys;
  qs[CHAPLYGIN_D] = qplus[CHAPLYGIN_D] == 0.0 ? 0.0 : ss->Delta;
  qs[CHAPLYGIN_THETA] = qplus[CHAPLYGIN_THETA];
  CHP_TRY (chaplygin_discrete_poincare (ss, qs, opt, qn, dtau ? &dts : NULL));
  if (dtau && !(dts >= DBL_MIN))
    return CHAPLYGIN_ERANGE;
  const double om = chp_far_out (&f, CHP_Q_RATE, qn[CHAPLYGIN_OMEGA]);
  const double v = chp_far_out (&f, CHP_Q_SPEED, qn[CHAPLYGIN_V]);
  if (!chp_far_out_exact (&f, CHP_Q_TIME, dts, &dt) || !isfinite (om)
      || !isfinite (v) || (v == 0.0) != (qn[CHAPLYGIN_V] == 0.0))
    return CHAPLYGIN_ERANGE;
  qnext[CHAPLYGIN_D] = qn[CHAPLYGIN_D] == 0.0 ? 0.0 : sys->Delta;
  qnext[CHAPLYGIN_V] = v;
  qnext[CHAPLYGIN_THETA] = qn[CHAPLYGIN_THETA];
  qnext[CHAPLYGIN_OMEGA] = om;
  if (dtau)
    *dtau = dt;
  return CHAPLYGIN_SUCCESS;
}

/* chaplygin_discrete_poincare: (3.5) f = h o p on phase states.
   p: the motion from just after collision i to just before collision i+1,
      by (B.1) for V and Omega at the end the peg leaves and by the heading
      of (B.3)/(B.4) (opt->method), with g(l0) = (1 + l0^2) V+^2/(2E) formed
      from V+ itself (accurate also when V+ is small beside Omega+);
   h: the collision rule (3.6).
   qplus: {D+, V+, theta+, Omega+} with D+ = 0 if V+ > 0, Delta if V+ < 0.
   Errors: those of chaplygin_discrete_state_from_phase and
   chaplygin_discrete_step; CHAPLYGIN_EINVAL for NULL. */
int
chaplygin_discrete_poincare (const chaplygin_discrete *sys,
                             const double qplus[4],
                             const chaplygin_options *opt, double qnext[4],
                             double *dtau)
{
  if (!sys || !qplus || !qnext)
    return CHAPLYGIN_EINVAL;
  if (!chp_finite4 (qplus[0], qplus[1], qplus[2], qplus[3]))
    return CHAPLYGIN_EDOM;
  const int far = chp_system_far (sys);
  if (far || chp_far_speed_needed (sys->L0 + qplus[CHAPLYGIN_D],
                                   qplus[CHAPLYGIN_V],
                                   qplus[CHAPLYGIN_OMEGA]))
    return poincare_scaled (sys, far, qplus, opt, qnext, dtau);
  chaplygin_discrete_state st;
  chaplygin_discrete_event ev;
  CHP_TRY (chaplygin_discrete_state_from_phase (sys, qplus, 0.0, NULL, &st));
  unsigned req = CHAPLYGIN_WANT_THETA | (dtau ? CHAPLYGIN_WANT_TAU : 0u);
  /* the step from the phase state, which keeps V+ (st.V): its g0 from V+
     itself, its classification the state's */
  CHP_TRY (step_core (sys, &st, req, opt, &st, &ev));

  /* p: (B.1) from the post-collision state to the end the peg leaves,
     which step_core has classified: no second reachability test that
     could disagree with it within rounding (a motion through l = 0 with
     2E within an ulp of H^2); where (B.1)'s V^2 there rounds to 0 or
     below on a pass (a turning point within rounding of the far end: its
     V0^2 and the term it subtracts cancel), the step's own V- (from g at
     that end, whose sign decided the pass) */
  double V2, Om;
  CHP_TRY (chp_flow_eval (sys->L0, qplus[CHAPLYGIN_D], qplus[CHAPLYGIN_V],
                          qplus[CHAPLYGIN_OMEGA], ev.Dminus, &V2, &Om));
  if (!(V2 > 0.0))
    V2 = ev.reversal ? 0.0 : ev.Vminus * ev.Vminus;
  /* a reversal returns with -V+ exactly (the motion is symmetric about
     the turning point; (B.1) would underflow V+^2 for |V+| < 1e-154) */
  double qminus[4]
      = { ev.Dminus,
          ev.reversal ? -qplus[CHAPLYGIN_V]
                      : copysign (sqrt (V2), qplus[CHAPLYGIN_V]),
          qplus[CHAPLYGIN_THETA] + ev.dtheta, Om };
  /* h: (3.6). */
  double q[4];
  CHP_TRY (chaplygin_discrete_collide (sys->L0, sys->Delta, qminus, q));
  for (int i = 0; i < 4; i++)
    qnext[i] = q[i];
  if (dtau)
    *dtau = ev.dtau;
  return CHAPLYGIN_SUCCESS;
}
