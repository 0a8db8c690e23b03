/* test_smooth.c -- lib/smooth.c: Section 2 and Appendix A, the smooth
   Chaplygin sleigh. */
#include <config.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>
#include <stdlib.h>
#include <string.h>

#include "internal.h"
#include "ref_smooth.h"
#include "testutil.h"

#define NREF (sizeof ref_smooth / sizeof ref_smooth[0])

/* ---- an integrator of (2.1) written out here, independent of lib/ ------
   y = {x, V, theta, Omega, sigma}: x the signed displacement of C (dx/dtau
   = V), sigma the arc length (dsigma/dtau = |V|). */
static int
rhs21 (double t, const double y[], double f[], void *p)
{
  (void) t;
  double L = *(double *) p;
  f[0] = y[1];
  f[1] = L * y[3] * y[3];
  f[2] = y[3];
  f[3] = -L / (1.0 + L * L) * y[1] * y[3];
  f[4] = fabs (y[1]);
  return GSL_SUCCESS;
}

/* The same with sigma as independent variable (Henon's trick), for landing
   exactly on a given arc length: y = {x, V, theta, Omega, tau}. */
static int
rhs21_sigma (double s, const double y[], double f[], void *p)
{
  (void) s;
  double g[5], yy[5] = { y[0], y[1], y[2], y[3], s };
  rhs21 (0.0, yy, g, p);
  double iv = 1.0 / fabs (y[1]);
  f[0] = g[0] * iv;
  f[1] = g[1] * iv;
  f[2] = g[2] * iv;
  f[3] = g[3] * iv;
  f[4] = iv;
  return GSL_SUCCESS;
}

/* State at arc length sigma (> 0) from (V0, Omega0), by rk8pd at tol. */
static void
ode_at_arclength (double L, double V0, double Om0, double sigma, double tol,
                  double *V, double *Om, double *dtheta, double *dtau)
{
  gsl_odeiv2_system sys = { rhs21, NULL, 5, &L };
  gsl_odeiv2_system sys_s = { rhs21_sigma, NULL, 5, &L };
  gsl_odeiv2_step *st = gsl_odeiv2_step_alloc (gsl_odeiv2_step_rk8pd, 5);
  gsl_odeiv2_control *c = gsl_odeiv2_control_standard_new (tol * 1e-3, tol, 1, 0);
  gsl_odeiv2_evolve *ev = gsl_odeiv2_evolve_alloc (5);
  double y[5] = { 0, V0, 0, Om0, 0 }, t = 0, h = 1e-3;
  for (int n = 0; n < 1000000; n++)
    {
      double ya[5], ta = t;
      for (int i = 0; i < 5; i++)
        ya[i] = y[i];
      /* steps no longer than 0.05 so that a step never straddles both a
         reversal and the target arc length */
      ck_assert_int_eq (gsl_odeiv2_evolve_apply (ev, c, st, &sys, &t, t + 0.05, &h, y),
                        GSL_SUCCESS);
      if (y[4] >= sigma)
        {
          double s = ya[4], z[5] = { ya[0], ya[1], ya[2], ya[3], ta }, hs = sigma - s;
          gsl_odeiv2_evolve_reset (ev);
          while (s < sigma)
            ck_assert_int_eq (gsl_odeiv2_evolve_apply (ev, c, st, &sys_s, &s, sigma, &hs, z),
                              GSL_SUCCESS);
          *V = z[1], *Om = z[3], *dtheta = z[2], *dtau = z[4];
          break;
        }
    }
  gsl_odeiv2_evolve_free (ev);
  gsl_odeiv2_control_free (c);
  gsl_odeiv2_step_free (st);
}

START_TEST (eq_2_1)
{
  /* Route: Newton-Euler for a rigid body with a skate at C: unknowns
     (dv/dt, domega/dt, F), equations m a_G = F e_n and I domega/dt =
     (C - G) x F e_n, with a_G = a_C + alpha x r - omega^2 r (r = G - C),
     a_C = dv/dt e_lambda + v omega e_n (C moves along the turning skate).
     The residuals are linear in the unknowns; the 3x3 system is assembled
     numerically and solved by Cramer's rule, then scaled by (2.2). */
  tu_rng r;
  tu_rng_seed (&r, 21);
  for (int k = 0; k < 1000; k++)
    {
      double m = tu_uniform (&r, 0.5, 4), I = tu_uniform (&r, 0.1, 3);
      double rho = sqrt (I / m), v0 = tu_uniform (&r, 0.5, 2);
      double ell = tu_uniform (&r, -2, 2), v = tu_uniform (&r, -2, 2);
      double th = tu_uniform (&r, -3, 3), om = tu_uniform (&r, -3, 3);
      double el[2] = { cos (th), sin (th) }, en[2] = { -el[1], el[0] };
      double rv[2] = { ell * el[0], ell * el[1] };     /* G - C */
      double A[3][3], b[3];
      for (int col = -1; col < 3; col++)
        {
          double u[3] = { 0, 0, 0 };
          if (col >= 0)
            u[col] = 1;
          double vdot = u[0], omdot = u[1], F = u[2];
          double aC[2] = { vdot * el[0] + v * om * en[0], vdot * el[1] + v * om * en[1] };
          double aG[2] = { aC[0] - omdot * rv[1] - om * om * rv[0],
                           aC[1] + omdot * rv[0] - om * om * rv[1] };
          double R[3];
          R[0] = m * aG[0] - F * en[0];
          R[1] = m * aG[1] - F * en[1];
          R[2] = I * omdot - ((-rv[0]) * F * en[1] - (-rv[1]) * F * en[0]);
          for (int i = 0; i < 3; i++)
            {
              if (col < 0)
                b[i] = R[i];
              else
                A[i][col] = R[i];
            }
        }
      for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
          A[i][j] -= b[i];
      double det = A[0][0] * (A[1][1] * A[2][2] - A[1][2] * A[2][1])
        - A[0][1] * (A[1][0] * A[2][2] - A[1][2] * A[2][0])
        + A[0][2] * (A[1][0] * A[2][1] - A[1][1] * A[2][0]);
      double x[3];
      for (int c = 0; c < 3; c++)
        {
          double B[3][3];
          for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
              B[i][j] = (j == c) ? -b[i] : A[i][j];
          x[c] = (B[0][0] * (B[1][1] * B[2][2] - B[1][2] * B[2][1])
                  - B[0][1] * (B[1][0] * B[2][2] - B[1][2] * B[2][0])
                  + B[0][2] * (B[1][0] * B[2][1] - B[1][1] * B[2][0])) / det;
        }
      double L = ell / rho, V = v / v0, Om = om * rho / v0;
      double q[4] = { 0.0, V, th, Om }, f[4];
      ck_assert_ok (chaplygin_smooth_field (L, q, f));
      ck_assert (f[CHAPLYGIN_S] == fabs (V));   /* arc length: |V| (erratum E1) */
      ck_assert (f[CHAPLYGIN_THETA] == Om);
      double s2 = rho / (v0 * v0);
      double scale = (v * v + ell * ell * om * om + fabs (v * om * ell)) * s2 + 1e-300;
      ck_assert_msg (fabs (f[CHAPLYGIN_V] - x[0] * s2) <= 1e-12 * scale,
                     "dV/dtau %.17g vs Newton-Euler %.17g", f[CHAPLYGIN_V], x[0] * s2);
      ck_assert_msg (fabs (f[CHAPLYGIN_OMEGA] - x[1] * s2 * rho) <= 1e-12 * scale * (1 + rho),
                     "dOmega/dtau %.17g vs Newton-Euler %.17g", f[CHAPLYGIN_OMEGA],
                     x[1] * s2 * rho);
    }
  double q[4] = { 0, 1, 0, 1 }, f[4];
  ck_assert_status (chaplygin_smooth_field (NAN, q, f), CHAPLYGIN_EDOM);
  q[2] = INFINITY;
  ck_assert_status (chaplygin_smooth_field (1.0, q, f), CHAPLYGIN_EDOM);
  q[2] = 0, q[3] = 1e200;
  ck_assert_status (chaplygin_smooth_field (1.0, q, f), CHAPLYGIN_ERANGE);
  ck_assert_status (chaplygin_smooth_field (1.0, NULL, f), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_smooth_field (1.0, q, NULL), CHAPLYGIN_EINVAL);
}
END_TEST

START_TEST (eq_2_4)
{
  /* Route: the steady solution is a rest point of (2.1) in (V, theta,
     Omega); the Jacobian of the field there, by central differences
     (step 1e-6, error O(h^2) ~ 1e-12 relative), is triangular with
     eigenvalues 0, 0, 0 and trace = xi4. */
  double L = -0.8125, Vs = 1.375, q[4], E, H, xi4;
  ck_assert_ok (chaplygin_smooth_steady (Vs, 0.3, 2.0, q, &E, &H));
  ck_assert (q[CHAPLYGIN_S] == 2.75 && q[CHAPLYGIN_V] == Vs
             && q[CHAPLYGIN_THETA] == 0.3 && q[CHAPLYGIN_OMEGA] == 0.0);
  ck_assert (E == 0.5 * Vs * Vs && H == 0.0);
  double f[4];
  ck_assert_ok (chaplygin_smooth_field (L, q, f));
  ck_assert (f[CHAPLYGIN_V] == 0.0 && f[CHAPLYGIN_THETA] == 0.0 && f[CHAPLYGIN_OMEGA] == 0.0);
  double J[4][4], h = 1e-6;
  for (int j = 0; j < 4; j++)
    {
      double qp[4], qm[4], fp[4], fm[4];
      for (int i = 0; i < 4; i++)
        qp[i] = qm[i] = q[i];
      qp[j] += h, qm[j] -= h;
      ck_assert_ok (chaplygin_smooth_field (L, qp, fp));
      ck_assert_ok (chaplygin_smooth_field (L, qm, fm));
      for (int i = 0; i < 4; i++)
        J[i][j] = (fp[i] - fm[i]) / (2 * h);
    }
  /* below-diagonal entries vanish: eigenvalues are the diagonal */
  for (int i = 0; i < 4; i++)
    for (int j = 0; j < i; j++)
      ck_assert_msg (fabs (J[i][j]) < 1e-9, "J[%d][%d] = %g", i, j, J[i][j]);
  ck_assert_ok (chaplygin_smooth_eigenvalue (L, Vs, &xi4));
  ck_assert (fabs (J[0][0]) < 1e-9 && fabs (J[1][1]) < 1e-9 && fabs (J[2][2]) < 1e-9);
  ck_assert_rel (J[3][3], xi4, 1e-9);
  /* and it is -L V* / (1 + L^2): stable for L > 0 (V* > 0), unstable L < 0 */
  ck_assert (xi4 > 0.0);
  ck_assert_ok (chaplygin_smooth_eigenvalue (-L, Vs, &xi4));
  ck_assert (xi4 < 0.0);
  /* Large L: 1/(L + 1/L) */
  ck_assert_ok (chaplygin_smooth_eigenvalue (1e200, 2.0, &xi4));
  ck_assert_rel (xi4, -2e-200, 2 * DBL_EPSILON);
  ck_assert_status (chaplygin_smooth_eigenvalue (NAN, 1.0, &xi4), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_smooth_eigenvalue (1.0, 1.0, NULL), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_smooth_steady (NAN, 0, 0, q, &E, &H), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_smooth_steady (1e300, 0, 1e300, q, &E, &H), CHAPLYGIN_ERANGE);
  ck_assert_status (chaplygin_smooth_steady (1, 0, 0, NULL, &E, &H), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_smooth_steady (1, 0, 0, q, NULL, &H), CHAPLYGIN_EINVAL);
}
END_TEST

