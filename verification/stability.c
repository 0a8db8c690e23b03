/* stability.c -- the period-1 analysis (3.9), (3.11), (3.12), (B.9),
   (B.11) confirmed against an integration of its own.

   Route: near a straight-line motion V does not vanish, so a segment
   between collisions is integrated with D as the independent variable,
   from the peg's end to the far end exactly (no event location needed):
       dV/dD = l Omega^2/V,  dtheta/dD = Omega/V,
       dOmega/dD = -2 l Omega/(1 + l^2),  dtau/dD = 1/V,   l = L0 + D,
   which is (3.1) divided by dD/dtau = V, written out here.  The
   collision is derived here from angular momentum about the new peg P'
   (the impulse acts at P'): with l- and l+ the distances of the mass
   centre from the old and the new peg along the slot, the velocity of G
   is v e + l- Omega e_n and (I + m l+^2) Omega+ = I Omega- + m l+ (l-
   Omega-), i.e. Omega+ = (1 + l+ l-)/(1 + l+^2) Omega- in units of rho;
   V is unchanged.  GSL rk8pd at relative tolerance 1e-13 (no absolute
   floor).

   Checks:
   (3.9)  d theta'/dH at H = 0 and d theta'/dE at H != 0 by central
          differences of the integrated heading, against the library's
          analytic Jacobian;
   (3.11), (3.12)  from a fixed point with a small Omega, |H| shrinks over
          20 integrated collisions iff chaplygin_discrete_stable says so;
   (B.9)  E and H after n integrated collisions against
          chaplygin_discrete_energy_after;
   (B.11) chaplygin_discrete_energy_converges against the measured
          one-collision ratio H'/H (|ratio| < 1).  */
#include <config.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>
#include <math.h>
#include <stdlib.h>

#include "chaplygin.h"
#include "tap.h"

struct skate
{
  double L0, Delta;
};

static int
rhs_D (double D, const double y[], double f[], void *p)
{
  const struct skate *s = p;
  double l = s->L0 + D, V = y[0], Om = y[2];
  f[0] = l * Om * Om / V;
  f[1] = Om / V;
  f[2] = -2.0 * l * Om / (1.0 + l * l);
  f[3] = 1.0 / V;
  return GSL_SUCCESS;
}

/* One segment and collision from the post-collision phase state
   (V, theta, Omega, tau) with the peg at the end dir implies, for a
   segment that does not reverse; returns 0 on success. */
static int
segment (const struct skate *s, int dir, double y[4])
{
  struct skate copy = *s;
  gsl_odeiv2_system sys = { rhs_D, NULL, 4, &copy };
  double D0 = dir > 0 ? 0.0 : s->Delta, D1 = s->Delta - D0;
  /* purely relative error control (with the derivative term, so that
     components starting at 0 are controlled too): Omega may have decayed
     by many orders of magnitude */
  gsl_odeiv2_driver *d
    = gsl_odeiv2_driver_alloc_standard_new (&sys, gsl_odeiv2_step_rk8pd,
                                            dir * 1e-3, 0.0, 1e-13, 1.0, 1.0);
  double D = D0;
  int st = gsl_odeiv2_driver_apply (d, &D, D1, y);
  gsl_odeiv2_driver_free (d);
  if (st != GSL_SUCCESS || !(y[0] * dir > 0))
    return 1;
  /* collision at D1: l- = L0 + D1, new peg at D0' = D0, l+ = L0 + D0 */
  double lm = s->L0 + D1, lp = s->L0 + D0;
  y[2] *= (1.0 + lp * lm) / (1.0 + lp * lp);
  return 0;
}

static double
energy (const struct skate *s, int dir, const double y[4])
{
  double l = s->L0 + (dir > 0 ? 0.0 : s->Delta);
  return 0.5 * (y[0] * y[0] + (1.0 + l * l) * y[2] * y[2]);
}

static double
momentum (const struct skate *s, int dir, const double y[4])
{
  double l = s->L0 + (dir > 0 ? 0.0 : s->Delta);
  return (1.0 + l * l) * y[2];
}

/* heading increment of one segment from (dir, E, H) */
static double
heading (const struct skate *s, int dir, double E, double H)
{
  double l = s->L0 + (dir > 0 ? 0.0 : s->Delta), n = 1.0 + l * l;
  double y[4] = { dir * sqrt (2.0 * E - H * H / n), 0.0, H / n, 0.0 };
  if (segment (s, dir, y))
    abort ();
  return y[1];
}

