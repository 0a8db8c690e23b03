/* smooth.c -- Section 2 and Appendix A: the smooth Chaplygin sleigh.

   q = {S, V, theta, Omega}: S the arc length travelled by the skate contact
   C (positive for forward and backward motion, as the paper's text says),
   V the velocity of C along the skate, theta the heading, Omega its rate.

   Closed form (derived in the manual, "The smooth sleigh"; checked against
   integration of (2.1) at 30 digits before it was written).  With
   a = L/(1 + L^2), B = sqrt(1 + L^2), x the signed displacement of C along
   its path (dx/dtau = V) and u = exp(-a x):
       Omega = Omega0 u,   V^2 = V0^2 + B^2 Omega0^2 (1 - u^2),
   and E = [V^2 + B^2 Omega^2]/2 is conserved.  If a V0 < 0 (the mass centre
   behind C for forward motion, or ahead of it for backward motion), V^2
   falls to 0 at arc length
       sigma_c = log(1 + V0^2/(B^2 Omega0^2)) / (2 |a|)              (A.1)
   and the motion reverses; beyond it x retraces itself, x = x_c - s0 (S -
   S_c), so every quantity is symmetric about S_c in the exponent (the paper's
   (A.2)-(A.3) reflect the exponent about S0 instead: see the errata).
   Heading: with psi = atan2(V, B |Omega|) (the angle of the state on the
   energy ellipse), dtheta/dpsi = sgn(Omega0) B/L along the whole motion:
       theta - theta0 = sgn(Omega0) (B/L) (psi - psi0),
   which is (A.2)'s arcsine form before S_c.  Time: with
   atanh(|V|/sqrt(2E)) = log((sqrt(2E) + |V|)/(B |Omega|)),
       tau - tau0 = sigma/sqrt(2E) + |log((sqrt(2E) + |V|)/(sqrt(2E) + |V0|))|
                    / (|a| sqrt(2E))        (before a reversal).
   Both are evaluated below in forms free of cancellation as L -> 0,
   Omega0 -> 0 and near S_c.  */
#include <config.h>

#include <float.h>
#include <math.h>
#include <stddef.h>

#include "chaplygin.h"
#include "eft.h"

/* expm1(z)/z, continuous at 0. */
static double
em1c (double z)
{
  return z == 0.0 ? 1.0 : expm1 (z) / z;
}

/* log1p(d)/d, continuous at 0. */
static double
log1pc (double d)
{
  return d == 0.0 ? 1.0 : log1p (d) / d;
}

/* atan(r)/r, continuous at 0. */
static double
atanc (double r)
{
  return r == 0.0 ? 1.0 : atan (r) / r;
}

/* chaplygin_smooth_field: (2.1) with dS/dtau = |V|:
       dS/dtau = |V|, dV/dtau = L Omega^2, dtheta/dtau = Omega,
       dOmega/dtau = -L V Omega/(1 + L^2).
   The paper prints dS/dtau = V, which makes S a signed displacement; its
   text and Appendix A take S as arc length, positive for forward and
   backward motion, so the library integrates |V| (errata, (2.1)).
   Derivation (test eq_2_1): no force along the skate, d v/dt = ell omega^2;
   the constraint force F e_n at C, m (v omega + ell domega/dt) = F and
   I domega/dt = -ell F, give domega/dt = -m ell v omega/(I + m ell^2).
   Domain: finite L and q.  Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM,
   CHAPLYGIN_ERANGE. */
int
chaplygin_smooth_field (double L, const double q[4], double dq[4])
{
  if (!q || !dq)
    return CHAPLYGIN_EINVAL;
  if (!isfinite (L) || !chp_finite4 (q[0], q[1], q[2], q[3]))
    return CHAPLYGIN_EDOM;
  double V = q[CHAPLYGIN_V], Om = q[CHAPLYGIN_OMEGA];
  double r[4];
  r[CHAPLYGIN_S] = fabs (V);
  r[CHAPLYGIN_V] = L * Om * Om;
  r[CHAPLYGIN_THETA] = Om;
  r[CHAPLYGIN_OMEGA] = -chp_L_over_one_plus_sq (L) * V * Om;
  if (!chp_finite4 (r[0], r[1], r[2], r[3]))
    return CHAPLYGIN_ERANGE;
  for (int i = 0; i < 4; i++)
    dq[i] = r[i];
  return CHAPLYGIN_SUCCESS;
}

