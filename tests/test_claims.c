/* test_claims.c -- the paper's claims beyond its numbered equations
   (doc/claims.txt, the manual's chapter "The paper's claims"): the checks
   of the claims about stability, basins of attraction and the massless
   skate, and the program's main, which runs every claim's check (these and
   tests/claims-motion.c's) and fails unless the checks registered are
   exactly those the registry names (tests/claims-list.h, generated from
   it).

   Each check asserts the claim itself (or, for a claim the project
   contradicts, the counterexample) through the library's public
   functions, against a reference from another route: the algebra of the
   claim (a sign, a limit, an exact identity of the motion), plain
   iteration of the map where the library has a closed form, finite
   differences where it has an analytic Jacobian, a Runge-Kutta
   integration of the equations of motion, or the mirror image of a
   motion.  Tolerances are stated where they are used. */
#include <config.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_eigen.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_matrix.h>
#include <gsl/gsl_sort.h>

#include "chaplygin.h"
#include "testutil.h"
#include "claims.h"
#include "claims-list.h"

#define FWD CHAPLYGIN_FATE_FORWARD
#define BWD CHAPLYGIN_FATE_BACKWARD

/* ---- helpers ---------------------------------------------------------- */

static chaplygin_discrete
skate (double L0, double Delta)
{
  chaplygin_discrete sys;
  ck_assert_ok (chaplygin_discrete_init (&sys, L0, Delta));
  return sys;
}

static double
sigma4 (double L0, double Delta, int dir)
{
  double s;
  ck_assert_ok (chaplygin_discrete_sigma4 (L0, Delta, dir, &s, NULL));
  return s;
}

static int
stable (double L0, double Delta, int dir)
{
  int st;
  ck_assert_ok (chaplygin_discrete_stable (L0, Delta, dir, &st));
  return st;
}

/* The post-collision state with V+ = V, Omega+ = Omega, heading 0, peg at
   the origin. */
static chaplygin_discrete_state
state (const chaplygin_discrete *sys, double V, double Omega)
{
  double q[4] = { V > 0 ? 0 : sys->Delta, V, 0, Omega };
  chaplygin_discrete_state st;
  ck_assert_ok (chaplygin_discrete_state_from_phase (sys, q, 0, NULL, &st));
  return st;
}

static chaplygin_fate
fate (const chaplygin_discrete *sys, double V, double Omega,
      unsigned long max_collisions)
{
  double q[4] = { V > 0 ? 0 : sys->Delta, V, 0, Omega };
  chaplygin_fate f;
  ck_assert_ok (chaplygin_discrete_fate_phase (sys, q, max_collisions, NULL,
                                               0, &f));
  return f;
}

/* Plain iteration of the return map: N collisions from *ST (updated), the
   number of reversing segments returned. */
static unsigned long
reversals_in (const chaplygin_discrete *sys, chaplygin_discrete_state *st,
              unsigned long n)
{
  unsigned long count = 0;
  for (unsigned long i = 0; i < n && st->H != 0; i++)
    {
      chaplygin_discrete_event ev;
      ck_assert_ok (chaplygin_discrete_step (sys, st, 0, NULL, st, &ev));
      count += (unsigned long) ev.reversal;
    }
  return count;
}

static chaplygin_discrete_state
massless_state (double L0, double V, double Omega)
{
  double q[4] = { V > 0 ? 0 : 1, V, 0, Omega };
  chaplygin_discrete_state st;
  ck_assert_ok (chaplygin_massless_state_from_phase (L0, q, 0, NULL, &st));
  return st;
}

/* The real parts of the eigenvalues of the 4 x 4 row-major A, ascending
   (GSL's nonsymmetric solver; the matrices here have real spectra). */
static void
eigenvalues (const double A[16], double re[4])
{
  double a[16];
  memcpy (a, A, sizeof a);
  gsl_matrix_view m = gsl_matrix_view_array (a, 4, 4);
  gsl_vector_complex *eval = gsl_vector_complex_alloc (4);
  gsl_eigen_nonsymm_workspace *w = gsl_eigen_nonsymm_alloc (4);
  ck_assert (eval != NULL && w != NULL);
  ck_assert_int_eq (gsl_eigen_nonsymm (&m.matrix, eval, w), GSL_SUCCESS);
  for (int i = 0; i < 4; i++)
    re[i] = GSL_REAL (gsl_vector_complex_get (eval, (size_t) i));
  gsl_eigen_nonsymm_free (w);
  gsl_vector_complex_free (eval);
  gsl_sort (re, 1, 4);
}

/* ---- Section 3.1.2 and the abstract: stability of the straight line --- */

/* Abstract, Section 3.1.2: "asymptotically stable if the mass center is in
   front of the center of the slot": for V* > 0, L0/Delta > -1/2 gives
   |sigma4| < 1 whatever Delta.  Reference: the algebra of (3.10),
   1 - sigma4 = Delta l1/(1 + l1^2), 1 + sigma4 = (2 + L0 l1 + l1^2)/(1 + l1^2),
   l1 = L0 + Delta, both positive there. */
START_TEST (claim_stable_ahead_of_centre)
{
  static const double x[] = { -0.4999, -0.49, -0.4, -0.25, -0.1, 0, 0.5, 2,
                              10 };
  static const double Delta[] = { 1e-3, 0.1, 1, 3, 10, 100, 1e4 };
  for (size_t i = 0; i < NELEM (x); i++)
    for (size_t j = 0; j < NELEM (Delta); j++)
      {
        double D = Delta[j], L0 = x[i] * D, s = sigma4 (L0, D, +1);
        long double l1 = (long double) L0 + D;
        long double below = D * l1 / (1 + l1 * l1);
        long double above = (2 + L0 * l1 + l1 * l1) / (1 + l1 * l1);
        ck_assert (below > 0 && above > 0);
        /* sigma4 is within 4 ulps of its value (accuracy of (3.10)), so
           1 - sigma4 is within 4 eps absolutely. */
        ck_assert_msg (fabsl ((1 - (long double) s) - below) <= 4 * DBL_EPSILON,
                       "x = %g, Delta = %g: sigma4 = %.17g", x[i], D, s);
        ck_assert_int_eq (stable (L0, D, +1), 1);
      }
}
END_TEST

/* Abstract: "unstable if it lies behind the slot": for V* > 0,
   L0/Delta < -1 gives sigma4 > 1 (1 - sigma4 = Delta l1/(1 + l1^2) < 0). */
START_TEST (claim_unstable_behind_slot)
{
  static const double x[] = { -1.0001, -1.1, -1.5, -2, -4, -100 };
  static const double Delta[] = { 1e-3, 0.1, 1, 3, 10, 100 };
  for (size_t i = 0; i < NELEM (x); i++)
    for (size_t j = 0; j < NELEM (Delta); j++)
      {
        double D = Delta[j], L0 = x[i] * D, s = sigma4 (L0, D, +1);
        long double l1 = (long double) L0 + D;
        long double below = D * l1 / (1 + l1 * l1);
        ck_assert (below < 0);
        /* sigma4 within 4 ulps: 1 - sigma4 within 4 eps of max(1, sigma4). */
        ck_assert_msg (fabsl ((1 - (long double) s) - below)
                       <= 4 * DBL_EPSILON * fmax (1, s),
                       "x = %g, Delta = %g: sigma4 = %.17g", x[i], D, s);
        ck_assert (s > 1);
        ck_assert_int_eq (stable (L0, D, +1), 0);
      }
}
END_TEST

/* Abstract, (3.11): between the centre and the rear of the slot
   (-1 < L0/Delta < -1/2) "stability depends subtly on slot length and
   radius of gyration": stable iff (1/Delta)^2 > y* = -(1 + 2x)(1 + x)/2,
   the curve where sigma4 = -1.  Reference: y* evaluated here, and
   sigma4 = -1 on it (1 + sigma4 = (2 + L0 l1 + l1^2)/(1 + l1^2)). */
