/* test_carlson.c -- lib/carlson.c: the fused R_F/R_D kernel.

   Two programs are built from this file.  tests/test_carlson (always)
   checks the kernel against references that need nothing but binary128
   (libquadmath): the elementary cases of R_F and R_D
       R_F(x, x, x) = x^-1/2,   R_D(x, x, x) = x^-3/2,
       R_F(x, y, y) = R_C(x, y),
       R_D(x, y, y) = 3/(2 (y - x)) [R_C(x, y) - sqrt(x)/y],
       R_D(y, y, x) = 3/(y - x) [1/sqrt(x) - R_C(x, y)],
   with R_C(x, y) = acos(sqrt(x/y))/sqrt(y - x) (x < y) and
   acosh(sqrt(x/y))/sqrt(x - y) (x > y) (DLMF 19.2(iv), 19.20; each form
   checked with mpmath at 40 digits), and Legendre's K and E at k^2 = 1/2
   from Gamma(1/4) (the lemniscatic case: K = Gamma(1/4)^2/(4 sqrt(pi)),
   E = K/2 + pi/(4K) by Legendre's relation); every series coefficient
   against the hypergeometric expansion; bit-exact homogeneity, the same
   bits in every request and in both entry points, closeness to GSL, the
   single-precision path and the statuses.  tests/test_carlson_arb (built
   where configure found Arb: -DCHP_TEST_ARB) adds the accuracy against
   Arb (>= 100 correct bits) over five randomized data sets, with the
   maximum and mean errors in ulps printed (TAP comments on stderr, in the
   test's log) and asserted, GSL's beside them.

   The error measure: |computed - exact| / ulp(exact), ulp(v) = 2^(e - 53)
   for 2^(e-1) <= |v| < 2^e, at least 2^-1074 (subnormal results are
   measured on the subnormal grid).

   The asserted bounds.  A worst-case rounding analysis gives about
   (2.5 m + 3) u, u = 2^-53, for R_F after m duplication steps (each step
   perturbs the arguments by at most ~5u, R_F's elasticities sum to 1/2;
   the series and the final division add ~3u) and about twice that for
   R_D, whose sum terms add ~3u each: up to ~20 and ~40 ulps at the m = 7
   of the library's triples.  Measured: R_F max 4.0 ulps, R_D 5.9 (Arb
   sets below), 3.4 and 4.4 (closed forms below); the largest found in a
   4-million-point scan of the closed forms were 5.2 and 7.6 ulps.  The
   tests assert BOUND_RF = 6 and BOUND_RD = 8 ulps (max) and MEAN_RF = 0.8,
   MEAN_RD = 1.0 ulps (mean per data set; measured 0.38-0.68 and
   0.52-0.88).  The truncation error itself is <= 2^-56 (carlson.c).

   Broken on purpose (each change alone, both programs run):
   - R_F's E3/14 -> E3/15: every accuracy test fails (1e7 ulps);
   - R_D's 3 E5/26 -> 3 E5/25: two_equal (20 ulps), gsl, single, Arb wide
     (11 ulps) fail;
   - the degree-6 and 7 coefficients 3/104 -> 3/100, 1/16 -> 1/15 (R_F),
     45/272 -> 45/262 (R_D): test_series fails (errors 1e-6 .. 4e-5); in
     DOUBLE their effect on values is at most an ulp, so only the series
     test sees them (45/262 also fails Arb SINGLE);
   - tau (DOUBLE) doubled: two_equal (25 ulps) and Arb (worse than GSL)
     fail; tau x 1.5 passes (truncation <= 3e-16, within the bounds);
   - tau (SINGLE) x 1.25 or x 1.5: single and Arb SINGLE fail;
   - R_F alone stopping by a looser rule, or the x = 1 entry with y and z
     swapped: same_bits fails;
   - the asymptotic 4 sqrt(z) -> 4.000000001 sqrt(z): two_equal, gsl and
     Arb fail; an odd scaling exponent: equal_arguments, homogeneity,
     statuses and Arb fail; R_D's sum term without its 2^m: all R_D tests
     fail. */
#include <config.h>

#include <float.h>
#include <math.h>
#include <quadmath.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_sf_ellint.h>

#ifdef CHP_TEST_ARB
#include <acb_elliptic.h>
#include <arb.h>
#endif

#include "carlson.h"
#include "testutil.h"

typedef __float128 q128;

#define BOUND_RF 6.0            /* ulps, DOUBLE (see the header) */
#define BOUND_RD 8.0
#define MEAN_RF 0.8             /* ulps, mean over a data set */
#define MEAN_RD 1.0
/* SINGLE: the truncation bound 2^-40 = 9.1e-13 (carlson.c) plus the
   rounding of the double path (< 20 eps = 4.4e-15) */
#define BOUND_SINGLE 9.2e-13
/* GSL's measured max error on the same kind of data (TOOLCHAIN.md: 7.9
   eps for F through R_F; 5.0 ulps R_F and 6.0 ulps R_D against Arb in
   test_carlson_arb's moderate and quartic sets): ours and GSL's may
   differ by the sum of the two bounds. */
#define GSL_BOUND 8.0

static const chaplygin_precision DBL = CHAPLYGIN_PREC_DOUBLE;
static const chaplygin_precision SGL = CHAPLYGIN_PREC_SINGLE;

/* ------------------------------------------------------------------ */
/* helpers                                                             */
/* ------------------------------------------------------------------ */

/* A "high-entropy" double: a uniform mantissa in [1, 2) times 2^e with e
   uniform in [emin, emax]. */
static double
hexp (tu_rng *r, int emin, int emax)
{
  int e = emin + (int) tu_uniform (r, 0.0, emax - emin + 1.0);
  if (e > emax)
    e = emax;
  return ldexp (tu_uniform (r, 1.0, 2.0), e);
}

/* The documented corner that chp_carlson_rfrd does not support for R_D. */
static int
rd_unsupported (double x, double y, double z)
{
  double m = fmax (fmax (x, y), z);
  if (!(m > 0x1p500) || x + y < z * 0x1p-100)
    return 0;
  int e;
  frexp (m, &e);
  int k = 1 - e;
  k += k & 1;
  return ldexp (z, k) < 0x1p-600;
}

/* Accumulates max and mean errors of one function over a data set. */
typedef struct
{
  double max, sum;
  long n;
  double at[3];                 /* the arguments of the max */
} errstat;

static void
err_add (errstat *s, double e, double x, double y, double z)
{
  if (e > s->max || s->n == 0)
    {
      s->max = e;
      s->at[0] = x, s->at[1] = y, s->at[2] = z;
    }
  s->sum += e;
  s->n++;
}

static void
err_report (const char *set, const char *fn, const errstat *s)
{
  fprintf (stderr, "# %-8s %-4s n = %6ld  max %.3f ulps  mean %.3f ulps"
           "  (max at %a %a %a)\n", set, fn, s->n, s->max,
           s->n ? s->sum / s->n : 0.0, s->at[0], s->at[1], s->at[2]);
}

