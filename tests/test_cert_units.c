/* test_cert_units.c -- the certified units and field (lib/cert-units.c):
   (2.2), (2.3), (3.1), (3.2), against a route written here:
   - every field in GMP's exact rationals (the library: FLINT's), the
     scalings grouped as printed, omega (rho/v0) and t (v0/rho) (the
     library: one factor at a time); (3.1)'s 2l/(1 + l^2) as
     1 - (l - 1)^2/(1 + l^2);
   - each rounded to binary64 by MPFR (certref.c), so that the exact ties
     built on purpose check ties to even;
   - (2.3)'s sqrt(I/m) by MPFR at 2000 bits as sqrt(I)/sqrt(m), or, where
     I/m is the square of a rational, exactly (GMP's mpz_perfect_square_p);
   plus the uncertified functions within their documented ulps, and the
   error statuses.  0 ulps is required of the certified functions. */
#include <config.h>

#include <float.h>
#include <math.h>

#include <gmp.h>
#include <mpfr.h>

#include "testutil.h"
#include "certref.h"
#include "chaplygin.h"

enum { RP = 2000 };             /* the irrational route's precision */

/* *Y = the double nearest to X rho^A v0^B (A, B in {-1, 0, 1}), by the
   printed grouping: lengths X/rho, speeds X/v0, rates X (rho/v0), times
   X (v0/rho), and their inverses. */
static double
scaled (const double x[2], const double rho[2], const double v0[2], int a,
        int b)
{
  mpq_t q, r, v, f;
  mpq_inits (q, r, v, f, NULL);
  cr_q_of (q, x);
  cr_q_of (r, rho);
  cr_q_of (v, v0);
  mpq_set_ui (f, 1, 1);
  if (a > 0)
    mpq_mul (f, f, r);
  if (b > 0)
    mpq_mul (f, f, v);
  if (a < 0)
    mpq_div (f, f, r);
  if (b < 0)
    mpq_div (f, f, v);
  mpq_mul (q, q, f);
  const double y = cr_round_q (q);
  mpq_clears (q, r, v, f, NULL);
  return y;
}

/* ---- (2.2) ------------------------------------------------------------ */