/* The paper's (A.2) exponent with its K, as printed (K = -1 beyond S_c):
   Omega = Omega0 exp(-K a (S - S0)). */
static double
printed_omega (double L, double Om0, double sigma, int K)
{
  return Om0 * exp (-K * L / (1 + L * L) * sigma);
}

START_TEST (eq_A_1)
{
  /* Route: integrate (2.1) (written out in this file) to the first zero of
     V: the arc length there is S_c.  Fig. 8's set-up, and a backward start
     with L > 0, which the printed formula gets wrong (erratum E3). */
  const double cases[][3] = { { -1.4142135623730951, 1.0, 0.1 },
                              { 2.385, -0.7, 0.4 }, { -0.5, 2.0, -0.75 } };
  for (int k = 0; k < 3; k++)
    {
      double L = cases[k][0], V0 = cases[k][1], Om0 = cases[k][2];
      double q0[4] = { 1.5, V0, 0.0, Om0 }, Sc;
      int rev;
      ck_assert_ok (chaplygin_smooth_reversal (L, q0, &rev, &Sc));
      ck_assert_int_eq (rev, 1);
      /* V changes sign at sigma = Sc - 1.5: just before it V has the sign
         of V0, just after the opposite, by the integration */
      double V, Om, th, tau;
      ode_at_arclength (L, V0, Om0, Sc - 1.5 - 1e-4, 1e-12, &V, &Om, &th, &tau);
      ck_assert (V * V0 > 0.0);
      ode_at_arclength (L, V0, Om0, Sc - 1.5 + 1e-4, 1e-12, &V, &Om, &th, &tau);
      ck_assert (V * V0 < 0.0);
      /* As printed, S_c = S0 - (1 + L^2)/(2L) log(...): right for V0 > 0,
         on the wrong side of S0 for V0 < 0. */
      double printed = 1.5 - (1 + L * L) / (2 * L)
        * log (1 + V0 * V0 / (Om0 * Om0 * (1 + L * L)));
      if (V0 > 0)
        ck_assert_rel (printed, Sc, 4 * DBL_EPSILON);
      else
        ck_assert (printed < 1.5 && Sc > 1.5);
    }
  /* no reversal: L V0 > 0, Omega0 = 0, or V0 = 0 */
  double q0[4] = { 0, 1, 0, 0.5 }, Sc = -7;
  int rev = -1;
  ck_assert_ok (chaplygin_smooth_reversal (1.0, q0, &rev, &Sc));
  ck_assert (rev == 0 && Sc == -7);
  q0[3] = 0.0;
  ck_assert_ok (chaplygin_smooth_reversal (-1.0, q0, &rev, &Sc));
  ck_assert (rev == 0);
  q0[1] = 0.0, q0[3] = 1.0;
  ck_assert_ok (chaplygin_smooth_reversal (-1.0, q0, &rev, &Sc));
  ck_assert (rev == 0);
  /* L V0 underflows: the signs decide, not the product */
  double qu[4] = { 0, -1e-200, 0, 1 };
  int K;
  ck_assert_ok (chaplygin_smooth_reversal (1e-200, qu, &rev, &Sc));
  ck_assert_ok (chaplygin_smooth_branch (1e-200, qu, 1e300, &K));
  ck_assert (rev == 1 && K == -1);
  /* a huge V0/Omega0: the logarithm is formed without overflow */
  double q1[4] = { 0, 1e200, 0, 1e-200 };
  ck_assert_ok (chaplygin_smooth_reversal (-1.0, q1, &rev, &Sc));
  ck_assert_rel (Sc, 2.0 / 2 * (2 * (log (1e200) - log (1e-200 * sqrt (2.0)))), 1e-15);
  double q2[4] = { 0, 1e10, 0, 1e-10 };   /* log1p(1e40)/(2e-307) overflows */
  ck_assert_status (chaplygin_smooth_reversal (-1e-307, q2, &rev, &Sc), CHAPLYGIN_ERANGE);
  ck_assert_status (chaplygin_smooth_reversal (NAN, q2, &rev, &Sc), CHAPLYGIN_EDOM);
  q2[0] = INFINITY;
  ck_assert_status (chaplygin_smooth_reversal (1, q2, &rev, &Sc), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_smooth_reversal (1, NULL, &rev, &Sc), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_smooth_reversal (1, q0, NULL, &Sc), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_smooth_reversal (1, q0, &rev, NULL), CHAPLYGIN_EINVAL);
}
END_TEST

START_TEST (eq_A_2_reference)
{
  /* Route: mpmath's Taylor-series ODE solver at 30 digits
     (tests/ref/make_refs.py).  The closed form is a handful of exp, expm1,
     log1p, atan, sqrt of well-conditioned arguments; 16 eps. */
  const int i = _i;
  double q0[4] = { 0.0, ref_smooth[i].V0, 0.0, ref_smooth[i].Omega0 }, q[4], tau;
  ck_assert_ok (chaplygin_smooth_closed_form (ref_smooth[i].L, q0, ref_smooth[i].sigma,
                                              q, &tau));
  ck_assert (q[CHAPLYGIN_S] == ref_smooth[i].sigma);
  ck_assert_rel (q[CHAPLYGIN_V], ref_smooth[i].V, 16 * DBL_EPSILON);
  ck_assert_rel (q[CHAPLYGIN_OMEGA], ref_smooth[i].Omega, 16 * DBL_EPSILON);
  ck_assert_rel (q[CHAPLYGIN_THETA], ref_smooth[i].dtheta, 16 * DBL_EPSILON);
  ck_assert_rel (tau, ref_smooth[i].dtau, 16 * DBL_EPSILON);
}
END_TEST

START_TEST (eq_A_2)
{
  /* Route: rk8pd on (2.1) in this file at tol 1e-13, landing on the arc
     length exactly; randomized, reversals included (L V0 < 0 half the
     time), arc lengths up to well past S_c.  The integration's global
     error is ~1e-11; 1e-9 relative (absolute where the value is < 1). */
  tu_rng r;
  tu_rng_seed (&r, 2002);
  int reversals = 0;
  for (int k = 0; k < 60; k++)
    {
      double L = tu_uniform (&r, -3, 3), V0 = tu_uniform (&r, -2, 2);
      double Om0 = tu_uniform (&r, -2, 2), sigma = tu_uniform (&r, 0.1, 8);
      double q0[4] = { 0.25, V0, 0.5, Om0 }, q[4], tau, Sc;
      int rev;
      ck_assert_ok (chaplygin_smooth_reversal (L, q0, &rev, &Sc));
      if (rev && fabs (Sc - 0.25 - sigma) < 0.1)
        continue;               /* the target too near the reversal cusp */
      if (rev && Sc - 0.25 < sigma)
        reversals++;
      ck_assert_ok (chaplygin_smooth_closed_form (L, q0, 0.25 + sigma, q, &tau));
      double V, Om, th, ta;
      ode_at_arclength (L, V0, Om0, sigma, 1e-13, &V, &Om, &th, &ta);
      ck_assert_msg (fabs (q[CHAPLYGIN_V] - V) <= 1e-9 * fmax (1, fabs (V)), "V %.17g ode %.17g", q[1], V);
      ck_assert_msg (fabs (q[CHAPLYGIN_OMEGA] - Om) <= 1e-9 * fmax (1, fabs (Om)), "Om %.17g ode %.17g", q[3], Om);
      ck_assert_msg (fabs (q[CHAPLYGIN_THETA] - 0.5 - th) <= 1e-9 * fmax (1, fabs (th)), "th %.17g ode %.17g", q[2] - 0.5, th);
      ck_assert_msg (fabs (tau - ta) <= 1e-9 * fmax (1, ta), "tau %.17g ode %.17g", tau, ta);
    }
  ck_assert_int_ge (reversals, 10);
}
END_TEST

START_TEST (eq_A_2_erratum)
{
  /* Erratum E5: the printed K = -1 branch, Omega0 exp(+a (S - S0)), is
     discontinuous at S_c and disagrees with the motion; the corrected
     branch is continuous and agrees.  L = -sqrt(2), V0 = 1, Omega0 = 0.1. */
  double L = -1.4142135623730951, q0[4] = { 0, 1.0, 0, 0.1 }, Sc, q[4];
  int rev;
  ck_assert_ok (chaplygin_smooth_reversal (L, q0, &rev, &Sc));
  double left = printed_omega (L, 0.1, Sc, 1), right = printed_omega (L, 0.1, Sc, -1);
  ck_assert_msg (fabs (left - 0.586) < 1e-3 && fabs (right - 0.0171) < 1e-4,
                 "printed branch at S_c: %g | %g", left, right);
  /* the library is continuous there */
  double qa[4], qb[4];
  ck_assert_ok (chaplygin_smooth_closed_form (L, q0, Sc * (1 - 1e-12), qa, NULL));
  ck_assert_ok (chaplygin_smooth_closed_form (L, q0, Sc * (1 + 1e-12), qb, NULL));
  ck_assert_rel (qa[CHAPLYGIN_OMEGA], qb[CHAPLYGIN_OMEGA], 1e-10);
  ck_assert_rel (qa[CHAPLYGIN_OMEGA], left, 1e-10);
  ck_assert (fabs (qa[CHAPLYGIN_V]) < 1e-5 && fabs (qb[CHAPLYGIN_V]) < 1e-5);
  ck_assert (qa[CHAPLYGIN_V] > 0 && qb[CHAPLYGIN_V] < 0);
  /* 2 past S_c: the motion (integration) against both branches */
  double V, Om, th, ta;
  ode_at_arclength (L, 1.0, 0.1, Sc + 2.0, 1e-13, &V, &Om, &th, &ta);
  ck_assert_ok (chaplygin_smooth_closed_form (L, q0, Sc + 2.0, q, NULL));
  ck_assert_rel (q[CHAPLYGIN_OMEGA], Om, 1e-9);
  ck_assert (fabs (printed_omega (L, 0.1, Sc + 2.0, -1) - Om) > 0.05);
}
END_TEST