static void
err_assert (const char *set, const char *fn, const errstat *s, double bound,
            double mean)
{
  ck_assert_msg (s->max <= bound, "%s %s: max error %.3f ulps > %.1f at "
                 "(%a, %a, %a)", set, fn, s->max, bound, s->at[0], s->at[1],
                 s->at[2]);
  ck_assert_msg (s->n == 0 || s->sum / s->n <= mean,
                 "%s %s: mean error %.3f ulps > %.1f", set, fn,
                 s->sum / s->n, mean);
}

/* The kernel's R_F alone and R_D alone (the same bits as together: tested
   in test_same_bits). */
static int
rf_only (double x, double y, double z, chaplygin_precision p, double *r)
{
  return chp_carlson_rfrd (x, y, z, p, r, NULL);
}

static int
rd_only (double x, double y, double z, chaplygin_precision p, double *r)
{
  return chp_carlson_rfrd (x, y, z, p, NULL, r);
}

#ifndef CHP_TEST_ARB
/* ulp of the double nearest to v on the grid of v's binade */
static int
ulp_exp_q (q128 v)
{
  int e;
  frexpq (fabsq (v), &e);       /* 2^(e-1) <= |v| < 2^e */
  return e - 53 < -1074 ? -1074 : e - 53;
}

static double
ulps_q (double got, q128 want)
{
  if (isnan (got) || isinf (got))
    return HUGE_VAL;
  q128 d = fabsq ((q128) got - want);
  return (double) ldexpq (d, -ulp_exp_q (want));
}

/* R_C(x, y) in binary128, x >= 0, y > 0, x != y */
static q128
rc_q (q128 x, q128 y)
{
  if (x < y)
    return acosq (sqrtq (x / y)) / sqrtq (y - x);
  return acoshq (sqrtq (x / y)) / sqrtq (x - y);
}

/* Checks a computed R_D against its exact value: success and the error
   when representable, ERANGE when it overflows or is in the unsupported
   corner. */
static void
check_rd_q (errstat *s, double x, double y, double z, q128 want)
{
  double r = -1.0;
  int st = rd_only (x, y, z, DBL, &r);
  if (want > (q128) DBL_MAX * (1 - 0x1p-50q) || rd_unsupported (x, y, z))
    {
      if (want > (q128) DBL_MAX * (1 + 0x1p-50q) || rd_unsupported (x, y, z))
        ck_assert_msg (st == CHAPLYGIN_ERANGE, "R_D(%a, %a, %a) = %g "
                       "overflows, status %d", x, y, z, (double) want, st);
      return;
    }
  ck_assert_msg (st == CHAPLYGIN_SUCCESS, "R_D(%a, %a, %a): status %d", x, y,
                 z, st);
  err_add (s, ulps_q (r, want), x, y, z);
}

static void
check_rf_q (errstat *s, double x, double y, double z, q128 want)
{
  double r = -1.0;
  ck_assert_msg (rf_only (x, y, z, DBL, &r) == CHAPLYGIN_SUCCESS,
                 "R_F(%a, %a, %a) failed", x, y, z);
  err_add (s, ulps_q (r, want), x, y, z);
}

/* ------------------------------------------------------------------ */
/* closed forms (no Arb)                                               */
/* ------------------------------------------------------------------ */

START_TEST (test_equal_arguments)
{
  /* R_F(x, x, x) = x^-1/2, R_D(x, x, x) = x^-3/2: no duplication step at
     all, only the scaling and the final roundings. */
  errstat ef = { 0 }, ed = { 0 };
  const double fixed[] = { 2.385, 1.0, 0.6180339887498949, 0x1p-1074,
    0x1.8p-1060, DBL_MIN, 1e-300, 1e300, DBL_MAX, 0x1p500, 0x1p-500,
    0x1.0000000000001p500, 0x1.fffffffffffffp-501
  };
  for (size_t i = 0; i < sizeof fixed / sizeof fixed[0]; i++)
    {
      q128 x = fixed[i];
      check_rf_q (&ef, fixed[i], fixed[i], fixed[i], 1 / sqrtq (x));
      check_rd_q (&ed, fixed[i], fixed[i], fixed[i], 1 / (x * sqrtq (x)));
    }
  tu_rng r;
  tu_rng_seed (&r, 1001);
  for (int i = 0; i < 2000; i++)
    {
      double x = hexp (&r, -1074, 1023);
      q128 xq = x;
      check_rf_q (&ef, x, x, x, 1 / sqrtq (xq));
      check_rd_q (&ed, x, x, x, 1 / (xq * sqrtq (xq)));
    }
  err_report ("equal", "R_F", &ef);
  err_report ("equal", "R_D", &ed);
  err_assert ("equal", "R_F", &ef, BOUND_RF, MEAN_RF);
  err_assert ("equal", "R_D", &ed, BOUND_RD, MEAN_RD);
  /* exact: 3 * 2^-1074 is no power of 4, but x = 4^-500 is */
  double v;
  ck_assert_ok (rf_only (0x1p-1000, 0x1p-1000, 0x1p-1000, DBL, &v));
  ck_assert (v == 0x1p500);
  ck_assert_ok (rd_only (0x1p-600, 0x1p-600, 0x1p-600, DBL, &v));
  ck_assert (v == 0x1p900);
}
END_TEST

START_TEST (test_two_equal)
{
  /* R_F(x, y, y), R_D(x, y, y), R_D(y, y, x) over x, y spanning 2^-1074 ..
     2^1023 independently (ratios up to 2^2000: the asymptotic branch,
     the scaling, subnormals, R_D's overflow), zeros, and the switch of
     the asymptotic branch at 2^-100 from both sides. */
  errstat ef = { 0 }, ed1 = { 0 }, ed2 = { 0 };
  tu_rng r;
  tu_rng_seed (&r, 2002);
  for (int i = 0; i < 7000; i++)
    {
      double x, y;
      switch (i % 7)
        {
        case 0:                /* anywhere */
          x = hexp (&r, -1074, 1023);
          y = hexp (&r, -1074, 1023);
          break;
        case 1:                /* moderate ratios */
          y = hexp (&r, -600, 600);
          x = y * hexp (&r, -40, 40);
          break;
        case 2:                /* x = 0: pi/(2 sqrt y), 3 pi/(4 y^3/2) */
          x = 0.0;
          y = hexp (&r, -1074, 1023);
          break;
        case 3:                /* around the switch: 2 x = 2^-100 y (1 +- d) */
          y = hexp (&r, -400, 400);
          x = y * 0x1p-101 * (1.0 + tu_uniform (&r, -0x1p-20, 0x1p-20));
          break;
        case 4:                /* near-equal, |x/y - 1| >= 2^-21: the
                                   reference's R_C - sqrt(x)/y cancels
                                   about 21 of binary128's 113 bits */
          y = hexp (&r, -300, 300);
          x = y * (1.0 + ldexp (tu_uniform (&r, 0.5, 1.0)
                                * (tu_uniform (&r, 0.0, 1.0) < 0.5 ? -1 : 1),
                                -(int) tu_uniform (&r, 2.0, 21.0)));
          break;
        case 5:                /* the library's range: (c^2, Y, 1)-like */
          y = 1.0;
          x = tu_uniform (&r, 0.0, 1.0);
          break;
        default:               /* at the stopping rule: |x/y - 1| in
                                   [0.004, 0.15], t from tau/4 to 4 tau
                                   in zero or one step (a too loose
                                   tau shows here first) */
          y = hexp (&r, -300, 300);
          x = y * (1.0 + exp (tu_uniform (&r, log (0.004), log (0.15)))
                   * (tu_uniform (&r, 0.0, 1.0) < 0.5 ? -1 : 1));
          break;
        }
      if (x == y)
        continue;
      q128 xq = x, yq = y, rc = rc_q (xq, yq);
      check_rf_q (&ef, x, y, y, rc);
      /* R_D(x, y, y), y > 0 */
      check_rd_q (&ed1, x, y, y, 3 / (2 * (yq - xq)) * (rc - sqrtq (xq) / yq));
      /* R_D(y, y, x), x > 0 */
      if (x > 0.0)
        check_rd_q (&ed2, y, y, x, 3 / (yq - xq) * (1 / sqrtq (xq) - rc));
    }
  err_report ("two-eq", "R_F", &ef);
  err_report ("two-eq", "R_D", &ed1);
  err_report ("two-eq", "R_D'", &ed2);
  err_assert ("two-eq", "R_F", &ef, BOUND_RF, MEAN_RF);
  err_assert ("two-eq", "R_D", &ed1, BOUND_RD, MEAN_RD);
  err_assert ("two-eq", "R_D'", &ed2, BOUND_RD, MEAN_RD);
}
END_TEST