START_TEST (certified_2_2)
{
  tu_rng g;
  tu_rng_seed (&g, 22);
  for (int i = 0; i < 2000; i++)
    {
      double rho[2], v0[2], x[6][2];
      cr_ratio_in (&g, 0.01, 3.0, rho);
      cr_ratio_in (&g, 0.1, 10.0, v0);
      for (int k = 0; k < 6; k++)
        cr_ratio_in (&g, -5.0, 5.0, x[k]);
      chaplygin_smooth_nondim nd;
      chaplygin_smooth_dim d;
      ck_assert_ok (chaplygin_certified_smooth_nondimensionalize
                    (rho, v0, x[0], x[1], x[2], x[3], x[4], x[5], &nd));
      ck_assert_same (nd.L, scaled (x[0], rho, v0, -1, 0));
      ck_assert_same (nd.S, scaled (x[1], rho, v0, -1, 0));
      ck_assert_same (nd.V, scaled (x[2], rho, v0, 0, -1));
      ck_assert_same (nd.theta, scaled (x[3], rho, v0, 0, 0));
      ck_assert_same (nd.Omega, scaled (x[4], rho, v0, 1, -1));
      ck_assert_same (nd.tau, scaled (x[5], rho, v0, -1, 1));
      ck_assert_ok (chaplygin_certified_smooth_dimensionalize
                    (rho, v0, x[0], x[1], x[2], x[3], x[4], x[5], &d));
      ck_assert_same (d.ell, scaled (x[0], rho, v0, 1, 0));
      ck_assert_same (d.s, scaled (x[1], rho, v0, 1, 0));
      ck_assert_same (d.v, scaled (x[2], rho, v0, 0, 1));
      ck_assert_same (d.theta, scaled (x[3], rho, v0, 0, 0));
      ck_assert_same (d.omega, scaled (x[4], rho, v0, -1, 1));
      ck_assert_same (d.t, scaled (x[5], rho, v0, 1, -1));
      /* the uncertified function at double inputs: within its 1.5 ulps
         (chaplygin_smooth_nondimensionalize's documented accuracy) */
      const chaplygin_smooth_dim dd = { x[0][0], x[1][0], x[2][0],
                                        x[3][0], x[4][0], x[5][0] };
      const double r1[2] = { rho[0], 1.0 }, v1[2] = { v0[0], 1.0 };
      const double a[6][2] = { { dd.ell, 1 }, { dd.s, 1 }, { dd.v, 1 },
                               { dd.theta, 1 }, { dd.omega, 1 },
                               { dd.t, 1 } };
      chaplygin_smooth_nondim u, c;
      ck_assert_ok (chaplygin_smooth_nondimensionalize (rho[0], v0[0], &dd,
                                                        &u));
      ck_assert_ok (chaplygin_certified_smooth_nondimensionalize
                    (r1, v1, a[0], a[1], a[2], a[3], a[4], a[5], &c));
      ck_assert_ulps (u.L, c.L, 0.5);
      ck_assert_ulps (u.Omega, c.Omega, 1.5);
      ck_assert_ulps (u.tau, c.tau, 1.5);
    }

  /* a tie: Omega = omega rho/v0 = 2^54 - 1, halfway between 2^54 - 2
     (odd significand) and 2^54 (even): 2^54 */
  const double w[2] = { 0x1p27 + 1, 1 }, r[2] = { 0x1p27 - 1, 1 },
    one[2] = { 1, 1 }, zero[2] = { 0, 1 };
  chaplygin_smooth_nondim nd;
  ck_assert_ok (chaplygin_certified_smooth_nondimensionalize
                (r, one, zero, zero, zero, zero, w, zero, &nd));
  ck_assert_same (nd.Omega, 0x1p54);
  ck_assert_same (nd.Omega, scaled (w, r, one, 1, -1));
  /* 1/3 exactly, not the double nearest it: L = (1/3)/(1/5) = 5/3 */
  const double third[2] = { 1, 3 }, fifth[2] = { 1, 5 };
  ck_assert_ok (chaplygin_certified_smooth_nondimensionalize
                (fifth, one, third, zero, zero, zero, zero, zero, &nd));
  ck_assert_same (nd.L, 5.0 / 3.0);
  /* a length below the subnormals rounds to 0; beyond DBL_MAX: ERANGE,
     nothing written */
  const double tiny[2] = { 0x1p-1074, 1 }, big[2] = { 0x1p1000, 1 },
    huge[2] = { 0x1p-100, 1 };
  ck_assert_ok (chaplygin_certified_smooth_nondimensionalize
                (big, one, tiny, zero, zero, zero, zero, zero, &nd));
  ck_assert_same (nd.L, 0.0);
  nd.L = 7.0;
  ck_assert_status (chaplygin_certified_smooth_nondimensionalize
                    (huge, one, big, zero, zero, zero, zero, zero, &nd),
                    CHAPLYGIN_ERANGE);
  ck_assert_same (nd.L, 7.0);
  /* errors */
  const double neg[2] = { -1, 1 }, nan_[2] = { NAN, 1 }, z0[2] = { 1, 0 };
  chaplygin_smooth_dim d;
  ck_assert_status (chaplygin_certified_smooth_nondimensionalize
                    (neg, one, one, one, one, one, one, one, &nd),
                    CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_certified_smooth_dimensionalize
                    (one, zero, one, one, one, one, one, one, &d),
                    CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_certified_smooth_dimensionalize
                    (one, one, one, nan_, one, one, one, one, &d),
                    CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_certified_smooth_dimensionalize
                    (one, one, one, one, z0, one, one, one, &d),
                    CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_certified_smooth_dimensionalize
                    (one, one, NULL, one, one, one, one, one, &d),
                    CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_certified_smooth_nondimensionalize
                    (one, one, one, one, one, one, one, one, NULL),
                    CHAPLYGIN_EINVAL);
}
END_TEST

/* ---- (3.2) ------------------------------------------------------------ */

