/* test_stability.c -- lib/stability.c and lib/sweep.c: (3.9)-(3.12), (4.1),
   (B.14), the spinning equilibrium, the Fig. 2 sweeps.  References:
   tests/ref_stability.h (mpmath: sigma4 = H'/H of the segment map built
   from angular momentum about the new peg, the f3 partials by numerical
   differentiation of the quadrature heading, xi4 at 400 digits, Taylor
   coefficients by mpmath.taylor), Richardson-extrapolated finite
   differences of the library's own return map (an independently verified
   route: closed form against quadrature and ODE in test_map), GSL's
   nonsymmetric eigensolver, and binary128 arithmetic. */
#include <config.h>

#include <gsl/gsl_eigen.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_matrix.h>
#include <quadmath.h>
#include <stdio.h>
#include <stdlib.h>

#include "internal.h"
#include "testutil.h"
#include "ref_stability.h"


/* ------------------------------------------------------------------ */

/* theta, E or H after one step from (dir, E, H), as a function of one of
   E (which = 1) or H (which = 3) -- for finite differences. */
static double
map_component (const chaplygin_discrete *sys, int dir, double E, double H,
               int out)
{
  chaplygin_discrete_state s = { dir, E, H, 0.0, 0.0, { 0.0, 0.0 }, 0.0 }, t;
  ck_assert_ok (chaplygin_discrete_step (sys, &s, CHAPLYGIN_WANT_THETA, NULL,
                                         &t, NULL));
  return out == 1 ? t.E : out == 2 ? t.theta : t.H;
}

/* d(out)/d(in) by central differences with step h and h/2, combined by
   one Richardson step: error O(h^4) + O(eps/h). */
static double
richardson (const chaplygin_discrete *sys, int dir, double E, double H,
            int in, int out, double h)
{
  double d[2];
  for (int k = 0; k < 2; k++)
    {
      double s = k ? h / 2 : h;
      double fp = in == 1 ? map_component (sys, dir, E + s, H, out)
        : map_component (sys, dir, E, H + s, out);
      double fm = in == 1 ? map_component (sys, dir, E - s, H, out)
        : map_component (sys, dir, E, H - s, out);
      d[k] = (fp - fm) / (2 * s);
    }
  return (4 * d[1] - d[0]) / 3;
}

/* eigenvalues of a 4x4 real matrix, real parts sorted ascending; asserts
   that the imaginary parts vanish */
static void
eigenvalues4 (const double A[16], double lam[4])
{
  double a[16];
  for (int i = 0; i < 16; i++)
    a[i] = A[i];
  gsl_matrix_view m = gsl_matrix_view_array (a, 4, 4);
  gsl_vector_complex *ev = gsl_vector_complex_alloc (4);
  gsl_eigen_nonsymm_workspace *w = gsl_eigen_nonsymm_alloc (4);
  ck_assert_int_eq (gsl_eigen_nonsymm (&m.matrix, ev, w), GSL_SUCCESS);
  for (int i = 0; i < 4; i++)
    {
      gsl_complex z = gsl_vector_complex_get (ev, i);
      ck_assert (fabs (GSL_IMAG (z)) <= 1e-12);
      lam[i] = GSL_REAL (z);
    }
  gsl_eigen_nonsymm_free (w);
  gsl_vector_complex_free (ev);
  for (int i = 1; i < 4; i++)
    for (int j = i; j > 0 && lam[j - 1] > lam[j]; j--)
      {
        double t = lam[j];
        lam[j] = lam[j - 1];
        lam[j - 1] = t;
      }
}

/* ---------------------------------------------------------------- (3.9) */

START_TEST (eq_3_9_reference)
{
  /* df3/dE and df3/dH against mpmath.diff of the quadrature heading
     (~25 digits).  Tolerance 16 eps: the closed-form heading and time are
     within 3 eps each and the identity cancels by at most a factor 8
     (else a 64 eps quadrature is used); measured at most 6.7 eps.  Three
     cases have L0 + Delta inexact in double, short slots far from l = 0. */
  for (size_t i = 0; i < NELEM (ref_jacobian); i++)
    {
      chaplygin_discrete sys;
      ck_assert_ok (chaplygin_discrete_init (&sys, ref_jacobian[i].L0,
                                             ref_jacobian[i].Delta));
      chaplygin_discrete_state s = { ref_jacobian[i].dir, ref_jacobian[i].E,
                                     ref_jacobian[i].H, 0.3, 0.0, { 0, 0 }, 0.0 };
      double J[16];
      ck_assert_ok (chaplygin_discrete_jacobian (&sys, &s, J));
      ck_assert_eps (J[9], ref_jacobian[i].df3dE, 16);
      ck_assert_eps (J[11], ref_jacobian[i].df3dH, 16);
      /* the rest of (3.9) */
      for (int k = 0; k < 4; k++)
        ck_assert (J[k] == 0.0 && J[4 * k] == 0.0);
      ck_assert (J[5] == 1.0 && J[10] == 1.0);
      ck_assert (J[6] == 0.0 && J[8] == 0.0 && J[12] == 0.0 && J[13] == 0.0
                 && J[14] == 0.0);
      int far = s.dir > 0 ? 1 : 0;
      ck_assert (J[7] == 2.0 * sys.C1[far] * s.H);
      ck_assert (J[15] == sys.C2[far]);
    }
}
END_TEST

START_TEST (eq_3_9_richardson)
{
  /* every nonconstant entry against Richardson-extrapolated central
     differences of the return map over random states without reversal:
     relative step 1e-3 gives truncation ~1e-12 and rounding ~1e-13;
     tolerance 1e-9 covers states near a turning point, where the map's
     derivatives grow like g^(-3/2). */
  tu_rng r;
  tu_rng_seed (&r, 39);
  int tested = 0, reverse = 0;
  while (tested < 300)
    {
      double L0 = tu_uniform (&r, -4.0, 3.0), Delta = tu_uniform (&r, 0.05, 3.0);
      int dir = tu_uniform (&r, 0, 1) < 0.5 ? 1 : -1;
      double E = tu_uniform (&r, 0.2, 2.0);
      double H = tu_uniform (&r, -2.0, 2.0);
      chaplygin_discrete sys;
      ck_assert_ok (chaplygin_discrete_init (&sys, L0, Delta));
      chaplygin_discrete_state s = { dir, E, H, 0.0, 0.0, { 0, 0 }, 0.0 }, t;
      chaplygin_discrete_event ev;
      if (chaplygin_discrete_step (&sys, &s, 0, NULL, &t, &ev))
        continue;               /* invalid state (V+^2 <= 0) */
      double J[16];
      if (ev.reversal)
        {
          ck_assert_status (chaplygin_discrete_jacobian (&sys, &s, J),
                            CHAPLYGIN_ESTATE);
          reverse++;
          continue;
        }
      /* keep clear of turning points for the differences */
      double l0 = L0 + (dir > 0 ? 0.0 : Delta), l1 = L0 + (dir > 0 ? Delta : 0.0);
      double lmin = l0 * l1 <= 0 ? 0.0 : fmin (fabs (l0), fabs (l1));
      double gmin = 1 + lmin * lmin - H * H / (2 * E);
      if (gmin < 0.05)
        continue;
      ck_assert_ok (chaplygin_discrete_jacobian (&sys, &s, J));
      /* steps scaled by the smallest g = (1 + l^2) V^2/(2E) on the
         segment, which sets the scale of the higher derivatives */
      double sc = 1e-3 * fmin (1.0, gmin);
      double hE = sc * E, hH = sc * fmax (fabs (H), 0.1);
      /* entry, its difference quotient, and the size of the differenced
         output (rounding of the map's output, 16 eps of it, over the step
         adds to the 1e-9 relative allowance) */
      struct { double got, fd, f, h; } c[] = {
        { J[9], richardson (&sys, dir, E, H, 1, 2, hE), 1.0, hE },
        { J[11], richardson (&sys, dir, E, H, 3, 2, hH), 1.0, hH },
        { J[7], richardson (&sys, dir, E, H, 3, 1, hH), E, hH },
        { J[15], richardson (&sys, dir, E, H, 3, 3, hH), fabs (H), hH },
        { J[5], richardson (&sys, dir, E, H, 1, 1, hE), E, hE } };
      for (size_t k = 0; k < NELEM (c); k++)
        ck_assert_msg (fabs (c[k].got - c[k].fd)
                       <= 1e-9 * fabs (c[k].fd) + 16 * DBL_EPSILON * c[k].f / c[k].h,
                       "entry %zu: %.17g, differences %.17g (L0 %.17g Delta %.17g dir %d E %.17g H %.17g)", k, c[k].got, c[k].fd, L0, Delta, dir, E, H);
      tested++;
    }
  ck_assert_int_gt (reverse, 10);
}
END_TEST