START_TEST (eq_A_2_special)
{
  /* L = 0: the circle, V and Omega constant, theta = theta0 + Omega0 S/|V0|.
     Omega0 = 0: the straight line.  Small L joins L = 0 continuously:
     the expm1/atan forms keep full accuracy (differences O(L)). */
  double q0[4] = { 0, -1.25, 0.5, 0.75 }, q[4], tau;
  ck_assert_ok (chaplygin_smooth_closed_form (0.0, q0, 2.0, q, &tau));
  ck_assert (q[CHAPLYGIN_V] == -1.25 && q[CHAPLYGIN_OMEGA] == 0.75);
  ck_assert_rel (tau, 1.6, DBL_EPSILON);
  ck_assert_rel (q[CHAPLYGIN_THETA], 0.5 + 0.75 * 1.6, DBL_EPSILON);
  double qs[4];
  ck_assert_ok (chaplygin_smooth_closed_form (1e-9, q0, 2.0, qs, &tau));
  ck_assert_rel (qs[CHAPLYGIN_THETA], q[CHAPLYGIN_THETA], 1e-8);
  ck_assert_rel (tau, 1.6, 1e-8);
  ck_assert_ok (chaplygin_smooth_closed_form (1e-300, q0, 2.0, qs, &tau));
  ck_assert_rel (qs[CHAPLYGIN_THETA], q[CHAPLYGIN_THETA], 4 * DBL_EPSILON);
  double ql[4] = { 1, 2, 0, 0 };
  ck_assert_ok (chaplygin_smooth_closed_form (-3.0, ql, 5.0, q, &tau));
  ck_assert (q[CHAPLYGIN_V] == 2 && q[CHAPLYGIN_OMEGA] == 0 && q[CHAPLYGIN_THETA] == 0);
  ck_assert (tau == 2.0);
  /* S = S0 */
  ck_assert_ok (chaplygin_smooth_closed_form (-3.0, q0, 0.0, q, &tau));
  ck_assert (q[CHAPLYGIN_V] == q0[1] && tau == 0.0);
  /* V0 = 0: starts at a turning point, moves in the direction of sgn(L),
     no reversal; the integration agrees */
  double qz[4] = { 0, 0, 0, 0.8 }, V, Om, th, ta;
  ck_assert_ok (chaplygin_smooth_closed_form (-0.7, qz, 1.5, q, &tau));
  ode_at_arclength (-0.7, 0.0, 0.8, 1.5, 1e-13, &V, &Om, &th, &ta);
  ck_assert (q[CHAPLYGIN_V] < 0);
  ck_assert_rel (q[CHAPLYGIN_V], V, 1e-9);
  ck_assert_rel (q[CHAPLYGIN_THETA], th, 1e-9);
  ck_assert_rel (tau, ta, 1e-9);
  /* Errors: at rest or spinning in place cannot advance in S. */
  double rest[4] = { 0, 0, 0, 0 }, spin[4] = { 0, 0, 0, 1 };
  ck_assert_status (chaplygin_smooth_closed_form (1.0, rest, 1.0, q, &tau), CHAPLYGIN_ESTATE);
  ck_assert_status (chaplygin_smooth_closed_form (0.0, spin, 1.0, q, &tau), CHAPLYGIN_ESTATE);
  ck_assert_status (chaplygin_smooth_closed_form (1.0, q0, -1.0, q, &tau), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_smooth_closed_form (NAN, q0, 1.0, q, &tau), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_smooth_closed_form (1.0, q0, INFINITY, q, &tau), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_smooth_closed_form (1.0, NULL, 1.0, q, &tau), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_smooth_closed_form (1.0, q0, 1.0, NULL, &tau), CHAPLYGIN_EINVAL);
  double big[4] = { 0, 1e300, 0, 1e-300 };
  ck_assert_status (chaplygin_smooth_closed_form (1e-300, big, 1e300, q, &tau), CHAPLYGIN_ERANGE);
  /* dtau may be NULL */
  ck_assert_ok (chaplygin_smooth_closed_form (1.0, q0, 1.0, q, NULL));
}
END_TEST

START_TEST (eq_A_3)
{
  /* K = sgn(V(S)/V0): +1 before S_c (and at it), -1 after; +1 throughout
     when there is no reversal.  Checked against the sign of V from the
     closed form and from the integration. */
  double L = -1.0, q0[4] = { 0, 1, 0, 0.5 }, Sc;
  int rev, K;
  ck_assert_ok (chaplygin_smooth_reversal (L, q0, &rev, &Sc));
  ck_assert_ok (chaplygin_smooth_branch (L, q0, Sc * 0.5, &K));
  ck_assert_int_eq (K, 1);
  ck_assert_ok (chaplygin_smooth_branch (L, q0, Sc, &K));
  ck_assert_int_eq (K, 1);
  ck_assert_ok (chaplygin_smooth_branch (L, q0, Sc * 1.5, &K));
  ck_assert_int_eq (K, -1);
  double V, Om, th, ta;
  ode_at_arclength (L, 1, 0.5, Sc * 1.5, 1e-12, &V, &Om, &th, &ta);
  ck_assert (V < 0);
  ck_assert_ok (chaplygin_smooth_branch (1.0, q0, 10.0, &K));
  ck_assert_int_eq (K, 1);
  ck_assert_status (chaplygin_smooth_branch (1.0, q0, -1.0, &K), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_smooth_branch (1.0, q0, 1.0, NULL), CHAPLYGIN_EINVAL);
  double rest[4] = { 0, 0, 0, 0 };
  ck_assert_status (chaplygin_smooth_branch (1.0, rest, 1.0, &K), CHAPLYGIN_ESTATE);
}
END_TEST

START_TEST (eq_A_4)
{
  /* Route 1: the (E, H) form agrees with the phase form through
     E = [V^2 + (1 + L^2) Omega^2]/2, H_C = (1 + L^2) Omega, and E is
     returned exactly conserved.  Route 2: before S_c, the printed arcsine
     form of (A.4), with the factor sgn(H0) the paper omits (erratum E6),
     gives the same heading. */
  tu_rng r;
  tu_rng_seed (&r, 44);
  for (int k = 0; k < 500; k++)
    {
      double L = tu_uniform (&r, -3, 3), V0 = tu_uniform (&r, -2, 2);
      double Om0 = tu_uniform (&r, -2, 2), sigma = tu_uniform (&r, 0, 5);
      double q0[4] = { 0, V0, 0.1, Om0 }, q[4], E0, H0, p[4];
      ck_assert_ok (chaplygin_smooth_energy (L, V0, Om0, &E0));
      ck_assert_ok (chaplygin_smooth_momentum (L, Om0, &H0));
      double p0[4] = { 0, E0, 0.1, H0 };
      ck_assert_ok (chaplygin_smooth_closed_form (L, q0, sigma, q, NULL));
      ck_assert_ok (chaplygin_smooth_closed_form_eh (L, p0, V0 > 0 ? 1 : -1, sigma, p));
      ck_assert (p[CHAPLYGIN_E] == E0);
      /* V0 is recovered from (E0, H0) with the cancellation of
         2E0 - H0^2/(1 + L^2): error eps 2E0/V0^2 relative in V0, which
         propagates with condition ~1 into theta and H. */
      double kappa = 2 * E0 / (V0 * V0) + 1;
      ck_assert_msg (fabs (p[CHAPLYGIN_THETA] - q[CHAPLYGIN_THETA])
                     <= 64 * DBL_EPSILON * kappa * (fabs (q[CHAPLYGIN_THETA]) + 1),
                     "theta %.17g vs %.17g", p[2], q[2]);
      double Hq = (1 + L * L) * q[CHAPLYGIN_OMEGA];
      ck_assert_msg (fabs (p[CHAPLYGIN_H] - Hq) <= 64 * DBL_EPSILON * kappa * (fabs (Hq) + fabs (H0)),
                     "H %.17g vs %.17g", p[3], Hq);
      int rev;
      double Sc;
      ck_assert_ok (chaplygin_smooth_reversal (L, q0, &rev, &Sc));
      if (!rev || sigma < Sc)
        {
          /* (A.4) as printed with sgn(H0) and the K of its branch (+1) */
          double a = L / (1 + L * L), rr = 2 * E0 * (1 + L * L) / (H0 * H0);
          double s0 = V0 > 0 ? 1 : -1;  /* x = s0 sigma */
          double printed = 0.1 + (H0 > 0 ? 1 : -1) * s0 * sqrt (1 + L * L) / L
            * (asin (1 / sqrt (rr)) - asin (exp (-a * s0 * sigma) / sqrt (rr)));
          /* asin near 1 is ill-conditioned close to S_c: skip there */
          if (exp (-a * s0 * sigma) / sqrt (rr) < 0.99)
            ck_assert_msg (fabs (printed - p[CHAPLYGIN_THETA]) <= 1e-11 * (1 + fabs (printed)),
                           "printed (A.4) %.17g vs %.17g", printed, p[2]);
        }
    }
  double p0[4] = { 0, 0.5, 0, 2.0 }, p[4];
  ck_assert_status (chaplygin_smooth_closed_form_eh (0.0, p0, 1, 1.0, p), CHAPLYGIN_ESTATE);
  p0[1] = 4.0;
  ck_assert_status (chaplygin_smooth_closed_form_eh (0.0, p0, 0, 1.0, p), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_smooth_closed_form_eh (0.0, p0, 1, -1.0, p), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_smooth_closed_form_eh (NAN, p0, 1, 1.0, p), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_smooth_closed_form_eh (0.0, NULL, 1, 1.0, p), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_smooth_closed_form_eh (0.0, p0, 1, 1.0, NULL), CHAPLYGIN_EINVAL);
  /* V0 = 0 exactly from (E0, H0) = (5/8, 5/4) at L = 1/2: accepted (an
     earlier version rounded V0^2 to -2e-16 and refused it) */
  double pv[4] = { 0, 0.625, 0, 1.25 };
  ck_assert_ok (chaplygin_smooth_closed_form_eh (0.5, pv, 1, 2.0, p));
  /* (1 + L^2) overflows: H_C is not representable */
  double ph[4] = { 0, 1.0, 0, 1.0 };
  ck_assert_status (chaplygin_smooth_closed_form_eh (1e200, ph, 1, 1.0, p), CHAPLYGIN_ERANGE);
  /* V0 = 0 exactly: dir0 is ignored */
  /* L = 3/4: sqrt(1 + L^2) = 5/4 exactly; H0 = 5/2, E0 = 2: V0^2 = 0 */
  double pz[4] = { 0, 2.0, 0, 2.5 };
  ck_assert_ok (chaplygin_smooth_closed_form_eh (0.75, pz, 0, 1.0, p));
  double E;
  ck_assert_status (chaplygin_smooth_energy (NAN, 1, 1, &E), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_smooth_energy (1, 1e300, 1, &E), CHAPLYGIN_ERANGE);
  ck_assert_status (chaplygin_smooth_energy (1, 1, 1, NULL), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_smooth_momentum (INFINITY, 1, &E), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_smooth_momentum (1e200, 1, &E), CHAPLYGIN_ERANGE);
  ck_assert_status (chaplygin_smooth_momentum (1, 1, NULL), CHAPLYGIN_EINVAL);
}
END_TEST

