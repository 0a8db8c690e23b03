/* printed.c -- the paper's printed forms, for audit (manual, "The paper's
   printed forms"; errata chapter).

   Where an erratum gives the paper's printed form as a formula that can be
   evaluated, a function chaplygin_printed_X evaluates that formula beside
   the library's corrected chaplygin_X, with the same signature wherever
   that makes sense, so that a caller (the program's "chaplygin eq") can
   print both and their difference.  These are NOT the dynamics: every
   other function of the library implements the corrected forms.

   Each function is thin: it validates its arguments as the corrected
   function does (mostly by calling it) and then applies the printed
   formula, written where possible as an exact identity between the printed
   and the corrected forms, so that it inherits their accuracy:
     (2.1)         dS/dtau = V instead of |V|;
     (A.1), (A.6)  S_c = S0 - sgn(L) sigma_c, sigma_c the arc length to the
                   reversal that the corrected form computes;
     (A.2)-(A.4)   with the printed K, the printed closed form is the
                   corrected one started from (K |V0|, |Omega0|), its
                   Omega (H_C) given back the sign of Omega0 (H0);
     (3.11/12)     the corrected criterion and the middle expression > 0;
     (4.1)         c2 = (2/3) c0 c1;
     (B.2), (B.3)  the magnitude of the corrected heading, the sign of
                   the direction of integration;
     (B.6)         the printed logarithm, from the accurate pieces of the
                   (B.3) run;
     (B.8)         MIN: at least one end of the slot inside the range;
     (B.9)         E_n + C1 H_n^2, the (n + 1)-th term of the printed sum;
     (B.16)        the no-reversal coefficient on every segment.
   Where the printed formula is undefined as written (a division by zero,
   the logarithm of a number <= 0) the functions return CHAPLYGIN_EDOM;
   where the paper gives no formula for an output (the time of (A.2) and
   (B.2)) they refuse to compute it (CHAPLYGIN_EINVAL for a non-null
   pointer).  */
#include <config.h>

#include <limits.h>
#include <math.h>
#include <stddef.h>

#include "chaplygin.h"
#include "eft.h"
#include "far.h"
#include "motion.h"
#include "series.h"

/* The largest count the printed (B.6) returns: 2^62, as the corrected
   chaplygin_discrete_collisions_before_reversal (or ULONG_MAX if smaller). */
#define PRINTED_N_MAX                                                   \
  (ULONG_MAX < 0x4000000000000000ULL ? (unsigned long) ULONG_MAX        \
   : (unsigned long) 0x4000000000000000ULL)

/* ---- Section 2 and Appendix A: the smooth sleigh ---------------------- */

/* chaplygin_printed_smooth_field: (2.1) as printed (erratum E1)
       dS/dtau = V,  dV/dtau = L Omega^2,  dtheta/dtau = Omega,
       dOmega/dtau = -L V Omega/(1 + L^2).
   Differs from chaplygin_smooth_field (dS/dtau = |V|, S arc length) only
   in the first component and only for V < 0; the other three components
   are those of chaplygin_smooth_field, bit for bit.
   Domain, errors: as chaplygin_smooth_field (CHAPLYGIN_EINVAL,
   CHAPLYGIN_EDOM, CHAPLYGIN_ERANGE). */
int
chaplygin_printed_smooth_field (double L, const double q[4], double dq[4])
{
  double r[4];
  if (!dq)
    return CHAPLYGIN_EINVAL;
  CHP_TRY (chaplygin_smooth_field (L, q, r));
  r[CHAPLYGIN_S] = q[CHAPLYGIN_V];
  for (int i = 0; i < 4; i++)
    dq[i] = r[i];
  return CHAPLYGIN_SUCCESS;
}

/* chaplygin_printed_smooth_reversal: (A.1) as printed (erratum E3)
       S_c = S0 - (1 + L^2)/(2L) ln(1 + V0^2/(Omega0^2 (1 + L^2))),
   S0 = q0[S]; the paper states it for V0 > 0 and "the change in sign of
   velocity for L < 0".
   *reverses = 1 iff L < 0 (the paper's condition; the sign of V0 plays no
   part), and, unlike chaplygin_smooth_reversal, *Sc is written whenever
   the formula is defined, whether or not the paper's condition holds, so
   that its value can be compared (erratum E3's example has L > 0).
   Agrees with the corrected form (reversal iff L V0 < 0, Omega0 != 0, at
   S0 + (1 + L^2)/(2|L|) ln(...)) for V0 > 0; for V0 < 0 and L > 0 the
   motion reverses but the printed S_c = 2 S0 - S_c(corrected) lies before
   the start (L = 1, V0 = -1, Omega0 = 0.3, S0 = 2: 0.1197 instead of
   3.8803); for V0 < 0 and L < 0 it reports a reversal that does not
   happen.  V0 = 0 gives S_c = S0.
   Method: S_c = S0 - sgn(L) sigma_c, with sigma_c = (1 + L^2)/(2|L|)
   ln(...) >= 0 (the same logarithm) from chaplygin_smooth_reversal for
   the direction that reverses: one more rounding than the corrected form.
   Domain: finite L and q0; L != 0 and Omega0 != 0 (the formula divides by
   both).
   Errors: CHAPLYGIN_EINVAL (NULL), CHAPLYGIN_EDOM (non-finite, L = 0,
   Omega0 = 0), CHAPLYGIN_ERANGE (S_c overflows). */
