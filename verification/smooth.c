/* smooth.c -- the smooth Chaplygin sleigh, Section 2 and Appendix A:
   (2.1), (2.4), the eigenvalue xi4 of Section 2.1, (A.1)-(A.6).

   Route: the equations of motion (2.1) are written out here from the
   paper, with dS/dtau = |V| (S is arc length: errata E1), together with the
   path of the skate contact C, dX/dtau = V cos theta, dY/dtau = V sin theta,
   and integrated with GSL's rk8pd from random states: both signs of L, V0
   and Omega0, plus the special starts V0 = 0, Omega0 = 0 and L = 0.
   dV/dtau = L Omega^2 has a fixed sign, so V is monotone and changes sign
   at most once.  The crossing V = 0 is located exactly by Henon's trick:
   from the last output before it, V itself becomes the independent
   variable (d(S, tau, theta, Omega, X, Y)/dV = f/(L Omega^2), smooth since
   Omega != 0 there) and the integration stops at V = 0 exactly; the
   integration in tau restarts from that state with the other sign of
   dS/dtau = |V| (so that each leg has a smooth vector field).

   Nothing of the library's closed forms is used: the library's functions
   are only evaluated at the integrated arc length S and compared with the
   integrated V, Omega, theta, tau (closed form (A.2), (A.3), (A.4)), at the
   integrated reversal (A.1), (A.6), and along the integration E and H_C
   (A.4) must stay constant / follow the integrated Omega.  The steady
   states (2.4), (A.5) are integrated too, and the eigenvalue xi4 is
   measured from the integration: (i) the growth or decay rate of a
   perturbation of amplitude 1e-9 in Omega over a time T, (ii) the whole
   monodromy matrix of the flow at time T by central differences, which
   must be upper triangular with diagonal {1, 1, 1, exp(xi4 T)}: the
   eigenvalues xi1-3 = 0 and xi4.

   Comparisons of V, Omega, theta, tau at the integrated S are made where
   |V| >= sqrt(2E)/10: near the reversal V, theta and tau are square-root
   functions of S (dV/dS = L Omega^2/|V|) and an integration error in S is
   amplified without bound; the reversal itself is compared separately, at
   the library's S_c against the integrated state at V = 0.  */
#include <config.h>

#include <float.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>
#include <math.h>
#include <stdlib.h>

#include "chaplygin.h"
#include "tap.h"

/* Integration tolerance: relative to |y| + h |dy/dtau| for each component
   (so that a component through 0, or the arc length from its start, gets
   no absolute floor that would swamp small motions). */
#define RTOL 1e-13

static gsl_odeiv2_driver *
new_driver (const gsl_odeiv2_system *sys, double h0, double rtol)
{
  return gsl_odeiv2_driver_alloc_standard_new (sys, gsl_odeiv2_step_rk8pd, h0,
                                               1e-300, rtol, 1.0, 1.0);
}

typedef struct
{
  double L;     /* L = ell/rho */
  double s;     /* the sign of V on the current leg: dS/dtau = s V = |V| */
} leg_par;

/* (2.1) with dS/dtau = |V|, and the contact point C = (X, Y).
   y = {S, V, theta, Omega, X, Y}. */
static int
rhs_tau (double t, const double y[], double f[], void *p)
{
  (void) t;
  const leg_par *P = p;
  double L = P->L, V = y[1], Om = y[3];
  f[0] = P->s * V;
  f[1] = L * Om * Om;
  f[2] = Om;
  f[3] = -L / (L * L + 1.0) * V * Om;
  f[4] = V * cos (y[2]);
  f[5] = V * sin (y[2]);
  return GSL_SUCCESS;
}

/* Henon's trick: the same motion with u = s (Vp - V) as the independent
   variable, u increasing while |V| falls to 0 (dV/dtau = L Omega^2 has the
   sign -s on such a leg): z = {S, tau, theta, Omega, X, Y, V},
   dz/du = f / |L Omega^2|, dV/du = -s. */