START_TEST (eq_3_9_fixed_point)
{
  /* At H = 0: df3/dE = 0, df3/dH = [atan(L0 + Delta) - atan(L0)]/sqrt(2E)
     (binary128 atan difference), and the f3 derivative by differences of
     the map across H = 0. */
  double cases[][3] = { { 1.0, 1.0 / 3, 1.0 }, { -0.6, 1.0, -0.75 },
                        { -3.3, 1.1, 2.5 }, { 1e4, 2.0, 1.0 },
                        { -1e4 - 2.0, 2.0, -1.0 }, { 0.0, 1e-8, 3.0 } };
  for (size_t i = 0; i < NELEM (cases); i++)
    {
      double L0 = cases[i][0], Delta = cases[i][1], V = cases[i][2];
      chaplygin_discrete sys;
      chaplygin_discrete_state s;
      ck_assert_ok (chaplygin_discrete_init (&sys, L0, Delta));
      ck_assert_ok (chaplygin_discrete_fixed_point (&sys, V, 0.5, 0.0, NULL,
                                                    &s, NULL));
      double J[16];
      ck_assert_ok (chaplygin_discrete_jacobian (&sys, &s, J));
      __float128 a = atanq ((__float128) L0 + Delta) - atanq ((__float128) L0);
      ck_assert (J[9] == 0.0);
      ck_assert_rel (J[11], (double) (a / sqrtq (2 * (__float128) s.E)),
                     4 * DBL_EPSILON);
      double hH = 1e-3 * sqrt (2 * s.E);
      ck_assert_rel (J[11], richardson (&sys, s.dir, s.E, 0.0, 3, 2, hH), 1e-9);
    }
}
END_TEST

START_TEST (eq_3_9_errors)
{
  chaplygin_discrete sys;
  ck_assert_ok (chaplygin_discrete_init (&sys, 1.0, 1.0 / 3));
  chaplygin_discrete_state s = { 1, 0.5, 0.0, 0.0, 0.0, { 0, 0 }, 0.0 };
  double J[16];
  /* subnormal H (found in review): df3/dH is its H = 0 value to O(h^2) */
  {
    chaplygin_discrete sy;
    ck_assert_ok (chaplygin_discrete_init (&sy, 0.3, 1.0));
    __float128 a = atanq ((__float128) 1.3) - atanq ((__float128) 0.3);
    for (double Hs = 1e-322; Hs < 1e-150; Hs *= 1e17)
      {
        chaplygin_discrete_state ts = { 1, 0.5, Hs, 0, 0, { 0, 0 }, 0.0 };
        ck_assert_ok (chaplygin_discrete_jacobian (&sy, &ts, J));
        ck_assert_eps (J[11], (double) a, 4);
      }
  }
  ck_assert_status (chaplygin_discrete_jacobian (NULL, &s, J),
                    CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_discrete_jacobian (&sys, NULL, J),
                    CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_discrete_jacobian (&sys, &s, NULL),
                    CHAPLYGIN_EINVAL);
  s.E = NAN;
  ck_assert_status (chaplygin_discrete_jacobian (&sys, &s, J),
                    CHAPLYGIN_EDOM);
  /* L0 > 0, V < 0 with 2E/H^2 in (3.13): reverses */
  s.dir = -1;
  s.E = 0.5;
  s.H = 1.5;
  ck_assert_status (chaplygin_discrete_jacobian (&sys, &s, J),
                    CHAPLYGIN_ESTATE);
}
END_TEST

/* --------------------------------------------------------------- (3.10) */