START_TEST (certified_3_2)
{
  tu_rng g;
  tu_rng_seed (&g, 32);
  for (int i = 0; i < 2000; i++)
    {
      double rho[2], v0[2], x[7][2];
      cr_ratio_in (&g, 0.01, 3.0, rho);
      cr_ratio_in (&g, 0.1, 10.0, v0);
      for (int k = 0; k < 7; k++)
        cr_ratio_in (&g, -5.0, 5.0, x[k]);
      chaplygin_discrete_nondim nd;
      chaplygin_discrete_dim d;
      ck_assert_ok (chaplygin_certified_discrete_nondimensionalize
                    (rho, v0, x[0], x[1], x[2], x[3], x[4], x[5], x[6],
                     &nd));
      ck_assert_same (nd.L0, scaled (x[0], rho, v0, -1, 0));
      ck_assert_same (nd.Delta, scaled (x[1], rho, v0, -1, 0));
      ck_assert_same (nd.D, scaled (x[2], rho, v0, -1, 0));
      ck_assert_same (nd.V, scaled (x[3], rho, v0, 0, -1));
      ck_assert_same (nd.theta, scaled (x[4], rho, v0, 0, 0));
      ck_assert_same (nd.Omega, scaled (x[5], rho, v0, 1, -1));
      ck_assert_same (nd.tau, scaled (x[6], rho, v0, -1, 1));
      ck_assert_ok (chaplygin_certified_discrete_dimensionalize
                    (rho, v0, x[0], x[1], x[2], x[3], x[4], x[5], x[6],
                     &d));
      ck_assert_same (d.ell0, scaled (x[0], rho, v0, 1, 0));
      ck_assert_same (d.delta, scaled (x[1], rho, v0, 1, 0));
      ck_assert_same (d.d, scaled (x[2], rho, v0, 1, 0));
      ck_assert_same (d.v, scaled (x[3], rho, v0, 0, 1));
      ck_assert_same (d.theta, scaled (x[4], rho, v0, 0, 0));
      ck_assert_same (d.omega, scaled (x[5], rho, v0, -1, 1));
      ck_assert_same (d.t, scaled (x[6], rho, v0, 1, -1));
    }
  /* the tie of (2.2), in t = tau rho/v0 = 2^54 - 1: 2^54 */
  const double a[2] = { 0x1p27 + 1, 1 }, b[2] = { 0x1p27 - 1, 1 },
    one[2] = { 1, 1 }, zero[2] = { 0, 1 };
  chaplygin_discrete_dim d;
  ck_assert_ok (chaplygin_certified_discrete_dimensionalize
                (b, one, zero, zero, zero, zero, zero, zero, a, &d));
  ck_assert_same (d.t, 0x1p54);
  ck_assert_status (chaplygin_certified_discrete_dimensionalize
                    (b, one, zero, zero, zero, zero, zero, zero, NULL, &d),
                    CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_certified_discrete_dimensionalize
                    (zero, one, zero, zero, zero, zero, zero, zero, a, &d),
                    CHAPLYGIN_EDOM);
}
END_TEST

/* ---- (2.3) ------------------------------------------------------------ */

/* The route: sqrt(I)/sqrt(m) at RP bits, or exact where I/m is a square. */
static double
rho_route (const double m[2], const double I[2])
{
  mpq_t q;
  mpq_init (q);
  cr_q_of (q, I);
  mpq_t mq;
  mpq_init (mq);
  cr_q_of (mq, m);
  mpq_div (q, q, mq);
  double r;
  if (mpz_perfect_square_p (mpq_numref (q))
      && mpz_perfect_square_p (mpq_denref (q)))
    {
      mpz_sqrt (mpq_numref (q), mpq_numref (q));
      mpz_sqrt (mpq_denref (q), mpq_denref (q));
      r = cr_round_q (q);
    }
  else
    {
      mpfr_t a, b;
      mpfr_inits2 (RP, a, b, NULL);
      mpfr_set_q (a, (cr_q_of (q, I), q), MPFR_RNDN);
      mpfr_sqrt (a, a, MPFR_RNDN);
      mpfr_set_q (b, mq, MPFR_RNDN);
      mpfr_sqrt (b, b, MPFR_RNDN);
      mpfr_div (a, a, b, MPFR_RNDN);
      r = cr_round_fr (a);
      mpfr_clears (a, b, NULL);
    }
  mpq_clears (q, mq, NULL);
  return r;
}

