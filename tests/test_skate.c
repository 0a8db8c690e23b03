/* test_skate.c -- lib/skate.c: the discrete skate at one point of its
   motion, Omega from H and the positions in the plane.

   Route: binary128 (libquadmath): H/(1 + l^2) with l = L0 + D formed
   exactly, and P + D e, P + (L0 + D) e with the exact cosine and sine of
   theta (cosq, sinq). */
#include <config.h>

#include <quadmath.h>
#include <stdio.h>
#include <stdlib.h>

#include "internal.h"
#include "testutil.h"

typedef __float128 q128;

START_TEST (test_omega)
{
  /* Tolerance 1.5 ulps (the quotient, and 1 + l^2 rounded once with the
     rounding error of l added), 2.5 where |l| > 2^511 (the rounding of l
     dropped) or the result is subnormal.  Measured: see the comment of
     chaplygin_discrete_omega. */
  tu_rng r;
  tu_rng_seed (&r, 34);
  double worst = 0;
  for (int k = 0; k < 20000; k++)
    {
      const double L0 = tu_uniform (&r, -4, 3), D = tu_uniform (&r, 0, 2);
      const double H = tu_uniform (&r, -3, 3);
      double Om;
      ck_assert_ok (chaplygin_discrete_omega (L0, D, H, &Om));
      const q128 l = (q128) L0 + D;
      const double want = (double) ((q128) H / (1 + l * l));
      ck_assert_rel (Om, want, 1.5 * DBL_EPSILON);
      worst = fmax (worst, tu_relerr (Om, want) / DBL_EPSILON);
    }
  printf ("# discrete_omega vs binary128, 20000 points: worst %.2f eps\n", worst);
  /* l = L0 + D cancelling (the rounding of l matters relatively) */
  double Om;
  ck_assert_ok (chaplygin_discrete_omega (-0.1, 0.30000000000000004, 2.0, &Om));
  ck_assert_rel (Om, (double) (2 / (1 + ((q128) -0.1 + 0.30000000000000004)
                                   * ((q128) -0.1 + 0.30000000000000004))),
                 1.5 * DBL_EPSILON);
  /* 1 + l^2 overflows: (H/l)/l */
  const double big[][3] = { { 0x1p600, 0.5, 3.0 }, { -0x1p1000, 1.0, -1e300 },
                            { 0x1p512, 0.0, 0x1p-900 } };
  for (int k = 0; k < 3; k++)
    {
      ck_assert_ok (chaplygin_discrete_omega (big[k][0], big[k][1], big[k][2], &Om));
      const q128 l = (q128) big[k][0] + big[k][1];
      ck_assert_rel (Om, (double) ((q128) big[k][2] / (1 + l * l)), 2.5 * DBL_EPSILON);
    }
  /* never overflows: |Omega| <= |H| */
  ck_assert_ok (chaplygin_discrete_omega (0.0, 0.0, DBL_MAX, &Om));
  ck_assert (Om == DBL_MAX);
  /* errors: the output untouched */
  Om = 7;
  ck_assert_status (chaplygin_discrete_omega (NAN, 0, 1, &Om), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_discrete_omega (0, INFINITY, 1, &Om), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_discrete_omega (0, 0, NAN, &Om), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_discrete_omega (DBL_MAX, DBL_MAX, 1, &Om), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_discrete_omega (0, 0, 1, NULL), CHAPLYGIN_EINVAL);
  ck_assert (Om == 7);
}
END_TEST

START_TEST (test_positions)
{
  /* Tolerance 2 eps of max(|P|, |D|) (front) and max(|P|, |l|) (G): one
     fma, and cos and sin within an ulp each */
  tu_rng r;
  tu_rng_seed (&r, 35);
  for (int k = 0; k < 20000; k++)
    {
      const double L0 = tu_uniform (&r, -4, 3), D = tu_uniform (&r, 0, 2);
      const double th = tu_uniform (&r, -10, 10);
      const double P[2] = { tu_uniform (&r, -50, 50), tu_uniform (&r, -50, 50) };
      double F[2], G[2];
      ck_assert_ok (chaplygin_discrete_positions (L0, D, th, P, F, G));
      const q128 c = cosq (th), s = sinq (th), l = (q128) L0 + D;
      const double sf = fmax (fmax (fabs (P[0]), fabs (P[1])), D);
      const double sg = fmax (fmax (fabs (P[0]), fabs (P[1])), fabs ((double) l));
      ck_assert (fabs (F[0] - (double) (P[0] + D * c)) <= 2 * DBL_EPSILON * sf);
      ck_assert (fabs (F[1] - (double) (P[1] + D * s)) <= 2 * DBL_EPSILON * sf);
      ck_assert (fabs (G[0] - (double) (P[0] + l * c)) <= 2 * DBL_EPSILON * sg);
      ck_assert (fabs (G[1] - (double) (P[1] + l * s)) <= 2 * DBL_EPSILON * sg);
    }
  /* the massless skate's mass centre at D = D+, bit for bit */
  for (int dir = -1; dir <= 1; dir += 2)
    {
      chaplygin_discrete_state st = { dir, 0.5, 0.1, 2.385, 0.0, { 1.25, -3.5 } };
      double G1[2], G2[2];
      ck_assert_ok (chaplygin_massless_mass_centre (-0.3, &st, G1));
      ck_assert_ok (chaplygin_discrete_positions (-0.3, dir > 0 ? 0.0 : 1.0, st.theta,
                                                  st.peg, NULL, G2));
      ck_assert (G1[0] == G2[0] && G1[1] == G2[1]);
    }
  /* either output may be NULL; errors leave them untouched */
  const double P[2] = { 1.0, 2.0 };
  double F[2] = { 7, 7 }, G[2] = { 7, 7 };
  ck_assert_ok (chaplygin_discrete_positions (0.5, 0.25, 0.3, P, F, NULL));
  ck_assert_rel (F[0], 1.0 + 0.25 * cos (0.3), DBL_EPSILON);
  ck_assert (G[0] == 7);
  F[0] = F[1] = 7;
  const double Pbig[2] = { DBL_MAX, 0.0 };
  ck_assert_status (chaplygin_discrete_positions (DBL_MAX, 0.5, 0.0, Pbig, F, G),
                    CHAPLYGIN_ERANGE);
  ck_assert_status (chaplygin_discrete_positions (0.5, 0.25, 0.3, NULL, F, G),
                    CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_discrete_positions (NAN, 0.25, 0.3, P, F, G), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_discrete_positions (0.5, 0.25, INFINITY, P, F, G),
                    CHAPLYGIN_EDOM);
  const double Pnan[2] = { 0.0, NAN };
  ck_assert_status (chaplygin_discrete_positions (0.5, 0.25, 0.3, Pnan, F, G),
                    CHAPLYGIN_EDOM);
  ck_assert (F[0] == 7 && F[1] == 7 && G[0] == 7 && G[1] == 7);
}
END_TEST

int
main (void)
{
  Suite *s = suite_create ("skate");
  tu_add (s, "discrete_omega", test_omega);
  tu_add (s, "discrete_positions", test_positions);
  return tu_run (s);
}