/* chaplygin_smooth_steady: (2.4) the steady solutions
       q* = {|V*| tau, V*, theta*, 0},  H*_C = (1 + L^2) Omega* = 0,
       E* = (V*)^2/2.
   (The paper prints H*_C = (1 + L^2) Omega^2; the momentum is linear in
   Omega, as in (A.4): errata.)  The arc length of the straight-line motion
   is |V*| tau.
   Domain: finite arguments.  Errors: CHAPLYGIN_EINVAL (NULL q, E or H),
   CHAPLYGIN_EDOM, CHAPLYGIN_ERANGE. */
int
chaplygin_smooth_steady (double Vstar, double theta_star, double tau,
                         double q[4], double *E, double *H)
{
  if (!q || !E || !H)
    return CHAPLYGIN_EINVAL;
  if (!isfinite (Vstar) || !chp_finite2 (theta_star, tau))
    return CHAPLYGIN_EDOM;
  double S = fabs (Vstar) * tau, e = 0.5 * Vstar * Vstar;
  if (!isfinite (S) || !isfinite (e))
    return CHAPLYGIN_ERANGE;
  q[CHAPLYGIN_S] = S;
  q[CHAPLYGIN_V] = Vstar;
  q[CHAPLYGIN_THETA] = theta_star;
  q[CHAPLYGIN_OMEGA] = 0.0;
  *E = e;
  *H = 0.0;
  return CHAPLYGIN_SUCCESS;
}

/* chaplygin_smooth_eigenvalue: Section 2.1, xi4 = -L V* / (1 + L^2), the
   nonzero eigenvalue of (2.1) linearised at q* (the others are 0, 0, 0):
   only dOmega/dtau = -L V* Omega/(1 + L^2) has a linear term in the
   perturbation.  Accuracy: within 3 ulps.  Errors: CHAPLYGIN_EINVAL,
   CHAPLYGIN_EDOM. */
int
chaplygin_smooth_eigenvalue (double L, double Vstar, double *xi4)
{
  if (!xi4)
    return CHAPLYGIN_EINVAL;
  if (!chp_finite2 (L, Vstar))
    return CHAPLYGIN_EDOM;
  *xi4 = -chp_L_over_one_plus_sq (L) * Vstar;
  return CHAPLYGIN_SUCCESS;
}

/* chaplygin_smooth_energy: (A.4) E = [V^2 + (1 + L^2) Omega^2]/2.
   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM, CHAPLYGIN_ERANGE. */
int
chaplygin_smooth_energy (double L, double V, double Omega, double *E)
{
  if (!E)
    return CHAPLYGIN_EINVAL;
  if (!isfinite (L) || !chp_finite2 (V, Omega))
    return CHAPLYGIN_EDOM;
  double r = 0.5 * (V * V + chp_one_plus_sq (L) * Omega * Omega);
  if (!isfinite (r))
    return CHAPLYGIN_ERANGE;
  *E = r;
  return CHAPLYGIN_SUCCESS;
}

/* chaplygin_smooth_momentum: (A.4) H_C = (1 + L^2) Omega, the angular
   momentum about the instantaneous contact point C'.
   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM, CHAPLYGIN_ERANGE. */
int
chaplygin_smooth_momentum (double L, double Omega, double *H)
{
  if (!H)
    return CHAPLYGIN_EINVAL;
  if (!chp_finite2 (L, Omega))
    return CHAPLYGIN_EDOM;
  double r = chp_one_plus_sq (L) * Omega;
  if (!isfinite (r))
    return CHAPLYGIN_ERANGE;
  *H = r;
  return CHAPLYGIN_SUCCESS;
}

/* log(1 + V0^2/(B Omega0)^2) for B Omega0 != 0, without overflow. */
static double
log1p_ratio_sq (double V0, double BO0)
{
  double t = fabs (V0) / fabs (BO0);
  if (t < 0x1p500)
    return log1p (t * t);
  return 2.0 * (log (fabs (V0)) - log (fabs (BO0)));
}

/* The arc length from the start to the reversal (A.1), for a V0 < 0 (or 0
   when the start is itself the turning point) and Omega0 != 0. */
static double
sigma_reversal (double a, double V0, double BO0)
{
  return log1p_ratio_sq (V0, BO0) / (2.0 * fabs (a));
}

