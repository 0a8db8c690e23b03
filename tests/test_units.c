/* test_units.c -- lib/units.c: (2.2), (2.3), (3.2) and the energy and
   momentum scales. */
#include <config.h>

#include <stdlib.h>
#include <string.h>

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

/* ---- the velocity scaling ----------------------------------------------- */

/* x 2^e in binary128 (exact: its exponent range holds 2^+-16000). */
static q128
ldexp128 (q128 x, int e)
{
  while (e > 0)
    x *= 2, e--;
  while (e < 0)
    x /= 2, e++;
  return x;
}

/* The speed max(|V|, sqrt(1 + l0^2) |Omega|) in binary128. */
static q128
speed128 (double l0, double V, double Omega)
{
  q128 a = fabs (V), b = sqrt128 (1 + (q128) l0 * l0) * fabs (Omega);
  return a > b ? a : b;
}

START_TEST (test_velocity_scaling)
{
  /* Route: the contract stated independently in binary128, whose exponent
     range holds every E and H of a double phase state: m = 0 exactly where
     the speed sp is in [2^-400, 2^450/max(1, |l0|)]; otherwise 2^m sp in
     [1, 2), V and Omega scaled without a lost bit, and E (3.3), H (3.4) of
     the scaled state those of the given one times 4^m, 2^m (the library's
     3 ulps of chaplygin_discrete_energy, 1.5 of chaplygin_discrete_momentum,
     plus the rounding of sqrt(1 + l0^2) in the speed: 4 eps), E in
     [1/2, 4) and |H| below 2 sqrt(1 + l0^2). */
  static const struct
  {
    double l0, V, Omega;
    int scaled;
  } c[] = {
    { -0.5, 1e-300, 1.0, 0 },             /* slow, not tiny: V+ in the state */
    { 0.7071, 2.385, -0.5, 0 },
    { -0.5, 2.385e-200, 2.385e-200, 1 },
    { 1.7, -1.3e-300, 0.61e-300, 1 },
    { 0.3, 4.9406564584124654e-324, 0.0, 1 },  /* the smallest subnormal */
    { -0.25, -1e-310, 2.385e-309, 1 },    /* subnormal V and Omega */
    { 0.3, 1e200, 1e200, 1 },
    { 0.3, -1.5e308, 0.0, 1 },
    { 0.0, 0.0, -1.7e308, 1 },
    { 1e200, 1.0, 1.0, 1 },               /* |l0| Omega beyond 2^450 */
    { -3e150, 2.385e-10, 0.0, 1 },
    { 2.0, 0x1p-400, 0.0, 0 },            /* the bounds, exactly */
    { 2.0, -0x1.fffffffffffffp-401, 0.0, 1 },
    { 0.0, 0x1p450, 0.0, 0 },
    { 0.0, 0x1.0000000000001p450, 0.0, 1 },
    { 0.0, 0.0, 0.0, 0 },                 /* no speed: nothing to scale */
    { 1.0, 1.7e308, -1.7e308, 1 },        /* the speed overflows: 2^1024 */
    { 0.0, -0x1.fffffffffffffp1023, 0x1.fffffffffffffp1023, 1 },
    { 1e300, 1.0, 2.385e10, 1 },          /* sqrt(1 + l0^2) Omega too */
  };
  for (size_t i = 0; i < sizeof c / sizeof c[0]; i++)
    {
      int m = 12345;
      double Vs = 0, Os = 0;
      ck_assert_ok (chaplygin_velocity_scaling (c[i].l0, c[i].V, c[i].Omega,
                                                &m, &Vs, &Os));
      ck_assert_msg ((m != 0) == c[i].scaled, "case %zu: m = %d", i, m);
      /* exact: the scaled values are the given ones times 2^m in binary128 */
      ck_assert ((q128) Vs == ldexp128 (c[i].V, m));
      ck_assert ((q128) Os == ldexp128 (c[i].Omega, m));
      if (!c[i].scaled)
        continue;
      q128 sp = speed128 (c[i].l0, Vs, Os);
      ck_assert_msg (sp >= 1 && sp < 2, "case %zu: scaled speed %g", i,
                     (double) sp);
      double E, H;
      ck_assert_ok (chaplygin_discrete_energy (c[i].l0, 0.0, Vs, Os, &E));
      ck_assert_ok (chaplygin_discrete_momentum (c[i].l0, 0.0, Os, &H));
      q128 n = 1 + (q128) c[i].l0 * c[i].l0;
      q128 E128 = ((q128) c[i].V * c[i].V + n * c[i].Omega * c[i].Omega) / 2;
      ck_assert_rel (E, (double) ldexp128 (E128, 2 * m), 4 * DBL_EPSILON);
      ck_assert_rel (H, (double) ldexp128 (n * c[i].Omega, m), 4 * DBL_EPSILON);
      /* sp in [1, 2): E = (V^2 + (1 + l0^2) Omega^2)/2 in [1/2, 4) and
         |H| = sqrt(1 + l0^2) (sqrt(1 + l0^2) |Omega|) < 2 sqrt(1 + l0^2) */
      ck_assert (E >= 0.5 && E < 4 && fabs (H) < 2 * sqrt ((double) n));
    }

  /* A state the map refuses unscaled (E underflows: ERANGE) runs scaled:
     V = Omega = 1e-200 at L0 = -0.5, Delta = 1 (issue 16). */
  chaplygin_discrete sys;
  chaplygin_discrete_state st;
  ck_assert_ok (chaplygin_discrete_init (&sys, -0.5, 1.0));
  double q[4] = { 0.0, 1e-200, 0.0, 1e-200 };
  ck_assert_status (chaplygin_discrete_state_from_phase (&sys, q, 0, NULL, &st),
                    CHAPLYGIN_ERANGE);
  int m;
  ck_assert_ok (chaplygin_velocity_scaling (-0.5, q[1], q[3], &m, &q[1], &q[3]));
  ck_assert_ok (chaplygin_discrete_state_from_phase (&sys, q, 0, NULL, &st));

  /* Errors; outputs untouched. */
  double Vs = 7, Os = 7;
  m = 7;
  ck_assert_status (chaplygin_velocity_scaling (NAN, 1, 1, &m, &Vs, &Os), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_velocity_scaling (0, INFINITY, 1, &m, &Vs, &Os), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_velocity_scaling (0, 1, -INFINITY, &m, &Vs, &Os), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_velocity_scaling (0, 1, 1, NULL, &Vs, &Os), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_velocity_scaling (0, 1, 1, &m, NULL, &Os), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_velocity_scaling (0, 1, 1, &m, &Vs, NULL), CHAPLYGIN_EINVAL);
  /* V below 2^-1074 of the speed 1e300: 2^m V would lose its bits */
  ck_assert_status (chaplygin_velocity_scaling (0, 1e-300, 1e300, &m, &Vs, &Os),
                    CHAPLYGIN_ERANGE);
  ck_assert (m == 7 && Vs == 7 && Os == 7);
}
END_TEST

