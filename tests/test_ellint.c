/* test_ellint.c -- lib/ellint.c: the guarded Carlson integrals and the
   cancellation-free reduction chp_quartic_interval that every closed form
   of Appendix B rests on. */
#include <config.h>

#include <gsl/gsl_sf_ellint.h>
#include <stdlib.h>

#include "internal.h"
#include "ref_ellint.h"
#include "testutil.h"

#define NREF (sizeof ref_ellint / sizeof ref_ellint[0])

/* Tolerance for the reduction against 40-digit quadrature: the Carlson
   kernel's R_F and R_D are accurate to 3.4 and 5.4 ulps (lib/carlson.c,
   against Arb); the reduction adds about eight roundings, each of
   relative size <= eps/2, to quantities whose condition numbers are <= 1
   (every term is a sum of nonnegative parts).  16 eps covers both. */
#define TOL_CF (16 * DBL_EPSILON)

START_TEST (test_reference_table)
{
  /* Route: tanh-sinh quadrature at 40 digits (tests/ref/make_refs.py). */
  const int i = _i;
  double F, T;
  ck_assert_ok (chp_quartic_interval (ref_ellint[i].sp, ref_ellint[i].sq,
                                      ref_ellint[i].pmq, ref_ellint[i].y,
                                      ref_ellint[i].x, ref_ellint[i].dxy,
                                      CHAPLYGIN_PREC_DOUBLE, &F, &T));
  ck_assert_rel (F, ref_ellint[i].F, TOL_CF);
  ck_assert_rel (T, ref_ellint[i].T, TOL_CF);
}
END_TEST

START_TEST (test_single_precision)
{
  /* CHAPLYGIN_PREC_SINGLE: the kernel's stopping rule tau = 0.042 bounds
     the truncation of each series by 2^-40 = 9.1e-13 (lib/carlson.c); F
     is R_F times a rounded factor and T a sum of nonnegative terms, one of
     them R_D's: each within 9.1e-13 plus TOL_CF's rounding, below 1e-12. */
  const int i = _i;
  double F, T;
  ck_assert_ok (chp_quartic_interval (ref_ellint[i].sp, ref_ellint[i].sq,
                                      ref_ellint[i].pmq, ref_ellint[i].y,
                                      ref_ellint[i].x, ref_ellint[i].dxy,
                                      CHAPLYGIN_PREC_SINGLE, &F, &T));
  ck_assert_rel (F, ref_ellint[i].F, 1e-12);
  ck_assert_rel (T, ref_ellint[i].T, 1e-12);
}
END_TEST

START_TEST (test_additivity)
{
  /* Route: the integrals over [y, m] and [m, x] add up to [y, x] (the
     reduction computes each from its own addition-theorem angle, so this
     checks the Euler/Legendre addition formulas, not a reuse). */
  tu_rng r;
  tu_rng_seed (&r, 12345);
  for (int k = 0; k < 2000; k++)
    {
      double h = tu_uniform (&r, 0.01, 3.0);
      double sp, sq, pmq;
      if (h < 1.0)
        sp = 1.0, sq = sqrt ((1.0 - h) * (1.0 + h)), pmq = h * h;
      else
        sp = h, sq = sqrt ((h - 1.0) * (h + 1.0)), pmq = 1.0;
      double y = tu_uniform (&r, 0.0, 2.0), m = y + tu_uniform (&r, 0.0, 2.0);
      double x = m + tu_uniform (&r, 0.0, 2.0);
      double F1, T1, F2, T2, F, T;
      ck_assert_ok (chp_quartic_interval (sp, sq, pmq, y, m, m - y, 0, &F1, &T1));
      ck_assert_ok (chp_quartic_interval (sp, sq, pmq, m, x, x - m, 0, &F2, &T2));
      ck_assert_ok (chp_quartic_interval (sp, sq, pmq, y, x, x - y, 0, &F, &T));
      /* Three results of 16 eps each; x - y etc. are rounded (1 eps each). */
      ck_assert_rel (F1 + F2, F, 64 * DBL_EPSILON);
      ck_assert_rel (T1 + T2, T, 64 * DBL_EPSILON);
    }
}
END_TEST

