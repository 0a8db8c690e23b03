/* certref.c -- the reference route's instruments of the certified tests:
   see certref.h. */
#include <config.h>

#include <float.h>
#include <math.h>

#include <acb_calc.h>

#include "certref.h"

enum { BALL_BITS = 400 };       /* room for the ends of a 300-bit ball */
enum { SQRT_BITS = 3000 };      /* the irrational square roots */

/* Q = R[0]/R[1] (GMP converts doubles exactly). */
void
cr_q_of (mpq_t q, const double r[2])
{
  mpq_t d;
  mpq_init (d);
  mpq_set_d (q, r[0]);
  mpq_set_d (d, r[1]);
  mpq_div (q, q, d);
  mpq_clear (d);
}

/* The double nearest to the value SET writes to a 53-bit MPFR number in
   binary64's exponent range (SET returns its ternary value). */
typedef int (*set_fn) (mpfr_t y, const void *x);

static double
binary64 (set_fn set, const void *x)
{
  const mpfr_exp_t emin = mpfr_get_emin (), emax = mpfr_get_emax ();
  mpfr_t y;
  mpfr_set_emin (-1073);
  mpfr_set_emax (1024);
  mpfr_init2 (y, 53);
  int t = set (y, x);
  t = mpfr_subnormalize (y, t, MPFR_RNDN);
  const double d = mpfr_get_d (y, MPFR_RNDN);
  mpfr_clear (y);
  mpfr_set_emin (emin);
  mpfr_set_emax (emax);
  return d;
}

static int
set_fr (mpfr_t y, const void *x)
{
  return mpfr_set (y, (mpfr_srcptr) x, MPFR_RNDN);
}

static int
set_q (mpfr_t y, const void *x)
{
  return mpfr_set_q (y, (mpq_srcptr) x, MPFR_RNDN);
}

/* X below the normal doubles (|X| < 2^-1022): the integer nearest to
   X 2^1074 (ties to even) times 2^-1074, a subnormal, DBL_MIN or a signed
   zero.  (binary64's exponent range must hold X's exponent: 1.5 2^-1076
   made mpfr_subnormalize abort.) */
static double
below_normal (const mpfr_t x)
{
  mpfr_t y;
  mpfr_init2 (y, mpfr_get_prec (x));
  mpfr_mul_2si (y, x, 1074, MPFR_RNDN);        /* exact */
  mpfr_rint (y, y, MPFR_RNDN);                 /* ties to even */
  const double d = ldexp (mpfr_get_d (y, MPFR_RNDN), -1074);
  mpfr_clear (y);
  return d;
}

double
cr_round_fr (const mpfr_t x)
{
  /* far outside binary64's range: infinity (the range binary64 sets must
     hold X's exponent) */
  if (mpfr_regular_p (x) && mpfr_get_exp (x) > 1100)
    return mpfr_signbit (x) ? -HUGE_VAL : HUGE_VAL;
  if (mpfr_regular_p (x) && mpfr_get_exp (x) <= -1022)
    return below_normal (x);
  return binary64 (set_fr, x);
}

double
cr_round_q (const mpq_t q)
{
  return binary64 (set_q, q);
}

int
cr_round_ball (const arb_t b, double *x)
{
  arf_t lo, hi;
  mpfr_t m;
  arf_init (lo);
  arf_init (hi);
  mpfr_init2 (m, 2 * BALL_BITS);
  arb_get_interval_arf (lo, hi, b, ARF_PREC_EXACT);
  arf_get_mpfr (m, lo, MPFR_RNDD);
  const double a = cr_round_fr (m);
  arf_get_mpfr (m, hi, MPFR_RNDU);
  const double c = cr_round_fr (m);
  mpfr_clear (m);
  arf_clear (lo);
  arf_clear (hi);
  if (!(a == c && signbit (a) == signbit (c)))
    return 0;
  *x = a;
  return 1;
}

int
cr_same (double a, double b)
{
  return a == b && signbit (a) == signbit (b);
}


double
cr_ulps (double a, double b)
{
  if (a == b)
    return 0.0;
  const double u = nextafter (fabs (b), HUGE_VAL) - fabs (b);
  return fabs (a - b) / (u > 0.0 ? u : DBL_MIN);
}



/* A random exact input near X: P/(Q 2^k) with Q up to 2^20 (kind 0), up
   to 2^53 - 1 (kind 1), or the double X itself (kind 2); 2^k brings a
   small X's significand into P. */
