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
#include "quad.h"

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

/* ---- the motion in time ------------------------------------------------

   With c = sqrt(2E), (2.1) and the energy give dV/dtau = L Omega^2
   = a (c^2 - V^2), a Riccati equation solved by
       V = c tanh z,   z = z0 + a c tau,   z0 = atanh(V0/c),
       B |Omega| = c sech z   (Omega keeps the sign s of Omega0),
   and with psi = atan2(V, B |Omega|) = gd(z) (the Gudermannian, so the
   angle of the file comment), dtheta/dpsi = s B/L:
       theta - theta0 = s (B/L) (psi - psi0),
       x = (1/a) log(cosh z/cosh z0)   (the signed displacement, dx = V dtau).
   z moves away from 0 if a V0 > 0 (or V0 = 0): no reversal; if a V0 < 0
   it reaches 0 at u = |a| c tau = |z0| = Z, where V changes sign (the
   reversal (A.1) in time), and the arc length is S - S0 = |x| before it,
   2 sigma_c - |x| after it.  Derived here by direct substitution into
   (2.1); tests eq_A_2_time and smooth_at_time check it against a
   30-digit Taylor-series integration of (2.1) in time.

   The forms below keep full accuracy in three regimes, with u = |a| c tau
   (never z0 + d, which cancels), T = |V0|/c, Sc = B |Omega0|/c and
   Tm = 1 - T = Sc^2/(1 + T) (formed without cancellation):
   receding (no reversal):
       V = sigma c (T + tanh u)/(1 + T tanh u),
       Omega = Omega0 2 e^-u/((1 + T) + Tm e^-2u),
       log R = log(cosh z/cosh z0) = log1p(2 sinh^2(u/2) + T sinh u)
               (u < 1, divided by |a| as log1pc(R - 1) ((R - 1)/u) c tau,
               since u/|a| = c tau: no underflow of u for tiny L),
               u + log1p(Tm expm1(-2u)/2)  (u >= 1),
       tan |psi - psi0| = Sc W/(1 + T W),  W = 2 T sinh^2(u/2) + sinh u;
   approaching, before half the way to the reversal (u <= Z/2):
       V = sigma c tanh(Z - u)   (Z - u >= Z/2: no cancellation),
       R = e^-u + Tm sinh u,  Omega = Omega0/R,
       log R = log1p(2 sinh^2(u/2) - T sinh u)  (u < 1; the terms differ by
               a factor 2 at least),  -u + log1p(Tm expm1(2u)/2)  (u >= 1),
       tan |psi - psi0| = Sc W/(Sc^2 + T tanh(Z - u) R),
       W = -expm1(-u) + 2 Tm sinh^2(u/2)   (both terms >= 0);
   approaching, beyond half the way (u > Z/2): from the reversal,
   zeta = u - Z,
       V = -sigma c tanh zeta,  Omega = s (c/B) sech zeta,
       S - S0 = sigma_c + sgn(zeta) log cosh(zeta)/|a|,
       |psi - psi0| = atan2(T sech zeta + Sc tanh zeta,
                            Sc sech zeta - T tanh zeta)
   (sin and cos of gd(Z) + gd(zeta), each term bounded).  For u <= 1 the
   heading is written Omega0 tau (W/u) atanc(r)/den, r = Sc W/den (den the
   denominator above), which stays accurate as L -> 0 (the circle). */

enum
{
  MOTION_REST = 1,              /* c = 0 */
  MOTION_LINE = 2,              /* Omega0 = 0 */
  MOTION_CIRCLE = 3,            /* L = 0 (spinning in place if V0 = 0) */
  MOTION_GENERAL = 4
};

/* sinh(x)/x, continuous at 0. */
static double
sinhc (double x)
{
  return x == 0.0 ? 1.0 : sinh (x) / x;
}

/* log cosh x, without overflow and without the cancellation of
   |x| + log((1 + e^-2|x|)/2) for small x. */
static double
logcosh (double x)
{
  double y = fabs (x);
  if (y < 1.0)
    {
      double h = sinh (0.5 * y);
      return log1p (2.0 * h * h);
    }
  return y + log1p (0.5 * expm1 (-2.0 * y));
}