START_TEST (eq_3_10)
{
  /* sigma4 against H'/H of the mpmath segment map (4 eps: the numerator
     is formed by an error-free sum) */
  for (size_t i = 0; i < NELEM (ref_sigma4); i++)
    {
      double s4, sig[4];
      ck_assert_ok (chaplygin_discrete_sigma4 (ref_sigma4[i].L0,
                                               ref_sigma4[i].Delta,
                                               ref_sigma4[i].dir, &s4, sig));
      ck_assert_eps (s4, ref_sigma4[i].sigma4, 4);
      ck_assert (sig[0] == 0.0 && sig[1] == 1.0 && sig[2] == 1.0
                 && sig[3] == s4);
      /* and against the eigenvalues of the Jacobian (3.9) at the fixed
         point, computed by GSL */
      chaplygin_discrete sys;
      chaplygin_discrete_state st;
      double J[16], lam[4], want[4] = { 0.0, 1.0, 1.0, s4 };
      ck_assert_ok (chaplygin_discrete_init (&sys, ref_sigma4[i].L0,
                                             ref_sigma4[i].Delta));
      ck_assert_ok (chaplygin_discrete_fixed_point (&sys, 1.7 * ref_sigma4[i].dir,
                                                    0.0, 0.0, NULL, &st,
                                                    NULL));
      ck_assert_ok (chaplygin_discrete_jacobian (&sys, &st, J));
      eigenvalues4 (J, lam);
      for (int a = 1; a < 4; a++)
        for (int b = a; b > 0 && want[b - 1] > want[b]; b--)
          {
            double t = want[b];
            want[b] = want[b - 1];
            want[b - 1] = t;
          }
      for (int k = 0; k < 4; k++)
        ck_assert (fabs (lam[k] - want[k]) <= 4 * DBL_EPSILON * fmax (1.0, fabs (want[k])));
    }
  /* reflection L0 -> -(L0 + Delta), dir -> -dir: the same sigma4 (dyadic
     values, so L0 + Delta is exact) */
  tu_rng r;
  tu_rng_seed (&r, 310);
  for (int i = 0; i < 1000; i++)
    {
      double L0 = ldexp (floor (tu_uniform (&r, -4096, 4096)), -10);
      double Delta = ldexp (floor (tu_uniform (&r, 1, 4096)), -10);
      double a, b;
      ck_assert_ok (chaplygin_discrete_sigma4 (L0, Delta, 1, &a, NULL));
      ck_assert_ok (chaplygin_discrete_sigma4 (-(L0 + Delta), Delta, -1, &b,
                                               NULL));
      ck_assert (a == b);
    }
  double s;
  ck_assert_status (chaplygin_discrete_sigma4 (1, 1, 0, &s, NULL),
                    CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_discrete_sigma4 (1, 1, 1, NULL, NULL),
                    CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_discrete_sigma4 (1, 0, 1, &s, NULL),
                    CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_discrete_sigma4 (NAN, 1, 1, &s, NULL),
                    CHAPLYGIN_EDOM);
  /* The far slot (an end beyond 2^500, both ends of one sign, max |l| <=
     2^400 min |l|): a value, no longer ERANGE.  Reference: (3.10) in
     binary128, whose exponent range holds l^2 ~ 1e600; L0 + Delta is
     exact there for these doubles (exponents within 3 of each other) but
     for (1e200, 1), where the binary128 sum drops the 1 (relative 1e-200,
     below every rounding: sigma4 = 1 - 1e-200 rounds to 1 either way).
     Tolerance 4 eps, as for ref_sigma4 above: the library solves a
     problem scaled by an exact power of two, which differs from this one
     by a relative O(2^-200). */
  {
    const double far[][3] = {
      { 1e200, 1, 1 }, { 1e200, 1, -1 }, { 1e200, 3e199, 1 },
      { 1e200, 3e199, -1 }, { -0x1.8p600, 0x1p599, 1 },
      { -0x1.8p600, 0x1p599, -1 }, { 1e300, 1e300, 1 }, { -3e300, 1e300, -1 }
    };
    for (size_t i = 0; i < NELEM (far); i++)
      {
        double L0 = far[i][0], Delta = far[i][1], sig[4];
        int dir = (int) far[i][2];
        __float128 l = L0, d = Delta, n = 1 + l * (l + d);
        __float128 den = dir > 0 ? 1 + (l + d) * (l + d) : 1 + l * l;
        ck_assert_ok (chaplygin_discrete_sigma4 (L0, Delta, dir, &s, sig));
        ck_assert_eps (s, (double) (n / den), 4);
        ck_assert (sig[0] == 0.0 && sig[1] == 1.0 && sig[2] == 1.0
                   && sig[3] == s);
      }
  }
  /* beyond the cap but not far: ERANGE, outputs untouched -- ends of
     opposite sign (the mass centre inside the slot), one end at 0, and
     ends 1 and 2^501 (max |l| > 2^400 min |l|) */
  {
    const double notfar[][2] = {
      { -1e200, 2e200 }, { -0x1p501, 0x1p501 }, { 1, 0x1p501 }
    };
    for (size_t i = 0; i < NELEM (notfar); i++)
      for (int dir = -1; dir <= 1; dir += 2)
        {
          double sig[4] = { 7, 7, 7, 7 };
          s = 7;
          ck_assert_status (chaplygin_discrete_sigma4 (notfar[i][0], notfar[i][1],
                                                       dir, &s, sig),
                            CHAPLYGIN_ERANGE);
          ck_assert (s == 7 && sig[0] == 7 && sig[3] == 7);
        }
  }
}
END_TEST

/* ------------------------------------------------------- (3.11), (3.12) */

/* |sigma4| < 1 in binary128 from (3.10) */
static int
stable_by_eigenvalue (double L0, double Delta, int dir, __float128 *margin)
{
  __float128 l = L0, d = Delta, n = 1 + l * (l + d);
  __float128 den = dir > 0 ? 1 + (l + d) * (l + d) : 1 + l * l;
  __float128 s = n / den;
  *margin = fabsq (fabsq (s) - 1);
  return fabsq (s) < 1;
}

static void
criteria_against_eigenvalues (int dir)
{
  tu_rng r;
  tu_rng_seed (&r, dir > 0 ? 311 : 312);
  int n_stable = 0, n_unstable = 0;
  for (int i = 0; i < 20000; i++)
    {
      double x = tu_uniform (&r, -4.0, 2.0), y = tu_uniform (&r, 0.0, 1.0);
      double Delta = 1.0 / sqrt (y), L0 = x * Delta;
      __float128 margin;
      int want = stable_by_eigenvalue (L0, Delta, dir, &margin);
      if (margin < 1e-12)
        continue;
      int got, ok;
      double ymin;
      ck_assert_ok (chaplygin_discrete_stable (L0, Delta, dir, &got));
      ck_assert_int_eq (got, want);
      /* the boundary curve gives the same answer (x, y rounded from
         L0, Delta: keep away from it) */
      ck_assert_ok (chaplygin_discrete_stability_boundary (dir, L0 / Delta, &ok,
                                                           &ymin));
      double yy = 1.0 / (Delta * Delta);
      if (!ok || fabs (yy - ymin) > 1e-9)
        ck_assert_int_eq (ok && yy > ymin, want);
      n_stable += want;
      n_unstable += !want;
    }
  ck_assert_int_gt (n_stable, 1000);
  ck_assert_int_gt (n_unstable, 1000);
  /* against iterating the map: from the fixed point with H perturbed to
     1e-6, 40 collisions shrink |H| without a reversal iff stable (points with
     ||sigma4| - 1| > 0.05, so |sigma4|^40 is below 0.13 or above 7);
     the first collision by the ODE route (3.1) + (3.6) gives
     H'/H = sigma4 to its tolerance */
  const chaplygin_options ode = { CHAPLYGIN_ODE, 1e-12, CHAPLYGIN_PREC_DOUBLE };
  int n_checked = 0;
  while (n_checked < 200)
    {
      double x = tu_uniform (&r, -4.0, 2.0), y = tu_uniform (&r, 0.01, 1.0);
      double Delta = 1.0 / sqrt (y), L0 = x * Delta, s4;
      __float128 margin;
      int want = stable_by_eigenvalue (L0, Delta, dir, &margin);
      if (margin < 0.05)
        continue;
      chaplygin_discrete sys;
      chaplygin_discrete_state st;
      ck_assert_ok (chaplygin_discrete_init (&sys, L0, Delta));
      ck_assert_ok (chaplygin_discrete_fixed_point (&sys, dir * 1.3, 0, 0, NULL,
                                                    &st, NULL));
      ck_assert_ok (chaplygin_discrete_sigma4 (L0, Delta, dir, &s4, NULL));
      st.H = 1e-6;
      chaplygin_discrete_state o;
      ck_assert_ok (chaplygin_discrete_step (&sys, &st, 0, &ode, &o, NULL));
      ck_assert_rel (o.H / st.H, s4, 1e-9);
      /* a reversal means the motion has left the fixed point */
      int left = 0;
      for (int k = 0; k < 40 && !left; k++)
        {
          chaplygin_discrete_event ev;
          ck_assert_ok (chaplygin_discrete_step (&sys, &st, 0, NULL, &st, &ev));
          left = ev.reversal;
        }
      ck_assert_int_eq (!left && fabs (st.H) < 1e-6, want);
      n_checked++;
    }
}

