/* test_status.c -- lib/status.c: status messages, options, and the small
   numerical helpers shared by the collision formulas. */
#include <config.h>

#include <stdlib.h>
#include <string.h>

#include "internal.h"
#include "testutil.h"

START_TEST (test_strerror)
{
  const char *seen[8];
  for (int s = CHAPLYGIN_SUCCESS; s <= CHAPLYGIN_ENOMEM; s++)
    {
      seen[s] = chaplygin_strerror (s);
      ck_assert_ptr_nonnull (seen[s]);
      ck_assert_str_ne (seen[s], "unknown status");
      for (int t = 0; t < s; t++)
        ck_assert_str_ne (seen[s], seen[t]);
    }
  ck_assert_str_eq (chaplygin_strerror (-1), "unknown status");
  ck_assert_str_eq (chaplygin_strerror (99), "unknown status");
}
END_TEST

START_TEST (test_options)
{
  chaplygin_options o, d = CHAPLYGIN_OPTIONS_DEFAULT;
  ck_assert_ok (chp_options_resolve (NULL, &o));
  ck_assert (o.method == CHAPLYGIN_CLOSED_FORM && o.tol == d.tol
             && o.precision == CHAPLYGIN_PREC_DOUBLE);
  chaplygin_options q = { CHAPLYGIN_QUADRATURE, 1e-15, CHAPLYGIN_PREC_DOUBLE };
  ck_assert_ok (chp_options_resolve (&q, &o));
  q.tol = 0.5e-15;
  ck_assert_status (chp_options_resolve (&q, &o), CHAPLYGIN_EINVAL);
  q.tol = 1.0;
  ck_assert_status (chp_options_resolve (&q, &o), CHAPLYGIN_EINVAL);
  q.tol = NAN;
  ck_assert_status (chp_options_resolve (&q, &o), CHAPLYGIN_EINVAL);
  q.method = CHAPLYGIN_ODE;
  ck_assert_status (chp_options_resolve (&q, &o), CHAPLYGIN_EINVAL);
  /* the closed form ignores tol */
  q.method = CHAPLYGIN_CLOSED_FORM;
  ck_assert_ok (chp_options_resolve (&q, &o));
  q.method = (chaplygin_method) 7;
  ck_assert_status (chp_options_resolve (&q, &o), CHAPLYGIN_EINVAL);
  q.method = CHAPLYGIN_CLOSED_FORM;
  q.precision = (chaplygin_precision) 3;
  ck_assert_status (chp_options_resolve (&q, &o), CHAPLYGIN_EINVAL);
}
END_TEST

/* Reference arithmetic: IEEE binary128 (113-bit significand), a different
   precision from the code under test. */
typedef __float128 q128;

START_TEST (test_one_plus_L0_L0D)
{
  /* Route: binary128 evaluation of 1 + L0^2 + L0 Delta (the products of
     two doubles are exact in binary128; the sum rounds at 2^-113). */
  tu_rng r;
  tu_rng_seed (&r, 7);
  for (int k = 0; k < 20000; k++)
    {
      double L0 = tu_uniform (&r, -4.0, 4.0), Delta;
      if (k % 2 == 0)
        Delta = -1.0 / L0 - L0 + tu_uniform (&r, -1e-9, 1e-9);  /* cancels */
      else
        Delta = tu_uniform (&r, 1e-3, 10.0);
      q128 ref = 1 + (q128) L0 * L0 + (q128) L0 * Delta;
      double got = chp_one_plus_L0_L0D (L0, Delta);
      /* Two final roundings and the product L0 e of size eps^2 |L0 s|:
         within 2 ulps of the result, however much 1 + L0 (L0 + Delta)
         cancels (naive evaluation loses up to 9 digits here). */
      ck_assert_rel (got, (double) ref, 2 * DBL_EPSILON);
    }
  /* An exact zero: L0 = -1/2, Delta = 5/2. */
  ck_assert (chp_one_plus_L0_L0D (-0.5, 2.5) == 0.0);
}
END_TEST