/* chaplygin_smooth_motion_init: the constants of the motion from q0 with
   parameter L (see the comment above): a, B, c = sqrt(2E) =
   hypot(V0, B Omega0), T = |V0|/c, Sc = B |Omega0|/c, Tm = Sc^2/(1 + T),
   Z = atanh(T) (for T < 1/2; log((1 + T)/Sc) otherwise, by logarithms of
   each factor when Sc is subnormal), the direction sigma, whether the
   motion reverses, and sigma_c = S_c - S0 of chaplygin_smooth_reversal.
   Domain: finite L and q0.
   Errors: CHAPLYGIN_EINVAL (NULL), CHAPLYGIN_EDOM (non-finite),
   CHAPLYGIN_ERANGE (B Omega0 or sqrt(2E) overflows). */
int
chaplygin_smooth_motion_init (double L, const double q0[4],
                              chaplygin_smooth_motion *m)
{
  if (!q0 || !m)
    return CHAPLYGIN_EINVAL;
  if (!isfinite (L) || !chp_finite4 (q0[0], q0[1], q0[2], q0[3]))
    return CHAPLYGIN_EDOM;
  chaplygin_smooth_motion r = { 0 };
  const double V0 = q0[CHAPLYGIN_V], Om0 = q0[CHAPLYGIN_OMEGA];
  r.L = L;
  for (int i = 0; i < 4; i++)
    r.q0[i] = q0[i];
  r.a = chp_L_over_one_plus_sq (L);
  r.B = hypot (1.0, L);
  const double BO = r.B * fabs (Om0);
  r.c = hypot (V0, BO);
  if (!isfinite (BO) || !isfinite (r.c))
    return CHAPLYGIN_ERANGE;
  r.s = chp_sign (Om0);
  r.sigma = V0 != 0.0 ? (V0 > 0.0 ? 1 : -1) : (L < 0.0 ? -1 : 1);
  if (r.c == 0.0)
    r.kind = MOTION_REST;
  else if (Om0 == 0.0)
    r.kind = MOTION_LINE;
  else if (L == 0.0)
    r.kind = MOTION_CIRCLE;
  else
    {
      r.kind = MOTION_GENERAL;
      r.ac = fabs (r.a) * r.c;
      r.T = fabs (V0) / r.c;
      r.Sc = BO / r.c;
      r.Tm = r.Sc * r.Sc / (1.0 + r.T);
      if (r.T < 0.5)
        r.Z = atanh (r.T);
      else if (r.Sc >= DBL_MIN)
        r.Z = log ((1.0 + r.T) / r.Sc);
      else
        r.Z = log1p (r.T) - (log (BO) - log (r.c));
      r.approaching = V0 != 0.0 && (L < 0.0) != (V0 < 0.0);
      if (r.approaching)
        r.sigma_c = sigma_reversal (r.a, V0, r.B * Om0);
    }
  *m = r;
  return CHAPLYGIN_SUCCESS;
}

/* The state at elapsed time tau > 0 of a general motion: V, Omega, the
   heading increment and (if want_S) the arc length increment. */
struct smooth_at
{
  double V, Omega, dtheta, dS;
};

/* |psi - psi0|/|L| B s: the heading increment from the angle swept on the
   energy ellipse (B (ang/|L|): no overflow of B/|L| for a subnormal L). */
static double
heading_from_angle (const chaplygin_smooth_motion *m, double ang)
{
  return m->s * (m->B * (ang / fabs (m->L)));
}

static void
motion_receding (const chaplygin_smooth_motion *m, double tau, double u,
                 int want_S, struct smooth_at *r)
{
  const double T = m->T, Tm = m->Tm, Om0 = m->q0[CHAPLYGIN_OMEGA];
  const double th = tanh (u), e1 = exp (-u);
  const double h = sinh (0.5 * u), sh = sinh (u);
  r->V = m->sigma * (m->c * ((T + th) / (1.0 + T * th)));
  r->Omega = Om0 * (2.0 * e1 / ((1.0 + T) + Tm * (e1 * e1)));
  if (want_S && u < 1.0)
    {
      /* log R/|a| = log1pc(R - 1) (R - 1)/u c tau: no division by a tiny
         |a| of a log R that may have underflowed (u/|a| = c tau) */
      const double hc = sinhc (0.5 * u);
      const double Ru = T * sinhc (u) + 0.5 * u * hc * hc;   /* (R - 1)/u */
      r->dS = m->c * tau * Ru * log1pc (Ru * u);
    }
  else if (want_S)
    r->dS = (u + log1p (0.5 * Tm * expm1 (-2.0 * u))) / fabs (m->a);
  if (u <= 1.0)
    {
      const double hc = sinhc (0.5 * u);
      const double Wu = sinhc (u) + T * (0.5 * u) * hc * hc;
      const double den = 1.0 + T * (Wu * u);
      r->dtheta = Om0 * tau * (Wu / den) * atanc (m->Sc * (Wu * u) / den);
    }
  else
    {
      /* Sc W/(1 + T W) as Sc/(T + 1/W): W may overflow (then 1/W = 0) */
      const double W = 2.0 * T * h * h + sh;
      r->dtheta = heading_from_angle (m, atan (m->Sc / (T + 1.0 / W)));
    }
}