START_TEST (test_legendre)
{
  /* K(k) = R_F(0, k'^2, 1) and E(k) = K - (k^2/3) R_D(0, k'^2, 1)
     (DLMF 19.25.1) at k^2 = 1/2, where K = Gamma(1/4)^2/(4 sqrt(pi)) and
     Legendre's relation 2 E K - K^2 = pi/2 gives E = K/2 + pi/(4 K); also
     R_F(0, 1, 1) = pi/2 and R_D(0, 1, 1) = 3 pi/4, each with the
     arguments permuted (R_F) and scaled by 4^j (both). */
  const q128 K = tgammaq (0.25Q) * tgammaq (0.25Q) / (4 * sqrtq (M_PIq));
  const q128 E = K / 2 + M_PIq / (4 * K);
  const q128 RD = 6 * (K - E);  /* 3 (K - E)/k^2 */
  errstat ef = { 0 }, ed = { 0 };
  for (int j = -300; j <= 300; j += 7)
    {
      double s = ldexp (1.0, 2 * j);    /* 4^j */
      q128 fs = ldexpq (1, -j), ds = ldexpq (1, -3 * j);
      check_rf_q (&ef, 0.0, 0.5 * s, s, K * fs);
      check_rf_q (&ef, 0.5 * s, s, 0.0, K * fs);
      check_rf_q (&ef, s, 0.0, 0.5 * s, K * fs);
      check_rd_q (&ed, 0.0, 0.5 * s, s, RD * ds);
      check_rd_q (&ed, 0.5 * s, 0.0, s, RD * ds);
      check_rf_q (&ef, 0.0, s, s, M_PIq / 2 * fs);
      check_rd_q (&ed, 0.0, s, s, 3 * M_PIq / 4 * ds);
    }
  err_report ("legendre", "R_F", &ef);
  err_report ("legendre", "R_D", &ed);
  err_assert ("legendre", "R_F", &ef, BOUND_RF, MEAN_RF);
  err_assert ("legendre", "R_D", &ed, BOUND_RD, MEAN_RD);
  /* the x = 1 entry on its fast path: R_F(1, 2, 2) = R_C(1, 2) = pi/4 and
     R_D(1, 2, 2) = 3/2 (pi/4 - 1/2) (test_two_equal's closed forms) */
  double f, d;
  ck_assert_ok (chp_carlson_rfrd_x1 (2.0, 2.0, DBL, &f, &d));
  ck_assert_msg (ulps_q (f, M_PIq / 4) <= BOUND_RF, "R_F(1, 2, 2): %g ulps",
                 ulps_q (f, M_PIq / 4));
  ck_assert_msg (ulps_q (d, 1.5Q * (M_PIq / 4 - 0.5Q)) <= BOUND_RD,
                 "R_D(1, 2, 2): %g ulps", ulps_q (d, 1.5Q * (M_PIq / 4 - 0.5Q)));
}
END_TEST

/* The truncated expansion of the hypergeometric R-function
       R_{-a}(b; z) = A^-a sum_N (a)_N/(c)_N T_N(b; Z),
       T_N = sum_{m1+m2+m3 = N} prod_j (b_j)_{m_j} Z_j^{m_j}/m_j!,
   Z_j = 1 - z_j/A, A = sum b_j z_j/c, c = sum b_j (Carlson 1995, Sec. 2;
   DLMF 19.19), summed to N = 7 in binary128 straight from this definition
   (R_F: a = 1/2, b = (1/2, 1/2, 1/2); R_D: a = 3/2, b = (1/2, 1/2, 3/2)). */
static q128
poch_q (q128 b, int m)
{
  q128 r = 1;
  for (int k = 0; k < m; k++)
    r *= b + k;
  return r;
}

static q128
hyper_series_q (q128 a, const q128 b[3], const q128 Z[3])
{
  const q128 c = b[0] + b[1] + b[2];
  q128 sum = 0;
  for (int N = 0; N <= 7; N++)
    {
      q128 T = 0;
      for (int m1 = 0; m1 <= N; m1++)
        for (int m2 = 0; m1 + m2 <= N; m2++)
          {
            int m3 = N - m1 - m2;
            T += poch_q (b[0], m1) / tgammaq (m1 + 1) * powq (Z[0], m1)
              * poch_q (b[1], m2) / tgammaq (m2 + 1) * powq (Z[1], m2)
              * poch_q (b[2], m3) / tgammaq (m3 + 1) * powq (Z[2], m3);
          }
      sum += poch_q (a, N) / poch_q (c, N) * T;
    }
  return sum;
}