START_TEST (eq_3_11)
{
  /* (3.11) as read in errata E12 is |sigma4| < 1, checked on 20000 points
     of Fig. 2(b)'s plane against binary128 sigma4 */
  criteria_against_eigenvalues (1);
  /* the literal chained reading would call L0/Delta = 3 (Figure 6's
     L0 = 1, Delta = 1/3, sigma4 = 0.84) unstable: the library says
     stable, with sigma4 from an independent route (ref_sigma4[0]) */
  int st;
  ck_assert_ok (chaplygin_discrete_stable (1.0, 1.0 / 3, 1, &st));
  ck_assert_int_eq (st, 1);
  ck_assert (fabs (ref_sigma4[0].sigma4) < 1.0);
  ck_assert (!(-0.5 * (1 + 2 * 3.0) * (1 + 3.0) > 0));    /* chain fails */
  /* the boundary: points a hair either side of the curve and the line */
  int ok;
  double ymin;
  ck_assert_ok (chaplygin_discrete_stability_boundary (1, -0.75, &ok, &ymin));
  ck_assert (ok && ymin == 0.0625);          /* the peak of the curve */
  ck_assert_ok (chaplygin_discrete_stability_boundary (1, -1.0, &ok, &ymin));
  ck_assert (!ok);
  ck_assert_ok (chaplygin_discrete_stability_boundary (1, 0.5, &ok, &ymin));
  ck_assert (ok && ymin == 0.0);
  /* exactly on the line L0 = -Delta: sigma4 = 1, not asymptotically stable */
  ck_assert_ok (chaplygin_discrete_stable (-2.0, 2.0, 1, &st));
  ck_assert_int_eq (st, 0);
  /* on the curve 2 + (L0 + Delta)(2 L0 + Delta) = 0: L0 = -3/4 Delta,
     Delta = 4 (y = 1/16): 2 + (1)(-2) = 0 exactly, sigma4 = -1 */
  ck_assert_ok (chaplygin_discrete_stable (-3.0, 4.0, 1, &st));
  ck_assert_int_eq (st, 0);
  ck_assert_ok (chaplygin_discrete_stable (-3.0, nextafter (4.0, 0.0), 1, &st));
  ck_assert_int_eq (st, 1);
  ck_assert_ok (chaplygin_discrete_stable (-3.0, nextafter (4.0, 8.0), 1, &st));
  ck_assert_int_eq (st, 0);
  ck_assert_status (chaplygin_discrete_stable (1, 1, 2, &st), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_discrete_stable (1, 1, 1, NULL), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_discrete_stable (1, -1, 1, &st), CHAPLYGIN_EDOM);
  /* Far slots (the same domain as sigma4): decided, no longer ERANGE.
     Reference: the factorisation of (3.10) (exact, no rounding to
     decide), with l_f = L0 + Delta:
       dir +1:  1 - sigma4 = Delta l_f/(1 + l_f^2),
                1 + sigma4 = (2 + l_f (2 L0 + Delta))/(1 + l_f^2);
       dir -1:  1 - sigma4 = -L0 Delta/(1 + L0^2),
                1 + sigma4 = (2 + L0 (2 L0 + Delta))/(1 + L0^2);
     on a far slot l_f (2 L0 + Delta) > 0 and L0 (2 L0 + Delta) > 0 (both
     ends of one sign), so stable iff 1 - sigma4 > 0: dir +1 iff the ends
     are positive, dir -1 iff they are negative.  (The binary128 sigma4 of
     stable_by_eigenvalue would round (1e300, 1) to sigma4 = 1.) */
  {
    const double far[][2] = {
      { 1e300, 1 }, { -1e300, 1 }, { 0x1p500, 0x1p500 }, { 0x1p501, 1 },
      { -0x1p502, 0x1p501 }, { 1e200, 3e199 }, { -0x1p1000, 0x1p700 }
    };
    for (size_t i = 0; i < sizeof far / sizeof far[0]; i++)
      for (int dir = -1; dir <= 1; dir += 2)
        {
          st = 7;
          ck_assert_ok (chaplygin_discrete_stable (far[i][0], far[i][1], dir, &st));
          ck_assert_int_eq (st, dir > 0 ? far[i][0] > 0 : far[i][0] < 0);
        }
  }
  /* beyond the cap and not far (opposite signs, an end at 0, max |l| >
     2^400 min |l|): still ERANGE, *stable untouched */
  st = 7;
  ck_assert_status (chaplygin_discrete_stable (-1e200, 2e200, 1, &st),
                    CHAPLYGIN_ERANGE);
  ck_assert_status (chaplygin_discrete_stable (-0x1p501, 0x1p501, -1, &st),
                    CHAPLYGIN_ERANGE);
  ck_assert_status (chaplygin_discrete_stable (1, 0x1p501, 1, &st),
                    CHAPLYGIN_ERANGE);
  ck_assert_int_eq (st, 7);
  ck_assert_status (chaplygin_discrete_stability_boundary (1, NAN, &ok, &ymin),
                    CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_discrete_stability_boundary (0, 1, &ok, &ymin),
                    CHAPLYGIN_EINVAL);
}
END_TEST

START_TEST (eq_3_12)
{
  criteria_against_eigenvalues (-1);
  int st, ok;
  double ymin;
  /* reflection: (3.12) at L0 is (3.11) at -(L0 + Delta) (dyadic grid) */
  for (int i = -64; i <= 64; i++)
    for (int j = 1; j <= 64; j++)
      {
        double L0 = i / 16.0, Delta = j / 32.0;
        int a, b;
        ck_assert_ok (chaplygin_discrete_stable (L0, Delta, -1, &a));
        ck_assert_ok (chaplygin_discrete_stable (-(L0 + Delta), Delta, 1, &b));
        ck_assert_int_eq (a, b);
      }
  ck_assert_ok (chaplygin_discrete_stability_boundary (-1, -0.25, &ok, &ymin));
  ck_assert (ok && ymin == 0.0625);
  ck_assert_ok (chaplygin_discrete_stability_boundary (-1, 0.0, &ok, &ymin));
  ck_assert (!ok);
  ck_assert_ok (chaplygin_discrete_stability_boundary (-1, -2.0, &ok, &ymin));
  ck_assert (ok && ymin == 0.0);
  /* Figure 7's overlap: L0 = -1/2, Delta = 1: both directions stable */
  ck_assert_ok (chaplygin_discrete_stable (-0.5, 1.0, -1, &st));
  ck_assert_int_eq (st, 1);
  ck_assert_ok (chaplygin_discrete_stable (-0.5, 1.0, 1, &st));
  ck_assert_int_eq (st, 1);
  /* L0 = 0: sigma4 = 1 for V* < 0 (neutral) */
  ck_assert_ok (chaplygin_discrete_stable (0.0, 2.5, -1, &st));
  ck_assert_int_eq (st, 0);
}
END_TEST

/* ---------------------------------------------------------------- (4.1) */

