/* energy.c -- Appendix B.2.2: energy analysis, (B.9)-(B.13).

   Along a run of collisions without reversal in one direction, (B.3) is
   linear in (E, H^2): H' = C2 H, E' = E + C1 H^2, with C1, C2 fixed by the
   direction (chp_run, reversal.c).  Hence the geometric series (B.9) and,
   for |C2| < 1, the final energy (B.10) of a motion that settles into
   straight-line motion; (B.12) is (B.10) in terms of V and Omega.  The
   symmetric case L0 = -Delta/2 (B.13) has the same C1, C2 with and without
   reversal, so r = 2E/H^2 obeys one affine map whatever the path does.  */
#include <config.h>

#include <math.h>

#include "chaplygin.h"
#include "eft.h"
#include "far.h"
#include "motion.h"
#include "series.h"

/* Common validation: the run of dir, the motion (E, H) and its validity
   as a post-collision state; *g0 = g(l_s). */
static int
setup (const chaplygin_discrete *sys, int dir, double E, double H,
       chp_run *run, chp_motion *m, double *g0)
{
  CHP_TRY (chp_run_init (sys, dir, run));
  CHP_TRY (chp_motion_init (E, H, m));
  *g0 = chp_motion_g_exact (m, run->seg.l0, run->seg.l0_err);
  if (!(*g0 > 0.0))
    return CHAPLYGIN_ESTATE;
  return CHAPLYGIN_SUCCESS;
}

/* The far regime of a system (lib/far.c) after the checks of setup that
   precede it: *f (f->k = 0 within the cap; when far, f->sys the scaled
   system). */
static int
far_state (const chaplygin_discrete *sys, int dir, double E, double H,
           chp_far *f)
{
  if (dir != 1 && dir != -1)
    return CHAPLYGIN_EINVAL;
  CHP_TRY (chp_far_open_sys (sys, f));
  if (f->k && (!chp_finite2 (E, H) || E < 0.0))
    return CHAPLYGIN_EDOM;
  return CHAPLYGIN_SUCCESS;
}

/* The status for a run that ends in FATE instead of a (B.3) collision. */
static int
fate_status (int fate)
{
  return fate == CHP_SEGMENT_SPIN ? CHAPLYGIN_ESPIN : CHAPLYGIN_ESTATE;
}

/* chaplygin_discrete_energy_after: (B.9), corrected
       E_n = E + C1 H^2 sum_{j=0}^{n-1} C2^2j
           = E + C1 H^2 (1 - C2^2n)/(1 - C2^2),      H_n = C2^n H,
   C1, C2 of (B.3) for direction dir: the state after n collisions without
   reversal.  The paper's sum runs j = 0 .. n (n + 1 terms) while its closed
   form has n terms; n = 1 must give (B.3) itself, E_1 = E + C1 H^2, so the
   sum stops at n - 1 (errata).
   Method: chp_run_state (expm1/log1p forms: accurate for C2^2 near 1 and
   for large n).  The paths of the first n collisions are checked: the
   first exactly (as chaplygin_discrete_step), the others through the
   (n-1)-th iterate (the run is monotone), consistently with
   chaplygin_discrete_collisions_before_reversal.
   Accuracy: H_n within (4 + 1.5 n |log C2^2|) eps; E_n within
   (4 + n |log C2^2|) eps times (E + |C1| H^2 S_n)/E_n, the condition of
   the sum, which the map iterated shares (measured: 1.2 and 0.2 x these
   bounds against binary128, 20000 random runs of up to 1.6e5 collisions).
   Domain: a valid system, dir = +-1, a valid state (E > 0, V+^2 > 0).
   Errors: CHAPLYGIN_EINVAL (NULL, dir), CHAPLYGIN_EDOM (non-finite,
   E < 0), CHAPLYGIN_ESTATE (E = 0, V+^2 <= 0, or a path among the n
   reverses: (B.9) does not apply), CHAPLYGIN_ESPIN (one of them ends in
   the spinning state), CHAPLYGIN_ERANGE (overflow, |l| > 2^500). */