START_TEST (test_series)
{
  /* Every coefficient of the two series (step 2 of carlson.c), against the
     expansion above at |X|, |Y|, |Z| <= 1/2, where a term of degree k is
     >= 2^-k in size for some draw: a coefficient wrong by 1% moves the
     sum by ~1e-5 at degree 7, the rounding of the comparison is ~1e-16.
     X, Y, Z are multiples of 2^-20, so that the constraint sum b_j Z_j = 0
     holds exactly in double. */
  tu_rng r;
  tu_rng_seed (&r, 3434);
  const q128 bF[3] = { 0.5Q, 0.5Q, 0.5Q }, bD[3] = { 0.5Q, 0.5Q, 1.5Q };
  double maxf = 0.0, maxd = 0.0;
  for (int i = 0; i < 4000; i++)
    {
      double X = ldexp (floor (tu_uniform (&r, -0x1p19, 0x1p19)), -20);
      double Y = ldexp (floor (tu_uniform (&r, -0x1p19, 0x1p19)), -20);
      double Z = -(X + Y);
      if (fabs (Z) <= 0.5)
        {
          const q128 Zq[3] = { X, Y, Z };
          double XY = X * Y, E2 = XY - Z * Z, E3 = XY * Z;
          q128 want = hyper_series_q (0.5Q, bF, Zq);
          double e = (double) fabsq (chp_carlson_series_rf (E2, E3) - want);
          maxf = fmax (maxf, e);
        }
      /* R_D: Z = -(X + Y)/3, so draw Z and X and set Y = -3 Z - X */
      double Zd = ldexp (floor (tu_uniform (&r, -0x1p19, 0x1p19)), -20);
      double Yd = -3.0 * Zd - X;
      if (fabs (Yd) <= 0.5)
        {
          const q128 Zq[3] = { X, Yd, Zd };
          double XY = X * Yd, Z2 = Zd * Zd;
          double E2 = XY - 6.0 * Z2, E3 = (3.0 * XY - 8.0 * Z2) * Zd;
          double E4 = 3.0 * (XY - Z2) * Z2, E5 = XY * Zd * Z2;
          q128 want = hyper_series_q (1.5Q, bD, Zq);
          double e = (double) fabsq (chp_carlson_series_rd (E2, E3, E4, E5)
                                     - want);
          maxd = fmax (maxd, e);
        }
    }
  fprintf (stderr, "# series against the hypergeometric expansion: max "
           "%.3g (R_F), %.3g (R_D)\n", maxf, maxd);
  ck_assert_msg (maxf <= 8 * DBL_EPSILON, "R_F series: %g", maxf);
  ck_assert_msg (maxd <= 8 * DBL_EPSILON, "R_D series: %g", maxd);
}
END_TEST

START_TEST (test_homogeneity)
{
  /* R_F(4^j x, 4^j y, 4^j z) = 2^-j R_F(x, y, z) and R_D likewise with
     2^-3j, BIT FOR BIT: inside the unscaled range every operation of the
     kernel scales exactly by a power of two, and outside it the kernel
     scales back into [1, 4) exactly.  This pins the scaling branch (and
     its thresholds 2^-500, 2^500) to the unscaled computation.  Results
     and arguments are kept normal. */
  tu_rng r;
  tu_rng_seed (&r, 3003);
  for (int i = 0; i < 3000; i++)
    {
      double x = hexp (&r, -30, 1), y = hexp (&r, -30, 1), z = hexp (&r,
                                                                        -30,
                                                                        1);
      if (i % 5 == 0)
        x = 0.0;
      if (i % 7 == 0)
        x = z * 0x1p-110, y = z * 0x1.8p-111;   /* asymptotic R_F, R_D */
      double f0, d0;
      ck_assert_ok (chp_carlson_rfrd (x, y, z, DBL, &f0, &d0));
      int j = (int) tu_uniform (&r, -300.0, 300.0);
      double s = ldexp (1.0, 2 * j);
      double f1, d1;
      ck_assert_ok (chp_carlson_rfrd (x * s, y * s, z * s, DBL, &f1, &d1));
      ck_assert_msg (f1 == ldexp (f0, -j), "R_F(%a, %a, %a) scaled by 4^%d: "
                     "%a != %a", x, y, z, j, f1, ldexp (f0, -j));
      ck_assert_msg (d1 == ldexp (d0, -3 * j), "R_D(%a, %a, %a) scaled by "
                     "4^%d: %a != %a", x, y, z, j, d1, ldexp (d0, -3 * j));
    }
}
END_TEST

/* A triple for the request and entry tests: every branch. */
static void
any_triple (tu_rng *r, int i, double *x, double *y, double *z)
{
  switch (i % 8)
    {
    case 0:
      *x = hexp (r, -1074, 1023), *y = hexp (r, -1074, 1023);
      *z = hexp (r, -1074, 1023);
      break;
    case 1:
      *x = hexp (r, -10, 10), *y = hexp (r, -10, 10), *z = hexp (r, -10, 10);
      break;
    case 2:
      *x = 0.0, *y = hexp (r, -600, 600), *z = hexp (r, -600, 600);
      break;
    case 3:
      *z = hexp (r, -400, 400), *x = *z * 0x1p-102, *y = *z * 0x1p-103;
      break;
    case 4:
      *y = hexp (r, 480, 520), *x = hexp (r, -20, 0), *z = hexp (r, 480, 520);
      break;
    case 5:
      *x = tu_uniform (r, 0.0, 1.0), *y = tu_uniform (r, *x, 1.0), *z = 1.0;
      break;
    case 6:
      *x = hexp (r, -1074, -1000), *y = hexp (r, -520, -480);
      *z = hexp (r, -520, -480);
      break;
    default:
      *x = *y = *z = hexp (r, -100, 100);
      break;
    }
}

