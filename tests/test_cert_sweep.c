/* test_cert_sweep.c -- the certified sweeps of Figure 2
   (lib/cert-sweep.c) against a route written here: sigma4 as
   1 - (x + 1)/[y + (x + 1)^2] (dir +1) and
   1 + x/[y + x^2] (dir -1) in GMP's rationals (the library: the quotient
   [y + x (x + 1)]/den in FLINT's), rounded by MPFR; the regions from the
   sign of sigma4's distance to +-1 (|sigma4| < 1, the meaning of (3.11),
   (3.12); the library: the polynomials).  0 ulps, and every region,
   required. */
#include <config.h>

#include <math.h>

#include <gmp.h>
#include <mpfr.h>

#include "testutil.h"
#include "certref.h"
#include "chaplygin.h"

/* sigma4 in the route's form into S; 0 where the denominator is 0. */
static int
sigma4_route (int dir, const double xr[2], const double yr[2], mpq_t s)
{
  mpq_t x, y, d, one;
  mpq_inits (x, y, d, one, NULL);
  cr_q_of (x, xr);
  cr_q_of (y, yr);
  mpq_set_ui (one, 1, 1);
  if (dir > 0)
    mpq_add (x, x, one);                /* x + 1 */
  mpq_mul (d, x, x);
  mpq_add (d, d, y);
  const int ok = mpq_sgn (d) != 0;
  if (ok)
    {
      mpq_div (s, x, d);
      if (dir > 0)
        mpq_sub (s, one, s);
      else
        mpq_add (s, one, s);
    }
  mpq_clears (x, y, d, one, NULL);
  return ok;
}

START_TEST (certified_fig2a)
{
  tu_rng g;
  tu_rng_seed (&g, 210);
  mpq_t s;
  mpq_init (s);
  for (int i = 0; i < 20000; i++)
    {
      double x[2], y[2], got;
      const int dir = i % 2 ? 1 : -1;
      cr_ratio_in (&g, -4.0, 2.0, x);
      cr_ratio_in (&g, 0.0, 2.0, y);
      ck_assert (sigma4_route (dir, x, y, s));
      ck_assert_ok (chaplygin_certified_sweep_sigma4 (dir, y, x, &got));
      ck_assert_same (got, cr_round_q (s));
      /* the uncertified sweep at double inputs, within 8 ulps away from
         sigma4's zeros (its fma quotient; cancellation near a zero) */
      double u, c;
      ck_assert_ok (chaplygin_sweep_sigma4 (dir, y[0], 1, &x[0], &u, NULL));
      ck_assert_ok (chaplygin_certified_sweep_sigma4
                    (dir, (const double[2]) { y[0], 1 },
                     (const double[2]) { x[0], 1 }, &c));
      if (fabs (c) > 1e-3)
        ck_assert_ulps (u, c, 8);
    }
  mpq_clear (s);
  /* exact values: x = -1/2, y = 1/4: dir +1 (1/4 - 1/4)/(1/2) = 0;
     dir -1: 0 too; x = 1/3, y = 0, dir +1: x/(x + 1) = 1/4 */
  double v = 7.0;
  ck_assert_ok (chaplygin_certified_sweep_sigma4
                (1, (const double[2]) { 1, 4 }, (const double[2]) { -1, 2 },
                 &v));
  ck_assert_same (v, 0.0);
  ck_assert_ok (chaplygin_certified_sweep_sigma4
                (1, (const double[2]) { 0, 1 }, (const double[2]) { 1, 3 },
                 &v));
  ck_assert_same (v, 0.25);
  /* infinite at y = 0, x = -1 (dir +1), x = 0 (dir -1): ERANGE, nothing
     written */
  v = 7.0;
  ck_assert_status (chaplygin_certified_sweep_sigma4
                    (1, AS_RATIO (0.0), AS_RATIO (-1.0), &v),
                    CHAPLYGIN_ERANGE);
  ck_assert_status (chaplygin_certified_sweep_sigma4
                    (-1, AS_RATIO (0.0), AS_RATIO (0.0), &v),
                    CHAPLYGIN_ERANGE);
  ck_assert_same (v, 7.0);
  ck_assert_status (chaplygin_certified_sweep_sigma4
                    (1, AS_RATIO (-1e-300), AS_RATIO (1.0), &v),
                    CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_certified_sweep_sigma4
                    (0, AS_RATIO (1.0), AS_RATIO (1.0), &v),
                    CHAPLYGIN_EINVAL);
  ck_assert_status (chaplygin_certified_sweep_sigma4
                    (1, AS_RATIO (1.0), (const double[2]) { 1, 0 }, &v),
                    CHAPLYGIN_EDOM);
}
END_TEST