START_TEST (certified_2_3)
{
  tu_rng g;
  tu_rng_seed (&g, 23);
  for (int i = 0; i < 3000; i++)
    {
      double m[2], I[2], rho;
      cr_ratio_in (&g, 0.01, 100.0, m);
      cr_ratio_in (&g, 0.0, 10.0, I);
      ck_assert_ok (chaplygin_certified_radius_of_gyration (m, I, &rho));
      ck_assert_same (rho, rho_route (m, I));
      /* the uncertified one within its 1 ulp at double inputs */
      double u, c;
      ck_assert_ok (chaplygin_radius_of_gyration (m[0], I[0], &u));
      ck_assert_ok (chaplygin_certified_radius_of_gyration
                    ((const double[2]) { m[0], 1 },
                     (const double[2]) { I[0], 1 }, &c));
      ck_assert_ulps (u, c, 1.0);
    }
  /* squares: I/m = 9/4 -> 3/2; I/m = ((2^53 - 1)/2^53)^2: 1 - 2^-53, a
     double */
  double rho;
  ck_assert_ok (chaplygin_certified_radius_of_gyration
                ((const double[2]) { 4, 1 }, (const double[2]) { 9, 1 },
                 &rho));
  ck_assert_same (rho, 1.5);
  const double s = 0x1p53 - 1;
  ck_assert_ok (chaplygin_certified_radius_of_gyration
                ((const double[2]) { 0x1p53, 1 },
                 (const double[2]) { s, 0x1p53 / s }, &rho));
  ck_assert_same (rho, s / 0x1p53);
  /* no midpoint is reachable: I/m = a d/(b c) for I = a/b, m = c/d, and a
     rational square root of it has a numerator (in lowest terms) at most
     sqrt(a d) < 2^53, never a 54-bit odd significand.  I = 0: rho = 0. */
  ck_assert_ok (chaplygin_certified_radius_of_gyration
                ((const double[2]) { 2, 1 }, (const double[2]) { 0, 1 },
                 &rho));
  ck_assert_same (rho, 0.0);
  /* beyond the doubles and below them */
  ck_assert_ok (chaplygin_certified_radius_of_gyration
                ((const double[2]) { 0x1p1000, 1 },
                 (const double[2]) { 0x1p-1000, 1 }, &rho));
  ck_assert_same (rho, 0x1p-1000);
  rho = 7.0;
  ck_assert_status (chaplygin_certified_radius_of_gyration
                    ((const double[2]) { 0x1p-1074, 1 },
                     (const double[2]) { 0x1p1023, 0x1p-1074 }, &rho),
                    CHAPLYGIN_ERANGE);
  ck_assert_same (rho, 7.0);
  ck_assert_status (chaplygin_certified_radius_of_gyration
                    ((const double[2]) { 0, 1 },
                     (const double[2]) { 1, 1 }, &rho), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_certified_radius_of_gyration
                    ((const double[2]) { 1, 1 },
                     (const double[2]) { -1, 1 }, &rho), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_certified_radius_of_gyration
                    ((const double[2]) { 1, 1 }, NULL, &rho),
                    CHAPLYGIN_EINVAL);
}
END_TEST

/* ---- (3.1) ------------------------------------------------------------ */

/* The route's field: 2l/(1 + l^2) as 1 - (l - 1)^2/(1 + l^2). */
static void
field_route (const double L0[2], const double D[2], const double V[2],
             const double W[2], double dq[4])
{
  mpq_t l, v, w, t, u, f;
  mpq_inits (l, v, w, t, u, f, NULL);
  cr_q_of (l, L0);
  cr_q_of (t, D);
  mpq_add (l, l, t);
  cr_q_of (v, V);
  cr_q_of (w, W);
  dq[CHAPLYGIN_D] = cr_round_q (v);
  mpq_mul (t, w, w);
  mpq_mul (t, t, l);
  dq[CHAPLYGIN_V] = cr_round_q (t);
  dq[CHAPLYGIN_THETA] = cr_round_q (w);
  mpq_set_ui (u, 1, 1);
  mpq_sub (t, l, u);
  mpq_mul (t, t, t);            /* (l - 1)^2 */
  mpq_mul (f, l, l);
  mpq_add (f, f, u);            /* 1 + l^2 */
  mpq_div (t, t, f);
  mpq_sub (f, u, t);            /* 2l/(1 + l^2) */
  mpq_mul (f, f, v);
  mpq_mul (f, f, w);
  mpq_neg (f, f);
  dq[CHAPLYGIN_OMEGA] = cr_round_q (f);
  mpq_clears (l, v, w, t, u, f, NULL);
}