static void
motion_approaching (const chaplygin_smooth_motion *m, double tau, double u,
                    int want_S, struct smooth_at *r)
{
  const double T = m->T, Tm = m->Tm, Sc = m->Sc, Om0 = m->q0[CHAPLYGIN_OMEGA];
  const double zu = m->Z - u, tz = tanh (zu);
  const double h = sinh (0.5 * u), sh = sinh (u);
  const double R = exp (-u) + Tm * sh;         /* cosh z/cosh z0 */
  r->V = m->sigma * (m->c * tz);
  r->Omega = Om0 / R;
  if (want_S)
    {
      if (u < 1.0)
        {
          /* as motion_receding: -log R/|a| = -log1pc(R - 1) (R - 1)/u c tau */
          const double hc = sinhc (0.5 * u);
          const double Ru = 0.5 * u * hc * hc - T * sinhc (u);
          r->dS = -(m->c * tau * Ru * log1pc (Ru * u));
        }
      else
        {
          /* Tm expm1(2u)/2 <= ~e^-Z: its logarithmic form where expm1(2u)
             would overflow (u <= Z/2 < ~373) */
          double X = u < 350.0 ? 0.5 * Tm * expm1 (2.0 * u)
            : exp (log (Tm) + 2.0 * u - M_LN2);
          r->dS = (u - log1p (X)) / fabs (m->a);
        }
    }
  const double den = Sc * Sc + T * tz * R;      /* 1 - T W > 0 */
  if (u <= 1.0)
    {
      const double hc = sinhc (0.5 * u);
      const double Wu = em1c (-u) + Tm * (0.5 * u) * hc * hc;
      r->dtheta = Om0 * tau * (Wu / den) * atanc (Sc * (Wu * u) / den);
    }
  else
    {
      const double W = -expm1 (-u) + 2.0 * Tm * h * h;
      r->dtheta = heading_from_angle (m, atan (Sc * W / den));
    }
}

static void
motion_from_reversal (const chaplygin_smooth_motion *m, double u, int want_S,
                      struct smooth_at *r)
{
  const double zeta = u - m->Z;
  const double th = tanh (zeta), se = 1.0 / cosh (zeta);
  r->V = -m->sigma * (m->c * th);
  r->Omega = m->s * (m->c / m->B) * se;
  if (want_S)
    {
      double lc = logcosh (zeta) / fabs (m->a);
      r->dS = zeta < 0.0 ? m->sigma_c - lc : m->sigma_c + lc;
    }
  r->dtheta = heading_from_angle (m, atan2 (m->T * se + m->Sc * th,
                                            m->Sc * se - m->T * th));
}

/* The state at tau >= 0 (tau finite) of a valid motion. */
static void
motion_eval (const chaplygin_smooth_motion *m, double tau, int want_S,
             struct smooth_at *r)
{
  const double V0 = m->q0[CHAPLYGIN_V], Om0 = m->q0[CHAPLYGIN_OMEGA];
  if (tau == 0.0 || m->kind == MOTION_REST)
    {
      r->V = V0, r->Omega = Om0, r->dtheta = 0.0, r->dS = 0.0;
      return;
    }
  if (m->kind != MOTION_GENERAL)
    {
      /* the line (Omega0 = 0) and the circle (L = 0): V, Omega constant */
      r->V = V0, r->Omega = Om0;
      r->dtheta = m->kind == MOTION_CIRCLE ? Om0 * tau : 0.0;
      r->dS = fabs (V0) * tau;
      return;
    }
  const double u = m->ac * tau;
  if (!m->approaching)
    motion_receding (m, tau, u, want_S, r);
  else if (u <= 0.5 * m->Z)
    motion_approaching (m, tau, u, want_S, r);
  else
    motion_from_reversal (m, u, want_S, r);
}