/* The route's region: 1 if |sigma4(+1)| < 1, + 2 if |sigma4(-1)| < 1,
   where sigma4 is finite. */
static int
region_route (const double x[2], const double y[2])
{
  mpq_t s, one;
  mpq_inits (s, one, NULL);
  mpq_set_ui (one, 1, 1);
  int r = 0;
  for (int k = 0; k < 2; k++)
    {
      const int dir = k ? -1 : 1;
      if (sigma4_route (dir, x, y, s))
        {
          mpq_abs (s, s);
          if (mpq_cmp (s, one) < 0)
            r += k ? 2 : 1;
        }
    }
  mpq_clears (s, one, NULL);
  return r;
}

START_TEST (certified_fig2b)
{
  tu_rng g;
  tu_rng_seed (&g, 211);
  for (int i = 0; i < 20000; i++)
    {
      double x[2], y[2];
      unsigned char reg = 9;
      cr_ratio_in (&g, -4.0, 2.0, x);
      cr_ratio_in (&g, 0.0, 1.0, y);
      ck_assert_ok (chaplygin_certified_sweep_stability (x, y, &reg));
      ck_assert_int_eq (reg, region_route (x, y));
    }
  /* on the boundaries, neutral: y = 0, x = -1/2 (sigma4 = -1 for dir +1,
     and for dir -1); y = 1/16, x = -3/4: 2y + (1 + 2x)(1 + x) = 0 */
  const double pts[][2][2] = {
    { { -1, 2 }, { 0, 1 } }, { { -3, 4 }, { 1, 16 } },
    { { -1, 4 }, { 1, 16 } }, { { -1, 1 }, { 0, 1 } }
  };
  for (size_t i = 0; i < sizeof pts / sizeof pts[0]; i++)
    {
      unsigned char reg = 9;
      ck_assert_ok (chaplygin_certified_sweep_stability (pts[i][0], pts[i][1],
                                                         &reg));
      ck_assert_int_eq (reg, region_route (pts[i][0], pts[i][1]));
    }
  unsigned char reg = 9;
  ck_assert_ok (chaplygin_certified_sweep_stability
                ((const double[2]) { -1, 2 }, AS_RATIO (0.0), &reg));
  ck_assert_int_eq (reg, 0);
  ck_assert_status (chaplygin_certified_sweep_stability
                    (AS_RATIO (1.0), AS_RATIO (-1.0), &reg),
                    CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_certified_sweep_stability
                    (AS_RATIO (NAN), AS_RATIO (1.0), &reg), CHAPLYGIN_EDOM);
  ck_assert_status (chaplygin_certified_sweep_stability
                    (AS_RATIO (1.0), AS_RATIO (1.0), NULL),
                    CHAPLYGIN_EINVAL);
  ck_assert_int_eq (reg, 0);
}
END_TEST

int
main (void)
{
  Suite *s = suite_create ("cert_sweep");
  tu_add (s, "certified_fig2a", certified_fig2a);
  tu_add (s, "certified_fig2b", certified_fig2b);
  return tu_run (s);
}
