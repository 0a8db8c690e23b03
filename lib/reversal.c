/* reversal.c -- Section 3.1.3 and Appendix B.2.1: velocity reversals,
   (3.13)-(3.15), (B.6)-(B.8).

   A post-collision state (dir, E, H) starts at l_s = L0 + D+ and moves
   towards the far end l_f (D+ = 0, l_f = L0 + Delta for dir = +1; the
   reverse for dir = -1).  With r = 2E/H^2 (3.8), (3.3) and (3.4) give

       V^2 = 2E g(l)/(1 + l^2),   g(l) = 1 + l^2 - 1/r,

   so the state is valid iff g(l_s) > 0 (3.15), and its path reverses iff g
   vanishes between l_s and l_f: iff r <= 1/(1 + m^2), m = min |l| over the
   path (m = 0 if the path reaches l = 0; r = 1 there is the spinning state
   (3.8) instead).  Along a run of collisions without reversal, (B.3) gives
   r' = (r + 2 C1)/C2^2, an affine map: the run is monotone in r and the
   first reversal has the closed form (B.6).  */
#include <config.h>

#include <limits.h>
#include <math.h>

#include "chaplygin.h"
#include "eft.h"
#include "far.h"
#include "motion.h"
#include "series.h"

/* The largest count (B.6) returns: 2^62, or ULONG_MAX if smaller; beyond
   2^53 consecutive counts are not resolved (documented). */
#define CHP_N_MAX                                                       \
  (ULONG_MAX < 0x4000000000000000ULL ? (unsigned long) ULONG_MAX        \
   : (unsigned long) 0x4000000000000000ULL)

/* Validate the common arguments L0, Delta, dir (CHAPLYGIN_EINVAL for dir
   first) and open their far scaling (lib/far.c). */
static int
open_params (double L0, double Delta, int dir, chp_far *f)
{
  if (dir != 1 && dir != -1)
    return CHAPLYGIN_EINVAL;
  return chp_far_open (L0, Delta, f);
}

/* Validate the common arguments L0, Delta, dir and set up the run of
   direction dir of that skate. */
static int
run_from_params (double L0, double Delta, int dir, chp_run *run)
{
  if (dir != 1 && dir != -1)
    return CHAPLYGIN_EINVAL;
  if (!chp_finite2 (L0, Delta) || !(Delta > 0.0))
    return CHAPLYGIN_EDOM;
  chaplygin_discrete sys;
  CHP_TRY (chaplygin_discrete_init (&sys, L0, Delta));
  return chp_run_init (&sys, dir, run);
}

/* chaplygin_discrete_ratio_lower_bound: (3.15)
       r = 2E/H^2 > 1/(1 + L0^2)            for V+ > 0,
       r = 2E/H^2 > 1/(1 + (L0 + Delta)^2)  for V+ < 0,
   i.e. rmin = 1/(1 + l_s^2): V+^2 = 2E g(l_s)/(1 + l_s^2) > 0 iff
   r > rmin.  As printed.
   Method: 1 + l_s^2 with the rounding error of L0 + Delta included.
   Accuracy: within 2 ulps.
   Domain: finite; Delta > 0; dir = +-1; |L0|, |L0 + Delta| <= 2^500
   (both ends, as everywhere in the library).
   Errors: CHAPLYGIN_EINVAL (NULL, dir), CHAPLYGIN_EDOM, CHAPLYGIN_ERANGE. */
