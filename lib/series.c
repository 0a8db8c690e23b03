/* series.c -- kernel: a run of collisions without reversal and its
   series (series.h), shared by
   the reversal counts (reversal.c) and the energy series (energy.c).
   Uses eft.h and motion.c.

   Along a run, (B.3) is linear in (E, H^2): H' = C2 H, E' = E + C1 H^2,
   with C1, C2 fixed by the direction; so r = 2E/H^2 follows the affine map
   r' = (r + 2 C1)/C2^2, the energy the geometric series (B.9), and for
   |C2| < 1 tends to (B.10).  */
#include <config.h>

#include <math.h>

#include "eft.h"
#include "motion.h"
#include "series.h"

/* chp_run_init: the run of collisions without reversal in direction dir.
   Method: C2 is the system's (3.7) coefficient of the far end (the one
   chaplygin_discrete_step uses); C1 = -Delta^2/(2 (1 + l_f^2)^2
   (1 + l_s^2)) is formed without a square root (exact when its factors
   are).  C2 - 1 = -dir Delta l_f/(1 + l_f^2) and C2 + 1 = (2 + l_f s)/
   (1 + l_f^2), s = 2 L0 + Delta = l_s + l_f, are formed without the
   cancellation of C2 -+ 1 (2 + l_f s from the exact parts of l_f and s),
   so that 1 - C2^2 and log C2^2 keep their relative accuracy near
   C2 = +-1: within ~3 ulps.  log C2^2 is 2 log1p(|C2| - 1) for |C2| > 1/2,
   2 log |C2| otherwise (C2 within 2 ulps: log C2^2 within ~3 eps). */
int
chp_run_init (const chaplygin_discrete *sys, int dir, chp_run *run)
{
  if (dir != 1 && dir != -1)
    return CHAPLYGIN_EINVAL;
  if (!chp_finite2 (sys->L0, sys->Delta) || !(sys->Delta > 0.0))
    return CHAPLYGIN_EDOM;
  chp_run r;
  r.dir = dir;
  r.Delta = sys->Delta;
  chp_segment_init (sys, dir, &r.seg);
  if (fabs (r.seg.l0) > CHP_L_MAX || fabs (r.seg.l1) > CHP_L_MAX)
    return CHAPLYGIN_ERANGE;
  const double d = dir * sys->Delta;
  double s, s_err;              /* 2 L0 + Delta = s + s_err exactly */
  chp_two_sum (2.0 * sys->L0, sys->Delta, &s, &s_err);
  const double nf = chp_one_plus_sq_exact (r.seg.l1, r.seg.l1_err);
  const double ns = chp_one_plus_sq_exact (r.seg.l0, r.seg.l0_err);
  /* C1 = -Delta^2/(2 (1 + l_f^2)^2 (1 + l_s^2)), exact when its factors
     are (no square root, unlike chp_collision_coefficients) */
  r.C1 = -0.5 * (sys->Delta / nf) * (sys->Delta / nf) / ns;
  r.C2 = sys->C2[r.seg.far];
  r.s = s;
  /* 2 + l_f (2 L0 + Delta), cancelling near C2 = -1: from the exact
     parts of both factors */
  const double t
      = fma (r.seg.l1, s, 2.0) + (r.seg.l1 * s_err + r.seg.l1_err * s);
  r.c2m1 = -d * chp_L_over_one_plus_sq (r.seg.l1);
  r.c2p1 = t / nf;
  if (r.C2 == 0.0)
    {
      r.omq = 1.0;
      r.logq = -HUGE_VAL;
    }
  else
    {
      r.omq = -r.c2m1 * r.c2p1;
      /* log |C2| from |C2| - 1 where that is accurate, else from C2 */
      double ac = fabs (r.C2);
      r.logq = 2.0 * (ac > 0.5 ? log1p (r.C2 > 0.0 ? r.c2m1 : -r.c2p1)
                      : log (ac));
    }
  /* kappa = 1 + 2 C1 (1 + l_s^2)/(1 - C2^2): with 1 - C2^2 =
     d l_f t/(1 + l_f^2)^2 and 2 C1 (1 + l_s^2) = -d^2/(1 + l_f^2)^2.
     kappa < 1 where defined (C1 < 0 < 1 - C2^2).  With |l| <= 2^500 none
     of these overflows: |1 - C2^2| <= Delta |2 L0 + Delta|/4 < 2^1002. */
  r.kappa = r.omq > 0.0 ? 1.0 - d / (r.seg.l1 * t) : 0.0;
  *run = r;
  return CHAPLYGIN_SUCCESS;
}

/* |C2|^k = a 2^j and L = k log C2^2 (L = 0, a = 1, j = 0 for |C2| = 1);
   the power of 2 is split off where |L/2| > 300, so that |C2|^k does not
   underflow before the exponent of H is put back.  CHAPLYGIN_ERANGE where
   it exceeds 2^4096. */
