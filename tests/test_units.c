/* test_units.c -- lib/units.c: (2.2), (2.3), (3.2) and the energy and
   momentum scales. */
#include <config.h>

#include <stdlib.h>

#include "internal.h"
#include "testutil.h"

typedef __float128 q128;

/* sqrt in binary128 by Newton's iteration from the double estimate. */
static q128
sqrt128 (q128 x)
{
  q128 scale = 1;
  while (x > (q128) 1e300)
    x /= (q128) 1e300, scale *= (q128) 1e150;
  while (x < (q128) 1e-300)
    x *= (q128) 1e300, scale /= (q128) 1e150;
  q128 r = sqrt ((double) x);
  for (int i = 0; i < 3; i++)
    r = (r + x / r) / 2;
  return r * scale;
}

START_TEST (eq_2_3)
{
  /* Route: binary128 square root of I/m.  sqrt(I/m) rounds twice: the
     quotient's relative error eps/2 is halved by the root, plus eps/2:
     within 1 ulp (0.75 in theory). */
  tu_rng r;
  tu_rng_seed (&r, 23);
  for (int k = 0; k < 10000; k++)
    {
      double m = pow (10.0, tu_uniform (&r, -6, 6)) * 2.385;
      double I = pow (10.0, tu_uniform (&r, -6, 6)) * 0.7071;
      double rho;
      ck_assert_ok (chaplygin_radius_of_gyration (m, I, &rho));
      ck_assert_rel (rho, (double) sqrt128 ((q128) I / m), DBL_EPSILON);
    }
  /* I/m overflows or underflows: sqrt(I)/sqrt(m), 1.5 ulps. */
  double rho;
  ck_assert_ok (chaplygin_radius_of_gyration (1e-10, 1e300, &rho));
  ck_assert_rel (rho, (double) sqrt128 ((q128) 1e300 / 1e-10), 2 * DBL_EPSILON);
  ck_assert_ok (chaplygin_radius_of_gyration (1e300, 1e-300, &rho));
  ck_assert_rel (rho, (double) sqrt128 ((q128) 1e-300 / 1e300), 2 * DBL_EPSILON);
  /* A point mass has rho = 0 (the massless limit of Appendix B.3). */
  ck_assert_ok (chaplygin_radius_of_gyration (2.0, 0.0, &rho));
  ck_assert (rho == 0.0);
  /* Errors. */
  ck_assert_status (chaplygin_radius_of_gyration (0.0, 1.0, &rho), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_radius_of_gyration (-1.0, 1.0, &rho), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_radius_of_gyration (1.0, -1.0, &rho), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_radius_of_gyration (NAN, 1.0, &rho), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_radius_of_gyration (1.0, INFINITY, &rho), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_radius_of_gyration (1.0, 1.0, NULL), CHAPLYGIN_EINVAL);
}
END_TEST