START_TEST (claim_rear_half_depends_on_size)
{
  static const double x[] = { -0.99, -0.9, -0.75, -2.0 / 3, -0.6, -0.51 };
  for (size_t i = 0; i < NELEM (x); i++)
    {
      double ystar = -(1 + 2 * x[i]) * (1 + x[i]) / 2, ymin;
      int stabilizable;
      ck_assert (ystar > 0);
      ck_assert_ok (chaplygin_discrete_stability_boundary (+1, x[i],
                                                           &stabilizable,
                                                           &ymin));
      ck_assert_int_eq (stabilizable, 1);
      /* Three roundings in each evaluation. */
      ck_assert_eps (ymin, ystar, 4);
      for (int side = -1; side <= 1; side += 2)
        {
          /* A relative step of 1e-6 in y moves sigma4 by about 1e-6, far
             beyond its 4-ulp error. */
          double y = ystar * (1 + side * 1e-6), D = 1 / sqrt (y);
          double s = sigma4 (x[i] * D, D, +1);
          ck_assert_int_eq (stable (x[i] * D, D, +1), side > 0);
          ck_assert (side > 0 ? s > -1 : s < -1);
          ck_assert (fabs (s + 1) < 1e-5);
        }
    }
}
END_TEST

/* Section 3.1.2, Figure 2(b): with the mass centre within the slot,
   "open sets of parameters exist for which (3.11-3.12) are both satisfied";
   outside the slot never both.  Figure 7's skate (L0/Delta = -2/3,
   (1/Delta)^2 = 0.08) and a neighbourhood of it are bistable. */
START_TEST (claim_bistable_within_slot)
{
  for (int i = -1; i <= 1; i++)
    for (int j = -1; j <= 1; j++)
      {
        double x = -2.0 / 3 * (1 + 0.01 * i), y = 0.08 * (1 + 0.01 * j);
        double D = 1 / sqrt (y);
        ck_assert_int_eq (stable (x * D, D, +1), 1);
        ck_assert_int_eq (stable (x * D, D, -1), 1);
      }
  static const double inside[] = { -0.9, -0.5, -0.1 };
  for (size_t i = 0; i < NELEM (inside); i++)
    {
      /* A short slot: both (3.11) and (3.12) hold for any -1 < x < 0. */
      ck_assert_int_eq (stable (inside[i] * 0.1, 0.1, +1), 1);
      ck_assert_int_eq (stable (inside[i] * 0.1, 0.1, -1), 1);
    }
  static const double outside[] = { -3, -1.5, -1, 0, 0.2, 1 };
  static const double Delta[] = { 0.01, 0.3, 1, 3, 30 };
  for (size_t i = 0; i < NELEM (outside); i++)
    for (size_t j = 0; j < NELEM (Delta); j++)
      {
        double D = Delta[j], L0 = outside[i] * D;
        ck_assert (!(stable (L0, D, +1) && stable (L0, D, -1)));
      }
}
END_TEST

/* Section 3.1.2: "(In fact the system has a reflection symmetry about the
   mass center: taking L0 to -(L0 + Delta) and V to -V.)"  sigma4 of one
   is sigma4 of the other, and the map commutes with the reflection:
   a forward state (E, H) of L0 and the backward state (E, H) of
   -(L0 + Delta) have the same E, H, heading increment and reversals.
   L0 + Delta is exact for every pair here, so the two sides compute the
   same numbers: 2 ulps allow for a different order of operations. */
START_TEST (claim_reflection_symmetry)
{
  static const double L0[] = { -0.375, 0.25, -1.75, -0.5, 2.5 };
  const double Delta = 1;
  for (size_t i = 0; i < NELEM (L0); i++)
    {
      double M0 = -(L0[i] + Delta);
      ck_assert_eps (sigma4 (L0[i], Delta, -1), sigma4 (M0, Delta, +1), 2);
      chaplygin_discrete a = skate (L0[i], Delta), b = skate (M0, Delta);
      chaplygin_discrete_state sa = state (&a, 0.3, 0.9), sb = sa;
      sb.dir = -1;
      sb.V = -sa.V;
      for (int k = 0; k < 8 && sa.H != 0; k++)
        {
          chaplygin_discrete_event ea, eb;
          ck_assert_ok (chaplygin_discrete_step (&a, &sa, CHAPLYGIN_WANT_THETA,
                                                 NULL, &sa, &ea));
          ck_assert_ok (chaplygin_discrete_step (&b, &sb, CHAPLYGIN_WANT_THETA,
                                                 NULL, &sb, &eb));
          ck_assert_int_eq (sa.dir, -sb.dir);
          ck_assert_int_eq (ea.reversal, eb.reversal);
          ck_assert_eps (sa.E, sb.E, 2 * (k + 1));
          ck_assert_eps (sa.H, sb.H, 2 * (k + 1));
          ck_assert_eps (ea.dtheta, eb.dtheta, 4 * (k + 1));
        }
    }
}
END_TEST

/* Section 3.1.2: "sigma1 = 0 ... sigma2,3 = 1 ... |sigma4| determines
   stability type": the eigenvalues of the return map's Jacobian at a
   straight-line motion are 0, 1, 1 and sigma4 of (3.10).  Reference:
   central differences of the map itself (chaplygin_discrete_step) in
   (D, E, theta, H), not the library's analytic Jacobian; step h = 1e-5
   relative: truncation about h^2 = 1e-10, rounding about eps/h = 2e-11,
   so the eigenvalues are asserted to 1e-8. */
START_TEST (claim_jacobian_eigenvalues)
{
  static const struct { double L0, Delta, V; } c[] = {
    { 0.3, 0.7, 1.3 }, { -0.5, 0.4, -0.8 }, { -2.0 / 3 * 3.5, 3.5, 0.6 },
  };
  for (size_t k = 0; k < NELEM (c); k++)
    {
      chaplygin_discrete sys = skate (c[k].L0, c[k].Delta);
      chaplygin_discrete_state p0;
      ck_assert_ok (chaplygin_discrete_fixed_point (&sys, c[k].V, 0.2, 0,
                                                    NULL, &p0, NULL));
      double scale[4] = { 0, p0.E, 1, sqrt (2 * p0.E) }, J[16] = { 0 };
      for (int j = 1; j < 4; j++)
        {
          double h = 1e-5 * scale[j], out[2][4];
          for (int side = 0; side < 2; side++)
            {
              chaplygin_discrete_state p = p0;
              double d = side ? h : -h;
              p.V = 0;   /* V+ no longer that of (E, H) */
              if (j == 1) p.E += d;
              if (j == 2) p.theta += d;
              if (j == 3) p.H += d;
              ck_assert_ok (chaplygin_discrete_step (&sys, &p,
                                                     CHAPLYGIN_WANT_THETA,
                                                     NULL, &p, NULL));
              ck_assert_int_eq (p.dir, p0.dir);
              out[side][0] = 0;   /* D+ is fixed by the direction */
              out[side][1] = p.E;
              out[side][2] = p.theta;
              out[side][3] = p.H;
            }
          for (int i = 0; i < 4; i++)
            J[4 * i + j] = (out[1][i] - out[0][i]) / (2 * h);
        }
      double re[4];
      eigenvalues (J, re);
      long double L0 = c[k].L0, D = c[k].Delta, l = c[k].V > 0 ? L0 + D : L0;
      double s4 = (double) ((1 + L0 * (L0 + D)) / (1 + l * l));
      double want[4] = { 0, 1, 1, s4 };
      gsl_sort (want, 1, 4);
      for (int i = 0; i < 4; i++)
        ck_assert_msg (fabs (re[i] - want[i]) < 1e-8,
                       "case %zu: eigenvalue %.12g, expected %.12g", k,
                       re[i], want[i]);
    }
}
END_TEST

/* Section 3.1.1, Appendix B.3: "periodic motions require no energy loss at
   collisions"; every collision with H != 0 loses energy (C1 < 0 in (B.3)
   and (B.4) for every end and direction), so for rho > 0 the only
   periodic motions are the straight lines H = 0.  Reference for the loss:
   (3.7), Delta^2 H^2/(2 (1 + l-^2)^2 (1 + l+^2)), evaluated here in long
   double, against the energies of plain steps (4 roundings in the step's
   E' = E + C1 H^2, 1e-13 relative of the loss where E' - E loses a
   factor E/loss: 4 eps of E absolutely). */