int
chaplygin_printed_smooth_reversal (double L, const double q0[4],
                                   int *reverses, double *Sc)
{
  if (!q0 || !reverses || !Sc)
    return CHAPLYGIN_EINVAL;
  if (!isfinite (L) || !chp_finite4 (q0[0], q0[1], q0[2], q0[3])
      || L == 0.0 || q0[CHAPLYGIN_OMEGA] == 0.0)
    return CHAPLYGIN_EDOM;
  /* the start turned towards the reversal (V0 of the sign of -L) from
     S = 0: its S_c is sigma_c (left 0 if V0 = 0: no reversal, ln 1 = 0) */
  const double V0 = fabs (q0[CHAPLYGIN_V]);
  const double p[4] = { 0.0, L < 0.0 ? V0 : -V0, 0.0, q0[CHAPLYGIN_OMEGA] };
  int rev;
  double sigma = 0.0;
  CHP_TRY (chaplygin_smooth_reversal (L, p, &rev, &sigma));
  const double s = q0[CHAPLYGIN_S] - chp_sign (L) * sigma;
  if (!isfinite (s))
    return CHAPLYGIN_ERANGE;
  *reverses = L < 0.0;
  *Sc = s;
  return CHAPLYGIN_SUCCESS;
}

/* chaplygin_printed_smooth_reversal_eh: (A.6) as printed (erratum E3)
       S_c = S0 - (1 + L^2)/(2L) ln(2 E0 (1 + L^2)/H0^2).
   *reverses = 1 iff L < 0; *Sc written whenever the formula is defined,
   as chaplygin_printed_smooth_reversal, to which it is equal for the
   state (E0, H0) (with V0^2 = 2 E0 - H0^2/(1 + L^2)).  dir0 (the sign of
   V0) does not enter the printed formula; it is validated as by
   chaplygin_smooth_reversal_eh.
   Method: S_c = S0 - sgn(L) sigma_c, sigma_c from
   chaplygin_smooth_reversal_eh.
   Domain: finite; E0 >= H0^2/(2 (1 + L^2)); dir0 = +-1; L != 0 and
   H0 != 0 (the formula divides by both).
   Errors: CHAPLYGIN_EINVAL (NULL, dir0), CHAPLYGIN_EDOM (non-finite,
   E0 < 0, L = 0, H0 = 0), CHAPLYGIN_ESTATE (V0^2 < 0), CHAPLYGIN_ERANGE. */
int
chaplygin_printed_smooth_reversal_eh (double L, double S0, double E0,
                                      double H0, int dir0, int *reverses,
                                      double *Sc)
{
  if (!reverses || !Sc || (dir0 != 1 && dir0 != -1))
    return CHAPLYGIN_EINVAL;
  if (!chp_finite4 (L, S0, E0, H0) || !(E0 >= 0.0) || L == 0.0 || H0 == 0.0)
    return CHAPLYGIN_EDOM;
  int rev;
  double sigma = 0.0;
  CHP_TRY (chaplygin_smooth_reversal_eh (L, 0.0, E0, H0, L < 0.0 ? 1 : -1,
                                         &rev, &sigma));
  const double s = S0 - chp_sign (L) * sigma;
  if (!isfinite (s))
    return CHAPLYGIN_ERANGE;
  *reverses = L < 0.0;
  *Sc = s;
  return CHAPLYGIN_SUCCESS;
}

/* The printed K of (A.3) at arc length S for the start q0 (L != 0;
   Omega0 != 0 if L < 0): 1 for L > 0; for L < 0, 1 up to the printed S_c
   (A.1) and -1 beyond it.  sigma_c is that of chaplygin_smooth_reversal
   from S = 0 and S - S0 is compared with it as chaplygin_smooth_closed_form
   compares them, so that the K used below and the corrected closed form
   agree about the side of S_c. */