START_TEST (test_velocity_scale)
{
  /* Route: binary128 (exact powers of two, no range limit) against
     ldexp-based scaling: exact where representable, the correctly rounded
     value with *exact = 0 below DBL_MIN, ERANGE beyond DBL_MAX. */
  static const int d[4] = { 0, 1, 2, -1 };       /* the degrees */
  static const double x[] = { 2.385, -0.61, 1.3e-300, -4.2e300, 0.0,
                              4.9406564584124654e-324, 0x1.fffffffffffffp-1 };
  static const int ms[] = { 0, 1, -1, 996, -996, 1074, -1074, 2000, -2000,
                            4096, -4096 };
  for (int k = 0; k < 4; k++)
    for (size_t i = 0; i < sizeof ms / sizeof ms[0]; i++)
      {
        int e;
        ck_assert_ok (chaplygin_velocity_exponent (ms[i], (chaplygin_scale_kind) k, &e));
        ck_assert_int_eq (e, d[k] * ms[i]);
        for (size_t j = 0; j < sizeof x / sizeof x[0]; j++)
          {
            q128 want = ldexp128 (x[j], e);
            double y = 99;
            int exact = 99;
            int status = chaplygin_velocity_scale (ms[i], (chaplygin_scale_kind) k,
                                                   x[j], &y, &exact);
            if (fabsl ((long double) want) > (long double) DBL_MAX)
              {
                ck_assert_status (status, CHAPLYGIN_ERANGE);
                ck_assert (y == 99 && exact == 99);
                continue;
              }
            ck_assert_ok (status);
            ck_assert ((q128) y == (q128) (double) want);        /* rounded */
            ck_assert_int_eq (exact, (q128) y == want);
            if (exact)
              {
                /* and back, exactly */
                double z;
                int ex2;
                ck_assert_ok (chaplygin_velocity_scale (-ms[i], (chaplygin_scale_kind) k,
                                                        y, &z, &ex2));
                ck_assert (z == x[j] && ex2 == 1);
              }
          }
      }
  /* a subnormal result loses bits: 2.385 E-scaled by 4^-520 */
  double y;
  int exact;
  ck_assert_ok (chaplygin_velocity_scale (-520, CHAPLYGIN_SCALE_ENERGY, 2.385, &y, &exact));
  ck_assert (exact == 0 && y > 0 && y < DBL_MIN);
  ck_assert_ok (chaplygin_velocity_scale (-520, CHAPLYGIN_SCALE_SPEED, 2.385, &y, &exact));
  ck_assert (exact == 1 && y == ldexp (2.385, -520));
  ck_assert_ok (chaplygin_velocity_scale (996, CHAPLYGIN_SCALE_NONE, -2.385, &y, &exact));
  ck_assert (exact == 1 && y == -2.385);
  ck_assert_ok (chaplygin_velocity_scale (-996, CHAPLYGIN_SCALE_TIME, 1.5, &y, &exact));
  ck_assert (exact == 1 && y == ldexp (1.5, 996));
  /* Errors. */
  int e = 7;
  ck_assert_status (chaplygin_velocity_exponent (4097, CHAPLYGIN_SCALE_SPEED, &e), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_velocity_exponent (-4097, CHAPLYGIN_SCALE_NONE, &e), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_velocity_exponent (1, (chaplygin_scale_kind) 4, &e), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_velocity_exponent (1, (chaplygin_scale_kind) -1, &e), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_velocity_exponent (1, CHAPLYGIN_SCALE_TIME, NULL), CHAPLYGIN_EINVAL);
  ck_assert (e == 7);
  ck_assert_status (chaplygin_velocity_scale (1, CHAPLYGIN_SCALE_TIME, NAN, &y, &exact), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_velocity_scale (1, CHAPLYGIN_SCALE_TIME, INFINITY, &y, &exact), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_velocity_scale (5000, CHAPLYGIN_SCALE_TIME, 1, &y, &exact), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_velocity_scale (1, (chaplygin_scale_kind) 9, 1, &y, &exact), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_velocity_scale (1, CHAPLYGIN_SCALE_TIME, 1, NULL, &exact), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_velocity_scale (1, CHAPLYGIN_SCALE_TIME, 1, &y, NULL), CHAPLYGIN_EINVAL);
}
END_TEST