START_TEST (claim_collisions_lose_energy)
{
  static const double L0[] = { -3, -0.6, -0.2, 0.4, 2 };
  static const double Delta[] = { 0.1, 1, 5 };
  for (size_t i = 0; i < NELEM (L0); i++)
    for (size_t j = 0; j < NELEM (Delta); j++)
      for (int end = 0; end < 2; end++)
        for (int rev = 0; rev < 2; rev++)
          {
            double C1, C2;
            ck_assert_ok (chaplygin_discrete_coefficients (L0[i], Delta[j],
                                                           end * Delta[j],
                                                           rev, &C1, &C2));
            ck_assert (C1 < 0);
          }
  chaplygin_discrete sys = skate (0.4, 1);
  chaplygin_discrete_state st = state (&sys, 0.5, 0.8);
  /* 12 collisions: H^2 falls by C2^2 = 0.28 per collision, and the loss
     stays above 1e-11, far above the rounding of E. */
  for (int k = 0; k < 12; k++)
    {
      chaplygin_discrete_state next;
      chaplygin_discrete_event ev;
      ck_assert_ok (chaplygin_discrete_step (&sys, &st, 0, NULL, &next, &ev));
      ck_assert_int_eq (ev.reversal, 0);
      long double lm = 0.4L + ev.Dminus, lp = 0.4L + ev.Dplus, H = st.H;
      long double loss = 1.0L * H * H / (2 * (1 + lm * lm) * (1 + lm * lm)
                                          * (1 + lp * lp));
      ck_assert (next.E < st.E);
      ck_assert_abs_eps (st.E - next.E, (double) loss, 4, st.E);
      st = next;
    }
}
END_TEST

/* Section 3.1.1: "an equilibrium solution exists without collisions if
   the mass center lies within the slot (-Delta < L0 < 0)": the skate
   spinning about the peg at the mass centre, D = -L0.  Reference: the
   equations of motion (3.1) vanish there but for dtheta/dtau = Omega;
   outside the slot the library refuses it. */
START_TEST (claim_spin_within_slot)
{
  static const double L0[] = { -0.999, -0.5, -0.01 };
  for (size_t i = 0; i < NELEM (L0); i++)
    {
      double q[4], dq[4];
      ck_assert_ok (chaplygin_discrete_spin_equilibrium (L0[i], 1, 0.7, 0.3,
                                                         2, q));
      ck_assert_ok (chaplygin_discrete_field (L0[i], q, dq));
      ck_assert (dq[0] == 0 && dq[1] == 0 && dq[3] == 0);
      ck_assert (dq[2] == 0.7);
    }
  static const double outside[] = { -1.5, -1, 0, 0.3 };
  for (size_t i = 0; i < NELEM (outside); i++)
    {
      double q[4];
      ck_assert_status (chaplygin_discrete_spin_equilibrium (outside[i], 1,
                                                             0.7, 0, 0, q),
                        CHAPLYGIN_EDOM);
    }
}
END_TEST

/* Section 3.1.2: the spinning solution "is always of unstable saddle type,
   having eigenvalues 0 and +-Omega_eq".  Reference: central differences
   of the vector field (3.1) (chaplygin_discrete_field), h = 1e-6: the
   field is quadratic in V and Omega and smooth in D, so the error is
   about h^2 plus eps/h, below 1e-9; asserted to 1e-8. */
START_TEST (claim_spin_saddle)
{
  static const struct { double L0, Delta, Omega; } c[] = {
    { -0.4, 1, 0.7 }, { -0.1, 0.3, -2.5 }, { -1.9, 2, 0.05 },
  };
  for (size_t k = 0; k < NELEM (c); k++)
    {
      double q0[4], A[16], re[4], lambda[4];
      ck_assert_ok (chaplygin_discrete_spin_equilibrium (c[k].L0, c[k].Delta,
                                                         c[k].Omega, 0, 0,
                                                         q0));
      for (int j = 0; j < 4; j++)
        {
          double qp[4], qm[4], fp[4], fm[4], h = 1e-6;
          memcpy (qp, q0, sizeof qp);
          memcpy (qm, q0, sizeof qm);
          qp[j] += h;
          qm[j] -= h;
          ck_assert_ok (chaplygin_discrete_field (c[k].L0, qp, fp));
          ck_assert_ok (chaplygin_discrete_field (c[k].L0, qm, fm));
          for (int i = 0; i < 4; i++)
            A[4 * i + j] = (fp[i] - fm[i]) / (2 * h);
        }
      eigenvalues (A, re);
      double w = fabs (c[k].Omega), want[4] = { -w, 0, 0, w };
      ck_assert_ok (chaplygin_discrete_spin_eigenvalues (c[k].L0, c[k].Delta,
                                                         c[k].Omega, lambda));
      for (int i = 0; i < 4; i++)
        {
          ck_assert_msg (fabs (re[i] - want[i]) < 1e-8 * fmax (1, w),
                         "eigenvalue %.12g, expected %.12g", re[i], want[i]);
          ck_assert (lambda[i] == want[i]);
        }
    }
}
END_TEST

/* Section 4.1, abstract: "as slot length vanishes, the system inherits the
   eigenvalues of the Chaplygin sleigh": xi4 = (V* / Delta) log sigma4 tends
   to the smooth sleigh's -L0 V* / (1 + L0^2) (chaplygin_smooth_eigenvalue,
   the other system) with an error of first order in Delta: it falls by a
   factor within 10 +- 1.5 per decade of Delta (the next term is of
   relative size Delta). */
START_TEST (claim_xi4_smooth_limit)
{
  static const double L0[] = { 1, -1, 0.5, 3, -0.2 };
  for (size_t i = 0; i < NELEM (L0); i++)
    {
      double smooth, prev = 0;
      ck_assert_ok (chaplygin_smooth_eigenvalue (L0[i], 1, &smooth));
      ck_assert_rel (smooth, -L0[i] / (1 + L0[i] * L0[i]), 2 * DBL_EPSILON);
      for (int k = 2; k <= 6; k++)
        {
          double Delta = pow (10, -k), xi4;
          ck_assert_ok (chaplygin_discrete_xi4 (L0[i], Delta, 1, &xi4));
          double err = fabs (xi4 - smooth);
          ck_assert (err < Delta);
          if (k > 2)
            ck_assert_msg (prev / err > 8.5 && prev / err < 11.5,
                           "L0 = %g: error %g after %g", L0[i], err, prev);
          prev = err;
        }
    }
}
END_TEST

/* Conclusions: "the discrete skate has somewhat broader stability ranges
   than its smooth sister, in terms of mass center position": for every
   slot, the forward motion is stable for every mass centre ahead of the
   slot's centre (L0 > -Delta/2, Section 3.1.2), where the smooth sleigh with
   its mass centre at the same distance behind its contact (L = L0 < 0) is
   unstable (xi4 > 0). */
START_TEST (claim_broader_than_smooth)
{
  static const double Delta[] = { 0.01, 0.5, 2, 50 };
  static const double x[] = { -0.49, -0.3, -0.05 };
  for (size_t j = 0; j < NELEM (Delta); j++)
    for (size_t i = 0; i < NELEM (x); i++)
      {
        double L0 = x[i] * Delta[j], xi;
        ck_assert_int_eq (stable (L0, Delta[j], +1), 1);
        ck_assert_ok (chaplygin_smooth_eigenvalue (L0, 1, &xi));
        ck_assert (xi > 0);
      }
}
END_TEST

/* Section 3.1.1, Appendix B.3: "a two-dimensional family of period-1
   motions parameterized by speed V* and heading theta*", with
   "inter collision duration tau* = Delta/V*".  Reference: one plain step
   of the map (heading and time requested) returns E and theta unchanged
   and advances the time by Delta/|V*| (2 roundings). */
START_TEST (claim_period1_family)
{
  static const double V[] = { 0.01, 0.7, 3, -0.2, -5 };
  static const double theta[] = { 0, 1.3, -2.9 };
  chaplygin_discrete sys = skate (-0.3, 0.8);
  for (size_t i = 0; i < NELEM (V); i++)
    for (size_t j = 0; j < NELEM (theta); j++)
      {
        chaplygin_discrete_state st, next;
        chaplygin_discrete_event ev;
        ck_assert_ok (chaplygin_discrete_fixed_point (&sys, V[i], theta[j], 0,
                                                      NULL, &st, NULL));
        ck_assert_ok (chaplygin_discrete_step (&sys, &st,
                                               CHAPLYGIN_WANT_THETA
                                               | CHAPLYGIN_WANT_TAU, NULL,
                                               &next, &ev));
        ck_assert (next.E == st.E && next.H == 0 && next.dir == st.dir);
        ck_assert (next.theta == theta[j]);
        ck_assert_eps (next.tau, 0.8 / fabs (V[i]), 2);
      }
}
END_TEST

/* Section 2: skates "enjoy velocity scaling; e.g., double the velocity as
   a function of position and the resulting solution is still legitimate".
   Reference: the same motion at three times the speed, by the library
   itself: after a collision (discrete) or at the same arc length (smooth)
   speeds and rates scale by 3, energies by 9, times by 1/3, headings are
   unchanged; 8 eps allow for the roundings of both runs. */