START_TEST (eq_4_1)
{
  /* xi4 against 400-digit values: 4 eps, Delta down to 1e-300 */
  for (size_t i = 0; i < NELEM (ref_xi4); i++)
    {
      double xi;
      ck_assert_ok (chaplygin_discrete_xi4 (ref_xi4[i].L0, ref_xi4[i].Delta,
                                            ref_xi4[i].V, &xi));
      ck_assert_eps (xi, ref_xi4[i].xi4, 4);
    }
  /* Taylor coefficients against mpmath.taylor (8 eps: the references
     come from numerical differentiation at high precision, the library's
     from three roundings) */
  for (size_t i = 0; i < NELEM (ref_taylor); i++)
    {
      double c[3];
      ck_assert_ok (chaplygin_discrete_xi4_taylor (ref_taylor[i].L0,
                                                   ref_taylor[i].dir, c));
      ck_assert_eps (c[0], ref_taylor[i].c0, 8);
      ck_assert_eps (c[1], ref_taylor[i].c1, 8);
      ck_assert_eps (c[2], ref_taylor[i].c2, 8);
    }
  /* errata E13: the paper's c2 = -L0 (L0^2 - 2)/(3 (1 + L0^2)^3) differs
     from the mpmath coefficient (L0 = 1: 1/24 against 5/24) */
  double paper_c2 = -1.0 * (1.0 - 2.0) / (3.0 * 8.0);
  ck_assert (fabs (paper_c2 - ref_taylor[0].c2) > 0.1);
  /* the remainder after three terms is O(Delta^3): halving Delta divides
     it by 8 (to 2%), so every coefficient is right; with the paper's c2
     it would shrink only by 4 */
  for (int dir = -1; dir <= 1; dir += 2)
    for (double L0 = -2.5; L0 <= 2.5; L0 += 0.625)
      {
        double c[3], R[2];
        ck_assert_ok (chaplygin_discrete_xi4_taylor (L0, dir, c));
        for (int k = 0; k < 2; k++)
          {
            double D = k ? 1e-3 : 2e-3, xi;
            ck_assert_ok (chaplygin_discrete_xi4 (L0, D, dir * 1.0, &xi));
            R[k] = dir * xi - (c[0] + D * (c[1] + D * c[2]));
          }
        if (fabs (R[0]) > 1e-12)
          ck_assert_rel (R[0] / R[1], 8.0, 0.02);
      }
  /* the Delta -> 0 limit is the smooth sleigh's eigenvalue (2.4): at
     Delta = 1e-300 the difference is c1 Delta, below 1e-300 */
  tu_rng r;
  tu_rng_seed (&r, 41);
  for (int i = 0; i < 200; i++)
    {
      double L0 = tu_uniform (&r, -50, 50), V = tu_uniform (&r, -3, 3);
      double xi, xs;
      ck_assert_ok (chaplygin_discrete_xi4 (L0, 1e-300, V, &xi));
      ck_assert_ok (chaplygin_smooth_eigenvalue (L0, V, &xs));
      ck_assert_eps (xi, xs, 2);
    }
  double xi, c[3];
  /* sigma4 <= 0: no real logarithm */
  ck_assert_status (chaplygin_discrete_xi4 (-0.5, 3.0, 1.0, &xi),
                    CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_discrete_xi4 (1.0, 1.0, 0.0, &xi),
                    CHAPLYGIN_ESTATE);
  ck_assert_status (chaplygin_discrete_xi4 (1.0, 0.0, 1.0, &xi),
                    CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_discrete_xi4 (1.0, 1.0, 1.0, NULL),
                    CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_discrete_xi4 (1.0, 1e-300, 1e300, &xi),
                    CHAPLYGIN_SUCCESS);
  ck_assert_status (chaplygin_discrete_xi4_taylor (1.0, 0, c),
                    CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_discrete_xi4_taylor (INFINITY, 1, c),
                    CHAPLYGIN_EDOM);
  /* No cap on the Taylor coefficients: any finite L0 (they underflow
     gradually far out).  Reference: the closed forms, from the series of
     log sigma4 in Delta (a = 1 + L0^2):
       dir +1:  c0 = -L0/a, c1 = (L0^2 - 2)/(2 a^2), c2 = L0 (6 - L0^2)/(3 a^3),
       dir -1:  c0 = -L0/a, c1 = L0^2/(2 a^2),       c2 = -L0^3/(3 a^3),
     checked here against the mpmath table first (where 1 + L0^2 matters),
     then evaluated in binary128 (exponent range to 1e+-4932: nothing
     overflows or underflows before the final conversion, which rounds
     correctly also into the subnormals).  Tolerance: 8 eps as above for a
     normal reference; for a subnormal one the format's own spacing
     2^-1074 takes over -- at most 2 of them (each of the library's last
     roundings into the subnormal range is worth half of one). */
  {
    for (size_t i = 0; i < NELEM (ref_taylor); i++)
      {
        __float128 L = ref_taylor[i].L0, a = 1 + L * L, cq[3];
        int dir = ref_taylor[i].dir;
        cq[0] = -L / a;
        cq[1] = dir > 0 ? (L * L - 2) / (2 * a * a) : L * L / (2 * a * a);
        cq[2] = dir > 0 ? L * (6 - L * L) / (3 * a * a * a) : -L * L * L / (3 * a * a * a);
        ck_assert_eps ((double) cq[0], ref_taylor[i].c0, 2);
        ck_assert_eps ((double) cq[1], ref_taylor[i].c1, 2);
        ck_assert_eps ((double) cq[2], ref_taylor[i].c2, 2);
      }
    /* 1e200 (the old cap's test point: c1 ~ 5e-401 and c2 underflow to
       0), 2^501 (c1 = 2^-1003 normal), c1 subnormal (2^515, 1.5 2^512),
       c0 subnormal (1e308), c2 subnormal (1.1875 2^341, inside the old
       cap), c1 rounding to 0 at the tie 2^-1075 (2^537) */
    const double Ls[] = { 1e200, 0x1p501, -0x1.8p505, 0x1p515, 0x1.8p512,
                          -0x1.8p512, 1e300, 1e308, -DBL_MAX, 0x1.3p341,
                          0x1p537, -0x1p538 };
    double worst = 0;
    for (size_t i = 0; i < NELEM (Ls); i++)
      for (int dir = -1; dir <= 1; dir += 2)
        {
          __float128 L = Ls[i], a = 1 + L * L, cq[3];
          cq[0] = -L / a;
          cq[1] = dir > 0 ? (L * L - 2) / (2 * a * a) : L * L / (2 * a * a);
          cq[2] = dir > 0 ? L * (6 - L * L) / (3 * a * a * a) : -L * L * L / (3 * a * a * a);
          ck_assert_ok (chaplygin_discrete_xi4_taylor (Ls[i], dir, c));
          for (int j = 0; j < 3; j++)
            {
              double want = (double) cq[j];
              double err = fabs (c[j] - want);
              double tol = fabs (want) >= DBL_MIN ? 8 * DBL_EPSILON * fabs (want)
                : 2 * 0x1p-1074;
              ck_assert_msg (err <= tol, "xi4_taylor (%a, %d): c%d = %a, binary128 %a",
                             Ls[i], dir, j, c[j], want);
              worst = fmax (worst, fabs (want) >= DBL_MIN ? err / (DBL_EPSILON * fabs (want))
                            : err / 0x1p-1074);
            }
        }
    printf ("# eq_4_1: far Taylor coefficients, worst error %.2g (eps or subnormal units)\n",
            worst);
  }
  ck_assert_status (chaplygin_discrete_xi4_taylor (-INFINITY, -1, c),
                    CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_discrete_xi4_taylor (NAN, 1, c),
                    CHAPLYGIN_EDOM);
  /* found in review: sigma4 near 0 (u = sigma4 - 1 cancels) and u in
     the subnormal range; references: binary128 log of the exact sigma4
     (quadmath), and -L0/(1 + L0^2) (to O(Delta)) */
  {
    double L0 = -0.5, D = 2.5 - 1e-12;
    __float128 l = L0, d = D, s4 = (1 + l * (l + d)) / (1 + (l + d) * (l + d));
    ck_assert_ok (chaplygin_discrete_xi4 (L0, D, 1.0, &xi));
    ck_assert_eps (xi, (double) (logq (s4) / d), 8);
    D = 2.4999999999999996;
    d = D;
    s4 = (1 + l * (l + d)) / (1 + (l + d) * (l + d));
    ck_assert (s4 > 0);
    ck_assert_ok (chaplygin_discrete_xi4 (L0, D, 1.0, &xi));
    ck_assert_eps (xi, (double) (logq (s4) / d), 8);
    ck_assert_ok (chaplygin_discrete_xi4 (1e-5, 1e-315, 1.0, &xi));
    ck_assert_eps (xi, -1e-5 / (1 + 1e-10), 2);
  }
  /* huge L0: no overflow in b/(1 + b^2) */
  ck_assert_ok (chaplygin_discrete_xi4 (1e200, 1.0, 1.0, &xi));
  ck_assert_rel (xi, -1e-200, 1e-15);
  /* found by the oracle (issue 6): beyond |L0 + Delta| = 2^500 with
     sigma4 < 1/2, a value (not sigma4's ERANGE), and EDOM where
     sigma4 < 0.  Reference: Arb (verification/oracle), confirmed with
     60-digit decimal arithmetic of sigma4 = (1 + L0 (L0 + Delta))/
     (1 + (L0 + Delta)^2) = 0.10044926848695838...:
     xi4 = -5.788672565194712e-164 (condition number ~1.2) */
  ck_assert_ok (chaplygin_discrete_xi4 (0x1.6b9b9d89981d3p+541,
                                        0x1.9706a940399aep+544,
                                        0x1.2733bb8b68b19p+1, &xi));
  ck_assert_eps (xi, -0x1.aaaf29ebbad23p-543, 8);
  /* sigma4 = (1 + L0 (L0 + Delta))/(1 + L0^2) < 0 for V* < 0 here
     (L0 < 0 < L0 + Delta, |L0 (L0 + Delta)| >> 1) */
  ck_assert_status (chaplygin_discrete_xi4 (-0x1.b7fdc586cb26dp+559,
                                            0x1.ec2b2e75a8b0ap+565,
                                            -0x1.6cfca3b9e635fp+1, &xi),
                    CHAPLYGIN_EDOM);
}
END_TEST