static int
rhs_u (double u, const double z[], double f[], void *p)
{
  (void) u;
  const leg_par *P = p;
  double L = P->L, Om = z[3], V = z[6];
  double w = 1.0 / fabs (L * Om * Om);
  f[0] = P->s * V * w;
  f[1] = w;
  f[2] = Om * w;
  f[3] = -L / (L * L + 1.0) * V * Om * w;
  f[4] = V * cos (z[2]) * w;
  f[5] = V * sin (z[2]) * w;
  f[6] = -P->s;                 /* dV/du */
  return GSL_SUCCESS;
}

/* Worst discrepancies over all trajectories. */
static struct
{
  double field, cfV, cfO, cfth, cftau, ehH, ehth, E, H, Sc, Sc_eh,
    rev_th, rev_tau, rev_O, rev_V;
  int bad, K_mismatch, rev_mismatch, Sc_shift, eh_E_not_exact, points, reversals,
    trajectories;
} W;

/* Checks at one integrated point y (time t) of the trajectory from q0;
   y[0] is the arc length from the start, S = S0 + y[0]. */
static void
check_point (double L, const double q0[4], double E0, double t,
             const double y[6])
{
  double S = q0[0] + y[0], V = y[1], th = y[2], Om = y[3];
  double B = sqrt (1.0 + L * L), s2E = sqrt (2.0 * E0);
  W.points++;

  /* (2.1): the library's field against the one written out above. */
  double q[4] = { S, V, th, Om }, dq[4], g[6];
  leg_par P = { L, V < 0 ? -1.0 : 1.0 };
  rhs_tau (0, y, g, &P);
  if (chaplygin_smooth_field (L, q, dq))
    W.bad = __LINE__;
  else
    for (int i = 0; i < 4; i++)
      W.field = fmax (W.field, fabs (dq[i] - g[i]) / (fabs (g[i]) + E0));

  /* (A.4) E conserved (library's E at the integrated state), and
     H_C = (1 + L^2) Omega. */
  double E, H;
  if (chaplygin_smooth_energy (L, V, Om, &E) || chaplygin_smooth_momentum (L, Om, &H))
    W.bad = __LINE__;
  else
    {
      W.E = fmax (W.E, fabs (E - E0) / E0);
      double Hm = (1.0 + L * L) * Om;
      W.H = fmax (W.H, fabs (H - Hm) / fmax (fabs (Hm), 1e-300));
    }

  if (fabs (V) < 0.1 * s2E || y[0] == 0.0)
    return;

  /* (A.2) closed form at the integrated S. */
  double qc[4], dtau;
  if (chaplygin_smooth_closed_form (L, q0, S, qc, &dtau))
    {
      W.bad = __LINE__;
      return;
    }
  W.cfV = fmax (W.cfV, fabs (qc[1] - V) / s2E);
  W.cfO = fmax (W.cfO, fabs (qc[3] - Om) * B / s2E);
  W.cfth = fmax (W.cfth, fabs (qc[2] - th) / (1.0 + fabs (th - q0[2])));
  W.cftau = fmax (W.cftau, fabs (dtau - t) / t);

  /* (A.3) K = sgn(V(S)/V0) (V0 = 0: the motion leaves the turning point
     and K = 1). */
  int K;
  if (chaplygin_smooth_branch (L, q0, S, &K))
    W.bad = __LINE__;
  else if (K != (q0[1] == 0.0 || (V > 0) == (q0[1] > 0) ? 1 : -1))
    W.K_mismatch++;

  /* (A.4) in energy-momentum form, p0 = {S0, E0, theta0, H0} with E0 and
     H0 formed here from q0.  Not from a turning point (V0 = 0): there the
     rounding of E0, H0 leaves V0^2 = 2 E0 - H0^2/(1 + L^2) ~ eps E0, i.e.
     V0 ~ 1e-8 sqrt(2 E0) of either sign, and the motion is ill-conditioned
     in (E0, H0) (the library documents this). */
  if (q0[1] == 0.0)
    return;
  double p0[4] = { q0[0], E0, q0[2], (1.0 + L * L) * q0[3] }, p[4];
  int dir0 = q0[1] > 0 ? 1 : -1;
  if (chaplygin_smooth_closed_form_eh (L, p0, dir0, S, p))
    W.bad = __LINE__;
  else
    {
      double Hm = (1.0 + L * L) * Om;
      if (p[1] != E0)
        W.eh_E_not_exact++;
      W.ehH = fmax (W.ehH, fabs (p[3] - Hm) / (B * s2E));
      W.ehth = fmax (W.ehth, fabs (p[2] - th) / (1.0 + fabs (th - q0[2])));
    }
}