int
chaplygin_discrete_energy_after (const chaplygin_discrete *sys, int dir,
                                 double E, double H, unsigned long n,
                                 double *En, double *Hn)
{
  if (!sys || !En || !Hn)
    return CHAPLYGIN_EINVAL;
  chp_far f;
  CHP_TRY (far_state (sys, dir, E, H, &f));
  if (f.k)
    {
      /* far (lib/far.c): the scaled run; H_n = C2^n H from the unscaled
         H (C2 is scale-free), since the scaled C2^n H_s may be subnormal
         where H_n is not */
      double Es, Hs, e, h;
      chp_run run;
      CHP_TRY (chp_far_state (&f, E, H, 0, &Es, &Hs));
      CHP_TRY (chaplygin_discrete_energy_after (&f.sys, dir, Es, Hs, n, &e,
                                                &h));
      CHP_TRY (chp_run_init (&f.sys, dir, &run));
      CHP_TRY (chp_run_momentum (&run, H, (double) n, &h));
      e = chp_far_out (&f, CHP_Q_ENERGY, e);
      if (!isfinite (e) || !isfinite (h))
        return CHAPLYGIN_ERANGE;
      *En = e;
      *Hn = h;
      return CHAPLYGIN_SUCCESS;
    }
  chp_run run;
  chp_motion m;
  double g0, e, h;
  CHP_TRY (setup (sys, dir, E, H, &run, &m, &g0));
  if (n > 0)
    {
      int fate = chp_segment_classify (&run.seg, &m, NULL);
      if (fate != CHP_SEGMENT_PASS)
        return fate_status (fate);
    }
  if (n > 1 && run.seg.toward && H != 0.0)
    {
      chp_motion mk;
      double gk;
      /* an iterate that is not a state lies beyond the first reversal */
      if (chp_run_state (&run, E, H, (double) (n - 1), &e, &h)
          != CHAPLYGIN_SUCCESS || !(e > 0.0)
          || chp_motion_init (e, h, &mk) != CHAPLYGIN_SUCCESS)
        return CHAPLYGIN_ESTATE;
      gk = chp_motion_g_exact (&mk, run.seg.l0, run.seg.l0_err);
      int fate = gk > 0.0 ? chp_segment_classify (&run.seg, &mk, NULL)
                          : CHP_SEGMENT_REVERSE;
      if (fate != CHP_SEGMENT_PASS)
        return fate_status (fate);
    }
  CHP_TRY (chp_run_state (&run, E, H, (double) n, &e, &h));
  *En = e;
  *Hn = h;
  return CHAPLYGIN_SUCCESS;
}

/* chaplygin_discrete_final_energy: (B.10)
       E_f = E + C1 H^2/(1 - C2^2),
   the limit of (B.9) for a state that never reverses again; as printed.
   Derivation: (B.9) with C2^2n -> 0, which needs |C2| < 1 ((B.11)).
   Method: as V^2/2 + kappa (1 + l_s^2) Omega^2/2 with V^2 = 2E g(l_s)/
   (1 + l_s^2), kappa = 1 + 2 C1 (1 + l_s^2)/(1 - C2^2) = 1 - dir Delta/
   (l_f (2 + l_f (2 L0 + Delta))) < 1 (chp_run_final_energy), with
   1 - C2^2 and 2 + l_f (2 L0 + Delta) formed without cancellation (near
   C2 = +-1 the printed form with a rounded C2^2 loses the digits of
   1 - C2^2): a sum of two nonnegative terms when kappa >= 0 (always for
   L0 > 0, dir = +1).  E_f <= E.
   Which states never reverse: H = 0 (E_f = E), and for H != 0 those whose
   path does not reverse, with |C2| < 1 and E_f >= 0 (E_f < 0 means the
   run ends in a reversal, chaplygin_discrete_collisions_before_reversal).
   Accuracy: within ~2 eps times (V^2 + max(1, |kappa|) H Omega)/(2 E_f)
   (measured against binary128: 1.7 over the test's 20000 random cases,
   2.19 over 500000 in review; 6 mpmath cases within 1.35 eps).
   Domain: a valid system, dir = +-1, a valid state.
   Errors: CHAPLYGIN_EINVAL (NULL, dir), CHAPLYGIN_EDOM (non-finite,
   E < 0; and H != 0 with |C2| >= 1: the series diverges), CHAPLYGIN_ESTATE
   (E = 0, V+^2 <= 0, or the motion reverses), CHAPLYGIN_ESPIN (the
   current path ends in the spinning state), CHAPLYGIN_ERANGE (|l| >
   2^500). */