START_TEST (test_large_tan)
{
  /* Route: additivity across the switch of chp_quartic_interval's two
     forms at tan(mu) = 2^50 ((1, 1 + k'^2 s^2, 1 + s^2) below it,
     (cos^2 mu, 1 - k^2 sin^2 mu, 1) above): Int_0^x2 = Int_0^x1 +
     Int_x1^x2 with x2 / sqrt(q) = 2^51 or 2^50 + 2^20 (the second form,
     the latter just above the switch) and x1 / sqrt(q) = 2^49 or
     2^50 - 2^20 (the first; the interval [x1, x2] has a tan(mu) of order
     1, also the first), with q = 1e-40 and 1e-30 (near the spinning
     state) and p = 1 and 2.25.  Tolerance as test_additivity. */
  const double sqs[] = { 1e-20, 1e-15 };
  const double sps[] = { 1.0, 1.5 };
  const double f1s[] = { 0x1p49, 0x1p50 - 0x1p20 };
  const double f2s[] = { 0x1p51, 0x1p50 + 0x1p20 };
  for (size_t i = 0; i < NELEM (sqs); i++)
    for (size_t j = 0; j < NELEM (sps); j++)
      for (size_t m = 0; m < NELEM (f1s) * NELEM (f2s); m++)
        {
          const double sp = sps[j], sq = sqs[i];
          const double pmq = sp * sp - sq * sq;
          const double x2 = f2s[m / NELEM (f1s)] * sq;
          const double x1 = f1s[m % NELEM (f1s)] * sq;
          double F1, T1, F2, T2, F, T;
          ck_assert_ok (chp_quartic_interval (sp, sq, pmq, 0.0, x1, x1, 0,
                                              &F1, &T1));
          ck_assert_ok (chp_quartic_interval (sp, sq, pmq, x1, x2, x2 - x1,
                                              0, &F2, &T2));
          ck_assert_ok (chp_quartic_interval (sp, sq, pmq, 0.0, x2, x2, 0,
                                              &F, &T));
          ck_assert_rel (F1 + F2, F, 64 * DBL_EPSILON);
          ck_assert_rel (T1 + T2, T, 64 * DBL_EPSILON);
        }
}
END_TEST

START_TEST (test_short_interval)
{
  /* Route: for x - y -> 0 the integrals tend to (x - y) times the
     integrand at the midpoint, with relative error (x - y)^2 f''/(24 f).
     At x - y = 1e-12 that error is far below eps: the reduction must keep
     all digits where F(phi_x) - F(phi_y) would keep about four. */
  double sp = 1.0, h = 0.6, sq = sqrt (1 - h * h), pmq = h * h;
  double y = 1.2345, d = 1e-12, x = y + d;
  double dxy = x - y;           /* exact: Sterbenz */
  double mid = y + 0.5 * dxy;
  double P = (mid * mid + sp * sp) * (mid * mid + sq * sq);
  double F, T;
  ck_assert_ok (chp_quartic_interval (sp, sq, pmq, y, x, dxy, 0, &F, &T));
  ck_assert_rel (F, sp * dxy / sqrt (P), 8 * DBL_EPSILON);
  ck_assert_rel (T, dxy * sqrt ((mid * mid + sp * sp) / (mid * mid + sq * sq)),
                 8 * DBL_EPSILON);
}
END_TEST

START_TEST (test_elementary_limits)
{
  /* Route: closed elementary forms.
     q = 0 (p = 1): Int dt/(t sqrt(t^2 + 1)) = asinh(1/y) - asinh(1/x) and
     Int sqrt(t^2 + 1)/t dt = [sqrt(t^2+1) - asinh(1/t)]_y^x.
     p = q + pmq with pmq -> 0 is not reachable; q = p (h = 0) is:
     Int dt/(t^2 + 1) = atan x - atan y, T = x - y. */
  double y = 0.375, x = 2.125, F, T;
  ck_assert_ok (chp_quartic_interval (1.0, 0.0, 1.0, y, x, x - y, 0, &F, &T));
  ck_assert_rel (F, asinh (1 / y) - asinh (1 / x), 8 * DBL_EPSILON);
  ck_assert_rel (T, (sqrt (x * x + 1) - asinh (1 / x))
                 - (sqrt (y * y + 1) - asinh (1 / y)), 8 * DBL_EPSILON);
  ck_assert_ok (chp_quartic_interval (1.0, 1.0, 0x1p-60, y, x, x - y, 0, &F,
                                      &T));
  ck_assert_rel (F, atan (x) - atan (y), 8 * DBL_EPSILON);
  ck_assert_rel (T, x - y, 8 * DBL_EPSILON);
}
END_TEST