START_TEST (eq_A_5)
{
  /* The straight-line equilibria: H = 0, E = V*^2/2; the (E, H) closed form
     keeps them: H stays 0 and theta constant for any arc length. */
  double E, H, p[4];
  ck_assert_ok (chaplygin_smooth_steady_eh (-1.75, &E, &H));
  ck_assert (E == 0.5 * 1.75 * 1.75 && H == 0.0);
  double p0[4] = { 0, E, 0.4, H };
  ck_assert_ok (chaplygin_smooth_closed_form_eh (-2.0, p0, -1, 7.5, p));
  ck_assert (p[CHAPLYGIN_E] == E && p[CHAPLYGIN_H] == 0.0 && p[CHAPLYGIN_THETA] == 0.4);
  ck_assert_status (chaplygin_smooth_steady_eh (NAN, &E, &H), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_smooth_steady_eh (1e300, &E, &H), CHAPLYGIN_ERANGE);
  ck_assert_status (chaplygin_smooth_steady_eh (1, NULL, &H), CHAPLYGIN_EINVAL);
}
END_TEST

START_TEST (eq_A_6)
{
  /* Route: (A.6) from (E0, H0) must equal (A.1) from (V0, Omega0). */
  tu_rng r;
  tu_rng_seed (&r, 66);
  for (int k = 0; k < 1000; k++)
    {
      double L = tu_uniform (&r, -3, 3), V0 = tu_uniform (&r, -2, 2);
      double Om0 = tu_uniform (&r, -2, 2);
      double q0[4] = { 0.75, V0, 0, Om0 }, E0, H0, Sc1, Sc2;
      int r1, r2;
      ck_assert_ok (chaplygin_smooth_energy (L, V0, Om0, &E0));
      ck_assert_ok (chaplygin_smooth_momentum (L, Om0, &H0));
      ck_assert_ok (chaplygin_smooth_reversal (L, q0, &r1, &Sc1));
      ck_assert_ok (chaplygin_smooth_reversal_eh (L, 0.75, E0, H0, V0 > 0 ? 1 : -1, &r2, &Sc2));
      ck_assert_int_eq (r1, r2);
      if (r1)
        {
          /* log of a ratio >= 1 formed from E0, H0 (a few eps of the ratio)
             against log1p of V0^2/... : absolute error in S_c of ~ 8 eps
             times (1 + L^2)/|L|. */
          double scale = (1 + L * L) / fabs (L);
          ck_assert_msg (fabs (Sc1 - Sc2) <= 8 * DBL_EPSILON * (scale + Sc1),
                         "%.17g vs %.17g", Sc1, Sc2);
        }
    }
  double Sc;
  int rev;
  ck_assert_status (chaplygin_smooth_reversal_eh (1, 0, 0.1, 2.0, 1, &rev, &Sc), CHAPLYGIN_ESTATE);
  ck_assert_status (chaplygin_smooth_reversal_eh (1, 0, 1.0, 1.0, 0, &rev, &Sc), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_smooth_reversal_eh (1, 0, -1.0, 1.0, 1, &rev, &Sc), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_smooth_reversal_eh (NAN, 0, 1.0, 1.0, 1, &rev, &Sc), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_smooth_reversal_eh (1, 0, 1.0, 1.0, 1, NULL, &Sc), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_smooth_reversal_eh (1, 0, 1.0, 1.0, 1, &rev, NULL), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_smooth_reversal_eh (-1e-307, 0, 0.5e20, 1e-10, 1, &rev, &Sc),
                    CHAPLYGIN_ERANGE);
  /* V0 = 0 exactly: no reversal */
  ck_assert_ok (chaplygin_smooth_reversal_eh (-0.75, 0, 2.0, 2.5, 1, &rev, &Sc));
  ck_assert_int_eq (rev, 0);
  /* tiny H0: the log of a huge ratio without overflow */
  ck_assert_ok (chaplygin_smooth_reversal_eh (-1.0, 0, 0.5, 1e-300, 1, &rev, &Sc));
  ck_assert_int_eq (rev, 1);
  ck_assert_rel (Sc, -2 * log (1e-300 / sqrt (2.0)), 1e-15);
}
END_TEST

/* ---- the motion in time and the path of C ----------------------------

   Route: mpmath's Taylor-series ODE solver at 32 digits on (2.1) in time
   with the signed displacement x and the contact point C (dC/dtau = V e),
   the arc length from x and the reversal located by findroot on V (the
   generator is at the end of this file); none of the library's closed
   forms.  Values printed to 17 digits. */
static const struct smooth_time_ref { double L, V0, Omega0, theta0, tau, S, V, theta, Omega, x, y, Gx, Gy; } ref_smooth_time[] = {
  { 1.0, 1.0, 0.5, 0.0, 0.25, 0.257191858707269, 1.055173007005829, 0.11736387191488974, 0.439664602445021, 0.25657473188042396, 0.01553246133827054, 1.2496954944839234, 0.1326270849801935 },
  { 1.0, 1.0, 0.5, 0.0, 2.0, 2.274382874483762, 1.2035654600790753, 0.6070341870270721, 0.16035925808110316, 2.090390332986605, 0.8079625764225055, 2.9117337612578127, 1.3783965978795882 },
  { 1.0, 1.0, 0.5, 0.0, 5.64, 6.715288164483239, 1.224497399621975, 0.841989720847941, 0.0174085944151348, 5.286882500203954, 3.8772376063668, 5.952862373844233, 4.6232073161446685 },
  { -1.4142135623730951, 1.0, 0.1, 0.0, 2.0, 1.9417209009111533, 0.9180728069217368, 0.32926403293554113, 0.24976143363273906, 1.9148841263924374, 0.26512511929940197, 0.5766413072462226, -0.19215614754146873 },
  { -1.4142135623730951, 1.0, 0.1, 0.0, 6.0, 3.9296919743303844, -0.40001256567788435, 2.209965335620088, 0.5385133694718564, 3.2773246277409975, 1.2554201634506785, 4.120943606682775, 0.1203840325855712 },
  { -1.4142135623730951, 1.0, 0.1, 0.0, 8.0, 5.325781724942427, -0.8925922327027984, 3.0301382868383593, 0.2788542666690693, 4.515744209293803, 0.6909772326910643, 5.9211831265043475, 0.533683081528176 },
  { -1.4142135623730951, 1.0, 0.1, 0.0, 12.0, 9.256471773918694, -1.012060467137951, 3.5461385119895863, 0.04371731486307866, 8.306435011292276, 1.566093130439753, 9.606495012339698, 2.122729451278214 },
  { -1.4142135623730951, 1.0, 0.1, 0.0, 17.17, 14.500511424025557, -1.014869029631623, 3.629888091965986, 0.0036901984846430193, 12.99909314313536, 3.903673006970464, 14.248032922422636, 4.567110590857485 },
  { -1.0, 1.0, 0.2, 0.3, 1.0, 0.9714230790944977, 0.9320214102538091, 0.5582136558339097, 0.3250662169685592, 0.885658056275129, 0.392531718913468, 0.03745541620656391, -0.1371401430734761 },
  { -1.0, 1.0, 0.2, 0.3, 4.5, 2.7315455929481605, -0.3613465393750921, 2.6338437131985315, 0.6889951663406809, 1.7907093829192717, 1.6120986220117126, 2.664550594504484, 1.1258872102418032 },
  { -1.0, 1.0, 0.2, 0.3, 10.47, 8.148220107631895, -1.0371994691774202, 4.26463478833352, 0.045919827624227756, 5.511080599175001, 4.961656586041045, 5.944022806818947, 5.863078265855984 },
  { 2.385, -0.7, 0.4, -1.25, 0.5, 0.2983984012633045, -0.4860192264367877, -1.0382988323131475, 0.44491020643439244, -0.12102422857273085, 0.2721535994522034, 1.08980835592067, -1.782623627482393 },
  { 2.385, -0.7, 0.4, -1.25, 1.9, 0.5916280678865592, 0.26187378144106094, -0.37587960457137365, 0.4722388815212776, -0.2075595121392745, 0.42341652574805133, 2.010931920341656, -0.4520951897696265 },
  { 2.385, -0.7, 0.4, -1.25, 3.0, 1.170615928875724, 0.7570686163433038, 0.10117083171062045, 0.38414485661018766, 0.36408327187819045, 0.3710700714150753, 2.7368878013720797, 0.6119510893747372 },
  { 2.385, -0.7, 0.4, -1.25, 7.5, 6.188725787107601, 1.2379713259760856, 0.9538578002881034, 0.06417267641689985, 4.171728189264734, 3.4343988172614583, 5.551547935729442, 5.37973232781076 },
  { -0.8, -1.2, -0.3, 2.0, 1.5, 1.848494741038931, -1.2503139317424927, 1.7026224784801107, -0.12176314495731426, 0.4689672113717104, -1.781101021580998, 0.5741229456778099, -2.574159828695921 },
  { -0.8, -1.2, -0.3, 2.0, 4.0, 4.990966012862454, -1.2595501358318746, 1.5467840581403771, -0.02628937611059086, 0.5777098166580265, -4.9186306445499, 0.5585018477093349, -5.718400020013144 },
  { -0.8, -1.2, -0.3, 2.0, 9.0, 11.290600803035378, -1.2599990365335605, 1.505986180938254, -0.0012167365636288243, 0.2407672703182122, -11.208866966240157, 0.18895544276011023, -12.007187412254844 },
  { 0.001, 1.0, 0.75, 0.0, 0.5, 0.500070289066735, 1.0002811094088333, 0.3749062569332035, 0.7496250414187954, 0.4884355360076367, 0.09265885603560717, 0.48936607796097054, 0.09302504133444582 },
  { 0.001, 1.0, 0.75, 0.0, 4.0, 4.004488017266668, 1.0022410172648226, 2.9940035204402506, 0.7470026424310865, 0.1917512966509657, 2.66082748111506, 0.19076216817144417, 2.6609745350201406 },
  { 0.001, 1.0, 0.75, 0.0, 9.0, 9.022645004999312, 1.005017134179325, 6.71966526627316, 0.7432634593906837, 0.5714140377432361, 0.10913244996121578, 0.5723202831224585, 0.1095552020311552 },
  { -0.7, 0.0, 0.8, 0.3, 0.7, 0.1079237169626594, -0.30324635681382633, 0.8506154835142713, 0.7604491992348165, -0.0839827211260112, -0.06633543229409404, -0.545647155267991, -0.5925159623865381 },
  { -0.7, 0.0, 0.8, 0.3, 3.0, 1.5857279158199824, -0.8594608565205865, 2.176530466413019, 0.3797977527039796, 0.0810655186353965, -1.4423949550732758, 0.4796215466525676, -2.0178539827469892 },
  { -0.5, 1.0, 1e-06, 0.0, 10.0, 9.999999997678158, 0.9999999981375263, 0.00013399537504077617, 5.459814998243692e-05, 9.999999986843918, 0.00030998843714135813, 9.499999991332608, 0.00024299074982145794 },
  { -0.5, 1.0, 1e-06, 0.0, 30.0, 29.979390557100487, 0.9835802191629621, 0.40576730544976286, 0.16141859241757603, 29.87775119941169, 1.0014544595059973, 29.418351302467176, 0.8040925212114776 },
  { -0.5, 1.0, 1e-06, 0.0, 36.0, 34.25985757027004, -0.0029140288933113875, 3.518920841436029, 0.8944233934493704, 31.334312424918643, 4.071883624763573, 31.79913859969073, 4.256102590255058 },
  { -0.5, 1.0, 1e-06, 0.0, 45.0, 41.53611902717009, -0.9985166064341786, 6.90300252476355, 0.04869978789622555, 25.57428166191515, 3.9050215064444105, 25.16728933887676, 3.614578312363689 },
  { 0.35, -0.001, 1.3, 0.1, 0.001, 7.042499476136017e-07, -0.0004084998519317671, 0.10130000016271233, 1.3000002854643755, -7.006921725973746e-07, -7.069937928890638e-08, 0.348205038685157, 0.03539432242562256 },
  { 0.35, -0.001, 1.3, 0.1, 0.01, 2.1265587197440388e-05, 0.0049149820794302445, 0.11299998030702804, 1.299992065403628, 1.9457114814504848e-05, 2.1444965640480892e-06, 0.34778725965420043, 0.03946802237767389 },
  { 0.35, -0.001, 1.3, 0.1, 2.0, 1.0593614549037293, 0.9576841564629293, 2.4296267641537432, 0.9343087229172573, -0.12406003588852457, 0.9044481010366644, -0.38903767828065405, 1.1331112791662197 },
  { 1.7, 2.0, -3.0, 0.0, 0.125, 0.3595725326053713, 3.6662885777864185, -0.34966995472834783, -2.5637540790787674, 0.3509344399074969, -0.06981948825423122, 1.9480603568276724, -0.6522186688012923 },
  { 1.7, 2.0, -3.0, 0.0, 1.0, 5.3003854982424645, 6.218473780388617, -1.335676199587036, -0.295894722914525, 2.7590736191300462, -4.1934218025501355, 3.1551052948797618, -5.846648620564794 },
  { 1.7, 2.0, -3.0, 0.0, 25.0, 155.1945407122351, 6.245798587850876, -1.444239716840536, -1.0520840330298195e-29, 21.923752871238474, -152.85080328669196, 22.13832525025694, -154.53720735872284 },
};