void
cr_ratio_near (tu_rng *g, double x, double r[2])
{
  const int kind = (int) tu_uniform (g, 0.0, 3.0);
  if (kind == 2 || x == 0.0)
    {
      r[0] = x;
      r[1] = 1.0;
      return;
    }
  const int k = ilogb (x) < 0 ? -ilogb (x) : 0;
  double q = floor (tu_uniform (g, 1.0, kind ? 0x1p53 : 0x1p20));
  double p = nearbyint (ldexp (x, k) * q);
  while (!(fabs (p) < 0x1p53))
    {
      q = floor (q / 2.0) + 1.0;
      p = nearbyint (ldexp (x, k) * q);
    }
  r[0] = p;
  r[1] = ldexp (q, k);
}

void
cr_ratio_in (tu_rng *g, double a, double b, double r[2])
{
  cr_ratio_near (g, tu_uniform (g, a, b), r);
}

double
cr_round_sqrt_q (const mpq_t q, int sgn)
{
  mpq_t r;
  mpq_init (r);
  double d;
  if (mpz_perfect_square_p (mpq_numref (q))
      && mpz_perfect_square_p (mpq_denref (q)))
    {
      mpz_sqrt (mpq_numref (r), mpq_numref (q));
      mpz_sqrt (mpq_denref (r), mpq_denref (q));
      if (sgn < 0)
        mpq_neg (r, r);
      d = cr_round_q (r);
    }
  else
    {
      mpfr_t m;
      mpfr_init2 (m, SQRT_BITS);
      mpfr_set_q (m, q, MPFR_RNDN);
      mpfr_sqrt (m, m, MPFR_RNDN);
      if (sgn < 0)
        mpfr_neg (m, m, MPFR_RNDN);
      d = cr_round_fr (m);
      mpfr_clear (m);
    }
  mpq_clear (r);
  return d;
}

/* The integrand: on a leg without a turning point nearby (q >= 0) in D,
   l = L0 + D: heading |H|/sqrt((1+l^2) g), time sqrt(1+l^2)/sqrt(g),
   g = 2E (1 + l^2) - H^2.  For q < 0 (WSUB) in w, l = s (lt + w^2) with
   lt = sqrt(-q) the turning point, s the side: |dl|/sqrt(g) =
   2 dw/sqrt(2E (2 lt + w^2)), with no singularity at the turning point
   nor beside it (a slow start). */
static int
leg_integrand (acb_ptr res, const acb_t z, void *param, slong order, slong prec)
{
  const cr_leg *p = param;
  const int an = order != 0;
  acb_t l, n, g, t;
  acb_init (l);
  acb_init (n);
  acb_init (g);
  acb_init (t);
  if (!p->rev)
    {
      acb_add_arb (l, z, p->L0, prec);
      acb_sqr (n, l, prec);
      acb_add_ui (n, n, 1, prec);       /* 1 + l^2 */
      acb_mul_arb (g, n, p->twoE, prec);
      acb_sub_arb (g, g, p->H2, prec);
      acb_rsqrt_analytic (g, g, an, prec);
    }
  else
    {
      acb_sqr (l, z, prec);
      acb_add_arb (l, l, p->lt, prec);          /* |l| = lt + w^2 */
      acb_sqr (n, l, prec);
      acb_add_ui (n, n, 1, prec);
      acb_add_arb (g, l, p->lt, prec);          /* 2 lt + w^2 */
      acb_mul_arb (g, g, p->twoE, prec);
      acb_rsqrt_analytic (g, g, an, prec);
      acb_mul_2exp_si (g, g, 1);
    }
  acb_sqrt_analytic (t, n, an, prec);
  if (p->kind == 0)
    {
      acb_div (g, g, t, prec);
      acb_mul_arb (g, g, p->absH, prec);
    }
  else
    acb_mul (g, g, t, prec);
  acb_set (res, g);
  acb_clear (l);
  acb_clear (n);
  acb_clear (g);
  acb_clear (t);
  return 0;
}

void
cr_leg_integrate (arb_t r, cr_leg *p, const arb_t A, const arb_t B,
                  slong prec)
{
  acb_t res, a, b;
  mag_t tol;
  acb_calc_integrate_opt_t opt;
  acb_init (res);
  acb_init (a);
  acb_init (b);
  mag_init (tol);
  acb_calc_integrate_opt_init (opt);
  acb_set_arb (a, A);
  acb_set_arb (b, B);
  mag_set_ui_2exp_si (tol, 1, -prec + 20);
  acb_calc_integrate (res, leg_integrand, p, a, b, prec - 20, tol, opt,
                      prec);
  arb_set (r, acb_realref (res));
  arb_abs (r, r);
  acb_clear (res);
  acb_clear (a);
  acb_clear (b);
  mag_clear (tol);
}