START_TEST (test_same_bits)
{
  /* Every request gives the same bits for each value (one loop, one
     stopping rule), and the x = 1 entry gives those of the general one;
     the statuses agree.  Checked byte for byte. */
  tu_rng r;
  tu_rng_seed (&r, 4004);
  for (int p = 0; p < 2; p++)
    for (int i = 0; i < 8000; i++)
      {
        double x, y, z;
        any_triple (&r, i, &x, &y, &z);
        double fb = -1.0, db = -1.0, f1 = -2.0, d1 = -2.0;
        int sb = chp_carlson_rfrd (x, y, z, p, &fb, &db);
        int sf = chp_carlson_rfrd (x, y, z, p, &f1, NULL);
        int sd = chp_carlson_rfrd (x, y, z, p, NULL, &d1);
        if (sb == CHAPLYGIN_SUCCESS)
          {
            ck_assert (sf == CHAPLYGIN_SUCCESS && sd == CHAPLYGIN_SUCCESS);
            ck_assert_msg (memcmp (&fb, &f1, sizeof fb) == 0,
                           "R_F(%a, %a, %a) prec %d: %a alone, %a with R_D",
                           x, y, z, p, f1, fb);
            ck_assert_msg (memcmp (&db, &d1, sizeof db) == 0,
                           "R_D(%a, %a, %a) prec %d: %a alone, %a with R_F",
                           x, y, z, p, d1, db);
          }
        else
          ck_assert (sb == sf || sb == sd);
        /* the x = 1 entry, on (y/x, z/x) and on (y, z) as drawn */
        for (int k = 0; k < 2; k++)
          {
            double a = k ? y : y / x, b = k ? z : z / x;
            double g0 = -1.0, e0 = -1.0, g1 = -2.0, e1 = -2.0;
            int s0 = chp_carlson_rfrd (1.0, a, b, p, &g0, &e0);
            int s1 = chp_carlson_rfrd_x1 (a, b, p, &g1, &e1);
            ck_assert_int_eq (s0, s1);
            if (s0 == CHAPLYGIN_SUCCESS)
              ck_assert_msg (memcmp (&g0, &g1, sizeof g0) == 0
                             && memcmp (&e0, &e1, sizeof e0) == 0,
                             "x = 1 entry at (%a, %a) prec %d: R_F %a / %a, "
                             "R_D %a / %a", a, b, p, g1, g0, e1, e0);
            else                /* nothing written */
              ck_assert (g1 == -2.0 && e1 == -2.0);
            double h1 = -3.0, h2 = -3.0;
            ck_assert_int_eq (chp_carlson_rfrd_x1 (a, b, p, &h1, NULL),
                              chp_carlson_rfrd (1.0, a, b, p, &h2, NULL));
            ck_assert (memcmp (&h1, &h2, sizeof h1) == 0);
            h1 = h2 = -4.0;
            ck_assert_int_eq (chp_carlson_rfrd_x1 (a, b, p, NULL, &h1),
                              chp_carlson_rfrd (1.0, a, b, p, NULL, &h2));
            ck_assert (memcmp (&h1, &h2, sizeof h1) == 0);
            if (s1 == CHAPLYGIN_SUCCESS)
              ck_assert (memcmp (&h1, &e1, sizeof h1) == 0);
          }
      }
  /* the x = 1 entry's own switches, from both sides */
  const double pts[][2] = { { 1.0, 1.0 }, { 0x1.fffffffffffffp-1, 1.0 },
  { 1.0, 0x1.fffffffffffffp-1 }, { 0x1p100, 0x1p100 },
  { 0x1.0000000000001p100, 2.0 }, { 3.0, 0x1.0000000000001p100 },
  { 0x1p-101, 1.0 }, { 1.0, 0x1p-101 }, { 0.0, 1.0 }, { 1.0, 0.0 },
  { 0.0, 0.0 }, { 0x1p-1074, 0x1p-1074 }, { 0x1p600, 0x1p-600 },
  { 0x1p200, 0x1p200 }, { 1e300, 1e300 }, { 2.0, 0x1p99 }
  };
  for (size_t i = 0; i < sizeof pts / sizeof pts[0]; i++)
    for (int p = 0; p < 2; p++)
      {
        double g0 = -1.0, e0 = -1.0, g1 = -2.0, e1 = -2.0;
        int s0 = chp_carlson_rfrd (1.0, pts[i][0], pts[i][1], p, &g0, &e0);
        int s1 = chp_carlson_rfrd_x1 (pts[i][0], pts[i][1], p, &g1, &e1);
        ck_assert_int_eq (s0, s1);
        if (s0 == CHAPLYGIN_SUCCESS)
          ck_assert_msg (memcmp (&g0, &g1, sizeof g0) == 0
                         && memcmp (&e0, &e1, sizeof e0) == 0,
                         "x = 1 entry at (%a, %a)", pts[i][0], pts[i][1]);
      }
}
END_TEST

START_TEST (test_gsl)
{
  /* Inside GSL's domain (pairwise sums >= 5 DBL_MIN, max <= DBL_MAX/5 for
     R_F; R_D needs min(x + y, z) >= 2/DBL_MAX^(2/3) and max below
     0.1 (DBL_MAX/5)^(2/3)... here 2^-300 .. 2^300 keeps clear of both) the
     kernel and gsl_sf_ellint_RF_e/RD_e agree to the sum of their error
     bounds: BOUND + GSL_BOUND ulps (GSL's own error measured against Arb
     in test_carlson_arb).  They are not equal: GSL stops Carlson's 1979
     loop by a different rule (errtol 1e-3 on the 5th-order series). */
  gsl_set_error_handler_off ();   /* this test's process only */
  tu_rng r;
  tu_rng_seed (&r, 5005);
  double maxf = 0.0, maxd = 0.0;
  for (int i = 0; i < 10000; i++)
    {
      double x, y, z;
      if (i % 2)
        x = hexp (&r, -300, 300), y = hexp (&r, -300, 300),
          z = hexp (&r, -300, 300);
      else
        x = tu_uniform (&r, 0.0, 1.0), y = tu_uniform (&r, x, 1.0), z = 1.0;
      if (i % 10 == 0)
        x = 0.0;
      double f, d;
      gsl_sf_result gf, gd;
      ck_assert_ok (chp_carlson_rfrd (x, y, z, DBL, &f, &d));
      ck_assert_int_eq (gsl_sf_ellint_RF_e (x, y, z, GSL_PREC_DOUBLE, &gf),
                        GSL_SUCCESS);
      ck_assert_int_eq (gsl_sf_ellint_RD_e (x, y, z, GSL_PREC_DOUBLE, &gd),
                        GSL_SUCCESS);
      double ef = ulps_q (f, gf.val), ed = ulps_q (d, gd.val);
      maxf = fmax (maxf, ef);
      maxd = fmax (maxd, ed);
      ck_assert_msg (ef <= BOUND_RF + GSL_BOUND, "R_F(%a, %a, %a): %a, GSL "
                     "%a: %.2f ulps apart", x, y, z, f, gf.val, ef);
      ck_assert_msg (ed <= BOUND_RD + GSL_BOUND, "R_D(%a, %a, %a): %a, GSL "
                     "%a: %.2f ulps apart", x, y, z, d, gd.val, ed);
    }
  fprintf (stderr, "# GSL vs kernel: max %.2f ulps apart (R_F), %.2f (R_D)\n",
           maxf, maxd);
}
END_TEST

START_TEST (test_single)
{
  /* SINGLE against DOUBLE (itself within BOUND ulps of the exact value):
     relative difference <= BOUND_SINGLE; and SINGLE is really looser
     somewhere (it takes fewer steps), and never takes more. */
  tu_rng r;
  tu_rng_seed (&r, 6006);
  double maxf = 0.0, maxd = 0.0;
  for (int i = 0; i < 8000; i++)
    {
      double x, y, z;
      any_triple (&r, i, &x, &y, &z);
      double f, d, fs, ds;
      int st = chp_carlson_rfrd (x, y, z, DBL, &f, &d);
      ck_assert_int_eq (chp_carlson_rfrd (x, y, z, SGL, &fs, &ds), st);
      if (st != CHAPLYGIN_SUCCESS || d < DBL_MIN)
        continue;
      maxf = fmax (maxf, fabs (fs - f) / f);
      maxd = fmax (maxd, fabs (ds - d) / d);
    }
  fprintf (stderr, "# SINGLE vs DOUBLE: max relative difference %.3g (R_F), "
           "%.3g (R_D)\n", maxf, maxd);
  ck_assert_msg (maxf <= BOUND_SINGLE, "R_F single: %g", maxf);
  ck_assert_msg (maxd <= BOUND_SINGLE, "R_D single: %g", maxd);
  ck_assert (maxf > 1e-15 && maxd > 1e-15);
  /* a precision value that is neither means DOUBLE */
  double a, b;
  ck_assert_ok (chp_carlson_rfrd (0.25, 1.5, 2.385, (chaplygin_precision) 7,
                                  &a, NULL));
  ck_assert_ok (chp_carlson_rfrd (0.25, 1.5, 2.385, DBL, &b, NULL));
  ck_assert (a == b);
}
END_TEST