static int
printed_K (double L, const double q0[4], double S, int *K)
{
  if (L > 0.0)
    {
      *K = 1;
      return CHAPLYGIN_SUCCESS;
    }
  const double p[4] = { 0.0, fabs (q0[CHAPLYGIN_V]), 0.0,
                         fabs (q0[CHAPLYGIN_OMEGA]) };
  int rev;
  double sigma = 0.0;           /* V0 = 0: S_c = S0 */
  CHP_TRY (chaplygin_smooth_reversal (L, p, &rev, &sigma));
  *K = S - q0[CHAPLYGIN_S] > sigma ? -1 : 1;
  return CHAPLYGIN_SUCCESS;
}

/* chaplygin_printed_smooth_branch: (A.3) as printed (erratum E7), for
   V0 > 0 in the paper and applied here to either sign of V0 (as errata
   E4 and E6 evaluate it):
       K = 1 for S > S0 and L > 0;  K = 1 for S < S_c and L < 0;
       K = -1 for S > S_c and L < 0,
   S_c the printed (A.1); K = 1 at S = S0 and at S = S_c.
   Agrees with chaplygin_smooth_branch (K = sgn(V(S)/V0)) for V0 > 0; for
   V0 < 0 it is -1 beyond the printed S_c when L < 0 (the motion does not
   reverse) and never -1 when L > 0 (it does); for V0 = 0 and L < 0 it is
   -1 for every S > S0.
   Domain: as chaplygin_smooth_closed_form (finite, S >= S0); L != 0 (K is
   not defined); Omega0 != 0 when L < 0 (S_c is not defined).
   Errors: CHAPLYGIN_EINVAL (NULL), CHAPLYGIN_EDOM (non-finite, S < S0,
   L = 0, L < 0 with Omega0 = 0), CHAPLYGIN_ERANGE (S_c overflows). */
int
chaplygin_printed_smooth_branch (double L, const double q0[4], double S,
                                 int *K)
{
  if (!q0 || !K)
    return CHAPLYGIN_EINVAL;
  if (!isfinite (L) || !chp_finite4 (q0[0], q0[1], q0[2], q0[3])
      || !isfinite (S) || !(S >= q0[CHAPLYGIN_S]) || L == 0.0
      || (L < 0.0 && q0[CHAPLYGIN_OMEGA] == 0.0))
    return CHAPLYGIN_EDOM;
  return printed_K (L, q0, S, K);
}

/* chaplygin_printed_smooth_closed_form: (A.2) as printed, with the
   parenthesis of erratum E4 read as intended (typesetting), K in the
   exponents (E4), the printed K of (A.3) (E5, E7) and no sign factor in
   the heading (E6):
       V(S) = K sqrt(V0^2 + Omega0^2 (1 + L^2) (1 - exp(-2 K a (S - S0)))),
       theta(S) = theta0 + K (sqrt(1 + L^2)/L)
                  [arcsin(k) - arcsin(k exp(-K a (S - S0)))],
       Omega(S) = Omega0 exp(-K a (S - S0)),
   a = L/(1 + L^2), k = 1/sqrt(V0^2/(Omega0^2 (1 + L^2)) + 1), K of
   chaplygin_printed_smooth_branch.  q = {S, V, theta, Omega}.
   Agrees with chaplygin_smooth_closed_form for V0 > 0, Omega0 > 0 up to
   S_c.  Differs: for V0 < 0 (V has the sign of K, not of V0, and the
   exponents the sign of K: L = 1, V0 = -1, Omega0 = 0.3, S - S0 = 1 gives
   V = +1.0554, Omega = 0.1820, theta - theta0 = 0.2292; the motion has
   -0.83109, 0.49462, 0.42198); for Omega0 < 0 (the heading turns the
   wrong way); beyond S_c (E5: the exponents reflected about S0, not S_c:
   for L = -sqrt(2), V0 = 1, Omega0 = 0.1, S0 = 0, Omega jumps from 0.586
   to 0.0171 and V from 0 to -1.014 at S_c = 3.7506).
   Method: the identity: with this K, the printed form is the corrected
   closed form started from V0' = K |V0|, Omega0' = |Omega0|, which does
   not reverse on [S0, S] (exponents -K a (S - S0), V of the sign K,
   heading sgn(V0' Omega0') (sqrt(1 + L^2)/L) [...] = K (...)), with Omega
   multiplied by sgn(Omega0).  So V, theta and Omega are those of
   chaplygin_smooth_closed_form (within 3 eps), and V = 0 at S_c exactly
   where the printed radicand vanishes.
   Time: the paper gives no tau(S): dtau must be NULL.
   Domain: finite; S >= S0; L != 0 and Omega0 != 0 (the formula divides by
   L and, in k, by Omega0).
   Errors: CHAPLYGIN_EINVAL (NULL q0 or q, non-null dtau), CHAPLYGIN_EDOM
   (non-finite, S < S0, L = 0, Omega0 = 0), CHAPLYGIN_ERANGE. */