int
chaplygin_discrete_final_energy (const chaplygin_discrete *sys, int dir,
                                 double E, double H, double *Ef)
{
  if (!sys || !Ef)
    return CHAPLYGIN_EINVAL;
  chp_far f;
  CHP_TRY (far_state (sys, dir, E, H, &f));
  if (f.k)
    {
      /* far: the scaled run */
      double Es, Hs, e;
      CHP_TRY (chp_far_state (&f, E, H, 0, &Es, &Hs));
      CHP_TRY (chaplygin_discrete_final_energy (&f.sys, dir, Es, Hs, &e));
      *Ef = chp_far_out (&f, CHP_Q_ENERGY, e);
      return CHAPLYGIN_SUCCESS;
    }
  chp_run run;
  chp_motion m;
  double g0;
  CHP_TRY (setup (sys, dir, E, H, &run, &m, &g0));
  if (H == 0.0)
    {
      *Ef = E;
      return CHAPLYGIN_SUCCESS;
    }
  int fate = chp_segment_classify (&run.seg, &m, NULL);
  if (fate != CHP_SEGMENT_PASS)
    return fate_status (fate);
  if (!(run.omq > 0.0))
    return CHAPLYGIN_EDOM;
  /* kappa < 1: E_f <= E, no overflow */
  double e = chp_run_final_energy (&run, E, g0, H);
  if (e < 0.0)
    return CHAPLYGIN_ESTATE;
  *Ef = e;
  return CHAPLYGIN_SUCCESS;
}

/* Shewchuk's Grow-Expansion: add b to the nonoverlapping expansion
   e[0 .. *n-1] (increasing magnitude), exactly. */
static void
grow_expansion (double *e, int *n, double b)
{
  double q = b;
  for (int i = 0; i < *n; i++)
    {
      double s, err;
      chp_two_sum (q, e[i], &s, &err);
      e[i] = err;
      q = s;
    }
  e[(*n)++] = q;
}

/* The exact sign of the sum of an expansion: that of its largest nonzero
   component. */
static int
expansion_sign (const double *e, int n)
{
  for (int i = n - 1; i >= 0; i--)
    if (e[i] != 0.0)
      return e[i] > 0.0 ? 1 : -1;
  return 0;
}

/* chaplygin_discrete_energy_converges: (B.11), corrected
       |C2| < 1  <=>   -x + 2 x u + u^2 > 0                          and
                       (1/Delta)^2 > -(2 x^2 + (1 + 2u) x + u^2)/2,
   x = L0/Delta, u = 1 - D+/Delta (1 for dir = +1, 0 for dir = -1), C2 the
   (B.3) coefficient (1 + L0 (L0 + Delta))/(1 + l_f^2), l_f = Delta (x + u).
   Derivation: C2 < 1 iff L0 (L0 + Delta) < l_f^2 iff x (x + 1) < (x + u)^2;
   C2 > -1 iff 2 + L0 (L0 + Delta) + l_f^2 > 0, divided by Delta^2.  The
   transcription garbles the first inequality (its terms are recognisable)
   and loses the second; they are (3.11) for dir = +1 (L0/Delta > -1 and
   (1/Delta)^2 > -(1 + 2x)(1 + x)/2) and (3.12) for dir = -1 (L0/Delta < 0
   and (1/Delta)^2 > -x (1 + 2x)/2), not (3.11) alone as the text says.
   Method: exactly, multiplied through by Delta^2: L0 > -Delta (dir = +1)
   or L0 < 0 (dir = -1), and the sign of 2 + 2 L0^2 + (1 + 2u) L0 Delta
   + u^2 Delta^2 from an exact expansion of error-free products.
   Domain: finite; Delta > 0; dir = +-1; |L0|, |L0 + Delta| <= 2^500.
   Errors: CHAPLYGIN_EINVAL (NULL, dir), CHAPLYGIN_EDOM, CHAPLYGIN_ERANGE. */
int
chaplygin_discrete_energy_converges (double L0, double Delta, int dir,
                                     int *converges)
{
  if (!converges || (dir != 1 && dir != -1))
    return CHAPLYGIN_EINVAL;
  if (!chp_finite2 (L0, Delta) || !(Delta > 0.0))
    return CHAPLYGIN_EDOM;
  chp_far f;
  CHP_TRY (chp_far_open (L0, Delta, &f));
  if (f.k)      /* far (lib/far.c): |C2| < 1 is scale-free */
    return chaplygin_discrete_energy_converges (f.sys.L0, f.sys.Delta, dir,
                                                converges);
  int below_one = dir > 0 ? L0 > -Delta : L0 < 0.0;
  double e[12], p, pe;
  int n = 0;
  grow_expansion (e, &n, 2.0);
  chp_two_prod (L0, L0, &p, &pe);
  grow_expansion (e, &n, 2.0 * p);
  grow_expansion (e, &n, 2.0 * pe);
  chp_two_prod (L0, Delta, &p, &pe);
  grow_expansion (e, &n, p);
  grow_expansion (e, &n, pe);
  if (dir > 0)
    {
      grow_expansion (e, &n, 2.0 * p);
      grow_expansion (e, &n, 2.0 * pe);
      chp_two_prod (Delta, Delta, &p, &pe);
      grow_expansion (e, &n, p);
      grow_expansion (e, &n, pe);
    }
  *converges = below_one && expansion_sign (e, n) > 0;
  return CHAPLYGIN_SUCCESS;
}