START_TEST (test_velocity_homogeneity)
{
  /* Route: what the scaling is for.  The return map of a tiny or huge
     state, run scaled by chaplygin_velocity_scaling and scaled back, against
     the run of the same state scaled by another power of two chosen here
     (2^k V, 2^k Omega with 2^k sp near 1/8, inside the unscaled range, run
     unscaled) and scaled back from it: two different exact scalings of one
     motion, so every column agrees to the map's own rounding differences
     (the two runs round the same operations on values differing by a power
     of two: identical unless a branch depends on a magnitude; measured:
     bit for bit here) -- 4 eps per quantity, over 12 collisions, with
     reversals for L0 = -0.5, Delta = 1. */
  static const struct
  {
    double L0, Delta, V, Omega;
  } c[] = {
    { -0.5, 1.0, 1e-300, 1e-300 },
    { -0.5, 1.0, -2.385e-200, 1e-200 },
    { 1.0, 1.0 / 3, 1e200, 0.5e200 },
    { -1.3, 0.7, 0.3e-250, -1.1e-250 },
  };
  for (size_t i = 0; i < sizeof c / sizeof c[0]; i++)
    {
      chaplygin_discrete sys;
      ck_assert_ok (chaplygin_discrete_init (&sys, c[i].L0, c[i].Delta));
      const double D0 = c[i].V > 0 ? 0.0 : c[i].Delta;
      int m;
      double Vs, Os;
      ck_assert_ok (chaplygin_velocity_scaling (c[i].L0 + D0, c[i].V, c[i].Omega,
                                                &m, &Vs, &Os));
      ck_assert (m != 0);
      const int k = m - 3;                   /* another scaling, unscaled run */
      double qa[4] = { D0, Vs, 0.0, Os };
      double qb[4] = { D0, ldexp (c[i].V, k), 0.0, ldexp (c[i].Omega, k) };
      int mb;
      double t1, t2;
      ck_assert_ok (chaplygin_velocity_scaling (c[i].L0 + D0, qb[1], qb[3], &mb, &t1, &t2));
      ck_assert_int_eq (mb, 0);
      chaplygin_discrete_state a, b;
      ck_assert_ok (chaplygin_discrete_state_from_phase (&sys, qa, 0, NULL, &a));
      ck_assert_ok (chaplygin_discrete_state_from_phase (&sys, qb, 0, NULL, &b));
      for (int n = 1; n <= 12; n++)
        {
          ck_assert_ok (chaplygin_discrete_step (&sys, &a, CHAPLYGIN_WANT_ALL, NULL, &a, NULL));
          ck_assert_ok (chaplygin_discrete_step (&sys, &b, CHAPLYGIN_WANT_ALL, NULL, &b, NULL));
          /* physical values in binary128: a's times 2^-m (degree d), b's
             times 2^-k */
          ck_assert (a.dir == b.dir);
          ck_assert_rel ((double) ldexp128 (ldexp128 (a.E, -2 * m), 2 * k), b.E, 4 * DBL_EPSILON);
          ck_assert_rel ((double) ldexp128 (ldexp128 (a.H, -m), k), b.H, 4 * DBL_EPSILON);
          ck_assert_rel ((double) ldexp128 (ldexp128 (a.V, -m), k), b.V, 4 * DBL_EPSILON);
          ck_assert_rel ((double) ldexp128 (ldexp128 (a.tau, m), -k), b.tau, 4 * DBL_EPSILON);
          ck_assert_rel (a.theta, b.theta, 4 * DBL_EPSILON);
          ck_assert_rel (a.peg[0], b.peg[0], 4 * DBL_EPSILON);
          ck_assert_rel (a.peg[1], b.peg[1], 4 * DBL_EPSILON);
        }
    }
}
END_TEST