int
chaplygin_printed_smooth_closed_form (double L, const double q0[4], double S,
                                      double q[4], double *dtau)
{
  if (!q0 || !q || dtau)
    return CHAPLYGIN_EINVAL;
  if (!isfinite (L) || !chp_finite4 (q0[0], q0[1], q0[2], q0[3])
      || !isfinite (S) || !(S >= q0[CHAPLYGIN_S]) || L == 0.0
      || q0[CHAPLYGIN_OMEGA] == 0.0)
    return CHAPLYGIN_EDOM;
  int K;
  CHP_TRY (printed_K (L, q0, S, &K));
  const double Om0 = q0[CHAPLYGIN_OMEGA];
  const double p0[4] = { q0[CHAPLYGIN_S], K * fabs (q0[CHAPLYGIN_V]),
                         q0[CHAPLYGIN_THETA], fabs (Om0) };
  double r[4];
  CHP_TRY (chaplygin_smooth_closed_form (L, p0, S, r, NULL));
  q[CHAPLYGIN_S] = S;
  q[CHAPLYGIN_V] = r[CHAPLYGIN_V];
  q[CHAPLYGIN_THETA] = r[CHAPLYGIN_THETA];
  q[CHAPLYGIN_OMEGA] = chp_sign (Om0) * r[CHAPLYGIN_OMEGA];
  return CHAPLYGIN_SUCCESS;
}

/* chaplygin_printed_smooth_closed_form_eh: (A.4) as printed (errata E5,
   E6), p = {S, E, theta, H_C}:
       E(S) = E0,
       theta(S) = theta0 + K (sqrt(1 + L^2)/L)
                  [arcsin(1/sqrt(2 E0 (1 + L^2)/H0^2))
                   - arcsin(exp(-K a (S - S0))/sqrt(2 E0 (1 + L^2)/H0^2))],
       H_C(S) = H0 exp(-K a (S - S0)),
   with the printed K of (A.3), its S_c that of the printed (A.6).  It is
   the printed (A.2) for the phase state (V0, H0/(1 + L^2)) of either sign
   of V0: dir0 does not enter the printed formula and is validated only,
   as by chaplygin_smooth_closed_form_eh.
   Agrees with chaplygin_smooth_closed_form_eh for V0 > 0, H0 > 0 before
   S_c; differs for H0 < 0 (heading), for V0 < 0 (exponents and heading)
   and beyond S_c (E5).
   Method: chaplygin_smooth_closed_form_eh from (E0, |H0|) with
   dir0' = K (the identity of chaplygin_printed_smooth_closed_form), H_C
   given back the sign of H0.  K is decided with the S_c of (A.6); where
   the closed form's own S_c (from the phase state) differs from it by
   rounding, S lies within rounding of both, where V = 0 and the values
   are continuous.
   Domain: finite; S >= S0; E0 >= H0^2/(2 (1 + L^2)); dir0 = +-1 (any value
   when V0 = 0); L != 0 and H0 != 0 (the formula divides by both).
   Errors: CHAPLYGIN_EINVAL (NULL, dir0), CHAPLYGIN_EDOM (non-finite,
   S < S0, E0 < 0, L = 0, H0 = 0), CHAPLYGIN_ESTATE (V0^2 < 0),
   CHAPLYGIN_ERANGE. */
int
chaplygin_printed_smooth_closed_form_eh (double L, const double p0[4],
                                         int dir0, double S, double p[4])
{
  double r[4];
  if (!p0 || !p)
    return CHAPLYGIN_EINVAL;
  if (!isfinite (S))
    return CHAPLYGIN_EDOM;
  /* the corrected form's validation (at S0: no motion computed) */
  CHP_TRY (chaplygin_smooth_closed_form_eh (L, p0, dir0, p0[CHAPLYGIN_S], r));
  const double S0 = p0[CHAPLYGIN_S], E0 = p0[CHAPLYGIN_E];
  const double H0 = p0[CHAPLYGIN_H];
  if (!(S >= S0) || L == 0.0 || H0 == 0.0)
    return CHAPLYGIN_EDOM;
  int K = 1;
  if (L < 0.0)
    {
      int rev;
      double sigma = 0.0;       /* V0 = 0: S_c = S0 */
      CHP_TRY (chaplygin_smooth_reversal_eh (L, 0.0, E0, fabs (H0), 1, &rev,
                                             &sigma));
      K = S - S0 > sigma ? -1 : 1;
    }
  const double pa[4] = { S0, E0, p0[CHAPLYGIN_THETA], fabs (H0) };
  CHP_TRY (chaplygin_smooth_closed_form_eh (L, pa, K, S, r));
  p[CHAPLYGIN_S] = S;
  p[CHAPLYGIN_E] = E0;
  p[CHAPLYGIN_THETA] = r[CHAPLYGIN_THETA];
  p[CHAPLYGIN_H] = chp_sign (H0) * r[CHAPLYGIN_H];
  return CHAPLYGIN_SUCCESS;
}