#define NREF_TIME (sizeof ref_smooth_time / sizeof ref_smooth_time[0])

/* The reversal times of two reference motions (the same route). */
#define TC_FIG8 5.1290205687329395      /* L = -sqrt(2), V0 = 1, Omega0 = 0.1 */
#define TC_TINY 35.99271490714607       /* L = -0.5, V0 = 1, Omega0 = 1e-6 */

/* GSL rk8pd on (2.1) in time, landing on tau exactly (the driver):
   y = {x, V, theta, Omega, S, Cx, Cy}, S the arc length (dS = |V| dtau). */
static int
rhs21_time (double t, const double y[], double f[], void *p)
{
  rhs21 (t, y, f, p);
  f[5] = y[1] * cos (y[2]);
  f[6] = y[1] * sin (y[2]);
  return GSL_SUCCESS;
}

static void
ode_at_time (double L, double V0, double Om0, double th0, double tau,
             double y[7])
{
  gsl_odeiv2_system sys = { rhs21_time, NULL, 7, &L };
  gsl_odeiv2_driver *d
    = gsl_odeiv2_driver_alloc_y_new (&sys, gsl_odeiv2_step_rk8pd, 1e-3,
                                     1e-14, 1e-14);
  double t = 0.0;
  y[0] = 0, y[1] = V0, y[2] = th0, y[3] = Om0, y[4] = 0, y[5] = 0, y[6] = 0;
  ck_assert_int_eq (gsl_odeiv2_driver_apply (d, &t, tau, y), GSL_SUCCESS);
  gsl_odeiv2_driver_free (d);
}

START_TEST (smooth_motion)
{
  /* set-up: errors leave the output untouched; sigma_c = S_c - S0 of
     chaplygin_smooth_reversal; Z = atanh(|V0|/sqrt(2E)) in its three
     forms against long double (64-bit significand) */
  chaplygin_smooth_motion m, sentinel;
  memset (&sentinel, 0x5a, sizeof sentinel);
  m = sentinel;
  double q0[4] = { 0.25, 1.0, 0.5, 0.1 };
  ck_assert_status (chaplygin_smooth_motion_init (1.0, NULL, &m), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_smooth_motion_init (1.0, q0, NULL), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_smooth_motion_init (NAN, q0, &m), CHAPLYGIN_EDOM);
  for (int i = 0; i < 4; i++)
    {
      double b[4] = { 0.25, 1.0, 0.5, 0.1 };
      b[i] = INFINITY;
      ck_assert_status (chaplygin_smooth_motion_init (1.0, b, &m), CHAPLYGIN_EDOM);
    }
  /* B Omega0 overflows; sqrt(2E) = hypot(V0, B Omega0) overflows */
  double big[4] = { 0, 1.0, 0, DBL_MAX };
  ck_assert_status (chaplygin_smooth_motion_init (1.0, big, &m), CHAPLYGIN_ERANGE);
  double big2[4] = { 0, DBL_MAX, 0, DBL_MAX };
  ck_assert_status (chaplygin_smooth_motion_init (0.0, big2, &m), CHAPLYGIN_ERANGE);
  ck_assert (memcmp (&m, &sentinel, sizeof m) == 0);
  /* a motion not set up is refused, the output untouched */
  double q[4] = { 7, 7, 7, 7 };
  memset (&m, 0, sizeof m);
  ck_assert_status (chaplygin_smooth_at_time (&m, 1.0, q), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_smooth_at_time (NULL, 1.0, q), CHAPLYGIN_EINVAL);
  ck_assert (q[0] == 7 && q[1] == 7 && q[2] == 7 && q[3] == 7);
  /* sigma_c: the reversal in time is at the S_c of (A.1) */
  const double L = -1.4142135623730951, qr[4] = { 0.25, 1.0, 0.5, 0.1 };
  double Sc;
  int rev;
  ck_assert_ok (chaplygin_smooth_motion_init (L, qr, &m));
  ck_assert_ok (chaplygin_smooth_reversal (L, qr, &rev, &Sc));
  ck_assert (rev && m.approaching);
  ck_assert_rel (m.sigma_c + 0.25, Sc, DBL_EPSILON);
  /* Z: atanh (T < 1/2), log((1 + T)/Sc), logarithms of each factor (Sc
     subnormal) */
  const double cases[][3] = { { 0.3, 0.2, 1.7 }, { -2.0, 3.0, 0.001 },
                              { -0.5, 1e10, 1e-310 } };
  for (int k = 0; k < 3; k++)
    {
      double qk[4] = { 0, cases[k][1], 0, cases[k][2] };
      ck_assert_ok (chaplygin_smooth_motion_init (cases[k][0], qk, &m));
      long double Lq = cases[k][0], V = cases[k][1], O = cases[k][2];
      long double B = sqrtl (1 + Lq * Lq), c = sqrtl (V * V + B * B * O * O);
      long double Z = logl (c + fabsl (V)) - logl (B) - logl (fabsl (O));
      ck_assert_rel (m.Z, (double) Z, 4 * DBL_EPSILON);
    }
}
END_TEST

START_TEST (smooth_at_time_reference)
{
  /* Against the 30-digit integration.  Tolerance: 4 eps (|q| + tau |q'|)
     for q = S - S0, V, Omega, theta - theta0 (q' from (2.1)): the change
     of q when q and tau are rounded by about an ulp each -- the conditioning
     of the time-parametrised state (large near a reversal after a long
     approach, where V is fixed by tau only to eps Z).  Measured: 1.1. */
  const int i = _i;
  const struct smooth_time_ref *r = &ref_smooth_time[i];
  const double q0[4] = { 0.0, r->V0, r->theta0, r->Omega0 };
  chaplygin_smooth_motion m;
  double q[4];
  ck_assert_ok (chaplygin_smooth_motion_init (r->L, q0, &m));
  ck_assert_ok (chaplygin_smooth_at_time (&m, r->tau, q));
  const double L = r->L, a = L / (1 + L * L), t = r->tau;
  const double dth = r->theta - r->theta0;
  ck_assert_abs_eps (q[CHAPLYGIN_S], r->S, 4, r->S + t * fabs (r->V));
  ck_assert_abs_eps (q[CHAPLYGIN_V], r->V, 4,
                     fabs (r->V) + t * fabs (L * r->Omega * r->Omega));
  ck_assert_abs_eps (q[CHAPLYGIN_OMEGA], r->Omega, 4,
                     fabs (r->Omega) + t * fabs (a * r->V * r->Omega));
  ck_assert_abs_eps (q[CHAPLYGIN_THETA] - r->theta0, dth, 4,
                     fabs (dth) + t * fabs (r->Omega));
}
END_TEST