START_TEST (test_statuses)
{
  /* Errors write nothing; the checks of a request of both are the union
     of the checks of each. */
  const double bad[] = { -1.0, -1e-300, NAN, INFINITY, -INFINITY };
  for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++)
    for (int pos = 0; pos < 3; pos++)
      {
        double a[3] = { 0.5, 1.5, 2.385 };
        a[pos] = bad[i];
        double f = 42.0, d = 43.0;
        ck_assert_status (chp_carlson_rfrd (a[0], a[1], a[2], DBL, &f, &d),
                          CHAPLYGIN_EDOM);
        ck_assert_status (chp_carlson_rfrd (a[0], a[1], a[2], DBL, &f, NULL),
                          CHAPLYGIN_EDOM);
        ck_assert_status (chp_carlson_rfrd (a[0], a[1], a[2], DBL, NULL, &d),
                          CHAPLYGIN_EDOM);
        ck_assert_status (chp_carlson_rfrd (a[0], a[1], a[2], DBL, NULL,
                                            NULL), CHAPLYGIN_EDOM);
        if (pos > 0)
          ck_assert_status (chp_carlson_rfrd_x1 (a[1], a[2], DBL, &f, &d),
                            CHAPLYGIN_EDOM);
        ck_assert (f == 42.0 && d == 43.0);
      }
  double f = 42.0, d = 43.0;
  /* z = 0: R_F fine, R_D is a domain error (as chp_rd) */
  ck_assert_ok (chp_carlson_rfrd (1.0, 2.0, 0.0, DBL, &f, NULL));
  ck_assert_eps (f, 1.3110287771460599052, 4);  /* R_F(0,1,2): lemniscate, mpmath */
  f = 42.0;
  ck_assert_status (chp_carlson_rfrd (1.0, 2.0, 0.0, DBL, NULL, &d),
                    CHAPLYGIN_EDOM);
  ck_assert_status (chp_carlson_rfrd (1.0, 2.0, 0.0, DBL, &f, &d),
                    CHAPLYGIN_EDOM);
  /* two zeros: R_F diverges; x = y = 0: R_D diverges */
  ck_assert_status (chp_carlson_rfrd (0.0, 0.0, 1.0, DBL, &f, NULL),
                    CHAPLYGIN_ERANGE);
  ck_assert_status (chp_carlson_rfrd (0.0, 2.0, 0.0, DBL, &f, NULL),
                    CHAPLYGIN_ERANGE);
  ck_assert_status (chp_carlson_rfrd (0.0, 0.0, 1.0, DBL, NULL, &d),
                    CHAPLYGIN_ERANGE);
  ck_assert_status (chp_carlson_rfrd_x1 (0.0, 0.0, DBL, &f, NULL),
                    CHAPLYGIN_ERANGE);
  ck_assert_status (chp_carlson_rfrd_x1 (0.0, 0.0, DBL, NULL, &d),
                    CHAPLYGIN_EDOM);
  ck_assert_status (chp_carlson_rfrd (0.0, 0.0, 0.0, DBL, &f, NULL),
                    CHAPLYGIN_ERANGE);
  ck_assert_status (chp_carlson_rfrd (0.0, 0.0, 0.0, DBL, NULL, &d),
                    CHAPLYGIN_EDOM);
  /* nothing requested: only the arguments are checked */
  ck_assert_ok (chp_carlson_rfrd (0.0, 0.0, 0.0, DBL, NULL, NULL));
  ck_assert_ok (chp_carlson_rfrd_x1 (0.0, 0.0, DBL, NULL, NULL));
  /* R_D overflows: R_D >= max^-3/2 */
  ck_assert_status (chp_carlson_rfrd (1e-300, 2e-300, 3e-300, DBL, NULL, &d),
                    CHAPLYGIN_ERANGE);
  /* ... also through the sum of the loop: 3/(sqrt(y) sqrt(z) (sqrt(x) +
     sqrt(z))) = 1.5 2^1074 */
  ck_assert_status (chp_carlson_rfrd (0x1p-1074, 1.0, 0x1p-1074, DBL, NULL,
                                      &d), CHAPLYGIN_ERANGE);
  ck_assert_ok (chp_carlson_rfrd (1e-300, 2e-300, 3e-300, DBL, &f, NULL));
  /* the unsupported corner: max > 2^500 and z < 2^-600 max, for R_D */
  ck_assert_status (chp_carlson_rfrd (0x1p600, 0x1p601, 0x1p-10, DBL, NULL,
                                      &d), CHAPLYGIN_ERANGE);
  ck_assert (f != 42.0 && d == 43.0);
  ck_assert_ok (chp_carlson_rfrd (0x1p600, 0x1p601, 0x1p-10, DBL, &f, NULL));
  /* ... but with z >= 2^-600 max it is computed: R_D -> 3/sqrt(x y z) */
  ck_assert_ok (chp_carlson_rfrd (0x1p600, 0x1p600, 0x1p1, DBL, NULL, &d));
  ck_assert_eps (d, 3.0 / (0x1p600 * sqrt (2.0)), 8);
  /* and z tiny without scaling is fine (chp_rd refused 1e-200 here) */
  ck_assert_ok (chp_carlson_rfrd (1.0, 2.0, 1e-200, DBL, NULL, &d));
  ck_assert_eps (d, 3.0 / sqrt (2.0 * 1e-200), 8);
  /* underflow is gradual and not an error (as chp_rd) */
  ck_assert_ok (chp_carlson_rfrd (1e300, 1e300, 1e300, DBL, NULL, &d));
  ck_assert (d == 0.0);
  ck_assert_ok (chp_carlson_rfrd (DBL_MAX, DBL_MAX, DBL_MAX, DBL, &f, &d));
  ck_assert_eps (f, 1.0 / sqrt (DBL_MAX), 2);
}
END_TEST

#else /* CHP_TEST_ARB */
/* ------------------------------------------------------------------ */
/* against Arb                                                         */
/* ------------------------------------------------------------------ */

/* R_F (which = 0) or R_D = R_J(x, y, z, z) (which = 1) to >= 100 correct
   bits, starting at 192 bits of working precision (doubling as needed). */
static void
arb_ref (arb_t out, int which, double x, double y, double z)
{
  acb_t a, b, c, r;
  acb_init (a), acb_init (b), acb_init (c), acb_init (r);
  acb_set_d (a, x), acb_set_d (b, y), acb_set_d (c, z);
  for (slong prec = 192;; prec *= 2)
    {
      if (which == 0)
        acb_elliptic_rf (r, a, b, c, 0, prec);
      else
        acb_elliptic_rj (r, a, b, c, c, 0, prec);
      if (acb_rel_accuracy_bits (r) >= 100 || prec > 8192)
        break;
    }
  ck_assert_msg (acb_rel_accuracy_bits (r) >= 100, "Arb failed at (%a, %a, "
                 "%a)", x, y, z);
  arb_set (out, acb_realref (r));
  acb_clear (a), acb_clear (b), acb_clear (c), acb_clear (r);
}