static int
motion_valid (const chaplygin_smooth_motion *m)
{
  return m && m->kind >= MOTION_REST && m->kind <= MOTION_GENERAL;
}

/* chaplygin_smooth_at_time: (2.1) at elapsed time tau >= 0 from q0:
       V = sqrt(2E) tanh z,  B |Omega| = sqrt(2E) sech z,
       z = atanh(V0/sqrt(2E)) + a sqrt(2E) tau,
       theta = theta0 + sgn(Omega0) (B/L) (gd z - gd z0),
       S = S0 + |log(cosh z/cosh z0)|/|a|  (before the reversal;
           S0 + 2 sigma_c - that after it),
   the closed form of the file comment, a = L/(1 + L^2), B = sqrt(1 + L^2).
   It is the inverse of tau(S) of chaplygin_smooth_closed_form, written in
   time: no root finding, and smooth through the reversal, where V(S) has a
   square-root singularity.  L = 0 is the circle, Omega0 = 0 the line, and
   V0 = 0 with L = 0 (spinning in place) or Omega0 = 0 (rest) keep S = S0.
   Method: the forms of the comment above, chosen by regime; no difference
   of nearly equal quantities except zeta = u - Z near the reversal.
   Accuracy: against a 32-digit Taylor-series integration of (2.1) in time
   (tests/test_smooth.c, smooth_at_time: 33 points on 10 motions, through
   reversals, Omega0 = 1e-6, V0 = 0, V0 tiny, L = 0.001, fast decay):
   S - S0, V, Omega and theta - theta0 within 1.1 eps of |q| + tau |dq/dtau|,
   the change one ulp of q and of tau makes.  That scale exceeds |q| only
   near a reversal after a long approach, where V and Omega are fixed by
   tau only to eps Z (Z = atanh(|V0|/sqrt(2E)) <= 745): the result is then
   exact for a tau within a few ulps of the given one.
   Domain: a motion set up by chaplygin_smooth_motion_init; finite
   tau >= 0.  tau = 0 returns q0 exactly.
   Errors: CHAPLYGIN_EINVAL (NULL, or m not set up), CHAPLYGIN_EDOM (tau
   not finite or negative), CHAPLYGIN_ERANGE (S or theta overflows: S grows
   like sqrt(2E) tau). */
int
chaplygin_smooth_at_time (const chaplygin_smooth_motion *m, double tau,
                          double q[4])
{
  if (!motion_valid (m) || !q)
    return CHAPLYGIN_EINVAL;
  if (!isfinite (tau) || !(tau >= 0.0))
    return CHAPLYGIN_EDOM;
  struct smooth_at r;
  motion_eval (m, tau, 1, &r);
  const double S = m->q0[CHAPLYGIN_S] + r.dS;
  const double th = m->q0[CHAPLYGIN_THETA] + r.dtheta;
  if (!chp_finite4 (S, r.V, th, r.Omega))
    return CHAPLYGIN_ERANGE;
  q[CHAPLYGIN_S] = S;
  q[CHAPLYGIN_V] = r.V;
  q[CHAPLYGIN_THETA] = th;
  q[CHAPLYGIN_OMEGA] = r.Omega;
  return CHAPLYGIN_SUCCESS;
}

/* ---- the path of the contact point ----------------------------------- */

/* dC/dtau = V (cos theta, sin theta) at tau. */
static int
path_integrand (double tau, void *params, double y[2])
{
  const chaplygin_smooth_motion *m = params;
  struct smooth_at r;
  double sn, cs;
  motion_eval (m, tau, 0, &r);
  sincos (m->q0[CHAPLYGIN_THETA] + r.dtheta, &sn, &cs);
  y[0] = r.V * cs;
  y[1] = r.V * sn;
  return CHAPLYGIN_SUCCESS;
}

/* The error allowed to the path quadrature, in units of the arc length
   covered: 128 eps, above the rounding floor of the rule (50 eps times
   Int |dC_x| + |dC_y|, at most 50 sqrt(2) eps times the arc length). */