int
chaplygin_discrete_ratio_lower_bound (double L0, double Delta, int dir,
                                      double *rmin)
{
  if (!rmin)
    return CHAPLYGIN_EINVAL;
  chp_far f;
  CHP_TRY (open_params (L0, Delta, dir, &f));
  if (f.k)
    {
      /* far (lib/far.c): r = 2E/H^2 is an inverse area; below 2^-1000
         here, subnormal or zero (ERANGE) */
      double r;
      CHP_TRY (chaplygin_discrete_ratio_lower_bound (f.sys.L0, f.sys.Delta,
                                                     dir, &r));
      r = chp_far_out (&f, CHP_Q_INVERSE_AREA, r);
      if (!(r > 0.0))
        return CHAPLYGIN_ERANGE;
      *rmin = r;
      return CHAPLYGIN_SUCCESS;
    }
  chp_run run;
  CHP_TRY (run_from_params (L0, Delta, dir, &run));
  *rmin = 1.0 / chp_one_plus_sq_exact (run.seg.l0, run.seg.l0_err);
  return CHAPLYGIN_SUCCESS;
}

/* chaplygin_discrete_reversal_range: (3.13), (3.14), generalised
       rlo = 1/(1 + l_s^2) < r < rhi = 1/(1 + m^2),
   m = min |l| over the path: the open interval of r in which a valid state
   of direction dir reverses before its next collision.
     (3.13) L0 > 0, dir = -1:      1/(1 + (L0 + Delta)^2) < r < 1/(1 + L0^2);
     (3.14) L0 < -Delta, dir = +1: 1/(1 + L0^2) < r < 1/(1 + (L0 + Delta)^2);
     -Delta < L0 < 0, either dir:  1/(1 + l_s^2) < r < 1;
     a path moving away from l = 0 (L0 >= 0, dir = +1; L0 + Delta <= 0,
     dir = -1) never reverses: *nonempty = 0 and rlo = rhi = 1/(1 + l_s^2).
   (3.13) and (3.14) are correct as printed, for the direction that moves
   towards the mass centre.  At r = rhi exactly the turning point is at the
   far end (a reversal, as chaplygin_discrete_step counts it) if m > 0, or
   the path ends in the spinning state (3.8) if m = 0.
   Method: *nonempty is exact (the sign of l_s); the bounds are rounded
   (2 ulps), and coincide when Delta << eps |L0| though the interval is
   not empty.  To classify a given state, use
   chaplygin_discrete_collisions_before_reversal (exact).
   Domain and errors: as chaplygin_discrete_ratio_lower_bound. */
int
chaplygin_discrete_reversal_range (double L0, double Delta, int dir,
                                   double *rlo, double *rhi, int *nonempty)
{
  if (!rlo || !rhi || !nonempty)
    return CHAPLYGIN_EINVAL;
  chp_far f;
  CHP_TRY (open_params (L0, Delta, dir, &f));
  if (f.k)
    {
      /* far: as chaplygin_discrete_ratio_lower_bound */
      double lo, hi;
      int ne;
      CHP_TRY (chaplygin_discrete_reversal_range (f.sys.L0, f.sys.Delta, dir,
                                                  &lo, &hi, &ne));
      lo = chp_far_out (&f, CHP_Q_INVERSE_AREA, lo);
      hi = chp_far_out (&f, CHP_Q_INVERSE_AREA, hi);
      if (!(lo > 0.0 && hi > 0.0))
        return CHAPLYGIN_ERANGE;
      *rlo = lo;
      *rhi = hi;
      *nonempty = ne;
      return CHAPLYGIN_SUCCESS;
    }
  chp_run run;
  CHP_TRY (run_from_params (L0, Delta, dir, &run));
  double lo = 1.0 / chp_one_plus_sq_exact (run.seg.l0, run.seg.l0_err),
         hi = lo;
  if (run.seg.toward)
    hi = run.seg.crosses
             ? 1.0
             : 1.0 / chp_one_plus_sq_exact (run.seg.l1, run.seg.l1_err);
  *rlo = lo;
  *rhi = hi;
  *nonempty = run.seg.toward;
  return CHAPLYGIN_SUCCESS;
}