int
main (void)
{
  gsl_set_error_handler_off ();
  unsigned long long seed = 3911;
  const int level = tap_level ();
  const int N = 60 * level * level;

  /* (3.9): the f3 partials by central differences (step 1e-4 relative:
     truncation ~1e-8, integration error 1e-13/1e-4 = 1e-9; measured
     6.3e-9); tolerance 1e-7 relative */
  double worst = 0;
  int bad = 0;
  for (int k = 0; k < N; k++)
    {
      struct skate s = { tap_uniform (&seed, -3, 3), tap_uniform (&seed, 0.1, 2) };
      int dir = tap_uniform (&seed, 0, 1) < 0.5 ? 1 : -1;
      double E = tap_uniform (&seed, 0.5, 2), H = k % 2 ? 0.0 : 0.05 * E;
      chaplygin_discrete sys;
      chaplygin_discrete_state st = { dir, E, H, 0, 0, { 0, 0 }, 0.0 };
      double J[16];
      if (chaplygin_discrete_init (&sys, s.L0, s.Delta)
          || chaplygin_discrete_jacobian (&sys, &st, J))
        {
          bad = 1;
          continue;
        }
      double hH = 1e-4 * sqrt (2 * E), hE = 1e-4 * E;
      double dH = (heading (&s, dir, E, H + hH) - heading (&s, dir, E, H - hH)) / (2 * hH);
      double dE = H == 0.0 ? 0.0
        : (heading (&s, dir, E + hE, H) - heading (&s, dir, E - hE, H)) / (2 * hE);
      double e1 = fabs (J[11] - dH) / fabs (dH);
      double e2 = H == 0.0 ? fabs (J[9]) : fabs (J[9] - dE) / fabs (dE);
      if (e1 > worst)
        worst = e1;
      if (e2 > worst)
        worst = e2;
    }
  tap_check (!bad && worst < 1e-7, worst, 1e-7,
             "(3.9) df3/dH and df3/dE of chaplygin_discrete_jacobian vs "
             "central differences of the integrated heading, %d states "
             "(half at the fixed point H = 0)", N);

  /* (3.11), (3.12): a fixed point with Omega perturbed to 1e-6 of V;
     over 20 collisions |H| must shrink iff stable (points where
     ||sigma4| - 1| < 0.05 are skipped: there 20 collisions decide
     nothing).  (B.11) with the measured one-collision ratio. */
  int mism = 0, n_st = 0, n_un = 0, mism11 = 0;
  for (int k = 0; k < 4 * N; k++)
    {
      double x = tap_uniform (&seed, -3, 1.5), yy = tap_uniform (&seed, 0.02, 1);
      struct skate s = { x / sqrt (yy), 1 / sqrt (yy) };
      int dir = k % 2 ? 1 : -1;
      double V = 1.3 * dir, l = s.L0 + (dir > 0 ? 0.0 : s.Delta);
      double y[4] = { V, 0, 1e-6 / (1 + l * l), 0 };
      double H0 = momentum (&s, dir, y);
      double y1[4] = { y[0], y[1], y[2], y[3] };
      if (segment (&s, dir, y1))
        continue;
      double ratio = momentum (&s, dir, y1) / H0;
      if (fabs (fabs (ratio) - 1) < 0.05)
        continue;
      int stable, conv;
      if (chaplygin_discrete_stable (s.L0, s.Delta, dir, &stable)
          || chaplygin_discrete_energy_converges (s.L0, s.Delta, dir, &conv))
        {
          mism++;
          continue;
        }
      int ok = 1;
      for (int c = 0; c < 20 && ok; c++)
        ok = !segment (&s, dir, y);
      int shrinks = ok && fabs (momentum (&s, dir, y)) < fabs (H0);
      mism += shrinks != stable;
      mism11 += (fabs (ratio) < 1) != conv;
      n_st += stable;
      n_un += !stable;
    }
  tap_check (mism == 0 && n_st > 10 && n_un > 10, mism, 0,
             "(3.11), (3.12) chaplygin_discrete_stable vs |H| over 20 "
             "integrated collisions from perturbed fixed points (%d stable, "
             "%d unstable); mismatches", n_st, n_un);
  tap_check (mism11 == 0, mism11, 0,
             "(B.11) chaplygin_discrete_energy_converges vs the integrated "
             "one-collision ratio |H'/H| < 1; mismatches");

  /* (B.9): n integrated collisions from states with 2E/H^2 well above the
     reversal range (no reversal: checked by the integration itself),
     against the series.  Tolerance 1e-11: the integration's 1e-13 per
     segment over up to 30 segments, amplified at most 10x by the
     collisions. */
  worst = 0;
  int nrun = 0;
  bad = 0;
  for (int k = 0; k < N; k++)
    {
      struct skate s = { tap_uniform (&seed, -3, 3), tap_uniform (&seed, 0.1, 1.5) };
      int dir = k % 2 ? 1 : -1;
      double l = s.L0 + (dir > 0 ? 0.0 : s.Delta), n0 = 1 + l * l;
      double y[4] = { dir * tap_uniform (&seed, 0.5, 2), 0,
                      tap_uniform (&seed, -0.3, 0.3) / n0, 0 };
      double E = energy (&s, dir, y), H = momentum (&s, dir, y);
      int n = 1 + (int) tap_uniform (&seed, 0, 30), c;
      /* integrating in D needs V bounded away from 0 on every segment:
         V^2 is smallest where |l| is, 2E - H^2/(1 + m^2) */
      double m = s.L0 < 0 && s.L0 + s.Delta > 0 ? 0.0
        : fmin (fabs (s.L0), fabs (s.L0 + s.Delta));
      for (c = 0; c < n; c++)
        {
          double Ec = energy (&s, dir, y), Hc = momentum (&s, dir, y);
          if (2 * Ec - Hc * Hc / (1 + m * m) < 0.25 * 2 * Ec
              || segment (&s, dir, y))
            break;
        }
      if (c < n)
        continue;               /* near a reversal: not this route's case */
      chaplygin_discrete sys;
      double En, Hn;
      if (chaplygin_discrete_init (&sys, s.L0, s.Delta)
          || chaplygin_discrete_energy_after (&sys, dir, E, H,
                                              (unsigned long) n, &En, &Hn))
        {
          bad = 1;
          continue;
        }
      double eE = fabs (En - energy (&s, dir, y)) / E;
      double eH = fabs (Hn - momentum (&s, dir, y)) / fmax (fabs (Hn), 1e-300);
      if (eE > worst)
        worst = eE;
      if (eH > worst)
        worst = eH;
      nrun++;
    }
  tap_check (!bad && nrun > N / 4 && worst < 1e-11, worst, 1e-11,
             "(B.9) chaplygin_discrete_energy_after vs E, H after n <= 30 "
             "integrated collisions, %d runs (E relative to the initial E, "
             "H relative)", nrun);
  return tap_done ();
}