START_TEST (smooth_at_time)
{
  /* Route 2: GSL rk8pd on (2.1) in time at 1e-14, randomized (reversals
     half the time, tau up to past 3 reversal times); its global error is
     ~1e-12: 1e-10 relative (absolute below 1). */
  tu_rng rg;
  tu_rng_seed (&rg, 2021);
  int reversed = 0;
  for (int k = 0; k < 200; k++)
    {
      double L = tu_uniform (&rg, -3, 3), V0 = tu_uniform (&rg, -2, 2);
      double Om0 = tu_uniform (&rg, -2, 2), th0 = tu_uniform (&rg, -3, 3);
      double tau = tu_uniform (&rg, 0.01, 10), y[7], q[4];
      const double q0[4] = { 0.75, V0, th0, Om0 };
      chaplygin_smooth_motion m;
      ck_assert_ok (chaplygin_smooth_motion_init (L, q0, &m));
      ck_assert_ok (chaplygin_smooth_at_time (&m, tau, q));
      ode_at_time (L, V0, Om0, th0, tau, y);
      if (q[CHAPLYGIN_V] * V0 < 0)
        reversed++;
      ck_assert_msg (fabs (q[CHAPLYGIN_S] - 0.75 - y[4]) <= 1e-10 * fmax (1, y[4]),
                     "S %.17g ode %.17g", q[0] - 0.75, y[4]);
      ck_assert_msg (fabs (q[CHAPLYGIN_V] - y[1]) <= 1e-10 * fmax (1, fabs (y[1])),
                     "V %.17g ode %.17g", q[1], y[1]);
      ck_assert_msg (fabs (q[CHAPLYGIN_THETA] - y[2]) <= 1e-10 * fmax (1, fabs (y[2])),
                     "theta %.17g ode %.17g", q[2], y[2]);
      ck_assert_msg (fabs (q[CHAPLYGIN_OMEGA] - y[3]) <= 1e-10 * fmax (1, fabs (y[3])),
                     "Omega %.17g ode %.17g", q[3], y[3]);
    }
  ck_assert_int_ge (reversed, 30);

  /* tau = 0: q0 exactly; the kinds: rest, line, circle, spinning in place */
  chaplygin_smooth_motion m;
  double q[4];
  const double qa[4] = { 0.5, -0.7, 1.25, 0.3 };
  ck_assert_ok (chaplygin_smooth_motion_init (2.385, qa, &m));
  ck_assert_ok (chaplygin_smooth_at_time (&m, 0.0, q));
  ck_assert (memcmp (q, qa, sizeof q) == 0);
  const double rest[4] = { 0.5, 0, 1.25, 0 };
  ck_assert_ok (chaplygin_smooth_motion_init (2.385, rest, &m));
  ck_assert_ok (chaplygin_smooth_at_time (&m, 3.0, q));
  ck_assert (memcmp (q, rest, sizeof q) == 0);
  const double line[4] = { 0.5, -0.7, 1.25, 0 };
  ck_assert_ok (chaplygin_smooth_motion_init (2.385, line, &m));
  ck_assert_ok (chaplygin_smooth_at_time (&m, 3.0, q));
  ck_assert (q[1] == -0.7 && q[2] == 1.25 && q[3] == 0);
  ck_assert_rel (q[0], 0.5 + 2.1, DBL_EPSILON);
  const double circ[4] = { 0.5, -0.7, 1.25, 0.3 };
  ck_assert_ok (chaplygin_smooth_motion_init (0.0, circ, &m));
  ck_assert_ok (chaplygin_smooth_at_time (&m, 3.0, q));
  ck_assert (q[1] == -0.7 && q[3] == 0.3);
  ck_assert_rel (q[0], 0.5 + 2.1, DBL_EPSILON);
  ck_assert_rel (q[2], 1.25 + 0.9, DBL_EPSILON);
  const double spin[4] = { 0.5, 0, 1.25, 0.3 };
  ck_assert_ok (chaplygin_smooth_motion_init (0.0, spin, &m));
  ck_assert_ok (chaplygin_smooth_at_time (&m, 3.0, q));
  ck_assert (q[0] == 0.5 && q[1] == 0 && q[3] == 0.3);
  ck_assert_rel (q[2], 1.25 + 0.9, DBL_EPSILON);

  /* small L joins the circle continuously: theta - theta0 = Omega0 tau
     (1 + O(L)), V = V0 (1 + O(L)) */
  const double qs[4] = { 0, 1.0, 0, 0.75 };
  ck_assert_ok (chaplygin_smooth_motion_init (1e-300, qs, &m));
  ck_assert_ok (chaplygin_smooth_at_time (&m, 2.0, q));
  ck_assert_rel (q[2], 1.5, DBL_EPSILON);
  ck_assert_rel (q[0], 2.0, DBL_EPSILON);
  ck_assert_rel (q[1], 1.0, DBL_EPSILON);

  /* L subnormal: u = |a| sqrt(2E) tau underflows to 0 -- the circle */
  ck_assert_ok (chaplygin_smooth_motion_init (0x1p-1074, qs, &m));
  ck_assert_ok (chaplygin_smooth_at_time (&m, 0.25, q));
  ck_assert (q[1] == 1.0 && q[3] == 0.75);
  ck_assert_rel (q[2], 0.1875, DBL_EPSILON);
  ck_assert_rel (q[0], 0.25, DBL_EPSILON);
  /* a motion with an invalid kind is refused */
  m.kind = 99;
  ck_assert_status (chaplygin_smooth_at_time (&m, 0.25, q), CHAPLYGIN_EINVAL);

  /* through the reversal: V changes sign at the reference tc, by
     dV/dtau = L Omega^2 = L (2E)/(1 + L^2) there (E conserved) */
  const double L8 = -1.4142135623730951, q8[4] = { 0, 1.0, 0, 0.1 };
  ck_assert_ok (chaplygin_smooth_motion_init (L8, q8, &m));
  double E0;
  ck_assert_ok (chaplygin_smooth_energy (L8, 1.0, 0.1, &E0));
  for (int sgn = -1; sgn <= 1; sgn += 2)
    {
      const double dt = sgn * 1e-6;
      ck_assert_ok (chaplygin_smooth_at_time (&m, TC_FIG8 + dt, q));
      ck_assert_rel (q[1], L8 * 2 * E0 / (1 + L8 * L8) * dt, 1e-6);
    }
  /* a long approach (Omega0 = 1e-6, Z = 14.4): the reversal at TC_TINY;
     Omega there is sqrt(2E)/B (all energy rotational) */
  const double qt[4] = { 0, 1.0, 0, 1e-6 };
  ck_assert_ok (chaplygin_smooth_motion_init (-0.5, qt, &m));
  ck_assert_ok (chaplygin_smooth_at_time (&m, TC_TINY, q));
  ck_assert (fabs (q[1]) < 1e-12);
  ck_assert_rel (q[3] * sqrt (1.25), hypot (1.0, sqrt (1.25) * 1e-6), 1e-13);
  /* Sc subnormal (Omega0 = 1e-320): the reversal after Z ~ 737 (tau ~
     1842); S there = S_c of (A.1); V = 0 within the conditioning eps Z */
  const double qx[4] = { 0, 1.0, 0, 1e-320 };
  int rev;
  double Sc;
  ck_assert_ok (chaplygin_smooth_motion_init (-0.5, qx, &m));
  ck_assert_ok (chaplygin_smooth_reversal (-0.5, qx, &rev, &Sc));
  const double tc = m.Z / m.ac;
  ck_assert (tc > 1800 && tc < 1900);
  ck_assert_ok (chaplygin_smooth_at_time (&m, tc, q));
  ck_assert_rel (q[0], Sc, 8 * DBL_EPSILON);
  ck_assert (fabs (q[1]) < 4 * DBL_EPSILON * m.Z);
  ck_assert_ok (chaplygin_smooth_at_time (&m, 0.5 * tc, q));
  ck_assert (q[1] > 0.99 && q[0] > 0.99 * 0.5 * tc);
  ck_assert_ok (chaplygin_smooth_at_time (&m, 1.5 * tc, q));
  ck_assert (q[1] < -0.99 && q[3] > 0 && q[3] < 1e-100);

  /* tau where S is huge: S = S0 + sqrt(2E) tau + O(1), V -> +-sqrt(2E),
     Omega -> 0, theta at its limit (the same at 1e3 and 1e300) */
  for (int k = 0; k < 2; k++)
    {
      const double qh[4] = { 0, k ? -1.0 : 1.0, 0.5, 0.4 };
      const double Lh = k ? 0.8 : -0.8;   /* k = 0 reverses, k = 1 not */
      double qa2[4];
      ck_assert_ok (chaplygin_smooth_motion_init (Lh, qh, &m));
      ck_assert_ok (chaplygin_smooth_at_time (&m, 1e300, q));
      ck_assert_ok (chaplygin_smooth_at_time (&m, 1e3, qa2));
      ck_assert_rel (q[0], m.c * 1e300, 2 * DBL_EPSILON);
      ck_assert (fabs (q[1]) == m.c && q[3] == 0);
      ck_assert_rel (q[2], qa2[2], DBL_EPSILON);
    }

  /* errors: the output untouched */
  const double qe[4] = { 0, 10.0, 0, 0.5 };
  ck_assert_ok (chaplygin_smooth_motion_init (1.0, qe, &m));
  q[0] = q[1] = q[2] = q[3] = 7;
  ck_assert_status (chaplygin_smooth_at_time (&m, DBL_MAX, q), CHAPLYGIN_ERANGE);
  ck_assert_status (chaplygin_smooth_at_time (&m, -1.0, q), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_smooth_at_time (&m, NAN, q), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_smooth_at_time (&m, INFINITY, q), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_smooth_at_time (&m, 1.0, NULL), CHAPLYGIN_EINVAL);
  ck_assert (q[0] == 7 && q[1] == 7 && q[2] == 7 && q[3] == 7);
  /* the approach form with expm1(2u) in logarithmic form (u > 350):
     Omega0 = 1e-310, L = -1, the first half of a 714-long approach */
  const double qf[4] = { 0, 1.0, 0, 1e-310 };
  ck_assert_ok (chaplygin_smooth_motion_init (-1.0, qf, &m));
  ck_assert (m.Z > 712);
  ck_assert_ok (chaplygin_smooth_at_time (&m, 355.0 / m.ac, q));
  /* S = (log cosh Z - log cosh(Z - u))/|a| = (u + log((1 + e^-2Z)/(1 +
     e^-2(Z-u))))/|a| = 2 u to 1e-300 */
  ck_assert_rel (q[0], 2 * 355.0, 2 * DBL_EPSILON);
  /* Omega = Omega0 cosh Z/cosh(Z - u) = Omega0 e^u (1 + O(e^-700)); the
     relative conditioning is u eps (u = 355): 4e-13 */
  ck_assert_rel (q[3], 1e-310 * exp (355.0), 4e-13);

  /* consistency with the closed form in S: tau(S(tau)) = tau (away from
     the reversal, where dtau/dS = 1/|V| is moderate) */
  tu_rng_seed (&rg, 7);
  for (int k = 0; k < 100; k++)
    {
      double L = tu_uniform (&rg, -3, 3), V0 = tu_uniform (&rg, -2, 2);
      double Om0 = tu_uniform (&rg, -2, 2), tau = tu_uniform (&rg, 0.01, 10);
      const double q0[4] = { 0, V0, 0.3, Om0 };
      double qb[4], dtau;
      ck_assert_ok (chaplygin_smooth_motion_init (L, q0, &m));
      ck_assert_ok (chaplygin_smooth_at_time (&m, tau, q));
      if (fabs (q[1]) < 0.1 * m.c)
        continue;
      ck_assert_ok (chaplygin_smooth_closed_form (L, q0, q[0], qb, &dtau));
      ck_assert_rel (dtau, tau, 64 * DBL_EPSILON);
      ck_assert_rel (qb[1], q[1], 64 * DBL_EPSILON);
    }
}
END_TEST