START_TEST (test_scaling)
{
  /* Route: homogeneity.  (t, sqrt p, sqrt q) -> lambda (t, sqrt p, sqrt q)
     leaves F unchanged and multiplies T by lambda; lambda = 2^300 takes the
     arguments into the scaled branch, exactly (power of two). */
  double sp = 1.7, sq = sqrt (1.7 * 1.7 - 1), y = 0.5, x = 3.25, F, T, Fs, Ts;
  ck_assert_ok (chp_quartic_interval (sp, sq, 1.0, y, x, x - y, 0, &F, &T));
  double L = 0x1p300;
  ck_assert_ok (chp_quartic_interval (sp * L, sq * L, L * L, y * L, x * L,
                                      (x - y) * L, 0, &Fs, &Ts));
  ck_assert_rel (Fs, F, 4 * DBL_EPSILON);
  ck_assert_rel (Ts, T * L, 4 * DBL_EPSILON);
}
END_TEST

START_TEST (test_special_cases)
{
  double F = 1, T = 1;
  /* x = y: nothing to integrate. */
  ck_assert_ok (chp_quartic_interval (1.0, 0.5, 0.75, 2.0, 2.0, 0.0, 0, &F, &T));
  ck_assert (F == 0.0 && T == 0.0);
  /* y = q = 0: the divergent integral of the spinning state. */
  ck_assert_status (chp_quartic_interval (1.0, 0.0, 1.0, 0.0, 1.0, 1.0, 0,
                                          &F, &T), CHAPLYGIN_ESPIN);
  /* Only what is asked for: NULL outputs are allowed. */
  ck_assert_ok (chp_quartic_interval (1.0, 0.5, 0.75, 0.1, 2.0, 1.9, 0, NULL,
                                      &T));
  ck_assert_ok (chp_quartic_interval (1.0, 0.5, 0.75, 0.1, 2.0, 1.9, 0, &F,
                                      NULL));
  /* y = 0 with a huge x over small sqrt(q): mu -> pi/2, the complete
     integral K(k) = R_F(0, k'^2, 1) (DLMF 19.25.1), here with k'^2 = q. */
  double q = 1e-300;
  ck_assert_ok (chp_quartic_interval (1.0, sqrt (q), 1.0, 0.0, 1e300, 1e300,
                                      0, &F, NULL));
  double K;
  ck_assert_ok (chp_rf (0.0, q, 1.0, 0, &K));
  ck_assert_rel (F, K, 4 * DBL_EPSILON);
}
END_TEST