START_TEST (eq_2_2)
{
  /* Route 1: the definitions L = ell/rho, S = s/rho, V = v/v0,
     Omega = omega rho/v0, tau = t v0/rho, evaluated here in binary128.
     Route 2: invariance under a change of units (metres to centimetres
     and seconds to minutes): the nondimensional state must not change. */
  double rho = 0.3725, v0 = 2.385;
  chaplygin_smooth_dim d = { 0.52, 3.3, -1.75, 0.41, 4.2, 0.8 };
  chaplygin_smooth_nondim n, n2;
  ck_assert_ok (chaplygin_smooth_nondimensionalize (rho, v0, &d, &n));
  ck_assert_rel (n.L, (double) ((q128) d.ell / rho), DBL_EPSILON / 2);
  ck_assert_rel (n.S, (double) ((q128) d.s / rho), DBL_EPSILON / 2);
  ck_assert_rel (n.V, (double) ((q128) d.v / v0), DBL_EPSILON / 2);
  ck_assert (n.theta == d.theta);
  ck_assert_rel (n.Omega, (double) ((q128) d.omega * rho / v0), 1.5 * DBL_EPSILON);
  ck_assert_rel (n.tau, (double) ((q128) d.t * v0 / rho), 1.5 * DBL_EPSILON);
  /* centimetres and minutes: lengths x100, times /60, speeds x6000,
     rates x60. */
  chaplygin_smooth_dim c = { d.ell * 100, d.s * 100, d.v * 6000, d.theta,
                             d.omega * 60, d.t / 60 };
  ck_assert_ok (chaplygin_smooth_nondimensionalize (rho * 100, v0 * 6000, &c,
                                                    &n2));
  ck_assert_rel (n2.L, n.L, 2 * DBL_EPSILON);
  ck_assert_rel (n2.S, n.S, 2 * DBL_EPSILON);
  ck_assert_rel (n2.V, n.V, 2 * DBL_EPSILON);
  ck_assert_rel (n2.Omega, n.Omega, 4 * DBL_EPSILON);
  ck_assert_rel (n2.tau, n.tau, 4 * DBL_EPSILON);
  /* Round trip. */
  chaplygin_smooth_dim back;
  ck_assert_ok (chaplygin_smooth_dimensionalize (rho, v0, &n, &back));
  ck_assert_rel (back.ell, d.ell, DBL_EPSILON);
  ck_assert_rel (back.s, d.s, DBL_EPSILON);
  ck_assert_rel (back.v, d.v, DBL_EPSILON);
  ck_assert_rel (back.omega, d.omega, 3 * DBL_EPSILON);
  ck_assert_rel (back.t, d.t, 3 * DBL_EPSILON);
  /* Errors. */
  ck_assert_status (chaplygin_smooth_nondimensionalize (0.0, v0, &d, &n), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_smooth_nondimensionalize (rho, -1.0, &d, &n), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_smooth_nondimensionalize (rho, NAN, &d, &n), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_smooth_nondimensionalize (rho, v0, NULL, &n), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_smooth_nondimensionalize (rho, v0, &d, NULL), CHAPLYGIN_EINVAL);
  chaplygin_smooth_dim bad = d;
  bad.omega = INFINITY;
  ck_assert_status (chaplygin_smooth_nondimensionalize (rho, v0, &bad, &n), CHAPLYGIN_EDOM);
  bad = d;
  bad.s = 1e300;
  ck_assert_status (chaplygin_smooth_nondimensionalize (1e-300, v0, &bad, &n), CHAPLYGIN_ERANGE);
  chaplygin_smooth_nondim nb = n;
  nb.tau = NAN;
  ck_assert_status (chaplygin_smooth_dimensionalize (rho, v0, &nb, &back), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_smooth_dimensionalize (rho, 0.0, &n, &back), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_smooth_dimensionalize (rho, v0, &n, NULL), CHAPLYGIN_EINVAL);
  nb = n;
  nb.L = 1e300;
  ck_assert_status (chaplygin_smooth_dimensionalize (1e300, v0, &nb, &back), CHAPLYGIN_ERANGE);
}
END_TEST

START_TEST (eq_3_2)
{
  double rho = 0.81, v0 = 0.3125;
  chaplygin_discrete_dim d = { -0.45, 0.27, 0.125, 0.9, -2.0, -1.3, 12.5 };
  chaplygin_discrete_nondim n, n2;
  ck_assert_ok (chaplygin_discrete_nondimensionalize (rho, v0, &d, &n));
  ck_assert_rel (n.L0, (double) ((q128) d.ell0 / rho), DBL_EPSILON / 2);
  ck_assert_rel (n.Delta, (double) ((q128) d.delta / rho), DBL_EPSILON / 2);
  ck_assert_rel (n.D, (double) ((q128) d.d / rho), DBL_EPSILON / 2);
  ck_assert_rel (n.V, (double) ((q128) d.v / v0), DBL_EPSILON / 2);
  ck_assert (n.theta == d.theta);
  ck_assert_rel (n.Omega, (double) ((q128) d.omega * rho / v0), 1.5 * DBL_EPSILON);
  ck_assert_rel (n.tau, (double) ((q128) d.t * v0 / rho), 1.5 * DBL_EPSILON);
  /* Unit invariance: inches and milliseconds. */
  double in = 1 / 0.0254, ms = 1000;
  chaplygin_discrete_dim c = { d.ell0 * in, d.delta * in, d.d * in,
                               d.v * in / ms, d.theta, d.omega / ms, d.t * ms };
  ck_assert_ok (chaplygin_discrete_nondimensionalize (rho * in, v0 * in / ms,
                                                      &c, &n2));
  ck_assert_rel (n2.L0, n.L0, 2 * DBL_EPSILON);
  ck_assert_rel (n2.Delta, n.Delta, 2 * DBL_EPSILON);
  ck_assert_rel (n2.D, n.D, 2 * DBL_EPSILON);
  ck_assert_rel (n2.V, n.V, 3 * DBL_EPSILON);
  ck_assert_rel (n2.Omega, n.Omega, 6 * DBL_EPSILON);
  ck_assert_rel (n2.tau, n.tau, 6 * DBL_EPSILON);
  chaplygin_discrete_dim back;
  ck_assert_ok (chaplygin_discrete_dimensionalize (rho, v0, &n, &back));
  ck_assert_rel (back.ell0, d.ell0, DBL_EPSILON);
  ck_assert_rel (back.delta, d.delta, DBL_EPSILON);
  ck_assert_rel (back.d, d.d, DBL_EPSILON);
  ck_assert_rel (back.v, d.v, DBL_EPSILON);
  ck_assert_rel (back.omega, d.omega, 3 * DBL_EPSILON);
  ck_assert_rel (back.t, d.t, 3 * DBL_EPSILON);
  ck_assert_status (chaplygin_discrete_nondimensionalize (-rho, v0, &d, &n), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_discrete_nondimensionalize (rho, v0, NULL, &n), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_discrete_nondimensionalize (rho, v0, &d, NULL), CHAPLYGIN_EINVAL);
  chaplygin_discrete_dim bad = d;
  bad.t = NAN;
  ck_assert_status (chaplygin_discrete_nondimensionalize (rho, v0, &bad, &n), CHAPLYGIN_EDOM);
  bad = d;
  bad.d = 1e300;
  ck_assert_status (chaplygin_discrete_nondimensionalize (1e-300, v0, &bad, &n), CHAPLYGIN_ERANGE);
  chaplygin_discrete_nondim nb = n;
  nb.Omega = INFINITY;
  ck_assert_status (chaplygin_discrete_dimensionalize (rho, v0, &nb, &back), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_discrete_dimensionalize (INFINITY, v0, &n, &back), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_discrete_dimensionalize (rho, v0, NULL, &back), CHAPLYGIN_EINVAL);
  nb = n;
  nb.D = 1e300;
  ck_assert_status (chaplygin_discrete_dimensionalize (1e300, v0, &nb, &back), CHAPLYGIN_ERANGE);
}
END_TEST