START_TEST (smooth_path_reference)
{
  /* C and G against the 30-digit integration, in one step and in 200
     equal steps (the compensated sum of the increments).  Tolerance 4 eps
     of the arc length (plus |L| for G): the quadrature is asked for
     128 eps of each piece's arc length as an error ESTIMATE (QUADPACK's,
     pessimistic by orders of magnitude here); what remains is the rounding
     of the integrand and of the sum.  Measured: 2.2 (one step), 1.5 (200
     steps). */
  const int i = _i;
  const struct smooth_time_ref *r = &ref_smooth_time[i];
  const double q0[4] = { 0.0, r->V0, r->theta0, r->Omega0 };
  chaplygin_smooth_motion m;
  chaplygin_smooth_path p1, p200;
  double G[2];
  ck_assert_ok (chaplygin_smooth_motion_init (r->L, q0, &m));
  ck_assert_ok (chaplygin_smooth_path_init (0.0, NULL, &p1));
  ck_assert_ok (chaplygin_smooth_path_advance (&m, &p1, r->tau, G));
  ck_assert (p1.tau == r->tau);
  ck_assert_abs_eps (p1.C[0], r->x, 8, r->S);
  ck_assert_abs_eps (p1.C[1], r->y, 8, r->S);
  ck_assert_abs_eps (G[0], r->Gx, 8, r->S + fabs (r->L));
  ck_assert_abs_eps (G[1], r->Gy, 8, r->S + fabs (r->L));
  ck_assert_ok (chaplygin_smooth_path_init (0.0, NULL, &p200));
  for (int k = 1; k <= 200; k++)
    ck_assert_ok (chaplygin_smooth_path_advance (&m, &p200, k == 200 ? r->tau
                                                 : r->tau * (k / 200.0), G));
  ck_assert_abs_eps (p200.C[0], r->x, 8, r->S);
  ck_assert_abs_eps (p200.C[1], r->y, 8, r->S);
  ck_assert_abs_eps (G[0], r->Gx, 8, r->S + fabs (r->L));
  ck_assert_abs_eps (G[1], r->Gy, 8, r->S + fabs (r->L));
}
END_TEST

START_TEST (smooth_path)
{
  /* Route 2: GSL rk8pd on (2.1) with dC/dtau, randomized; 1e-10 of the
     arc length (the integration's global error ~1e-12) */
  tu_rng rg;
  tu_rng_seed (&rg, 1999);
  for (int k = 0; k < 100; k++)
    {
      double L = tu_uniform (&rg, -3, 3), V0 = tu_uniform (&rg, -2, 2);
      double Om0 = tu_uniform (&rg, -2, 2), th0 = tu_uniform (&rg, -3, 3);
      double tau = tu_uniform (&rg, 0.01, 10), y[7], G[2];
      const double q0[4] = { 0, V0, th0, Om0 };
      const double C0[2] = { -1.5, 2.25 };
      chaplygin_smooth_motion m;
      chaplygin_smooth_path p;
      ck_assert_ok (chaplygin_smooth_motion_init (L, q0, &m));
      ck_assert_ok (chaplygin_smooth_path_init (0.0, C0, &p));
      ck_assert_ok (chaplygin_smooth_path_advance (&m, &p, tau, G));
      ode_at_time (L, V0, Om0, th0, tau, y);
      ck_assert (fabs (p.C[0] - (-1.5 + y[5])) <= 1e-10 * fmax (1, y[4]));
      ck_assert (fabs (p.C[1] - (2.25 + y[6])) <= 1e-10 * fmax (1, y[4]));
      ck_assert (fabs (G[0] - (-1.5 + y[5] + L * cos (y[2]))) <= 1e-10 * fmax (1, y[4]));
      ck_assert (fabs (G[1] - (2.25 + y[6] + L * sin (y[2]))) <= 1e-10 * fmax (1, y[4]));
    }

  /* the line and the circle in closed form, against elementary geometry:
     C = V0 tau e(theta0); on the circle of radius |V0/Omega0| through C0
     with the chord 2 (V0/Omega0) sin(Omega0 tau/2) */
  chaplygin_smooth_motion m;
  chaplygin_smooth_path p;
  double G[2];
  const double line[4] = { 0, -2.0, 0.3, 0 };
  ck_assert_ok (chaplygin_smooth_motion_init (0.5, line, &m));
  ck_assert_ok (chaplygin_smooth_path_init (0.0, NULL, &p));
  ck_assert_ok (chaplygin_smooth_path_advance (&m, &p, 3.0, G));
  ck_assert_rel (p.C[0], -6.0 * cos (0.3), 2 * DBL_EPSILON);
  ck_assert_rel (p.C[1], -6.0 * sin (0.3), 2 * DBL_EPSILON);
  ck_assert_rel (G[0], -5.5 * cos (0.3), 2 * DBL_EPSILON);
  const double circ[4] = { 0, 1.0, 0.3, 2.0 };
  ck_assert_ok (chaplygin_smooth_motion_init (0.0, circ, &m));
  ck_assert_ok (chaplygin_smooth_path_init (0.0, NULL, &p));
  for (int k = 1; k <= 50; k++)
    {
      const double t = 0.1 * k, th = 0.3 + 2.0 * t;
      ck_assert_ok (chaplygin_smooth_path_advance (&m, &p, t, G));
      /* centre (-0.5 sin 0.3, 0.5 cos 0.3), radius 1/2 */
      ck_assert (fabs (p.C[0] - 0.5 * (sin (th) - sin (0.3))) < 4 * DBL_EPSILON);
      ck_assert (fabs (p.C[1] - 0.5 * (cos (0.3) - cos (th))) < 4 * DBL_EPSILON);
      ck_assert (G[0] == p.C[0] && G[1] == p.C[1]);
    }
  /* many short steps add no rounding (the compensated sum): 10000 steps
     of 1e-3 along a line from C0 = (1e6, -1e6); a plain sum would drift
     by thousands of ulps of 1e6 (each increment rounded the same way) */
  const double far0[2] = { 1e6, -1e6 };
  ck_assert_ok (chaplygin_smooth_motion_init (0.5, line, &m));
  ck_assert_ok (chaplygin_smooth_path_init (0.0, far0, &p));
  for (int k = 1; k <= 10000; k++)
    ck_assert_ok (chaplygin_smooth_path_advance (&m, &p, k * 1e-3, NULL));
  ck_assert (fabs (p.C[0] - (1e6 - 20.0 * cos (0.3))) <= 2 * DBL_EPSILON * 1e6);
  ck_assert (fabs (p.C[1] - (-1e6 - 20.0 * sin (0.3))) <= 2 * DBL_EPSILON * 1e6);
  /* spinning in place and rest: C stays */
  const double spin[4] = { 0, 0, 0.3, 2.0 };
  const double C0[2] = { 1.0, -1.0 };
  ck_assert_ok (chaplygin_smooth_motion_init (0.0, spin, &m));
  ck_assert_ok (chaplygin_smooth_path_init (1.0, C0, &p));
  ck_assert_ok (chaplygin_smooth_path_advance (&m, &p, 4.0, G));
  ck_assert (p.C[0] == 1.0 && p.C[1] == -1.0 && p.tau == 4.0);
  const double rest[4] = { 0, 0, 0.3, 0 };
  ck_assert_ok (chaplygin_smooth_motion_init (2.0, rest, &m));
  ck_assert_ok (chaplygin_smooth_path_advance (&m, &p, 5.0, G));
  ck_assert (p.C[0] == 1.0 && p.C[1] == -1.0);
  ck_assert_rel (G[0], 1.0 + 2 * cos (0.3), DBL_EPSILON);

  /* a long interval: many turns of a near-circle (L = 1e-3: 90 radians
     over tau = 100), pieces of one radian, against the integration */
  const double qn[4] = { 0, 1.0, 0, 1.0 };
  double y[7];
  ck_assert_ok (chaplygin_smooth_motion_init (1e-3, qn, &m));
  ck_assert_ok (chaplygin_smooth_path_init (0.0, NULL, &p));
  ck_assert_ok (chaplygin_smooth_path_advance (&m, &p, 100.0, NULL));
  ode_at_time (1e-3, 1.0, 1.0, 0.0, 100.0, y);
  ck_assert (fabs (p.C[0] - y[5]) < 1e-9 && fabs (p.C[1] - y[6]) < 1e-9);
  /* a transient at the start of a long interval (less than a radian to
     turn, z from 0.66 to 3e4): one step to tau = 2e4 and 1e6.  Reference:
     the 30-digit Taylor-series integration to tau = 60, where V = sqrt(2E)
     and theta is constant to 1e-33, then the straight line (mpmath) */
  const double qt[4] = { 0, 2.0, 0, -1.0 };
  const double tt[2] = { 2e4, 1e6 };
  const double xt[2][2] = { { 33493.701127392218328, -39422.206544193598852 },
                            { 1674643.0383031647369, -1971184.3174386801711 } };
  ck_assert_ok (chaplygin_smooth_motion_init (1.3, qt, &m));
  for (int k = 0; k < 2; k++)
    {
      double qq[4];
      ck_assert_ok (chaplygin_smooth_path_init (0.0, NULL, &p));
      ck_assert_ok (chaplygin_smooth_path_advance (&m, &p, tt[k], NULL));
      ck_assert_ok (chaplygin_smooth_at_time (&m, tt[k], qq));
      ck_assert_abs_eps (p.C[0], xt[k][0], 8, qq[0]);
      ck_assert_abs_eps (p.C[1], xt[k][1], 8, qq[0]);
    }
  /* tiny L (1e-20): the heading has no resolution in psi, the pieces come
     from the bound |Omega| <= sqrt(2E)/B: the circle to rounding */
  ck_assert_ok (chaplygin_smooth_motion_init (1e-20, qn, &m));
  ck_assert_ok (chaplygin_smooth_path_init (0.0, NULL, &p));
  ck_assert_ok (chaplygin_smooth_path_advance (&m, &p, 20.0, NULL));
  ck_assert (fabs (p.C[0] - sin (20.0)) < 1e-13 && fabs (p.C[1] - (1 - cos (20.0))) < 1e-13);
  /* a time where a unit step is below the ulp of t (t = 1e17, tiny L): the
     partition cannot advance and takes the rest as one piece (here 64
     time units, 0.064 radians; theta ~ 1e14 has ulps of 1/64 there, so
     only the length of the chord, 2000 sin(0.032) = 63.989, to 1e-2) */
  const double qs17[4] = { 0, 1.0, 0, 1e-3 };
  ck_assert_ok (chaplygin_smooth_motion_init (1e-20, qs17, &m));
  ck_assert_ok (chaplygin_smooth_path_init (1e17, NULL, &p));
  ck_assert_ok (chaplygin_smooth_path_advance (&m, &p, 1e17 + 64, NULL));
  ck_assert (fabs (hypot (p.C[0], p.C[1]) - 2000 * sin (0.032)) < 1e-2);
  /* a motion that runs far: psi reaches +-pi/2 in double long before tau
     (one piece to the end, bisected) */
  const double qr[4] = { 0, 1.0, 0, 1.0 };
  ck_assert_ok (chaplygin_smooth_motion_init (2.0, qr, &m));
  ck_assert_ok (chaplygin_smooth_path_init (0.0, NULL, &p));
  ck_assert_ok (chaplygin_smooth_path_advance (&m, &p, 1e6, G));
  ck_assert (isfinite (p.C[0]) && hypot (p.C[0], p.C[1]) > 0.99 * m.c * 1e6);

  /* errors: the path untouched */
  const double qe[4] = { 0, 1.0, 0.2, 0.5 };
  ck_assert_ok (chaplygin_smooth_motion_init (-1.0, qe, &m));
  ck_assert_ok (chaplygin_smooth_path_init (2.0, C0, &p));
  chaplygin_smooth_path keep = p;
  ck_assert_status (chaplygin_smooth_path_advance (&m, &p, 1.0, G), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_smooth_path_advance (&m, &p, NAN, G), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_smooth_path_advance (&m, NULL, 3.0, G), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_smooth_path_advance (NULL, &p, 3.0, G), CHAPLYGIN_EINVAL);
  ck_assert (memcmp (&p, &keep, sizeof p) == 0);
  ck_assert_status (chaplygin_smooth_path_init (-1.0, NULL, &p), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_smooth_path_init (INFINITY, NULL, &p), CHAPLYGIN_EDOM);
  const double Cbad[2] = { 0, NAN };
  ck_assert_status (chaplygin_smooth_path_init (0.0, Cbad, &p), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_smooth_path_init (0.0, NULL, NULL), CHAPLYGIN_EINVAL);
  ck_assert (memcmp (&p, &keep, sizeof p) == 0);
  /* C overflows: a line (closed form) and a general motion (the
     quadrature's sum) */
  const double qbig[4] = { 0, 1e300, 0.2, 0 };
  ck_assert_ok (chaplygin_smooth_motion_init (1.0, qbig, &m));
  ck_assert_status (chaplygin_smooth_path_advance (&m, &p, 1e10, G), CHAPLYGIN_ERANGE);
  const double qbig2[4] = { 0, 1e308, 0.2, 1e307 };
  ck_assert_ok (chaplygin_smooth_motion_init (1.0, qbig2, &m));
  ck_assert_status (chaplygin_smooth_path_advance (&m, &p, 10.0, G), CHAPLYGIN_ERANGE);
  ck_assert (memcmp (&p, &keep, sizeof p) == 0);
}
END_TEST