/* chaplygin_discrete_c3: (B.7)
       C3 = sgn(V+) Delta (2 L0 + Delta)/(1 + (L0 + (Delta - D+))^2)
          = dir Delta (2 L0 + Delta)/(1 + l_f^2).
   As printed.  Meaning (derivation): with Y = (1 + l_s^2) V^2/H^2 =
   r (1 + l_s^2) - 1 at the start of a path, (B.1) gives Y + C3 at its far
   end (l_f^2 - l_s^2 = dir Delta (2 L0 + Delta)), and the (B.3) collision
   Y' = (Y + C3)/C2^2.
   Accuracy: within 3 ulps (2 L0 + Delta is rounded once).
   Domain: finite; Delta > 0; dir = +-1; |L0|, |L0 + Delta| <= 2^500.
   Errors: CHAPLYGIN_EINVAL (NULL, dir), CHAPLYGIN_EDOM, CHAPLYGIN_ERANGE. */
int
chaplygin_discrete_c3 (double L0, double Delta, int dir, double *C3)
{
  if (!C3)
    return CHAPLYGIN_EINVAL;
  chp_far f;
  CHP_TRY (open_params (L0, Delta, dir, &f));
  if (f.k)      /* far: C3 is a ratio of lengths squared, scale-free */
    return chaplygin_discrete_c3 (f.sys.L0, f.sys.Delta, dir, C3);
  chp_run run;
  CHP_TRY (run_from_params (L0, Delta, dir, &run));
  /* |Delta (2 L0 + Delta)| < 2^1003: finite */
  *C3 = dir * Delta
        * (run.s / chp_one_plus_sq_exact (run.seg.l1, run.seg.l1_err));
  return CHAPLYGIN_SUCCESS;
}

/* The fate of the path after k collisions of the run, from the (B.9)
   iterate.  An iterate that is no longer a valid state of the run (E_k or
   g(l_s) not positive, or not representable) lies beyond the first
   reversal, so it counts as one: the fates are then monotone in k. */
static int
iterate_fate (const chp_run *run, double E, double H, unsigned long k,
              int *fate)
{
  double Ek, Hk;
  chp_motion m;
  if (chp_run_state (run, E, H, (double) k, &Ek, &Hk) != CHAPLYGIN_SUCCESS
      || !(Ek > 0.0) || chp_motion_init (Ek, Hk, &m) != CHAPLYGIN_SUCCESS
      || !(chp_motion_g_exact (&m, run->seg.l0, run->seg.l0_err) > 0.0))
    {
      *fate = CHP_SEGMENT_REVERSE;
      return CHAPLYGIN_SUCCESS;
    }
  *fate = chp_segment_classify (&run->seg, &m, NULL);
  return CHAPLYGIN_SUCCESS;
}

/* The closed form (B.6), as a real number x: the first reversal is on the
   path after ceil(x) collisions.  NaN where it cannot be formed (the search
   in the caller then starts from 1). */
static double
count_estimate (const chp_run *run, const chp_motion *m)
{
  const double E = m->E, H = m->H;
  /* g and 1 + l^2 at the point of the path nearest l = 0 */
  double gm, nm;
  if (run->seg.crosses)
    {
      gm = m->one_minus_h2;
      nm = 1.0;
    }
  else
    {
      gm = chp_motion_g_exact (m, run->seg.l1, run->seg.l1_err);
      nm = chp_one_plus_sq_exact (run->seg.l1, run->seg.l1_err);
    }
  /* r - rho = r g(m)/(1 + m^2) > 0 */
  const double r = (2.0 * E / H) / H, rmr = r * (gm / nm);
  if (run->omq == 0.0)
    return rmr / (-2.0 * run->C1);        /* r_k = r + 2 C1 k */
  /* den = rho (1 - q) + 2 C1: for a path that reaches l = 0 (rho = 1)
     directly; otherwise = C3 q/(1 + l_s^2), without cancellation */
  double den;
  if (run->seg.crosses)
    den = run->omq + 2.0 * run->C1;
  else
    {
      double d = run->dir * run->Delta;
      den = (d * run->s / chp_one_plus_sq_exact (run->seg.l1, run->seg.l1_err))
            * (run->C2 * run->C2
               / chp_one_plus_sq_exact (run->seg.l0, run->seg.l0_err));
    }
  /* (r (1-q) + 2 C1)/(rho (1-q) + 2 C1) = 1 + z */
  const double z = (run->omq / den) * rmr;
  if (isfinite (z) && z > -1.0)
    return log1p (z) / run->logq;
  return NAN;
}