START_TEST (test_energy_momentum_scales)
{
  /* Route: the kinetic energy and the angular momentum about the peg of a
     rigid body in dimensional form -- T = m |v_G|^2/2 + I omega^2/2,
     h = I omega + m (G - P) x v_G, with v_G = v e_lambda + ell omega e_n
     built as a vector at heading theta -- scaled by these functions, must
     equal (3.3) and (3.4) of the nondimensional state. */
  double m = 3.5, I = 0.42, v0 = 1.6, rho;
  ck_assert_ok (chaplygin_radius_of_gyration (m, I, &rho));
  double ell0 = -0.21, d = 0.13, v = -0.7, omega = 2.9, theta = 0.6;
  double el[2] = { cos (theta), sin (theta) }, en[2] = { -el[1], el[0] };
  double ell = ell0 + d;
  double vG[2] = { v * el[0] + ell * omega * en[0], v * el[1] + ell * omega * en[1] };
  double GP[2] = { ell * el[0], ell * el[1] };          /* G - P */
  double T = 0.5 * m * (vG[0] * vG[0] + vG[1] * vG[1]) + 0.5 * I * omega * omega;
  double h = I * omega + m * (GP[0] * vG[1] - GP[1] * vG[0]);
  double E, H, E3, H4;
  ck_assert_ok (chaplygin_energy_nondimensionalize (m, v0, T, &E));
  ck_assert_ok (chaplygin_momentum_nondimensionalize (m, rho, v0, h, &H));
  chaplygin_discrete_dim dd = { ell0, 1.0, d, v, theta, omega, 0.0 };
  chaplygin_discrete_nondim n;
  ck_assert_ok (chaplygin_discrete_nondimensionalize (rho, v0, &dd, &n));
  ck_assert_ok (chaplygin_discrete_energy (n.L0, n.D, n.V, n.Omega, &E3));
  ck_assert_ok (chaplygin_discrete_momentum (n.L0, n.D, n.Omega, &H4));
  /* a dozen roundings on each side, terms of one sign: 16 eps */
  ck_assert_rel (E, E3, 16 * DBL_EPSILON);
  ck_assert_rel (H, H4, 16 * DBL_EPSILON);
  ck_assert_status (chaplygin_energy_nondimensionalize (0.0, v0, T, &E), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_energy_nondimensionalize (m, v0, NAN, &E), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_energy_nondimensionalize (m, v0, T, NULL), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_energy_nondimensionalize (1e-300, 1e-10, 1e300, &E), CHAPLYGIN_ERANGE);
  ck_assert_status (chaplygin_momentum_nondimensionalize (m, 0.0, v0, h, &H), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_momentum_nondimensionalize (m, rho, v0, INFINITY, &H), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_momentum_nondimensionalize (m, rho, v0, h, NULL), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_momentum_nondimensionalize (1e-300, 1e-10, 1e-10, 1e300, &H), CHAPLYGIN_ERANGE);
}
END_TEST