#define PATH_TOL (128.0 * DBL_EPSILON)

/* The end of the quadrature piece that starts at t (at most tau).  The
   integrand V e(theta) varies on two scales: the heading, and z = z0 +
   sgn(a) |a| c t (V = c tanh z).  A piece ends where the heading has
   turned one more radian (psi = gd(z) moved by |L|/B: t' = sgn(a)
   (gd^-1(psi') - z0)/(|a| c)) or z has moved by 1, whichever is first, so
   that no feature of the integrand falls between the nodes of a long
   piece; at least t + B/c, in which the heading turns by at most a radian
   (|Omega| <= c/B), so that the partition advances where psi has no
   resolution (tiny L).  Once z moves away from 0 beyond
   ZCUT + log(B/|L|), V and theta are constant to within e^-40 (theta has
   (B/|L|) 2 e^-|z| left to turn): the rest is one piece.  Only a
   partition: rounding does no harm. */
#define ZCUT 40.0

static double
path_next (const chaplygin_smooth_motion *m, double t, double tau)
{
  const double sa = chp_sign (m->a);
  const double z0 = m->q0[CHAPLYGIN_V] < 0.0 ? -m->Z : m->Z;
  const double z = z0 + sa * m->ac * t;
  if (sa * z > ZCUT + fmax (0.0, log (m->B / fabs (m->L))))
    return tau;
  if (t + m->B / m->c == t)
    return tau;         /* B/c below the ulp of t: no piece can be shorter */
  /* t1 > t: t + B/c > t, and t + 1/(|a| c) > t since |a| c t < 2^53
     (else sgn(a) z > 2^53 - 745 would have cut off above) */
  double t1 = t + 1.0 / m->ac;                  /* z moves by 1 */
  const double psi1 = atan (sinh (z)) + sa * fabs (m->L) / m->B;
  if (fabs (psi1) < M_PI_2)
    t1 = fmin (t1, fmax (t + m->B / m->c,
                         sa * (asinh (tan (psi1)) - z0) / m->ac));
  return t1 < tau ? t1 : tau;
}

/* x + y as hi + lo (hi the rounded sum), error-free, |x| >= |y| not
   needed (TwoSum), then the running compensation added into lo. */
static void
add_compensated (double *hi, double *lo, double y)
{
  double s, e;
  chp_two_sum (*hi, y, &s, &e);
  *lo += e;
  chp_two_sum (s, *lo, hi, lo);
}

/* chaplygin_smooth_path_init: a path at time tau with C there (NULL: the
   origin), no accumulated error.
   Errors: CHAPLYGIN_EINVAL (NULL path), CHAPLYGIN_EDOM (tau not finite or
   negative, C not finite). */
int
chaplygin_smooth_path_init (double tau, const double C[2],
                            chaplygin_smooth_path *path)
{
  if (!path)
    return CHAPLYGIN_EINVAL;
  if (!isfinite (tau) || !(tau >= 0.0) || (C && !chp_finite2 (C[0], C[1])))
    return CHAPLYGIN_EDOM;
  path->tau = tau;
  path->C[0] = C ? C[0] : 0.0;
  path->C[1] = C ? C[1] : 0.0;
  path->Cerr[0] = 0.0;
  path->Cerr[1] = 0.0;
  return CHAPLYGIN_SUCCESS;
}