/* The reversal: y = {S, 0, theta, Omega, X, Y} at time t, V = 0 exactly. */
static void
check_reversal (double L, const double q0[4], double E0, double t,
                const double y[6])
{
  double B = sqrt (1.0 + L * L), s2E = sqrt (2.0 * E0);
  W.reversals++;
  /* The library's S_c from the start shifted to S0 = 0, so that S_c is the
     arc length to the reversal itself, not rounded through S0 + (S_c - S0):
     V, theta and tau are square-root functions of S - S_c near S_c, and
     the closed form is evaluated there below.  The start at S0 itself
     must give S0 + that arc length. */
  int rev, rev_eh, rev0;
  double Sc, Sc_eh, Sc0;
  double H0 = (1.0 + L * L) * q0[3];
  double q00[4] = { 0.0, q0[1], q0[2], q0[3] }, qc[4], dtau;
  if (chaplygin_smooth_reversal (L, q0, &rev, &Sc)
      || chaplygin_smooth_reversal (L, q00, &rev0, &Sc0)
      || chaplygin_smooth_reversal_eh (L, 0.0, E0, H0, q0[1] > 0 ? 1 : -1,
                                       &rev_eh, &Sc_eh))
    {
      W.bad = __LINE__;
      return;
    }
  if (!rev || !rev_eh || !rev0)
    {
      W.rev_mismatch++;
      return;
    }
  if (Sc != q0[0] + Sc0)
    W.Sc_shift++;
  double arc = y[0];
  W.Sc = fmax (W.Sc, fabs (Sc0 - arc) / arc);
  /* (A.6) from (E0, H0) rounded to doubles: S_c - S0 is proportional to
     log(2 E0 (1 + L^2)/H0^2) = log1p(V0^2 (1 + L^2)/H0^2), so a relative
     error u in E0, H0 or 1 + L^2 (the rounding of the inputs, ~2.5 eps in
     all) or in the argument of the logarithm (the library's own roundings
     of 2 E0 (1 + L^2)/H0^2, formed as a quotient near 1: ~5 eps) moves it
     by u kappa relative, kappa = 2 E0/V0^2 (up to 1e7 here).  The excess
     over 8 eps kappa is checked. */
  double kappa = 2.0 * E0 / (q0[1] * q0[1]);
  W.Sc_eh = fmax (W.Sc_eh, fabs (Sc_eh - arc) / arc - 8.0 * DBL_EPSILON * kappa);
  if (chaplygin_smooth_closed_form (L, q00, Sc0, qc, &dtau))
    {
      W.bad = __LINE__;
      return;
    }
  W.rev_V = fmax (W.rev_V, fabs (qc[1]) / s2E);
  W.rev_O = fmax (W.rev_O, fabs (qc[3] - y[3]) * B / s2E);
  W.rev_th = fmax (W.rev_th, fabs (qc[2] - y[2]) / (1.0 + fabs (y[2] - q0[2])));
  W.rev_tau = fmax (W.rev_tau, fabs (dtau - t) / t);
}

/* Integrate from q0 to the reversal (if any) and T_after beyond it (or to
   T_after if there is none), checking every hout. */