/* ---- Section 3 and 4: stability --------------------------------------- */

/* chaplygin_printed_discrete_stable: (3.11) (dir +1) and (3.12) (dir -1)
   as printed, read as chains (erratum E12), x = L0/Delta,
   y = (1/Delta)^2:
       (3.11)  x > -1  and  y > -(1/2)(1 + 2x)(1 + x) > 0,
       (3.12)  x < 0   and  y > -(1/2) x (1 + 2x) > 0,
   the trailing "> 0" a third condition: the middle expression positive,
   i.e. -1 < x < -1/2 (dir +1), -1/2 < x < 0 (dir -1).
   *stable = 1 iff chaplygin_discrete_stable says stable (|sigma4| < 1) and
   that condition holds.  Agrees where the middle expression is positive;
   elsewhere the printed chain calls every motion unstable (Figure 6's
   skate, L0 = 1, Delta = 1/3, x = 3: printed unstable, sigma4 = 21/25).
   Method: 2 L0 against -Delta, exact.
   Domain, errors: as chaplygin_discrete_stable (CHAPLYGIN_EINVAL,
   CHAPLYGIN_EDOM, CHAPLYGIN_ERANGE). */
int
chaplygin_printed_discrete_stable (double L0, double Delta, int dir,
                                   int *stable)
{
  int st;
  if (!stable)
    return CHAPLYGIN_EINVAL;
  CHP_TRY (chaplygin_discrete_stable (L0, Delta, dir, &st));
  /* the middle expression > 0: (1 + 2x)(1 + x) < 0 or x (1 + 2x) < 0 */
  const int middle = dir > 0 ? L0 > -Delta && 2.0 * L0 < -Delta
    : L0 < 0.0 && 2.0 * L0 > -Delta;
  *stable = st && middle;
  return CHAPLYGIN_SUCCESS;
}

/* chaplygin_printed_discrete_xi4_taylor: (4.1) as printed (erratum E13)
       xi4 = V* [ -L0/(1 + L0^2) + (1/2)(L0^2 - 2)/(1 + L0^2)^2 Delta
                  - (1/3) L0 (L0^2 - 2)/(1 + L0^2)^3 Delta^2 + O(Delta^3) ],
   c = {c0, c1, c2}.  c0 and c1 are those of chaplygin_discrete_xi4_taylor
   (right); c2 differs (correct: L0 (6 - L0^2)/(3 (1 + L0^2)^3); at L0 = 1
   the printed 1/24, the correct 5/24): the difference is 4 L0/(3 a^3),
   a = 1 + L0^2, so they agree only at L0 = 0.
   The paper gives the series for V* > 0 only: dir = -1 is
   CHAPLYGIN_EDOM.
   Method: c2 = (2/3) c0 c1 exactly in real arithmetic, from the library's
   c0 and c1 (no overflow for large |L0|): within ~3 ulps.
   Errors: CHAPLYGIN_EINVAL (NULL, dir not +-1), CHAPLYGIN_EDOM (L0 not
   finite, dir = -1). */
int
chaplygin_printed_discrete_xi4_taylor (double L0, int dir, double c[3])
{
  double r[3];
  if (!c)
    return CHAPLYGIN_EINVAL;
  CHP_TRY (chaplygin_discrete_xi4_taylor (L0, dir, r));
  if (dir < 0)
    return CHAPLYGIN_EDOM;
  c[0] = r[0];
  c[1] = r[1];
  c[2] = (2.0 * r[0]) * r[1] / 3.0;
  return CHAPLYGIN_SUCCESS;
}

/* ---- Appendix B: the discrete skate ----------------------------------- */