/* chaplygin_smooth_reversal: (A.1)
       S_c = S0 - (1 + L^2)/(2L) log(1 + V0^2/(Omega0^2 (1 + L^2))),
   valid as printed for V0 > 0 and L < 0; in general the reversal happens
   iff L V0 < 0 and Omega0 != 0, at
       S_c = S0 + (1 + L^2)/(2|L|) log(1 + V0^2/(Omega0^2 (1 + L^2))).
   A start with V0 = 0 is a turning point already passed: no reversal.
   Domain: finite L, q0.  Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM,
   CHAPLYGIN_ERANGE (S_c overflows). */
int
chaplygin_smooth_reversal (double L, const double q0[4], int *reverses,
                           double *Sc)
{
  if (!q0 || !reverses || !Sc)
    return CHAPLYGIN_EINVAL;
  if (!isfinite (L) || !chp_finite4 (q0[0], q0[1], q0[2], q0[3]))
    return CHAPLYGIN_EDOM;
  double V0 = q0[CHAPLYGIN_V], Om0 = q0[CHAPLYGIN_OMEGA];
  /* a reversal iff L and V0 have opposite signs (compared as signs: the
     product could underflow) and Omega0 != 0 */
  if (L == 0.0 || V0 == 0.0 || (L < 0.0) == (V0 < 0.0) || Om0 == 0.0)
    {
      *reverses = 0;
      return CHAPLYGIN_SUCCESS;
    }
  double a = chp_L_over_one_plus_sq (L), B = hypot (1.0, L);
  double s = q0[CHAPLYGIN_S] + sigma_reversal (a, V0, B * Om0);
  if (!isfinite (s))
    return CHAPLYGIN_ERANGE;
  *reverses = 1;
  *Sc = s;
  return CHAPLYGIN_SUCCESS;
}

/* V0^2 = 2 E0 - H0^2/(1 + L^2) as [2 E0 (1 + L^2) - H0^2]/(1 + L^2), the
   numerator formed with an error-free product and one fma: its sign is
   exact for the rounded 1 + L^2 (so V0 = 0 is recognised whenever the
   inputs make it exactly so), its value accurate to ~1 ulp. */
static double
v0_squared (double L, double E0, double H0)
{
  double n = chp_one_plus_sq (L), twoE = 2.0 * E0;
  double p = twoE * n, e = fma (twoE, n, -p);   /* 2 E0 n = p + e exactly */
  if (!isfinite (p) || !isfinite (H0 * H0))
    {
      double b = H0 / hypot (1.0, L);            /* overflow-free form */
      return twoE - b * b;
    }
  return (fma (-H0, H0, p) + e) / n;
}

/* chaplygin_smooth_reversal_eh: (A.6)
       S_c = S0 - (1 + L^2)/(2L) log(2 E0 (1 + L^2)/(H_C^0)^2),
   generalised as (A.1): reversal iff L dir0 < 0, H0 != 0 and V0 != 0,
   S_c = S0 + (1 + L^2)/(2|L|) log(2 E0 (1 + L^2)/H0^2).
   Domain: finite; E0 >= H0^2/(2 (1 + L^2)) (V0^2 >= 0); dir0 = +-1.
   Errors: CHAPLYGIN_EINVAL (NULL, dir0), CHAPLYGIN_EDOM, CHAPLYGIN_ESTATE
   (V0^2 < 0), CHAPLYGIN_ERANGE. */
int
chaplygin_smooth_reversal_eh (double L, double S0, double E0, double H0,
                              int dir0, int *reverses, double *Sc)
{
  if (!reverses || !Sc || (dir0 != 1 && dir0 != -1))
    return CHAPLYGIN_EINVAL;
  if (!chp_finite4 (L, S0, E0, H0) || !(E0 >= 0.0))
    return CHAPLYGIN_EDOM;
  double B = hypot (1.0, L);
  double BOm = H0 / B;                  /* B Omega0 */
  double v2 = v0_squared (L, E0, H0);
  if (v2 < 0.0)
    return CHAPLYGIN_ESTATE;
  if (L == 0.0 || (L < 0.0) == (dir0 < 0) || H0 == 0.0 || v2 == 0.0)
    {
      *reverses = 0;
      return CHAPLYGIN_SUCCESS;
    }
  /* log(2 E0 B^2/H0^2) = 2 log(sqrt(2 E0)/|B Omega0|). */
  double t = sqrt (2.0 * E0) / fabs (BOm);
  double lg = isfinite (t) ? 2.0 * log (t)
    : log (2.0 * E0) - 2.0 * log (fabs (BOm));
  double s = S0 + lg / (2.0 * fabs (chp_L_over_one_plus_sq (L)));
  if (!isfinite (s))
    return CHAPLYGIN_ERANGE;
  *reverses = 1;
  *Sc = s;
  return CHAPLYGIN_SUCCESS;
}