static void
trajectory (double L, const double q0[4])
{
  double E0 = 0.5 * (q0[1] * q0[1] + (1.0 + L * L) * q0[3] * q0[3]);
  /* output every ~0.05 of arc length (time scales as 1/speed), and 8
     units of time (or of arc, for slow motions) beyond the reversal */
  const double v = fmin (1.0, sqrt (2.0 * E0));
  const double hout = 0.05 / v, T_after = 8.0 / v, T_cap = 1e4 / v;
  double y[6] = { 0.0, q0[1], q0[2], q0[3], 0.0, 0.0 };
  /* The sign of V on the first leg: V0's, or, from a turning point
     (V0 = 0), L's (dV/dtau = L Omega^2). */
  leg_par P = { L, q0[1] != 0.0 ? (q0[1] > 0 ? 1.0 : -1.0) : (L > 0 ? 1.0 : -1.0) };
  gsl_odeiv2_system sys = { rhs_tau, NULL, 6, &P };
  gsl_odeiv2_driver *d = new_driver (&sys, 1e-3, RTOL);
  double t = 0.0, t_end = T_after;
  int reversed = 0;
  /* a reversal is expected iff V moves towards 0 */
  int expect = L != 0.0 && q0[3] != 0.0 && q0[1] != 0.0 && (L > 0) != (q0[1] > 0);
  if (expect)
    t_end = T_cap;
  W.trajectories++;
  while (t < t_end)
    {
      double yp[6], tp = t;
      for (int i = 0; i < 6; i++)
        yp[i] = y[i];
      if (gsl_odeiv2_driver_apply (d, &t, fmin (t + hout, t_end), y) != GSL_SUCCESS)
        {
          W.bad = __LINE__;
          break;
        }
      if (!reversed && y[1] * P.s < 0.0)
        {
          /* V crossed 0 in (tp, t]: from yp, integrate in u = s (Vp - V)
             up to u = |Vp|, i.e. V = 0 exactly. */
          double z[7] = { yp[0], tp, yp[2], yp[3], yp[4], yp[5], yp[1] };
          gsl_odeiv2_system hs = { rhs_u, NULL, 7, &P };
          gsl_odeiv2_driver *dh = new_driver (&hs, 1e-3 * fabs (yp[1]), RTOL);
          double u = 0.0;
          int st = gsl_odeiv2_driver_apply (dh, &u, fabs (yp[1]), z);
          gsl_odeiv2_driver_free (dh);
          if (st != GSL_SUCCESS)
            {
              W.bad = __LINE__;
              break;
            }
          double yc[6] = { z[0], 0.0, z[2], z[3], z[4], z[5] };
          check_reversal (L, q0, E0, z[1], yc);
          for (int i = 0; i < 6; i++)
            y[i] = yc[i];
          t = z[1];
          t_end = t + T_after;
          P.s = -P.s;
          gsl_odeiv2_driver_reset (d);
          reversed = 1;
          continue;
        }
      check_point (L, q0, E0, t, y);
    }
  if (expect != reversed)
    W.rev_mismatch++;
  if (!expect)
    {
      /* the library must agree that there is no reversal */
      int rev;
      double Sc = -1.0;
      if (chaplygin_smooth_reversal (L, q0, &rev, &Sc))
        W.bad = __LINE__;
      else if (rev)
        W.rev_mismatch++;
    }
  gsl_odeiv2_driver_free (d);
}

/* Steady states (2.4), (A.5): integrate from q* = {0, V*, theta*, 0} to tau
   and compare with chaplygin_smooth_steady; E* = V*^2/2 by the energy of
   the integrated state, H* = 0.  Returns the worst relative discrepancy. */
static double
steady (double Vs, double ths, double tau, int *bad)
{
  leg_par P = { 0.7, Vs > 0 ? 1.0 : -1.0 };
  double worst = 0.0;
  for (int k = 0; k < 2; k++)
    {
      P.L = k ? -1.3 : 0.7;     /* L plays no role on the steady state */
      gsl_odeiv2_system sys = { rhs_tau, NULL, 6, &P };
      gsl_odeiv2_driver *d = new_driver (&sys, 1e-3, RTOL);
      double y[6] = { 0.0, Vs, ths, 0.0, 0.0, 0.0 }, t = 0.0;
      if (gsl_odeiv2_driver_apply (d, &t, tau, y) != GSL_SUCCESS)
        *bad = __LINE__;
      gsl_odeiv2_driver_free (d);
      double q[4], E, H, Eh, Hh;
      if (chaplygin_smooth_steady (Vs, ths, tau, q, &E, &H)
          || chaplygin_smooth_steady_eh (Vs, &Eh, &Hh))
        {
          *bad = __LINE__;
          continue;
        }
      double Ei = 0.5 * (y[1] * y[1] + (1.0 + P.L * P.L) * y[3] * y[3]);
      double Hi = (1.0 + P.L * P.L) * y[3];
      double e[8] = { (q[0] - y[0]) / y[0], (q[1] - y[1]) / y[1],
                      (q[2] - y[2]) / (1.0 + fabs (y[2])), q[3] - y[3],
                      (E - Ei) / Ei, H - Hi, (Eh - Ei) / Ei, Hh - Hi };
      for (int i = 0; i < 8; i++)
        worst = fmax (worst, fabs (e[i]));
    }
  return worst;
}