START_TEST (test_every_field_validated)
{
  /* Each field in turn NaN or Inf: EDOM, output untouched. */
  for (int f = 0; f < 6; f++)
    for (int v = 0; v < 2; v++)
      {
        double bad = v ? (double) NAN : (double) INFINITY;
        double a[6] = { 0.5, 1.0, 0.25, 0.1, 2.0, 3.0 };
        a[f] = bad;
        chaplygin_smooth_dim d = { a[0], a[1], a[2], a[3], a[4], a[5] };
        chaplygin_smooth_nondim n = { 9, 9, 9, 9, 9, 9 };
        ck_assert_status (chaplygin_smooth_nondimensionalize (1, 1, &d, &n), CHAPLYGIN_EDOM);
        ck_assert (n.L == 9 && n.tau == 9);
        chaplygin_smooth_nondim nn = { a[0], a[1], a[2], a[3], a[4], a[5] };
        ck_assert_status (chaplygin_smooth_dimensionalize (1, 1, &nn, &d), CHAPLYGIN_EDOM);
      }
  for (int f = 0; f < 7; f++)
    for (int v = 0; v < 2; v++)
      {
        double bad = v ? (double) NAN : (double) -INFINITY;
        double a[7] = { 0.5, 1.0, 0.25, 0.1, 2.0, 3.0, 4.0 };
        a[f] = bad;
        chaplygin_discrete_dim d = { a[0], a[1], a[2], a[3], a[4], a[5], a[6] };
        chaplygin_discrete_nondim n = { 9, 9, 9, 9, 9, 9, 9 };
        ck_assert_status (chaplygin_discrete_nondimensionalize (1, 1, &d, &n), CHAPLYGIN_EDOM);
        ck_assert (n.L0 == 9 && n.tau == 9);
        chaplygin_discrete_nondim nn = { a[0], a[1], a[2], a[3], a[4], a[5], a[6] };
        ck_assert_status (chaplygin_discrete_dimensionalize (1, 1, &nn, &d), CHAPLYGIN_EDOM);
      }
  /* overflow in each output: tiny rho or v0 */
  chaplygin_smooth_dim d = { 1, 1, 1, 1, 1, 1 };
  chaplygin_smooth_nondim n;
  for (int f = 0; f < 6; f++)
    {
      double a[6] = { 1, 1, 1, 1, 1, 1 };
      a[f] = 1e300;
      chaplygin_smooth_dim dd = { a[0], a[1], a[2], a[3], a[4], a[5] };
      double rho = (f == 4) ? 1e300 : 1e-300, v0 = (f == 2 || f == 4) ? 1e-300 : 1e300;
      if (f == 3)
        continue;               /* theta is not scaled */
      ck_assert_status (chaplygin_smooth_nondimensionalize (rho, v0, &dd, &n), CHAPLYGIN_ERANGE);
    }
  (void) d;
  for (int f = 0; f < 6; f++)
    {
      double a[6] = { 1, 1, 1, 1, 1, 1 };
      a[f] = 1e300;
      chaplygin_smooth_nondim nn = { a[0], a[1], a[2], a[3], a[4], a[5] };
      double rho = (f == 5) ? 1e300 : 1e300, v0 = (f == 2 || f == 4) ? 1e300 : 1e-300;
      if (f == 3)
        continue;
      if (f == 5)
        v0 = 1e-300;
      chaplygin_smooth_dim out;
      int st = chaplygin_smooth_dimensionalize (f == 4 ? 1e-300 : rho, v0, &nn, &out);
      ck_assert_status (st, CHAPLYGIN_ERANGE);
    }
}
END_TEST

int
main (void)
{
  Suite *s = suite_create ("units");
  TCase *t;
  t = tcase_create ("eq_2_2");
  tcase_add_test (t, eq_2_2);
  suite_add_tcase (s, t);
  t = tcase_create ("eq_2_3");
  tcase_add_test (t, eq_2_3);
  suite_add_tcase (s, t);
  t = tcase_create ("eq_3_2");
  tcase_add_test (t, eq_3_2);
  suite_add_tcase (s, t);
  t = tcase_create ("validation");
  tcase_add_test (t, test_every_field_validated);
  suite_add_tcase (s, t);
  t = tcase_create ("scales");
  tcase_add_test (t, test_energy_momentum_scales);
  suite_add_tcase (s, t);
  return tu_run (s);
}