START_TEST (test_carlson_guards)
{
  /* Inside GSL's domain chp_rf/chp_rd (the kernel of carlson.c) and GSL
     agree within the sum of their errors against Arb (kernel <= 6 ulps
     for R_F, 8 for R_D; GSL 4.6 and 6.2: tests/test_carlson): 16 eps. */
  double r;
  gsl_sf_result g;
  ck_assert_ok (chp_rf (0.25, 1.5, 2.385, 0, &r));
  gsl_sf_ellint_RF_e (0.25, 1.5, 2.385, GSL_PREC_DOUBLE, &g);
  ck_assert_eps (r, g.val, 16);
  ck_assert_ok (chp_rd (0.25, 1.5, 2.385, 0, &r));
  gsl_sf_ellint_RD_e (0.25, 1.5, 2.385, GSL_PREC_DOUBLE, &g);
  ck_assert_eps (r, g.val, 16);
  /* Scaling branch: homogeneity of degree -1/2 and -3/2. */
  double a, b;
  ck_assert_ok (chp_rf (0.25, 1.5, 2.385, 0, &a));
  ck_assert_ok (chp_rf (0.25 * 0x1p600, 1.5 * 0x1p600, 2.385 * 0x1p600, 0, &b));
  ck_assert_rel (b, a * 0x1p-300, 0.0);
  ck_assert_ok (chp_rd (0.25, 1.5, 2.385, 0, &a));
  ck_assert_ok (chp_rd (0.25 * 0x1p-600, 1.5 * 0x1p-600, 2.385 * 0x1p-600, 0,
                        &b));
  ck_assert_rel (b, a * 0x1p900, 0.0);
  /* Asymptotic branch, against the scaled GSL value where both apply:
     x + y = 2^-101 z is below the switch, 2^-99 z above; R_F varies by
     O(2^-100) relatively between the two (log derivative), so the two
     routes must agree to that. */
  ck_assert_ok (chp_rf (0x1p-102, 0x1p-102, 1.0, 0, &a));
  double s = 4.0 / (2.0 * 0x1p-51);
  ck_assert_rel (a, log (s), 1e-15);
  ck_assert_ok (chp_rd (0x1p-102, 0x1p-102, 1.0, 0, &a));
  ck_assert_rel (a, 3.0 * (log (s) - 1.0), 1e-15);
  /* R_F is symmetric: the order of the arguments does not matter (the
     wrapper sorts them before choosing a branch). */
  double perm[6][3] = { { 0.25, 1.5, 2.385 }, { 0.25, 2.385, 1.5 }, { 1.5, 0.25, 2.385 },
                        { 1.5, 2.385, 0.25 }, { 2.385, 0.25, 1.5 }, { 2.385, 1.5, 0.25 } };
  ck_assert_ok (chp_rf (0.25, 1.5, 2.385, 0, &a));
  for (int k = 0; k < 6; k++)
    {
      ck_assert_ok (chp_rf (perm[k][0], perm[k][1], perm[k][2], 0, &b));
      ck_assert_rel (b, a, 2 * DBL_EPSILON);
    }
  /* R_D with z far below x, y (the GSL wrapper supported only
     z >= 2^-600 max; the kernel of carlson.c computes it). */
  ck_assert_ok (chp_rd (1.0, 2.0, 1e-170, 0, &a));
  /* z -> 0: R_D -> 3/sqrt(x y z), relative correction O(sqrt(z)) */
  ck_assert_rel (a, 3.0 / sqrt (2.0 * 1e-170), 16 * DBL_EPSILON);
  ck_assert_ok (chp_rd (1.0, 2.0, 1e-200, 0, &a));
  ck_assert_rel (a, 3.0 / sqrt (2.0 * 1e-200), 16 * DBL_EPSILON);
  /* Errors. */
  ck_assert_status (chp_rf (-1.0, 1.0, 1.0, 0, &r), CHAPLYGIN_EDOM);
  ck_assert_status (chp_rf (NAN, 1.0, 1.0, 0, &r), CHAPLYGIN_EDOM);
  ck_assert_status (chp_rf (1.0, INFINITY, 1.0, 0, &r), CHAPLYGIN_EDOM);
  ck_assert_status (chp_rf (0.0, 0.0, 1.0, 0, &r), CHAPLYGIN_ERANGE);
  ck_assert_status (chp_rd (1.0, 1.0, 0.0, 0, &r), CHAPLYGIN_EDOM);
  ck_assert_status (chp_rd (0.0, 0.0, 1.0, 0, &r), CHAPLYGIN_ERANGE);
  ck_assert_status (chp_rd (1.0, -1.0, 1.0, 0, &r), CHAPLYGIN_EDOM);
  ck_assert_status (chp_rd (1.0, 1.0, NAN, 0, &r), CHAPLYGIN_EDOM);
}
END_TEST

static Suite *
ellint_suite (void)
{
  Suite *s = suite_create ("ellint");
  TCase *tc = tcase_create ("quartic_interval");
  tcase_add_loop_test (tc, test_reference_table, 0, NREF);
  tcase_add_loop_test (tc, test_single_precision, 0, NREF);
  tcase_add_test (tc, test_additivity);
  tcase_add_test (tc, test_large_tan);
  tcase_add_test (tc, test_short_interval);
  tcase_add_test (tc, test_elementary_limits);
  tcase_add_test (tc, test_scaling);
  tcase_add_test (tc, test_special_cases);
  suite_add_tcase (s, tc);
  TCase *tg = tcase_create ("carlson_guards");
  tcase_add_test (tg, test_carlson_guards);
  suite_add_tcase (s, tg);
  return s;
}

int
main (void)
{
  return tu_run (ellint_suite ());
}
