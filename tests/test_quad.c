/* test_quad.c -- lib/quad.c: the adaptive Gauss-Kronrod driver. */
#include <config.h>

#include <stdlib.h>

#include "internal.h"
#include "testutil.h"

static double
f_poly (double t, void *p)
{
  (void) p;
  return ((3.0 * t - 2.0) * t + 0.5) * t;       /* 3t^3 - 2t^2 + t/2 */
}

static double
f_runge (double t, void *p)
{
  (void) p;
  return 1.0 / (1.0 + 25.0 * t * t);
}

static double
f_peak (double t, void *p)
{
  double w = *(double *) p;
  return w / (t * t + w * w);                   /* Int = atan(t/w) */
}

static double
f_nan (double t, void *p)
{
  (void) p;
  return t > 0.5 ? (double) NAN : 1.0;
}

static double
f_singular (double t, void *p)
{
  (void) p;
  double d = fmax (fabs (t - 0.3), 1e-200);
  return 1.0 / (sqrt (d) * d);                  /* not integrable, finite */
}

START_TEST (test_exact_rules)
{
  /* Route: exact antiderivatives.  The 21-point Kronrod rule integrates the
     cubic exactly; the Runge function and a sharp peak need bisection. */
  double r;
  ck_assert_ok (chp_integrate (f_poly, NULL, -0.5, 1.75, 1e-14, &r));
  double F1 = 0.75 * pow (1.75, 4) - 2.0 / 3.0 * pow (1.75, 3) + 0.25 * 1.75 * 1.75;
  double F0 = 0.75 * pow (-0.5, 4) - 2.0 / 3.0 * pow (-0.5, 3) + 0.25 * 0.25;
  ck_assert_rel (r, F1 - F0, 8 * DBL_EPSILON);
  ck_assert_ok (chp_integrate (f_runge, NULL, -1.0, 1.0, 1e-14, &r));
  ck_assert_rel (r, 0.4 * atan (5.0), 64 * DBL_EPSILON);
  double w = 1e-6;
  ck_assert_ok (chp_integrate (f_peak, &w, -0.3, 2.0, 1e-13, &r));
  ck_assert_rel (r, atan (2.0 / w) + atan (0.3 / w), 1e-13);
  /* Reversed limits give the negative; equal limits give 0. */
  double rr;
  ck_assert_ok (chp_integrate (f_runge, NULL, 1.0, -1.0, 1e-14, &rr));
  ck_assert_rel (rr, -0.4 * atan (5.0), 64 * DBL_EPSILON);
  ck_assert_ok (chp_integrate (f_runge, NULL, 0.7, 0.7, 1e-14, &r));
  ck_assert (r == 0.0);
}
END_TEST

START_TEST (test_failures)
{
  double r = 42.0;
  ck_assert_status (chp_integrate (f_nan, NULL, 0.0, 1.0, 1e-12, &r),
                    CHAPLYGIN_ERANGE);
  ck_assert_status (chp_integrate (f_singular, NULL, 0.0, 1.0, 1e-12, &r),
                    CHAPLYGIN_ENOCONV);
  ck_assert (r == 42.0);        /* not written on failure */
}
END_TEST

/* ---- chp_integrate2: a 2-vector integrand, absolute tolerance -------- */

struct vec_case
{
  int k;                        /* polynomial degree, or -1 (cos, sin) */
  int calls;
  int fail;                     /* status to return, or -1: NaN, -2: huge,
                                   -3: (+-0.9 DBL_MAX sin 2 pi t) */
  int fail_after;               /* with fail > 0: fail from this call on */
};

static int
f_vec (double t, void *p, double y[2])
{
  struct vec_case *c = p;
  c->calls++;
  if (c->fail > 0 && c->calls > c->fail_after)
    return c->fail;
  if (c->fail == -3)
    {
      y[0] = 0.9 * DBL_MAX * sin (2 * M_PI * t);
      y[1] = -y[0];
      return CHAPLYGIN_SUCCESS;
    }
  if (c->k < 0)
    {
      y[0] = cos (t);
      y[1] = sin (t);
      return CHAPLYGIN_SUCCESS;
    }
  y[0] = pow (t, c->k);
  y[1] = 1.0 - 2.0 * pow (t, c->k);
  if (c->fail == -1 && t > 0.5)
    y[1] = NAN;
  if (c->fail == -2)
    y[0] = DBL_MAX;
  return CHAPLYGIN_SUCCESS;
}