START_TEST (claim_velocity_scaling)
{
  chaplygin_discrete sys = skate (-0.3, 0.8);
  static const double q[][2] = { { 0.37, 0.61 }, { -0.9, 0.2 }, { 0.05, 2 } };
  for (size_t k = 0; k < NELEM (q); k++)
    {
      chaplygin_discrete_state a = state (&sys, q[k][0], q[k][1]);
      chaplygin_discrete_state b = state (&sys, 3 * q[k][0], 3 * q[k][1]);
      for (int n = 0; n < 5 && a.H != 0; n++)
        {
          unsigned req = CHAPLYGIN_WANT_THETA | CHAPLYGIN_WANT_TAU;
          ck_assert_ok (chaplygin_discrete_step (&sys, &a, req, NULL, &a, NULL));
          ck_assert_ok (chaplygin_discrete_step (&sys, &b, req, NULL, &b, NULL));
          ck_assert_int_eq (a.dir, b.dir);
          ck_assert_eps (b.E, 9 * a.E, 8 * (n + 1));
          ck_assert_eps (b.H, 3 * a.H, 8 * (n + 1));
          ck_assert_eps (b.theta, a.theta, 8 * (n + 1));
          ck_assert_eps (b.tau, a.tau / 3, 8 * (n + 1));
        }
    }
  double q0[4] = { 0, 0.8, 0.1, 0.3 }, q1[4] = { 0, 2.4, 0.1, 0.9 };
  static const double L[] = { 1, -1.4 };
  for (size_t i = 0; i < NELEM (L); i++)
    for (int s = 1; s <= 6; s++)
      {
        double a[4], b[4], ta, tb;
        ck_assert_ok (chaplygin_smooth_closed_form (L[i], q0, s, a, &ta));
        ck_assert_ok (chaplygin_smooth_closed_form (L[i], q1, s, b, &tb));
        ck_assert_eps (b[1], 3 * a[1], 8);
        ck_assert_eps (b[3], 3 * a[3], 8);
        ck_assert_eps (b[2], a[2], 8);
        ck_assert_eps (tb, ta / 3, 8);
      }
}
END_TEST

/* Section 2: smooth "trajectories ... are curves with angular momentum
   exponentially growing (L < 0) or decaying (L > 0) as functions of arc
   length, and lying in constant energy planes".  Reference: a classical
   Runge-Kutta integration (fourth order, step 1e-3) of (2.1) here, not
   the library's closed form: over tau in [0, 3] its error is about
   1e-12, so E is asserted constant to 1e-11 and log(H/H0) to equal
   -L S/(1 + L^2) to 1e-10 (before any reversal). */
START_TEST (claim_smooth_exponential_momentum)
{
  static const double L[] = { 0.7, -0.7, 2, -0.3 };
  for (size_t i = 0; i < NELEM (L); i++)
    {
      double q[4] = { 0, 1, 0, 0.2 }, h = 1e-3, a = L[i] / (1 + L[i] * L[i]);
      double E0 = (1 + (1 + L[i] * L[i]) * 0.04) / 2, H0 = (1 + L[i] * L[i]) * 0.2;
      for (int n = 0; n < 3000; n++)
        {
          double k1[4], k2[4], k3[4], k4[4], t[4];
          ck_assert_ok (chaplygin_smooth_field (L[i], q, k1));
          for (int j = 0; j < 4; j++) t[j] = q[j] + h / 2 * k1[j];
          ck_assert_ok (chaplygin_smooth_field (L[i], t, k2));
          for (int j = 0; j < 4; j++) t[j] = q[j] + h / 2 * k2[j];
          ck_assert_ok (chaplygin_smooth_field (L[i], t, k3));
          for (int j = 0; j < 4; j++) t[j] = q[j] + h * k3[j];
          ck_assert_ok (chaplygin_smooth_field (L[i], t, k4));
          for (int j = 0; j < 4; j++)
            q[j] += h / 6 * (k1[j] + 2 * k2[j] + 2 * k3[j] + k4[j]);
          ck_assert (q[1] > 0);
          double E = (q[1] * q[1] + (1 + L[i] * L[i]) * q[3] * q[3]) / 2;
          double H = (1 + L[i] * L[i]) * q[3];
          ck_assert_rel (E, E0, 1e-11);
          ck_assert_msg (fabs (log (H / H0) + a * q[0]) < 1e-10,
                         "L = %g, S = %g: log(H/H0) = %.15g, -a S = %.15g",
                         L[i], q[0], log (H / H0), -a * q[0]);
        }
      ck_assert (L[i] > 0 ? q[3] < 0.2 : q[3] > 0.2);
    }
}
END_TEST

/* ---- Section 3.1.3, Appendix B.2: reversals and basins ------------------ */

/* Section 3.1.3: "For I != 0 almost all initial conditions are attracted
   to straight-line constant-speed motions".  Every start of a grid over
   the bistable band of Figure 2(b) ((1/Delta)^2 = 1, Omega+ = 4/5,
   L0/Delta in [-0.99, -0.01], V+ in [-1, 1]) and of a skate ahead of
   and one behind the slot ends forward or backward within 10^5
   collisions: none spins and none is undecided. */
START_TEST (claim_almost_all_straight)
{
  enum { NV = 80 };
  double V[NV], Omega[NV];
  chaplygin_fate f[NV];
  for (int k = 0; k < NV; k++)
    {
      V[k] = (k < NV / 2 ? -1 : 1) * (1 + (k % (NV / 2))) / (NV / 2.0);
      Omega[k] = 0.8;
    }
  for (int i = 0; i <= 50; i++)
    {
      double x = i < 49 ? -0.99 + 0.02 * i : (i == 49 ? 0.5 : -2);
      chaplygin_discrete sys = skate (x, 1);
      ck_assert_ok (chaplygin_discrete_fates_phase (&sys, NV, V, Omega,
                                                    100000, f, NULL, NULL));
      for (int k = 0; k < NV; k++)
        ck_assert_msg (f[k].kind == FWD || f[k].kind == BWD,
                       "L0 = %g, V = %g: fate %d", x, V[k], f[k].kind);
    }
}
END_TEST

/* Section 3.1.3: "if L0 > 0 and V > 0 initially, no velocity reversal
   occurs".  Reference: plain iteration of the map, 200 collisions (or
   until H = 0), counting reversing segments. */
START_TEST (claim_no_reversal_ahead_forward)
{
  static const double L0[] = { 0.01, 0.3, 1, 5 };
  static const double Delta[] = { 0.1, 1, 10 };
  static const double V[] = { 1e-3, 0.1, 1 };
  static const double Omega[] = { 0.1, -1, 10 };
  for (size_t a = 0; a < NELEM (L0); a++)
    for (size_t b = 0; b < NELEM (Delta); b++)
      {
        chaplygin_discrete sys = skate (L0[a], Delta[b]);
        for (size_t c = 0; c < NELEM (V); c++)
          for (size_t d = 0; d < NELEM (Omega); d++)
            {
              chaplygin_discrete_state st = state (&sys, V[c], Omega[d]);
              ck_assert_msg (reversals_in (&sys, &st, 200) == 0,
                             "L0 = %g, Delta = %g, V = %g, Omega = %g",
                             L0[a], Delta[b], V[c], Omega[d]);
              ck_assert_int_eq (st.dir, 1);
            }
      }
}
END_TEST

/* Section 3.1.3: "For -Delta < L0 < 0 ... more complex behavior may occur,
   involving multiple reversals", where outside the slot a motion reverses
   at most once.  Figure 3's skate from V+ between the basin boundaries
   (3/5)^3/sqrt(5) and (3/5)^2/sqrt(5) reverses three times; 400 random
   starts of skates ahead of and behind the slot reverse at most once in
   300 collisions (plain iteration of the map). */
START_TEST (claim_multiple_reversals_in_slot)
{
  chaplygin_discrete fig3 = skate (-0.5, 1);
  double V = sqrt (0.6 * 0.6 * 0.6 * 0.6 * 0.6) / sqrt (5);
  chaplygin_discrete_state st = state (&fig3, V, 0.8);
  ck_assert_int_eq (reversals_in (&fig3, &st, 1000), 3);
  tu_rng r;
  tu_rng_seed (&r, 30);
  static const double L0[] = { 0.3, 2, -1.6, -4 };
  for (size_t i = 0; i < NELEM (L0); i++)
    {
      chaplygin_discrete sys = skate (L0[i], 1);
      for (int k = 0; k < 100; k++)
        {
          double v = tu_uniform (&r, -2, 2), w = tu_uniform (&r, -2, 2);
          if (v == 0)
            continue;
          chaplygin_discrete_state s = state (&sys, v, w);
          ck_assert_uint_le (reversals_in (&sys, &s, 300), 1);
        }
    }
}
END_TEST

