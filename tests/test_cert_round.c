/* test_cert_round.c -- the correct rounding of the certified method
   (lib/cert-round.c, issue 28): exact rationals and Arb balls to binary64,
   round to nearest, ties to even, against MPFR (mpfr_set_q at 53 bits in
   the double's exponent range, subnormalized: a separate route).  Built
   where configure found Arb. */
#include <config.h>

#include <float.h>
#include <math.h>
#include <mpfr.h>

#include "testutil.h"
#include "cert-round.h"
#include "chaplygin.h"

/* The double nearest to Q by MPFR; *OVER: it rounds beyond DBL_MAX. */
static double
mpfr_nearest (const fmpq_t q, int *over)
{
  mpq_t g;
  mpfr_t m;
  mpq_init (g);
  mpfr_init2 (m, 53);
  fmpq_get_mpq (g, q);
  const mpfr_exp_t emin = mpfr_get_emin (), emax = mpfr_get_emax ();
  mpfr_set_emin (-1073);
  mpfr_set_emax (1024);
  int t = mpfr_set_q (m, g, MPFR_RNDN);
  (void) mpfr_subnormalize (m, t, MPFR_RNDN);
  const double d = mpfr_get_d (m, MPFR_RNDN);
  mpfr_set_emin (emin);
  mpfr_set_emax (emax);
  mpfr_clear (m);
  mpq_clear (g);
  *over = isinf (d);
  return d;
}

/* Q = D exactly. */
static void
set_double (fmpq_t q, double d)
{
  int e;
  const double f = frexp (d, &e);
  fmpz_set_d (fmpq_numref (q), ldexp (f, 53));
  fmpz_one (fmpq_denref (q));
  if (e >= 53)
    fmpq_mul_2exp (q, q, (ulong) (e - 53));
  else
    fmpq_div_2exp (q, q, (ulong) (53 - e));
}

/* Q = (A + B)/2 exactly. */
static void
set_midpoint (fmpq_t q, double a, double b)
{
  fmpq_t t;
  fmpq_init (t);
  set_double (q, a);
  set_double (t, b);
  fmpq_add (q, q, t);
  fmpq_div_2exp (q, q, 1);
  fmpq_clear (t);
}

/* Same double, the sign of a zero included. */
static int
same (double a, double b)
{
  return a == b && signbit (a) == signbit (b);
}

/* Q against MPFR; the ball of Q at 300 bits decides it the same way. */
static void
check_one (const fmpq_t q)
{
  int over;
  const double want = mpfr_nearest (q, &over);
  double got = 0.5;
  const int r = chp_cert_round_fmpq (q, &got);
  if (over)
    {
      ck_assert_int_eq (r, CHAPLYGIN_ERANGE);
      ck_assert (got == 0.5);           /* untouched */
      return;
    }
  ck_assert_int_eq (r, CHAPLYGIN_SUCCESS);
  ck_assert_msg (same (got, want), "got %a, want %a", got, want);
  arb_t b;
  arb_init (b);
  arb_set_fmpq (b, q, 300);
  double z;
  if (chp_cert_round_arb (b, &z))
    ck_assert_msg (same (z, want), "ball: %a, want %a", z, want);
  arb_clear (b);
}

/* Random rationals of up to 200-bit numerators and denominators over
   binary exponents -1100..1100, both signs: the subnormals, the
   overflow and everything between. */
START_TEST (random_rationals)
{
  flint_rand_t st;
  fmpq_t q;
  flint_randinit (st);
  fmpq_init (q);
  for (int i = 0; i < 100000; i++)
    {
      fmpq_randtest_not_zero (q, st, 200);
      const long sh = (long) n_randint (st, 2201) - 1100;
      if (sh >= 0)
        fmpq_mul_2exp (q, q, (ulong) sh);
      else
        fmpq_div_2exp (q, q, (ulong) -sh);
      check_one (q);
    }
  fmpq_clear (q);
  flint_randclear (st);
}
END_TEST