/* chaplygin_discrete_final_velocity: (B.12) and its V < 0 counterpart
       V > 0:  Vf^2 = V^2 + (1 + L0^2) [1 - Delta/((L0 + Delta)
                      (2 + (L0 + Delta)(2 L0 + Delta)))] Omega^2,
       V < 0:  Vf^2 = V^2 + (1 + (L0 + Delta)^2) [1 + Delta/(L0
                      (2 + L0 (2 L0 + Delta)))] Omega^2,
   i.e. Vf^2 = V^2 + kappa (1 + l_s^2) Omega^2 = 2 E_f of (B.10), for the
   post-collision phase state (V, Omega) (peg at D = 0 if V > 0, Delta if
   V < 0), Vf with the sign of V.  The V > 0 form is correct as printed;
   the paper omits the other, which is its image under the reflection
   L0 -> -(L0 + Delta), V -> -V.  For L0 = -Delta/2, kappa = 0: Vf = V.
   Method: E and H by (3.3), (3.4); g(l_s) from V itself (accurate when
   V is small beside Omega), the path classified as by
   chaplygin_discrete_step.
   Accuracy: within 2 eps times (V^2 + max(1, |kappa|) H Omega)/Vf^2
   (measured 1.4 against binary128).
   Domain: finite; Delta > 0; V != 0.
   Errors: CHAPLYGIN_EINVAL (NULL), CHAPLYGIN_EDOM (non-finite, Delta <= 0;
   Omega != 0 with |C2| >= 1), CHAPLYGIN_ESTATE (V = 0, or the motion
   reverses), CHAPLYGIN_ESPIN, CHAPLYGIN_ERANGE (overflow, |l| > 2^500). */
int
chaplygin_discrete_final_velocity (double L0, double Delta, double V,
                                   double Omega, double *Vf)
{
  if (!Vf)
    return CHAPLYGIN_EINVAL;
  if (!chp_finite4 (L0, Delta, V, Omega) || !(Delta > 0.0))
    return CHAPLYGIN_EDOM;
  if (V == 0.0)
    return CHAPLYGIN_ESTATE;
  const int dir = V > 0.0 ? 1 : -1;
  chp_far f;
  CHP_TRY (chp_far_open (L0, Delta, &f));
  if (f.k)
    {
      /* far (lib/far.c): Omega scaled (m = 0: V and Vf unchanged) */
      double Om;
      if (!chp_far_in (&f, CHP_Q_RATE, Omega, &Om))
        return CHAPLYGIN_ERANGE;
      return chaplygin_discrete_final_velocity (f.sys.L0, f.sys.Delta, V, Om,
                                                Vf);
    }
  chaplygin_discrete sys;
  chp_run run;
  chp_motion m;
  double E, H;
  CHP_TRY (chaplygin_discrete_init (&sys, L0, Delta));
  CHP_TRY (chp_run_init (&sys, dir, &run));
  const double D = dir > 0 ? 0.0 : Delta;
  CHP_TRY (chaplygin_discrete_energy (L0, D, V, Omega, &E));
  CHP_TRY (chaplygin_discrete_momentum (L0, D, Omega, &H));
  if (Omega == 0.0)
    {
      *Vf = V;
      return CHAPLYGIN_SUCCESS;
    }
  CHP_TRY (chp_motion_init (E, H, &m));
  int fate = chp_segment_classify (&run.seg, &m, NULL);
  if (fate != CHP_SEGMENT_PASS)
    return fate_status (fate);
  if (!(run.omq > 0.0))
    return CHAPLYGIN_EDOM;
  /* kappa < 1: Vf^2 <= 2E, no overflow */
  double v2 = V * V + H * (run.kappa * Omega);
  if (v2 < 0.0)
    return CHAPLYGIN_ESTATE;
  *Vf = dir * sqrt (v2);
  return CHAPLYGIN_SUCCESS;
}