struct smooth_sol
{
  double V, Omega, dtheta, dtau;
  int K;
};

/* The careful leg formulas for V, V0 of the same sign (or V0 = 0):
   x the signed displacement, one_m_u2 = 1 - u^2, u = |Omega/Omega0|.
     theta - theta0 = sgn(Omega0) B atanc(rho) (rho/L),
       rho = tan(psi - psi0) = B|Omega0| 2E (1 - u^2)
             / ((V + V0 u)(B|Omega| B|Omega0| + V V0)),
       (1 - u^2)/L = 2 x em1c(-2 a x)/B^2;
     tau - tau0 = sigma/sqrt(2E) + log1pc(d) |d|/(|a| sqrt(2E)),
       d = (|V| - |V0|)/(sqrt(2E) + |V0|),
       |V| - |V0| = (B Omega0)^2 (1 - u^2)/(|V| + |V0|),
       |1 - u^2|/|a| = 2 sigma em1c(-2 a x). */
static void
leg_same_sign (double L, double a, double B, double V0, double Om0,
               double sqrt2E, double sigma, double x, double V, double Om,
               double one_m_u2, struct smooth_sol *r)
{
  double twoE = sqrt2E * sqrt2E;
  double BO0 = B * fabs (Om0), BO = B * fabs (Om);
  double u = fabs (Om) / fabs (Om0);
  double e = em1c (-2.0 * a * x);
  double den = (V + V0 * u) * (BO * BO0 + V * V0);
  double rho_over_L = BO0 * twoE * (2.0 * x / (B * B)) * e / den;
  double rho = rho_over_L * L;
  r->dtheta = chp_sign (Om0) * B * atanc (rho) * rho_over_L;

  double sumV = fabs (V) + fabs (V0);
  double dV = BO0 * BO0 * one_m_u2 / sumV;          /* |V| - |V0| */
  double d = dV / (sqrt2E + fabs (V0));
  double d_over_a = BO0 * BO0 * 2.0 * sigma * e / (sumV * (sqrt2E + fabs (V0)));
  r->dtau = sigma / sqrt2E + log1pc (d) * d_over_a / sqrt2E;
}

/* The state at arc length sigma >= 0 beyond the start (V0, Omega0). */
static int
smooth_solve (double L, double V0, double Om0, double sigma,
              struct smooth_sol *r)
{
  r->K = 1;
  if (sigma == 0.0)
    {
      r->V = V0, r->Omega = Om0, r->dtheta = 0.0, r->dtau = 0.0;
      return CHAPLYGIN_SUCCESS;
    }
  if (Om0 == 0.0 || L == 0.0)
    {
      /* Straight line (Omega0 = 0), or the circle of L = 0: V and Omega
         constant.  At rest, or spinning in place (V0 = 0), S never
         advances. */
      if (V0 == 0.0)
        return CHAPLYGIN_ESTATE;
      r->V = V0;
      r->Omega = Om0;
      r->dtau = sigma / fabs (V0);
      r->dtheta = Om0 * r->dtau;
      return CHAPLYGIN_SUCCESS;
    }

  double a = chp_L_over_one_plus_sq (L), B = hypot (1.0, L);
  double BO0 = B * Om0;
  double twoE = V0 * V0 + BO0 * BO0;
  double sqrt2E = sqrt (twoE);
  double s0 = V0 != 0.0 ? chp_sign (V0) : chp_sign (L);
  double x = s0 * sigma;

  if (a * s0 > 0.0)
    {
      /* Omega decays, |V| grows: no reversal. */
      double z = 2.0 * fabs (a) * sigma;
      double one_m_u2 = z * em1c (-z);
      double u = exp (-fabs (a) * sigma);
      r->Omega = Om0 * u;
      r->V = s0 * sqrt (V0 * V0 + BO0 * BO0 * one_m_u2);
      leg_same_sign (L, a, B, V0, Om0, sqrt2E, sigma, x, r->V, r->Omega,
                     one_m_u2, r);
      return CHAPLYGIN_SUCCESS;
    }