START_TEST (certified_3_1)
{
  tu_rng g;
  tu_rng_seed (&g, 31);
  for (int i = 0; i < 3000; i++)
    {
      double L0[2], D[2], V[2], W[2], dq[4], want[4];
      cr_ratio_in (&g, -3.0, 3.0, L0);
      cr_ratio_in (&g, 0.0, 2.0, D);
      cr_ratio_in (&g, -3.0, 3.0, V);
      cr_ratio_in (&g, -3.0, 3.0, W);
      ck_assert_ok (chaplygin_certified_field (L0, D, V, W, dq));
      field_route (L0, D, V, W, want);
      for (int k = 0; k < 4; k++)
        ck_assert_same (dq[k], want[k]);
      /* the uncertified field at double inputs, within 4 ulps */
      double q[4] = { D[0], V[0], 0.0, W[0] }, du[4];
      if (L0[1] == 1.0 && D[1] == 1.0 && V[1] == 1.0 && W[1] == 1.0)
        {
          ck_assert_ok (chaplygin_discrete_field (L0[0], q, du));
          for (int k = 0; k < 4; k++)
            ck_assert_ulps (du[k], dq[k], 4);
        }
    }
  /* the exact values: l = 1/3 + 1/6 = 1/2, V = 1, Omega = 1/2:
     dV = 1/8, dOmega = -2 (1/2)(1)(1/2)/(5/4) = -2/5 */
  double dq[4];
  ck_assert_ok (chaplygin_certified_field ((const double[2]) { 1, 3 },
                                           (const double[2]) { 1, 6 },
                                           (const double[2]) { 1, 1 },
                                           (const double[2]) { 1, 2 }, dq));
  ck_assert_same (dq[CHAPLYGIN_V], 0.125);
  ck_assert_same (dq[CHAPLYGIN_OMEGA], -0.4);
  ck_assert_same (dq[CHAPLYGIN_THETA], 0.5);
  /* l Omega^2 beyond DBL_MAX, though every input is a double: ERANGE;
     l = 1e300 needs no overflow-free form: dOmega = -2 V Omega/(l + 1/l)
     rounded from the exact value */
  dq[0] = 7.0;
  ck_assert_status (chaplygin_certified_field ((const double[2]) { 1e300, 1 },
                                               (const double[2]) { 0, 1 },
                                               (const double[2]) { 1, 1 },
                                               (const double[2]) { 1e10, 1 },
                                               dq), CHAPLYGIN_ERANGE);
  ck_assert_same (dq[0], 7.0);
  double want[4];
  const double big[2] = { 1e300, 1 }, zero[2] = { 0, 1 }, one[2] = { 1, 1 };
  ck_assert_ok (chaplygin_certified_field (big, zero, one, one, dq));
  field_route (big, zero, one, one, want);
  ck_assert_same (dq[CHAPLYGIN_OMEGA], want[CHAPLYGIN_OMEGA]);
  ck_assert_status (chaplygin_certified_field ((const double[2]) { 1, 0 },
                                               zero, one, one, dq),
                    CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_certified_field (one, zero, one, one, NULL),
                    CHAPLYGIN_EINVAL);
}
END_TEST

int
main (void)
{
  Suite *s = suite_create ("cert_units");
  tu_add (s, "certified_2_2", certified_2_2);
  tu_add (s, "certified_2_3", certified_2_3);
  tu_add (s, "certified_3_1", certified_3_1);
  tu_add (s, "certified_3_2", certified_3_2);
  return tu_run (s);
}