static double
ulps_arb (double got, const arb_t want)
{
  if (!isfinite (got))
    return HUGE_VAL;
  arb_t d;
  arb_init (d);
  arb_set_d (d, got);
  arb_sub (d, d, want, 256);
  arb_abs (d, d);
  slong e = arf_abs_bound_lt_2exp_si (arb_midref (want));
  slong u = e - 53 < -1074 ? -1074 : e - 53;
  arb_mul_2exp_si (d, d, -u);
  double r = arf_get_d (arb_midref (d), ARF_RND_UP);
  arb_clear (d);
  return r;
}

static int
arb_above_max (const arb_t v)
{
  arb_t m;
  arb_init (m);
  arb_set_d (m, DBL_MAX);
  int r = arb_gt (v, m);
  arb_clear (m);
  return r;
}

enum
{ SET_WIDE, SET_MODERATE, SET_QUARTIC, SET_EDGES, SET_STOP, NSETS };
static const char *const set_name[NSETS] = { "wide", "moderate", "quartic",
  "edges", "stop"
};

/* The quartic set: the triples (1, 1 + k'^2 s^2, 1 + s^2), s = tan(mu),
   that chp_quartic_interval forms (lib/ellint.c; (cos^2 mu, 1 - k^2 sin^2
   mu, 1) above s = 2^50), from random legs: sp = 1, sq = k' in (0, 1)
   over six decades, the interval [y, x] with x over six decades about sq,
   y = 0 (a fifth) or in (0, x). */
static void
quartic_triple (tu_rng *r, double *x, double *y, double *z)
{
  double sq = pow (10.0, tu_uniform (r, -6.0, 0.0)) * tu_uniform (r, 0.0, 1.0);
  double xx = pow (10.0, tu_uniform (r, -3.0, 3.0)) * sq
    + 1e-3 * tu_uniform (r, 0.0, 1.0);
  double yy = tu_uniform (r, 0.0, 1.0) < 0.2 ? 0.0 : xx * tu_uniform (r, 0.0,
                                                                    1.0);
  double dxy = xx - yy;
  double ax = hypot (xx, 1.0), bx = hypot (xx, sq);
  double ay = hypot (yy, 1.0), by = hypot (yy, sq);
  double s = yy == 0.0 ? xx / sq
    : dxy / ((xx / (xx + yy)) * (ay * by) + (yy / (xx + yy)) * (ax * bx));
  if (s <= 0x1p50)
    {
      *x = 1.0;
      *y = fma (sq * sq * s, s, 1.0);
      *z = fma (s, s, 1.0);
      return;
    }
  double c = 1.0 / hypot (1.0, s), sn = s * c;
  *x = c * c;
  *y = *x + sq * sq * sn * sn;
  *z = 1.0;
}

/* The edge set: fixed points, then random points near every switch and
   boundary.  Returns 0 when i is past the end. */
static int
edge_triple (tu_rng *r, int i, double *x, double *y, double *z)
{
  static const double fixed[][3] = {
    { 0.0, 1.0, 1.0 }, { 1.0, 0.0, 1.0 }, { 1.0, 1.0, 0.0 },
    { 0.0, 2.385, 0.25 }, { 2.385, 0.0, 0.25 }, { 2.385, 0.25, 0.0 },
    { 1e-300, 1.0, 1e300 }, { 1e300, 1e-300, 1.0 }, { 1.0, 1e300, 1e-300 },
    { 0.0, 1e-300, 1e300 }, { 1e-300, 1e300, 1e300 }, { 1e300, 1e300, 1e-300 },
    { 0x1p-1074, 1.0, 2.0 }, { 1.0, 2.0, 0x1p-1074 }, { 0x1p-1074, 0x1p-1074, 1.0 },
    { 0x1.8p-1070, 0x1p-1060, 0x1p-1065 }, { DBL_MIN, DBL_MIN, DBL_MIN },
    { DBL_MAX, DBL_MAX, DBL_MAX }, { DBL_MAX, 1.0, 1.0 }, { 1.0, 1.0, DBL_MAX },
    { DBL_MAX, DBL_MAX, 1.0 }, { 0.0, DBL_MAX, DBL_MAX }, { 0.0, DBL_MIN, 1.0 },
    { 2.385, 2.385, 2.385 }, { 2.385, 2.385000000000001, 2.385 },
    { 0x1p500, 0x1p500, 0x1p500 }, { 0x1.0000000000001p500, 1.0, 2.0 },
    { 0x1p-500, 0x1p-500, 0x1p-500 }, { 0x1.fffffffffffffp-501, 0x1p-520, 0x1p-510 },
    { 0x1p-101, 0x1p-101, 1.0 }, { 0x1.0000000000001p-101, 0x1p-101, 1.0 },
    { 0x1.fffffffffffffp-102, 0x1p-101, 1.0 }, { 0x1p600, 0x1p600, 0x1p-0 },
    { 0x1p600, 0x1p601, 0x1p-10 }, { 0x1p-900, 0x1p-880, 0x1p-1000 },
  };
  const int nf = (int) (sizeof fixed / sizeof fixed[0]);
  if (i < nf)
    {
      *x = fixed[i][0], *y = fixed[i][1], *z = fixed[i][2];
      return 1;
    }
  if (i >= nf + 6000)
    return 0;
  double m = hexp (r, -900, 900);
  switch (i % 6)
    {
    case 0:                    /* two args summing near 2^-100 the third */
      *z = m = hexp (r, -800, 1000);
      *x = m * 0x1p-101 * (1.0 + tu_uniform (r, -1e-6, 1e-6));
      *y = *x * tu_uniform (r, 0.5, 1.0);
      break;
    case 1:                    /* around the scaling thresholds 2^+-500 */
      *x = ldexp (tu_uniform (r, 0.999, 1.001), tu_uniform (r, 0, 1) < 0.5 ?
                  500 : -500);
      *y = *x * hexp (r, -60, 0);
      *z = *x * hexp (r, -60, 0);
      break;
    case 2:                    /* one subnormal, others anywhere */
      *x = ldexp (tu_uniform (r, 0.0, 1.0), -1022);
      *y = m, *z = m * hexp (r, -90, 90);
      break;
    case 3:                    /* nearly equal */
      *x = m, *y = m * (1.0 + tu_uniform (r, -1e-8, 1e-8));
      *z = m * (1.0 + tu_uniform (r, -1e-3, 1e-3));
      break;
    case 4:                    /* R_D's z small against x, y */
      *x = m, *y = m * hexp (r, -30, 30), *z = m * hexp (r, -599, -100);
      break;
    default:                   /* one zero */
      *x = 0.0, *y = m, *z = m * hexp (r, -99, 99);
      break;
    }
  return 1;
}