static int
c2_power (const chp_run *run, double k, double *a, int *j, double *L)
{
  const double sign = run->C2 < 0.0 && fmod (k, 2.0) == 1.0 ? -1.0 : 1.0;
  *a = sign;
  *j = 0;
  *L = 0.0;
  if (run->omq == 0.0)
    return CHAPLYGIN_SUCCESS;
  *L = k * run->logq;
  double hl = 0.5 * *L;
  if (fabs (hl) > 300.0)
    {
      /* exp(hl) = 2^j exp(hl - j ln 2), ln 2 split as in fdlibm (the
         low 21 bits of ln2_hi are zero: j ln2_hi is exact for
         |j| < 2^21) */
      const double ln2 = 0x1.62e42fefa39efp-1;   /* log 2 rounded */
      const double ln2_hi = 6.93147180369123816490e-01;
      const double ln2_lo = 1.90821492927058770002e-10;
      double jj = floor (hl / ln2);
      if (jj > 4096.0)
        return CHAPLYGIN_ERANGE;
      if (jj < -4096.0)
        jj = -4096.0;           /* H_k underflows to 0 whatever H is */
      *j = (int) jj;
      hl = (hl - jj * ln2_hi) - jj * ln2_lo;
    }
  *a = sign * exp (hl);
  return CHAPLYGIN_SUCCESS;
}

/* chp_run_state: the (B.9) iterate (series.h).
   Method: S_k = (1 - q^k)/(1 - q) as expm1(k log q)/(q - 1), with log q
   = 2 log1p(|C2| - 1) and q - 1 = (C2 - 1)(C2 + 1) from the accurate
   factors of chp_run_init: no cancellation when q is near 1 and no
   rounding growth with k beyond that of k log q; |H_k| = exp(k log q / 2)
   |H|.  For q > 1, H^2 S_k = H_k^2 (1 - q^-k)/(q - 1), so that neither
   H^2 (H tiny) nor S_k (k log q large) leaves the range of double while
   the iterate is a state; H = m 2^e is scaled exactly (frexp, ldexp).
   Accuracy: S_k within ~(4 + |k log q|) eps, H_k within ~(4 + 1.5 |k log q|)
   eps (log q within ~3 eps, relatively; measured 1.2 x that bound).
   CHAPLYGIN_ERANGE where H_k or E_k overflows: beyond the first
   reversal of a run, for a valid state. */
int
chp_run_state (const chp_run *run, double E, double H, double k, double *Ek,
               double *Hk)
{
  if (k == 0.0 || H == 0.0)
    {
      *Ek = E;
      *Hk = H;
      return CHAPLYGIN_SUCCESS;
    }
  int eh, j, jt = 0;            /* T carries the exponent 2^-2(eh+jt) */
  const double m = frexp (H, &eh);
  double a, L, T;               /* C2^k (times 2^-j); C1 H^2 S_k 2^-2(eh+jt) */
  CHP_TRY (c2_power (run, k, &a, &j, &L));
  if (run->omq == 0.0)
    T = run->C1 * m * m * k;    /* |C2| = 1: S_k = k */
  else if (L <= 0.0)
    T = run->C1 * m * m * (expm1 (L) / -run->omq);
  else
    {
      double ma = m * a;
      jt = j;
      T = run->C1 * ma * ma * (-expm1 (-L) / -run->omq);
    }
  double h = ldexp (m * a, eh + j);
  double e = E + ldexp (T, 2 * (eh + jt));
  if (!isfinite (e) || !isfinite (h))
    return CHAPLYGIN_ERANGE;
  *Ek = e;
  *Hk = h;
  return CHAPLYGIN_SUCCESS;
}

/* chp_run_momentum: H_k alone (series.h). */
int
chp_run_momentum (const chp_run *run, double H, double k, double *Hk)
{
  if (k == 0.0 || H == 0.0)
    {
      *Hk = H;
      return CHAPLYGIN_SUCCESS;
    }
  int eh, j;
  const double m = frexp (H, &eh);
  double a, L;
  CHP_TRY (c2_power (run, k, &a, &j, &L));
  double h = ldexp (m * a, eh + j);
  if (!isfinite (h))
    return CHAPLYGIN_ERANGE;
  *Hk = h;
  return CHAPLYGIN_SUCCESS;
}

/* chp_run_final_energy: (B.10) in the form of (B.12) (series.h). */
double
chp_run_final_energy (const chp_run *run, double E, double g0, double H)
{
  double ns = chp_one_plus_sq_exact (run->seg.l0, run->seg.l0_err);
  return E * (g0 / ns) + 0.5 * H * (H / ns) * run->kappa;
}