/* chaplygin_printed_discrete_heading: (B.2) as printed (erratum E9)
       theta(D) - theta0 = Int_D0^D dD' / sqrt( n(D')/n0
                             [ (V0/Omega0)^2 n(D')/n0
                               + (D' - D0)(2 L0 + D' + D0) ] ),
   n(D) = 1 + (L0 + D)^2, n0 = n(D0).  The integrand is positive, so the
   printed increment is sgn(D - D0) |dtheta|, where the heading turns with
   the sign of Omega0: chaplygin_discrete_heading gives sgn(Omega0)
   |dtheta|.  They agree when D - D0 (i.e. V0) and Omega0 have the same
   sign and differ in sign otherwise (backward motion with Omega0 > 0).
   Method: |dtheta| of chaplygin_discrete_heading (the magnitude is the
   same integral; opt chooses its method: closed form, quadrature, ODE),
   signed by D - D0.  D = D0 gives 0.
   Time: (B.2) gives none: dtau must be NULL.
   Domain: as chaplygin_discrete_heading; Omega0 != 0 ((V0/Omega0)^2 is
   undefined: for Omega0 = 0 the heading is constant, erratum E9).
   Errors: CHAPLYGIN_EINVAL (NULL dtheta, non-null dtau, options),
   CHAPLYGIN_EDOM (non-finite, Omega0 = 0), and the statuses of
   chaplygin_discrete_heading (CHAPLYGIN_ESTATE, CHAPLYGIN_ESPIN,
   CHAPLYGIN_ERANGE, CHAPLYGIN_ENOCONV). */
int
chaplygin_printed_discrete_heading (double L0, double D0, double V0,
                                    double Omega0, double D,
                                    const chaplygin_options *opt,
                                    double *dtheta, double *dtau)
{
  double th;
  if (!dtheta || dtau)
    return CHAPLYGIN_EINVAL;
  CHP_TRY (chaplygin_discrete_heading (L0, D0, V0, Omega0, D, opt, &th,
                                       NULL));
  if (Omega0 == 0.0)
    return CHAPLYGIN_EDOM;
  *dtheta = D < D0 ? -fabs (th) : fabs (th);
  return CHAPLYGIN_SUCCESS;
}

/* chaplygin_printed_discrete_f3: the heading increment f3(E, H) of (B.3)
   as printed (erratum E10; the upper limit "Delta ^iD^+" read as
   Delta - ^iD^+, typesetting):
       f3 = Int_(D+)^(Delta - D+) dD' / sqrt((1 + (L0 + D')^2)
               [2 E (1 + (L0 + D')^2)/H^2 - 1]),
   for the post-collision state (dir, E, H) of the system: D+ = 0 for
   dir = +1, Delta for dir = -1, and a segment without velocity reversal.
   The integrand is positive, so f3 = sgn(Delta - 2 D+) |f3| = dir |f3|,
   whatever the sign of H; the heading increment of the step
   (chaplygin_discrete_step, ev->dtheta) is sgn(H) |f3|.  They agree when
   dir and H have the same sign.
   Method: |ev->dtheta| of chaplygin_discrete_step for this state (the
   same integral; opt chooses its method), signed by dir.
   Domain: as chaplygin_discrete_step; H != 0 (the integrand divides by
   H^2); the segment must not reverse ((B.3) does not apply, and the
   heading line of (B.4) is garbled, erratum E11).
   Errors: CHAPLYGIN_EINVAL (NULL, dir, options), CHAPLYGIN_EDOM
   (non-finite, E < 0, H = 0), CHAPLYGIN_ESTATE (E = 0, V+^2 <= 0, or the
   segment reverses), and those of chaplygin_discrete_step
   (CHAPLYGIN_ESPIN, CHAPLYGIN_ERANGE, CHAPLYGIN_ENOCONV). */
int
chaplygin_printed_discrete_f3 (const chaplygin_discrete *sys, int dir,
                               double E, double H,
                               const chaplygin_options *opt, double *f3)
{
  if (!sys || !f3)
    return CHAPLYGIN_EINVAL;
  const chaplygin_discrete_state in = { dir, E, H, 0.0, 0.0, { 0.0, 0.0 }, 0.0 };
  chaplygin_discrete_state out;
  chaplygin_discrete_event ev;
  CHP_TRY (chaplygin_discrete_step (sys, &in, CHAPLYGIN_WANT_THETA, opt, &out,
                                    &ev));
  if (H == 0.0)
    return CHAPLYGIN_EDOM;
  if (ev.reversal)
    return CHAPLYGIN_ESTATE;
  *f3 = dir * fabs (ev.dtheta);
  return CHAPLYGIN_SUCCESS;
}