/* Section 3.1.3, basins item 1: "For 2E/H^2 > 1, no reversals occur and
   all initial states with V+ > 0 are attracted to solutions V* > 0":
   contradicted where r*+ = 2 C1/(C2^2 - 1) > 1 (erratum E14).  At
   L0 = -0.95, Delta = 1 (both directions stable) forward starts with
   2E/H^2 = 1.0001, 2, 3 and 5 reverse and end backward (plain iteration of
   the map, then the fate); for Figure 3's skate, where r* <= 1, the
   statement holds for 2E/H^2 from 1.001 to 10. */
START_TEST (claim_no_reversal_above_one)
{
  ck_assert_int_eq (stable (-0.95, 1, +1) && stable (-0.95, 1, -1), 1);
  chaplygin_discrete sys = skate (-0.95, 1);
  static const double r[] = { 1.0001, 2, 3, 5 };
  for (size_t i = 0; i < NELEM (r); i++)
    {
      chaplygin_discrete_state st = { .dir = 1, .H = 1, .E = r[i] / 2 };
      ck_assert_uint_ge (reversals_in (&sys, &st, 100000), 1);
      ck_assert_int_eq (st.dir, -1);
      double l = -0.95, Omega = 1 / (1 + l * l);
      double V = sqrt (r[i] - (1 + l * l) * Omega * Omega);
      ck_assert_int_eq (fate (&sys, V, Omega, 100000).kind, BWD);
    }
  chaplygin_discrete fig3 = skate (-0.5, 1);
  for (double rr = 1.001; rr <= 10; rr *= 1.1)
    {
      chaplygin_discrete_state st = { .dir = 1, .H = 1, .E = rr / 2 };
      ck_assert_uint_eq (reversals_in (&fig3, &st, 100000), 0);
    }
}
END_TEST

/* Section 3.1.3 item 2, Appendix B.2.2, Figure 3: for 2E/H^2 < 1 the
   starts "fall into an alternating infinite sequence of open intervals",
   whose boundaries reach the spinning state and whose widths decrease as
   the ratio tends to 0.  Figure 3 (L0 = -1/2, Delta = 1, Omega+ = 4/5):
   the boundaries in [0.0005, 0.5] found by bisecting the fates are the
   (B.13) members (3/5)^n/sqrt(5), n = 0..13 (reference: that closed form,
   erratum E15; (7 + n) eps, the bound of chaplygin_discrete_basin_boundaries),
   the fates alternate between them and the widths decrease. */
START_TEST (claim_basins_alternate)
{
  chaplygin_discrete sys = skate (-0.5, 1);
  double Vb[32];
  size_t count;
  ck_assert_ok (chaplygin_discrete_basin_boundaries (&sys, 0.8, 0.0005, 0.5,
                                                     4000, 100000, Vb, 32,
                                                     &count));
  ck_assert_uint_eq (count, 14);
  for (size_t k = 0; k < count; k++)
    {
      int n = (int) (count - 1 - k);
      ck_assert_eps (Vb[k], pow (0.6, n) / sqrt (5), 7 + n);
      if (k > 0)
        {
          double mid = sqrt (Vb[k - 1] * Vb[k]);
          chaplygin_fate f = fate (&sys, mid, 0.8, 100000);
          /* between boundaries n+1 and n: n + 1 reversals, ending
             backward for odd n + 1 */
          ck_assert_uint_eq (f.reversals, (unsigned long) n + 1);
          ck_assert_int_eq (f.kind, (n + 1) % 2 ? BWD : FWD);
          if (k > 1)
            ck_assert (Vb[k] - Vb[k - 1] > Vb[k - 1] - Vb[k - 2]);
        }
    }
  ck_assert_int_eq (fate (&sys, 0.6, 0.8, 100000).kind, FWD);
}
END_TEST

/* Figure 3's caption: "No reversals or spinning solutions occur for
   2 ^(i+1)E+/(^(i+1)H+)^2 > 1 (^iV+ > 1/sqrt(5), here)": refined
   (erratum E16).  With the initial state's ratio it holds: every
   V+ in (1/sqrt(5), 3] goes forward without reversal.  With the ratio
   after the next collision, as printed, it does not: V+ = 0.3 has
   2E/H^2 = 1.05 > 1 after its first collision, having reversed on the
   way. */
START_TEST (claim_figure3_threshold)
{
  chaplygin_discrete sys = skate (-0.5, 1);
  for (int k = 1; k <= 200; k++)
    {
      double V = 1 / sqrt (5) * (1 + 1e-9) + (3 - 1 / sqrt (5)) * (k - 1) / 199;
      chaplygin_fate f = fate (&sys, V, 0.8, 100000);
      ck_assert_int_eq (f.kind, FWD);
      ck_assert_uint_eq (f.reversals, 0);
    }
  chaplygin_discrete_state st = state (&sys, 0.3, 0.8);
  chaplygin_discrete_event ev;
  ck_assert (2 * st.E / (st.H * st.H) < 1);
  ck_assert_ok (chaplygin_discrete_step (&sys, &st, 0, NULL, &st, &ev));
  ck_assert_int_eq (ev.reversal, 1);
  /* 2E/H^2 = (0.89 + 2 C1)/C2^2 = 1.05 after the collision
     (C1 = -1/(2 (5/4)^3), C2 = 3/5; a few roundings). */
  ck_assert_rel (2 * st.E / (st.H * st.H), (0.89 - 0.512) / 0.36, 1e-14);
}
END_TEST

/* Figure 3's caption: "the plot is symmetric about ^iV+ = 0".  For
   L0 = -Delta/2 the reflection of Section 3.1.2 maps the skate to itself:
   the fate from -V+ is the opposite of that from V+, with as many
   reversals, at 300 starts. */
START_TEST (claim_figure3_symmetric)
{
  enum { N = 300 };
  double V[2 * N], Omega[2 * N];
  chaplygin_fate f[2 * N];
  for (int k = 0; k < N; k++)
    {
      V[k] = 0.0005 + 0.6 * k / N;
      V[N + k] = -V[k];
      Omega[k] = Omega[N + k] = 0.8;
    }
  chaplygin_discrete sys = skate (-0.5, 1);
  ck_assert_ok (chaplygin_discrete_fates_phase (&sys, 2 * N, V, Omega, 100000,
                                                f, NULL, NULL));
  for (int k = 0; k < N; k++)
    {
      ck_assert_int_eq (f[N + k].kind, -f[k].kind);
      ck_assert_uint_eq (f[N + k].reversals, f[k].reversals);
    }
}
END_TEST

/* Section 3.1.3: "Similar results hold for different initial angular
   velocities."  Confirmed exactly: the map is homogeneous in velocity
   (Section 2), so the fate of (V+, Omega+) is that of (c V+, c Omega+);
   Figure 3's basins at Omega+ are those at 4/5 scaled by Omega+/(4/5).
   300 starts each at c = 0.37 and 5 have the fates and reversal counts of
   Figure 3's. */
START_TEST (claim_other_angular_velocities)
{
  enum { N = 300 };
  static const double c[] = { 0.37, 5 };
  double V[N], Omega[N], cV[N], cOmega[N];
  chaplygin_fate f[N], g[N];
  chaplygin_discrete sys = skate (-0.5, 1);
  for (int k = 0; k < N; k++)
    {
      V[k] = 0.001 + 0.6 * k / N;
      Omega[k] = 0.8;
    }
  ck_assert_ok (chaplygin_discrete_fates_phase (&sys, N, V, Omega, 100000, f,
                                                NULL, NULL));
  for (size_t i = 0; i < NELEM (c); i++)
    {
      for (int k = 0; k < N; k++)
        {
          cV[k] = c[i] * V[k];
          cOmega[k] = c[i] * Omega[k];
        }
      ck_assert_ok (chaplygin_discrete_fates_phase (&sys, N, cV, cOmega,
                                                    100000, g, NULL, NULL));
      for (int k = 0; k < N; k++)
        {
          ck_assert_int_eq (g[k].kind, f[k].kind);
          ck_assert_uint_eq (g[k].reversals, f[k].reversals);
        }
    }
}
END_TEST