  /* a s0 < 0: Omega grows, |V| falls to 0 at sigma_c, then the motion
     retraces its exponent about S_c. */
  double sc = sigma_reversal (a, V0, BO0);
  double Omc = chp_sign (Om0) * sqrt2E / B;     /* Omega at the reversal */
  if (sigma <= sc)
    {
      double z = 2.0 * fabs (a) * sigma;
      double one_m_u2 = -z * em1c (z);          /* < 0 */
      double v2;
      if (sigma <= 0.5 * sc)
        {
          r->Omega = Om0 * exp (fabs (a) * sigma);
          v2 = V0 * V0 + BO0 * BO0 * one_m_u2;
        }
      else
        {
          double rest = sc - sigma;
          r->Omega = Omc * exp (-fabs (a) * rest);
          v2 = -twoE * expm1 (-2.0 * fabs (a) * rest);
        }
      r->V = s0 * sqrt (fmax (v2, 0.0));
      leg_same_sign (L, a, B, V0, Om0, sqrt2E, sigma, x, r->V, r->Omega,
                     one_m_u2, r);
      return CHAPLYGIN_SUCCESS;
    }

  double past = sigma - sc;
  r->K = -1;
  r->Omega = Omc * exp (-fabs (a) * past);
  r->V = -s0 * sqrt (-twoE * expm1 (-2.0 * fabs (a) * past));
  double psi = atan2 (r->V, B * fabs (r->Omega));
  double psi0 = atan2 (V0, B * fabs (Om0));
  r->dtheta = chp_sign (Om0) * (B / L) * (psi - psi0);
  r->dtau = sigma / sqrt2E + (log1p (fabs (V0) / sqrt2E)
                              + log1p (fabs (r->V) / sqrt2E))
    / (fabs (a) * sqrt2E);
  return CHAPLYGIN_SUCCESS;
}

static int
check_closed_form_args (double L, const double q0[4], double S)
{
  if (!isfinite (L) || !chp_finite4 (q0[0], q0[1], q0[2], q0[3])
      || !isfinite (S) || !(S >= q0[CHAPLYGIN_S]))
    return CHAPLYGIN_EDOM;
  return CHAPLYGIN_SUCCESS;
}

/* chaplygin_smooth_closed_form: (A.2) with (A.3), corrected beyond S_c:
       V(S) = K s0 sqrt(V0^2 + Omega0^2 (1 + L^2)(1 - exp(-2 a x))),
       Omega(S) = Omega0 exp(-a x),
       theta(S) = theta0 + sgn(Omega0) (sqrt(1 + L^2)/L) (psi(S) - psi0),
   x = s0 (S - S0) before the reversal, x = s0 (2 S_c - S - S0) after it
   (s0 = sgn V0, or sgn L if V0 = 0), psi = atan2(V, sqrt(1 + L^2)|Omega|);
   before S_c, |psi(S) - psi0| = |arcsin(k) - arcsin(k u)| of (A.2),
   k = 1/sqrt(V0^2/(Omega0^2 (1 + L^2)) + 1).  Also tau(S) - tau(S0).
   Domain: finite; S >= S0 = q0[S].
   Method: see the file comment and leg_same_sign: expm1, log1p, atan
   forms with no cancellation as L -> 0 or Omega0 -> 0; V^2 near S_c from
   the S_c side.  L = 0 and Omega0 = 0 are the circle and the line.
   Accuracy: within 3 eps of a 30-digit ODE solution on the reference set
   (manual, "Speed and accuracy").
   Errors: CHAPLYGIN_EINVAL (NULL), CHAPLYGIN_EDOM (non-finite, S < S0),
   CHAPLYGIN_ESTATE (at rest or spinning in place, V0 = 0 with Omega0 = 0
   or L = 0: S never advances), CHAPLYGIN_ERANGE. */
int
chaplygin_smooth_closed_form (double L, const double q0[4], double S,
                              double q[4], double *dtau)
{
  if (!q0 || !q)
    return CHAPLYGIN_EINVAL;
  CHP_TRY (check_closed_form_args (L, q0, S));
  struct smooth_sol r;
  CHP_TRY (smooth_solve (L, q0[CHAPLYGIN_V], q0[CHAPLYGIN_OMEGA],
                         S - q0[CHAPLYGIN_S], &r));
  double th = q0[CHAPLYGIN_THETA] + r.dtheta;
  if (!chp_finite4 (r.V, r.Omega, th, r.dtau))
    return CHAPLYGIN_ERANGE;
  q[CHAPLYGIN_S] = S;
  q[CHAPLYGIN_V] = r.V;
  q[CHAPLYGIN_THETA] = th;
  q[CHAPLYGIN_OMEGA] = r.Omega;
  if (dtau)
    *dtau = r.dtau;
  return CHAPLYGIN_SUCCESS;
}