int
main (void)
{
  Suite *s = suite_create ("smooth");
  TCase *t;
  t = tcase_create ("eq_2_1");
  tcase_add_test (t, eq_2_1);
  suite_add_tcase (s, t);
  t = tcase_create ("eq_2_4");
  tcase_add_test (t, eq_2_4);
  suite_add_tcase (s, t);
  t = tcase_create ("eq_A_1");
  tcase_set_timeout (t, 60);
  tcase_add_test (t, eq_A_1);
  suite_add_tcase (s, t);
  t = tcase_create ("eq_A_2");
  tcase_set_timeout (t, 120);
  tcase_add_loop_test (t, eq_A_2_reference, 0, NREF);
  tcase_add_test (t, eq_A_2);
  tcase_add_test (t, eq_A_2_erratum);
  tcase_add_test (t, eq_A_2_special);
  suite_add_tcase (s, t);
  t = tcase_create ("eq_A_3");
  tcase_set_timeout (t, 60);
  tcase_add_test (t, eq_A_3);
  suite_add_tcase (s, t);
  t = tcase_create ("eq_A_4");
  tcase_add_test (t, eq_A_4);
  suite_add_tcase (s, t);
  t = tcase_create ("eq_A_5");
  tcase_add_test (t, eq_A_5);
  suite_add_tcase (s, t);
  t = tcase_create ("eq_A_6");
  tcase_add_test (t, eq_A_6);
  suite_add_tcase (s, t);
  t = tcase_create ("smooth_motion");
  tcase_add_test (t, smooth_motion);
  suite_add_tcase (s, t);
  t = tcase_create ("smooth_at_time");
  tcase_set_timeout (t, 60);
  tcase_add_loop_test (t, smooth_at_time_reference, 0, NREF_TIME);
  tcase_add_test (t, smooth_at_time);
  suite_add_tcase (s, t);
  t = tcase_create ("smooth_path");
  tcase_set_timeout (t, 60);
  tcase_add_loop_test (t, smooth_path_reference, 0, NREF_TIME);
  tcase_add_test (t, smooth_path);
  suite_add_tcase (s, t);
  return tu_run (s);
}

/* The generator of ref_smooth_time (python3 with mpmath 1.3; ~2 minutes):

# Reference states and contact-point paths of the smooth sleigh at given
# times, by mpmath's Taylor-series ODE solver on (2.1) in time with the
# signed displacement x (dx/dtau = V) and the contact point C
# (dC/dtau = V (cos theta, sin theta)); the arc length S from x, the
# reversal (first zero of V) located by findroot on the solution.
from mpmath import mp, mpf, odefun, findroot, cos, sin, sign, nstr
mp.dps = 32

def smooth_time_ref(L, V0, Om0, th0, taus):
    L, V0, Om0, th0 = mpf(L), mpf(V0), mpf(Om0), mpf(th0)
    a = L / (1 + L * L)
    F = lambda t, y: [y[1], L * y[3] ** 2, y[3], -a * y[1] * y[3],
                      y[1] * cos(y[2]), y[1] * sin(y[2])]
    f = odefun(F, 0, [mpf(0), V0, th0, Om0, mpf(0), mpf(0)])
    s0 = sign(V0) if V0 != 0 else sign(L)
    rev = V0 != 0 and L * V0 < 0 and Om0 != 0
    tc = xc = None
    if rev:
        t = mpf(0)
        step = mpf(1) / 8
        while f(t + step)[1] * s0 > 0:
            t += step
        tc = findroot(lambda tt: f(tt)[1], (t, t + step), solver="anderson")
        xc = f(tc)[0]
    out = []
    for ta in taus:
        ta = mpf(ta)
        y = f(ta)
        x = y[0]
        if rev and ta > tc:
            S = abs(xc) + abs(xc - x)
        else:
            S = abs(x)
        G = (y[4] + L * cos(y[2]), y[5] + L * sin(y[2]))
        out.append((ta, S, y[1], y[2], y[3], y[4], y[5], G[0], G[1]))
    return out

def c(x):
    return repr(float(x))

rows = [
    # L, V0, Om0, theta0, taus
    (1.0, 1.0, 0.5, 0.0, [0.25, 2.0, 5.64]),                      # Fig. 6
    (-1.4142135623730951, 1.0, 0.1, 0.0, [2.0, 6.0, 8.0, 12.0, 17.17]),  # Fig. 8, reverses
    (-1.0, 1.0, 0.2, 0.3, [1.0, 4.5, 10.47]),                     # Fig. 5
    (2.385, -0.7, 0.4, -1.25, [0.5, 1.9, 3.0, 7.5]),              # V0 < 0, L > 0: reverses
    (-0.8, -1.2, -0.3, 2.0, [1.5, 4.0, 9.0]),                     # recedes
    (0.001, 1.0, 0.75, 0.0, [0.5, 4.0, 9.0]),                     # nearly L = 0
    (-0.7, 0.0, 0.8, 0.3, [0.7, 3.0]),                            # V0 = 0
    (-0.5, 1.0, 1e-6, 0.0, [10.0, 30.0, 36.0, 45.0]),             # Omega0 tiny: long approach
    (0.35, -0.001, 1.3, 0.1, [0.001, 0.01, 2.0]),                 # V0 tiny, reverses early
    (1.7, 2.0, -3.0, 0.0, [0.125, 1.0, 25.0]),                    # fast decay
]
print("static const struct smooth_time_ref { double L, V0, Omega0, theta0, tau, S, V, theta, Omega, x, y, Gx, Gy; } ref_smooth_time[] = {")
for (L, V0, Om0, th0, taus) in rows:
    for r in smooth_time_ref(L, V0, Om0, th0, taus):
        print("  { %s, %s, %s, %s, %s },"
              % (c(L), c(V0), c(Om0), c(th0), ", ".join(c(v) for v in r)))
print("};")
*/