/* Appendix B.2.2: for L0/Delta = -1/2 "the velocity along the slot after
   many collisions returns to its initial value, V_f = V_0 (the skate has
   no sense of whether it is going forwards or backwards)".  Confirmed in
   size, with or without reversals: |V*| = |V+| for 200 random starts of
   three symmetric skates (the fate's V_final; 1e-12 relative: at most a
   few hundred collisions of a few roundings each); its sign is the
   fate's, not V+'s.  Not so off the centre: at L0/Delta = -0.3 the final
   speed differs from |V+| by more than 1e-3 relative. */
START_TEST (claim_symmetric_final_speed)
{
  tu_rng r;
  tu_rng_seed (&r, 31);
  static const double Delta[] = { 0.5, 1, 1.5 };
  for (size_t i = 0; i < NELEM (Delta); i++)
    {
      chaplygin_discrete sys = skate (-Delta[i] / 2, Delta[i]);
      chaplygin_discrete off = skate (-0.3 * Delta[i], Delta[i]);
      for (int k = 0; k < 200; k++)
        {
          double V = tu_uniform (&r, -1, 1), W = tu_uniform (&r, 0.1, 1);
          if (V == 0)
            continue;
          chaplygin_fate f = fate (&sys, V, W, 100000);
          ck_assert (f.kind == FWD || f.kind == BWD);
          ck_assert_rel (fabs (f.V_final), fabs (V), 1e-12);
          chaplygin_fate g = fate (&off, V, W, 100000);
          if (g.kind == FWD || g.kind == BWD)
            ck_assert (tu_relerr (fabs (g.V_final), fabs (V)) > 1e-3);
        }
    }
}
END_TEST

/* Appendix B.2.2: (B.13) gives "a monotone decreasing sequence of
   energy/momentum ratios" leading to the spinning state.  The sequence
   V^2/Omega^2 of chaplygin_discrete_spin_sequence decreases strictly for
   every slot tried, with ratio C2^2 = ((1 - L0^2)/(1 + L0^2))^2,
   L0 = -Delta/2 (reference: that ratio evaluated here; each member is
   within (4 + n |log C2^2|) eps, so the ratio of two within twice that). */
START_TEST (claim_spin_sequence_decreasing)
{
  static const double Delta[] = { 0.3, 1, 1.7, 3, 10 };
  for (size_t i = 0; i < NELEM (Delta); i++)
    {
      double a = Delta[i] * Delta[i] / 4, c2 = (1 - a) / (1 + a), prev;
      ck_assert_ok (chaplygin_discrete_spin_sequence (Delta[i], 0, &prev));
      for (unsigned long n = 1; n < 30; n++)
        {
          double v;
          ck_assert_ok (chaplygin_discrete_spin_sequence (Delta[i], n, &v));
          ck_assert (v < prev);
          ck_assert_rel (v / prev, c2 * c2,
                         2 * (4 + n * fabs (log (c2 * c2))) * DBL_EPSILON);
          prev = v;
        }
    }
}
END_TEST

/* Appendix B.2.2, (B.11): the series (B.10) converges, |C2| < 1, under
   "exactly those [conditions] for asymptotic stability of period-1 fixed
   points (Equation (3.11))"; and for V < 0 under (3.12) (erratum E23: the
   printed (B.11) is garbled; E12: (3.11) and (3.12) read as chains).  On
   a grid of 41 x 9 skates both directions agree. */
START_TEST (claim_convergence_is_stability)
{
  static const double Delta[] = { 0.05, 0.3, 0.8, 1, 1.3, 2, 3.5, 8, 40 };
  for (int i = 0; i <= 40; i++)
    for (size_t j = 0; j < NELEM (Delta); j++)
      {
        double x = -2.5 + 0.0875 * i + 1e-3, D = Delta[j];
        for (int dir = -1; dir <= 1; dir += 2)
          {
            double C1, C2;
            ck_assert_ok (chaplygin_discrete_coefficients (x * D, D,
                                                           dir > 0 ? 0 : D,
                                                           0, &C1, &C2));
            ck_assert_int_eq (fabs (C2) < 1, stable (x * D, D, dir));
          }
      }
}
END_TEST

/* ---- rho = 0: Section 3.1.2 and Appendix B.3 --------------------------- */

/* Section 3.1.2: "For the special case of zero moment of inertia
   (rho = 0), as L0/Delta -> -1 from left or right, sigma4 approaches
   infinity or minus infinity, respectively".  At rho = 0 (slot-length
   units, (B.16)) sigma4 = C2 = L0/(L0 + 1) (exact for the L0 used);
   the rho -> 0 limit of (3.10) (Delta = 10^8 in units of rho) agrees
   with it to 1e-13 (the difference is 1/((x + 1)(1 + (x + 1)^2 Delta^2)),
   below 1e-14 relative for these x). */
START_TEST (claim_massless_sigma4_poles)
{
  for (int k = 10; k <= 40; k += 10)
    {
      double e = ldexp (1, -k), left, right;
      ck_assert_ok (chaplygin_massless_coefficient (-1 - e, 0, 0, &left));
      ck_assert_ok (chaplygin_massless_coefficient (-1 + e, 0, 0, &right));
      ck_assert_eps (left, (1 + e) / e, 2);
      ck_assert_eps (right, -(1 - e) / e, 2);
    }
  static const double x[] = { -3, -1.5, -0.75, -0.25, 0.5 };
  for (size_t i = 0; i < NELEM (x); i++)
    ck_assert_rel (sigma4 (x[i] * 1e8, 1e8, +1), x[i] / (x[i] + 1), 1e-13);
}
END_TEST

/* Section 3.1.2: at rho = 0 "the eigenvalues indicate that period-1
   motions are asymptotically stable for L0/Delta > -1/2": |L0/(L0 + 1)|
   < 1 exactly there; and the library's (3.11) verdict at Delta = 10^8
   (rho -> 0) agrees on both sides. */
START_TEST (claim_massless_stable_ahead_of_centre)
{
  static const double x[] = { -3, -1.5, -0.9, -0.6, -0.5001, -0.4999, -0.3,
                              0.2, 3 };
  for (size_t i = 0; i < NELEM (x); i++)
    {
      double C2;
      ck_assert_ok (chaplygin_massless_coefficient (x[i], 0, 0, &C2));
      ck_assert_int_eq (fabs (C2) < 1, x[i] > -0.5);
      ck_assert_int_eq (stable (x[i] * 1e8, 1e8, +1), x[i] > -0.5);
    }
}
END_TEST

/* Section 3.1.2: at rho = 0 "the existence of period-1 motions requires
   L0 > 0 (so that the skate does not change direction between
   collisions)".  For -1/2 < L0 < 0, where the eigenvalue says stable,
   every forward segment with H != 0 reverses (so no motion stays near a
   straight line); for L0 > 0 none does, over 50 collisions of 100 random
   starts each (chaplygin_massless_step's classification). */
START_TEST (claim_massless_period1_needs_ahead)
{
  tu_rng r;
  tu_rng_seed (&r, 32);
  static const double L0[] = { -0.45, -0.3, -0.05, 0.05, 0.5, 3 };
  for (size_t i = 0; i < NELEM (L0); i++)
    for (int k = 0; k < 100; k++)
      {
        chaplygin_discrete_state st
          = massless_state (L0[i], tu_uniform (&r, 0.01, 2),
                            tu_uniform (&r, 0.01, 2));
        for (int n = 0; n < 50; n++)
          {
            chaplygin_discrete_event ev;
            int dir = st.dir;
            ck_assert_ok (chaplygin_massless_step (L0[i], &st, 0, &st, &ev));
            if (dir > 0)
              ck_assert_int_eq (ev.reversal, L0[i] < 0);
            if (L0[i] > 0)
              ck_assert_int_eq (st.dir, 1);
          }
      }
}
END_TEST

/* Section 3.1.2: "an example of a system with no dissipation but
   exponential stability: ... yet angular momentum eventually decreases to
   zero".  At rho = 0 with L0 = 1/2 the energy is the same bits after each
   of 100 collisions while |H| falls by exactly L0/(L0 + 1) = 1/3 per
   collision (reference: 3^-n; 1.5 ulps per collision). */