/* --------------------------------------------------------------- (B.14) */

START_TEST (eq_B_14)
{
  /* the fixed point maps to itself: E to 2 eps (E' is recomputed as
     V-^2/2 + 0), H = 0 exactly, theta unchanged, time +Delta/|V*|, the peg
     advanced by Delta along the heading (forwards) or backwards */
  double cases[][3] = { { 1.0, 1.0 / 3, 1.25 }, { -0.5, 1.0, -0.8 },
                        { -3.3, 1.1, 0.3 }, { 2.385, 0.7182, -2.0 } };
  for (size_t i = 0; i < NELEM (cases); i++)
    {
      chaplygin_discrete sys;
      chaplygin_discrete_state s, t;
      double ts, peg[2] = { 0.25, -1.5 };
      ck_assert_ok (chaplygin_discrete_init (&sys, cases[i][0], cases[i][1]));
      ck_assert_ok (chaplygin_discrete_fixed_point (&sys, cases[i][2], 0.7,
                                                    2.0, peg, &s, &ts));
      ck_assert_eps (ts, cases[i][1] / fabs (cases[i][2]), 1);
      ck_assert_ok (chaplygin_discrete_step (&sys, &s, CHAPLYGIN_WANT_ALL, NULL,
                                             &t, NULL));
      ck_assert_int_eq (t.dir, s.dir);
      ck_assert_eps (t.E, s.E, 2);
      ck_assert (t.H == 0.0 && t.theta == s.theta);
      ck_assert_eps (t.tau - s.tau, ts, 4);
      double step = s.dir * cases[i][1];
      ck_assert_eps (t.peg[0], peg[0] + step * cos (0.7), 4);
      ck_assert_eps (t.peg[1], peg[1] + step * sin (0.7), 4);
      double loss;
      ck_assert_ok (chaplygin_discrete_collision_loss (&sys, s.dir, 0, 0.0,
                                                       &loss));
      ck_assert (loss == 0.0);
    }
  /* any H != 0 loses energy at the collision: the loss equals E - E' of
     the map, within the cancellation of that difference */
  tu_rng r;
  tu_rng_seed (&r, 14);
  for (int i = 0; i < 500; i++)
    {
      chaplygin_discrete sys;
      ck_assert_ok (chaplygin_discrete_init (&sys, tu_uniform (&r, -3, 3),
                                             tu_uniform (&r, 0.1, 3)));
      chaplygin_discrete_state s = { tu_uniform (&r, 0, 1) < 0.5 ? 1 : -1,
                                     tu_uniform (&r, 0.5, 2),
                                     tu_uniform (&r, -1, 1), 0, 0, { 0, 0 }, 0.0 }, t;
      chaplygin_discrete_event ev;
      if (chaplygin_discrete_step (&sys, &s, 0, NULL, &t, &ev))
        continue;
      double loss;
      ck_assert_ok (chaplygin_discrete_collision_loss (&sys, s.dir, ev.reversal,
                                                       s.H, &loss));
      ck_assert (loss > 0.0);
      ck_assert_rel (loss, s.E - t.E, 8 * DBL_EPSILON * s.E / loss);
    }
  chaplygin_discrete sys;
  chaplygin_discrete_state s;
  double loss;
  ck_assert_ok (chaplygin_discrete_init (&sys, 1, 1));
  ck_assert_status (chaplygin_discrete_fixed_point (&sys, 0.0, 0, 0, NULL, &s,
                                                    NULL), CHAPLYGIN_ESTATE);
  ck_assert_status (chaplygin_discrete_fixed_point (&sys, NAN, 0, 0, NULL, &s,
                                                    NULL), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_discrete_fixed_point (&sys, 1e300, 0, 0, NULL,
                                                    &s, NULL), CHAPLYGIN_ERANGE);
  /* E = V*^2/2 below the normal range: a state the map rejects */
  ck_assert_status (chaplygin_discrete_fixed_point (&sys, 1e-170, 0, 0, NULL,
                                                    &s, NULL), CHAPLYGIN_ERANGE);
  ck_assert_ok (chaplygin_discrete_fixed_point (&sys, 1e-150, 0, 0, NULL, &s,
                                                NULL));
  ck_assert_status (chaplygin_discrete_fixed_point (NULL, 1, 0, 0, NULL, &s,
                                                    NULL), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_discrete_collision_loss (&sys, 1, 2, 1, &loss),
                    CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_discrete_collision_loss (&sys, 1, 0, NAN, &loss),
                    CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_discrete_collision_loss (&sys, 1, 0, 1e300,
                                                       &loss), CHAPLYGIN_ERANGE);
}
END_TEST

