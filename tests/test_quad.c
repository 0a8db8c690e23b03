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

int
main (void)
{
  Suite *s = suite_create ("quad");
  TCase *tc = tcase_create ("adaptive_gauss_kronrod");
  tcase_add_test (tc, test_exact_rules);
  tcase_add_test (tc, test_failures);
  suite_add_tcase (s, tc);
  return tu_run (s);
}