START_TEST (claim_massless_lossless_decay)
{
  chaplygin_discrete_state st = massless_state (0.5, 0.8, 1.1);
  double E0 = st.E, H0 = st.H;
  for (int n = 1; n <= 100; n++)
    {
      ck_assert_ok (chaplygin_massless_step (0.5, &st, 0, &st, NULL));
      ck_assert (st.E == E0);
      ck_assert_rel (st.H, H0 * pow (3, -n), 1.5 * n * DBL_EPSILON + 2 * DBL_EPSILON);
    }
}
END_TEST

/* Section 3.1.2, Appendix B.3, Figure 10: "The period-2 motions are always
   just neutrally stable; i.e., the eigenvalues of J^2 ... are (sigma1 = 0,
   sigma2,3,4 = 1)".  At Figure 10's L0 = -2/3 and other masses inside the
   slot: the two-collision Jacobian (chaplygin_massless_jacobian2) has
   eigenvalues 0, 1, 1, 1 (GSL, 1e-10: it is diagonal up to rounding), and,
   by another route, two plain steps return E (bits), H (4 eps) and the
   heading (8 eps absolute). */
START_TEST (claim_massless_period2_neutral)
{
  static const double L0[] = { -2.0 / 3, -0.1, -0.5, -0.93 };
  for (size_t i = 0; i < NELEM (L0); i++)
    {
      chaplygin_discrete_state st = massless_state (L0[i], 1, 0.5), p = st;
      double J[16], re[4];
      ck_assert_ok (chaplygin_massless_jacobian2 (L0[i], &st, J));
      eigenvalues (J, re);
      const double want[4] = { 0, 1, 1, 1 };
      for (int k = 0; k < 4; k++)
        ck_assert (fabs (re[k] - want[k]) < 1e-10);
      unsigned req = CHAPLYGIN_WANT_THETA;
      ck_assert_ok (chaplygin_massless_step (L0[i], &p, req, &p, NULL));
      ck_assert_ok (chaplygin_massless_step (L0[i], &p, req, &p, NULL));
      ck_assert (p.E == st.E && p.dir == st.dir);
      ck_assert_eps (p.H, st.H, 4);
      ck_assert (fabs (p.theta - st.theta) <= 8 * DBL_EPSILON);
    }
}
END_TEST

/* Section 3.1.1 and Appendix B.3: period-2 motions exist "for a point mass
   located behind the front of the slot", for "any E* != 0 and H* != 0",
   with "the velocity along the slot [changing] sign once after each
   collision for L0 < 0": refined (erratum E18).  For -1 < L0 < 0 every
   segment reverses and every state returns after two collisions; behind
   the slot (L0 < -1) backward segments never reverse and after at most
   one reversal |H| falls by (L0 + 1)/L0 per collision, so there are no
   period-2 motions (500 random starts each, 40 collisions). */
START_TEST (claim_massless_period2_where)
{
  tu_rng r;
  tu_rng_seed (&r, 33);
  static const double L0[] = { -0.95, -2.0 / 3, -0.2, -1.5, -4 };
  for (size_t i = 0; i < NELEM (L0); i++)
    {
      int inside = L0[i] > -1, exists;
      ck_assert_ok (chaplygin_massless_period2 (L0[i], &exists));
      ck_assert_int_eq (exists, inside);
      for (int k = 0; k < 500; k++)
        {
          double V = tu_uniform (&r, -2, 2), W = tu_uniform (&r, -2, 2);
          if (V == 0 || W == 0)
            continue;
          chaplygin_discrete_state st = massless_state (L0[i], V, W), s0 = st;
          int reversals = 0;
          for (int n = 1; n <= 40; n++)
            {
              chaplygin_discrete_event ev;
              int dir = st.dir;
              double H = st.H;
              ck_assert_ok (chaplygin_massless_step (L0[i], &st, 0, &st, &ev));
              reversals += ev.reversal;
              if (inside)
                {
                  ck_assert_int_eq (ev.reversal, 1);
                  if (n % 2 == 0)
                    ck_assert_rel (st.H, s0.H, 2.0 * n * DBL_EPSILON);
                }
              else
                {
                  if (dir < 0)
                    ck_assert_int_eq (ev.reversal, 0);
                  if (reversals > 0 && !ev.reversal)
                    ck_assert_rel (fabs (st.H),
                                   fabs (H) * (L0[i] + 1) / L0[i],
                                   4 * DBL_EPSILON);
                }
            }
          if (!inside)
            ck_assert_int_le (reversals, 1);
        }
    }
}
END_TEST

/* Appendix B.3: "No other periodic solutions exist."  Confirmed at rho = 0:
   inside the slot every motion with H != 0 is of period 2 (above); ahead
   of and behind the slot a segment towards the point mass that does not
   reverse raises |H| and one away from it lowers |H|, and a motion
   reverses at most once and then moves away for ever, so |H| is strictly
   monotone before and after the one reversal and no motion with H != 0
   returns (200 collisions of 300 random starts each). */
START_TEST (claim_massless_no_other_periodic)
{
  tu_rng r;
  tu_rng_seed (&r, 34);
  static const double L0[] = { 0.1, 2, -1.2, -6 };
  for (size_t i = 0; i < NELEM (L0); i++)
    {
      int away = L0[i] > 0 ? 1 : -1;   /* the direction away from G */
      for (int k = 0; k < 300; k++)
        {
          double V = tu_uniform (&r, -2, 2), W = tu_uniform (&r, -2, 2);
          if (V == 0 || W == 0)
            continue;
          chaplygin_discrete_state st = massless_state (L0[i], V, W);
          int reversals = 0;
          for (int n = 0; n < 200 && st.H != 0; n++)
            {
              chaplygin_discrete_event ev;
              int dir = st.dir;
              double H = fabs (st.H);
              ck_assert_ok (chaplygin_massless_step (L0[i], &st, 0, &st, &ev));
              reversals += ev.reversal;
              ck_assert_int_le (reversals, 1);
              if (dir == away)
                ck_assert (!ev.reversal && fabs (st.H) < H);
              else if (!ev.reversal)
                ck_assert (fabs (st.H) > H);
            }
        }
    }
}
END_TEST

/* Appendix B.3: "For L0/Delta = -1 and given arbitrary initial conditions,
   the skate stops translating after one collision and spins infinitely
   fast about a peg": contradicted (erratum E19).  Exactly at L0 = -1 the
   map has no next state after the first reversal (CHAPLYGIN_ESPIN); as
   L0 -> -1 the angular rate after the collision grows like 1/(L0 + 1) but
   the speed along the slot keeps its size (|V-| = |V+| here: the point
   mass moves on its line at constant speed) and the motion stays of
   period 2. */
START_TEST (claim_massless_minus_one)
{
  chaplygin_discrete_state st = massless_state (-1, 1, 0.5);
  ck_assert_status (chaplygin_massless_step (-1, &st, 0, &st, NULL),
                    CHAPLYGIN_ESPIN);
  double prev_rate = 0;
  for (int k = 10; k <= 40; k += 10)
    {
      double L0 = -1 + ldexp (1, -k), W;
      chaplygin_discrete_state s = massless_state (L0, 1, 0.5), s0 = s;
      chaplygin_discrete_event ev;
      ck_assert_ok (chaplygin_massless_step (L0, &s, 0, &s, &ev));
      ck_assert_ok (chaplygin_massless_omega (L0, s.dir > 0 ? 0 : 1, s.H, &W));
      /* the angular rate grows like 2^k */
      ck_assert (fabs (W) > prev_rate * 512);
      prev_rate = fabs (W);
      ck_assert (fabs (ev.Vminus) > 0.5);
      ck_assert_ok (chaplygin_massless_step (L0, &s, 0, &s, &ev));
      ck_assert (s.E == s0.E);
      ck_assert_rel (s.H, s0.H, 8 * DBL_EPSILON);
    }
}
END_TEST

/* Appendix B.3, Figure 10's caption: at rho = 0 "the mass center must
   travel in a straight line at constant velocity", and "no energy is lost
   at collisions".  Figure 10's skate (L0 = -2/3, V+ = 1, Omega+ = 1/2):
   the mass centre after each of 60 collisions lies on the line through
   the first two positions (1e-12 of the distance travelled), at a distance
   proportional to the elapsed time (speed sqrt(2E)), and E keeps its
   bits. */