/* ---------------------------------------------------- spinning solution */

START_TEST (spin_equilibrium)
{
  double L0 = -0.375, Delta = 1.25, Om = -0.8125, q[4], dq[4], A[16], lam[4];
  ck_assert_ok (chaplygin_discrete_spin_equilibrium (L0, Delta, Om, 0.5, 2.0, q));
  ck_assert (q[0] == 0.375 && q[1] == 0.0 && q[3] == Om);
  ck_assert_eps (q[2], 0.5 + 2.0 * Om, 1);
  /* it solves (3.1): dD = dV = dOmega = 0, dtheta = Omega */
  ck_assert_ok (chaplygin_discrete_field (L0, q, dq));
  ck_assert (dq[0] == 0.0 && dq[1] == 0.0 && dq[2] == Om && dq[3] == 0.0);
  /* and has 2E/H^2 = 1 (3.8) */
  double E, H, ratio;
  ck_assert_ok (chaplygin_discrete_energy (L0, q[0], q[1], q[3], &E));
  ck_assert_ok (chaplygin_discrete_momentum (L0, q[0], q[3], &H));
  ck_assert_ok (chaplygin_discrete_spin_ratio (E, H, &ratio));
  ck_assert (ratio == 1.0);
  /* eigenvalues of the linearisation (GSL) against the stated ones */
  ck_assert_ok (chaplygin_discrete_field_jacobian (L0, q, A));
  eigenvalues4 (A, lam);
  double want[4];
  ck_assert_ok (chaplygin_discrete_spin_eigenvalues (L0, Delta, Om, want));
  ck_assert (want[0] == -0.8125 && want[1] == 0 && want[2] == 0
             && want[3] == 0.8125);
  for (int k = 0; k < 4; k++)
    ck_assert (fabs (lam[k] - want[k]) <= 4 * DBL_EPSILON);
  /* the field Jacobian against Richardson differences of (3.1) */
  tu_rng r;
  tu_rng_seed (&r, 81);
  for (int i = 0; i < 200; i++)
    {
      double L = tu_uniform (&r, -3, 3);
      double x[4] = { tu_uniform (&r, 0, 2), tu_uniform (&r, -2, 2),
                      tu_uniform (&r, -3, 3), tu_uniform (&r, -2, 2) };
      ck_assert_ok (chaplygin_discrete_field_jacobian (L, x, A));
      for (int j = 0; j < 4; j++)
        {
          const double h = 1e-3;
          for (int m = 0; m < 4; m++)
            {
              double dd[2];
              for (int k = 0; k < 2; k++)
                {
                  double s = k ? h / 2 : h, xp[4], xm[4], fp[4], fm[4];
                  for (int n = 0; n < 4; n++)
                    xp[n] = xm[n] = x[n];
                  xp[j] += s;
                  xm[j] -= s;
                  ck_assert_ok (chaplygin_discrete_field (L, xp, fp));
                  ck_assert_ok (chaplygin_discrete_field (L, xm, fm));
                  dd[k] = (fp[m] - fm[m]) / (2 * s);
                }
              double fd = (4 * dd[1] - dd[0]) / 3;
              ck_assert_msg (fabs (A[4 * m + j] - fd) <= 1e-9 * fmax (1.0, fabs (fd)),
                             "A[%d][%d] = %.17g, differences %.17g", m, j,
                             A[4 * m + j], fd);
            }
        }
    }
  ck_assert_status (chaplygin_discrete_spin_equilibrium (0.5, 1, 1, 0, 0, q),
                    CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_discrete_spin_equilibrium (-1.0, 1, 1, 0, 0, q),
                    CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_discrete_spin_equilibrium (-0.5, 1, 0, 0, 0, q),
                    CHAPLYGIN_ESTATE);
  ck_assert_status (chaplygin_discrete_spin_equilibrium (-0.5, 1, 1, 0, 0, NULL),
                    CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_discrete_spin_equilibrium (-0.5, 1, 1e300, 0,
                                                         1e300, q),
                    CHAPLYGIN_ERANGE);
  ck_assert_status (chaplygin_discrete_spin_eigenvalues (-0.5, 1, 1, NULL),
                    CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_discrete_spin_eigenvalues (0.5, 1, 1, lam),
                    CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_discrete_field_jacobian (0, q, NULL),
                    CHAPLYGIN_EINVAL);
  q[1] = NAN;
  ck_assert_status (chaplygin_discrete_field_jacobian (0, q, A),
                    CHAPLYGIN_EDOM);
  q[1] = 1e300;
  q[3] = 1e300;
  ck_assert_status (chaplygin_discrete_field_jacobian (0, q, A),
                    CHAPLYGIN_ERANGE);
}
END_TEST

/* ----------------------------------------------------------- Fig. 2 sweeps */