START_TEST (test_ratio_helpers)
{
  /* Route: binary128. */
  tu_rng r;
  tu_rng_seed (&r, 8);
  for (int k = 0; k < 20000; k++)
    {
      double e = tu_uniform (&r, -300.0, 300.0);
      double L = (k % 2 ? 1.0 : -1.0) * pow (10.0, e / 2);
      q128 ref = (q128) L / (1 + (q128) L * L);
      ck_assert_rel (chp_L_over_one_plus_sq (L), (double) ref, 2 * DBL_EPSILON);

      double L0 = tu_uniform (&r, -5.0, 5.0) * pow (10.0, tu_uniform (&r, 0, 2));
      double Delta = tu_uniform (&r, 0.01, 5.0);
      double b = (k % 2) ? L0 : L0 + Delta, bp = (k % 2) ? L0 + Delta : L0;
      q128 bq = (k % 2) ? (q128) L0 : (q128) L0 + Delta;
      q128 rq = (1 + (q128) L0 * ((q128) L0 + Delta)) / (1 + bq * bq);
      /* The numerator is accurate to 2 ulps (above); the denominator 1 + b^2
         is formed from the rounded b = fl(L0 + Delta) (relative error
         eps/2, doubled by squaring) and rounded once; then one division:
         within 4 ulps, cancellation in the numerator included. */
      ck_assert_rel (chp_collision_ratio (L0, Delta, b, bp), (double) rq,
                     4 * DBL_EPSILON);
    }
  /* Overflow branch: b beyond 2^500, against the asymptotic value
     (1 + b b')/(1 + b^2) -> b'/b for huge b. */
  double L0 = 1e200, Delta = 3.0;
  ck_assert_rel (chp_collision_ratio (L0, Delta, L0 + Delta, L0), L0 / (L0 + Delta),
                 2 * DBL_EPSILON);
  /* |L0| << Delta beyond 2^500: the other end's value is passed, not
     reconstructed as 2 L0 + Delta - b (which cancels to 0 here). */
  ck_assert_rel (chp_collision_ratio (1.0, 1e160, 1.0 + 1e160, 1.0), 1e-160,
                 2 * DBL_EPSILON);
}
END_TEST

/* chaplygin_method_available: the three methods always, the certified
   one where configure found Arb; without it, the certified functions
   refuse with CHAPLYGIN_EINVAL and set no orbit. */
START_TEST (test_method_available)
{
  int a = -1;
  for (int m = 0; m <= 2; m++)
    ck_assert (chaplygin_method_available (m, &a) == 0 && a == 1);
  ck_assert (chaplygin_method_available (CHAPLYGIN_CERTIFIED, &a) == 0
             && a == HAVE_ARB);
  ck_assert (chaplygin_method_available (4, &a) == CHAPLYGIN_EINVAL);
  ck_assert (chaplygin_method_available (-1, &a) == CHAPLYGIN_EINVAL);
  ck_assert (chaplygin_method_available (0, NULL) == CHAPLYGIN_EINVAL);
#if !HAVE_ARB
  chaplygin_discrete sys;
  ck_assert (chaplygin_discrete_init (&sys, 0.5, 1.0) == 0);
  chaplygin_discrete_state st = { 1, 1.0, 0.5, 0, 0, { 0, 0 }, 0 };
  chaplygin_certified_orbit *o = (chaplygin_certified_orbit *) &sys;
  const double r[2] = { 1, 1 }, q[4] = { 0, 1, 0, 0.5 }, peg[2] = { 0, 0 };
  unsigned long n;
  ck_assert (chaplygin_certified_orbit_new (&sys, &st, 0, &o)
             == CHAPLYGIN_EINVAL && !o);
  o = (chaplygin_certified_orbit *) &sys;
  ck_assert (chaplygin_certified_orbit_new_exact (r, r, 1, r, r, 0, 0, peg,
                                                  0, &o) == CHAPLYGIN_EINVAL
             && !o);
  o = (chaplygin_certified_orbit *) &sys;
  ck_assert (chaplygin_certified_orbit_new_phase (&sys, q, 0, peg, 0, &o)
             == CHAPLYGIN_EINVAL && !o);
  ck_assert (chaplygin_certified_orbit_cap (NULL, 100) == CHAPLYGIN_EINVAL);
  ck_assert (chaplygin_certified_orbit_step (NULL, &st, NULL, NULL)
             == CHAPLYGIN_EINVAL);
  ck_assert (chaplygin_certified_orbit_state (NULL, &st, NULL)
             == CHAPLYGIN_EINVAL);
  ck_assert (chaplygin_certified_orbit_collisions (NULL, &n)
             == CHAPLYGIN_EINVAL);
  ck_assert (chaplygin_certified_orbit_free (NULL) == CHAPLYGIN_SUCCESS);
  chaplygin_options opt = CHAPLYGIN_OPTIONS_DEFAULT;
  opt.method = CHAPLYGIN_CERTIFIED;
  ck_assert (chaplygin_discrete_step (&sys, &st, 0, &opt, &st, NULL)
             == CHAPLYGIN_EINVAL);
#endif
}
END_TEST

int
main (void)
{
  Suite *s = suite_create ("status");
  TCase *tc = tcase_create ("status");
  tcase_add_test (tc, test_strerror);
  tcase_add_test (tc, test_options);
  tcase_add_test (tc, test_method_available);
  suite_add_tcase (s, tc);
  TCase *th = tcase_create ("helpers");
  tcase_add_test (th, test_one_plus_L0_L0D);
  tcase_add_test (th, test_ratio_helpers);
  suite_add_tcase (s, th);
  return tu_run (s);
}