/* Whether A and B hold the same bits field by field (not their padding). */
static int
same_state (const chaplygin_discrete_state *a,
            const chaplygin_discrete_state *b)
{
#define SAME(f) (memcmp (&a->f, &b->f, sizeof a->f) == 0)
  return SAME (dir) && SAME (E) && SAME (H) && SAME (theta) && SAME (tau)
    && SAME (peg) && SAME (V);
#undef SAME
}

/* chaplygin_discrete_scaled_state (issue 26: the one sequence of the
   velocity scaling before a run).  Routes: where E and H are in range, m
   = 0 and the state is chaplygin_discrete_state_from_phase's bit for bit;
   for tiny and huge starts, qs = 2^m q exactly (ldexp of the inputs), st
   = state_from_phase of qs bit for bit, and E 2^-2m, H 2^-m equal (3.3),
   (3.4) of the unscaled q in binary128 within 4 eps (the scaled
   computation rounds as the unscaled one would, in range). */
START_TEST (test_scaled_state)
{
  chaplygin_discrete sys;
  chaplygin_discrete_state st, ref;
  const double L0 = -0.3, Delta = 1.0 / 3.0;
  ck_assert_ok (chaplygin_discrete_init (&sys, L0, Delta));
  static const double scales[] = { 1.0, 1e-300, 1e-200, 1e200, 2.5e250 };
  for (size_t k = 0; k < NELEM (scales); k++)
    for (int dir = -1; dir <= 1; dir += 2)
      {
        const double D = dir > 0 ? 0.0 : Delta;
        const double q[4] = { D, dir * 0.7 * scales[k], 2.385,
                              -1.25 * scales[k] };
        const double peg[2] = { 0.5, -2.0 };
        double qs[4], E, H;
        int m = 999;
        ck_assert_ok (chaplygin_discrete_scaled_state (&sys, q, 3.0, peg,
                                                       &st, &m, qs));
        ck_assert_int_eq (m != 0, k != 0);
        ck_assert (qs[CHAPLYGIN_D] == D && qs[CHAPLYGIN_THETA] == 2.385);
        ck_assert (qs[CHAPLYGIN_V] == ldexp (q[CHAPLYGIN_V], m));
        ck_assert (qs[CHAPLYGIN_OMEGA] == ldexp (q[CHAPLYGIN_OMEGA], m));
        ck_assert_ok (chaplygin_discrete_state_from_phase (&sys, qs,
                                                           ldexp (3.0, -m),
                                                           peg, &ref));
        ck_assert (same_state (&st, &ref));
        const q128 l = (q128) L0 + D, V = q[CHAPLYGIN_V],
          Om = q[CHAPLYGIN_OMEGA];
        E = (double) ((V * V + (1 + l * l) * Om * Om) / 2
                      * (q128) ldexp (1.0, m) * (q128) ldexp (1.0, m));
        H = (double) ((1 + l * l) * Om * (q128) ldexp (1.0, m));
        ck_assert_rel (st.E, E, 4 * DBL_EPSILON);
        ck_assert_rel (st.H, H, 4 * DBL_EPSILON);
        ck_assert_int_eq (st.dir, dir);
        /* qs may be NULL */
        ck_assert_ok (chaplygin_discrete_scaled_state (&sys, q, 3.0, peg,
                                                       &ref, &m, NULL));
        ck_assert (same_state (&st, &ref));
      }
  /* errors, nothing written */
  const double good[4] = { 0.0, 1.0, 0.0, 0.5 };
  const double zero_v[4] = { 0.0, 0.0, 0.0, 0.5 };
  const double wrong_end[4] = { Delta, 1.0, 0.0, 0.5 };
  const double nan_v[4] = { 0.0, NAN, 0.0, 0.5 };
  const double apart[4] = { 0.0, 1e-300, 0.0, 1e300 };
  chaplygin_discrete_state keep = st;
  int m = 77;
  ck_assert_status (chaplygin_discrete_scaled_state (NULL, good, 0, NULL, &st, &m, NULL), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_discrete_scaled_state (&sys, NULL, 0, NULL, &st, &m, NULL), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_discrete_scaled_state (&sys, good, 0, NULL, NULL, &m, NULL), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_discrete_scaled_state (&sys, good, 0, NULL, &st, NULL, NULL), CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_discrete_scaled_state (&sys, nan_v, 0, NULL, &st, &m, NULL), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_discrete_scaled_state (&sys, zero_v, 0, NULL, &st, &m, NULL), CHAPLYGIN_ESTATE);
  ck_assert_status (chaplygin_discrete_scaled_state (&sys, wrong_end, 0, NULL, &st, &m, NULL), CHAPLYGIN_ESTATE);
  ck_assert_status (chaplygin_discrete_scaled_state (&sys, apart, 0, NULL, &st, &m, NULL), CHAPLYGIN_ERANGE);
  ck_assert (same_state (&st, &keep) && m == 77);
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
  t = tcase_create ("velocity_scaling");
  tcase_add_test (t, test_velocity_scaling);
  tcase_add_test (t, test_velocity_scale);
  tcase_add_test (t, test_velocity_homogeneity);
  tcase_add_test (t, test_scaled_state);
  suite_add_tcase (s, t);
  return tu_run (s);
}
