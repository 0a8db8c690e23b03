/* test_smooth.c -- lib/smooth.c: Section 2 and Appendix A, the smooth
   Chaplygin sleigh. */
#include <config.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>
#include <stdlib.h>

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
  return tu_run (s);
}