/* chaplygin_printed_discrete_collisions_before_reversal: (B.6) as printed
   (erratum E20), with C1, C2 of (B.3) and C3 of (B.7) for the state's
   direction:
       n = floor( log[1 + (1 - C2^2)/C3 (2E/H^2 (1 + (L0 + D+)^2) - 1)]
                  / log C2^2 ).
   *reverses = 1 and *n written when the value is >= 0; *reverses = 0
   (*n untouched) when it is negative (the printed count of a path moving
   away from l = 0: no reversal ahead).
   Agrees with chaplygin_discrete_collisions_before_reversal outside the
   slot (L0 > 0, L0 < -Delta) for the direction that moves towards the
   mass centre, except where the ratio of logarithms is an exact integer
   (the turning point exactly at the far end: the printed floor counts
   that path as a collision); inside the slot (-Delta < L0 < 0) it
   overcounts, or takes the logarithm of a number <= 0.  It knows nothing
   of the spinning state (3.8): no CHAPLYGIN_ESPIN.
   Method: with r = 2E/H^2 and g = 1 + l_s^2 - 1/r (the state's
   V+^2 (1 + l_s^2)/(2E), by error-free arithmetic), the argument is
   1 + z, z = (1 - C2^2) r g/C3, taken through log1p; 1 - C2^2 and
   log C2^2 come from the run's factored C2 - 1, C2 + 1 (no cancellation
   near |C2| = 1); C3 from chaplygin_discrete_c3.  A far slot (|l| >
   2^500) is scaled as by the corrected function (the formula is
   scale-free there).  Accuracy: the logarithm ratio within a few eps
   times its condition; floor() then exact unless the ratio is within
   that of an integer (and n is not resolved to units beyond 2^53).
   Domain: a valid system, dir = +-1, a valid state (E > 0, V+^2 > 0);
   H != 0 (2E/H^2), C3 != 0 (2 L0 + Delta != 0), C2^2 != 1 and C2 != 0
   (log C2^2 must be finite and nonzero), argument > 0.
   Errors: CHAPLYGIN_EINVAL (NULL, dir), CHAPLYGIN_EDOM (non-finite,
   E < 0, or the formula undefined as above), CHAPLYGIN_ESTATE (E = 0,
   V+^2 <= 0), CHAPLYGIN_ERANGE (n > 2^62, |l| beyond the far-slot
   scaling). */
int
chaplygin_printed_discrete_collisions_before_reversal
  (const chaplygin_discrete *sys, int dir, double E, double H, int *reverses,
   unsigned long *n)
{
  if (!sys || !reverses || !n || (dir != 1 && dir != -1))
    return CHAPLYGIN_EINVAL;
  chp_far far;
  CHP_TRY (chp_far_open_sys (sys, &far));
  if (far.k)
    {
      double Es, Hs;
      if (!chp_finite2 (E, H) || E < 0.0)
        return CHAPLYGIN_EDOM;
      CHP_TRY (chp_far_state (&far, E, H, 0, &Es, &Hs));
      return chaplygin_printed_discrete_collisions_before_reversal
        (&far.sys, dir, Es, Hs, reverses, n);
    }
  chp_run run;
  chp_motion m;
  double C3;
  /* dir, the system and the cap (k = 0) are checked above: neither
     chp_run_init nor chaplygin_discrete_c3 can fail */
  (void) chp_run_init (sys, dir, &run);
  CHP_TRY (chp_motion_init (E, H, &m));
  const double g = chp_motion_g_exact (&m, run.seg.l0, run.seg.l0_err);
  if (!(g > 0.0))
    return CHAPLYGIN_ESTATE;
  (void) chaplygin_discrete_c3 (sys->L0, sys->Delta, dir, &C3);
  if (H == 0.0 || C3 == 0.0 || run.logq == 0.0 || !isfinite (run.logq))
    return CHAPLYGIN_EDOM;
  /* 2E/H^2 (1 + l_s^2) - 1 = r g = g/h^2 (divided twice: h^2 may
     underflow where g/h^2 does not overflow) */
  const double z = (run.omq / C3) * ((g / m.h) / m.h);
  if (!(z > -1.0))
    return CHAPLYGIN_EDOM;
  const double x = log1p (z) / run.logq;
  if (x < 0.0)
    {
      *reverses = 0;
      return CHAPLYGIN_SUCCESS;
    }
  if (!(x < (double) PRINTED_N_MAX))
    return CHAPLYGIN_ERANGE;
  *reverses = 1;
  *n = (unsigned long) floor (x);
  return CHAPLYGIN_SUCCESS;
}

/* chaplygin_printed_discrete_two_turning_points: (B.8) as printed
   (erratum E21), in its context -Delta < L0 < 0:
       MIN{1/(1 + L0^2), 1/(1 + (L0 + Delta)^2)} < 2E/H^2 < 1
   ("then (B.5) has two relevant solutions").  *two = 1 iff -Delta < L0 < 0
   and that holds; 0 outside the slot (the paper's context; the corrected
   condition is never met there either).
   Agrees with chaplygin_discrete_two_turning_points (MAX) when both or
   neither end satisfies r > 1/(1 + l^2); between MIN and MAX the printed
   form says two where one turning point lies in the slot.
   Method: r > 1/(1 + l^2) iff g(l) = 1 + l^2 - 1/r > 0 at an end, and
   r < 1 iff 2E < H^2, all signs exact (error-free arithmetic), as the
   corrected function decides them.
   Domain, errors: as chaplygin_discrete_two_turning_points
   (CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM, CHAPLYGIN_ESTATE, CHAPLYGIN_ERANGE);
   H = 0 (r infinite) gives 0. */