START_TEST (test_integrate2)
{
  /* Route: exact antiderivatives.  The 21-point Kronrod rule is exact to
     degree 31 (one rule, 21 calls); its embedded 10-point Gauss rule to
     degree 19, so the error estimate is at the rounding floor there and
     the first rule converges, while degree 20 needs bisection: the three
     tables XGK, WGK, WG are right.  Tolerance 4 eps: a 21-term sum. */
  double r[2];
  for (int k = 0; k <= 31; k++)
    {
      struct vec_case c = { k, 0, 0, 0 };
      ck_assert_ok (chp_integrate2 (f_vec, &c, 0.0, 1.0, 1.0, r));
      ck_assert_int_eq (c.calls, 21);
      ck_assert_rel (r[0], 1.0 / (k + 1), 4 * DBL_EPSILON);
      ck_assert_rel (r[1], 1.0 - 2.0 / (k + 1), 4 * DBL_EPSILON);
    }
  struct vec_case c19 = { 19, 0, 0, 0 }, c20 = { 20, 0, 0, 0 };
  /* estimates: 1.09e-14 (the rounding floor 50 eps Int |f|) for degree
     19, 5.0e-14 for degree 20 (QUADPACK's rescaling of |K - G|) */
  ck_assert_ok (chp_integrate2 (f_vec, &c19, 0.0, 1.0, 2e-14, r));
  ck_assert_int_eq (c19.calls, 21);
  ck_assert_ok (chp_integrate2 (f_vec, &c20, 0.0, 1.0, 2e-14, r));
  ck_assert_int_gt (c20.calls, 21);
  ck_assert_rel (r[0], 1.0 / 21, 4 * DBL_EPSILON);
  /* a component integrating to 0 (no relative tolerance could be met):
     (cos, sin) over a full turn, to an absolute 1e-13 */
  struct vec_case cs = { -1, 0, 0, 0 };
  ck_assert_ok (chp_integrate2 (f_vec, &cs, 0.0, 2 * M_PI, 1e-13, r));
  ck_assert (fabs (r[0]) < 1e-13 && fabs (r[1]) < 1e-13);
  /* equal limits: 0 */
  ck_assert_ok (chp_integrate2 (f_vec, &cs, 0.7, 0.7, 0.0, r));
  ck_assert (r[0] == 0.0 && r[1] == 0.0);
}
END_TEST

START_TEST (test_integrate2_failures)
{
  double r[2] = { 42.0, 42.0 };
  struct vec_case c = { 3, 0, CHAPLYGIN_EDOM, 0 };
  ck_assert_status (chp_integrate2 (f_vec, &c, 0.0, 1.0, 1e-10, r), CHAPLYGIN_EDOM);
  /* the integrand fails only on a later piece (the first or the second
     of a bisection) */
  c.calls = 0, c.fail_after = 21;
  ck_assert_status (chp_integrate2 (f_vec, &c, 0.0, 1.0, 0.0, r), CHAPLYGIN_EDOM);
  c.calls = 0, c.fail_after = 42;
  ck_assert_status (chp_integrate2 (f_vec, &c, 0.0, 1.0, 0.0, r), CHAPLYGIN_EDOM);
  c.fail_after = 0;
  /* the error estimate overflows while the integral does not */
  c.fail = -3;
  ck_assert_status (chp_integrate2 (f_vec, &c, 0.0, 1.0, 1e-10, r), CHAPLYGIN_ERANGE);
  c.fail = -1;
  ck_assert_status (chp_integrate2 (f_vec, &c, 0.0, 1.0, 1e-10, r), CHAPLYGIN_ERANGE);
  c.fail = -2;                  /* the sum of DBL_MAX values overflows */
  ck_assert_status (chp_integrate2 (f_vec, &c, 0.0, 4.0, 1e-10, r), CHAPLYGIN_ERANGE);
  /* a tolerance below the rounding floor: bisection to the piece limit;
     a piece of two adjacent doubles cannot be bisected */
  c.fail = 0;
  ck_assert_status (chp_integrate2 (f_vec, &c, 0.0, 1.0, 0.0, r), CHAPLYGIN_ENOCONV);
  ck_assert_status (chp_integrate2 (f_vec, &c, 1.0, 1.0 + DBL_EPSILON, 0.0, r),
                    CHAPLYGIN_ENOCONV);
  /* (the midpoint rounds to the upper end: ties to even) */
  ck_assert_status (chp_integrate2 (f_vec, &c, 1.0 + DBL_EPSILON, 1.0 + 2 * DBL_EPSILON,
                                    0.0, r), CHAPLYGIN_ENOCONV);
  ck_assert (r[0] == 42.0 && r[1] == 42.0);     /* not written on failure */
}
END_TEST

int
main (void)
{
  Suite *s = suite_create ("quad");
  TCase *tc = tcase_create ("adaptive_gauss_kronrod");
  tcase_add_test (tc, test_exact_rules);
  tcase_add_test (tc, test_failures);
  suite_add_tcase (s, tc);
  tc = tcase_create ("quad_integrate2");
  tcase_add_test (tc, test_integrate2);
  tcase_add_test (tc, test_integrate2_failures);
  suite_add_tcase (s, tc);
  return tu_run (s);
}