START_TEST (claim_massless_straight_line)
{
  const double L0 = -2.0 / 3;
  chaplygin_discrete_state st = massless_state (L0, 1, 0.5);
  double G0[2], G1[2], E0 = st.E, tau0 = st.tau;
  ck_assert_ok (chaplygin_massless_mass_centre (L0, &st, G0));
  ck_assert_ok (chaplygin_massless_step (L0, &st, CHAPLYGIN_WANT_ALL, &st, NULL));
  ck_assert_ok (chaplygin_massless_mass_centre (L0, &st, G1));
  double ux = G1[0] - G0[0], uy = G1[1] - G0[1], len = hypot (ux, uy);
  ux /= len;
  uy /= len;
  for (int n = 2; n <= 60; n++)
    {
      double G[2];
      ck_assert_ok (chaplygin_massless_step (L0, &st, CHAPLYGIN_WANT_ALL, &st,
                                             NULL));
      ck_assert (st.E == E0);
      ck_assert_ok (chaplygin_massless_mass_centre (L0, &st, G));
      double dx = G[0] - G0[0], dy = G[1] - G0[1], dist = hypot (dx, dy);
      ck_assert (fabs (dx * uy - dy * ux) <= 1e-12 * dist);
      ck_assert_rel (dist, sqrt (2 * E0) * (st.tau - tau0), 1e-12);
    }
}
END_TEST

/* Appendix B.3: "For rho small but nonzero, however, numerical studies
   show that quasi-periodic motions exist closely resembling those in
   Figure 10; after many collisions and looping motions, the skate
   eventually settles into a straight-line motion."  Confirmed: Figure 10's
   start (L0/Delta = -2/3, V+ = 1, Omega+ = 1/2 in slot units) with
   (rho/delta)^2 = 1/Delta^2 = 1/900 and 1/10^4 reverses at every
   collision, as at rho = 0, and |H| returns after two collisions up to the
   factor C2 C2' = (1 + L0 l1)^2/((1 + L0^2)(1 + l1^2)) of (B.4)
   (reference: that product evaluated here in long double, 8 eps a
   collision), which is 1 - 1/(x^2 (x + 1)^2 Delta^2) + O(Delta^-4),
   1 - 81/(4 Delta^2) here; so the motion flips for more than
   4 Delta^2/81 collisions (109 and 2379 measured) and then goes backward
   for ever (plain iteration of the map: no reversal in the next 1000
   collisions). */
START_TEST (claim_small_rho_settles)
{
  static const double Delta[] = { 30, 100 };
  for (size_t i = 0; i < NELEM (Delta); i++)
    {
      double D = Delta[i], x = -2.0 / 3, L0 = x * D;
      chaplygin_discrete sys = skate (L0, D);
      chaplygin_fate f = fate (&sys, 1, 0.5 / D, 10000000);
      ck_assert_int_eq (f.kind, BWD);
      ck_assert_uint_eq (f.reversals, f.collisions);
      ck_assert (f.collisions > 4 * D * D / 81);
      long double l0 = L0, l1 = (long double) L0 + D;
      long double c22 = (1 + l0 * l1) * (1 + l0 * l1)
                        / ((1 + l0 * l0) * (1 + l1 * l1));
      ck_assert (fabsl (c22 - (1 - 1 / (x * x * (x + 1) * (x + 1) * D * D)))
                 < 2 * 227.8 / (D * D * D * D));
      chaplygin_discrete_state st = state (&sys, 1, 0.5 / D);
      double H0 = st.H;
      for (unsigned long n = 1; n <= f.collisions; n++)
        {
          ck_assert_uint_eq (reversals_in (&sys, &st, 1), 1);
          if (n % 2 == 0 && n <= 200)
            {
              ck_assert_rel (st.H, (double) (H0 * c22), 8 * DBL_EPSILON);
              H0 = st.H;
            }
        }
      ck_assert_uint_eq (reversals_in (&sys, &st, 1000), 0);
      ck_assert_int_eq (st.dir, -1);
    }
}
END_TEST

/* ---- main ------------------------------------------------------------- */

static const char *const registry[] = { CLAIM_CHECKS };
static const char *registered[NELEM (registry) + 64];
static size_t n_registered;

void
claim_case (Suite *s, const char *name, const TTest *test)
{
  if (n_registered < NELEM (registered))
    registered[n_registered] = name;
  n_registered++;
  tu_add (s, name, test);
}

static void
claims_stability_cases (Suite *s)
{
  claim_case (s, "claim_stable_ahead_of_centre", claim_stable_ahead_of_centre);
  claim_case (s, "claim_unstable_behind_slot", claim_unstable_behind_slot);
  claim_case (s, "claim_rear_half_depends_on_size",
              claim_rear_half_depends_on_size);
  claim_case (s, "claim_bistable_within_slot", claim_bistable_within_slot);
  claim_case (s, "claim_reflection_symmetry", claim_reflection_symmetry);
  claim_case (s, "claim_jacobian_eigenvalues", claim_jacobian_eigenvalues);
  claim_case (s, "claim_collisions_lose_energy", claim_collisions_lose_energy);
  claim_case (s, "claim_spin_within_slot", claim_spin_within_slot);
  claim_case (s, "claim_spin_saddle", claim_spin_saddle);
  claim_case (s, "claim_xi4_smooth_limit", claim_xi4_smooth_limit);
  claim_case (s, "claim_broader_than_smooth", claim_broader_than_smooth);
  claim_case (s, "claim_period1_family", claim_period1_family);
  claim_case (s, "claim_velocity_scaling", claim_velocity_scaling);
  claim_case (s, "claim_smooth_exponential_momentum",
              claim_smooth_exponential_momentum);
  claim_case (s, "claim_almost_all_straight", claim_almost_all_straight);
  claim_case (s, "claim_no_reversal_ahead_forward",
              claim_no_reversal_ahead_forward);
  claim_case (s, "claim_multiple_reversals_in_slot",
              claim_multiple_reversals_in_slot);
  claim_case (s, "claim_no_reversal_above_one", claim_no_reversal_above_one);
  claim_case (s, "claim_basins_alternate", claim_basins_alternate);
  claim_case (s, "claim_figure3_threshold", claim_figure3_threshold);
  claim_case (s, "claim_figure3_symmetric", claim_figure3_symmetric);
  claim_case (s, "claim_other_angular_velocities",
              claim_other_angular_velocities);
  claim_case (s, "claim_symmetric_final_speed", claim_symmetric_final_speed);
  claim_case (s, "claim_spin_sequence_decreasing",
              claim_spin_sequence_decreasing);
  claim_case (s, "claim_convergence_is_stability",
              claim_convergence_is_stability);
  claim_case (s, "claim_massless_sigma4_poles", claim_massless_sigma4_poles);
  claim_case (s, "claim_massless_stable_ahead_of_centre",
              claim_massless_stable_ahead_of_centre);
  claim_case (s, "claim_massless_period1_needs_ahead",
              claim_massless_period1_needs_ahead);
  claim_case (s, "claim_massless_lossless_decay",
              claim_massless_lossless_decay);
  claim_case (s, "claim_massless_period2_neutral",
              claim_massless_period2_neutral);
  claim_case (s, "claim_massless_period2_where", claim_massless_period2_where);
  claim_case (s, "claim_massless_no_other_periodic",
              claim_massless_no_other_periodic);
  claim_case (s, "claim_massless_minus_one", claim_massless_minus_one);
  claim_case (s, "claim_massless_straight_line", claim_massless_straight_line);
  claim_case (s, "claim_small_rho_settles", claim_small_rho_settles);
}

/* 1 if NAME is among the first N of LIST. */
static int
listed (const char *name, const char *const *list, size_t n)
{
  for (size_t i = 0; i < n; i++)
    if (strcmp (list[i], name) == 0)
      return 1;
  return 0;
}

/* The registered checks are the registry's, each once. */
static int
registry_matches (void)
{
  int ok = n_registered <= NELEM (registered);
  size_t n = ok ? n_registered : NELEM (registered);
  for (size_t i = 0; i < NELEM (registry); i++)
    if (!listed (registry[i], registered, n))
      {
        fprintf (stderr, "test_claims: doc/claims.txt names %s, which no "
                 "check registers\n", registry[i]);
        ok = 0;
      }
  for (size_t i = 0; i < n; i++)
    if (!listed (registered[i], registry, NELEM (registry))
        || listed (registered[i], registered, i))
      {
        fprintf (stderr, "test_claims: %s is registered twice or is not in "
                 "doc/claims.txt\n", registered[i]);
        ok = 0;
      }
  return ok;
}

int
main (void)
{
  Suite *s = suite_create ("claims");
  claims_stability_cases (s);
  claims_motion_cases (s);
  if (!registry_matches ())
    return 99;   /* a hard error for the test driver */
  return tu_run (s);
}