/* chaplygin_smooth_branch: (A.3) K(S), the sign of V(S)/V0: the paper
   defines, for V0 > 0, K = 1 for L > 0, K = 1 for S < S_c and K = -1 for
   S > S_c when L < 0.  Here K = -1 exactly when a reversal happens and
   S > S_c; K = 1 at S = S_c.  Domain and errors: as the closed form. */
int
chaplygin_smooth_branch (double L, const double q0[4], double S, int *K)
{
  if (!q0 || !K)
    return CHAPLYGIN_EINVAL;
  CHP_TRY (check_closed_form_args (L, q0, S));
  struct smooth_sol r;
  CHP_TRY (smooth_solve (L, q0[CHAPLYGIN_V], q0[CHAPLYGIN_OMEGA],
                         S - q0[CHAPLYGIN_S], &r));
  *K = r.K;
  return CHAPLYGIN_SUCCESS;
}

/* chaplygin_smooth_closed_form_eh: (A.4)
       E(S) = E0,
       theta(S) = theta0 + K (sqrt(1 + L^2)/L) [arcsin(1/sqrt(2 E0 (1+L^2)/H0^2))
                  - arcsin(exp(-K a (S - S0))/sqrt(2 E0 (1+L^2)/H0^2))],
       H_C(S) = H0 exp(-K a (S - S0)),
   as printed valid before S_c; computed through the corrected (A.2) with
   Omega0 = H0/(1 + L^2), V0 = dir0 sqrt(2 E0 - H0^2/(1 + L^2)).
   p = {S, E, theta, H_C}.  E is returned as E0 exactly (it is conserved).
   Domain: finite; S >= S0; E0 >= H0^2/(2 (1 + L^2)); dir0 = +-1 (any value
   is accepted when V0 = 0).
   Errors: CHAPLYGIN_EINVAL (NULL, dir0), CHAPLYGIN_EDOM, CHAPLYGIN_ESTATE
   (V0^2 < 0, or a motion that cannot advance), CHAPLYGIN_ERANGE. */
int
chaplygin_smooth_closed_form_eh (double L, const double p0[4], int dir0,
                                 double S, double p[4])
{
  if (!p0 || !p)
    return CHAPLYGIN_EINVAL;
  if (!isfinite (L) || !chp_finite4 (p0[0], p0[1], p0[2], p0[3])
      || !isfinite (S) || !(S >= p0[CHAPLYGIN_S]) || !(p0[CHAPLYGIN_E] >= 0.0))
    return CHAPLYGIN_EDOM;
  double E0 = p0[CHAPLYGIN_E], H0 = p0[CHAPLYGIN_H];
  double Om0 = H0 / chp_one_plus_sq (L);
  double v2 = v0_squared (L, E0, H0);
  if (!isfinite (v2))
    return CHAPLYGIN_ERANGE;
  if (v2 < 0.0)
    return CHAPLYGIN_ESTATE;
  if (v2 > 0.0 && dir0 != 1 && dir0 != -1)
    return CHAPLYGIN_EINVAL;
  double q0[4] = { p0[CHAPLYGIN_S], v2 > 0.0 ? dir0 * sqrt (v2) : 0.0,
                   p0[CHAPLYGIN_THETA], Om0 };
  double q[4];
  CHP_TRY (chaplygin_smooth_closed_form (L, q0, S, q, NULL));
  double H = chp_one_plus_sq (L) * q[CHAPLYGIN_OMEGA];
  if (!isfinite (H))
    return CHAPLYGIN_ERANGE;
  p[CHAPLYGIN_S] = S;
  p[CHAPLYGIN_E] = E0;
  p[CHAPLYGIN_THETA] = q[CHAPLYGIN_THETA];
  p[CHAPLYGIN_H] = H;
  return CHAPLYGIN_SUCCESS;
}

/* chaplygin_smooth_steady_eh: (A.5) H*_C = 0, E* = (V*)^2/2: the
   straight-line equilibria, all energy translational.
   Errors: CHAPLYGIN_EINVAL, CHAPLYGIN_EDOM, CHAPLYGIN_ERANGE. */
int
chaplygin_smooth_steady_eh (double Vstar, double *E, double *H)
{
  if (!E || !H)
    return CHAPLYGIN_EINVAL;
  if (!isfinite (Vstar))
    return CHAPLYGIN_EDOM;
  double e = 0.5 * Vstar * Vstar;
  if (!isfinite (e))
    return CHAPLYGIN_ERANGE;
  *E = e;
  *H = 0.0;
  return CHAPLYGIN_SUCCESS;
}