/* A bracket lo < hi of the count: iterate lo passes (lo = 0: the current
   segment, which the caller found to pass), iterate hi does not (its
   outcome in *fhi), galloping up or down from k0 = ceil(x), x the closed
   form's estimate (CHAPLYGIN_ERANGE beyond CHP_N_MAX). */
static int
count_bracket (const chp_run *run, double E, double H, double x,
               unsigned long *lo_out, unsigned long *hi_out, int *fhi_out)
{
  unsigned long k0 = 1, lo = 0, hi = 0, step;
  int f, fhi = CHP_SEGMENT_PASS;
  if (x > 1.0)
    k0 = x < (double) CHP_N_MAX ? (unsigned long) ceil (x) : CHP_N_MAX;
  CHP_TRY (iterate_fate (run, E, H, k0, &f));
  if (f == CHP_SEGMENT_PASS)
    {
      /* gallop up */
      lo = k0;
      for (step = 1;; step *= 2)
        {
          if (lo >= CHP_N_MAX)
            return CHAPLYGIN_ERANGE;
          hi = CHP_N_MAX - lo > step ? lo + step : CHP_N_MAX;
          CHP_TRY (iterate_fate (run, E, H, hi, &fhi));
          if (fhi != CHP_SEGMENT_PASS)
            break;
          lo = hi;
        }
    }
  else
    {
      /* gallop down (iterate 0 passes) */
      hi = k0;
      fhi = f;
      for (step = 1; hi - lo > 1; step *= 2)
        {
          unsigned long c = hi - lo > step ? hi - step : lo + 1;
          CHP_TRY (iterate_fate (run, E, H, c, &f));
          if (f == CHP_SEGMENT_PASS)
            {
              lo = c;
              break;
            }
          hi = c;
          fhi = f;
        }
    }
  *lo_out = lo;
  *hi_out = hi;
  *fhi_out = fhi;
  return CHAPLYGIN_SUCCESS;
}

/* The bracket narrowed to hi - lo = 1 by bisection: hi is the count. */
static int
count_bisect (const chp_run *run, double E, double H, unsigned long *lo,
              unsigned long *hi, int *fhi)
{
  int f;
  while (*hi - *lo > 1)
    {
      unsigned long mid = *lo + (*hi - *lo) / 2;
      CHP_TRY (iterate_fate (run, E, H, mid, &f));
      if (f == CHP_SEGMENT_PASS)
        *lo = mid;
      else
        {
          *hi = mid;
          *fhi = f;
        }
    }
  return CHAPLYGIN_SUCCESS;
}