START_TEST (fig_2)
{
  /* Fig. 2(a): the sweep against chaplygin_discrete_sigma4 at
     Delta = 1/sqrt(y), L0 = x Delta (the conversion rounds: 16 eps away
     from zeros of sigma4) */
  enum { N = 121 };
  double x[N], s[N];
  int st[N];
  for (int i = 0; i < N; i++)
    x[i] = -4.0 + 6.0 * i / (N - 1);
  double ys[] = { 0.04, 0.25, 0.5625, 1.0 };
  for (size_t k = 0; k < NELEM (ys); k++)
    for (int dir = -1; dir <= 1; dir += 2)
      {
        ck_assert_ok (chaplygin_sweep_sigma4 (dir, ys[k], N, x, s, st));
        for (int i = 0; i < N; i++)
          {
            double Delta = 1.0 / sqrt (ys[k]), want;
            ck_assert_ok (chaplygin_discrete_sigma4 (x[i] * Delta, Delta, dir,
                                                     &want, NULL));
            ck_assert_int_eq (st[i], CHAPLYGIN_SUCCESS);
            if (fabs (want) > 1e-3)
              ck_assert_eps (s[i], want, 16);
          }
      }
  /* y = 0 (rho = 0): sigma4 = x/(x + 1); infinite at x = -1, where the
     point fails and is left alone */
  double xx[3] = { -0.5, -1.0, 2.0 }, ss[3] = { 7, 7, 7 };
  int sst[3];
  ck_assert_status (chaplygin_sweep_sigma4 (1, 0.0, 3, xx, ss, sst),
                    CHAPLYGIN_ERANGE);
  ck_assert (ss[0] == -1.0 && ss[1] == 7 && ss[2] == 2.0 / 3.0);
  ck_assert (sst[0] == 0 && sst[1] == CHAPLYGIN_ERANGE && sst[2] == 0);
  ck_assert_status (chaplygin_sweep_sigma4 (1, 0.0, 3, xx, ss, NULL),
                    CHAPLYGIN_ERANGE);
  xx[1] = NAN;
  ck_assert_status (chaplygin_sweep_sigma4 (-1, 0.0, 3, xx, ss, sst),
                    CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_sweep_sigma4 (1, -1.0, 3, xx, ss, sst),
                    CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_sweep_sigma4 (0, 1.0, 3, xx, ss, sst),
                    CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_sweep_sigma4 (1, 1.0, 3, NULL, ss, sst),
                    CHAPLYGIN_EINVAL);
  ck_assert_ok (chaplygin_sweep_sigma4 (1, 1.0, 0, NULL, NULL, NULL));
  /* near the top of the range (found in review): sigma4 -> 1 as |x| grows
     at fixed y, and (y + x(x+1))/(y + x^2) at x = 1e154, y = 1.7e308, both
     in binary128 */
  {
    double bx[2] = { 1e160, -3e200 }, bs[2];
    ck_assert_ok (chaplygin_sweep_sigma4 (1, 1.0, 2, bx, bs, NULL));
    __float128 X = 1e160, Y = 1;
    ck_assert_eps (bs[0], (double) ((Y + X * (X + 1)) / (Y + (X + 1) * (X + 1))), 4);
    ck_assert_eps (bs[1], 1.0, 4);
    double cx = 1e154, cs;
    ck_assert_ok (chaplygin_sweep_sigma4 (-1, 1.7e308, 1, &cx, &cs, NULL));
    X = 1e154;
    Y = 1.7e308;
    ck_assert_eps (cs, (double) ((Y + X * (X + 1)) / (Y + X * X)), 4);
  }

  /* Fig. 2(b): on a dyadic grid (Delta = 2^-k, so y and L0 = x Delta are
     exact) the regions agree with chaplygin_discrete_stable exactly */
  enum { NX = 97, NY = 7 };
  double gx[NX], gy[NY];
  unsigned char reg[NX * NY];
  for (int j = 0; j < NX; j++)
    gx[j] = -4.0 + j / 16.0;
  for (int i = 0; i < NY; i++)
    gy[i] = ldexp (1.0, 2 * (i - 4));          /* Delta = 2^(4 - i) */
  ck_assert_ok (chaplygin_sweep_stability (NX, gx, NY, gy, reg));
  int overlap = 0;
  for (int i = 0; i < NY; i++)
    for (int j = 0; j < NX; j++)
      {
        double Delta = ldexp (1.0, 4 - i);
        int a, b;
        ck_assert_ok (chaplygin_discrete_stable (gx[j] * Delta, Delta, 1, &a));
        ck_assert_ok (chaplygin_discrete_stable (gx[j] * Delta, Delta, -1, &b));
        ck_assert_int_eq (reg[i * NX + j], a + 2 * b);
        overlap += reg[i * NX + j] == 3;
      }
  ck_assert_int_gt (overlap, 0);
  /* y = 0: V* > 0 stable iff x > -1/2 (Section 3.1.2, rho = 0) */
  double y0 = 0.0;
  unsigned char r0[NX];
  ck_assert_ok (chaplygin_sweep_stability (NX, gx, 1, &y0, r0));
  for (int j = 0; j < NX; j++)
    ck_assert_int_eq (r0[j] & 1, gx[j] > -0.5);
  ck_assert_status (chaplygin_sweep_stability (NX, gx, 1, NULL, r0),
                    CHAPLYGIN_EINVAL);
  y0 = -1.0;
  ck_assert_status (chaplygin_sweep_stability (NX, gx, 1, &y0, r0),
                    CHAPLYGIN_EDOM);
  gx[3] = INFINITY;
  ck_assert_status (chaplygin_sweep_stability (NX, gx, NY, gy, reg),
                    CHAPLYGIN_EDOM);
  ck_assert_ok (chaplygin_sweep_stability (0, NULL, 0, NULL, NULL));
}
END_TEST


/* chaplygin_grid_point, the grid of every sweep (issue 26: the program's
   overflow-safe grid, now the library's).  Route: the exact point
   lo + (hi - lo) i/(n - 1) in binary128 (exact for these doubles: hi - lo
   and the product hold in its 113 bits); the double is within 2 ulps of
   max(|lo|, |hi|) of it (one rounding of hi - lo, of t and of the product
   and sum), the ends exactly, and the points nondecreasing.  Where
   hi - lo overflows, lo (1 - t) + hi t: the same bound. */
START_TEST (grid_point)
{
  static const double ends[][2] = { { -4.0, 2.0 }, { 0.1, 0.7 },
                                    { -2.385e300, 1.5e300 },
                                    { -DBL_MAX, DBL_MAX },
                                    { 3.0, 3.0 }, { -1e-300, 1e-300 } };
  static const size_t ns[] = { 1, 2, 3, 7, 601, 1001 };
  for (size_t e = 0; e < NELEM (ends); e++)
    for (size_t k = 0; k < NELEM (ns); k++)
      {
        const double lo = ends[e][0], hi = ends[e][1];
        const size_t n = ns[k];
        const double scale = fmax (fabs (lo), fabs (hi));
        double prev = -INFINITY;
        for (size_t i = 0; i < n; i++)
          {
            double v;
            ck_assert_ok (chaplygin_grid_point (lo, hi, n, i, &v));
            if (i == 0)
              ck_assert (v == lo);
            else if (i == n - 1)
              ck_assert (v == hi);
            else
              {
                __float128 want = (__float128) lo
                  + ((__float128) hi - (__float128) lo)
                  * (__float128) i / (__float128) (n - 1);
                ck_assert_msg (fabs ((double) ((__float128) v - want))
                               <= 2 * DBL_EPSILON * scale,
                               "[%g, %g] n = %zu i = %zu: %.17g", lo, hi, n,
                               i, v);
              }
            ck_assert (v >= prev);
            prev = v;
          }
      }
  double v = 7.0;
  ck_assert_status (chaplygin_grid_point (0, 1, 3, 0, NULL), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_grid_point (0, 1, 0, 0, &v), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_grid_point (0, 1, 3, 3, &v), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_grid_point (NAN, 1, 3, 1, &v), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_grid_point (0, INFINITY, 3, 1, &v), CHAPLYGIN_EDOM);
  ck_assert (v == 7.0);
}
END_TEST

int
main (void)
{
  gsl_set_error_handler_off ();
  Suite *s = suite_create ("stability");
  TCase *tc = tcase_create ("eq_3_9");
  tcase_add_test (tc, eq_3_9_reference);
  tcase_add_test (tc, eq_3_9_richardson);
  tcase_add_test (tc, eq_3_9_fixed_point);
  tcase_add_test (tc, eq_3_9_errors);
  tcase_set_timeout (tc, 120);
  suite_add_tcase (s, tc);
  tu_add (s, "eq_3_10", eq_3_10);
  tu_add (s, "eq_3_11", eq_3_11);
  tu_add (s, "eq_3_12", eq_3_12);
  tu_add (s, "eq_4_1", eq_4_1);
  tu_add (s, "eq_B_14", eq_B_14);
  tu_add (s, "spin_equilibrium", spin_equilibrium);
  tu_add (s, "fig_2", fig_2);
  tu_add (s, "grid_point", grid_point);
  return tu_run (s);
}