/* chaplygin_smooth_path_advance: the contact point C at time tau,
       C(tau) = C(tau1) + Int_(tau1)^tau V (cos theta, sin theta) dtau,
   tau1 = path->tau, and (G not NULL) the mass centre G = C + L (cos theta,
   sin theta) at tau, V and theta those of chaplygin_smooth_at_time.  A
   caller sampling a motion advances one path from sample to sample, so
   that each call integrates one interval; the increments are summed with
   an error-free transformation (path->Cerr), so that the rounding of C
   does not grow with the number of samples.
   Method: the line and the circle in closed form (C moves by V0 dtau
   along theta0, or by V0 dtau sinc(Omega0 dtau/2) along the mean heading);
   otherwise adaptive 21-point Gauss-Kronrod quadrature in time
   (chp_integrate2), over pieces in which the heading turns by at most one
   radian and z = atanh(V/sqrt(2E)) moves by at most 1 (path_next: no
   transient between the nodes of a long piece), to an absolute error
   estimate of 128 eps times the arc length of each piece.  Why quadrature: in closed form the integral is
   Int tan(psi) exp(i k psi) dpsi (k = B/L), a hypergeometric function of
   unit-modulus argument that neither libm nor GSL provides; why time:
   there the integrand is analytic (in a strip of half-width pi/(2|a|c)),
   also through the reversal, where in the arc length theta has a
   square-root singularity.  Cost: proportional to the turn of the heading
   and to the change of z (at most ~90 + 2 Z pieces for the approach,
   reversal and decay) over the interval.
   At an arc length S: advance to the time chaplygin_smooth_closed_form
   gives for S.
   Accuracy: against C and G from the 32-digit Taylor-series integration of
   (2.1) with dC/dtau (tests/test_smooth.c, smooth_path: the 33 points of
   smooth_at_time), within 2.2 eps of the arc length from the start in one
   step, 1.5 in 200 steps.
   Domain: a motion set up by chaplygin_smooth_motion_init; finite
   tau >= path->tau.
   Errors: CHAPLYGIN_EINVAL (NULL, m not set up), CHAPLYGIN_EDOM (tau not
   finite, tau < path->tau), CHAPLYGIN_ERANGE (overflow),
   CHAPLYGIN_ENOCONV (the quadrature did not reach its tolerance).  The
   path is changed only on success. */
int
chaplygin_smooth_path_advance (const chaplygin_smooth_motion *m,
                               chaplygin_smooth_path *path, double tau,
                               double G[2])
{
  if (!motion_valid (m) || !path)
    return CHAPLYGIN_EINVAL;
  const double tau_from = path->tau;
  if (!isfinite (tau) || !(tau >= tau_from))
    return CHAPLYGIN_EDOM;
  const double V0 = m->q0[CHAPLYGIN_V], Om0 = m->q0[CHAPLYGIN_OMEGA];
  const double th0 = m->q0[CHAPLYGIN_THETA];
  double c[2] = { path->C[0], path->C[1] };
  double e[2] = { path->Cerr[0], path->Cerr[1] }, sn, cs;
  if (m->kind == MOTION_LINE)
    {
      sincos (th0, &sn, &cs);
      add_compensated (&c[0], &e[0], V0 * (tau - tau_from) * cs);
      add_compensated (&c[1], &e[1], V0 * (tau - tau_from) * sn);
    }
  else if (m->kind == MOTION_CIRCLE)
    {
      /* (V0/Omega0)(sin th - sin th_from, cos th_from - cos th) */
      const double dt = tau - tau_from, half = 0.5 * Om0 * dt;
      const double len = V0 * dt * (half == 0.0 ? 1.0 : sin (half) / half);
      sincos (th0 + Om0 * (0.5 * (tau_from + tau)), &sn, &cs);
      add_compensated (&c[0], &e[0], len * cs);
      add_compensated (&c[1], &e[1], len * sn);
    }
  else if (m->kind == MOTION_GENERAL)
    {
      struct smooth_at ra, rb;
      chaplygin_smooth_motion mm = *m;  /* the integrand's (non-const) */
      motion_eval (m, tau_from, 1, &ra);
      for (double t = tau_from; t < tau;)
        {
          const double t1 = path_next (m, t, tau);
          double piece[2];
          motion_eval (m, t1, 1, &rb);
          CHP_TRY (chp_integrate2 (path_integrand, &mm, t, t1,
                                   PATH_TOL * fabs (rb.dS - ra.dS), piece));
          add_compensated (&c[0], &e[0], piece[0]);
          add_compensated (&c[1], &e[1], piece[1]);
          t = t1;
          ra = rb;
        }
    }
  struct smooth_at r;
  motion_eval (m, tau, 0, &r);
  sincos (th0 + r.dtheta, &sn, &cs);
  const double g0 = fma (m->L, cs, c[0]), g1 = fma (m->L, sn, c[1]);
  if (!chp_finite4 (c[0], c[1], g0, g1))
    return CHAPLYGIN_ERANGE;            /* (e is finite where c is) */
  path->tau = tau;
  path->C[0] = c[0];
  path->C[1] = c[1];
  path->Cerr[0] = e[0];
  path->Cerr[1] = e[1];
  if (G)
    {
      G[0] = g0;
      G[1] = g1;
    }
  return CHAPLYGIN_SUCCESS;
}