/* Draws triple i of set s; 0 when the set is exhausted. */
static int
draw (int s, tu_rng *r, int i, double *x, double *y, double *z)
{
  const int n = 15000;
  switch (s)
    {
    case SET_WIDE:
      if (i >= n)
        return 0;
      *x = hexp (r, -1074, 1023), *y = hexp (r, -1074, 1023);
      *z = hexp (r, -1074, 1023);
      if (i % 10 == 0)
        *x = 0.0;
      return 1;
    case SET_MODERATE:
      if (i >= n)
        return 0;
      *x = pow (10.0, tu_uniform (r, -3.0, 3.0));
      *y = pow (10.0, tu_uniform (r, -3.0, 3.0));
      *z = pow (10.0, tu_uniform (r, -3.0, 3.0));
      if (i % 10 == 0)
        *x = 0.0;
      return 1;
    case SET_QUARTIC:
      if (i >= n)
        return 0;
      quartic_triple (r, x, y, z);
      return 1;
    case SET_STOP:
      /* at the stopping rule: m (1 + d u) with u a random direction in
         [-1, 1]^3 and d log-uniform in [0.003, 0.12], so that t_F, t_D
         run from tau/4 to 4 tau and the last step's t is near tau in
         every direction (the largest truncation error) */
      if (i >= n)
        return 0;
      {
        double m = hexp (r, -200, 200);
        double d = exp (tu_uniform (r, log (0.003), log (0.12)));
        *x = m * (1.0 + d * tu_uniform (r, -1.0, 1.0));
        *y = m * (1.0 + d * tu_uniform (r, -1.0, 1.0));
        *z = m * (1.0 + d * tu_uniform (r, -1.0, 1.0));
      }
      return 1;
    default:
      return edge_triple (r, i, x, y, z);
    }
}

START_TEST (test_arb_double)
{
  /* DOUBLE against Arb over the four data sets: max and mean ulps per
     function and set, asserted <= BOUND_RF, BOUND_RD and BOUND_MEAN; GSL
     on the sets inside its domain, for comparison (the kernel's max must
     not exceed GSL's).  A status other than success must be an R_D that
     overflows or lies in the unsupported corner. */
  gsl_set_error_handler_off ();   /* this test's process only */
  arb_t ref;
  arb_init (ref);
  for (int s = 0; s < NSETS; s++)
    {
      errstat ef = { 0 }, ed = { 0 }, gf = { 0 }, gd = { 0 };
      tu_rng r;
      tu_rng_seed (&r, 7007 + s);
      double x, y, z;
      for (int i = 0; draw (s, &r, i, &x, &y, &z); i++)
        {
          double f = -1.0, d = -1.0;
          int st = chp_carlson_rfrd (x, y, z, DBL, &f, &d);
          if (st != CHAPLYGIN_SUCCESS)
            {
              /* R_F alone must succeed; then R_D's failure is checked */
              ck_assert_msg (rf_only (x, y, z, DBL, &f) == CHAPLYGIN_SUCCESS,
                             "R_F(%a, %a, %a) failed", x, y, z);
              d = -1.0;
              st = rd_only (x, y, z, DBL, &d);
              if (st == CHAPLYGIN_ERANGE && x + y > 0.0 && z > 0.0
                  && !rd_unsupported (x, y, z))
                {
                  arb_ref (ref, 1, x, y, z);
                  ck_assert_msg (arb_above_max (ref), "R_D(%a, %a, %a): "
                                 "ERANGE, but it is finite", x, y, z);
                }
              else
                ck_assert_msg (z == 0.0 || rd_unsupported (x, y, z),
                               "R_D(%a, %a, %a): status %d", x, y, z, st);
            }
          arb_ref (ref, 0, x, y, z);
          err_add (&ef, ulps_arb (f, ref), x, y, z);
          if (st == CHAPLYGIN_SUCCESS)
            {
              arb_ref (ref, 1, x, y, z);
              err_add (&ed, ulps_arb (d, ref), x, y, z);
            }
          if ((s == SET_MODERATE || s == SET_QUARTIC) && st == 0)
            {
              gsl_sf_result g;
              gsl_sf_ellint_RD_e (x, y, z, GSL_PREC_DOUBLE, &g);
              err_add (&gd, ulps_arb (g.val, ref), x, y, z);
              gsl_sf_ellint_RF_e (x, y, z, GSL_PREC_DOUBLE, &g);
              arb_ref (ref, 0, x, y, z);
              err_add (&gf, ulps_arb (g.val, ref), x, y, z);
            }
        }
      err_report (set_name[s], "R_F", &ef);
      err_report (set_name[s], "R_D", &ed);
      if (gf.n)
        {
          err_report (set_name[s], "GSL F", &gf);
          err_report (set_name[s], "GSL D", &gd);
          ck_assert_msg (ef.max <= gf.max && ed.max <= gd.max,
                         "%s: worse than GSL", set_name[s]);
          ck_assert (gf.max <= GSL_BOUND && gd.max <= GSL_BOUND);
        }
      err_assert (set_name[s], "R_F", &ef, BOUND_RF, MEAN_RF);
      err_assert (set_name[s], "R_D", &ed, BOUND_RD, MEAN_RD);
    }
  arb_clear (ref);
}
END_TEST

START_TEST (test_arb_single)
{
  /* SINGLE against Arb: relative error <= BOUND_SINGLE everywhere. */
  arb_t ref;
  arb_init (ref);
  for (int s = 0; s < NSETS; s++)
    {
      tu_rng r;
      tu_rng_seed (&r, 8008 + s);
      double x, y, z, maxf = 0.0, maxd = 0.0;
      for (int i = 0; draw (s, &r, i, &x, &y, &z) && i < 3000; i++)
        {
          double f, d;
          if (chp_carlson_rfrd (x, y, z, SGL, &f, &d) != CHAPLYGIN_SUCCESS)
            continue;
          arb_ref (ref, 0, x, y, z);
          maxf = fmax (maxf, ulps_arb (f, ref) * 0x1p-53);
          if (d < DBL_MIN)
            continue;
          arb_ref (ref, 1, x, y, z);
          maxd = fmax (maxd, ulps_arb (d, ref) * 0x1p-53);
        }
      fprintf (stderr, "# %-8s SINGLE: max relative error <= %.3g (R_F), "
               "%.3g (R_D)\n", set_name[s], maxf, maxd);
      ck_assert_msg (maxf <= BOUND_SINGLE && maxd <= BOUND_SINGLE,
                     "%s: SINGLE %g %g", set_name[s], maxf, maxd);
    }
  arb_clear (ref);
}
END_TEST
#endif /* CHP_TEST_ARB */

static Suite *
carlson_suite (void)
{
  Suite *s = suite_create ("carlson");
#ifdef CHP_TEST_ARB
  tu_add (s, "carlson_arb_double", test_arb_double);
  tu_add (s, "carlson_arb_single", test_arb_single);
#else
  tu_add (s, "carlson_equal_arguments", test_equal_arguments);
  tu_add (s, "carlson_two_equal", test_two_equal);
  tu_add (s, "carlson_legendre", test_legendre);
  tu_add (s, "carlson_series", test_series);
  tu_add (s, "carlson_homogeneity", test_homogeneity);
  tu_add (s, "carlson_same_bits", test_same_bits);
  tu_add (s, "carlson_gsl", test_gsl);
  tu_add (s, "carlson_single", test_single);
  tu_add (s, "carlson_statuses", test_statuses);
#endif
  return s;
}

int
main (void)
{
  return tu_run (carlson_suite ());
}