/* Exact ties: midpoints of neighbouring doubles (normal, subnormal, at
   0, at DBL_MAX's upper neighbour 2^1024, where the tie overflows) go to
   the even one; a ball around a tie, however tight, decides nothing. */
START_TEST (ties_to_even)
{
  flint_rand_t st;
  fmpq_t q;
  flint_randinit (st);
  fmpq_init (q);
  for (int i = 0; i < 60000; i++)
    {
      const double m = (double) n_randint (st, UWORD (1) << 52);
      double a = i % 2 ? ldexp (m, -1074)       /* subnormal */
        : ldexp (m + 0x1p52, (int) n_randint (st, 2098) - 1126);
      const double b = nextafter (a, HUGE_VAL);
      if (!isfinite (b))
        continue;
      set_midpoint (q, a, b);
      if (i % 4 >= 2)
        fmpq_neg (q, q);
      check_one (q);
      arb_t ball;
      arb_init (ball);
      arb_set_fmpq (ball, q, 300);
      mag_set_ui_2exp_si (arb_radref (ball), 1, -2000);
      double z = 0.5;
      ck_assert (!chp_cert_round_arb (ball, &z) && z == 0.5);
      arb_clear (ball);
    }
  /* the named ones */
  fmpq_zero (q);                        /* 0: +0 */
  double z = -1.0;
  ck_assert (chp_cert_round_fmpq (q, &z) == CHAPLYGIN_SUCCESS
             && same (z, 0.0));
  set_midpoint (q, 0.0, 0x1p-1074);     /* to +0 */
  check_one (q);
  fmpq_neg (q, q);                      /* to -0 */
  check_one (q);
  set_midpoint (q, 1.0, nextafter (1.0, 2.0));
  check_one (q);
  set_double (q, DBL_MAX);              /* DBL_MAX + 2^970: overflows */
  fmpq_t t;
  fmpq_init (t);
  set_double (t, 0x1p970);
  fmpq_add (q, q, t);
  double x = 0.5;
  ck_assert_int_eq (chp_cert_round_fmpq (q, &x), CHAPLYGIN_ERANGE);
  fmpq_sub (q, q, t);                   /* DBL_MAX itself */
  ck_assert_int_eq (chp_cert_round_fmpq (q, &x), CHAPLYGIN_SUCCESS);
  ck_assert (x == DBL_MAX);
  fmpq_clear (t);
  fmpq_clear (q);
  flint_randclear (st);
}
END_TEST

/* Balls: exact zero, non-finite, across zero (-0 and +0 do not decide
   the sign), and coarse balls, which decide only rightly. */
START_TEST (balls)
{
  arb_t b;
  arb_init (b);
  double x = 0.5;
  arb_zero (b);
  ck_assert (chp_cert_round_arb (b, &x) && same (x, 0.0));
  x = 0.5;
  arb_pos_inf (b);
  ck_assert (!chp_cert_round_arb (b, &x) && x == 0.5);
  arb_indeterminate (b);
  ck_assert (!chp_cert_round_arb (b, &x) && x == 0.5);
  arb_zero (b);
  mag_set_ui_2exp_si (arb_radref (b), 1, -1200);  /* [-tiny, +tiny] */
  ck_assert (!chp_cert_round_arb (b, &x) && x == 0.5);
  arb_set_d (b, 1.0 / 3.0);             /* a ball of 40 bits: too wide */
  mag_set_ui_2exp_si (arb_radref (b), 1, -40);
  ck_assert (!chp_cert_round_arb (b, &x));
  mag_set_ui_2exp_si (arb_radref (b), 1, -60);   /* within the ulp */
  ck_assert (chp_cert_round_arb (b, &x) && x == 1.0 / 3.0);
  arb_clear (b);
}
END_TEST

int
main (void)
{
  Suite *s = suite_create ("cert_round");
  tu_add (s, "random_rationals", random_rationals);
  tu_add (s, "ties_to_even", ties_to_even);
  tu_add (s, "balls", balls);
  int r = tu_run (s);
  flint_cleanup ();
  return r;
}