/* chaplygin_discrete_collisions_before_reversal: (B.6), (B.7), corrected:
       n = ceil( log[(r (1 - C2^2) + 2 C1)/(rho (1 - C2^2) + 2 C1)]
                 / log C2^2 ),   rho = 1/(1 + m^2),
   r = 2E/H^2, C1, C2 of (B.3) for direction dir, m = min |l| over the path
   (0 if it reaches l = 0): the number of further collisions without
   reversal before the path on which V changes sign.
   Derivation: along the run, r_k = C2^-2k (r + 2 C1 S_k), S_k = (1 -
   C2^2k)/(1 - C2^2) (from (B.9)), and the path after k collisions reverses
   iff r_k <= rho.  With Y = r (1 + l_s^2) - 1 and C3 of (B.7) the printed
   form is
       n = floor( log[1 + (1 - C2^2) Y/C3] / log C2^2 ),
   the special case rho = 1/(1 + l_f^2) (turning point reached before the
   far end), which is ceil(...) - 1 of the same logarithm: the printed form
   is right for L0 > 0, dir = -1 and L0 < -Delta, dir = +1 except where the
   ratio of logarithms is an integer (the turning point exactly at the far
   end: floor counts that path as a collision, the return map as a
   reversal).  For the other direction it gives a negative number (no
   reversal ever); for -Delta < L0 < 0 it uses the far end instead of
   l = 0 and overestimates n or takes the logarithm of a nonpositive
   number (errata).
   When does it reverse: a path moving away from l = 0 never reverses; for
   one moving towards it: if |C2| >= 1 always, after finitely many
   collisions; if |C2| < 1 iff the final energy (B.10) of the run would be
   negative; if C2 = 0 or H = 0 never after the current path.
   Method: the current path is classified exactly, as by
   chaplygin_discrete_step; for n >= 1, x = log1p(z)/log C2^2 (z formed
   without cancellation; n = (r - rho)/(-2 C1) for C2^2 = 1) gives a
   candidate, which is then verified and if need be corrected by testing
   the (B.9) iterates (chaplygin_discrete_energy_after) with the step's
   classification: the result is the smallest n whose iterate reverses,
   so a ratio within rounding of an integer cannot be misrounded by floor.
   The iterates' fates are monotone in n; the search gallops and bisects.
   Accuracy: n is exact unless r_n or r_{n-1} lies within ~(n + 1) eps
   max(1, C2^-2n) (relative) of rho -- there the map iterated in floating
   point may also go either way, and the n-th iterate may even be a state
   with V+^2 <= 0 by rounding (the (n-1)-th path turning at its far end) --
   and for n <= 2^53 (tests: 4500 random cases with n up to 121 built in
   binary128, none off outside that band).
   Domain: a valid system; dir = +-1; E > 0, H finite, and a valid state:
   r > 1/(1 + l_s^2).
   Errors: CHAPLYGIN_EINVAL (NULL, dir), CHAPLYGIN_EDOM (non-finite,
   E < 0), CHAPLYGIN_ESTATE (E = 0 or V+^2 <= 0), CHAPLYGIN_ESPIN (the
   path after n collisions ends in the spinning state (3.8) before any
   reversal), CHAPLYGIN_ERANGE (|l| > 2^500, or n > 2^62). */
int
chaplygin_discrete_collisions_before_reversal (const chaplygin_discrete *sys,
                                               int dir, double E, double H,
                                               int *reverses,
                                               unsigned long *n)
{
  if (!sys || !reverses || !n)
    return CHAPLYGIN_EINVAL;
  chp_far far;
  if (dir != 1 && dir != -1)
    return CHAPLYGIN_EINVAL;
  CHP_TRY (chp_far_open_sys (sys, &far));
  if (far.k)
    {
      /* far: the scaled state; n and the outcome are scale-free */
      double Es, Hs;
      if (!chp_finite2 (E, H) || E < 0.0)
        return CHAPLYGIN_EDOM;
      CHP_TRY (chp_far_state (&far, E, H, 0, &Es, &Hs));
      return chaplygin_discrete_collisions_before_reversal (&far.sys, dir, Es,
                                                            Hs, reverses, n);
    }
  chp_run run;
  chp_motion m;
  CHP_TRY (chp_run_init (sys, dir, &run));
  CHP_TRY (chp_motion_init (E, H, &m));
  if (!(chp_motion_g_exact (&m, run.seg.l0, run.seg.l0_err) > 0.0))
    return CHAPLYGIN_ESTATE;
  const int fate0 = chp_segment_classify (&run.seg, &m, NULL);
  if (fate0 == CHP_SEGMENT_SPIN)
    return CHAPLYGIN_ESPIN;
  if (fate0 == CHP_SEGMENT_REVERSE)
    {
      *reverses = 1;
      *n = 0;
      return CHAPLYGIN_SUCCESS;
    }
  if (!run.seg.toward || H == 0.0 || run.C2 == 0.0
      || (run.omq > 0.0
          && !(chp_run_final_energy (
                   &run, E,
                   chp_motion_g_exact (&m, run.seg.l0, run.seg.l0_err), H)
               < 0.0)))
    {
      *reverses = 0;
      return CHAPLYGIN_SUCCESS;
    }

  /* It reverses after n >= 1 collisions: the smallest k whose iterate
     does not pass, bracketed from the closed form, then bisected. */
  unsigned long lo, hi;
  int fhi;
  CHP_TRY (count_bracket (&run, E, H, count_estimate (&run, &m), &lo, &hi,
                          &fhi));
  CHP_TRY (count_bisect (&run, E, H, &lo, &hi, &fhi));
  if (fhi == CHP_SEGMENT_SPIN)
    return CHAPLYGIN_ESPIN;
  *reverses = 1;
  *n = hi;
  return CHAPLYGIN_SUCCESS;
}