/* chaplygin_discrete_spin_sequence: (B.13), L0 = -Delta/2,
       V^2/Omega^2 = (1 + L0^2)^2 (C2^2n - 2 C1 (1 - C2^2n)/(1 - C2^2))
                     - (1 + L0^2)                       (as printed)
                   = L0^2 (1 + L0^2) C2^2n,
   C1 = -Delta^2/(2 (1 + L0^2)^3), C2 = (1 - L0^2)/(1 + L0^2): the
   post-collision state with this V^2/Omega^2 (either direction) reaches
   r = 2E/H^2 = 1 just after the n-th collision and then spins (3.8).
   Derivation: with a = L0^2 = Delta^2/4 both ends have 1 + l^2 = 1 + a, so
   (B.3) and (B.4) have the same C1, C2 and r' = (r + 2 C1)/C2^2 on every
   path.  Its fixed point is r* = -2 C1/(1 - C2^2) = 1/(1 + a), the bound
   (3.15): r_0 - r* = C2^2n (r_n - r*), and r_n = 1 gives r_0; V^2/Omega^2 =
   (1 + a)^2 r - (1 + a) = (1 + a)^2 (r - r*).  Every r_k, k < n, lies in
   (r*, 1): the path reverses each time.  The sequence decreases
   geometrically to 0 as n grows; the state just above (below) it settles
   into straight-line motion in the direction it has after n collisions
   (the opposite one).
   Method: the geometric form, C2^2n = exp(n log C2^2) with log |C2| by
   log1p where |C2| > 1/2.
   Accuracy: within ~(4 + n |log C2^2|) eps for the test's slot lengths
   (measured 0.85 x that); up to ~2 x that for |C2| just below 1/2, where
   log |C2| comes from a rounded |C2| (review: Delta = 1.1624, n = 134);
   a result in the subnormal range keeps only its leading digits.
   Domain: 0 < Delta finite, Delta <= 2^501.  For Delta = 2 (C2 = 0) only
   n = 0 exists.
   Errors: CHAPLYGIN_EINVAL (NULL), CHAPLYGIN_EDOM (Delta not finite or
   <= 0; Delta = 2 with n > 0), CHAPLYGIN_ERANGE (the value underflows to
   0 or overflows; Delta > 2^501). */
int
chaplygin_discrete_spin_sequence (double Delta, unsigned long n,
                                  double *v2_over_omega2)
{
  if (!v2_over_omega2)
    return CHAPLYGIN_EINVAL;
  if (!isfinite (Delta) || !(Delta > 0.0))
    return CHAPLYGIN_EDOM;
  const double a = 0.5 * Delta;         /* |L0| */
  if (a > CHP_L_MAX)
    return CHAPLYGIN_ERANGE;
  const double na = chp_one_plus_sq (a);
  double e2 = 0.0;              /* log C2^2n */
  if (n > 0)
    {
      if (a == 1.0)
        return CHAPLYGIN_EDOM;
      /* |C2| = |1 - a^2|/(1 + a^2); |C2| - 1 = -2 a^2/(1 + a^2) (a < 1)
         or -2/(1 + a^2) (a > 1) */
      double ac = fabs ((1.0 - a) * (1.0 + a)) / na;
      double lc = ac > 0.5 ? log1p (a < 1.0 ? -2.0 * (a * (a / na))
                                    : -2.0 / na)
        : log (ac);
      e2 = 2.0 * (double) n * lc;
    }
  /* a^2 (1 + a^2) C2^2n with the exponents kept apart (frexp, and
     e2 = jj ln 2 + r with ln 2 split as in fdlibm): no factor leaves the
     range of double unless the result does */
  const double ln2_hi = 6.93147180369123816490e-01;
  const double ln2_lo = 1.90821492927058770002e-10;
  int ea, en;
  const double ma = frexp (a, &ea), mn = frexp (na, &en);
  double jj = floor (e2 / 0x1.62e42fefa39efp-1);
  if (jj < -4096.0)
    jj = -4096.0;               /* the result underflows whatever a is */
  const double r = (e2 - jj * ln2_hi) - jj * ln2_lo;
  double v = ldexp (ma * ma * mn * exp (r), 2 * ea + en + (int) jj);
  if (!(v > 0.0) || !isfinite (v))
    return CHAPLYGIN_ERANGE;
  *v2_over_omega2 = v;
  return CHAPLYGIN_SUCCESS;
}