/* The flow of (2.1) over time T from q (phase form), with tolerance rtol
   and no absolute floor (the perturbations are tiny). */
static int
flow (double L, const double q[4], double T, double rtol, double out[4])
{
  leg_par P = { L, q[1] > 0 ? 1.0 : -1.0 };
  gsl_odeiv2_system sys = { rhs_tau, NULL, 6, &P };
  gsl_odeiv2_driver *d = new_driver (&sys, 1e-3, rtol);
  double y[6] = { q[0], q[1], q[2], q[3], 0.0, 0.0 }, t = 0.0;
  int st = gsl_odeiv2_driver_apply (d, &t, T, y);
  gsl_odeiv2_driver_free (d);
  for (int i = 0; i < 4; i++)
    out[i] = y[i];
  return st;
}

static double
sgn_rand (unsigned long long *seed)
{
  return tap_uniform (seed, 0, 1) < 0.5 ? -1.0 : 1.0;
}

int
main (void)
{
  gsl_set_error_handler_off ();
  const int level = tap_level ();
  unsigned long long seed = 20260417;

  /* ---- trajectories through the reversal ---- */
  const int ntraj = level == 1 ? 10000 : 250000;
  int special = 0;
  for (int k = 0; k < ntraj; k++)
    {
      /* magnitudes log-uniform: L in [0.05, 20], V0 in [0.01, 5],
         Omega0 in [0.01, 5]; signs random */
      double L = sgn_rand (&seed) * exp (tap_uniform (&seed, log (0.05), log (20.0)));
      double V0 = sgn_rand (&seed) * exp (tap_uniform (&seed, log (0.01), log (5.0)));
      double Om0 = sgn_rand (&seed) * exp (tap_uniform (&seed, log (0.01), log (5.0)));
      double S0 = tap_uniform (&seed, 0, 5), th0 = tap_uniform (&seed, -3, 3);
      /* special starts: a turning point (V0 = 0), straight line
         (Omega0 = 0), the circle L = 0 */
      switch (k % 20)
        {
        case 7:
          V0 = 0.0, special++;
          break;
        case 11:
          Om0 = 0.0, special++;
          break;
        case 13:
          L = 0.0, special++;
          break;
        default:
          break;
        }
      double q0[4] = { S0, V0, th0, Om0 };
      trajectory (L, q0);
    }
  tap_check (!W.bad && W.points > 100 * ntraj && W.reversals > ntraj / 3, W.bad, 0,
             "set-up: %d trajectories (%d special starts V0 = 0, Omega0 = 0, L = 0), "
             "%d points, %d reversals located at V = 0, all calls succeeded",
             W.trajectories, special, W.points, W.reversals);
  tap_check (W.field <= 4e-16, W.field, 4e-16,
             "(2.1) library field (dS/dtau = |V|) vs the field written out here, "
             "at every integrated point (relative to |f| + E)");
  /* Tolerances of the integration route: rk8pd at rtol 1e-13 (relative
     to |y| + h |dy/dtau|) keeps global errors at a few 1e-14 here; each
     tolerance below is 2-10 times the worst measured at level 2 (250000
     trajectories) and 100-1000 times below the discrepancy that a 1e-10
     relative perturbation of the library's results produces. */
  tap_check (W.E <= 2e-13, W.E, 2e-13,
             "(A.4) E conserved: library's E at the integrated states (relative)");
  /* three roundings on each side (L^2, 1 + L^2, the product) */
  tap_check (W.H <= 3 * 0x1p-52, W.H, 3 * 0x1p-52,
             "(A.4) library's H_C vs (1 + L^2) Omega of the integrated state (relative)");
  tap_check (W.rev_mismatch == 0, W.rev_mismatch, 0,
             "(A.1), (A.6) a reversal iff the integration crosses V = 0 "
             "(L V0 < 0, Omega0 != 0), both library forms");
  tap_check (W.Sc <= 1e-13 && W.Sc_eh <= 1e-13 && W.Sc_shift == 0, fmax (W.Sc, W.Sc_eh), 1e-13,
             "(A.1), (A.6) S_c - S0 vs the arc length to V = 0 located by Henon's "
             "trick (relative: (A.1) %.2g; (A.6) %.2g beyond 8 eps 2E0/V0^2, the effect of "
             "rounding E0, H0 and of log near 1), %d reversals; S_c = S0 + (S_c at S0 = 0) "
             "exactly (%d not)",
             W.Sc, W.Sc_eh, W.reversals, W.Sc_shift);
  tap_check (W.rev_V <= 1e-15 && W.rev_O <= 5e-14 && W.rev_th <= 5e-14 && W.rev_tau <= 5e-14,
             fmax (fmax (W.rev_V, W.rev_O), fmax (W.rev_th, W.rev_tau)), 5e-14,
             "(A.2) at the library's S_c: V = 0 (/sqrt(2E), <= 1e-15), Omega, theta, tau "
             "vs the integrated state at V = 0 (V %.2g, Omega %.2g, theta %.2g, tau %.2g)",
             W.rev_V, W.rev_O, W.rev_th, W.rev_tau);
  /* points with |V| >= sqrt(2E)/10, where the conditioning in S is at
     most ~10 |L| Omega^2/sqrt(2E) */
  tap_check (W.cfV <= 1e-12 && W.cfO <= 1e-12, fmax (W.cfV, W.cfO), 1e-12,
             "(A.2) V and Omega at the integrated S, before and after the reversal "
             "(relative to sqrt(2E), sqrt(2E)/sqrt(1 + L^2)): V %.2g, Omega %.2g",
             W.cfV, W.cfO);
  tap_check (W.cfth <= 1e-12, W.cfth, 1e-12,
             "(A.2) theta at the integrated S (relative to 1 + |theta - theta0|)");
  tap_check (W.cftau <= 1e-12, W.cftau, 1e-12,
             "(A.2) elapsed time tau(S) - tau(S0) vs the integrated time (relative)");
  tap_check (W.K_mismatch == 0, W.K_mismatch, 0,
             "(A.3) K = sgn(V(S)/V0) of the integration at every point");
  /* from (E0, H0) rounded to doubles, V0 is known to eps E0/|V0| only,
     which moves psi0 by up to eps sqrt(2E0)/|V0|: 3e-12 for theta */
  tap_check (W.eh_E_not_exact == 0 && W.ehH <= 1e-12 && W.ehth <= 3e-12,
             fmax (W.ehH, W.ehth / 3), 1e-12,
             "(A.4) energy-momentum closed form: E = E0 exactly (%d not), H_C "
             "(relative to sqrt(2E (1 + L^2))) %.2g and theta %.2g at the integrated S",
             W.eh_E_not_exact, W.ehH, W.ehth);

  /* ---- steady states (2.4), (A.5) ---- */
  {
    double worst = 0.0;
    int bad = 0;
    for (int k = 0; k < 40; k++)
      {
        double Vs = tap_uniform (&seed, 0.1, 3) * (k % 2 ? -1 : 1);
        worst = fmax (worst, steady (Vs, tap_uniform (&seed, -3, 3),
                                     tap_uniform (&seed, 0.5, 10), &bad));
      }
    /* along a straight line rk8pd is exact up to the rounding of the sum
       S = sum |V*| h: a few ulps */
    tap_check (!bad && worst <= 4e-15, worst, 4e-15,
               "(2.4), (A.5) steady states {|V*| tau, V*, theta*, 0}, E* = V*^2/2, "
               "H*_C = 0 vs integration of (2.1) from them, 40 cases");
  }

  /* ---- the eigenvalue xi4 ---- */
  {
    double worst_amp = 0.0, worst_tri = 0.0, worst_diag = 0.0, worst_eig = 0.0;
    int bad = 0;
    const int n = level == 1 ? 200 : 5000;
    for (int k = 0; k < n; k++)
      {
        double L = tap_uniform (&seed, 0.1, 3) * (k % 2 ? -1 : 1);
        double Vs = tap_uniform (&seed, 0.3, 2) * (k % 4 < 2 ? -1 : 1);
        double ths = tap_uniform (&seed, 0.2, 3), S0 = tap_uniform (&seed, 1, 3);
        double T = 4.0, xi_lib;
        if (chaplygin_smooth_eigenvalue (L, Vs, &xi_lib))
          {
            bad = __LINE__;
            continue;
          }
        /* (i) amplitude 1e-9: nonlinear terms are O(1e-18) relative;
           xi = log(Omega(T)/eps)/T to ~rtol/T. */
        const double eps = 1e-9;
        double q[4] = { S0, Vs, ths, eps }, o[4];
        if (flow (L, q, T, 1e-14, o) != GSL_SUCCESS)
          bad = __LINE__;
        double xi = log (o[3] / eps) / T;
        worst_amp = fmax (worst_amp, fabs (xi - xi_lib) / fabs (xi_lib));
        /* (ii) the monodromy matrix M = dPhi_T/dq by central differences:
           upper triangular, diagonal {1, 1, 1, exp(xi4 T)}.  Along the
           steady family (S, V, theta; Omega = 0) the flow is linear, so
           the steps are large (1e-2, relative in V) and the differences
           lose only eps/1e-2; Omega(T) is odd in Omega0 (the symmetry
           Omega -> -Omega, theta -> -theta), so the central difference
           in Omega has no cancellation in the Omega row and an error
           O(h^2) = 1e-14 for h = 1e-7. */
        double M[4][4], h[4] = { 1e-2, 1e-2 * fabs (Vs), 1e-2, 1e-7 };
        double base[4] = { S0, Vs, ths, 0.0 };
        for (int j = 0; j < 4; j++)
          {
            double qp[4], qm[4], op[4], om[4];
            for (int i = 0; i < 4; i++)
              qp[i] = qm[i] = base[i];
            qp[j] += h[j];
            qm[j] -= h[j];
            if (flow (L, qp, T, 1e-14, op) != GSL_SUCCESS
                || flow (L, qm, T, 1e-14, om) != GSL_SUCCESS)
              bad = __LINE__;
            for (int i = 0; i < 4; i++)
              M[i][j] = (op[i] - om[i]) / (2.0 * h[j]);
          }
        for (int i = 0; i < 4; i++)
          for (int j = 0; j < i; j++)
            worst_tri = fmax (worst_tri, fabs (M[i][j]));
        for (int i = 0; i < 3; i++)
          worst_diag = fmax (worst_diag, fabs (log (M[i][i]) / T));
        worst_eig = fmax (worst_eig, fabs (log (M[3][3]) / T - xi_lib) / fabs (xi_lib));
      }
    /* at amplitude 1e-9 the Omega equation is linear to 1e-18 and V
       constant to 1e-18; rk8pd at rtol 1e-14 gives Omega(T) to ~1e-14,
       xi to ~1e-14/(xi T) relative */
    tap_check (!bad && worst_amp <= 2e-14, worst_amp, 2e-14,
               "Section 2.1 xi4 = -L V*/(1 + L^2) (library) vs the rate log(Omega(T)/Omega0)/T "
               "of a 1e-9 perturbation integrated over T = 4, %d steady states, both signs of L, V* "
               "(relative)", n);
    /* (the entries below the diagonal vanish identically on the steady
       family: it is invariant; the diagonal differences lose ~1e-14 to
       rounding of states |y| <= 10 over steps 1e-2) */
    tap_check (!bad && worst_tri == 0 && worst_diag <= 2e-13, fmax (worst_tri, worst_diag), 2e-13,
               "Section 2.1 xi1-3 = 0: the numerical monodromy matrix is upper triangular "
               "(below-diagonal %.2g) with log(diagonal)/T = 0, 0, 0 (%.2g)",
               worst_tri, worst_diag);
    tap_check (!bad && worst_eig <= 1e-11, worst_eig, 1e-11,
               "Section 2.1 xi4 (library) vs log(M_44)/T of the numerical monodromy matrix (relative)");
  }
  return tap_done ();
}