int
chaplygin_printed_discrete_two_turning_points (double L0, double Delta,
                                               double E, double H, int *two)
{
  int t;
  if (!two)
    return CHAPLYGIN_EINVAL;
  CHP_TRY (chaplygin_discrete_two_turning_points (L0, Delta, E, H, &t));
  if (!(L0 < 0.0 && -L0 < Delta))
    {
      *two = 0;
      return CHAPLYGIN_SUCCESS;
    }
  /* validated above: a slot about l = 0 is within the cap (a far slot has
     ends of one sign), E > 0 and finite; neither call can fail */
  chaplygin_discrete sys;
  chp_motion m;
  (void) chaplygin_discrete_init (&sys, L0, Delta);
  (void) chp_motion_init (E, H, &m);
  *two = m.one_minus_h2 < 0.0
    && (chp_motion_g_exact (&m, sys.l_end[0], sys.l_err[0]) > 0.0
        || chp_motion_g_exact (&m, sys.l_end[1], sys.l_err[1]) > 0.0);
  return CHAPLYGIN_SUCCESS;
}

/* chaplygin_printed_discrete_energy_after: (B.9) as printed (erratum E22),
   the sum with n + 1 terms:
       E_n = E + C1 H^2 Sum_(j=0)^n C2^2j,   H_n = C2^n H,
   C1, C2 of (B.3) for direction dir.  (The printed closed form
   (1 - C2^2n)/(1 - C2^2) has n terms and is right.)  H_n is that of
   chaplygin_discrete_energy_after; E_n exceeds its loss by the term
   C1 H^2 C2^2n = C1 H_n^2: n = 1 gives E + C1 (1 + C2^2) H^2 instead of
   E + C1 H^2, n = 0 gives E + C1 H^2 instead of E.
   Method: E_n(printed) = E_n(corrected) + C1 H_n^2, C1 the system's (3.7)
   coefficient of the collision at the far end; the sum's condition is
   that of the corrected E_n.  (For a far slot C1 H_n^2 lies below the
   rounding of E_n.)
   Domain, errors: as chaplygin_discrete_energy_after (a valid system,
   dir = +-1, a valid state whose first n paths do not reverse:
   CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM, CHAPLYGIN_ESTATE, CHAPLYGIN_ESPIN,
   CHAPLYGIN_ERANGE). */
int
chaplygin_printed_discrete_energy_after (const chaplygin_discrete *sys,
                                         int dir, double E, double H,
                                         unsigned long n, double *En,
                                         double *Hn)
{
  double e, h;
  if (!En || !Hn)
    return CHAPLYGIN_EINVAL;
  CHP_TRY (chaplygin_discrete_energy_after (sys, dir, E, H, n, &e, &h));
  /* the collision at the far end: the peg leaves D- = Delta for dir = +1
     (index 1), D- = 0 for dir = -1 (index 0) */
  const double C1 = sys->C1[dir > 0 ? 1 : 0];
  const double ep = e + (C1 * h) * h;
  if (!isfinite (ep))
    return CHAPLYGIN_ERANGE;
  *En = ep;
  *Hn = h;
  return CHAPLYGIN_SUCCESS;
}

/* chaplygin_printed_massless_coefficient: (B.16) as printed (erratum E17),
   on every segment:
       C2 = L0 (L0 + 1)/(L0 + (1 - D+))^2,
   whatever REVERSAL says.  Agrees with chaplygin_massless_coefficient for
   reversal = 0; for reversal = 1 the correct coefficient is
   L0 (L0 + 1)/(L0 + D+)^2, the reciprocal when L0 + D+ and L0 + 1 - D+
   are both nonzero (L0 = -2/3, D+ = 0: printed H'/H = -2, correct -1/2).
   Method: chaplygin_massless_coefficient with reversal = 0.
   Domain: L0 finite; Dplus exactly 0 or 1; reversal 0 or 1 (validated,
   unused); L0 + 1 - D+ != 0 (the printed denominator; the correct
   coefficient on a reversing segment needs L0 + D+ != 0 instead).
   Errors: CHAPLYGIN_EINVAL (NULL, reversal), CHAPLYGIN_EDOM (non-finite,
   L0 + 1 - D+ = 0), CHAPLYGIN_ESTATE (Dplus not an end). */
int
chaplygin_printed_massless_coefficient (double L0, double Dplus, int reversal,
                                        double *C2)
{
  if (reversal != 0 && reversal != 1)
    return CHAPLYGIN_EINVAL;
  return chaplygin_massless_coefficient (L0, Dplus, 0, C2);
}