/* chaplygin_discrete_two_turning_points: (B.8), corrected
       MAX{1/(1 + L0^2), 1/(1 + (L0 + Delta)^2)} < 2E/H^2 < 1
   (-Delta < L0 < 0): both turning points D_c = -L0 -+ sqrt(H^2/(2E) - 1) of
   (B.5) lie inside the slot, 0 < D_c < Delta, and a state of either
   direction is valid and reverses (at the turning point nearer its
   start).  The paper prints MIN: that is the condition for at least one
   turning point inside the slot; between MIN and MAX only the direction
   starting from the end farther from the mass centre is valid (errata).
   Derivation: D_c in (0, Delta) for both signs iff c = sqrt(1/r - 1) <
   min(-L0, L0 + Delta), i.e. g(L0) > 0 and g(L0 + Delta) > 0.
   Method: exact signs: 2E - H^2 (chp_one_minus_h2) and g at the ends by
   error-free arithmetic, and -L0 < Delta compared without rounding.
   Domain: finite; Delta > 0; E >= 0; |L0|, |L0 + Delta| <= 2^500.
   Errors: CHAPLYGIN_EINVAL (NULL), CHAPLYGIN_EDOM (non-finite, Delta <= 0,
   E < 0), CHAPLYGIN_ESTATE (E = 0), CHAPLYGIN_ERANGE. */
int
chaplygin_discrete_two_turning_points (double L0, double Delta, double E,
                                       double H, int *two)
{
  if (!two)
    return CHAPLYGIN_EINVAL;
  if (!chp_finite4 (L0, Delta, E, H) || !(Delta > 0.0) || E < 0.0)
    return CHAPLYGIN_EDOM;
  chaplygin_discrete sys;
  chp_motion m;
  chp_far f;
  CHP_TRY (chp_far_open (L0, Delta, &f));
  if (f.k)
    {
      /* far: the scaled problem (a far slot holds no turning point pair:
         its ends have one sign) */
      double Es, Hs;
      CHP_TRY (chp_far_state (&f, E, H, 1, &Es, &Hs));
      return chaplygin_discrete_two_turning_points (f.sys.L0, f.sys.Delta,
                                                    Es, Hs, two);
    }
  CHP_TRY (chaplygin_discrete_init (&sys, L0, Delta));
  CHP_TRY (chp_motion_init (E, H, &m));
  *two = L0 < 0.0 && -L0 < Delta && m.one_minus_h2 < 0.0
    && chp_motion_g_exact (&m, sys.l_end[0], sys.l_err[0]) > 0.0
    && chp_motion_g_exact (&m, sys.l_end[1], sys.l_err[1]) > 0.0;
  return CHAPLYGIN_SUCCESS;
}
